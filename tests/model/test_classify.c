/* Classification of native face parameters against trim loops (lib/model/classify.c): a square
 * loop with a circular hole and a closed B-spline loop on a flat patch (S(u,v) = (2u, 3v, 0), so
 * 3-D distances are known), a square on a twisted bilinear patch, ellipses on planes of every
 * scale (as flat faces and raised to degree 2) against sampled distances, a cylinder whose hole crosses the seam and whose loop lies over
 * [-0.5, 5.5], a full cylinder with its seams, a hemisphere with its pole, an untrimmed face, and
 * bs_model_classify on the model of a surface. Points at 1e-10 from the exact curves (tol 0)
 * must fall on their exact side, points within tol in 3-D must be ON. */
#include "harness.h"

#include "model/internal.h"
#include "cad_model.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static const char *name(int w)
{
    return w == BS_TRIM_INSIDE ? "INSIDE" : w == BS_TRIM_OUTSIDE ? "OUTSIDE" : w == BS_TRIM_ON ? "ON" : "?";
}

#define EXPECT(m, f, u, v, tol, want)                                                          \
    do {                                                                                       \
        int got_ = bsi_face_classify(m, f, u, v, tol);                                         \
        CHECKF(got_ == (want), "(%.17g, %.17g) tol %g: %s, want %s", (double)(u), (double)(v), \
               (double)(tol), name(got_), name(want));                                         \
    } while (0)

static bsi_trim line_trim(double u0, double v0, double u1, double v1)
{
    bsi_trim t;
    memset(&t, 0, sizeof t);
    double p[2] = {u0, v0}, d[2] = {u1 - u0, v1 - v0};
    CHECK_STATUS(bsi_curve_line(2, p, d, 0.0, 1.0, &t.uv), BS_OK);
    t.edge = BSI_NO_EDGE;
    return t;
}

static bsi_trim circle_trim(double cu, double cv, double r, int reversed)
{
    bsi_trim t;
    memset(&t, 0, sizeof t);
    double c[2] = {cu, cv}, x[2] = {1, 0}, y[2] = {0, 1};
    CHECK_STATUS(bsi_curve_conic(2, c, x, y, r, r, 1.0, 0.0, 2 * PI, &t.uv), BS_OK);
    t.reversed = reversed;
    t.edge = BSI_NO_EDGE;
    return t;
}

/* The flat patch S(u, v) = (2u, 3v, 0) over (0,1)^2. */
static bs_patch *flat_patch(void)
{
    double ctrl[12] = {0, 0, 0, 0, 3, 0, 2, 0, 0, 2, 3, 0};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, NULL, &p), BS_OK);
    return p;
}

static size_t add_bezier_face(bs_model *m, bs_patch *patch, bsi_trim *trims, size_t ntrim,
                              const size_t *loop_len, size_t nloop)
{
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.patch = patch;
    spec.trims = trims;
    spec.ntrim = ntrim;
    spec.loop_len = loop_len;
    spec.nloop = nloop;
    size_t f = SIZE_MAX;
    CHECK_STATUS(bsi_model_add_face(m, &spec, &f), BS_OK);
    return f;
}

