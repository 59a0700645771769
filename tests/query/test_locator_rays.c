/* Rays through a locator: rays aimed at known points of the tea set (inside patches, on shared
 * sides, at corners between them and at the lid's pole) from random directions that cross the
 * surface there (|d.N| >= 1e-3 |d|) must hit that point or an earlier one, checked independently
 * (the point reported, evaluated in long double, lies on the surface and on the ray at the t
 * reported); rays leaving the surface for other points of it; a rational sphere octant against
 * the exact intersection with its sphere; misses and t ranges. */
#include "harness.h"
#include "reference.h"
#include "shapes.h"

#include <bezsurf.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

typedef struct hit {
    uint32_t patch;
    double u, v, t, n[3];
} hit;

static bs_status shoot(const bs_locator *L, const double o[3], const double d[3], const double *range,
                       hit *h)
{
    bs_cview ov[3], dv[3], rv[2];
    bs_view uv[2] = {{&h->u, 1, 0}, {&h->v, 1, 0}}, tv = {&h->t, 1, 0};
    bs_view nv[3] = {{&h->n[0], 1, 0}, {&h->n[1], 1, 0}, {&h->n[2], 1, 0}};
    for (int c = 0; c < 3; c++) {
        ov[c] = (bs_cview){&o[c], 1, 0};
        dv[c] = (bs_cview){&d[c], 1, 0};
    }
    for (int c = 0; c < 2 && range; c++)
        rv[c] = (bs_cview){&range[c], 1, 0};
    return bs_locator_intersect(L, 1, ov, dv, range ? rv : NULL, &h->patch, uv, &tv, nv);
}

static void point_normal(const bs_patch *p, double u, double v, double x[3], double n[3], unsigned char *kind)
{
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
    bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, xv, nv, kind), BS_OK);
}

/* S at the hit in long double from the patch's net: on the ray within tau at the hit's t. */
static long double off_ray(const bs_patch *p, const hit *h, const double o[3], const double d[3])
{
    double ctrl[3 * 16 * 16], w[16 * 16];
    size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p);
    bs_patch_get_ctrl(p, ctrl, sizeof ctrl / sizeof ctrl[0], w, sizeof w / sizeof w[0]);
    ref_net net = {m, n, 3, ctrl, bs_patch_is_rational(p) ? w : NULL};
    long double x[3], e = 0;
    ref_eval(&net, h->u, h->v, x);
    for (int c = 0; c < 3; c++)
        e += (x[c] - (o[c] + (long double)h->t * d[c])) * (x[c] - (o[c] + (long double)h->t * d[c]));
    return sqrtl(e);
}

static unsigned long long rng = 12345;

/* A random direction crossing the surface at normal n: |d.n| >= 1e-3 |d|, of random length. */
static void random_dir(const double n[3], double d[3])
{
    double len = exp2(bs_test_rand(&rng, -8, 8));
    for (;;) {
        double a[3] = {bs_test_rand(&rng, -1, 1), bs_test_rand(&rng, -1, 1), bs_test_rand(&rng, -1, 1)};
        double l = sqrt(dot3(a, a));
        if (l > 1 || l < 1e-3)
            continue;
        if (bs_test_rand(&rng, 0, 1) < 0.2) { /* a fifth close to grazing: 1e-3 .. 1e-2 */
            double s = dot3(a, n), tang[3] = {a[0] - s * n[0], a[1] - s * n[1], a[2] - s * n[2]};
            double tl = sqrt(dot3(tang, tang)), c = bs_test_rand(&rng, 1e-3, 1e-2);
            if (tl < 1e-6)
                continue;
            for (int k = 0; k < 3; k++)
                a[k] = tang[k] / tl * sqrt(1 - c * c) + (s < 0 ? -c : c) * n[k];
            l = 1;
        }
        if (fabs(dot3(a, n)) < 1.0001e-3 * l)
            continue;
        for (int k = 0; k < 3; k++)
            d[k] = a[k] / l * len;
        return;
    }
}

typedef struct tally {
    long tried, missed, earlier, late;
    double worst_off, worst_t; /* over tau, and (t - t_aimed) |d| / tau */
} tally;

