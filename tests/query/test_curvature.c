/* Curvature: random patches against the fundamental forms in long double (tests/support/
 * reference.h), exact surfaces (sphere with a pole, cylinder), limits at poles (sphere, the
 * teapot's lid) and a cone's apex, and every argument rule. */
#include "harness.h"
#include "reference.h"
#include "shapes.h"

#include <bezsurf.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct result {
    double k[4], dmin[3], dmax[3];
    unsigned char kind;
} result;

static bs_status curvature_at(const bs_patch *p, double u, double v, result *r)
{
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view k[4], a[3], b[3];
    for (int i = 0; i < 4; i++)
        k[i] = (bs_view){&r->k[i], 1, 0};
    for (int i = 0; i < 3; i++) {
        a[i] = (bs_view){&r->dmin[i], 1, 0};
        b[i] = (bs_view){&r->dmax[i], 1, 0};
    }
    return bs_patch_eval_curvature(p, 1, &cu, &cv, k, a, b, &r->kind);
}

static double normal_at(const bs_patch *p, double u, double v, double n[3])
{
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
    unsigned char kind;
    return bs_patch_eval_normal(p, 1, &cu, &cv, NULL, nv, &kind) == BS_OK ? kind : -1;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Directions: unit, orthogonal, (dmin, dmax, N) right-handed. */
static void check_frame(const result *r, const double n[3])
{
    double c[3] = {r->dmin[1] * r->dmax[2] - r->dmin[2] * r->dmax[1],
                   r->dmin[2] * r->dmax[0] - r->dmin[0] * r->dmax[2],
                   r->dmin[0] * r->dmax[1] - r->dmin[1] * r->dmax[0]};
    CHECKF(fabs(dot3(r->dmin, r->dmin) - 1) < 1e-12 && fabs(dot3(r->dmax, r->dmax) - 1) < 1e-12 &&
               fabs(dot3(r->dmin, r->dmax)) < 1e-12 && fabs(dot3(c, n) - 1) < 1e-9,
           "frame: |dmin|^2-1 %.2g, dmin.dmax %.2g, (dmin x dmax).N %.12g",
           dot3(r->dmin, r->dmin) - 1, dot3(r->dmin, r->dmax), dot3(c, n));
}

static double worst_regular, worst_angle; /* errors over the scale, and in radians */
static double worst_limit;                /* error at the sphere's pole over the scale */

/* The fundamental forms of a net at (u, v) in long double: the first partials d[0..1], the
 * second d[2..4], the unit normal N, and K, H, k_min, k_max in want[]. */
typedef struct ref_forms {
    long double d[5][3], N[3], E, F, G, L, M, NN, want[4];
} ref_forms;

static void ref_curvature(const ref_net *net, long double u, long double v, ref_forms *f)
{
    long double(*d)[3] = f->d;
    static const unsigned ab[5][2] = {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    for (int j = 0; j < 5; j++)
        ref_deriv(net, ab[j][0], ab[j][1], u, v, d[j]);
    long double cr[3] = {d[0][1] * d[1][2] - d[0][2] * d[1][1], d[0][2] * d[1][0] - d[0][0] * d[1][2],
                         d[0][0] * d[1][1] - d[0][1] * d[1][0]};
    long double wl = sqrtl(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    for (int c = 0; c < 3; c++)
        f->N[c] = cr[c] / wl;
    f->E = f->F = f->G = f->L = f->M = f->NN = 0;
    for (int c = 0; c < 3; c++) {
        f->E += d[0][c] * d[0][c];
        f->F += d[0][c] * d[1][c];
        f->G += d[1][c] * d[1][c];
        f->L += d[2][c] * f->N[c];
        f->M += d[3][c] * f->N[c];
        f->NN += d[4][c] * f->N[c];
    }
    long double W = f->E * f->G - f->F * f->F, K = (f->L * f->NN - f->M * f->M) / W;
    long double H = (f->E * f->NN - 2 * f->F * f->M + f->G * f->L) / (2 * W);
    long double s = sqrtl(fmaxl(H * H - K, 0.0L));
    f->want[0] = K;
    f->want[1] = H;
    f->want[2] = H - s;
    f->want[3] = H + s;
}

/* One random point of a random patch against the long double fundamental forms. */
static void against_reference(const bs_patch *p, const double *ctrl, const double *w, size_t m,
                              size_t n, double u, double v, double inv_d)
{
    ref_net net = {m, n, 3, ctrl, w};
    ref_forms rf;
    ref_curvature(&net, u, v, &rf);
    long double(*d)[3] = rf.d, *N = rf.N, E = rf.E, F = rf.F, G = rf.G, L = rf.L, M = rf.M, NN = rf.NN;
    long double kmin = rf.want[2], kmax = rf.want[3], s = 0.5L * (kmax - kmin);
    result r;
    CHECK_STATUS(curvature_at(p, u, v, &r), BS_OK);
    CHECK(r.kind == BS_CURV_REGULAR);
    double scale = fabs((double)kmin) + fabs((double)kmax) + inv_d;
    for (int i = 0; i < 4; i++) {
        double e = (double)fabsl((long double)r.k[i] - rf.want[i]) / (i == 0 ? scale * scale : scale);
        worst_regular = fmax(worst_regular, e);
        CHECKF(e <= 1e-9, "(%g,%g) value %d: error %.3g of the scale", u, v, i, e);
    }
    double nd[3] = {(double)N[0], (double)N[1], (double)N[2]};
    check_frame(&r, nd);
    if (2 * s < 1e-3L * scale)
        return; /* near an umbilic the directions are ill-conditioned */
    /* the direction of k_max: (II - k_max I) t = 0, from the better-conditioned row */
    long double a1 = M - kmax * F, b1 = -(L - kmax * E), a2 = NN - kmax * G, b2 = -(M - kmax * F);
    long double du = fabsl(a1) + fabsl(b1) > fabsl(a2) + fabsl(b2) ? a1 : a2;
    long double dv = fabsl(a1) + fabsl(b1) > fabsl(a2) + fabsl(b2) ? b1 : b2;
    long double t[3], tl = 0;
    for (int c = 0; c < 3; c++) {
        t[c] = du * d[0][c] + dv * d[1][c];
        tl += t[c] * t[c];
    }
    /* the sine of the angle between the lines, from the cross product (a sine from the cosine
     * would measure the rounding of |dmax| instead) */
    long double x[3], dl = 0, xl = 0;
    for (int c = 0; c < 3; c++)
        dl += (long double)r.dmax[c] * r.dmax[c];
    x[0] = t[1] * r.dmax[2] - t[2] * r.dmax[1];
    x[1] = t[2] * r.dmax[0] - t[0] * r.dmax[2];
    x[2] = t[0] * r.dmax[1] - t[1] * r.dmax[0];
    for (int c = 0; c < 3; c++)
        xl += x[c] * x[c];
    double sinang = (double)sqrtl(xl / (tl * dl));
    worst_angle = fmax(worst_angle, sinang);
    CHECKF(sinang <= 1e-8, "(%g,%g): k_max direction off by %.3g rad", u, v, sinang);
}

static void random_patches(void)
{
    unsigned long long rng = 99;
    double ctrl[8 * 8 * 3], w[64];
    for (int trial = 0; trial < 70; trial++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 5), n = 1 + (size_t)(bs_test_rand_u64(&rng) % 5);
        if (m + n < 3)
            m = 2;
        if (trial >= 60) /* and bicubic ones, which have their own kernel */
            m = n = 3;
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (size_t k = 0; k < (m + 1) * (n + 1); k++) {
            for (int c = 0; c < 3; c++) {
                double base = c == 0 ? (double)(k / (n + 1)) : c == 1 ? (double)(k % (n + 1)) : 0.0;
                ctrl[3 * k + (size_t)c] = base + bs_test_rand(&rng, -0.4, 0.4);
                lo[c] = fmin(lo[c], ctrl[3 * k + (size_t)c]);
                hi[c] = fmax(hi[c], ctrl[3 * k + (size_t)c]);
            }
            w[k] = bs_test_rand(&rng, 0.5, 2.0);
        }
        int rational = trial % 2;
        bs_patch *p;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? w : NULL, &p), BS_OK);
        double inv_d = 1.0 / hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
        for (int k = 0; k < 20; k++)
            against_reference(p, ctrl, rational ? w : NULL, m, n, bs_test_rand(&rng, 0, 1),
                              bs_test_rand(&rng, 0, 1), inv_d);
        bs_patch_destroy(p);
    }
}

