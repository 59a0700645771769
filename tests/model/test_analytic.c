/* Exact surfaces: every kind's patches, evaluated through the native map at many parameters of
 * boxes of every shape (not starting at 0, less and more than a quarter turn, a full turn, across
 * a sphere's pole, cutting a curve's arcs and a B-spline's spans), against the closed form in
 * long double; the refusals; the surface unchanged on failure. */
#include "harness.h"

#include "model/internal.h"

#include <math.h>
#include <string.h>

static const long double PI_L = 3.141592653589793238462643383279502884L;

/* A tilted right-handed frame at o. */
static bsi_frame tilted(double ox, double oy, double oz)
{
    bsi_frame f;
    const double a = 0.7, b = -0.4; /* rotations about z, then x */
    double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
    double x[3] = {ca, sa, 0}, y[3] = {-sa * cb, ca * cb, sb}, z[3] = {sa * sb, -ca * sb, cb};
    f.o[0] = ox, f.o[1] = oy, f.o[2] = oz;
    memcpy(f.x, x, sizeof x);
    memcpy(f.y, y, sizeof y);
    memcpy(f.z, z, sizeof z);
    return f;
}

/* The closed form in long double (analytic kinds only). */
static void exact(const bsi_surface_def *d, long double u, long double v, long double *p)
{
    long double x, y, z;
    switch (d->kind) {
    case BS_FACE_PLANE: x = u, y = v, z = 0; break;
    case BS_FACE_CYLINDER: x = d->r * cosl(u), y = d->r * sinl(u), z = v; break;
    case BS_FACE_CONE: {
        long double rad = d->r + v * tanl(d->r2);
        x = rad * cosl(u), y = rad * sinl(u), z = v;
        break;
    }
    case BS_FACE_SPHERE: x = d->r * cosl(v) * cosl(u), y = d->r * cosl(v) * sinl(u), z = d->r * sinl(v); break;
    default: {
        long double rho = d->r + d->r2 * cosl(v);
        x = rho * cosl(u), y = rho * sinl(u), z = d->r2 * sinl(v);
        break;
    }
    }
    for (int c = 0; c < 3; c++)
        p[c] = d->f.o[c] + x * d->f.x[c] + y * d->f.y[c] + z * d->f.z[c];
}

/* Worst distance between the patches (through the axes' maps) and the reference at an 11 x 11
 * grid of the box, relative to scale; the reference is `exact` or bsi_surface_def_eval. */
static double worst_error(const bsi_surface_def *d, const double *box, double scale, int closed_form)
{
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    bs_status st = bsi_surface_def_patches(d, box, s, &au, &av);
    CHECKF(st == BS_OK, "kind %d: status %d", d->kind, st);
    if (st != BS_OK) {
        bs_surface_destroy(s);
        return INFINITY;
    }
    CHECK(bs_surface_count(s) == au.n * av.n);
    double worst = 0.0;
    for (int i = 0; i <= 10; i++)
        for (int j = 0; j <= 10; j++) {
            /* the box's own ends at i, j = 10 (a sum may round past them) */
            double u = i == 10 ? box[1] : box[0] + (box[1] - box[0]) * i / 10.0;
            double v = j == 10 ? box[3] : box[2] + (box[3] - box[2]) * j / 10.0;
            size_t pi, pj;
            double su, tv, p[3];
            if (!bsi_axis_locate(&au, u, &pi, &su) || !bsi_axis_locate(&av, v, &pj, &tv)) {
                CHECKF(0, "(%g, %g) not in the axes", u, v);
                continue;
            }
            bs_cview cu = {&su, 1, 0}, cv = {&tv, 1, 0};
            bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval(bs_surface_get(s, pi * av.n + pj), 1, &cu, &cv, pos, NULL, NULL), BS_OK);
            long double q[3];
            if (closed_form) {
                exact(d, u, v, q);
            } else {
                double r[3];
                bsi_surface_def_eval(d, u, v, r);
                q[0] = r[0], q[1] = r[1], q[2] = r[2];
            }
            double e = (double)sqrtl((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                     (p[2] - q[2]) * (p[2] - q[2]));
            worst = fmax(worst, e / scale);
        }
    bsi_axis_free(&au);
    bsi_axis_free(&av);
    bs_surface_destroy(s);
    return worst;
}

