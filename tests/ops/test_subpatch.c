/* Sub-patches: the net over any rectangle (reversed directions, extrapolation included) equals the
 * exact blossom net, and evaluates to the parent over the mapped rectangle. */
#include "ops_check.h"

static double worst_net, worst_eval, worst_extra;
static int n_nonpositive;

static void check_sub(const tnet *net, const bs_patch *p, double u0, double u1, double v0, double v1,
                      double growth, unsigned long long *rng, double *worst)
{
    bs_patch *q = NULL;
    lnet ex = lnet_of(net);
    lnet_sub(&ex, BS_DIR_U, u0, u1);
    lnet_sub(&ex, BS_DIR_V, v0, v1);
    /* Extrapolated weights may fail to be positive: then the result is no valid patch. */
    long double wmin = INFINITY;
    size_t cnt = tnet_count(net);
    for (size_t k = 0; k < cnt; k++)
        wmin = ex.h[net->dim * cnt + k] < wmin ? ex.h[net->dim * cnt + k] : wmin;
    if (wmin < 1e-3L) {
        q = (bs_patch *)&q;
        CHECK_STATUS(bs_patch_subpatch(p, u0, u1, v0, v1, &q), wmin <= 0 ? BS_ERR_NONFINITE : BS_OK);
        if (wmin <= 0)
            CHECK(q == NULL);
        bs_patch_destroy(q);
        n_nonpositive++;
        free(ex.h);
        return;
    }
    CHECK_STATUS(bs_patch_subpatch(p, u0, u1, v0, v1, &q), BS_OK);
    CHECK(q != NULL);
    if (q == NULL) {
        free(ex.h);
        return;
    }
    tnet got = tnet_of(q);
    CHECK(got.m == net->m && got.n == net->n && (got.w != NULL) == (net->w != NULL));
    /* Outside [0,1] each de Casteljau level can amplify by |1-t| + |t|: growth^(m+n). */
    double amp = pow(growth, (double)(net->m + net->n));
    double bound = ops_bound(net->m, net->n, net) * amp;
    double wb = 4.0 * (double)(net->m + net->n + 1) * OPS_EPS * tnet_wmax(net) * amp;
    double e = compare_net(&got, &ex, bound, wb);
    CHECKF(e <= 1.0, "net error %g of bound, [%g,%g]x[%g,%g] degree (%zu,%zu)", e, u0, u1, v0, v1, net->m, net->n);
    *worst = e > *worst ? e : *worst;
    e = compare_eval(&got, net, rng, 5, u0, u1, v0, v1, bound);
    CHECKF(e <= 1.0, "evaluation error %g of bound", e);
    worst_eval = e > worst_eval ? e : worst_eval;
    free(ex.h);
    tnet_free(&got);
    bs_patch_destroy(q);
}

static void test_random_rectangles(void)
{
    unsigned long long rng = 21;
    for (size_t d = 0; d < OPS_NDEGREES && !ops_degree_skipped(d); d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (5 * d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            bs_patch *p = tnet_patch(&net);
            double a = bs_test_rand(&rng, 0, 1), b = bs_test_rand(&rng, 0, 1);
            double c = bs_test_rand(&rng, 0, 1), e = bs_test_rand(&rng, 0, 1);
            check_sub(&net, p, a, b, c, e, 1.0, &rng, &worst_net); /* any order: reversals too */
            check_sub(&net, p, b, a, e, c, 1.0, &rng, &worst_net);
            check_sub(&net, p, 0.0, 1.0, 1.0, 0.0, 1.0, &rng, &worst_net);
            check_sub(&net, p, 0.3, 0.3000001, 0.999, 1.0, 1.0, &rng, &worst_net); /* tiny intervals */
            if (m + n <= 20) {
                /* Extrapolation: [-0.25, 1.25] amplifies by at most 1.5 per level. */
                check_sub(&net, p, -0.25, 1.25, 1.25, -0.25, 1.5, &rng, &worst_extra);
                check_sub(&net, p, 1.1, 1.2, -0.2, 0.5, 1.4, &rng, &worst_extra);
            }
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

/* The identity rectangle returns the polynomial net unchanged; reversal reindexes it exactly. */
static void test_identity_and_reversal(void)
{
    unsigned long long rng = 22;
    tnet net = tnet_random(&rng, 4, 2, 3, 0, 1, 1);
    bs_patch *p = tnet_patch(&net), *q = NULL;
    CHECK_STATUS(bs_patch_subpatch(p, 0, 1, 0, 1, &q), BS_OK);
    tnet got = tnet_of(q);
    CHECK(memcmp(got.ctrl, net.ctrl, 15 * 3 * sizeof(double)) == 0);
    tnet_free(&got);
    bs_patch_destroy(q);
    CHECK_STATUS(bs_patch_subpatch(p, 1, 0, 1, 0, &q), BS_OK);
    got = tnet_of(q);
    int ok = 1;
    for (size_t i = 0; i <= 4; i++)
        for (size_t j = 0; j <= 2; j++)
            ok &= memcmp(got.ctrl + (i * 3 + j) * 3, net.ctrl + ((4 - i) * 3 + (2 - j)) * 3, 3 * sizeof(double)) == 0;
    CHECK(ok);
    tnet_free(&got);
    bs_patch_destroy(q);
    bs_patch_destroy(p);
    tnet_free(&net);
}

int main(void)
{
    test_random_rectangles();
    test_identity_and_reversal();
    print_worst("sub-patch nets vs exact (inside [0,1])", worst_net);
    print_worst("sub-patch nets vs exact (extrapolated)", worst_extra);
    print_worst("sub-patch evaluation vs parent", worst_eval);
    printf("  %d extrapolated rational cases with weights not positive (rejected)\n", n_nonpositive);
    return bs_test_exit("test_subpatch");
}