/* The octant of a sphere of radius R as a surface of revolution (rational biquadratic): u along
 * the meridian from the pole (the collapsed side u = 0), v around the axis. */
#define R 2.5
static bs_patch *sphere_octant(void)
{
    bs_patch *p = shape_sphere_octant(R);
    CHECK(p != NULL);
    return p;
}

static void sphere(void)
{
    bs_patch *p = sphere_octant();
    const double pts[][2] = {{0.3, 0.7}, {0.9, 0.1}, {0.5, 0.5}, {1.0, 1.0}, {0.0, 0.3}, {0.0, 1.0}};
    for (size_t k = 0; k < sizeof pts / sizeof pts[0]; k++) {
        double u = pts[k][0], v = pts[k][1], nrm[3];
        result r;
        CHECK_STATUS(curvature_at(p, u, v, &r), BS_OK);
        int kind = (int)normal_at(p, u, v, nrm);
        CHECK(r.kind == (u == 0.0 ? BS_CURV_LIMIT : BS_CURV_REGULAR) && kind == (int)r.kind);
        double x[3];
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, xv, NULL, NULL), BS_OK);
        double outward = dot3(nrm, x) / R; /* +1 or -1; outward normals give k = -1/R */
        double tol = r.kind == BS_CURV_LIMIT ? 1e-6 : 1e-9, scale = 2.0 / R;
        CHECKF(fabs(fabs(outward) - 1) < 1e-12, "normal not radial: %.17g", outward);
        CHECKF(fabs(r.k[0] - 1 / (R * R)) <= tol * scale * scale, "K %.17g at (%g,%g)", r.k[0], u, v);
        for (int i = 1; i < 4; i++) {
            CHECKF(fabs(r.k[i] + outward / R) <= tol * scale, "k%d %.17g at (%g,%g)", i, r.k[i], u, v);
            if (r.kind == BS_CURV_LIMIT)
                worst_limit = fmax(worst_limit, fabs(r.k[i] + outward / R) / scale);
        }
        check_frame(&r, nrm);
        if (r.kind == BS_CURV_REGULAR) { /* umbilic: dmin is S_u made unit */
            double su[3];
            bs_view sv[3] = {{&su[0], 1, 0}, {&su[1], 1, 0}, {&su[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, NULL, sv, NULL), BS_OK);
            double l = sqrt(dot3(su, su));
            CHECKF(fabs(dot3(su, r.dmin) / l - 1) < 1e-12, "umbilic dmin not S_u: %.3g", dot3(su, r.dmin) / l - 1);
        }
    }
    bs_patch_destroy(p);
}

