/* Corner cases of rays through a locator: directions of subnormal and of huge length (a hit is
 * never reported with t = +Inf, the miss value, nor t = 0 for a positive t), origins far from
 * the surface (the reported point within the documented tolerance of the ray, measured in long
 * double), and the kind of each hit's normal (bs_locator_intersect_kind), which is
 * bs_patch_eval_normal's kind at the hit: limit normals at the teapot's poles, undefined on a
 * patch collapsed to a point. */
#include "harness.h"
#include "shapes.h"
#include "reference.h"

#include <bezsurf.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long rng = 777;

typedef struct ray_out {
    uint32_t id;
    double u, v, t, n[3];
    unsigned char kind;
} ray_out;

static bs_status shoot(const bs_locator *L, const double o[3], const double d[3], const double *range,
                       ray_out *r)
{
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_cview rv[2] = {{range, 1, 0}, {range ? range + 1 : NULL, 1, 0}};
    bs_view uv[2] = {{&r->u, 1, 0}, {&r->v, 1, 0}}, tv = {&r->t, 1, 0};
    bs_view nv[3] = {{&r->n[0], 1, 0}, {&r->n[1], 1, 0}, {&r->n[2], 1, 0}};
    r->kind = 9;
    return bs_locator_intersect_kind(L, 1, ov, dv, range ? rv : NULL, &r->id, uv, &tv, nv, &r->kind);
}

/* The unit square z = 0 seen from z = 1 with directions (0, 0, -len). */
static void lengths(void)
{
    double ctrl[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, NULL, &p), BS_OK);
    bs_locator *L = p ? shape_locator(p) : NULL;
    if (L == NULL) {
        bs_patch_destroy(p);
        return;
    }
    double o[3] = {0.25, 0.5, 1.0};
    const double lens[] = {1.0, 1e-300, 0x1p-1022, 1e-310, 4.9e-324, 1e300, DBL_MAX};
    for (size_t k = 0; k < sizeof lens / sizeof lens[0]; k++) {
        double d[3] = {0, 0, -lens[k]}, t = 1.0 / lens[k];
        ray_out r;
        CHECK_STATUS(shoot(L, o, d, NULL, &r), BS_OK);
        if (isfinite(t) && t > 0.0) /* a hit at t = 1 / len */
            CHECKF(r.id == 0 && fabs(r.t - t) <= 1e-12 * t && r.kind == BS_NORMAL_REGULAR,
                   "length %g: patch %u t %.17g (%.17g)", lens[k], r.id, r.t, t);
        else /* t beyond the largest double: a miss, never a hit with the miss value */
            CHECKF(r.id == UINT32_MAX && r.t == INFINITY && isnan(r.u) && isnan(r.n[0]) &&
                       r.kind == BS_NORMAL_UNDEFINED,
                   "length %g: patch %u t %.17g", lens[k], r.id, r.t);
    }
    /* a range given: t_max = DBL_MAX with a subnormal direction is a miss too */
    double d[3] = {0, 0, -1e-320}, tr[2] = {0.0, DBL_MAX}, t = 0, u = 0;
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}}, rv[2] = {{&tr[0], 1, 0}, {&tr[1], 1, 0}};
    bs_view tv = {&t, 1, 0}, uvv[2] = {{&u, 1, 0}, {&u, 1, 0}};
    uint32_t id = 0;
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, rv, &id, uvv, &tv, NULL), BS_OK);
    CHECKF(id == UINT32_MAX && t == INFINITY, "subnormal direction with a range: patch %u t %g", id, t);
    bs_locator_destroy(L);
    bs_patch_destroy(p);
}

/* Rays at points of the teapot from origins 2^k D away (k = 0 .. 60): the point reported within
 * 1e-9 D + 2^-40 |S - o| of the ray (long double), its t within that over |d| of the exact t of
 * the point. */
