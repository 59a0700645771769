/* B-spline and NURBS surfaces to Bezier patches: every patch against an independent evaluation of
 * the B-spline (the Cox-de Boor basis functions in long double), span bookkeeping, locate, and
 * every error status with the surface left as it was. */
#include "harness.h"

#include <bezsurf.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAXP 24
#define MAXN 40

/* Basis functions N[i-p .. i] of degree p at x on span i (Piegl and Tiller's triangular scheme),
 * in long double; x may be anywhere: the values are those of span i's polynomial piece. */
static void basis(const double *t, size_t p, size_t i, long double x, long double *N)
{
    long double left[MAXP + 1], right[MAXP + 1];
    N[0] = 1.0L;
    for (size_t j = 1; j <= p; j++) {
        left[j] = x - (long double)t[i + 1 - j];
        right[j] = (long double)t[i + j] - x;
        long double saved = 0.0L;
        for (size_t r = 0; r < j; r++) {
            long double tmp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
}

/* S(u,v) of span (iu, iv)'s piece, in long double. */
static void reference(const bs_bspline *b, size_t iu, size_t iv, long double u, long double v, long double *out)
{
    long double Nu[MAXP + 1], Nv[MAXP + 1], num[8] = {0}, den = 0.0L;
    basis(b->knots_u, b->deg_u, iu, u, Nu);
    basis(b->knots_v, b->deg_v, iv, v, Nv);
    for (size_t k = 0; k <= b->deg_u; k++)
        for (size_t l = 0; l <= b->deg_v; l++) {
            size_t idx = (iu - b->deg_u + k) * b->count_v + (iv - b->deg_v + l);
            long double w = b->weights ? (long double)b->weights[idx] : 1.0L;
            long double f = Nu[k] * Nv[l] * w;
            for (size_t c = 0; c < b->dim; c++)
                num[c] += f * (long double)b->ctrl[idx * b->dim + c];
            den += f;
        }
    for (size_t c = 0; c < b->dim; c++)
        out[c] = num[c] / den;
}

/* A random knot vector: count + p + 1 knots, interior multiplicities 1 .. p + 1, clamped or not. */
static void random_knots(unsigned long long *rng, size_t p, size_t count, int clamped, double *t)
{
    size_t n = count + p + 1, k = 0;
    double x = bs_test_rand(rng, -3.0, 3.0);
    if (clamped)
        for (; k <= p; k++)
            t[k] = x;
    while (k < n) {
        x += bs_test_rand(rng, 0.05, 2.0);
        size_t mult = 1 + (size_t)(bs_test_rand_u64(rng) % (p + 1));
        if (bs_test_rand_u64(rng) % 3 != 0)
            mult = 1;
        if (clamped && n - k <= p + 1)
            mult = n - k; /* the end clamped too */
        for (size_t m = 0; m < mult && k < n; m++)
            t[k++] = x;
    }
}

/* Knot index of span a along one direction. */
static size_t span_start(const double *t, size_t p, size_t count, size_t a)
{
    for (size_t i = p; i < count; i++)
        if (t[i] < t[i + 1] && a-- == 0)
            return i;
    return (size_t)-1;
}

static double worst_ratio; /* largest |patch - reference| / (max|P| wmax/wmin) seen */

/* Every patch of b against the reference at local (s,t) on a 5x5 grid including the borders. */
static void check_patches(const bs_bspline *b, unsigned long long *rng)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    size_t nu = 0, nv = 0, count = 0;
    CHECK_STATUS(bs_bspline_span_count(b, &nu, &nv), BS_OK);
    double *spans = malloc(4 * nu * nv * sizeof(double));
    CHECK_STATUS(bs_surface_add_bspline(s, b, spans, 4 * nu * nv, &count), BS_OK);
    CHECK(count == nu * nv && bs_surface_count(s) == count);
    double pmax = 0.0, wlo = 1.0, whi = 1.0;
    for (size_t k = 0; k < b->count_u * b->count_v; k++) {
        for (size_t c = 0; c < b->dim; c++)
            pmax = fmax(pmax, fabs(b->ctrl[k * b->dim + c]));
        if (b->weights) {
            wlo = k == 0 ? b->weights[0] : fmin(wlo, b->weights[k]);
            whi = k == 0 ? b->weights[0] : fmax(whi, b->weights[k]);
        }
    }
    double scale = pmax * whi / wlo;
    for (size_t a = 0; a < nu && count == nu * nv; a++)
        for (size_t bv = 0; bv < nv; bv++) {
            size_t id = a * nv + bv;
            size_t iu = span_start(b->knots_u, b->deg_u, b->count_u, a);
            size_t iv = span_start(b->knots_v, b->deg_v, b->count_v, bv);
            CHECK(spans[4 * id] == b->knots_u[iu] && spans[4 * id + 1] == b->knots_u[iu + 1] &&
                  spans[4 * id + 2] == b->knots_v[iv] && spans[4 * id + 3] == b->knots_v[iv + 1]);
            const bs_patch *p = bs_surface_get(s, id);
            CHECK(bs_patch_degree_u(p) == b->deg_u && bs_patch_degree_v(p) == b->deg_v);
            CHECK(bs_patch_is_rational(p) == (b->weights != NULL));
            for (int gi = 0; gi <= 4; gi++)
                for (int gj = 0; gj <= 4; gj++) {
                    double su = gi / 4.0, sv = gj / 4.0;
                    if (gi % 4 && gj % 4) { /* inside: random points too */
                        su = bs_test_rand(rng, 0.0, 1.0);
                        sv = bs_test_rand(rng, 0.0, 1.0);
                    }
                    double x[8];
                    bs_cview cu = {&su, 1, 0}, cv = {&sv, 1, 0};
                    bs_view pos[8];
                    for (size_t c = 0; c < b->dim; c++)
                        pos[c] = (bs_view){&x[c], 1, 0};
                    CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, pos, NULL, NULL), BS_OK);
                    long double u0 = b->knots_u[iu], u1 = b->knots_u[iu + 1];
                    long double v0 = b->knots_v[iv], v1 = b->knots_v[iv + 1];
                    long double ref[8];
                    reference(b, iu, iv, u0 + (u1 - u0) * su, v0 + (v1 - v0) * sv, ref);
                    for (size_t c = 0; c < b->dim; c++) {
                        double r = (double)(fabsl((long double)x[c] - ref[c]) / scale);
                        worst_ratio = fmax(worst_ratio, r);
                        CHECKF(r <= 1e-13, "patch %zu coordinate %zu: error %.3g max|P|", id, c, r);
                    }
                }
        }
    free(spans);
    bs_surface_destroy(s);
}