static void cylinder(void)
{
    double ctrl[18], w[6];
    shape_cylinder_quarter(R, 4.0, ctrl, w);
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(1, 2, 3, ctrl, w, &p), BS_OK);
    for (int k = 0; k <= 4; k++) {
        double u = k / 4.0, v = (k * 3 % 5) / 4.0, nrm[3];
        result r;
        CHECK_STATUS(curvature_at(p, u, v, &r), BS_OK);
        normal_at(p, u, v, nrm);
        double radial = nrm[0] * nrm[0] + nrm[1] * nrm[1]; /* N is horizontal */
        CHECK(r.kind == BS_CURV_REGULAR && fabs(radial - 1) < 1e-12);
        /* zero along the axis, -+1/R around it */
        double zero = fabs(r.k[2]) < fabs(r.k[3]) ? r.k[2] : r.k[3];
        double bent = fabs(r.k[2]) < fabs(r.k[3]) ? r.k[3] : r.k[2];
        const double *axis_dir = fabs(r.k[2]) < fabs(r.k[3]) ? r.dmin : r.dmax;
        CHECKF(fabs(zero) <= 1e-9 * 2 / R && fabs(fabs(bent) - 1 / R) <= 1e-9 * 2 / R &&
                   fabs(r.k[0]) <= 1e-9 * 4 / (R * R),
               "cylinder k %.17g %.17g K %.3g", zero, bent, r.k[0]);
        CHECKF(fabs(fabs(axis_dir[2]) - 1) < 1e-12, "axis direction %.17g", axis_dir[2]);
        check_frame(&r, nrm);
    }
    bs_patch_destroy(p);
}

/* The teapot's lid and bottom have poles shared by four patches: the limit is the same from
 * each, and the curvature next to the pole tends to it. */