/* ---- a square loop with a circular hole ---- */
static void test_square_hole(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bs_patch *patch = flat_patch();
    bsi_trim trims[5] = {line_trim(0.2, 0.2, 0.8, 0.2), line_trim(0.8, 0.2, 0.8, 0.8),
                         line_trim(0.8, 0.8, 0.2, 0.8), line_trim(0.2, 0.8, 0.2, 0.2),
                         circle_trim(0.5, 0.5, 0.15, 1)};
    size_t loops[2] = {4, 1};
    size_t f = add_bezier_face(m, patch, trims, 5, loops, 2);
    EXPECT(m, f, 0.3, 0.3, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.5, 0.5, 1e-6, BS_TRIM_OUTSIDE);   /* in the hole */
    EXPECT(m, f, 0.1, 0.5, 1e-6, BS_TRIM_OUTSIDE);   /* in the box, outside the loop */
    EXPECT(m, f, 1.5, 0.5, 1e-6, BS_TRIM_OUTSIDE);   /* outside the box */
    EXPECT(m, f, 0.5, -0.5, 1e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, NAN, 0.5, 1e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.5, NAN, 1e-6, BS_TRIM_OUTSIDE);
    /* rays through the square's corners and along its sides, through the circle's joints */
    EXPECT(m, f, 0.1, 0.2, 0.0, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.1, 0.8, 0.0, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.9, 0.8, 0.0, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.5, 0.2 + 1e-12, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.5, 0.2 - 1e-12, 0.0, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.3, 0.5, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.7, 0.5, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.5, 0.65 + 1e-12, 0.0, BS_TRIM_INSIDE);
    /* the square's sides: 3-D distance 2 du along u, 3 dv along v */
    EXPECT(m, f, 0.2 + 0.4e-4, 0.5, 1e-4, BS_TRIM_ON);
    EXPECT(m, f, 0.2 + 0.6e-4, 0.5, 1e-4, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.2 - 0.4e-4, 0.5, 1e-4, BS_TRIM_ON);
    EXPECT(m, f, 0.2 - 0.6e-4, 0.5, 1e-4, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.5, 0.8 - 0.32e-4, 1e-4, BS_TRIM_ON);
    EXPECT(m, f, 0.5, 0.8 - 0.35e-4, 1e-4, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.8, 0.8, 1e-12, BS_TRIM_ON); /* a corner, exactly */
    /* the hole's ends of axes: 3-D distance 2 d at (0.65 + d, 0.5), 3 d at (0.5, 0.65 + d) */
    EXPECT(m, f, 0.65 + 1e-6, 0.5, 1.9e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.65 - 1e-6, 0.5, 1.9e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.65 + 1e-6, 0.5, 2.2e-6, BS_TRIM_ON);
    EXPECT(m, f, 0.65 - 1e-6, 0.5, 2.2e-6, BS_TRIM_ON);
    EXPECT(m, f, 0.5, 0.65 + 1e-6, 2.9e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.5, 0.65 + 1e-6, 3.1e-6, BS_TRIM_ON);
    /* around the circle: exact sides at 1e-10 (tol 0); ON within tol, exact beyond it */
    unsigned long long seed = 7;
    int wrong = 0, on_wrong = 0;
    for (int i = 0; i < 3000; i++) {
        double a = bs_test_rand(&seed, 0.0, 2 * PI), d = i % 2 ? 1e-10 : -1e-10;
        double u = 0.5 + (0.15 + d) * cos(a), v = 0.5 + (0.15 + d) * sin(a);
        int want = d > 0 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE;
        wrong += bsi_face_classify(m, f, u, v, 0.0) != want;
        double e = i % 2 ? 1e-6 : -1e-6;
        u = 0.5 + (0.15 + e) * cos(a), v = 0.5 + (0.15 + e) * sin(a);
        /* the 3-D distance to the boundary lies between 2 |e| and 3 |e| */
        on_wrong += bsi_face_classify(m, f, u, v, 3.02e-6) != BS_TRIM_ON;
        on_wrong += bsi_face_classify(m, f, u, v, 1.98e-6) != (e > 0 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE);
    }
    CHECKF(wrong == 0, "%d of 3000 points at 1e-10 from the hole on the wrong side", wrong);
    CHECKF(on_wrong == 0, "%d of 6000 points at 1e-6 from the hole misjudged", on_wrong);
    /* along the square at 1e-10 */
    wrong = 0;
    for (int i = 0; i < 2000; i++) {
        double s = bs_test_rand(&seed, 0.21, 0.79), d = i % 2 ? 1e-10 : -1e-10;
        int side = (i / 2) % 4, want = d > 0 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE;
        double u = side == 0 ? s : side == 1 ? 0.8 - d : side == 2 ? s : 0.2 + d;
        double v = side == 0 ? 0.2 + d : side == 1 ? s : side == 2 ? 0.8 - d : s;
        wrong += bsi_face_classify(m, f, u, v, 0.0) != want;
    }
    CHECKF(wrong == 0, "%d of 2000 points at 1e-10 from the square on the wrong side", wrong);
    /* the public entry point */
    uint32_t faces[3] = {(uint32_t)f, (uint32_t)f, (uint32_t)f};
    double us[3] = {0.3, 0.5, 0.2}, vs[3] = {0.3, 0.5, 0.5};
    bs_cview cu = {us, 3, 0}, cv = {vs, 3, 0};
    unsigned char where[3] = {9, 9, 9};
    CHECK_STATUS(bs_model_classify(m, 3, faces, &cu, &cv, 1e-9, where), BS_OK);
    CHECK(where[0] == BS_TRIM_INSIDE && where[1] == BS_TRIM_OUTSIDE && where[2] == BS_TRIM_ON);
    CHECK_STATUS(bs_model_classify(m, 3, faces, &cu, &cv, -1.0, where), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_classify(m, 3, faces, &cu, &cv, NAN, where), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_classify(m, 3, faces, &cu, &cv, 0.0, NULL), BS_ERR_INVALID_ARG);
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* A face of the patch trimmed by the square [0.2, 0.8]^2. */
static size_t square_face(bs_model *m, bs_patch *patch)
{
    bsi_trim trims[4] = {line_trim(0.2, 0.2, 0.8, 0.2), line_trim(0.8, 0.2, 0.8, 0.8),
                         line_trim(0.8, 0.8, 0.2, 0.8), line_trim(0.2, 0.8, 0.2, 0.2)};
    size_t four = 4;
    size_t f = add_bezier_face(m, patch, trims, 4, &four, 1);
    return f;
}

/* ---- a twisted bilinear face: its map is not affine, so ON is judged on the surface ---- */
static void twisted_point(double u, double v, double *p)
{
    p[0] = 2 * u, p[1] = 3 * v, p[2] = 1.5 * u * v;
}

/* The distance from the point at (u, v) to the side u = 0.2, 0.2 <= v' <= 0.8, in 3-D: sampled,
 * then narrowed around the nearest sample (the squared distance is a quartic in v'). */
static double twisted_side_distance(double u, double v)
{
    double p[3], q[3], best = INFINITY, at = 0.2;
    twisted_point(u, v, p);
    for (int k = 0; k <= 6000; k++) {
        double w = 0.2 + 0.6 * k / 6000.0;
        twisted_point(0.2, w, q);
        double d = hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]);
        if (d < best)
            best = d, at = w;
    }
    for (double h = 1e-4; h > 1e-16; h *= 0.5)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double w = fmin(0.8, fmax(0.2, at + sgn * h));
            twisted_point(0.2, w, q);
            double d = hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]);
            if (d < best)
                best = d, at = w;
        }
    return best;
}

