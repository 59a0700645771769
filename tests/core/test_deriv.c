/* bs_patch_eval_deriv: mixed partials of any order against the reference (polynomial and
 * rational), zero beyond the degree, agreement with bs_patch_eval, batch independence. */
#include "eval_util.h"

static void deriv1(const bs_patch *p, unsigned ku, unsigned kv, double u, double v, double *out)
{
    bs_cview cu = cview_of(&u, 1), cv = cview_of(&v, 1);
    bs_view vo[BS_MAX_DIM];
    views_of(out, bs_patch_dim(p), 1, vo);
    CHECK_STATUS(bs_patch_eval_deriv(p, ku, kv, 1, &cu, &cv, vo), BS_OK);
}

static void test_against_reference(int rational)
{
    unsigned long long rng = rational ? 101 : 100;
    double worst = 0.0;
    for (int trial = 0; trial < 80; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 10), n = (size_t)(bs_test_rand_u64(&rng) % 10);
        if (trial % 8 == 0) {
            m = 20 + (size_t)(bs_test_rand_u64(&rng) % 45);
            n = (size_t)(bs_test_rand_u64(&rng) % 65);
        }
        size_t dim = 1 + (size_t)(bs_test_rand_u64(&rng) % 8);
        tnet t = tnet_random(&rng, m, n, dim, rational, 0.5, 2.0);
        ref_net r = tnet_ref(&t);
        bs_patch *p = tnet_patch(&t);
        for (int k = 0; k < 4; k++) {
            unsigned ku = (unsigned)(bs_test_rand_u64(&rng) % (m + 3)), kv = (unsigned)(bs_test_rand_u64(&rng) % (n + 3));
            if (rational || m > 12 || n > 12) { /* keep the reference's Leibniz sums short */
                ku %= 4;
                kv %= 4;
            }
            double u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1);
            if (k == 0)
                u = 1.0;
            double out[BS_MAX_DIM];
            long double e[BS_MAX_DIM];
            deriv1(p, ku, kv, u, v, out);
            CHECK(ref_deriv(&r, ku, kv, u, v, e));
            double bnd = accuracy_bound(&t, ku, kv);
            if (!rational && (ku > m || kv > n))
                bnd = 0.0; /* exactly zero */
            for (size_t c = 0; c < dim; c++) {
                double err = (double)fabsl(out[c] - e[c]);
                if (bnd > 0)
                    worst = fmax(worst, err / bnd);
                CHECKF(err <= bnd, "deg (%zu,%zu) order (%u,%u) rational %d: %.17g vs %.17Lg bound %g", m, n,
                       ku, kv, rational, out[c], e[c], bnd);
            }
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
    printf("%s derivatives: worst error %.3g of the bound\n", rational ? "rational" : "polynomial", worst);
}

/* Order (0,0) is the position of bs_patch_eval bit for bit; (1,0) and (0,1) agree with its
 * derivatives within the bound. */