static void teapot_poles(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    int limits = 0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        for (int corner = 0; corner < 4; corner++) {
            double u = corner & 1, v = corner >> 1, nrm[3];
            if (normal_at(p, u, v, nrm) != BS_NORMAL_LIMIT)
                continue;
            result r, near;
            CHECK_STATUS(curvature_at(p, u, v, &r), BS_OK);
            CHECKF(r.kind == BS_CURV_LIMIT, "patch %zu corner %d: kind %d", i, corner, r.kind);
            if (r.kind != BS_CURV_LIMIT)
                continue;
            limits++;
            double h = 1e-4, un = u + h * (0.5 - u), vn = v + h * (0.5 - v);
            CHECK_STATUS(curvature_at(p, un, vn, &near), BS_OK);
            double scale = fabs(r.k[2]) + fabs(r.k[3]) + 0.1;
            CHECKF(fabs(near.k[1] - r.k[1]) < 1e-2 * scale, "patch %zu: H %.9g at the pole, %.9g next to it",
                   i, r.k[1], near.k[1]);
            check_frame(&r, nrm);
        }
    }
    CHECKF(limits >= 8, "only %d limit points found on the teapot", limits);
    bs_surface_destroy(s);
}

/* Every point of the teapot's collapsed edges (u or v = 0 or 1 on a side that is one point,
 * at k / 20 along it) is a limit point whose curvature exists (the lid and the bottom are
 * smooth there): its kind is LIMIT and its values within 1e-6 of the scale of the limit along
 * the line to the centre, from the long double forms at h = 2^-24 and 2^-25 extrapolated
 * linearly (the curvature is nearly linear in h there). */
static void teapot_collapsed_edges(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    int points = 0;
    double worst = 0.0;
    for (size_t i = 0; s != NULL && i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        double ctrl[16 * 3], w[16];
        CHECK_STATUS(bs_patch_get_ctrl(p, ctrl, 48, w, 16), BS_OK);
        ref_net net = {3, 3, 3, ctrl, w};
        for (int side = 0; side < 4; side++) {
            double ends[2][3];
            for (int e = 0; e < 2; e++) {
                double u = side < 2 ? side : e, v = side < 2 ? e : side - 2;
                long double P[3];
                ref_deriv(&net, 0, 0, u, v, P);
                for (int c = 0; c < 3; c++)
                    ends[e][c] = (double)P[c];
            }
            if (ends[0][0] != ends[1][0] || ends[0][1] != ends[1][1] || ends[0][2] != ends[1][2])
                continue; /* not a collapsed side */
            for (int k = 0; k <= 20; k++) {
                double t = k / 20.0, u = side < 2 ? side : t, v = side < 2 ? t : side - 2;
                result r;
                CHECK_STATUS(curvature_at(p, u, v, &r), BS_OK);
                CHECKF(r.kind == BS_CURV_LIMIT, "patch %zu (%g, %g): kind %d", i, u, v, r.kind);
                ref_forms a, b;
                long double h = ldexpl(1.0L, -24);
                ref_curvature(&net, u + h * (0.5L - u), v + h * (0.5L - v), &a);
                ref_curvature(&net, u + 0.5L * h * (0.5L - u), v + 0.5L * h * (0.5L - v), &b);
                double scale = fabs((double)b.want[2]) + fabs((double)b.want[3]) + 0.1;
                for (int q = 0; q < 4 && r.kind == BS_CURV_LIMIT; q++) {
                    long double want = 2.0L * b.want[q] - a.want[q];
                    double e = (double)fabsl((long double)r.k[q] - want) / (q == 0 ? scale * scale : scale);
                    worst = fmax(worst, e);
                    CHECKF(e <= 1e-6, "patch %zu (%g, %g) value %d: %.9g, limit %.9Lg", i, u, v, q, r.k[q], want);
                }
                points++;
            }
        }
    }
    CHECKF(points == 168, "%d points on the teapot's collapsed edges, 168 expected", points);
    printf("teapot collapsed edges: %d limit points, worst %.3g of the scale\n", points, worst);
    bs_surface_destroy(s);
}

/* n points at once (packed outputs) against the same points one by one (the same bits), and
 * each kind against bs_patch_eval_normal's at the point: regular with regular, undefined with
 * undefined, a limit normal giving a limit or undefined curvature. Returns the limits seen. */