static void test_twisted(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    double ctrl[12] = {0, 0, 0, 0, 3, 0, 2, 0, 0, 2, 3, 1.5};
    bs_patch *patch = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, NULL, &patch), BS_OK);
    size_t f = square_face(m, patch);
    for (int k = 0; k < 7; k++) { /* inside, near the side u = 0.2, nearer to it than to the others */
        double v = 0.3 + 0.4 * k / 6.0, e = k % 2 ? 1e-5 : 1e-3;
        double d = twisted_side_distance(0.2 + e, v);
        EXPECT(m, f, 0.2 + e, v, 1.02 * d, BS_TRIM_ON);
        EXPECT(m, f, 0.2 + e, v, 0.98 * d, BS_TRIM_INSIDE);
        d = twisted_side_distance(0.2 - e, v);
        EXPECT(m, f, 0.2 - e, v, 1.02 * d, BS_TRIM_ON);
        EXPECT(m, f, 0.2 - e, v, 0.98 * d, BS_TRIM_OUTSIDE);
    }
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* ---- planes at every scale: the flat path against the surface's, and both against the truth ----
 * A parallelogram S = O + u Ju + v Jv over [0,1]^2, once as its bilinear patch (judged as flat,
 * by the box of each trim piece mapped into 3-D) and once raised to degree (2, 2) (judged on the
 * surface), trimmed by an ellipse of the parameters. Points beside the ellipse get tolerances
 * 1% and 10% either side of their true 3-D distance to it (sampled along the ellipse, then
 * narrowed), so both faces must say ON, or the side of the ellipse the point lies on. */
static void ellipse_uv(const double *c, const double *x, const double *y, double t, double *uv)
{
    uv[0] = c[0] + 0.3 * cos(t) * x[0] + 0.2 * sin(t) * y[0];
    uv[1] = c[1] + 0.3 * cos(t) * x[1] + 0.2 * sin(t) * y[1];
}

static double plane_gap(const double *ju, const double *jv, const double *p, const double *q)
{
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = ju[k] * (p[0] - q[0]) + jv[k] * (p[1] - q[1]);
    return hypot(hypot(d[0], d[1]), d[2]);
}

static double ellipse_distance(const double *c, const double *x, const double *y, const double *ju,
                               const double *jv, const double *p)
{
    double best = INFINITY, at = 0.0, q[2];
    for (int k = 0; k < 4096; k++) {
        double t = 2 * PI * k / 4096.0, d;
        ellipse_uv(c, x, y, t, q);
        if ((d = plane_gap(ju, jv, p, q)) < best)
            best = d, at = t;
    }
    for (double h = 2 * PI / 4096.0; h > 1e-15; h *= 0.5)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double d;
            ellipse_uv(c, x, y, at + sgn * h, q);
            if ((d = plane_gap(ju, jv, p, q)) < best)
                best = d, at += sgn * h;
        }
    return best;
}

static void test_planes_any_scale(void)
{
    unsigned long long seed = 31;
    int wrong = 0, checked = 0;
    for (int trial = 0; trial < 12; trial++) {
        double scale = trial % 3 == 0 ? 1e-3 : trial % 3 == 1 ? 1.0 : 1e3, o[3], ju[3], jv[3];
        for (int k = 0; k < 3; k++) {
            o[k] = bs_test_rand(&seed, -scale, scale);
            ju[k] = bs_test_rand(&seed, -scale, scale);
            jv[k] = bs_test_rand(&seed, -scale, scale);
        }
        double ctrl1[12], ctrl2[27];
        for (int i = 0; i <= 2; i++)
            for (int j = 0; j <= 2; j++)
                for (int k = 0; k < 3; k++) {
                    double at = o[k] + 0.5 * i * ju[k] + 0.5 * j * jv[k];
                    ctrl2[(i * 3 + j) * 3 + k] = at;
                    if (i % 2 == 0 && j % 2 == 0)
                        ctrl1[((i / 2) * 2 + j / 2) * 3 + k] = at;
                }
        double a = bs_test_rand(&seed, 0.0, PI), c[2] = {0.5, 0.5};
        double x[2] = {cos(a), sin(a)}, y[2] = {-sin(a), cos(a)};
        bs_model *m = NULL;
        bs_patch *flat = NULL, *raised = NULL;
        CHECK_STATUS(bsi_model_create(&m), BS_OK);
        CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl1, NULL, &flat), BS_OK);
        CHECK_STATUS(bs_patch_create(2, 2, 3, ctrl2, NULL, &raised), BS_OK);
        size_t one = 1, f[2];
        for (int g = 0; g < 2; g++) {
            bsi_trim t;
            memset(&t, 0, sizeof t);
            t.edge = BSI_NO_EDGE;
            CHECK_STATUS(bsi_curve_conic(2, c, x, y, 0.3, 0.2, 1.0, 0.0, 2 * PI, &t.uv), BS_OK);
            f[g] = add_bezier_face(m, g ? raised : flat, &t, 1, &one, 1);
        }
        for (int k = 0; k < 40; k++) {
            double t = bs_test_rand(&seed, 0.0, 2 * PI), off = (k % 2 ? 1.0 : -1.0) * (k % 4 < 2 ? 1e-3 : 3e-2);
            double e[2], p[2];
            ellipse_uv(c, x, y, t, e);
            p[0] = c[0] + (1.0 + off) * (e[0] - c[0]);
            p[1] = c[1] + (1.0 + off) * (e[1] - c[1]);
            double d = ellipse_distance(c, x, y, ju, jv, p);
            int side = off > 0 ? BS_TRIM_OUTSIDE : BS_TRIM_INSIDE;
            static const double factor[4] = {0.9, 0.99, 1.01, 1.1};
            for (int g = 0; g < 2; g++)
                for (int q = 0; q < 4; q++) {
                    int want = factor[q] > 1.0 ? BS_TRIM_ON : side;
                    int got = bsi_face_classify(m, f[g], p[0], p[1], factor[q] * d);
                    checked++;
                    if (got != want && wrong++ < 5)
                        CHECKF(0, "scale %g, %s face, (%.17g, %.17g) at %g from the ellipse, tol %g times that: %s",
                               scale, g ? "raised" : "flat", p[0], p[1], d, factor[q], name(got));
                }
        }
        bs_patch_destroy(flat);
        bs_patch_destroy(raised);
        bs_model_destroy(m);
    }
    CHECKF(wrong == 0, "%d of %d classifications beside ellipses on planes wrong", wrong, checked);
}

