/* bs_model_properties against closed forms: a unit cube either way out and far from the origin,
 * a square with a circular hole given in either orientation (area 1 - pi r^2, centroid by
 * symmetry), the hyperbolic paraboloid z = uv against a long double double integral, and the
 * argument rules. */
#include "harness.h"

#include "model/internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

/* A unit cube of six bilinear patches at offset o; inward = 1 keeps S_u x S_v pointing in. */
static bs_model *cube(const double *o, int inward)
{
    static const double corners[6][4][3] = {
        {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}},
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 0}, {1, 1, 1}},
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 1, 1}}, {{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}}};
    bs_surface *s = NULL;
    bs_model *m = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    for (int f = 0; f < 6; f++) {
        double net[12];
        for (int k = 0; k < 4; k++) {
            int src = inward ? k : (k == 1 ? 2 : k == 2 ? 1 : k); /* swapping u and v flips the normal */
            for (int c = 0; c < 3; c++)
                net[3 * k + c] = corners[f][src][c] + o[c];
        }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s);
    return m;
}

static void test_cubes(void)
{
    const double at[3][3] = {{0, 0, 0}, {-0.5, 2, 7}, {1e6, -3e6, 2.5e6}};
    for (int k = 0; k < 3; k++)
        for (int inward = 0; inward <= 1; inward++) {
            bs_model *m = cube(at[k], inward);
            double area = 0, volume = 0, c[3] = {0, 0, 0};
            CHECK_STATUS(bs_model_properties(m, 1e-10, &area, &volume, c), BS_OK);
            double sign = inward ? -1.0 : 1.0;
            /* the documented bound: rel_tol, or 16 eps x (largest coordinate / diagonal) */
            double far = fmax(fabs(at[k][0]), fmax(fabs(at[k][1]), fabs(at[k][2]))) + 1.0;
            double rel = fmax(1e-10, 16.0 * DBL_EPSILON * far / sqrt(3.0));
            CHECKF(fabs(area - 6.0) <= rel * 6.0, "area %.17g", area);
            CHECKF(fabs(volume - sign) <= rel, "volume %.17g, expected %g", volume, sign);
            for (int d = 0; d < 3; d++)
                CHECKF(fabs(c[d] - (at[k][d] + 0.5)) <= rel * sqrt(3.0) + 4.0 * DBL_EPSILON * far, "centroid %d: %.17g", d, c[d]);
            printf("cube at (%g, %g, %g), %s: area error %.1e, volume error %.1e (bound %.1e)\n", at[k][0], at[k][1],
                   at[k][2], inward ? "inward" : "outward", fabs(area - 6.0), fabs(volume - sign), rel);
            bs_model_destroy(m);
        }
}

/* The unit square in z = 0 as one Bezier face, its outer loop four lines, a hole of radius r at
 * (0.5, 0.5) given counter-clockwise (ccw = 1) or clockwise. */
static bs_model *square_with_hole(double r, int ccw, int outer_ccw)
{
    const double net[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    bs_patch *p = NULL;
    bs_model *m = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p), BS_OK);
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bsi_trim trims[5];
    memset(trims, 0, sizeof trims);
    static const double start[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static const double dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int k = 0; k < 4; k++) {
        CHECK_STATUS(bsi_curve_line(2, start[k], dir[k], 0.0, 1.0, &trims[k].uv), BS_OK);
        trims[k].reversed = !outer_ccw;
        trims[k].edge = BSI_NO_EDGE;
    }
    const double centre[2] = {0.5, 0.5}, x[2] = {1, 0}, y[2] = {0, ccw ? 1.0 : -1.0};
    CHECK_STATUS(bsi_curve_conic(2, centre, x, y, r, r, 1.0, 0.0, 2.0 * pi, &trims[4].uv), BS_OK);
    trims[4].edge = BSI_NO_EDGE;
    size_t loops[2] = {4, 1};
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.patch = p;
    spec.trims = trims;
    spec.ntrim = 5;
    spec.loop_len = loops;
    spec.nloop = 2;
    CHECK_STATUS(bsi_model_add_face(m, &spec, NULL), BS_OK);
    CHECK_STATUS(bsi_model_finish(m), BS_OK);
    bs_patch_destroy(p);
    return m;
}