enum { KN = 300 };
static int kinds_and_bits(const bs_patch *p, size_t n, const double *u, const double *v)
{
    static double out[10][KN], nrm[3][KN];
    static unsigned char ck[KN], nk[KN];
    bs_cview cu = {u, n, 0}, cv = {v, n, 0};
    bs_view o[10], nv[3];
    for (int i = 0; i < 10; i++)
        o[i] = (bs_view){out[i], n, 0};
    for (int i = 0; i < 3; i++)
        nv[i] = (bs_view){nrm[i], n, 0};
    CHECK_STATUS(bs_patch_eval_curvature(p, n, &cu, &cv, o, o + 4, o + 7, ck), BS_OK);
    CHECK_STATUS(bs_patch_eval_normal(p, n, &cu, &cv, NULL, nv, nk), BS_OK);
    int limits = 0;
    for (size_t k = 0; k < n; k++) {
        int ok = nk[k] == BS_NORMAL_REGULAR ? ck[k] == BS_CURV_REGULAR
                 : nk[k] == BS_NORMAL_LIMIT ? ck[k] == BS_CURV_LIMIT || ck[k] == BS_CURV_UNDEFINED
                                            : ck[k] == BS_CURV_UNDEFINED;
        CHECKF(ok, "(%.17g,%.17g): curvature kind %d, normal kind %d", u[k], v[k], ck[k], nk[k]);
        limits += ck[k] == BS_CURV_LIMIT;
        result r;
        CHECK_STATUS(curvature_at(p, u[k], v[k], &r), BS_OK);
        int same = r.kind == ck[k];
        for (int i = 0; i < 4; i++)
            same &= memcmp(&r.k[i], &out[i][k], sizeof(double)) == 0;
        for (int i = 0; i < 3; i++)
            same &= memcmp(&r.dmin[i], &out[4 + i][k], sizeof(double)) == 0 &&
                    memcmp(&r.dmax[i], &out[7 + i][k], sizeof(double)) == 0;
        CHECKF(same, "(%.17g,%.17g): a batch differs from the point alone", u[k], v[k]);
        if (ck[k] != BS_CURV_UNDEFINED) {
            double nk3[3] = {nrm[0][k], nrm[1][k], nrm[2][k]};
            check_frame(&r, nk3);
        }
    }
    return limits;
}

/* kinds_and_bits on the teapot (bicubic, with collapsed edges and poles) on a grid with its
 * edges and points just inside them, and on polynomial patches of other degrees, some
 * degenerate (a collapsed row, degree 0). */
static void kinds_polynomial(void)
{
    static const double t[17] = {0.0, 1e-12, 1e-6, 0.0625, 0.125, 0.25, 0.3, 0.375, 0.5, 0.6,
                                 0.7, 0.75, 0.875, 0.9375, 1.0 - 1e-6, 1.0 - 1e-12, 1.0};
    double u[KN], v[KN];
    size_t n = 0;
    for (int i = 0; i < 17; i++)
        for (int j = 0; j < 17; j++) {
            u[n] = t[i];
            v[n++] = t[j];
        }
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    int limits = 0;
    for (size_t i = 0; i < bs_surface_count(s); i++)
        limits += kinds_and_bits(bs_surface_get(s, i), n, u, v);
    CHECKF(limits >= 8, "only %d limit points of the teapot's grid", limits);
    bs_surface_destroy(s);
    static const size_t deg[][2] = {{2, 3}, {3, 2}, {5, 1}, {1, 1}, {4, 4}, {3, 3}, {0, 2}, {6, 3}};
    unsigned long long rng = 7;
    double ctrl[7 * 7 * 3];
    for (size_t d = 0; d < sizeof deg / sizeof deg[0]; d++) {
        for (int collapsed = 0; collapsed < 2; collapsed++) {
            size_t m = deg[d][0], nn = deg[d][1];
            for (size_t k = 0; k < (m + 1) * (nn + 1); k++)
                for (size_t c = 0; c < 3; c++) {
                    double base = c == 0 ? (double)(k / (nn + 1)) : c == 1 ? (double)(k % (nn + 1)) : 0.0;
                    /* collapsed: row i = 0 is one point (a pole or collapsed edge at u = 0) */
                    ctrl[3 * k + c] = collapsed && k <= nn ? (c == 2 ? 0.3 : 0.0)
                                                           : base + bs_test_rand(&rng, -0.4, 0.4);
                }
            bs_patch *p;
            CHECK_STATUS(bs_patch_create(m, nn, 3, ctrl, NULL, &p), BS_OK);
            kinds_and_bits(p, n, u, v);
            bs_patch_destroy(p);
        }
    }
}

static void cone_apex(void)
{
    /* S(u,v) = u (a(v), b(v), 1): apex at u = 0 (a collapsed side) */
    const double ctrl[18] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(1, 2, 3, ctrl, NULL, &p), BS_OK);
    result r;
    CHECK_STATUS(curvature_at(p, 0.0, 0.4, &r), BS_OK);
    CHECK(r.kind == BS_CURV_UNDEFINED && isnan(r.k[0]) && isnan(r.k[3]) && isnan(r.dmin[0]) && isnan(r.dmax[2]));
    CHECK_STATUS(curvature_at(p, 0.5, 0.4, &r), BS_OK); /* elsewhere the cone is regular */
    CHECK(r.kind == BS_CURV_REGULAR && fabs(r.k[0]) < 1e-9 && fabs(r.k[2] * r.k[3]) < 1e-9);
    bs_patch_destroy(p);
}