/* ---- a closed periodic cubic B-spline loop (rational or not) ---- */
static void spline_loop(int rational)
{
    enum { N = 9 };
    double ctrl[(N + 3) * 2], w[N + 3], knots[N + 3 + 4];
    static const double radius[N] = {0.3, 0.2, 0.35, 0.25, 0.33, 0.18, 0.3, 0.22, 0.36};
    for (int i = 0; i < N + 3; i++) {
        double a = 2 * PI * (i % N) / N;
        ctrl[2 * i] = 0.5 + radius[i % N] * cos(a);
        ctrl[2 * i + 1] = 0.5 + radius[i % N] * sin(a);
        w[i] = rational ? 1.0 + 0.5 * ((i % N) % 3) : 1.0;
    }
    for (int i = 0; i < N + 3 + 4; i++)
        knots[i] = i;
    bsi_trim t;
    memset(&t, 0, sizeof t);
    t.edge = BSI_NO_EDGE;
    CHECK_STATUS(bsi_curve_bspline(2, 3, N + 3, knots, ctrl, rational ? w : NULL, 3.0, N + 3.0, &t.uv),
                 BS_OK);
    bsi_curve ref;
    CHECK_STATUS(bsi_curve_copy(&t.uv, &ref), BS_OK);
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bs_patch *patch = flat_patch();
    size_t one = 1;
    size_t f = add_bezier_face(m, patch, &t, 1, &one, 1);
    EXPECT(m, f, 0.5, 0.5, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.02, 0.02, 1e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.98, 0.5, 1e-6, BS_TRIM_OUTSIDE);
    /* points off the curve along its normal: the left side of a counter-clockwise loop is in */
    int wrong = 0, on_wrong = 0;
    for (int i = 0; i < 1000; i++) {
        double s = 3.0 + N * (i + 0.37) / 1000.0, p[2], a[2], b[2];
        CHECK(bsi_curve_eval(&ref, s, p) && bsi_curve_eval(&ref, s - 1e-5, a) &&
              bsi_curve_eval(&ref, s + 1e-5, b));
        double nx = -(b[1] - a[1]), ny = b[0] - a[0], len = hypot(nx, ny), d = i % 2 ? 1e-10 : -1e-10;
        int want = d > 0 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE;
        wrong += bsi_face_classify(m, f, p[0] + d * nx / len, p[1] + d * ny / len, 0.0) != want;
        double e = 1e3 * d; /* 1e-7: 3-D distance between 2e-7 and 3e-7 */
        double u = p[0] + e * nx / len, v = p[1] + e * ny / len;
        on_wrong += bsi_face_classify(m, f, u, v, 3.05e-7) != BS_TRIM_ON;
        on_wrong += bsi_face_classify(m, f, u, v, 1.95e-7) != want;
    }
    CHECKF(wrong == 0, "rational %d: %d of 1000 points at 1e-10 from the B-spline misjudged", rational, wrong);
    CHECKF(on_wrong == 0, "rational %d: %d of 2000 points at 1e-7 from the B-spline misjudged", rational,
           on_wrong);
    bsi_curve_free(&ref);
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* ---- faces built by hand over analytic patches ---- */
/* Append a face whose patches (au.n by av.n, i-major) are given; the axes and trims are moved. */
static size_t hand_face(bs_model *m, bs_patch **patches, bsi_axis *au, bsi_axis *av,
                        const double *period, const double *box, bsi_trim *trims, size_t ntrim,
                        const size_t *loop_len, size_t nloop)
{
    bsi_face face;
    memset(&face, 0, sizeof face);
    face.kind = BS_FACE_BEZIER;
    face.first_patch = bs_surface_count(m->surface);
    face.patch_count = au->n * av->n;
    for (size_t k = 0; k < face.patch_count; k++) {
        CHECK_STATUS(bs_surface_add(m->surface, patches[k], NULL), BS_OK);
        bs_patch_destroy(patches[k]);
    }
    face.au = *au;
    face.av = *av;
    memcpy(face.period, period, sizeof face.period);
    memcpy(face.box, box, sizeof face.box);
    face.first_loop = m->nloop;
    face.loop_count = nloop;
    m->faces = realloc(m->faces, (m->nface + 1) * sizeof *m->faces);
    m->loops = realloc(m->loops, (m->nloop + nloop) * sizeof *m->loops);
    m->trims = realloc(m->trims, (m->ntrim + ntrim) * sizeof *m->trims);
    CHECK(m->faces != NULL && m->loops != NULL && m->trims != NULL);
    for (size_t l = 0, t = m->ntrim; l < nloop; l++) {
        m->loops[m->nloop].first_trim = t;
        m->loops[m->nloop++].trim_count = loop_len[l];
        t += loop_len[l];
    }
    memcpy(m->trims + m->ntrim, trims, ntrim * sizeof *trims);
    for (size_t k = m->ntrim; k < m->ntrim + ntrim; k++) /* as bsi_model_add_face */
        bsi_curve_bounds(&m->trims[k].uv, m->trims[k].lo, m->trims[k].hi);
    m->ntrim += ntrim;
    bsi_face_speed(m, &face, face.lip);
    m->faces[m->nface++] = face;
    m->face_cap = m->nface, m->loop_cap = m->nloop, m->trim_cap = m->ntrim;
    return m->nface - 1;
}

/* The quadratic arc of the unit circle over [a0, a1] (at most a quarter turn): x, y, w. */
static void arc(double a0, double a1, double *x, double *y, double *w)
{
    double c[2] = {0, 0}, ex[2] = {1, 0}, ey[2] = {0, 1};
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_conic(2, c, ex, ey, 1.0, 1.0, 1.0, a0, a1, &cv), BS_OK);
    CHECK(cv.axis.n == 1);
    for (int i = 0; i < 3; i++) {
        w[i] = cv.hom[i * 3 + 2];
        x[i] = cv.hom[i * 3] / w[i];
        y[i] = cv.hom[i * 3 + 1] / w[i];
    }
    bsi_curve_free(&cv);
}

