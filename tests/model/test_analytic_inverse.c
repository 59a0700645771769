/* Exact surfaces, second part: the nearest point's canonical (u, v) in closed form
 * (bsi_surface_def_inverse: the round trip through the closed form, feet of points off the surface,
 * unwrapping to a hint, the singular points); patches over boxes past a sphere's pole and beyond a
 * turn, spindle tori, cones past their apex, frames far from the origin, the revolution of a
 * rational B-spline against long double de Boor; every allocation failing in turn leaves the
 * surface unchanged. */
#include "harness.h"

#include "model/internal.h"

#include <math.h>
#include <string.h>

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
void *__real_calloc(size_t n, size_t k);
void *__wrap_calloc(size_t n, size_t k);
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static size_t fail_in;
static int fails(void) { return fail_in != 0 && --fail_in == 0; }
void *__wrap_malloc(size_t n) { return fails() ? NULL : __real_malloc(n); }
void *__wrap_calloc(size_t n, size_t k) { return fails() ? NULL : __real_calloc(n, k); }
void *__wrap_realloc(void *p, size_t n) { return fails() ? NULL : __real_realloc(p, n); }
#endif

static const long double PI_L = 3.141592653589793238462643383279502884L;
#define PI ((double)PI_L)

/* A right-handed frame turned by a about z, then b about x, then c about z, at o. */
static bsi_frame frame(double a, double b, double c, double ox, double oy, double oz)
{
    long double R[3][3], ca = cosl(a), sa = sinl(a), cb = cosl(b), sb = sinl(b), cc = cosl(c), sc = sinl(c);
    long double A[3][3] = {{ca, -sa, 0}, {sa, ca, 0}, {0, 0, 1}}, B[3][3] = {{1, 0, 0}, {0, cb, -sb}, {0, sb, cb}},
                C[3][3] = {{cc, -sc, 0}, {sc, cc, 0}, {0, 0, 1}}, AB[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            AB[i][j] = 0;
            for (int k = 0; k < 3; k++)
                AB[i][j] += A[i][k] * B[k][j];
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[i][j] = 0;
            for (int k = 0; k < 3; k++)
                R[i][j] += AB[i][k] * C[k][j];
        }
    bsi_frame f;
    for (int i = 0; i < 3; i++) {
        f.x[i] = (double)R[i][0], f.y[i] = (double)R[i][1], f.z[i] = (double)R[i][2];
    }
    f.o[0] = ox, f.o[1] = oy, f.o[2] = oz;
    return f;
}

static bsi_surface_def make(int kind, bsi_frame f, double r, double r2)
{
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = kind;
    d.f = f;
    d.r = r;
    d.r2 = r2;
    return d;
}

/* The closed form of the analytic kinds in long double, in the frame (x, y, z) then placed. */
static void exact(const bsi_surface_def *d, long double u, long double v, long double *p)
{
    long double x, y, z, rad;
    switch (d->kind) {
    case BS_FACE_PLANE: x = u, y = v, z = 0; break;
    case BS_FACE_CYLINDER: x = d->r * cosl(u), y = d->r * sinl(u), z = v; break;
    case BS_FACE_CONE:
        rad = d->r + v * tanl(d->r2);
        x = rad * cosl(u), y = rad * sinl(u), z = v;
        break;
    case BS_FACE_SPHERE: x = d->r * cosl(v) * cosl(u), y = d->r * cosl(v) * sinl(u), z = d->r * sinl(v); break;
    default:
        rad = d->r + d->r2 * cosl(v);
        x = rad * cosl(u), y = rad * sinl(u), z = d->r2 * sinl(v);
        break;
    }
    for (int c = 0; c < 3; c++)
        p[c] = d->f.o[c] + x * d->f.x[c] + y * d->f.y[c] + z * d->f.z[c];
}

/* The unit normal of the analytic kinds (not of a plane) at (u, v), for points off the surface. */
static void normal(const bsi_surface_def *d, double u, double v, double *n)
{
    double a, b, c;
    switch (d->kind) {
    case BS_FACE_CYLINDER: a = cos(u), b = sin(u), c = 0; break;
    case BS_FACE_CONE: {
        double t = tan(d->r2), k = 1.0 / sqrt(1.0 + t * t);
        a = k * cos(u), b = k * sin(u), c = -t * k;
        break;
    }
    default: a = cos(v) * cos(u), b = cos(v) * sin(u), c = sin(v); break; /* SPHERE, TORUS */
    }
    for (int i = 0; i < 3; i++)
        n[i] = a * d->f.x[i] + b * d->f.y[i] + c * d->f.z[i];
}