static void far_origins(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    bs_locator *L = NULL;
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    if (L == NULL) {
        bs_surface_destroy(s);
        return;
    }
    const double D = 9.0; /* about the teapot's diagonal (6.4 x 3.15 x 4) */
    double worst = 0.0, worst_d = 0.0;
    int rays = 0, missed = 0;
    for (int k = 0; k <= 60; k += bs_test_quick() ? 10 : 2)
        for (int q = 0; q < 20; q++) {
            uint32_t pi = (uint32_t)(bs_test_rand_u64(&rng) % bs_surface_count(s));
            const bs_patch *p = bs_surface_get(s, pi);
            double u = bs_test_rand(&rng, 0.1, 0.9), v = bs_test_rand(&rng, 0.1, 0.9), P[3], N[3];
            unsigned char kind;
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view pv[3] = {{&P[0], 1, 0}, {&P[1], 1, 0}, {&P[2], 1, 0}};
            bs_view nv[3] = {{&N[0], 1, 0}, {&N[1], 1, 0}, {&N[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, pv, nv, &kind), BS_OK);
            /* a direction within 60 degrees of -N, the origin 2^k D back along it */
            double d[3], o[3], len = 0;
            for (int c = 0; c < 3; c++) {
                d[c] = -N[c] + bs_test_rand(&rng, -0.5, 0.5);
                len += d[c] * d[c];
            }
            len = sqrt(len);
            for (int c = 0; c < 3; c++)
                o[c] = P[c] - ldexp(D, k) * d[c] / len;
            ray_out r;
            CHECK_STATUS(shoot(L, o, d, NULL, &r), BS_OK);
            rays++;
            if (r.id >= bs_surface_count(s)) {
                missed++;
                continue;
            }
            /* the reported point in long double, its distance from the ray */
            const bs_patch *h = bs_surface_get(s, r.id);
            double ctrl[48];
            CHECK_STATUS(bs_patch_get_ctrl(h, ctrl, 48, NULL, 0), BS_OK);
            ref_net net = {3, 3, 3, ctrl, NULL};
            long double S[3], a[3], dl[3], dd = 0, ad = 0, a2 = 0;
            ref_eval(&net, (long double)r.u, (long double)r.v, S);
            for (int c = 0; c < 3; c++) {
                a[c] = S[c] - (long double)o[c];
                dl[c] = (long double)d[c];
                dd += dl[c] * dl[c];
                ad += a[c] * dl[c];
                a2 += a[c] * a[c];
            }
            long double cx = a[1] * dl[2] - a[2] * dl[1], cy = a[2] * dl[0] - a[0] * dl[2];
            long double cz = a[0] * dl[1] - a[1] * dl[0];
            double off = (double)(sqrtl(cx * cx + cy * cy + cz * cz) / sqrtl(dd)); /* |a x d| / |d| */
            double tol = 1e-9 * D + 0x1p-40 * (double)sqrtl(a2);
            double terr = fabs((double)(ad / dd) - r.t) * (double)sqrtl(dd);
            worst = fmax(worst, fmax(off, terr) / tol);
            worst_d = fmax(worst_d, fmax(off, terr) / (1e-9 * D));
            CHECKF(off <= tol && terr <= tol, "origin 2^%d D away: the point %.3g off the ray, t off by %.3g |d|, tolerance %.3g",
                   k, off, terr, tol);
        }
    CHECKF(missed == 0, "%d of %d rays from far origins missed", missed, rays);
    printf("far origins: %d rays, %d missed, worst %.2g of 1e-9 D + 2^-40 |S - o| (%.2g of 1e-9 D, "
           "the tolerance of 1.1, which the rounding of P - o alone exceeds from about 2^20 D on)\n", rays, missed, worst, worst_d);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

/* The kind of each hit's normal is bs_patch_eval_normal's at the hit. */
static void kinds(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    bs_locator *L = NULL;
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    int limit = 0, regular = 0;
    for (int q = 0; L != NULL && q < 400; q++) {
        /* rays straight down at the lid's pole (x = y = 0) and around, and random rays */
        double o[3], d[3];
        if (q < 100) {
            o[0] = q == 0 ? 0.0 : bs_test_rand(&rng, -1e-9, 1e-9);
            o[1] = q == 0 ? 0.0 : bs_test_rand(&rng, -1e-9, 1e-9);
            o[2] = 10.0;
            d[0] = d[1] = 0.0;
            d[2] = -1.0;
        } else
            for (int c = 0; c < 3; c++) {
                o[c] = bs_test_rand(&rng, -5, 5);
                d[c] = bs_test_rand(&rng, -1, 1) - o[c];
            }
        ray_out r;
        CHECK_STATUS(shoot(L, o, d, NULL, &r), BS_OK);
        if (r.id == UINT32_MAX) {
            CHECK(r.kind == BS_NORMAL_UNDEFINED);
            continue;
        }
        double P[3], N[3];
        unsigned char kind = 9;
        bs_cview cu = {&r.u, 1, 0}, cv = {&r.v, 1, 0};
        bs_view pv[3] = {{&P[0], 1, 0}, {&P[1], 1, 0}, {&P[2], 1, 0}};
        bs_view nv[3] = {{&N[0], 1, 0}, {&N[1], 1, 0}, {&N[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval_normal(bs_surface_get(s, r.id), 1, &cu, &cv, pv, nv, &kind), BS_OK);
        CHECKF(kind == r.kind && N[0] == r.n[0] && N[1] == r.n[1] && N[2] == r.n[2],
               "ray %d: kind %d normal (%g %g %g) against %d (%g %g %g)", q, r.kind, r.n[0], r.n[1],
               r.n[2], kind, N[0], N[1], N[2]);
        limit += r.kind == BS_NORMAL_LIMIT;
        regular += r.kind == BS_NORMAL_REGULAR;
    }
    CHECKF(limit >= 1 && regular >= 100, "%d limit and %d regular normals", limit, regular);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    /* a patch collapsed to one point: a hit there has no normal, (0,0,0) and kind undefined */
    double ctrl[12] = {1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, NULL, &p), BS_OK);
    L = p ? shape_locator(p) : NULL;
    if (L != NULL) {
        double o[3] = {1, 2, 5}, d[3] = {0, 0, -1};
        ray_out r;
        CHECK_STATUS(shoot(L, o, d, NULL, &r), BS_OK);
        if (r.id == 0) /* a degenerate hit may be reported or not; reported, it says so */
            CHECKF(r.kind == BS_NORMAL_UNDEFINED && r.n[0] == 0 && r.n[1] == 0 && r.n[2] == 0,
                   "point patch: kind %d normal (%g %g %g)", r.kind, r.n[0], r.n[1], r.n[2]);
        printf("a patch collapsed to a point: %s\n", r.id == 0 ? "hit, kind undefined" : "missed");
    }
    bs_locator_destroy(L);
    bs_patch_destroy(p);
}

/* The range [t_min, t_max] is closed: the unit square z = 0 seen from z = 1 along (0, 0, -1), a
 * hit at t = 1 with every coordinate exact, is found when t_max, t_min or both are 1. */
static void closed_range(void)
{
    double ctrl[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, NULL, &p), BS_OK);
    bs_locator *L = p ? shape_locator(p) : NULL;
    double o[3] = {0.25, 0.5, 1.0}, d[3] = {0, 0, -1};
    const double ranges[4][2] = {{0.5, 1.0}, {1.0, 1.0}, {1.0, 2.0}, {0.5, 0x1.fffffffffffffp-1}};
    for (int k = 0; L != NULL && k < 4; k++) {
        ray_out r;
        CHECK_STATUS(shoot(L, o, d, ranges[k], &r), BS_OK);
        if (k < 3)
            CHECKF(r.id == 0 && r.t == 1.0 && fabs(r.u - 0.25) < 1e-9 && fabs(r.v - 0.5) < 1e-9,
                   "range [%g, %g]: patch %u t %.17g", ranges[k][0], ranges[k][1], r.id, r.t);
        else
            CHECKF(r.id == UINT32_MAX && r.t == INFINITY, "range ending before the hit: patch %u t %.17g", r.id,
                   r.t);
    }
    bs_locator_destroy(L);
    bs_patch_destroy(p);
}

/* The parabolic cylinder z = -8 x^2 + 6 x - 1/8 over the unit square (a patch of degree (2, 1)
 * with exact control points), its top at x = 3/8, inside the sub-patches of x in [1/4, 1/2]. A
 * line meets it at most twice: chords through two of its points in those sub-patches must hit
 * the nearer one (t within 1e-9 of the exact root), which a search that took
 * a piece holding both for one to one could miss. The chords' directions run from nearly along
 * the top (both points close together) to steep. */
static void chords(void)
{
    double ctrl[18] = {0, 0, -0.125, 0, 1, -0.125, 0.5, 0, 2.875, 0.5, 1, 2.875, 1, 0, -2.125, 1, 1, -2.125};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(2, 1, 3, ctrl, NULL, &p), BS_OK);
    bs_locator *L = p ? shape_locator(p) : NULL;
    int bad = 0, n = 0;
    for (int k = 0; L != NULL && k < 4000; k++) {
        double a[3], b[3], o[3], d[3];
        for (int e = 0; e < 2; e++) {
            double *q = e ? b : a, x = bs_test_rand(&rng, 0.25, 0.5);
            q[0] = x;
            q[1] = bs_test_rand(&rng, 0.25, 0.5);
            q[2] = (-8.0 * x + 6.0) * x - 0.125;
        }
        for (int c = 0; c < 3; c++) { /* from 1.5 chords before a, along a -> b */
            d[c] = b[c] - a[c];
            o[c] = a[c] - 1.5 * d[c];
        }
        if (!(fabs(d[0]) > 1e-3))
            continue;
        ray_out r;
        CHECK_STATUS(shoot(L, o, d, NULL, &r), BS_OK);
        n++;
        /* the nearer point is a, at t = 1.5 exactly */
        if (!(r.id == 0 && fabs(r.t - 1.5) <= 1e-9 * 2.5)) {
            if (bad++ < 5)
                printf("chord %d: patch %u t %.17g (1.5), d (%g %g %g)\n", k, r.id, r.t, d[0], d[1], d[2]);
        }
    }
    CHECKF(bad == 0, "%d of %d chords did not hit their nearer point", bad, n);
    printf("chords of a parabolic cylinder: %d rays, %d wrong\n", n, bad);
    bs_locator_destroy(L);
    bs_patch_destroy(p);
}

/* The teapot as given, with weights 1 + 0.5 (k % 3), and scaled by 2^600 and 2^-950 (the
 * locator's scaled copies): rays from a camera answer the same with and without normals asked
 * for (patch, t, u and v bit for bit), since the position is bs_patch_eval's either way. */
static void without_normals(void)
{
    bs_surface *tea = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &tea), BS_OK);
    const double scale[3] = {1.0, 0x1p600, 0x1p-950};
    for (int kind = 0; tea != NULL && kind < 4; kind++) {
        double sc = kind < 3 ? scale[kind] : 1.0;
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create(&s), BS_OK);
        for (size_t i = 0; s != NULL && i < bs_surface_count(tea); i++) {
            double ctrl[48], w[16];
            bs_patch *p = NULL;
            CHECK_STATUS(bs_patch_get_ctrl(bs_surface_get(tea, i), ctrl, 48, w, 16), BS_OK);
            for (int k = 0; k < 48; k++)
                ctrl[k] *= sc;
            for (int k = 0; k < 16; k++)
                w[k] = 1.0 + 0.5 * (k % 3);
            CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl, kind == 3 ? w : NULL, &p), BS_OK);
            CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
            bs_patch_destroy(p);
        }
        bs_locator *L = NULL;
        CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
        int differ = 0, hits = 0;
        for (int k = 0; L != NULL && k < 1024; k++) {
            double o[3] = {6.0 * sc, -8.0 * sc, 5.5 * sc}, d[3];
            for (int c = 0; c < 3; c++)
                d[c] = (c == 2 ? 1.4 : 0.2) * sc - o[c] + bs_test_rand(&rng, -1.5, 1.5) * sc;
            ray_out a, b;
            CHECK_STATUS(shoot(L, o, d, NULL, &a), BS_OK);
            double t = 0.0, u = 0.0, v = 0.0;
            uint32_t id = 0;
            bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
            bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
            bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}}, tv = {&t, 1, 0};
            CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, uv, &tv, NULL), BS_OK);
            b = (ray_out){id, u, v, t, {0, 0, 0}, 0};
            hits += a.id != UINT32_MAX;
            differ += a.id != b.id || memcmp(&a.t, &b.t, sizeof a.t) != 0 ||
                      memcmp(&a.u, &b.u, sizeof a.u) != 0 || memcmp(&a.v, &b.v, sizeof a.v) != 0;
        }
        CHECKF(differ == 0 && hits > 256, "teapot %d: %d of 1024 rays differ without normals (%d hits)", kind,
               differ, hits);
        bs_locator_destroy(L);
        bs_surface_destroy(s);
    }
    bs_surface_destroy(tea);
}