/* A cylinder of radius 1 along z: (cos u, sin u, v) over the box. */
static size_t cylinder_face(bs_model *m, const double *box, bsi_trim *trims, size_t ntrim,
                            const size_t *loop_len, size_t nloop)
{
    bsi_axis au, av;
    CHECK_STATUS(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, box[0], box[1], NULL, 0, &au), BS_OK);
    CHECK_STATUS(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, box[2], box[3], NULL, 0, &av), BS_OK);
    bs_patch *patches[8];
    for (size_t i = 0; i < au.n; i++) {
        double x[3], y[3], w[3], ctrl[18], wt[6];
        arc(au.breaks[i], au.breaks[i + 1], x, y, w);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 2; b++) {
                double *q = ctrl + (a * 2 + b) * 3;
                q[0] = x[a], q[1] = y[a], q[2] = box[2 + b];
                wt[a * 2 + b] = w[a];
            }
        CHECK_STATUS(bs_patch_create(2, 1, 3, ctrl, wt, &patches[i]), BS_OK);
    }
    double period[2] = {2 * PI, 0.0};
    size_t f = hand_face(m, patches, &au, &av, period, box, trims, ntrim, loop_len, nloop);
    for (int i = 0; i <= 20; i++) { /* the face is the cylinder */
        double u = box[0] + (box[1] - box[0]) * i / 20.0, v = box[2] + 0.3 * (box[3] - box[2]), p[3];
        CHECK(bsi_face_point(m, f, u, v, p) == 1);
        CHECK(fabs(p[0] - cos(u)) < 1e-14 && fabs(p[1] - sin(u)) < 1e-14 && fabs(p[2] - v) < 1e-14);
    }
    return f;
}

static void test_cylinder_seam(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    /* a loop over [-0.5, 5.5] (not a whole turn) with a hole across u = 0 */
    double box[4] = {-0.5, 5.5, 0.0, 1.0};
    bsi_trim trims[5] = {line_trim(-0.5, 0, 5.5, 0), line_trim(5.5, 0, 5.5, 1),
                         line_trim(5.5, 1, -0.5, 1), line_trim(-0.5, 1, -0.5, 0),
                         circle_trim(0.0, 0.5, 0.2, 0)};
    size_t loops[2] = {4, 1};
    size_t f = cylinder_face(m, box, trims, 5, loops, 2);
    EXPECT(m, f, 3.0, 0.5, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.1, 0.5, 1e-6, BS_TRIM_OUTSIDE);          /* in the hole */
    EXPECT(m, f, 0.1 + 2 * PI, 0.5, 1e-6, BS_TRIM_OUTSIDE); /* the same, a turn later */
    EXPECT(m, f, 2 * PI - 0.1, 0.5, 1e-6, BS_TRIM_OUTSIDE); /* -0.1: in the hole */
    EXPECT(m, f, -0.1 - 4 * PI, 0.5, 1e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.25, 0.5, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, -0.25, 0.5, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 2 * PI - 0.25, 0.5, 1e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 5.6, 0.5, 1e-6, BS_TRIM_OUTSIDE); /* in the gap (5.5, 2 pi - 0.5) */
    EXPECT(m, f, 3.0, -1e-6, 1e-5, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 3.0, 1e-6, 1e-5, BS_TRIM_ON);
    EXPECT(m, f, 3.0, 1e-6, 0.5e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 5.5 - 1e-6, 0.5, 1e-5, BS_TRIM_ON); /* a true boundary, not a seam */
    EXPECT(m, f, -0.5 + 1e-6, 0.5, 1e-5, BS_TRIM_ON);
    /* the hole's rim: 3-D distance 2 sin(d / 2) ~ d across u */
    EXPECT(m, f, 0.2 + 1e-5, 0.5, 2e-5, BS_TRIM_ON);
    EXPECT(m, f, 0.2 + 1e-5, 0.5, 5e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.2 - 1e-5, 0.5, 5e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, -0.2 + 1e-5 + 2 * PI, 0.5, 5e-6, BS_TRIM_OUTSIDE);
    EXPECT(m, f, -0.2 - 1e-5 + 2 * PI, 0.5, 5e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 2 * PI - 0.2, 0.5, 1e-9, BS_TRIM_ON);

    /* a whole turn: its seams u = 0 and u = 2 pi are no boundary */
    double full[4] = {0.0, 2 * PI, 0.0, 1.0};
    bsi_trim ring[4] = {line_trim(0, 0, 2 * PI, 0), line_trim(2 * PI, 0, 2 * PI, 1),
                        line_trim(2 * PI, 1, 0, 1), line_trim(0, 1, 0, 0)};
    size_t four = 4;
    size_t g = cylinder_face(m, full, ring, 4, &four, 1);
    EXPECT(m, g, 1e-7, 0.5, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, g, 2 * PI - 1e-7, 0.5, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, g, 0.0, 0.5, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, g, 2 * PI, 0.5, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, g, -1e-7, 0.5, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, g, 3.0, 1.0 - 1e-6, 1e-5, BS_TRIM_ON);
    EXPECT(m, g, 1e-7, 1.0 - 1e-6, 1e-5, BS_TRIM_ON); /* near the seam and the top */
    EXPECT(m, g, 3.0, 1.0 + 1e-6, 1e-5, BS_TRIM_OUTSIDE);

    /* the same, its seams a little off u = const, known as seams by their edge (used twice) */
    uint32_t e = 0;
    CHECK_STATUS(bsi_model_add_edge(m, &e), BS_OK);
    bsi_trim ring2[4] = {line_trim(0, 0, 2 * PI, 0), line_trim(2 * PI, 0, 2 * PI + 1e-13, 1),
                         line_trim(2 * PI + 1e-13, 1, 1e-13, 1), line_trim(1e-13, 1, 0, 0)};
    ring2[1].edge = ring2[3].edge = e;
    size_t h = cylinder_face(m, full, ring2, 4, &four, 1);
    m->edges[e].uses = 2;
    m->edges[e].face[0] = m->edges[e].face[1] = (uint32_t)h;
    EXPECT(m, h, 1e-7, 0.5, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, h, 2 * PI - 1e-7, 0.5, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, h, 3.0, 1e-6, 1e-5, BS_TRIM_ON);
    m->edges[e].face[1] = UINT32_MAX; /* one face only: a boundary */
    EXPECT(m, h, 1e-7, 0.5, 1e-5, BS_TRIM_ON);
    bs_model_destroy(m);
}