/* |x - y| up to whole turns when period > 0. */
static double angle_gap(double x, double y, double period)
{
    double d = x - y;
    if (period > 0.0)
        d -= period * round(d / period);
    return fabs(d);
}

static double worst_inverse;

/* inverse(point at (u, v) moved off by `off` along the normal) is (u, v): up to turns without a
 * hint, exactly the turn of the hint with one; in range without a hint. */
static void round_trip(const bsi_surface_def *d, double u, double v, double off)
{
    long double q[3];
    exact(d, u, v, q);
    double p[3] = {(double)q[0], (double)q[1], (double)q[2]}, n[3], uv[2], pu, pv;
    if (off != 0.0) {
        normal(d, u, v, n);
        for (int c = 0; c < 3; c++)
            p[c] += off * n[c];
    }
    bsi_surface_def_periods(d, &pu, &pv);
    CHECKF(bsi_surface_def_inverse(d, p, NULL, uv) == 1, "kind %d at (%g, %g)", d->kind, u, v);
    if (d->kind == BS_FACE_TORUS && d->r == 0.0) {
        /* (u + pi, pi - v) is the same point: only the point can be compared */
        long double back[3];
        exact(d, uv[0], uv[1], back);
        double e = (double)sqrtl((back[0] - q[0]) * (back[0] - q[0]) + (back[1] - q[1]) * (back[1] - q[1]) +
                                 (back[2] - q[2]) * (back[2] - q[2]));
        CHECKF(e <= 1e-14 * (d->r2 + 200.0), "torus of major radius 0: %.3g away", e);
        return;
    }
    double e = fmax(angle_gap(uv[0], u, pu), angle_gap(uv[1], v, pv));
    if (pu > 0.0)
        CHECKF(uv[0] >= 0.0 && uv[0] < pu, "u %.17g out of [0, 2 pi)", uv[0]);
    if (pv > 0.0)
        CHECKF(uv[1] >= 0.0 && uv[1] < pv, "v %.17g out of [0, 2 pi)", uv[1]);
    if (d->kind == BS_FACE_SPHERE)
        CHECK(fabs(uv[1]) <= 0.5 * PI);
    /* a hint a few turns away and off by a little under half a turn */
    double hint[2] = {u + 3.0 * pu + 1.4, v - 2.0 * pv - 1.4};
    CHECK(bsi_surface_def_inverse(d, p, hint, uv) == 1);
    e = fmax(e, fmax(fabs(uv[0] - (u + 3.0 * pu)), fabs(uv[1] - (v - 2.0 * pv))));
    double scale = fmax(1.0, fabs(u) + fabs(v));
    CHECKF(e <= 1e-12 * scale, "kind %d at (%.17g, %.17g) off %g: error %.3g", d->kind, u, v, off, e);
    worst_inverse = fmax(worst_inverse, e / scale);
}