/* The teapot raised to degree (8, 8) (81 control points a patch, more than a sub-patch's cone
 * of normals is made for) against the teapot itself: camera rays hit and miss alike, at the same
 * t within 1e-9 of it. */
static void raised(void)
{
    bs_surface *tea = NULL, *high = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &tea), BS_OK);
    CHECK_STATUS(bs_surface_create(&high), BS_OK);
    for (size_t i = 0; tea != NULL && high != NULL && i < bs_surface_count(tea); i++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_elevate(bs_surface_get(tea, i), 5, 5, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(high, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    bs_locator *L = NULL, *H = NULL;
    CHECK_STATUS(bs_locator_create(tea, &L), BS_OK);
    CHECK_STATUS(bs_locator_create(high, &H), BS_OK);
    int differ = 0, hits = 0;
    for (int k = 0; L != NULL && H != NULL && k < 1024; k++) {
        double o[3] = {6.0, -8.0, 5.5}, d[3];
        for (int c = 0; c < 3; c++)
            d[c] = (c == 2 ? 1.4 : 0.2) - o[c] + bs_test_rand(&rng, -1.5, 1.5);
        ray_out a, b;
        CHECK_STATUS(shoot(L, o, d, NULL, &a), BS_OK);
        CHECK_STATUS(shoot(H, o, d, NULL, &b), BS_OK);
        hits += a.id != UINT32_MAX;
        differ += (a.id == UINT32_MAX) != (b.id == UINT32_MAX) ||
                  (a.id != UINT32_MAX && !(fabs(a.t - b.t) <= 1e-9 * a.t));
    }
    CHECKF(differ == 0 && hits > 256, "degree (8, 8): %d of 1024 rays differ from the teapot's (%d hits)", differ,
           hits);
    bs_locator_destroy(L);
    bs_locator_destroy(H);
    bs_surface_destroy(tea);
    bs_surface_destroy(high);
}

int main(void)
{
    chords();
    without_normals();
    raised();
    lengths();
    closed_range();
    far_origins();
    kinds();
    return bs_test_exit("test_ray_cases");
}
