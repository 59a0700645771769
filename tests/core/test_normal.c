/* bs_patch_eval_normal: regular normals against the reference; limit normals on collapsed edges
 * (the teapot, synthetic nets collapsed on each side, polynomial and rational), cone and
 * parallel-derivative corners; undefined normals; never NaN for finite parameters. */
#include "eval_util.h"

#ifndef BS_DATA_DIR
#define BS_DATA_DIR "data"
#endif

static double worst_regular, worst_limit;

/* The reference normal at a point 1e-9 inside the domain, towards its centre (long double keeps
 * ~1e-10 relative accuracy there; the normal moves by O(1e-9) from the limit). */
static int inside_normal(const ref_net *r, double u, double v, long double *nrm)
{
    long double du = 0.5L - u, dv = 0.5L - v, big = fmaxl(fabsl(du), fabsl(dv));
    return ref_normal(r, u + 1e-9L * du / big, v + 1e-9L * dv / big, nrm);
}

/* Checks one point by its kind; returns the kind. */
static unsigned char check_point(const bs_patch *p, const ref_net *r, double u, double v)
{
    double n[3];
    unsigned char kind = normal1(p, u, v, n);
    CHECK(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2]));
    long double e[3] = {0, 0, 0};
    if (kind == BS_NORMAL_REGULAR) {
        CHECK(ref_normal(r, u, v, e));
        double d = dist3(n, e);
        worst_regular = fmax(worst_regular, d);
        CHECKF(d <= 1e-9, "regular normal at (%g,%g) off by %g", u, v, d);
    } else if (kind == BS_NORMAL_LIMIT) {
        CHECK(inside_normal(r, u, v, e));
        double d = dist3(n, e);
        worst_limit = fmax(worst_limit, d);
        CHECKF(d <= 1e-6, "limit normal at (%g,%g) off by %g", u, v, d);
    } else {
        CHECK(kind == BS_NORMAL_UNDEFINED && n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0);
    }
    return kind;
}

static void test_teapot(void)
{
    static double ctrl[32][48];
    size_t np = load_bpt(BS_DATA_DIR "/teapot.bpt", ctrl, 32);
    CHECKF(np == 32, "teapot.bpt: %zu patches", np);
    int limits = 0;
    for (size_t k = 0; k < np; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl[k], NULL, &p), BS_OK);
        ref_net r = {3, 3, 3, ctrl[k], NULL};
        /* patches 20..23 (lid top) and 28..31 (bottom) collapse their row i = 0 to a point */
        int collapsed = (k >= 20 && k <= 23) || k >= 28;
        for (int a = 0; a <= 8; a++)
            for (int b = 0; b <= 8; b++) {
                unsigned char kind = check_point(p, &r, a / 8.0, b / 8.0);
                int want = collapsed && a == 0 ? BS_NORMAL_LIMIT : BS_NORMAL_REGULAR;
                CHECKF(kind == want, "patch %zu (%d,%d): kind %d", k, a, b, kind);
                limits += kind == BS_NORMAL_LIMIT;
                if (kind == BS_NORMAL_LIMIT) {
                    /* the analytic limit on u = 0 where S_v vanishes: S_u x S_uv */
                    long double su[3], suv[3], n[3];
                    ref_deriv(&r, 1, 0, 0.0L, b / 8.0L, su);
                    ref_deriv(&r, 1, 1, 0.0L, b / 8.0L, suv);
                    long double c[3] = {su[1] * suv[2] - su[2] * suv[1], su[2] * suv[0] - su[0] * suv[2],
                                        su[0] * suv[1] - su[1] * suv[0]};
                    long double len = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
                    for (int d = 0; d < 3; d++)
                        n[d] = c[d] / len;
                    double got[3];
                    normal1(p, 0.0, b / 8.0, got);
                    double err = dist3(got, n);
                    worst_limit = fmax(worst_limit, err);
                    CHECKF(err <= 1e-9, "patch %zu: analytic limit off by %g", k, err);
                }
            }
        /* random interior points: regular, as the reference */
        unsigned long long rng = 200 + k;
        for (int t = 0; t < 20; t++)
            CHECK(check_point(p, &r, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1)) == BS_NORMAL_REGULAR);
        bs_patch_destroy(p);
    }
    CHECK(limits == 8 * 9);
}

/* The teacup and the teaspoon: every normal finite; regular ones as the reference, limit ones as
 * the reference just inside. */