static void test_inverse(void)
{
    unsigned long long seed = 42;
    const bsi_frame frames[3] = {frame(0, 0, 0, 0, 0, 0), frame(0.7, -0.4, 1.9, 1.5, -2, 0.25),
                                 frame(-2.1, 2.6, 0.3, 40, -75, 120)};
    for (int fr = 0; fr < 3; fr++) {
        bsi_surface_def defs[8] = {make(BS_FACE_PLANE, frames[fr], 0, 0),
                                   make(BS_FACE_CYLINDER, frames[fr], 2.5, 0),
                                   make(BS_FACE_CONE, frames[fr], 1.5, 0.4),
                                   make(BS_FACE_CONE, frames[fr], 0.0, -1.1),
                                   make(BS_FACE_SPHERE, frames[fr], 3.0, 0),
                                   make(BS_FACE_TORUS, frames[fr], 4.0, 1.25),
                                   make(BS_FACE_TORUS, frames[fr], 1.0, 2.5), /* spindle */
                                   make(BS_FACE_TORUS, frames[fr], 0.0, 2.0)};
        for (int k = 0; k < 8; k++) {
            const bsi_surface_def *d = &defs[k];
            for (int i = 0; i < 40; i++) {
                double u = bs_test_rand(&seed, 0.0, 2 * PI), v;
                switch (d->kind) {
                case BS_FACE_SPHERE: v = bs_test_rand(&seed, -1.5, 1.5); break;
                case BS_FACE_TORUS: v = bs_test_rand(&seed, 0.0, 2 * PI); break;
                case BS_FACE_PLANE: u = bs_test_rand(&seed, -5, 5), v = bs_test_rand(&seed, -5, 5); break;
                default: v = bs_test_rand(&seed, -4, 4); break; /* both sides of a cone's apex */
                }
                /* the core circle and axis of a torus of major radius 0 or a spindle: only
                 * points away from them */
                if (d->kind == BS_FACE_TORUS && d->r + d->r2 * cos(v) > -0.2 && d->r + d->r2 * cos(v) < 0.2)
                    continue;
                if (d->kind == BS_FACE_CONE && fabs(d->r + v * tan(d->r2)) < 0.2)
                    continue;
                round_trip(d, u, v, 0.0);
                if (d->kind != BS_FACE_PLANE && !(d->kind == BS_FACE_TORUS && d->r < d->r2))
                    round_trip(d, u, v, d->kind == BS_FACE_CONE ? 0.05 : -0.1); /* within the reach */
            }
        }
    }
    /* the spindle's inner lobe: the nearest meridian is on the other side of the axis */
    bsi_surface_def spindle = make(BS_FACE_TORUS, frames[1], 1.0, 2.5);
    round_trip(&spindle, 0.5, 2.6, 0.0);
    /* a plane's (u, v) of a point off it */
    bsi_surface_def plane = make(BS_FACE_PLANE, frames[2], 0, 0);
    long double q[3];
    exact(&plane, 1.25, -3.5, q);
    double p[3] = {(double)q[0] + 2 * plane.f.z[0], (double)q[1] + 2 * plane.f.z[1], (double)q[2] + 2 * plane.f.z[2]};
    double uv[2];
    CHECK(bsi_surface_def_inverse(&plane, p, NULL, uv) == 1 && fabs(uv[0] - 1.25) < 1e-12 && fabs(uv[1] + 3.5) < 1e-12);
    printf("inverse: worst parameter error %.2e (relative to 1 + |u| + |v|)\n", worst_inverse);
}

/* Points where (u, v) is undefined, kinds without a closed form, and NaN: 0 and uv untouched. */
static void test_inverse_none(void)
{
    bsi_frame f = frame(0.7, -0.4, 1.9, 1.5, -2, 0.25);
    double on_axis[3], centre_circle[3], uv[2] = {7, 8};
    for (int c = 0; c < 3; c++)
        on_axis[c] = f.o[c] + 0.75 * f.z[c];
    const int kinds[4] = {BS_FACE_CYLINDER, BS_FACE_CONE, BS_FACE_SPHERE, BS_FACE_TORUS};
    for (int k = 0; k < 4; k++) {
        bsi_surface_def d = make(kinds[k], f, 2.0, 0.5);
        CHECK(bsi_surface_def_inverse(&d, on_axis, NULL, uv) == 0);
        CHECK(bsi_surface_def_inverse(&d, f.o, NULL, uv) == 0);
    }
    bsi_surface_def torus = make(BS_FACE_TORUS, f, 2.0, 0.5);
    for (int c = 0; c < 3; c++)
        centre_circle[c] = f.o[c] + 2.0 * (cos(1.0) * f.x[c] + sin(1.0) * f.y[c]);
    CHECK(bsi_surface_def_inverse(&torus, centre_circle, NULL, uv) == 0);
    const int none[3] = {BS_FACE_REVOLUTION, BS_FACE_EXTRUSION, BS_FACE_BSPLINE};
    for (int k = 0; k < 3; k++) {
        bsi_surface_def d = make(none[k], f, 2.0, 0.5);
        CHECK(bsi_surface_def_inverse(&d, centre_circle, NULL, uv) == 0);
    }
    /* exactly at u = v = 0: 0, not 2 pi; a NaN hint is no hint */
    bsi_surface_def plain = make(BS_FACE_TORUS, frame(0, 0, 0, 0, 0, 0), 4.0, 2.5);
    double start[3] = {6.5, 0, 0}, nan_hint[2] = {NAN, NAN}, at[2];
    CHECK(bsi_surface_def_inverse(&plain, start, NULL, at) == 1 && at[0] == 0.0 && at[1] == 0.0);
    start[1] = -1e-300;
    CHECK(bsi_surface_def_inverse(&plain, start, nan_hint, at) == 1 && at[0] >= 0.0 && at[0] < 2 * PI);
    CHECK(angle_gap(at[0], 0.0, 2 * PI) < 1e-15);
    double nan_point[3] = {NAN, 0, 0};
    CHECK(bsi_surface_def_inverse(&torus, nan_point, NULL, uv) == 0);
    CHECK(uv[0] == 7 && uv[1] == 8);
}