/* One ray at S(u,v) of patch i. */
static void aim(const bs_surface *s, const bs_locator *L, size_t i, double u, double v, double D, tally *ty)
{
    const bs_patch *p = bs_surface_get(s, i);
    double x[3], n[3], d[3], o[3];
    unsigned char kind;
    point_normal(p, u, v, x, n, &kind);
    if (kind == BS_NORMAL_UNDEFINED)
        return;
    random_dir(n, d);
    double dl = sqrt(dot3(d, d)), t0 = bs_test_rand(&rng, 0.05, 2.0) * D / dl, tau = 1e-9 * D;
    for (int c = 0; c < 3; c++)
        o[c] = x[c] - t0 * d[c];
    hit h;
    ty->tried++;
    CHECK_STATUS(shoot(L, o, d, NULL, &h), BS_OK);
    if (h.patch == UINT32_MAX) {
        ty->missed++;
        CHECKF(0, "miss: patch %zu (%.17g, %.17g) from (%.17g, %.17g, %.17g) dir (%.17g, %.17g, %.17g)",
               i, u, v, o[0], o[1], o[2], d[0], d[1], d[2]);
        return;
    }
    double late = (h.t - t0) * dl / tau;
    ty->worst_t = fmax(ty->worst_t, late);
    if (late > 1) {
        ty->late++;
        CHECKF(0, "late hit: t %.17g aimed %.17g (patch %zu (%g, %g), got %u (%g, %g))", h.t, t0, i, u, v,
               h.patch, h.u, h.v);
    }
    if (late < -1)
        ty->earlier++;
    long double off = off_ray(bs_surface_get(s, h.patch), &h, o, d) / tau;
    ty->worst_off = fmax(ty->worst_off, (double)off);
    CHECKF(off <= 1, "hit off the ray by %.3Lg tau", off);
    CHECKF(h.u >= 0 && h.u <= 1 && h.v >= 0 && h.v <= 1 && h.t > 0, "uv (%g, %g) t %g", h.u, h.v, h.t);
    double hx[3], hn[3];
    point_normal(bs_surface_get(s, h.patch), h.u, h.v, hx, hn, &kind);
    CHECK(h.n[0] == hn[0] && h.n[1] == hn[1] && h.n[2] == hn[2]);
}

/* Control point k (0..3) of side `side` of a bicubic net: u = 0, u = 1, v = 0, v = 1. */
static const double *side_point(const double *ctrl, int side, int k)
{
    int idx = side == 0 ? k : side == 1 ? 12 + k : side == 2 ? 4 * k : 4 * k + 3;
    return ctrl + 3 * idx;
}