static void test_teaset(const char *path, size_t expect)
{
    static double ctrl[32][48];
    size_t np = load_bpt(path, ctrl, 32);
    CHECKF(np == expect, "%s: %zu patches", path, np);
    int count[3] = {0, 0, 0};
    for (size_t k = 0; k < np; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl[k], NULL, &p), BS_OK);
        ref_net r = {3, 3, 3, ctrl[k], NULL};
        for (int a = 0; a <= 8; a++)
            for (int b = 0; b <= 8; b++)
                count[check_point(p, &r, a / 8.0, b / 8.0)]++;
        bs_patch_destroy(p);
    }
    printf("%s: %d regular, %d limit, %d undefined normals on 9 x 9 grids\n", path, count[0], count[1], count[2]);
    /* docs/normals.md: the cup's 2106 all regular; the spoon 7 limit points among 1296 */
    if (expect == 26)
        CHECKF(count[0] == 2106 && count[1] == 0 && count[2] == 0, "%s: kinds as documented", path);
    else
        CHECKF(count[0] == 1296 - 7 && count[1] == 7 && count[2] == 0, "%s: kinds as documented", path);
}

/* A wavy graph-like net of degree (m,n), then side `side` (0: u=0, 1: u=1, 2: v=0, 3: v=1)
 * collapsed to one point. */
static tnet collapsed_net(unsigned long long *rng, size_t m, size_t n, int side, int rational)
{
    tnet t = tnet_random(rng, m, n, 3, rational, 0.5, 2.0);
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            double *P = t.ctrl + (i * (n + 1) + j) * 3;
            P[0] = (double)i / (double)m + 0.1 * P[0];
            P[1] = (double)j / (double)n + 0.1 * P[1];
            P[2] = 0.5 * P[2];
        }
    for (size_t k = 0; k <= (side < 2 ? n : m); k++) {
        size_t i = side == 0 ? 0 : side == 1 ? m : k, j = side == 2 ? 0 : side == 3 ? n : k;
        size_t i0 = side == 0 ? 0 : side == 1 ? m : 0, j0 = side == 2 ? 0 : side == 3 ? n : 0;
        memcpy(t.ctrl + (i * (n + 1) + j) * 3, t.ctrl + (i0 * (n + 1) + j0) * 3, 3 * sizeof(double));
    }
    return t;
}

static void test_collapsed_sides(void)
{
    unsigned long long rng = 300;
    for (int rational = 0; rational < 2; rational++)
        for (int side = 0; side < 4; side++)
            for (int deg = 0; deg < 3; deg++) {
                size_t m = deg == 0 ? 3 : deg == 1 ? 2 : 7, n = deg == 0 ? 3 : deg == 1 ? 5 : 4;
                tnet t = collapsed_net(&rng, m, n, side, rational);
                ref_net r = tnet_ref(&t);
                bs_patch *p = tnet_patch(&t);
                for (int k = 0; k <= 8; k++) {
                    double s = k / 8.0;
                    double u = side == 0 ? 0.0 : side == 1 ? 1.0 : s, v = side == 2 ? 0.0 : side == 3 ? 1.0 : s;
                    unsigned char kind = check_point(p, &r, u, v);
                    CHECKF(kind == BS_NORMAL_LIMIT, "side %d deg (%zu,%zu) rational %d t=%g: kind %d", side, m,
                           n, rational, s, kind);
                    /* the analytic limit: S_u x S_uv on u = 0, its opposite on u = 1; S_uv x S_v on
                     * v = 0, its opposite on v = 1 */
                    long double a[3], b[3], e[3];
                    ref_deriv(&r, side < 2 ? 1 : 1, side < 2 ? 0 : 1, u, v, a);
                    ref_deriv(&r, side < 2 ? 1 : 0, 1, u, v, b);
                    long double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
                    long double len = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) * (side % 2 ? -1 : 1);
                    for (int d = 0; d < 3; d++)
                        e[d] = c[d] / len;
                    double got[3];
                    normal1(p, u, v, got);
                    double err = dist3(got, e);
                    worst_limit = fmax(worst_limit, err);
                    CHECKF(err <= 1e-6, "side %d: analytic limit off by %g", side, err);
                    /* orientation: the limit agrees with the regular normal just inside */
                    double nl[3], ni[3];
                    normal1(p, u, v, nl);
                    double ui = u + 1e-3 * (0.5 - u), vi = v + 1e-3 * (0.5 - v);
                    CHECK(normal1(p, ui, vi, ni) == BS_NORMAL_REGULAR);
                    CHECK(nl[0] * ni[0] + nl[1] * ni[1] + nl[2] * ni[2] > 0.99);
                }
                for (int k = 0; k < 10; k++)
                    CHECK(check_point(p, &r, bs_test_rand(&rng, 0.01, 0.99), bs_test_rand(&rng, 0.01, 0.99)) ==
                          BS_NORMAL_REGULAR);
                bs_patch_destroy(p);
                tnet_free(&t);
            }
}