/* Worst distance of the patches (through the axes' maps) from ref at a 13 x 13 grid of the box
 * and at every break, relative to scale. */
typedef void (*ref_fn)(const void *ctx, long double u, long double v, long double *p);

static double worst_error(const bsi_surface_def *d, const double *box, double scale, ref_fn ref, const void *ctx)
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
    CHECK(au.breaks[0] == box[0] && au.breaks[au.n] == box[1] && av.breaks[0] == box[2] && av.breaks[av.n] == box[3]);
    double worst = 0.0;
    size_t nu = 13 + au.n + 1, nv = 13 + av.n + 1;
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            double u = i < 13 ? box[0] + (box[1] - box[0]) * (double)i / 12.0 : au.breaks[i - 13];
            double v = j < 13 ? box[2] + (box[3] - box[2]) * (double)j / 12.0 : av.breaks[j - 13];
            u = fmin(u, box[1]), v = fmin(v, box[3]);
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
            ref(ctx, u, v, q);
            long double e = sqrtl((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                  (p[2] - q[2]) * (p[2] - q[2]));
            worst = fmax(worst, (double)e / scale);
        }
    bsi_axis_free(&au);
    bsi_axis_free(&av);
    bs_surface_destroy(s);
    return worst;
}

static void exact_ref(const void *ctx, long double u, long double v, long double *p) { exact(ctx, u, v, p); }

/* Boxes reaching past a sphere's poles, beyond a turn, not starting at 0; spindle tori, cones past
 * the apex, a frame far from the origin. */
static void test_boxes(void)
{
    const bsi_frame far = frame(-2.1, 2.6, 0.3, 40, -75, 120), near = frame(0.7, -0.4, 1.9, 1.5, -2, 0.25);
    struct {
        bsi_surface_def d;
        double box[4];
    } cases[] = {
        {make(BS_FACE_SPHERE, near, 2.0, 0), {0.3, 2.0, 0.5, 2.5}},       /* past the north pole */
        {make(BS_FACE_SPHERE, near, 2.0, 0), {-1.0, 1.0, -3.0, -1.2}},    /* past the south pole */
        {make(BS_FACE_SPHERE, far, 7.0, 0), {-1.0, 9.0, -PI / 2, PI / 2}}, /* beyond a turn, far */
        {make(BS_FACE_SPHERE, near, 2.0, 0), {2.0, 2.0 + 2 * PI, -PI / 2, PI / 2}},
        {make(BS_FACE_TORUS, near, 1.0, 2.5), {0.2, 6.0, -3.0, 3.5}},     /* spindle */
        {make(BS_FACE_TORUS, far, 5.0, 1.0), {-7.0, -6.9, 1.0, 1.0 + 2 * PI}},
        {make(BS_FACE_TORUS, near, 0.0, 1.5), {0, PI, 0.1, 1.6}},         /* major radius 0 */
        {make(BS_FACE_CONE, near, 1.0, -0.6), {1.0, 4.0, -2.0, 5.0}},     /* through the apex */
        {make(BS_FACE_CONE, far, 0.0, 1.2), {0.0, 2 * PI, -3.0, 3.0}},    /* apex at o, steep */
        {make(BS_FACE_CYLINDER, far, 0.5, 0), {-20.0, 20.0, -1e3, 1e3}},
        {make(BS_FACE_PLANE, far, 0, 0), {-1e3, 1e-3, 7.0, 7.5}},
    };
    double worst = 0.0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const bsi_surface_def *d = &cases[k].d;
        double o = hypot(hypot(d->f.o[0], d->f.o[1]), d->f.o[2]);
        const double *b = cases[k].box;
        double ext = d->kind == BS_FACE_PLANE ? fmax(fmax(fabs(b[0]), fabs(b[1])), fmax(fabs(b[2]), fabs(b[3])))
                     : d->kind == BS_FACE_CONE ? fabs(d->r) + 5.0 * (1.0 + fabs(tan(d->r2)))
                     : d->kind == BS_FACE_CYLINDER ? d->r + fmax(fabs(b[2]), fabs(b[3]))
                                                    : d->r + d->r2;
        double e = worst_error(d, b, o + ext, exact_ref, d);
        CHECKF(e <= 1e-15, "case %zu (kind %d): worst %.3g of the scale", k, d->kind, e);
        worst = fmax(worst, e);
    }
    printf("boxes past poles and turns: worst distance from the closed form %.2e of the scale\n", worst);
}

/* A rational quadratic B-spline curve of 4 points and its frame, evaluated in long double. */
typedef struct rev_ref {
    const double *knots, *ctrl, *w;
    size_t count;
    const bsi_frame *f;
} rev_ref;