static int same_point(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* 1 if side `side` of bicubic patch i is collapsed (a pole) or shared with another patch's side
 * (the same four control points, in order or reversed): the sides a ray cannot slip past. */
static int closed_side(const bs_surface *s, size_t i, int side)
{
    double a[48], b[48];
    bs_patch_get_ctrl(bs_surface_get(s, i), a, 48, NULL, 0);
    int collapsed = 1;
    for (int k = 1; k < 4; k++)
        collapsed &= same_point(side_point(a, side, k), side_point(a, side, 0));
    if (collapsed)
        return 1;
    for (size_t j = 0; j < bs_surface_count(s); j++) {
        bs_patch_get_ctrl(bs_surface_get(s, j), b, 48, NULL, 0);
        for (int t = 0; t < 4; t++) {
            if (j == i && t == side)
                continue;
            int fwd = 1, rev = 1;
            for (int k = 0; k < 4; k++) {
                fwd &= same_point(side_point(a, side, k), side_point(b, t, k));
                rev &= same_point(side_point(a, side, k), side_point(b, t, 3 - k));
            }
            if (fwd || rev)
                return 1;
        }
    }
    return 0;
}

/* Rays at points inside every patch, on every closed side (shared or a pole), and at corners
 * between two closed sides: on an open side rounding may put the ray just outside the surface. */
static void tea_on(bs_surface *s, const char *name, int per_patch, int with_sides)
{
    bs_locator *L = NULL;
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    CHECK(bs_locator_dim(L) == 3);
    double D = shape_diagonal(s);
    tally inside = {0}, sides = {0}, corners = {0};
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        int closed[4];
        for (int side = 0; side < 4; side++)
            closed[side] = with_sides && closed_side(s, i, side);
        for (int k = 0; k < per_patch; k++)
            aim(s, L, i, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), D, &inside);
        for (int k = 0; k < per_patch; k++) {
            double a = bs_test_rand(&rng, 0, 1);
            for (int side = 0; side < 4; side++)
                if (closed[side])
                    aim(s, L, i, side < 2 ? side : a, side < 2 ? a : side - 2, D, &sides);
        }
        for (int c = 0; c < 4; c++) /* corner (u, v) = (c & 1, c >> 1): sides u = c & 1, v = c >> 1 */
            if (closed[c & 1] && closed[2 + (c >> 1)])
                for (int k = 0; k < per_patch / 4; k++)
                    aim(s, L, i, c & 1, c >> 1, D, &corners);
    }
    const char *what[3] = {"inside", "on closed sides", "at closed corners"};
    const tally *ty[3] = {&inside, &sides, &corners};
    for (int k = 0; k < (with_sides ? 3 : 1); k++) {
        printf("%s %s: %ld rays, %ld missed, %ld late, %ld hit earlier; worst off the ray %.2g tau, "
               "worst t past the aimed point %.2g tau\n",
               name, what[k], ty[k]->tried, ty[k]->missed, ty[k]->late, ty[k]->earlier, ty[k]->worst_off,
               ty[k]->worst_t);
        CHECK(ty[k]->missed == 0 && ty[k]->late == 0);
    }
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

static void tea(const char *name, int per_patch)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin(name, &s), BS_OK);
    tea_on(s, name, per_patch, 1);
}

/* The teapot as other nets of the same surface: every patch rational with all weights 2 (the
 * rational path; shared sides stay shared), and elevated to degree (5, 7) (degrees other than
 * 3; sides elevated along u in one patch and along v in the other are no longer the same bits,
 * so only points inside are aimed at). */