static void random_surfaces(void)
{
    unsigned long long rng = 2026;
    static double ku[MAXN + MAXP + 1], kv[MAXN + MAXP + 1], ctrl[MAXN * MAXN * 4], w[MAXN * MAXN];
    for (int trial = 0; trial < 300; trial++) {
        size_t maxdeg = trial < 280 ? 5 : 20;
        bs_bspline b;
        b.deg_u = 1 + (size_t)(bs_test_rand_u64(&rng) % maxdeg);
        b.deg_v = 1 + (size_t)(bs_test_rand_u64(&rng) % maxdeg);
        b.count_u = b.deg_u + 1 + (size_t)(bs_test_rand_u64(&rng) % 7);
        b.count_v = b.deg_v + 1 + (size_t)(bs_test_rand_u64(&rng) % 7);
        b.dim = 1 + (size_t)(bs_test_rand_u64(&rng) % 4);
        random_knots(&rng, b.deg_u, b.count_u, trial % 2 == 0, ku);
        random_knots(&rng, b.deg_v, b.count_v, trial % 4 < 2, kv);
        for (size_t k = 0; k < b.count_u * b.count_v; k++) {
            for (size_t c = 0; c < b.dim; c++)
                ctrl[k * b.dim + c] = bs_test_rand(&rng, -10.0, 10.0);
            w[k] = bs_test_rand(&rng, 0.2, 5.0);
        }
        b.knots_u = ku;
        b.knots_v = kv;
        b.ctrl = ctrl;
        b.weights = trial % 3 == 0 ? NULL : w;
        size_t nu, nv;
        if (bs_bspline_span_count(&b, &nu, &nv) != BS_OK)
            continue; /* every interior knot of an unclamped vector may sit outside the domain */
        check_patches(&b, &rng);
    }
}