static void test_hole(void)
{
    for (int ccw = 0; ccw <= 1; ccw++)
        for (int outer = 0; outer <= 1; outer++) {
            double r = 0.3, area = 0, volume = 0, c[3];
            bs_model *m = square_with_hole(r, ccw, outer);
            CHECK_STATUS(bs_model_properties(m, 1e-12, &area, &volume, c), BS_OK);
            double exact = 1.0 - pi * r * r;
            CHECKF(fabs(area - exact) <= 1e-12, "hole ccw %d outer %d: area %.17g, exact %.17g", ccw, outer, area, exact);
            CHECK(isnan(volume));
            CHECKF(fabs(c[0] - 0.5) <= 1e-12 && fabs(c[1] - 0.5) <= 1e-12 && fabs(c[2]) <= 1e-12,
                   "centroid %g %g %g", c[0], c[1], c[2]);
            bs_model_destroy(m);
        }
}

/* Area of z = uv over the unit square: the integral of sqrt(1 + u^2 + v^2), by composite
 * Gauss-Legendre (4 points per cell, 64 x 64 cells) in long double: good to about 1e-16. */
static long double saddle_area(void)
{
    const long double g[4] = {-0.861136311594052575223946488892809505L, -0.339981043584856264802665759103244687L,
                              0.339981043584856264802665759103244687L, 0.861136311594052575223946488892809505L};
    const long double w[4] = {0.347854845137453857373063949221999407L, 0.652145154862546142626936050778000593L,
                              0.652145154862546142626936050778000593L, 0.347854845137453857373063949221999407L};
    const int cells = 64;
    long double h = 1.0L / cells, sum = 0.0L;
    for (int i = 0; i < cells; i++)
        for (int j = 0; j < cells; j++)
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++) {
                    long double u = h * (i + 0.5L + 0.5L * g[a]), v = h * (j + 0.5L + 0.5L * g[b]);
                    sum += w[a] * w[b] * sqrtl(1.0L + u * u + v * v);
                }
    return sum * h * h / 4.0L;
}

static void test_saddle(void)
{
    const double net[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    bs_patch *p = NULL;
    bs_surface *s = NULL;
    bs_model *m = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    double area = 0;
    CHECK_STATUS(bs_model_properties(m, 1e-11, &area, NULL, NULL), BS_OK);
    double exact = (double)saddle_area();
    CHECKF(fabs(area - exact) <= 1e-11 * exact, "saddle area %.17g, reference %.17g", area, exact);
    printf("saddle z = uv: area %.17g, long double reference %.17g, relative error %.2e\n", area, exact,
           fabs(area - exact) / exact);
    bs_model_destroy(m);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
}

static void test_arguments(void)
{
    const double o[3] = {0, 0, 0};
    bs_model *m = cube(o, 0);
    double area = -7.0;
    CHECK_STATUS(bs_model_properties(NULL, 1e-10, &area, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_properties(m, 1e-13, &area, NULL, NULL), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_properties(m, 0.2, &area, NULL, NULL), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_properties(m, NAN, &area, NULL, NULL), BS_ERR_DOMAIN);
    CHECK(area == -7.0);
    CHECK_STATUS(bs_model_properties(m, 1e-10, NULL, NULL, NULL), BS_OK);
    bs_model_destroy(m);
    /* an empty model: no area, no volume, no centroid */
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    CHECK_STATUS(bsi_model_finish(m), BS_OK);
    double volume = 0, c[3] = {0, 0, 0};
    CHECK_STATUS(bs_model_properties(m, 1e-10, &area, &volume, c), BS_OK);
    CHECK(area == 0.0 && isnan(volume) && isnan(c[0]));
    bs_model_destroy(m);
}

int main(void)
{
    test_cubes();
    test_hole();
    test_saddle();
    test_arguments();
    return bs_test_exit("test_properties");
}