static void test_analytic_kinds(void)
{
    const double pi = (double)PI_L;
    const double boxes[][4] = {{0.3, 1.1, -2, 3}, {-1, 2 * pi - 1, 0.5, 1.5}, {0, 2 * pi, -pi / 2, pi / 2},
                               {2.5, 4.0, -1.2, 0.4}, {0.1, 0.2, 1.0, 1.3}};
    const int kinds[] = {BS_FACE_PLANE, BS_FACE_CYLINDER, BS_FACE_CONE, BS_FACE_SPHERE, BS_FACE_TORUS};
    double worst_all = 0.0;
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        for (size_t b = 0; b < sizeof boxes / sizeof boxes[0]; b++) {
            bsi_surface_def d;
            memset(&d, 0, sizeof d);
            d.kind = kinds[k];
            d.f = tilted(1.5, -2.0, 0.25);
            d.r = kinds[k] == BS_FACE_TORUS ? 4.0 : 2.5;
            d.r2 = kinds[k] == BS_FACE_CONE ? 0.4 : 1.25;
            double e = worst_error(&d, boxes[b], 6.0, 1);
            CHECKF(e <= 4e-15, "kind %d box %zu: worst error %.3g of the scale", kinds[k], b, e);
            worst_all = fmax(worst_all, e);
        }
    printf("planes .. tori: worst distance from the closed form %.2e of the scale\n", worst_all);
}

/* A sphere as the revolution of a half circle cut to a box that cuts its arcs, an extrusion of an
 * ellipse, a cylinder as the extrusion of a B-spline line; against bsi_surface_def_eval. */
static void test_sweeps(void)
{
    const double pi = (double)PI_L;
    bsi_curve meridian, ellipse, bline;
    const double c[3] = {1, 2, 3}, x[3] = {1, 0, 0}, z[3] = {0, 0, 1}, y[3] = {0, 1, 0};
    CHECK_STATUS(bsi_curve_conic(3, c, x, z, 2.0, 2.0, 1.0, -pi / 2, pi / 2, &meridian), BS_OK);
    CHECK_STATUS(bsi_curve_conic(3, c, x, y, 3.0, 1.0, 1.0, 0.0, 2 * pi, &ellipse), BS_OK);
    const double knots[6] = {0, 0, 0, 1, 1, 1}, ctrl[9] = {0, 0, 0, 1, 1, 0, 2, 0, 1};
    CHECK_STATUS(bsi_curve_bspline(3, 2, 3, knots, ctrl, NULL, 0.0, 1.0, &bline), BS_OK);
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = BS_FACE_REVOLUTION;
    d.f = tilted(1, 2, 3);
    memcpy(d.f.z, z, sizeof z);
    d.curve = &meridian;
    const double rbox[2][4] = {{0.2, 5.0, -1.3, 0.9}, {-pi, pi, -pi / 2, pi / 2}};
    for (int b = 0; b < 2; b++) {
        double e = worst_error(&d, rbox[b], 4.0, 0);
        CHECKF(e <= 4e-15, "revolution box %d: %.3g", b, e);
    }
    /* the revolved half circle is the sphere of radius 2 about (1, 2, 3) */
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bsi_surface_def_patches(&d, rbox[0], s, &au, &av), BS_OK);
    CHECK(av.kind == BSI_AXIS_ANGULAR && au.kind == BSI_AXIS_ANGULAR);
    for (size_t p = 0; p < bs_surface_count(s); p++) {
        double st[2] = {0.3, 0.7}, q[3];
        bs_cview cu = {&st[0], 1, 0}, cv = {&st[1], 1, 0};
        bs_view pos[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval(bs_surface_get(s, p), 1, &cu, &cv, pos, NULL, NULL), BS_OK);
        CHECK(fabs(hypot(hypot(q[0] - 1, q[1] - 2), q[2] - 3) - 2.0) <= 1e-14);
    }
    bsi_axis_free(&au);
    bsi_axis_free(&av);
    bs_surface_destroy(s);

    d.kind = BS_FACE_EXTRUSION;
    d.dir[0] = 0.1, d.dir[1] = 0.2, d.dir[2] = 1.0;
    d.curve = &ellipse;
    const double ebox[4] = {0.4, 5.9, -1, 2};
    CHECKF(worst_error(&d, ebox, 4.0, 0) <= 4e-15, "extrusion of an ellipse");
    d.curve = &bline;
    const double lbox[4] = {0.25, 0.8, 0, 3};
    CHECKF(worst_error(&d, lbox, 4.0, 0) <= 4e-15, "extrusion of a B-spline");
    bsi_curve_free(&meridian);
    bsi_curve_free(&ellipse);
    bsi_curve_free(&bline);
}