/* A clamped B-spline without interior knots is one Bezier patch with the same net. */
static void single_span_is_the_net(void)
{
    double ku[8] = {0, 0, 0, 0, 1, 1, 1, 1}, kv[6] = {-2, -2, -2, 5, 5, 5};
    double ctrl[4 * 3 * 2], w[12];
    for (int k = 0; k < 24; k++)
        ctrl[k] = (double)(k * 7 % 11) - 3.5;
    for (int k = 0; k < 12; k++)
        w[k] = 1.0 + 0.25 * (k % 5);
    bs_bspline b = {3, 2, 4, 3, 2, ku, kv, ctrl, w};
    bs_surface *s;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    size_t count = 0;
    double spans[4];
    CHECK_STATUS(bs_surface_add_bspline(s, &b, spans, 4, &count), BS_OK);
    CHECK(count == 1 && spans[0] == 0 && spans[1] == 1 && spans[2] == -2 && spans[3] == 5);
    double got[24], gw[12];
    CHECK_STATUS(bs_patch_get_ctrl(bs_surface_get(s, 0), got, 24, gw, 12), BS_OK);
    double err = 0.0;
    for (int k = 0; k < 24; k++)
        err = fmax(err, fabs(got[k] - ctrl[k]));
    for (int k = 0; k < 12; k++)
        err = fmax(err, fabs(gw[k] - w[k]));
    CHECKF(err <= 4 * DBL_EPSILON * 10, "largest difference %.3g", err);
    bs_surface_destroy(s);
}

static void locate(void)
{
    /* cubic along u with a double knot at 1 and a triple (C0) knot at 2; quadratic along v */
    double ku[] = {0, 0, 0, 0, 1, 1, 2, 2, 2, 3, 3, 3, 3}, kv[] = {0, 0, 0, 0.5, 1, 1, 1};
    double ctrl[9 * 4 * 3];
    for (int k = 0; k < 108; k++)
        ctrl[k] = sin(0.7 * k);
    bs_bspline b = {3, 2, 9, 4, 3, ku, kv, ctrl, NULL};
    size_t nu = 0, nv = 0, idx = 99;
    CHECK_STATUS(bs_bspline_span_count(&b, &nu, &nv), BS_OK);
    CHECK(nu == 3 && nv == 2);
    double lu = -1, lv = -1;
    CHECK_STATUS(bs_bspline_locate(&b, 1.5, 0.25, &idx, &lu, &lv), BS_OK);
    CHECK(idx == 1 * 2 + 0 && lu == 0.5 && lv == 0.5);
    CHECK_STATUS(bs_bspline_locate(&b, 1.0, 0.5, &idx, &lu, &lv), BS_OK); /* knots: the later span */
    CHECK(idx == 1 * 2 + 1 && lu == 0.0 && lv == 0.0);
    CHECK_STATUS(bs_bspline_locate(&b, 3.0, 1.0, &idx, &lu, &lv), BS_OK); /* the domain's end */
    CHECK(idx == 2 * 2 + 1 && lu == 1.0 && lv == 1.0);
    CHECK_STATUS(bs_bspline_locate(&b, 0.0, 0.0, &idx, NULL, NULL), BS_OK);
    CHECK(idx == 0);
    idx = 77;
    CHECK_STATUS(bs_bspline_locate(&b, 3.0000001, 0.5, &idx, &lu, &lv), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_bspline_locate(&b, 1.0, -1e-300, &idx, &lu, &lv), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_bspline_locate(&b, NAN, 0.5, &idx, &lu, &lv), BS_ERR_DOMAIN);
    CHECK(idx == 77);
    CHECK_STATUS(bs_bspline_locate(NULL, 0.5, 0.5, &idx, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_bspline_locate(&b, 0.5, 0.5, NULL, NULL, NULL), BS_ERR_INVALID_ARG);

    /* the point a located patch gives is the B-spline's (right-continuous at knots) */
    bs_surface *s;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add_bspline(s, &b, NULL, 0, NULL), BS_OK);
    unsigned long long rng = 7;
    for (int k = 0; k < 200; k++) {
        double u = k < 4 ? (double)k : bs_test_rand(&rng, 0.0, 3.0), v = bs_test_rand(&rng, 0.0, 1.0);
        CHECK_STATUS(bs_bspline_locate(&b, u, v, &idx, &lu, &lv), BS_OK);
        size_t iu = span_start(ku, 3, 9, idx / nv), iv = span_start(kv, 2, 4, idx % nv);
        CHECK(ku[iu] <= u && (u < ku[iu + 1] || (u == 3.0 && ku[iu + 1] == 3.0)));
        double x[3];
        bs_cview cu = {&lu, 1, 0}, cv = {&lv, 1, 0};
        bs_view pos[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval(bs_surface_get(s, idx), 1, &cu, &cv, pos, NULL, NULL), BS_OK);
        long double ref[3];
        reference(&b, iu, iv, u, v, ref);
        for (int c = 0; c < 3; c++)
            CHECKF(fabsl((long double)x[c] - ref[c]) <= 1e-13L, "u %g v %g: %.3Lg", u, v,
                   fabsl((long double)x[c] - ref[c]));
    }
    bs_surface_destroy(s);
}