/* ---- a loop that closes only within a tolerance: rays through its gaps ---- */
static void test_gaps(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bs_patch *patch = flat_patch();
    bsi_trim trims[5] = {line_trim(0.2, 0.2, 0.8, 0.2), line_trim(0.8, 0.2, 0.8, 0.5 - 1e-9),
                         line_trim(0.8 + 1e-9, 0.5, 0.8, 0.8), line_trim(0.8, 0.8, 0.2, 0.8 + 1e-9),
                         line_trim(0.2, 0.8, 0.2, 0.2 + 2e-9)};
    size_t five = 5;
    size_t f = add_bezier_face(m, patch, trims, 5, &five, 1);
    double vs[6] = {0.5 - 1e-9, 0.5 - 0.5e-9, 0.5, 0.8 + 0.25e-9, 0.2 + 1e-9, 0.8 - 1e-12};
    for (int i = 0; i < 6; i++) {
        EXPECT(m, f, 0.5, vs[i], 0.0, BS_TRIM_INSIDE);
        EXPECT(m, f, 0.1, vs[i], 0.0, BS_TRIM_OUTSIDE);
        EXPECT(m, f, 0.9, vs[i], 0.0, BS_TRIM_OUTSIDE);
    }
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* ---- a surface constant along v, S(u, v) = (2u, 0, 0): every point of the square is at 3-D
 * distance 0 from its bottom side ---- */
static void test_degenerate_surface(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    double ctrl[6] = {0, 0, 0, 2, 0, 0};
    bs_patch *patch = NULL;
    CHECK_STATUS(bs_patch_create(1, 0, 3, ctrl, NULL, &patch), BS_OK);
    size_t f = square_face(m, patch);
    EXPECT(m, f, 0.5, 0.5, 1e-9, BS_TRIM_ON);
    EXPECT(m, f, 0.1, 0.5, 1e-9, BS_TRIM_OUTSIDE);
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* A hemisphere of radius 1: (cos v cos u, cos v sin u, sin v), u in [0, 2 pi], v in [0, pi / 2],
 * its loop the equator, the seam, the pole (a degenerate trim along v = pi / 2), the seam. */
static void test_pole(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    double box[4] = {0.0, 2 * PI, 0.0, PI / 2};
    bsi_axis au, av;
    CHECK_STATUS(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, box[0], box[1], NULL, 0, &au), BS_OK);
    CHECK_STATUS(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, box[2], box[3], NULL, 0, &av), BS_OK);
    CHECK(au.n == 4 && av.n == 1);
    bs_patch *patches[4];
    double cx[3], cz[3], cw[3];
    arc(box[2], box[3], cx, cz, cw);
    for (size_t i = 0; i < au.n; i++) {
        double x[3], y[3], w[3], ctrl[27], wt[9];
        arc(au.breaks[i], au.breaks[i + 1], x, y, w);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double *q = ctrl + (a * 3 + b) * 3;
                q[0] = x[a] * cx[b], q[1] = y[a] * cx[b], q[2] = cz[b];
                wt[a * 3 + b] = w[a] * cw[b];
            }
        CHECK_STATUS(bs_patch_create(2, 2, 3, ctrl, wt, &patches[i]), BS_OK);
    }
    bsi_trim trims[4] = {line_trim(0, 0, 2 * PI, 0), line_trim(2 * PI, 0, 2 * PI, PI / 2),
                         line_trim(2 * PI, PI / 2, 0, PI / 2), line_trim(0, PI / 2, 0, 0)};
    size_t four = 4;
    double period[2] = {2 * PI, 0.0};
    size_t f = hand_face(m, patches, &au, &av, period, box, trims, 4, &four, 1);
    double p[3];
    CHECK(bsi_face_point(m, f, 1.0, 0.5, p) == 1);
    CHECK(fabs(p[0] - cos(0.5) * cos(1.0)) < 1e-14 && fabs(p[2] - sin(0.5)) < 1e-14);
    EXPECT(m, f, 1.0, 0.7, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, f, 1.0 + 2 * PI, 0.7, 0.0, BS_TRIM_INSIDE);
    EXPECT(m, f, 1.0, -0.1, 1e-5, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 1.0, PI / 2 - 1e-6, 1e-5, BS_TRIM_ON); /* 1e-6 from the pole in 3-D */
    EXPECT(m, f, 4.0, PI / 2 - 1e-6, 1e-5, BS_TRIM_ON);
    EXPECT(m, f, 1.0, PI / 2 - 1e-6, 0.5e-6, BS_TRIM_INSIDE);
    EXPECT(m, f, 1.0, PI / 2 - 1e-3, 1e-5, BS_TRIM_INSIDE);
    EXPECT(m, f, 1.0, PI / 2, 1e-9, BS_TRIM_ON);
    EXPECT(m, f, 1.0, 1e-6, 1e-5, BS_TRIM_ON); /* the equator */
    EXPECT(m, f, 1e-8, 0.5, 1e-5, BS_TRIM_INSIDE); /* the seam */
    bs_model_destroy(m);
}