/* A rational B-spline surface with interior knots, boxes cutting its spans, against de Boor. */
static void test_bspline(void)
{
    const double ku[7] = {0, 0, 0, 0.4, 1, 1, 1}, kv[6] = {0, 0, 0.5, 0.75, 1, 1};
    double ctrl[4 * 4 * 3], w[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            ctrl[(i * 4 + j) * 3 + 0] = i + 0.1 * j * j;
            ctrl[(i * 4 + j) * 3 + 1] = j - 0.2 * i;
            ctrl[(i * 4 + j) * 3 + 2] = sin(i + 2.0 * j);
            w[i * 4 + j] = 1.0 + 0.3 * ((i + j) % 3);
        }
    bs_bspline b = {2, 1, 4, 4, 3, ku, kv, ctrl, w};
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = BS_FACE_BSPLINE;
    d.bspline = &b;
    const double boxes[3][4] = {{0, 1, 0, 1}, {0.1, 0.7, 0.3, 0.8}, {0, 0.3, 0.6, 1}};
    for (int k = 0; k < 3; k++)
        CHECKF(worst_error(&d, boxes[k], 4.0, 0) <= 4e-15, "B-spline box %d", k);
    const double past[4] = {-0.5, 0.3, 0.6, 2.0};
    /* a box reaching past the domain is cut to it */
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bsi_surface_def_patches(&d, past, s, &au, &av), BS_OK);
    CHECK(au.breaks[0] == 0.0 && au.breaks[au.n] == 0.3 && av.breaks[0] == 0.6 && av.breaks[av.n] == 1.0);
    bsi_axis_free(&au);
    bsi_axis_free(&av);
    const double outside[4] = {2, 3, 0, 1};
    CHECK_STATUS(bsi_surface_def_patches(&d, outside, s, &au, &av), BS_ERR_DOMAIN);
    CHECK(bs_surface_count(s) == 2 && au.n == 0 && av.n == 0);
    bs_surface_destroy(s);
}

static void test_refusals(void)
{
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = BS_FACE_SPHERE;
    d.f = tilted(0, 0, 0);
    d.r = 1.0;
    const double box[4] = {0, 1, 0, 1}, empty[4] = {1, 1, 0, 1}, inf[4] = {0, INFINITY, 0, 1};
    CHECK_STATUS(bsi_surface_def_patches(&d, empty, s, &au, &av), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_surface_def_patches(&d, inf, s, &au, &av), BS_ERR_DOMAIN);
    d.r = -1.0;
    CHECK_STATUS(bsi_surface_def_patches(&d, box, s, &au, &av), BS_ERR_DOMAIN);
    d.r = 1.0;
    d.f.x[0] += 1e-6; /* not orthonormal */
    CHECK_STATUS(bsi_surface_def_patches(&d, box, s, &au, &av), BS_ERR_DOMAIN);
    d.f = tilted(0, 0, 0);
    d.kind = BS_FACE_CONE;
    d.r2 = 1.6; /* beyond a right angle */
    CHECK_STATUS(bsi_surface_def_patches(&d, box, s, &au, &av), BS_ERR_DOMAIN);
    d.kind = BS_FACE_EXTRUSION;
    CHECK_STATUS(bsi_surface_def_patches(&d, box, s, &au, &av), BS_ERR_INVALID_ARG);
    CHECK(bs_surface_count(s) == 0 && au.n == 0 && av.n == 0);
    double pu, pv;
    d.kind = BS_FACE_TORUS;
    bsi_surface_def_periods(&d, &pu, &pv);
    CHECK(pu > 6.28 && pv > 6.28);
    d.kind = BS_FACE_PLANE;
    bsi_surface_def_periods(&d, &pu, &pv);
    CHECK(pu == 0.0 && pv == 0.0);
    bs_surface_destroy(s);
}

int main(void)
{
    test_analytic_kinds();
    test_sweeps();
    test_bspline();
    test_refusals();
    return bs_test_exit("test_analytic");
}