static void curve_ld(const rev_ref *r, long double t, long double *q)
{
    size_t i = 2; /* span: t[i] <= t < t[i+1] */
    while (i + 1 < r->count && r->knots[i + 1] <= t)
        i++;
    long double h[3][4];
    for (size_t k = 0; k < 3; k++) {
        size_t j = i - 2 + k;
        for (int c = 0; c < 3; c++)
            h[k][c] = (long double)r->ctrl[3 * j + (size_t)c] * r->w[j];
        h[k][3] = r->w[j];
    }
    for (size_t lev = 1; lev <= 2; lev++)
        for (size_t k = 2; k >= lev; k--) {
            size_t j = i - 2 + k;
            long double a = (t - r->knots[j]) / ((long double)r->knots[j + 3 - lev] - r->knots[j]);
            for (int c = 0; c < 4; c++)
                h[k][c] = (1 - a) * h[k - 1][c] + a * h[k][c];
        }
    for (int c = 0; c < 3; c++)
        q[c] = h[2][c] / h[2][3];
}

static void revolved(const void *ctx, long double u, long double v, long double *p)
{
    const rev_ref *r = ctx;
    long double q[3], rel[3], h = 0, radial[3], perp[3];
    curve_ld(r, v, q);
    for (int c = 0; c < 3; c++) {
        rel[c] = q[c] - r->f->o[c];
        h += rel[c] * r->f->z[c];
    }
    for (int c = 0; c < 3; c++)
        radial[c] = rel[c] - h * r->f->z[c];
    const double *z = r->f->z;
    perp[0] = z[1] * radial[2] - z[2] * radial[1];
    perp[1] = z[2] * radial[0] - z[0] * radial[2];
    perp[2] = z[0] * radial[1] - z[1] * radial[0];
    for (int c = 0; c < 3; c++)
        p[c] = r->f->o[c] + h * z[c] + cosl(u) * radial[c] + sinl(u) * perp[c];
}

static void extruded(const void *ctx, long double u, long double v, long double *p)
{
    const rev_ref *r = ctx;
    long double q[3];
    curve_ld(r, u, q);
    for (int c = 0; c < 3; c++)
        p[c] = q[c] + v * r->f->x[c]; /* the sweep is the frame's x here */
}

static void test_rational_sweeps(void)
{
    static const double knots[7] = {0, 0, 0, 1, 2.5, 2.5, 2.5}; /* 4 points, 2 spans */
    static const double ctrl[12] = {3, 0, -1, 4, 1, 0.5, 2.5, -1, 2, 3.5, 0.5, 3};
    static const double w[4] = {1, 2.5, 0.5, 1.5};
    bsi_curve c;
    CHECK_STATUS(bsi_curve_bspline(3, 2, 4, knots, ctrl, w, 0.0, 2.5, &c), BS_OK);
    bsi_frame f = frame(0.3, 0.2, -0.5, 0.5, -0.25, 1.0);
    rev_ref r = {knots, ctrl, w, 4, &f};
    bsi_surface_def d = make(BS_FACE_REVOLUTION, f, 0, 0);
    d.curve = &c;
    const double boxes[3][4] = {{0.0, 2 * PI, 0.0, 2.5}, {-0.4, 2.0, 0.3, 0.9}, {1.0, 8.5, 0.7, 2.2}};
    double worst = 0.0;
    for (int k = 0; k < 3; k++) {
        double e = worst_error(&d, boxes[k], 8.0, revolved, &r);
        CHECKF(e <= 1e-15, "revolution box %d: %.3g", k, e);
        worst = fmax(worst, e);
    }
    d.kind = BS_FACE_EXTRUSION;
    memcpy(d.dir, f.x, sizeof d.dir);
    const double ebox[4] = {0.2, 1.7, -2.0, 0.5};
    double e = worst_error(&d, ebox, 8.0, extruded, &r);
    CHECKF(e <= 1e-15, "extrusion: %.3g", e);
    worst = fmax(worst, e);
    printf("rational B-spline revolved and extruded: worst %.2e of the scale\n", worst);
    /* the box outside the curve's range, a curve of the wrong dimension or range */
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    const double outside[4] = {0.0, 1.0, 3.0, 4.0};
    d.kind = BS_FACE_REVOLUTION;
    CHECK_STATUS(bsi_surface_def_patches(&d, outside, s, &au, &av), BS_ERR_DOMAIN);
    d.f.z[0] += 1e-6; /* not a unit axis */
    CHECK_STATUS(bsi_surface_def_patches(&d, boxes[1], s, &au, &av), BS_ERR_DOMAIN);
    d.kind = BS_FACE_EXTRUSION;
    d.dir[1] = NAN;
    CHECK_STATUS(bsi_surface_def_patches(&d, ebox, s, &au, &av), BS_ERR_DOMAIN);
    d.dir[0] = d.dir[1] = d.dir[2] = 0.0; /* no sweep */
    CHECK_STATUS(bsi_surface_def_patches(&d, ebox, s, &au, &av), BS_ERR_DOMAIN);
    CHECK(bs_surface_count(s) == 0 && au.n == 0 && av.n == 0);
    bs_surface_destroy(s);
    bsi_curve_free(&c);
}