static void other_nets(void)
{
    bs_surface *t = NULL, *rat = NULL, *high = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &t), BS_OK);
    CHECK_STATUS(bs_surface_create(&rat), BS_OK);
    CHECK_STATUS(bs_surface_create(&high), BS_OK);
    for (size_t i = 0; i < bs_surface_count(t); i++) {
        double ctrl[48], w[16];
        bs_patch *p = NULL;
        bs_patch_get_ctrl(bs_surface_get(t, i), ctrl, 48, NULL, 0);
        for (int k = 0; k < 16; k++)
            w[k] = 2;
        CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl, w, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(rat, p, NULL), BS_OK);
        bs_patch_destroy(p);
        CHECK_STATUS(bs_patch_elevate(bs_surface_get(t, i), 2, 4, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(high, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    bs_surface_destroy(t);
    tea_on(rat, "teapot, rational", 20, 1);
    tea_on(high, "teapot, degree (5, 7)", 20, 0);
}

/* Rays leaving the surface (t from 1e-6) at S(u,v) of patch i aimed at other surface points
 * crossed transversally: the first hit is there or earlier. */
static void from_surface(const char *name, int count)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin(name, &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    double D = shape_diagonal(s), tau = 1e-9 * D;
    tally ty = {0};
    size_t np = bs_surface_count(s);
    for (int k = 0; k < count; k++) {
        double a[3], b[3], na[3], nb[3], d[3], range[2] = {1e-6, 1e30};
        unsigned char ka, kb;
        const bs_patch *pa = bs_surface_get(s, bs_test_rand_u64(&rng) % np);
        const bs_patch *pb = bs_surface_get(s, bs_test_rand_u64(&rng) % np);
        point_normal(pa, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), a, na, &ka);
        point_normal(pb, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), b, nb, &kb);
        for (int c = 0; c < 3; c++)
            d[c] = b[c] - a[c];
        double dl = sqrt(dot3(d, d));
        if (kb == BS_NORMAL_UNDEFINED || fabs(dot3(d, nb)) < 1e-3 * dl || dl < 1e-3 * D)
            continue;
        hit h;
        ty.tried++;
        CHECK_STATUS(shoot(L, a, d, range, &h), BS_OK);
        if (h.patch == UINT32_MAX) {
            ty.missed++;
            CHECKF(0, "miss from the surface (%.17g, %.17g, %.17g) dir (%.17g, %.17g, %.17g)", a[0], a[1],
                   a[2], d[0], d[1], d[2]);
            continue;
        }
        double late = (h.t - 1) * dl / tau;
        ty.worst_t = fmax(ty.worst_t, late);
        ty.late += late > 1;
        ty.earlier += late < -1;
        CHECKF(late <= 1 && h.t >= range[0], "late hit from the surface: t %.17g", h.t);
        long double off = off_ray(bs_surface_get(s, h.patch), &h, a, d) / tau;
        ty.worst_off = fmax(ty.worst_off, (double)off);
        CHECKF(off <= 1, "hit off the ray by %.3Lg tau", off);
    }
    printf("%s from the surface: %ld rays, %ld missed, %ld late, %ld hit earlier; worst off the ray "
           "%.2g tau\n", name, ty.tried, ty.missed, ty.late, ty.earlier, ty.worst_off);
    CHECK(ty.missed == 0 && ty.late == 0);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

/* The lid's pole (the collapsed sides of the teapot's top patches) from many directions. */
static void pole(void)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    double D = shape_diagonal(s);
    tally ty = {0};
    size_t poles = 0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        double ctrl[48];
        bs_patch_get_ctrl(bs_surface_get(s, i), ctrl, 48, NULL, 0);
        for (int side = 0; side < 4; side++) {
            int collapsed = 1;
            for (int k = 1; k < 4; k++)
                collapsed &= same_point(side_point(ctrl, side, k), side_point(ctrl, side, 0));
            if (!collapsed)
                continue;
            poles++;
            for (int k = 0; k < 50; k++) {
                double a = bs_test_rand(&rng, 0, 1);
                aim(s, L, i, side < 2 ? side : a, side < 2 ? a : side - 2, D, &ty);
            }
        }
    }
    printf("teapot poles: %zu collapsed sides, %ld rays, %ld missed, %ld late\n", poles, ty.tried,
           ty.missed, ty.late);
    CHECK(poles == 8 && ty.missed == 0 && ty.late == 0);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

/* The octant x, y, z >= 0 of the sphere of radius R as a rational biquadratic patch with a pole. */
#define R 2.5
static void sphere(void)
{
    bs_patch *p = shape_sphere_octant(R);
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK(p != NULL);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    bs_surface_destroy(s); /* the locator keeps its own copy */
    double D = R * sqrt(3.0), worst = 0;
    long tried = 0, missed = 0;
    for (int k = 0; k < 2000; k++) {
        /* a point of the octant (the pole among them, not the open sides), a ray from outside */
        double th = k % 10 == 0 ? 0 : bs_test_rand(&rng, 0.001, 0.999) * acos(0.0);
        double ph = bs_test_rand(&rng, 0.001, 0.999) * acos(0.0);
        double x[3] = {R * sin(th) * cos(ph), R * sin(th) * sin(ph), R * cos(th)}, n[3], d[3], o[3];
        for (int c = 0; c < 3; c++)
            n[c] = x[c] / R;
        random_dir(n, d);
        if (dot3(d, n) > 0) /* from outside the sphere: the point is the first hit */
            for (int c = 0; c < 3; c++)
                d[c] = -d[c];
        double dl = sqrt(dot3(d, d)), t0 = bs_test_rand(&rng, 0.1, 3) * R / dl;
        for (int c = 0; c < 3; c++)
            o[c] = x[c] - t0 * d[c];
        /* the exact first hit: the smaller root of |o + t d|^2 = R^2 (long double) */
        long double A = 0, B = 0, C = -(long double)R * R;
        for (int c = 0; c < 3; c++) {
            A += (long double)d[c] * d[c];
            B += 2.0L * o[c] * d[c];
            C += (long double)o[c] * o[c];
        }
        long double disc = sqrtl(B * B - 4 * A * C), t1 = (-B - disc) / (2 * A);
        hit hh;
        tried++;
        CHECK_STATUS(shoot(L, o, d, NULL, &hh), BS_OK);
        if (hh.patch != 0) {
            missed++;
            CHECKF(0, "sphere miss at (%g, %g)", th, ph);
            continue;
        }
        double err = (double)fabsl(hh.t - t1) * dl / (1e-9 * D);
        worst = fmax(worst, err);
        CHECKF(err <= 1, "sphere t %.17g exact %.17Lg o %.17g %.17g %.17g d %.17g %.17g %.17g", hh.t, t1, o[0], o[1], o[2], d[0], d[1], d[2]);
        double xr[3], nr[3];
        unsigned char kind;
        point_normal(p, hh.u, hh.v, xr, nr, &kind);
        CHECKF(fabs(dot3(hh.n, xr) / R - 1) < 1e-9, "sphere normal not outward radial: %.17g",
               dot3(hh.n, xr) / R);
    }
    printf("sphere octant: %ld rays, %ld missed, worst |t - exact| %.2g tau\n", tried, missed, worst);
    bs_patch_destroy(p);
    bs_locator_destroy(L);
}