/* ---- faces of exact surfaces through bsi_model_add_face ---- */
static size_t def_face(bs_model *m, const bsi_surface_def *def, bsi_trim *trims, size_t ntrim,
                       const size_t *loop_len, size_t nloop)
{
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.def = def;
    spec.trims = trims;
    spec.ntrim = ntrim;
    spec.loop_len = loop_len;
    spec.nloop = nloop;
    size_t f = SIZE_MAX;
    CHECK_STATUS(bsi_model_add_face(m, &spec, &f), BS_OK);
    return f;
}

static void test_exact_surfaces(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bsi_surface_def def;
    memset(&def, 0, sizeof def);
    def.f.x[0] = def.f.y[1] = def.f.z[2] = 1.0;
    /* a cylinder of radius 2, its loop over [-0.5, 5.5] with a hole across the seam */
    def.kind = BS_FACE_CYLINDER;
    def.r = 2.0;
    bsi_trim trims[5] = {line_trim(-0.5, 0, 5.5, 0), line_trim(5.5, 0, 5.5, 3),
                         line_trim(5.5, 3, -0.5, 3), line_trim(-0.5, 3, -0.5, 0),
                         circle_trim(0.0, 1.5, 0.4, 0)};
    size_t loops[2] = {4, 1};
    size_t f = def_face(m, &def, trims, 5, loops, 2);
    if (f < m->nface) {
        CHECK(fabs(m->faces[f].period[0] - 2 * PI) < 1e-15 && m->faces[f].period[1] == 0.0);
        EXPECT(m, f, 3.0, 1.5, 1e-6, BS_TRIM_INSIDE);
        EXPECT(m, f, 0.1, 1.5, 1e-6, BS_TRIM_OUTSIDE);
        EXPECT(m, f, 2 * PI - 0.1, 1.5, 1e-6, BS_TRIM_OUTSIDE);
        EXPECT(m, f, 5.6, 1.5, 1e-6, BS_TRIM_OUTSIDE);
        /* across u the 3-D distance is 2 du (radius 2) */
        EXPECT(m, f, 0.4 + 1e-6, 1.5, 2.2e-6, BS_TRIM_ON);
        EXPECT(m, f, 0.4 + 1e-6, 1.5, 1.8e-6, BS_TRIM_INSIDE);
        EXPECT(m, f, 0.4 - 1e-6, 1.5, 1.8e-6, BS_TRIM_OUTSIDE);
        EXPECT(m, f, 2 * PI - 0.4 - 1e-6, 1.5, 1.8e-6, BS_TRIM_INSIDE);
        EXPECT(m, f, 2 * PI - 0.4 + 1e-6, 1.5, 1.8e-6, BS_TRIM_OUTSIDE);
    }
    /* a whole unit sphere: seams u = 0 and 2 pi, poles v = -pi / 2 and pi / 2 */
    def.kind = BS_FACE_SPHERE;
    def.r = 1.0;
    bsi_trim sph[4] = {line_trim(0, -PI / 2, 0, PI / 2), line_trim(0, PI / 2, 2 * PI, PI / 2),
                       line_trim(2 * PI, PI / 2, 2 * PI, -PI / 2),
                       line_trim(2 * PI, -PI / 2, 0, -PI / 2)};
    size_t four = 4;
    size_t g = def_face(m, &def, sph, 4, &four, 1);
    if (g < m->nface) {
        unsigned long long seed = 11;
        int wrong = 0;
        for (int i = 0; i < 2000; i++) {
            double u = bs_test_rand(&seed, -3.0, 10.0), v = bs_test_rand(&seed, -1.5, 1.5);
            wrong += bsi_face_classify(m, g, u, v, 1e-7) != BS_TRIM_INSIDE;
        }
        CHECKF(wrong == 0, "%d of 2000 points of a whole sphere not inside", wrong);
        EXPECT(m, g, 0.0, 0.3, 1e-7, BS_TRIM_INSIDE);
        EXPECT(m, g, 1.0, PI / 2 - 1e-8, 1e-7, BS_TRIM_ON);
        EXPECT(m, g, 1.0, -PI / 2 + 1e-8, 1e-7, BS_TRIM_ON);
        EXPECT(m, g, 1.0, -PI / 2 + 1e-6, 1e-7, BS_TRIM_INSIDE);
        EXPECT(m, g, 1.0, PI / 2 + 1e-6, 1e-7, BS_TRIM_OUTSIDE);
    }
    bs_model_destroy(m);
}