/* Corners: a cone point (S_u = S_v = 0) and parallel S_u, S_v; the limit along the diagonal. */
static void test_corners(void)
{
    unsigned long long rng = 400;
    for (int rational = 0; rational < 2; rational++) {
        tnet t = collapsed_net(&rng, 3, 3, -1, rational); /* side -1: nothing collapsed */
        double *P00 = t.ctrl, *P10 = t.ctrl + 4 * 3, *P01 = t.ctrl + 3;
        memcpy(P10, P00, 3 * sizeof(double));
        memcpy(P01, P00, 3 * sizeof(double));
        ref_net r = tnet_ref(&t);
        bs_patch *p = tnet_patch(&t);
        CHECK(check_point(p, &r, 0.0, 0.0) == BS_NORMAL_LIMIT);
        bs_patch_destroy(p);
        /* P01 - P00 = 2 (P10 - P00): S_u parallel to S_v at (0,0) */
        for (int c = 0; c < 3; c++) {
            P10[c] = P00[c] + 0.3 * (c + 1);
            P01[c] = P00[c] + 0.6 * (c + 1);
        }
        p = tnet_patch(&t);
        CHECK(check_point(p, &r, 0.0, 0.0) == BS_NORMAL_LIMIT);
        CHECK(check_point(p, &r, 1.0, 1.0) == BS_NORMAL_REGULAR);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* No normal: a net on a line, a single point, a curve swept as a constant. */
static void test_undefined(void)
{
    double line[16 * 3], pt[16 * 3];
    for (int k = 0; k < 16; k++) {
        double s = (k % 4) * 0.3 + (k / 4) * 0.7 - (k == 5) * 0.4;
        line[3 * k] = 1 + s;
        line[3 * k + 1] = 2 - 2 * s;
        line[3 * k + 2] = 0.5 * s;
        pt[3 * k] = 1.5;
        pt[3 * k + 1] = -2;
        pt[3 * k + 2] = 3;
    }
    const double *nets[2] = {line, pt};
    for (int q = 0; q < 2; q++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, nets[q], NULL, &p), BS_OK);
        for (int a = 0; a <= 4; a++)
            for (int b = 0; b <= 4; b++) {
                double n[3] = {7, 7, 7};
                CHECK(normal1(p, a / 4.0, b / 4.0, n) == BS_NORMAL_UNDEFINED);
                CHECK(n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0);
            }
        bs_patch_destroy(p);
    }
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(0, 3, 3, line + 3, NULL, &p), BS_OK); /* degree 0 in u */
    double n[3];
    CHECK(normal1(p, 0.3, 0.4, n) == BS_NORMAL_UNDEFINED);
    bs_patch_destroy(p);
}