/* Refusals of the analytic kinds and B-splines not in test_analytic; s unchanged. */
static void test_refusals(void)
{
    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    bsi_frame f = frame(0.7, -0.4, 1.9, 1.5, -2, 0.25);
    const double box[4] = {0, 1, 0, 1}, nan_box[4] = {0, 1, NAN, 1}, reversed[4] = {0, 1, 1, 0};
    bsi_surface_def ok = make(BS_FACE_TORUS, f, 2.0, 0.5);
    CHECK_STATUS(bsi_surface_def_patches(&ok, box, s, &au, &av), BS_OK);
    bsi_axis_free(&au);
    bsi_axis_free(&av);
    size_t before = bs_surface_count(s);
    CHECK_STATUS(bsi_surface_def_patches(&ok, nan_box, s, &au, &av), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_surface_def_patches(&ok, reversed, s, &au, &av), BS_ERR_DOMAIN);
    bsi_surface_def bad[] = {make(BS_FACE_CYLINDER, f, 0.0, 0), make(BS_FACE_SPHERE, f, NAN, 0),
                             make(BS_FACE_TORUS, f, 2.0, 0.0), make(BS_FACE_TORUS, f, -1.0, 0.5),
                             make(BS_FACE_CONE, f, 1.0, -1.5707963267948966), make(BS_FACE_CONE, f, -1.0, 0.2),
                             make(BS_FACE_BEZIER, f, 1.0, 0), make(BS_FACE_PLANE, f, 0, 0)};
    bad[7].f.z[0] = -bad[7].f.z[0], bad[7].f.z[1] = -bad[7].f.z[1], bad[7].f.z[2] = -bad[7].f.z[2]; /* left-handed */
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        CHECKF(bsi_surface_def_patches(&bad[k], box, s, &au, &av) == BS_ERR_DOMAIN, "bad def %zu", k);
    bsi_surface_def nans[4] = {make(BS_FACE_CONE, f, NAN, 0.2), make(BS_FACE_CONE, f, 1.0, NAN),
                               make(BS_FACE_TORUS, f, NAN, 0.5), make(BS_FACE_TORUS, f, 2.0, NAN)};
    for (size_t k = 0; k < 4; k++)
        CHECKF(bsi_surface_def_patches(&nans[k], box, s, &au, &av) == BS_ERR_DOMAIN, "NaN radius %zu", k);
    for (int c = 0; c < 4; c++) {
        double b[4] = {0, 1, 0, 1};
        b[c] = c % 2 ? INFINITY : NAN;
        CHECKF(bsi_surface_def_patches(&ok, b, s, &au, &av) == BS_ERR_DOMAIN, "box end %d", c);
    }
    /* sweeps without a 3-D curve, or about an axis through a point at infinity */
    const double lp[3] = {1, 0, 0}, ld[3] = {0, 0, 1};
    bsi_curve flat_line, line;
    CHECK_STATUS(bsi_curve_line(2, lp, ld, 0.0, 1.0, &flat_line), BS_OK);
    CHECK_STATUS(bsi_curve_line(3, lp, ld, 0.0, 1.0, &line), BS_OK);
    bsi_surface_def sw = make(BS_FACE_REVOLUTION, f, 0, 0);
    CHECK_STATUS(bsi_surface_def_patches(&sw, box, s, &au, &av), BS_ERR_INVALID_ARG);
    sw.curve = &flat_line;
    CHECK_STATUS(bsi_surface_def_patches(&sw, box, s, &au, &av), BS_ERR_INVALID_ARG);
    sw.curve = &line;
    sw.f.o[2] = NAN;
    CHECK_STATUS(bsi_surface_def_patches(&sw, box, s, &au, &av), BS_ERR_DOMAIN);
    bsi_curve_free(&flat_line);
    bsi_curve_free(&line);
    bsi_surface_def far = make(BS_FACE_PLANE, f, 0, 0);
    far.f.o[1] = INFINITY;
    CHECK_STATUS(bsi_surface_def_patches(&far, box, s, &au, &av), BS_ERR_DOMAIN);
    /* a B-spline in 2-D and one with bad knots */
    const double k4[4] = {0, 0, 1, 1}, kbad[4] = {0, 1, 0, 1}, ctrl[12] = {0, 0, 1, 0, 0, 1, 1, 1, 0, 0, 0, 0};
    bs_bspline flat = {1, 1, 2, 2, 2, k4, k4, ctrl, NULL}, knotted = {1, 1, 2, 2, 3, kbad, k4, ctrl, NULL};
    bsi_surface_def bs = make(BS_FACE_BSPLINE, f, 0, 0);
    bs.bspline = &flat;
    CHECK(bsi_surface_def_patches(&bs, box, s, &au, &av) != BS_OK);
    bs.bspline = &knotted;
    CHECK(bsi_surface_def_patches(&bs, box, s, &au, &av) != BS_OK);
    bs.bspline = NULL;
    CHECK(bsi_surface_def_patches(&bs, box, s, &au, &av) != BS_OK);
    bs_bspline square = {1, 1, 2, 2, 3, k4, k4, ctrl, NULL};
    const double beside[4] = {0.2, 0.8, 1.5, 2.0};
    bs.bspline = &square;
    CHECK_STATUS(bsi_surface_def_patches(&bs, beside, s, &au, &av), BS_ERR_DOMAIN);
    double at[3];
    bsi_surface_def_eval(&bs, 0.25, 0.5, at); /* (1 - u) (1 - v) P00 + ... of the bilinear net */
    CHECK(fabs(at[0] - 0.125) < 1e-15 && fabs(at[1] - 0.125) < 1e-15 && fabs(at[2] - 0.75) < 1e-15);
    CHECK(bs_surface_count(s) == before && au.n == 0 && av.n == 0);
    /* periods */
    double pu, pv;
    const int kinds[8] = {BS_FACE_BSPLINE, BS_FACE_PLANE, BS_FACE_CYLINDER, BS_FACE_CONE,
                          BS_FACE_SPHERE, BS_FACE_TORUS, BS_FACE_REVOLUTION, BS_FACE_EXTRUSION};
    for (int k = 0; k < 8; k++) {
        bsi_surface_def d = make(kinds[k], f, 1, 0);
        bsi_surface_def_periods(&d, &pu, &pv);
        int closed_u = kinds[k] >= BS_FACE_CYLINDER && kinds[k] <= BS_FACE_REVOLUTION;
        CHECK(pu == (closed_u ? 2 * PI : 0.0) && pv == (kinds[k] == BS_FACE_TORUS ? 2 * PI : 0.0));
    }
    bs_surface_destroy(s);
}