/* ---- a face without loops: its whole box ---- */
static void test_untrimmed(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    bs_patch *patch = flat_patch();
    size_t f = add_bezier_face(m, patch, NULL, 0, NULL, 0);
    EXPECT(m, f, 0.5, 0.5, 1e-3, BS_TRIM_INSIDE);
    EXPECT(m, f, 0.0, 1.0, 1e-3, BS_TRIM_INSIDE);
    EXPECT(m, f, -1e-9, 0.5, 1e-3, BS_TRIM_OUTSIDE);
    EXPECT(m, f, 0.5, INFINITY, 1e-3, BS_TRIM_OUTSIDE);
    bs_patch_destroy(patch);
    bs_model_destroy(m);
}

/* ---- bs_model_classify on the model of a surface: each patch a face with its four sides ---- */
static void test_public(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    bs_patch *patch = flat_patch();
    CHECK_STATUS(bs_surface_add(s, patch, NULL), BS_OK);
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    if (m != NULL) {
        enum { N = 6 };
        uint32_t faces[N] = {0, 0, 0, 0, 0, 0};
        double us[N] = {0.5, 0.5, 1.5, NAN, 1.0 - 1e-9, 0.25};
        double vs[N] = {0.5, 1e-9, 0.5, 0.5, 0.5, 0.75};
        bs_cview cu = {us, N, 0}, cv = {vs, N, 0};
        unsigned char where[N];
        memset(where, 9, sizeof where);
        CHECK_STATUS(bs_model_classify(m, N, faces, &cu, &cv, 1e-6, where), BS_OK);
        CHECK(where[0] == BS_TRIM_INSIDE && where[1] == BS_TRIM_ON && where[2] == BS_TRIM_OUTSIDE &&
              where[3] == BS_TRIM_OUTSIDE && where[4] == BS_TRIM_ON && where[5] == BS_TRIM_INSIDE);
        CHECK_STATUS(bs_model_classify(m, N, faces, &cu, &cv, 1e-12, where), BS_OK);
        CHECK(where[1] == BS_TRIM_INSIDE && where[4] == BS_TRIM_INSIDE);
        uint32_t bad[1] = {1};
        CHECK_STATUS(bs_model_classify(m, 1, bad, &cu, &cv, 1e-6, where), BS_ERR_INVALID_ARG);
        CHECK_STATUS(bs_model_classify(NULL, 1, faces, &cu, &cv, 1e-6, where), BS_ERR_INVALID_ARG);
        CHECK_STATUS(bs_model_classify(m, 0, NULL, NULL, NULL, 0.0, NULL), BS_OK);
    }
    bs_model_destroy(m);
    bs_patch_destroy(patch);
    bs_surface_destroy(s);
}

/* bsi_face_box_place on the CAD parts' faces: a box called inside or outside holds no trim, so
 * the loops' parity (exact off the trims) agrees with it at every point of a 7 x 7 grid across
 * the box; boxes of every size from half the face's box down to 1/64 of it, at random places. */
static void test_box_place(void)
{
    static const char *parts[] = {"bottle.step", "block.step", "bell.step", "duct.step"};
    unsigned long long rng = 77;
    size_t count[3] = {0, 0, 0}, wrong = 0;
    for (size_t q = 0; q < sizeof parts / sizeof parts[0]; q++) {
        bs_model *m = read_model(parts[q]);
        for (size_t f = 0; m != NULL && f < m->nface; f++) {
            const double *fb = m->faces[f].box;
            for (int k = 0; k < 60; k++) {
                double nb[4];
                double scale = ldexp(1.0, -1 - k % 6);
                for (int d = 0; d < 2; d++) {
                    double lo = fb[2 * d], w = (fb[2 * d + 1] - lo) * scale;
                    double a = lo + bs_test_rand(&rng, 0.0, 1.0) * (fb[2 * d + 1] - lo - w);
                    nb[2 * d] = a;
                    nb[2 * d + 1] = a + w;
                }
                int place = bsi_face_box_place(m, f, nb);
                count[place == BSI_CL_IN ? 0 : place == BSI_CL_OUT ? 1 : 2]++;
                if (place != BSI_CL_IN && place != BSI_CL_OUT)
                    continue;
                for (int i = 0; i < 7; i++)
                    for (int j = 0; j < 7; j++) {
                        double u = nb[0] + (nb[1] - nb[0]) * (i + 0.5) / 7.0;
                        double v = nb[2] + (nb[3] - nb[2]) * (j + 0.5) / 7.0;
                        wrong += bsi_face_parity(m, f, u, v) != (place == BSI_CL_IN);
                    }
            }
        }
        bs_model_destroy(m);
    }
    CHECKF(wrong == 0, "%zu grid points disagree with their box's place", wrong);
    /* every answer occurs */
    CHECKF(count[0] > 0 && count[1] > 0 && count[2] > 0, "in %zu, out %zu, crossed %zu", count[0], count[1],
           count[2]);
}

int main(void)
{
    test_square_hole();
    test_twisted();
    test_planes_any_scale();
    spline_loop(0);
    spline_loop(1);
    test_cylinder_seam();
    test_pole();
    test_gaps();
    test_degenerate_surface();
    test_exact_surfaces();
    test_untrimmed();
    test_public();
    test_box_place();
    return bs_test_exit("test_classify");
}
