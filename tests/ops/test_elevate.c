/* Degree elevation: the elevated net equals the exact formula
 * Q_k = sum_i C(m,i) C(r,k-i) / C(m+r,k) P_i (homogeneous, per direction), and the surface is unchanged. */
#include "ops_check.h"

static double worst_net, worst_eval;

/* Exact elevation of an lnet along dir by r, returning a new lnet. */
static lnet lnet_elevate(const lnet *l, int dir, size_t r)
{
    size_t m2 = dir == BS_DIR_U ? l->m + r : l->m, n2 = dir == BS_DIR_U ? l->n : l->n + r;
    lnet e = {m2, n2, l->dim, malloc((l->dim + 1) * (m2 + 1) * (n2 + 1) * sizeof(long double))};
    size_t deg = dir == BS_DIR_U ? l->m : l->n, nfib = (dir == BS_DIR_U ? l->n : l->m) + 1;
    for (size_t c = 0; c <= l->dim; c++)
        for (size_t f = 0; f < nfib; f++)
            for (size_t k = 0; k <= deg + r; k++) {
                long double acc = 0.0L;
                for (size_t i = 0; i <= deg; i++)
                    if (i <= k && k - i <= r)
                        acc += ref_binom((unsigned)deg, (unsigned)i) * ref_binom((unsigned)r, (unsigned)(k - i)) /
                               ref_binom((unsigned)(deg + r), (unsigned)k) *
                               (dir == BS_DIR_U ? *lnet_at(l, c, i, f) : *lnet_at(l, c, f, i));
                *(dir == BS_DIR_U ? lnet_at(&e, c, k, f) : lnet_at(&e, c, f, k)) = acc;
            }
    return e;
}

static void check_elevate(const tnet *net, size_t ru, size_t rv, unsigned long long *rng)
{
    bs_patch *p = tnet_patch(net), *q = NULL;
    CHECK_STATUS(bs_patch_elevate(p, ru, rv, &q), BS_OK);
    CHECK(q != NULL);
    if (q != NULL) {
        tnet got = tnet_of(q);
        CHECK(got.m == net->m + ru && got.n == net->n + rv && (got.w != NULL) == (net->w != NULL));
        lnet l = lnet_of(net), a = lnet_elevate(&l, BS_DIR_U, ru), b = lnet_elevate(&a, BS_DIR_V, rv);
        double bound = ops_bound(got.m, got.n, net);
        double wb = 4.0 * (double)(got.m + got.n + 1) * OPS_EPS * tnet_wmax(net);
        double e = compare_net(&got, &b, bound, wb);
        CHECKF(e <= 1.0, "net error %g of bound, (%zu,%zu) raised by (%zu,%zu)", e, net->m, net->n, ru, rv);
        worst_net = e > worst_net ? e : worst_net;
        e = compare_eval(&got, net, rng, 5, 0, 1, 0, 1, bound);
        CHECKF(e <= 1.0, "evaluation error %g of bound", e);
        worst_eval = e > worst_eval ? e : worst_eval;
        free(l.h);
        free(a.h);
        free(b.h);
        tnet_free(&got);
    }
    bs_patch_destroy(q);
    bs_patch_destroy(p);
}

static void test_random(void)
{
    unsigned long long rng = 31;
    for (size_t d = 0; d < OPS_NDEGREES; d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (7 * d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            size_t ru = BS_MAX_DEGREE - m, rv = BS_MAX_DEGREE - n;
            check_elevate(&net, ru < 3 ? ru : 3, rv < 1 ? rv : 1, &rng);
            check_elevate(&net, 0, rv, &rng);  /* to the largest degree */
            check_elevate(&net, ru / 2, 0, &rng);
            bs_patch *p = tnet_patch(&net), *q = (bs_patch *)&q;
            CHECK_STATUS(bs_patch_elevate(p, ru + 1, 0, &q), BS_ERR_DEGREE);
            CHECK(q == NULL);
            CHECK_STATUS(bs_patch_elevate(p, 0, (size_t)-1, &q), BS_ERR_DEGREE);
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

/* A small integer net: (1,1) raised to (2,1) has the midpoints as new middle row, exactly. */
static void test_small_exact(void)
{
    const double net[8] = {0, 0, 1, 4, 6, 2, 3, 10};
    bs_patch *p = NULL, *q = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 2, net, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_elevate(p, 1, 0, &q), BS_OK);
    double c[12];
    CHECK_STATUS(bs_patch_get_ctrl(q, c, 12, NULL, 0), BS_OK);
    const double want[12] = {0, 0, 1, 4, 3, 1, 2, 7, 6, 2, 3, 10};
    CHECK(memcmp(c, want, sizeof want) == 0);
    bs_patch_destroy(q);
    CHECK_STATUS(bs_patch_elevate(p, 0, 2, &q), BS_OK); /* v: (0,0) (1/3)(2/3) (1,4) mixing by thirds */
    double d[16];
    CHECK_STATUS(bs_patch_get_ctrl(q, d, 16, NULL, 0), BS_OK);
    CHECK(d[0] == 0 && d[6] == 1 && d[7] == 4 && fabs(d[2] - 1.0 / 3) < 1e-16 && fabs(d[5] - 8.0 / 3) < 1e-15);
    bs_patch_destroy(q);
    bs_patch_destroy(p);
}

int main(void)
{
    test_random();
    test_small_exact();
    print_worst("elevated nets vs exact", worst_net);
    print_worst("elevated evaluation vs parent", worst_eval);
    return bs_test_exit("test_elevate");
}