/* bsi_surface_def_eval of the analytic kinds against the long double closed form; a sweep's point
 * outside its curve's range is NaN; control points overflowing to infinity: BS_ERR_NONFINITE. */
static void test_eval_and_overflow(void)
{
    const bsi_frame f = frame(0.7, -0.4, 1.9, 1.5, -2, 0.25);
    const int kinds[5] = {BS_FACE_PLANE, BS_FACE_CYLINDER, BS_FACE_CONE, BS_FACE_SPHERE, BS_FACE_TORUS};
    double worst = 0.0;
    for (int k = 0; k < 5; k++) {
        bsi_surface_def d = make(kinds[k], f, 2.0, kinds[k] == BS_FACE_CONE ? 0.3 : 0.75);
        for (int i = 0; i < 20; i++) {
            double u = -4.0 + 0.47 * i, v = 1.3 - 0.13 * i, p[3];
            long double q[3];
            bsi_surface_def_eval(&d, u, v, p);
            exact(&d, u, v, q);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, (double)fabsl(p[c] - q[c]) / 8.0);
        }
    }
    CHECKF(worst <= 1e-15, "closed forms: %.3g", worst);
    const double line_p[3] = {3, 0, 0}, line_d[3] = {0, 0, 1};
    bsi_curve line;
    CHECK_STATUS(bsi_curve_line(3, line_p, line_d, 0.0, 1.0, &line), BS_OK);
    bsi_surface_def rev = make(BS_FACE_REVOLUTION, f, 0, 0);
    rev.curve = &line;
    double p[3];
    bsi_surface_def_eval(&rev, 0.5, 1.5, p);
    CHECK(isnan(p[0]) && isnan(p[1]) && isnan(p[2]));

    bs_surface *s = NULL;
    bsi_axis au, av;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    /* the middle arc point of a quarter turn is sqrt 2 times the radius: past DBL_MAX */
    bsi_surface_def huge = make(BS_FACE_CYLINDER, frame(0, 0, 0, 0, 0, 0), 1.5e308, 0);
    const double quarter[4] = {-PI / 4, PI / 4, 0, 1};
    CHECK_STATUS(bsi_surface_def_patches(&huge, quarter, s, &au, &av), BS_ERR_NONFINITE);
    const double far_p[3] = {1.5e308, 0, 0};
    bsi_curve far_line;
    CHECK_STATUS(bsi_curve_line(3, far_p, line_d, 0.0, 1.0, &far_line), BS_OK);
    rev.curve = &far_line;
    rev.f = frame(0, 0, 0, 0, 0, 0);
    CHECK_STATUS(bsi_surface_def_patches(&rev, quarter, s, &au, &av), BS_ERR_NONFINITE);
    bsi_surface_def ext = make(BS_FACE_EXTRUSION, f, 0, 0);
    ext.curve = &far_line;
    ext.dir[0] = 1e308;
    const double sweep[4] = {0, 1, 0, 1};
    CHECK_STATUS(bsi_surface_def_patches(&ext, sweep, s, &au, &av), BS_ERR_NONFINITE);
    CHECK(bs_surface_count(s) == 0 && au.n == 0 && av.n == 0);
    bs_surface_destroy(s);
    bsi_curve_free(&line);
    bsi_curve_free(&far_line);
}