/* Rays that miss, and t ranges that exclude the first hit. */
static void misses_and_ranges(void)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    for (int k = 0; k < 200; k++) { /* from outside the box, pointing away */
        double o[3], d[3];
        for (int c = 0; c < 3; c++) {
            o[c] = bs_test_rand(&rng, -10, 10);
            d[c] = bs_test_rand(&rng, -1, 1);
        }
        int c = k % 3;
        o[c] = k & 1 ? 8 : -8;
        d[c] = k & 1 ? 0.5 : -0.5;
        hit h;
        CHECK_STATUS(shoot(L, o, d, NULL, &h), BS_OK);
        CHECK(h.patch == UINT32_MAX && h.t == INFINITY && isnan(h.u) && isnan(h.v) && isnan(h.n[0]) &&
              isnan(h.n[1]) && isnan(h.n[2]));
    }
    for (int k = 0; k < 200; k++) { /* at the teapot's centre from outside: then exclude that hit */
        double o[3] = {bs_test_rand(&rng, -10, 10), bs_test_rand(&rng, -10, 10), 9};
        double d[3] = {bs_test_rand(&rng, -1, 1) - o[0] / 9, bs_test_rand(&rng, -1, 1) - o[1] / 9, -1};
        hit h, g;
        CHECK_STATUS(shoot(L, o, d, NULL, &h), BS_OK);
        if (h.patch == UINT32_MAX)
            continue;
        double before[2] = {0, h.t * (1 - 1e-6)}, after[2] = {h.t * (1 + 1e-6), 1e300};
        CHECK_STATUS(shoot(L, o, d, before, &g), BS_OK);
        CHECK(g.patch == UINT32_MAX && g.t == INFINITY);
        CHECK_STATUS(shoot(L, o, d, after, &g), BS_OK);
        CHECK(g.patch == UINT32_MAX || g.t >= after[0]);
        double around[2] = {h.t * 0.5, h.t * 2}, nothing[2] = {h.t * 2, h.t * 0.5};
        CHECK_STATUS(shoot(L, o, d, around, &g), BS_OK);
        CHECK(g.patch != UINT32_MAX && fabs(g.t - h.t) <= 1e-9 * h.t);
        CHECK_STATUS(shoot(L, o, d, nothing, &g), BS_OK);
        CHECK(g.patch == UINT32_MAX && g.t == INFINITY);
    }
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

int main(void)
{
    tea("teapot", 40);
    tea("teacup", 40);
    tea("teaspoon", 40);
    other_nets();
    from_surface("teapot", 3000);
    from_surface("teaspoon", 1000);
    pole();
    sphere();
    misses_and_ranges();
    return bs_test_exit("test_locator_rays");
}