static void test_matches_eval(void)
{
    unsigned long long rng = 102;
    enum { N = 21 };
    for (int trial = 0; trial < 10; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 9), n = (size_t)(bs_test_rand_u64(&rng) % 9);
        tnet t = tnet_random(&rng, m, n, 2, 0, 0, 0);
        bs_patch *p = tnet_patch(&t);
        double u[N], v[N], pos[2 * N], du[2 * N], dv[2 * N], d0[2 * N], d1[2 * N], d2[2 * N];
        for (int k = 0; k < N; k++) {
            u[k] = bs_test_rand(&rng, 0, 1);
            v[k] = bs_test_rand(&rng, 0, 1);
        }
        bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
        bs_view vp[2], vu[2], vv[2], w0[2], w1[2], w2[2];
        views_of(pos, 2, N, vp);
        views_of(du, 2, N, vu);
        views_of(dv, 2, N, vv);
        views_of(d0, 2, N, w0);
        views_of(d1, 2, N, w1);
        views_of(d2, 2, N, w2);
        CHECK_STATUS(bs_patch_eval(p, N, &cu, &cv, vp, vu, vv), BS_OK);
        CHECK_STATUS(bs_patch_eval_deriv(p, 0, 0, N, &cu, &cv, w0), BS_OK);
        CHECK_STATUS(bs_patch_eval_deriv(p, 1, 0, N, &cu, &cv, w1), BS_OK);
        CHECK_STATUS(bs_patch_eval_deriv(p, 0, 1, N, &cu, &cv, w2), BS_OK);
        CHECK(memcmp(pos, d0, sizeof pos) == 0);
        for (int k = 0; k < 2 * N; k++) {
            CHECK(fabs(du[k] - d1[k]) <= 2 * accuracy_bound(&t, 1, 0));
            CHECK(fabs(dv[k] - d2[k]) <= 2 * accuracy_bound(&t, 0, 1));
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Batch size, negative strides and NaN parameters change nothing for the other points. */
static void test_layout_independence(void)
{
    unsigned long long rng = 103;
    enum { N = 19 };
    for (int rational = 0; rational < 2; rational++) {
        tnet t = tnet_random(&rng, 5, 3, 3, rational, 0.5, 2.0);
        bs_patch *p = tnet_patch(&t);
        double u[N], v[N], all[3 * N];
        for (int k = 0; k < N; k++) {
            u[k] = bs_test_rand(&rng, -0.5, 1.5);
            v[k] = bs_test_rand(&rng, -0.5, 1.5);
        }
        u[3] = -INFINITY;
        bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
        bs_view va[3];
        views_of(all, 3, N, va);
        CHECK_STATUS(bs_patch_eval_deriv(p, 2, 1, N, &cu, &cv, va), BS_OK);
        CHECK(isnan(all[3]) && isnan(all[N + 3]) && isnan(all[2 * N + 3]));
        int same = 1;
        for (int k = 0; k < N; k++) {
            double one[3];
            deriv1(p, 2, 1, u[k], v[k], one);
            for (int c = 0; c < 3; c++)
                same &= memcmp(&one[c], &all[c * N + k], 8) == 0;
        }
        CHECK(same);
        double rev[3 * N];
        bs_view vr[3];
        for (int c = 0; c < 3; c++) {
            vr[c].data = rev + c * N + N - 1;
            vr[c].count = N;
            vr[c].stride = -8;
        }
        CHECK_STATUS(bs_patch_eval_deriv(p, 2, 1, N, &cu, &cv, vr), BS_OK);
        same = 1;
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < N; k++)
                same &= memcmp(&rev[c * N + N - 1 - k], &all[c * N + k], 8) == 0;
        CHECK(same);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* High orders: degree 64 differentiated 64 times is 64! times the 64th difference; rational
 * patches have non-zero derivatives beyond their degree. */
static void test_high_orders(void)
{
    static double c[65];
    for (int i = 0; i <= 64; i++)
        c[i] = i == 64 ? 1.0 : 0.0; /* S = u^64 */
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(64, 0, 1, c, NULL, &p), BS_OK);
    double out, f = 1.0;
    for (int k = 2; k <= 64; k++)
        f *= k;
    deriv1(p, 64, 0, 0.3, 0.7, &out);
    CHECKF(fabs(out - f) <= 1e-13 * f, "%.17g vs %.17g", out, f);
    deriv1(p, 64, 1, 0.3, 0.7, &out);
    CHECK(out == 0.0);
    deriv1(p, 1, 0, 0.5, 0.0, &out);
    CHECKF(fabs(out - 64.0 * ldexp(1.0, -63)) <= 1e-15 * 64.0 * ldexp(1.0, -63), "%g", out);
    bs_patch_destroy(p);

    /* the rational quarter circle x = (1-t^2)/(1+t^2) along u: derivatives exist at every order */
    double q[6] = {1, 0, 1, 1, 0, 1}, w[3] = {1, 0.70710678118654752440, 1};
    CHECK_STATUS(bs_patch_create(2, 0, 2, q, w, &p), BS_OK);
    tnet t = {2, 0, 2, q, w};
    ref_net r = tnet_ref(&t);
    for (unsigned k = 0; k <= 8; k++) {
        double o[2];
        long double e[2];
        deriv1(p, k, 0, 0.4, 0.5, o);
        ref_deriv(&r, k, 0, 0.4L, 0.5L, e);
        for (int d = 0; d < 2; d++)
            CHECKF(fabsl(o[d] - e[d]) <= accuracy_bound(&t, k, 0), "order %u: %.17g vs %.17Lg", k, o[d], e[d]);
        if (k >= 3)
            CHECK(o[0] != 0.0 || o[1] != 0.0);
    }
    bs_patch_destroy(p);
}

int main(void)
{
    test_against_reference(0);
    test_against_reference(1);
    test_matches_eval();
    test_layout_independence();
    test_high_orders();
    return bs_test_exit("test_deriv");
}