/* Finite parameters, even far outside [0,1], never give NaN; NaN parameters give NaN. */
static void test_finite_and_nan(void)
{
    unsigned long long rng = 500;
    for (int side = 0; side < 4; side++) {
        tnet t = collapsed_net(&rng, 3, 4, side, side % 2);
        bs_patch *p = tnet_patch(&t);
        for (int k = 0; k < 200; k++) {
            double u = bs_test_rand(&rng, -3, 4), v = bs_test_rand(&rng, -3, 4), n[3];
            if (k % 5 == 0)
                u = k % 10 == 0 ? 1e300 : -1e200;
            unsigned char kind = normal1(p, u, v, n);
            CHECK(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2]));
            double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            CHECK(kind == BS_NORMAL_UNDEFINED ? len == 0.0 : fabs(len - 1.0) <= 4 * EPS);
        }
        double n[3], pos[3];
        double u = NAN, v = 0.5;
        bs_cview cu = cview_of(&u, 1), cv = cview_of(&v, 1);
        bs_view vn[3], vp[3];
        views_of(n, 3, 1, vn);
        views_of(pos, 3, 1, vp);
        unsigned char kind = 0;
        CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, vp, vn, &kind), BS_OK);
        CHECK(kind == BS_NORMAL_UNDEFINED && isnan(n[0]) && isnan(n[2]) && isnan(pos[1]));
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Positions from the normal evaluator are those of bs_patch_eval, bit for bit. */
static void test_positions_match_eval(void)
{
    unsigned long long rng = 600;
    enum { N = 13 };
    tnet t = tnet_random(&rng, 4, 6, 3, 1, 0.5, 2.0);
    bs_patch *p = tnet_patch(&t);
    double u[N], v[N], a[3 * N], b[3 * N];
    for (int k = 0; k < N; k++) {
        u[k] = bs_test_rand(&rng, 0, 1);
        v[k] = bs_test_rand(&rng, 0, 1);
    }
    bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
    bs_view va[3], vb[3];
    views_of(a, 3, N, va);
    views_of(b, 3, N, vb);
    CHECK_STATUS(bs_patch_eval(p, N, &cu, &cv, va, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, vb, NULL, NULL), BS_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    bs_patch_destroy(p);
    tnet_free(&t);
}

/* The chunked path of polynomial bicubic patches with packed arrays against the general loop
 * (strided outputs) and one call per point, bit for bit: positions, normals and kinds, with
 * limit normals, undefined normals, NaN, infinite and huge parameters in each size of chunk, and
 * a count that is not a multiple of the chunk; each output may be left out. */
static void test_packed_chunks(void)
{
    enum { N = 128 + 32 + 7 }; /* a chunk of 128, one of 32, a tail */
    static double ctrl[32][48];
    CHECK(load_bpt(BS_DATA_DIR "/teapot.bpt", ctrl, 32) == 32);
    unsigned long long rng = 700;
    tnet col = collapsed_net(&rng, 3, 3, 3, 0), wild = tnet_random(&rng, 3, 3, 3, 0, 0.5, 2.0);
    double pt[48], big[48];
    for (int k = 0; k < 48; k++) {
        pt[k] = k % 3 - 1.5;           /* one point: no normal anywhere */
        big[k] = wild.ctrl[k] * 1e200; /* goes through the scaled copy */
    }
    const double *nets[5] = {ctrl[20], ctrl[5], col.ctrl, pt, big};
    for (int q = 0; q < 5; q++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, nets[q], NULL, &p), BS_OK);
        double u[N], v[N], a[6 * N], b[6 * N], s[6 * N * 2], c[6 * N];
        unsigned char ka[N], kb[N], kc[N];
        for (int k = 0; k < N; k++) {
            u[k] = bs_test_rand(&rng, -0.1, 1.1);
            v[k] = bs_test_rand(&rng, -0.1, 1.1);
            if (k % 4 == 0)
                u[k] = 0.0; /* the teapot's collapsed row: limit normals */
            if (k % 9 == 0)
                v[k] = k % 2 ? 1.0 : 0.0;
        }
        u[3] = NAN;
        v[40] = INFINITY;
        u[41] = -INFINITY;
        u[70] = 1e300; /* squares out of range: the general rule */
        v[140] = NAN;
        u[145] = NAN;
        u[150] = -1e300;
        v[N - 1] = NAN;
        bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
        bs_view va[6], vs[6];
        views_of(a, 6, N, va);
        for (int d = 0; d < 6; d++) { /* interleaved with a gap: the general loop */
            bs_view w = {s + d, N, 12 * (ptrdiff_t)sizeof(double)};
            vs[d] = w;
        }
        CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, va, va + 3, ka), BS_OK);
        CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, vs, vs + 3, kb), BS_OK);
        for (int k = 0; k < N; k++) {
            for (int d = 0; d < 6; d++)
                b[d * N + k] = s[12 * k + d];
            bs_cview cu1 = cview_of(u + k, 1), cv1 = cview_of(v + k, 1);
            bs_view v1[6];
            for (int d = 0; d < 6; d++) {
                bs_view w = {c + d * N + k, 1, 0};
                v1[d] = w;
            }
            CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu1, &cv1, v1, v1 + 3, kc + k), BS_OK);
        }
        CHECKF(memcmp(a, b, sizeof a) == 0 && memcmp(ka, kb, sizeof ka) == 0, "net %d: packed/strided", q);
        CHECKF(memcmp(a, c, sizeof a) == 0 && memcmp(ka, kc, sizeof ka) == 0, "net %d: packed/one by one", q);
        int limits = 0;
        for (int k = 0; k < N; k++)
            limits += ka[k] == BS_NORMAL_LIMIT;
        CHECK(q != 0 || limits > 0);
        /* a strided parameter or normal array: the general loop, the same bits */
        double uu[2 * N], vv[2 * N];
        for (int k = 0; k < N; k++) {
            uu[2 * k] = u[k];
            vv[2 * k] = v[k];
        }
        bs_cview su = {uu, N, 2 * (ptrdiff_t)sizeof(double)}, sv = {vv, N, 2 * (ptrdiff_t)sizeof(double)};
        const bs_cview *lu[3] = {&su, &cu, &cu}, *lv[3] = {&cv, &sv, &cv};
        for (int l = 0; l < 3; l++) {
            memset(c, 0, sizeof c);
            bs_view vc[6];
            views_of(c, 6, N, vc);
            CHECK_STATUS(bs_patch_eval_normal(p, N, lu[l], lv[l], vc, l == 2 ? vs + 3 : vc + 3, kc), BS_OK);
            for (int k = 0; l == 2 && k < N; k++)
                for (int d = 3; d < 6; d++)
                    c[d * N + k] = s[12 * k + d];
            CHECKF(memcmp(a, c, sizeof a) == 0 && memcmp(ka, kc, sizeof ka) == 0, "net %d: layout %d", q, l);
        }
        memset(kc, 9, sizeof kc);
        CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, NULL, NULL, kc), BS_OK);
        CHECK(memcmp(ka, kc, sizeof ka) == 0);
        /* each output left out in turn: the others keep their bits */
        memset(c, 0, sizeof c);
        CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, NULL, va + 3, NULL), BS_OK);
        CHECK(memcmp(a + 3 * N, b + 3 * N, 3 * N * sizeof(double)) == 0);
        bs_view vc[3];
        views_of(c, 3, N, vc);
        CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, vc, NULL, kc), BS_OK);
        CHECK(memcmp(c, b, 3 * N * sizeof(double)) == 0 && memcmp(kc, kb, sizeof kc) == 0);
        bs_patch_destroy(p);
    }
    tnet_free(&col);
    tnet_free(&wild);
}

