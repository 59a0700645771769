/* Hodographs: the derivative patch's net equals the scaled difference net
 * m!/(m-k)! n!/(n-l)! Delta^(k,l) P, and it evaluates to the reference derivative of the parent. */
#include "ops_check.h"

static double worst_net, worst_eval, worst_lib;

static long double falling(size_t deg, unsigned k)
{
    long double f = 1.0L;
    for (unsigned r = 0; r < k; r++)
        f *= (long double)(deg - r);
    return f;
}

/* The exact hodograph net, in long double, as an lnet with weights 1. Delta^k by the binomial sum. */
static lnet exact_hodograph(const tnet *t, unsigned ku, unsigned kv)
{
    size_t m = t->m - ku, n = t->n - kv, cnt = (m + 1) * (n + 1);
    lnet l = {m, n, t->dim, malloc((t->dim + 1) * cnt * sizeof(long double))};
    long double scale = falling(t->m, ku) * falling(t->n, kv);
    for (size_t c = 0; c < t->dim; c++)
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                long double acc = 0.0L;
                for (unsigned a = 0; a <= ku; a++)
                    for (unsigned b = 0; b <= kv; b++) {
                        long double sgn = ((ku - a) + (kv - b)) % 2 ? -1.0L : 1.0L;
                        acc += sgn * ref_binom(ku, a) * ref_binom(kv, b) *
                               (long double)t->ctrl[((i + a) * (t->n + 1) + j + b) * t->dim + c];
                    }
                *lnet_at(&l, c, i, j) = scale * acc;
            }
    for (size_t k = 0; k < cnt; k++)
        l.h[t->dim * cnt + k] = 1.0L;
    return l;
}

static void check_hodograph(const tnet *net, const bs_patch *p, unsigned ku, unsigned kv, unsigned long long *rng)
{
    bs_patch *q = NULL;
    bs_status st = bs_patch_derivative(p, ku, kv, &q);
    CHECKF(st == BS_OK, "status %d, (%zu,%zu) order (%u,%u)", st, net->m, net->n, ku, kv);
    if (q == NULL)
        return;
    tnet got = tnet_of(q);
    CHECK(got.w == NULL && got.dim == net->dim);
    if (ku > net->m || kv > net->n) {
        CHECK(got.m == 0 && got.n == 0);
        int zero = 1;
        for (size_t c = 0; c < got.dim; c++)
            zero &= got.ctrl[c] == 0.0;
        CHECK(zero);
    } else {
        lnet ex = exact_hodograph(net, ku, kv);
        /* Each difference level can double the magnitude; the scale multiplies it. */
        double amp = (double)(falling(net->m, ku) * falling(net->n, kv)) * ldexp(1.0, (int)(ku + kv));
        double bound = ops_bound(net->m, net->n, net) * amp;
        double e = compare_net(&got, &ex, bound, 1.0);
        CHECKF(e <= 1.0, "net error %g of bound, (%zu,%zu) order (%u,%u)", e, net->m, net->n, ku, kv);
        worst_net = e > worst_net ? e : worst_net;
        /* evaluation of the hodograph vs the reference derivative of the parent */
        ref_net a = tnet_ref(&got), b = tnet_ref(net);
        long double x[BS_MAX_DIM], y[BS_MAX_DIM];
        for (int k = 0; k < 4; k++) {
            long double u = (long double)bs_test_rand(rng, 0, 1), v = (long double)bs_test_rand(rng, 0, 1);
            ref_eval(&a, u, v, x);
            ref_deriv(&b, ku, kv, u, v, y);
            for (size_t c = 0; c < net->dim; c++) {
                double err = (double)fabsl(x[c] - y[c]) / bound;
                CHECKF(err <= 1.0, "evaluation error %g of bound", err);
                worst_eval = err > worst_eval ? err : worst_eval;
            }
        }
        /* the library's own derivative evaluator agrees with the hodograph's reference value */
        enum { NPT = 5 };
        double us[NPT], vs[NPT], res[BS_MAX_DIM][NPT];
        for (int k = 0; k < NPT; k++) {
            us[k] = bs_test_rand(rng, 0, 1);
            vs[k] = bs_test_rand(rng, 0, 1);
        }
        bs_cview cu = {us, NPT, 0}, cv = {vs, NPT, 0};
        bs_view outv[BS_MAX_DIM];
        for (size_t c = 0; c < net->dim; c++) {
            outv[c].data = res[c];
            outv[c].count = NPT;
            outv[c].stride = 0;
        }
        CHECK_STATUS(bs_patch_eval_deriv(p, ku, kv, NPT, &cu, &cv, outv), BS_OK);
        for (int k = 0; k < NPT; k++) {
            ref_eval(&a, (long double)us[k], (long double)vs[k], x);
            for (size_t c = 0; c < net->dim; c++) {
                double err = (double)fabsl((long double)res[c][k] - x[c]) / bound;
                CHECKF(err <= 1.0, "bs_patch_eval_deriv differs from the hodograph by %g of the bound", err);
                worst_lib = err > worst_lib ? err : worst_lib;
            }
        }
        free(ex.h);
    }
    tnet_free(&got);
    bs_patch_destroy(q);
}

static void test_random(void)
{
    unsigned long long rng = 41;
    static const unsigned orders[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 3}, {3, 0}, {5, 2}, {8, 8}};
    for (size_t d = 0; d < OPS_NDEGREES; d++) {
        size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (3 * d) % 8;
        tnet net = tnet_random(&rng, m, n, dim, 0, 1, 1);
        bs_patch *p = tnet_patch(&net);
        for (size_t k = 0; k < sizeof orders / sizeof orders[0]; k++)
            check_hodograph(&net, p, orders[k][0], orders[k][1], &rng);
        check_hodograph(&net, p, (unsigned)m, (unsigned)n, &rng);          /* constant */
        if (m < BS_MAX_DEGREE)
            check_hodograph(&net, p, (unsigned)m + 1, 0, &rng); /* beyond the degree */
        check_hodograph(&net, p, 0, BS_MAX_DEGREE, &rng);
        bs_patch_destroy(p);
        tnet_free(&net);
    }
}

/* A small integer net: first differences times the degree, exactly. */
static void test_small_exact(void)
{
    const double net[6] = {1, 4, 9, 2, 3, 5}; /* (1,2), dim 1: rows (1,4,9), (2,3,5) */
    bs_patch *p = NULL, *q = NULL;
    CHECK_STATUS(bs_patch_create(1, 2, 1, net, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_derivative(p, 0, 1, &q), BS_OK);
    double c[4];
    CHECK(bs_patch_degree_u(q) == 1 && bs_patch_degree_v(q) == 1);
    CHECK_STATUS(bs_patch_get_ctrl(q, c, 4, NULL, 0), BS_OK);
    CHECK(c[0] == 6 && c[1] == 10 && c[2] == 2 && c[3] == 4);
    bs_patch_destroy(q);
    CHECK_STATUS(bs_patch_derivative(p, 1, 2, &q), BS_OK); /* 2 * (Delta^2 row1 - Delta^2 row0) = 2*(1 - 2) */
    CHECK_STATUS(bs_patch_get_ctrl(q, c, 1, NULL, 0), BS_OK);
    CHECK(c[0] == -2);
    bs_patch_destroy(q);
    bs_patch_destroy(p);
}

int main(void)
{
    test_random();
    test_small_exact();
    print_worst("hodograph nets vs difference formula", worst_net);
    print_worst("hodograph evaluation vs reference derivative", worst_eval);
    print_worst("bs_patch_eval_deriv vs hodograph (reference)", worst_lib);
    return bs_test_exit("test_hodograph");
}