static void errors(void)
{
    double ku[] = {0, 0, 1, 2, 2}, kv[] = {0, 0, 1, 1}, ctrl[3 * 2 * 3], w[6] = {1, 1, 1, 1, 1, 1};
    for (int k = 0; k < 18; k++)
        ctrl[k] = k;
    const bs_bspline good = {1, 1, 3, 2, 3, ku, kv, ctrl, w};
    bs_surface *s;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add_bspline(s, &good, NULL, 0, NULL), BS_OK);
    CHECK(bs_surface_count(s) == 2);
    bs_bspline b;
    size_t count = 42, nu = 42, nv = 42;
    double spans[8] = {0};
#define EXPECT(edit, status)                                                                   \
    do {                                                                                       \
        b = good;                                                                              \
        edit;                                                                                  \
        CHECK_STATUS(bs_surface_add_bspline(s, &b, spans, 8, &count), status);                 \
        CHECK(bs_surface_count(s) == 2 && count == 42 && spans[0] == 0.0);                     \
    } while (0)
    EXPECT(b.ctrl = NULL, BS_ERR_INVALID_ARG);
    EXPECT(b.knots_u = NULL, BS_ERR_INVALID_ARG);
    EXPECT(b.knots_v = NULL, BS_ERR_INVALID_ARG);
    EXPECT((b.deg_u = 0, b.ctrl = NULL), BS_ERR_INVALID_ARG); /* NULL is checked first */
    EXPECT(b.deg_u = 0, BS_ERR_DEGREE);
    EXPECT(b.deg_v = BS_MAX_DEGREE + 1, BS_ERR_DEGREE);
    EXPECT((b.deg_v = BS_MAX_DEGREE + 1, b.dim = 0), BS_ERR_DEGREE);
    EXPECT(b.dim = 0, BS_ERR_DIMENSION);
    EXPECT(b.dim = BS_MAX_DIM + 1, BS_ERR_DIMENSION);
    EXPECT((b.dim = 0, b.count_u = 1), BS_ERR_DIMENSION);
    EXPECT(b.count_u = 1, BS_ERR_SIZE);
    EXPECT((b.count_v = 1, ku[1] = -1), BS_ERR_SIZE);
    ku[1] = 0;
    EXPECT(ku[2] = 3, BS_ERR_DOMAIN); /* decreasing */
    ku[2] = 1;
    EXPECT(kv[3] = NAN, BS_ERR_DOMAIN);
    kv[3] = 1;
    EXPECT(kv[2] = INFINITY, BS_ERR_DOMAIN);
    kv[2] = 1;
    EXPECT((kv[0] = kv[1] = kv[2] = kv[3] = 1), BS_ERR_DOMAIN); /* empty domain */
    kv[0] = kv[1] = 0;
    {
        double wide[] = {-DBL_MAX, -DBL_MAX, DBL_MAX, DBL_MAX}; /* finite knots whose span overflows */
        EXPECT(b.knots_v = wide, BS_ERR_DOMAIN);
        double half[] = {-DBL_MAX / 4, -DBL_MAX / 4, DBL_MAX / 4, DBL_MAX / 4}; /* wide, but no overflow */
        b = good;
        b.knots_v = half;
        CHECK_STATUS(bs_bspline_span_count(&b, &nu, &nv), BS_OK);
        b.knots_v = wide;
        CHECK_STATUS(bs_bspline_span_count(&b, &nu, &nv), BS_ERR_DOMAIN);
    }
    {
        double k3[] = {0, 1, 1, 1, 2}; /* a triple knot in a degree-1 vector: mult > p + 1 */
        EXPECT(b.knots_u = k3, BS_ERR_DOMAIN);
        double e3[] = {0, 0, 0, 1, 2}; /* the same at the start, the domain [0,1] not empty */
        EXPECT(b.knots_u = e3, BS_ERR_DOMAIN);
    }
    EXPECT((ku[2] = 3, ctrl[4] = NAN), BS_ERR_DOMAIN); /* knots before control points */
    ku[2] = 1;
    EXPECT(ctrl[4] = NAN, BS_ERR_NONFINITE);
    ctrl[4] = 4;
    EXPECT(ctrl[5] = -INFINITY, BS_ERR_NONFINITE);
    ctrl[5] = 5;
    EXPECT(w[3] = 0.0, BS_ERR_NONFINITE);
    EXPECT(w[3] = -1.0, BS_ERR_NONFINITE);
    EXPECT(w[3] = NAN, BS_ERR_NONFINITE);
    { /* a zero weight that no Bezier point keeps: in u the third of five points of a cubic with
       * one interior knot enters the Bezier nets only blended with its neighbours */
        double cu[] = {0, 0, 0, 0, 1, 2, 2, 2, 2}, c5[5 * 2 * 3], w5[10];
        for (int k = 0; k < 30; k++)
            c5[k] = k % 7;
        for (int k = 0; k < 10; k++)
            w5[k] = k == 4 ? 0.0 : 1.0;
        const bs_bspline cubic = {3, 1, 5, 2, 3, cu, kv, c5, w5};
        CHECK_STATUS(bs_surface_add_bspline(s, &cubic, NULL, 0, NULL), BS_ERR_NONFINITE);
        CHECK(bs_surface_count(s) == 2);
    }
    EXPECT((w[3] = 1e300, ctrl[9] = 1e10), BS_ERR_NONFINITE); /* w P overflows */
    w[3] = 1.0;
    ctrl[9] = 9;
    EXPECT(b.dim = 2, BS_ERR_INCOMPATIBLE); /* the surface holds 3-D patches */
    CHECK_STATUS(bs_surface_add_bspline(s, &good, spans, 7, &count), BS_ERR_SIZE); /* 2 patches need 8 */
    CHECK(bs_surface_count(s) == 2 && count == 42 && spans[0] == 0.0);
    CHECK_STATUS(bs_surface_add_bspline(NULL, &good, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_add_bspline(s, NULL, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_bspline_span_count(NULL, &nu, &nv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_bspline_span_count(&good, NULL, &nv), BS_ERR_INVALID_ARG);
    b = good;
    b.ctrl = NULL; /* the knot-only functions do not read the points */
    b.dim = 0;
    CHECK_STATUS(bs_bspline_span_count(&b, &nu, &nv), BS_OK);
    CHECK(nu == 2 && nv == 1);
    b.deg_u = 0;
    nu = 42;
    CHECK_STATUS(bs_bspline_span_count(&b, &nu, &nv), BS_ERR_DEGREE);
    CHECK(nu == 42);
    /* success with spans and count after all the failures */
    CHECK_STATUS(bs_surface_add_bspline(s, &good, spans, 8, &count), BS_OK);
    CHECK(bs_surface_count(s) == 4 && count == 2 && spans[1] == 1.0 && spans[4] == 1.0 && spans[5] == 2.0);
    /* a new surface takes the B-spline's dim */
    bs_surface *s2;
    CHECK_STATUS(bs_surface_create(&s2), BS_OK);
    b = good;
    b.dim = 2;
    b.weights = NULL;
    CHECK_STATUS(bs_surface_add_bspline(s2, &b, NULL, 0, &count), BS_OK);
    CHECK(bs_surface_dim(s2) == 2 && count == 2);
    bs_surface_destroy(s2);
    bs_surface_destroy(s);
#undef EXPECT
}

int main(void)
{
    random_surfaces();
    printf("worst patch error: %.3g of max|P| wmax/wmin (contract 1e-13)\n", worst_ratio);
    single_span_is_the_net();
    locate();
    errors();
    return bs_test_exit("test_bspline");
}