static void arguments(void)
{
    bs_patch *p = sphere_octant(), *q2;
    const double flat[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    CHECK_STATUS(bs_patch_create(1, 1, 2, flat, NULL, &q2), BS_OK);
    double u[3] = {0.2, NAN, 0.7}, v[3] = {0.5, 0.5, INFINITY}, out[4][3], dm[3][3];
    unsigned char kind[3] = {9, 9, 9};
    bs_cview cu = {u, 3, 0}, cv = {v, 3, 0};
    bs_view k[4], d[3];
    for (int i = 0; i < 4; i++)
        k[i] = (bs_view){out[i], 3, 0};
    for (int i = 0; i < 3; i++)
        d[i] = (bs_view){dm[i], 3, 0};
    memset(out, 0, sizeof out);
    CHECK_STATUS(bs_patch_eval_curvature(NULL, 3, &cu, &cv, k, d, d, kind), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_eval_curvature(q2, 3, &cu, &cv, k, d, d, kind), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_patch_eval_curvature(p, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_patch_eval_curvature(p, 3, NULL, &cv, k, NULL, NULL, kind), BS_ERR_INVALID_ARG);
    bs_view short_k[4] = {k[0], k[1], {out[2], 2, 0}, k[3]};
    CHECK_STATUS(bs_patch_eval_curvature(p, 3, &cu, &cv, short_k, NULL, NULL, kind), BS_ERR_SIZE);
    bs_view odd = {(double *)(void *)((char *)dm[0] + 1), 3, 0};
    bs_view odd_d[3] = {odd, d[1], d[2]};
    CHECK_STATUS(bs_patch_eval_curvature(p, 3, &cu, &cv, NULL, odd_d, NULL, kind), BS_ERR_INVALID_ARG);
    CHECK(kind[0] == 9 && out[0][0] == 0.0); /* nothing written by a failed check */
    CHECK_STATUS(bs_patch_eval_curvature(p, 3, &cu, &cv, k, d, NULL, kind), BS_OK);
    CHECK(kind[0] == BS_CURV_REGULAR && kind[1] == BS_CURV_UNDEFINED && kind[2] == BS_CURV_UNDEFINED);
    CHECK(isnan(out[0][1]) && isnan(out[3][2]) && isnan(dm[0][1]) && !isnan(out[0][0]));
    CHECK_STATUS(bs_patch_eval_curvature(p, 3, &cu, &cv, NULL, NULL, NULL, NULL), BS_OK);
    /* strided, in a larger batch: the same values as one by one */
    enum { NB = 70 };
    double ub[NB], vb[NB], res[4][2 * NB];
    for (int i = 0; i < NB; i++) {
        ub[i] = (i % 10) / 9.0;
        vb[i] = (i / 10) / 6.0;
    }
    bs_cview bu = {ub, NB, 0}, bv = {vb, NB, 0};
    bs_view bk[4];
    for (int i = 0; i < 4; i++)
        bk[i] = (bs_view){res[i], NB, 2 * (ptrdiff_t)sizeof(double)};
    CHECK_STATUS(bs_patch_eval_curvature(p, NB, &bu, &bv, bk, NULL, NULL, NULL), BS_OK);
    int same = 1;
    for (int i = 0; i < NB; i++) {
        result r;
        curvature_at(p, ub[i], vb[i], &r);
        for (int c = 0; c < 4; c++)
            same &= memcmp(&r.k[c], &res[c][2 * i], sizeof(double)) == 0;
    }
    CHECK(same);
    bs_patch_destroy(q2);
    bs_patch_destroy(p);
}

int main(void)
{
    random_patches();
    printf("regular points: worst error %.3g of the scale (contract 1e-9), k_max direction %.3g rad "
           "(contract 1e-8)\n", worst_regular, worst_angle);
    sphere();
    printf("limit points (the sphere's pole): worst error %.3g of the scale (contract 1e-6)\n", worst_limit);
    cylinder();
    teapot_poles();
    teapot_collapsed_edges();
    kinds_polynomial();
    cone_apex();
    arguments();
    return bs_test_exit("test_curvature");
}