#ifdef BS_WRAP_MALLOC
/* Every allocation failing in turn: BS_ERR_NO_MEMORY, s unchanged, the axes empty; then success. */
static void test_no_memory(void)
{
    static const double knots[7] = {0, 0, 0, 1, 2.5, 2.5, 2.5};
    static const double ctrl[12] = {3, 0, -1, 4, 1, 0.5, 2.5, -1, 2, 3.5, 0.5, 3};
    static const double w[4] = {1, 2.5, 0.5, 1.5};
    bsi_curve c;
    CHECK_STATUS(bsi_curve_bspline(3, 2, 4, knots, ctrl, w, 0.0, 2.5, &c), BS_OK);
    const double ku[5] = {0, 0, 0.5, 1, 1}, kv[4] = {0, 0, 1, 1};
    double net[3 * 2 * 3];
    for (int i = 0; i < 18; i++)
        net[i] = sin(1.0 + i);
    bs_bspline b = {1, 1, 3, 2, 3, ku, kv, net, NULL};
    bsi_frame f = frame(0.3, 0.2, -0.5, 0.5, -0.25, 1.0);
    bsi_surface_def defs[4] = {make(BS_FACE_TORUS, f, 2.0, 0.5), make(BS_FACE_REVOLUTION, f, 0, 0),
                               make(BS_FACE_EXTRUSION, f, 0, 0), make(BS_FACE_BSPLINE, f, 0, 0)};
    defs[1].curve = defs[2].curve = &c;
    memcpy(defs[2].dir, f.z, sizeof defs[2].dir);
    defs[3].bspline = &b;
    const double box[4] = {0.1, 2.0, 0.2, 0.9};
    int failures = 0;
    for (int k = 0; k < 4; k++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create(&s), BS_OK);
        bs_status st = BS_ERR_NO_MEMORY;
        for (size_t n = 1; n < 200 && st == BS_ERR_NO_MEMORY; n++) {
            bsi_axis au, av;
            fail_in = n;
            st = bsi_surface_def_patches(&defs[k], box, s, &au, &av);
            fail_in = 0;
            if (st == BS_ERR_NO_MEMORY) {
                failures++;
                CHECK(bs_surface_count(s) == 0 && au.n == 0 && av.n == 0);
            } else {
                CHECKF(st == BS_OK, "kind %d: status %d", defs[k].kind, st);
                CHECK(bs_surface_count(s) == au.n * av.n && au.n > 0);
                bsi_axis_free(&au);
                bsi_axis_free(&av);
            }
        }
        bs_surface_destroy(s);
    }
    CHECK(failures >= 8);
    bsi_curve_free(&c);
}
#endif

int main(void)
{
    test_inverse();
    test_inverse_none();
    test_boxes();
    test_rational_sweeps();
    test_refusals();
    test_eval_and_overflow();
#ifdef BS_WRAP_MALLOC
    test_no_memory();
#endif
    return bs_test_exit("test_analytic_inverse");
}