/* A call of one point (its own path) against the same point in a batch, bit for bit: positions,
 * normals and kinds on nets of degrees 1..5, rational and polynomial, with collapsed sides (limit
 * normals), at parameters on the sides, inside, outside and not finite. */
static void test_single_point_calls(void)
{
    enum { N = 40 };
    unsigned long long rng = 4242;
    int same = 1, limits = 0;
    for (size_t m = 1; m <= 5; m++)
        for (size_t n = 1; n <= 5; n += 2)
            for (int kind = 0; kind < 4; kind++) {
                int rational = kind & 1;
                tnet t = kind & 2 ? collapsed_net(&rng, m, n, (int)((m + n) % 4), rational)
                                  : tnet_random(&rng, m, n, 3, rational, 0.25, 4.0);
                bs_patch *p = tnet_patch(&t);
                double u[N], v[N], a[6 * N];
                unsigned char ka[N];
                for (int k = 0; k < N; k++) {
                    u[k] = k % 5 == 0 ? 0.0 : k % 7 == 0 ? 1.0 : bs_test_rand(&rng, -0.1, 1.1);
                    v[k] = k % 3 == 0 ? 0.0 : k % 4 == 0 ? 1.0 : bs_test_rand(&rng, -0.1, 1.1);
                }
                u[11] = NAN;
                v[13] = -INFINITY;
                bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
                bs_view va[6];
                views_of(a, 6, N, va);
                CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, va, va + 3, ka), BS_OK);
                for (int k = 0; k < N; k++) {
                    double one[6];
                    unsigned char k1 = 77;
                    bs_cview cu1 = cview_of(u + k, 1), cv1 = cview_of(v + k, 1);
                    bs_view v1[6];
                    views_of(one, 6, 1, v1);
                    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu1, &cv1, v1, v1 + 3, &k1), BS_OK);
                    for (int d = 0; d < 6; d++)
                        same &= memcmp(&one[d], &a[d * N + k], sizeof(double)) == 0;
                    same &= k1 == ka[k];
                    limits += ka[k] == BS_NORMAL_LIMIT;
                }
                CHECKF(same, "deg (%zu,%zu) kind %d: one point differs from its batch", m, n, kind);
                bs_patch_destroy(p);
                tnet_free(&t);
            }
    CHECK(limits > 0); /* the collapsed nets' sides were reached */
}

int main(void)
{
    test_teapot();
    test_teaset(BS_DATA_DIR "/teacup.bpt", 26);
    test_teaset(BS_DATA_DIR "/teaspoon.bpt", 16);
    test_collapsed_sides();
    test_corners();
    test_undefined();
    test_finite_and_nan();
    test_positions_match_eval();
    test_packed_chunks();
    test_single_point_calls();
    printf("normals: worst regular error %.3g (limit 1e-9), worst limit error %.3g (limit 1e-6)\n",
           worst_regular, worst_limit);
    return bs_test_exit("test_normal");
}
