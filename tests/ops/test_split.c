/* Splitting: each half's net equals the exact de Casteljau (blossom) net of its part, evaluates to
 * the parent over its part, and the halves share their common boundary bit for bit. Split4 too. */
#include "ops_check.h"

static double worst_net, worst_eval;

/* Row i (dir U) or column (dir V) k of two nets are identical, weights included. */
static int same_boundary(const tnet *a, size_t ka, const tnet *b, size_t kb, int dir)
{
    size_t cnt = (dir == BS_DIR_U ? a->n : a->m) + 1;
    for (size_t f = 0; f < cnt; f++) {
        size_t ia = dir == BS_DIR_U ? ka * (a->n + 1) + f : f * (a->n + 1) + ka;
        size_t ib = dir == BS_DIR_U ? kb * (b->n + 1) + f : f * (b->n + 1) + kb;
        if (memcmp(a->ctrl + ia * a->dim, b->ctrl + ib * b->dim, a->dim * sizeof(double)) != 0)
            return 0;
        if (a->w && memcmp(a->w + ia, b->w + ib, sizeof(double)) != 0)
            return 0;
    }
    return 1;
}

static void check_part(const bs_patch *part, const tnet *parent, double u0, double u1, double v0,
                       double v1, unsigned long long *rng)
{
    CHECK(part != NULL);
    if (part == NULL)
        return;
    tnet got = tnet_of(part);
    CHECK(got.m == parent->m && got.n == parent->n && got.dim == parent->dim);
    CHECK((got.w != NULL) == (parent->w != NULL));
    lnet ex = lnet_of(parent);
    lnet_sub(&ex, BS_DIR_U, u0, u1);
    lnet_sub(&ex, BS_DIR_V, v0, v1);
    double bound = ops_bound(parent->m, parent->n, parent);
    double wb = 4.0 * (double)(parent->m + parent->n + 1) * OPS_EPS * tnet_wmax(parent);
    double e = compare_net(&got, &ex, bound, wb);
    CHECKF(e <= 1.0, "net error %g of bound, degree (%zu,%zu) dim %zu", e, parent->m, parent->n, parent->dim);
    worst_net = e > worst_net ? e : worst_net;
    e = compare_eval(&got, parent, rng, 6, u0, u1, v0, v1, bound);
    CHECKF(e <= 1.0, "evaluation error %g of bound", e);
    worst_eval = e > worst_eval ? e : worst_eval;
    free(ex.h);
    tnet_free(&got);
}

static void test_split_random(void)
{
    unsigned long long rng = 11;
    for (size_t d = 0; d < OPS_NDEGREES && !ops_degree_skipped(d); d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            bs_patch *p = tnet_patch(&net);
            CHECK(p != NULL);
            for (int dir = BS_DIR_U; dir <= BS_DIR_V; dir++) {
                double t = d == 0 ? 0.5 : bs_test_rand(&rng, 0.05, 0.95);
                bs_patch *lo = NULL, *hi = NULL;
                CHECK_STATUS(bs_patch_split(p, dir, t, &lo, &hi), BS_OK);
                if (dir == BS_DIR_U) {
                    check_part(lo, &net, 0, t, 0, 1, &rng);
                    check_part(hi, &net, t, 1, 0, 1, &rng);
                } else {
                    check_part(lo, &net, 0, 1, 0, t, &rng);
                    check_part(hi, &net, 0, 1, t, 1, &rng);
                }
                if (lo && hi) {
                    tnet a = tnet_of(lo), b = tnet_of(hi);
                    size_t last = dir == BS_DIR_U ? m : n;
                    CHECKF(same_boundary(&a, last, &b, 0, dir), "split halves differ on their boundary");
                    /* the outer boundaries are the parent's, exactly for polynomial patches */
                    if (!rational) {
                        CHECK(same_boundary(&a, 0, &net, 0, dir));
                        CHECK(same_boundary(&b, last, &net, last, dir));
                    }
                    tnet_free(&a);
                    tnet_free(&b);
                }
                bs_patch_destroy(lo);
                bs_patch_destroy(hi);
            }
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

static void test_split4_random(void)
{
    unsigned long long rng = 12;
    for (size_t d = 0; d < OPS_NDEGREES && !ops_degree_skipped(d); d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (3 * d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.5, 2.0);
            bs_patch *p = tnet_patch(&net), *q[4] = {NULL, NULL, NULL, NULL};
            double u = bs_test_rand(&rng, 0.1, 0.9), v = bs_test_rand(&rng, 0.1, 0.9);
            CHECK_STATUS(bs_patch_split4(p, u, v, q), BS_OK);
            check_part(q[0], &net, 0, u, 0, v, &rng);
            check_part(q[1], &net, u, 1, 0, v, &rng);
            check_part(q[2], &net, 0, u, v, 1, &rng);
            check_part(q[3], &net, u, 1, v, 1, &rng);
            if (q[0] && q[1] && q[2] && q[3]) {
                tnet a[4];
                for (int k = 0; k < 4; k++)
                    a[k] = tnet_of(q[k]);
                CHECK(same_boundary(&a[0], m, &a[1], 0, BS_DIR_U));
                CHECK(same_boundary(&a[2], m, &a[3], 0, BS_DIR_U));
                CHECK(same_boundary(&a[0], n, &a[2], 0, BS_DIR_V));
                CHECK(same_boundary(&a[1], n, &a[3], 0, BS_DIR_V));
                for (int k = 0; k < 4; k++)
                    tnet_free(&a[k]);
            }
            for (int k = 0; k < 4; k++)
                bs_patch_destroy(q[k]);
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

/* MATH.md's worked net: the corner of the halves at u = v = 1/2 is (17/8, 9/4, 13/8) exactly. */
static void test_split_worked_example(void)
{
    static const double net3[27] = {1, 0, 2, 1, 2, 4, 1, 3, 2, 2, 1, 0, 2, 2, 2, 2, 4, 0, 4, 1, 0, 3, 3, 2, 4, 4, 2};
    bs_patch *p = NULL, *q[4] = {NULL, NULL, NULL, NULL};
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_split4(p, 0.5, 0.5, q), BS_OK);
    double c[27];
    CHECK_STATUS(bs_patch_get_ctrl(q[0], c, 27, NULL, 0), BS_OK);
    CHECK(c[24] == 17.0 / 8 && c[25] == 9.0 / 4 && c[26] == 13.0 / 8);
    CHECK(c[0] == 1 && c[1] == 0 && c[2] == 2);
    CHECK_STATUS(bs_patch_get_ctrl(q[3], c, 27, NULL, 0), BS_OK);
    CHECK(c[0] == 17.0 / 8 && c[1] == 9.0 / 4 && c[2] == 13.0 / 8);
    CHECK(c[24] == 4 && c[25] == 4 && c[26] == 2);
    for (int k = 0; k < 4; k++)
        bs_patch_destroy(q[k]);
    bs_patch_destroy(p);
}

int main(void)
{
    test_split_random();
    test_split4_random();
    test_split_worked_example();
    print_worst("split/split4 nets vs exact", worst_net);
    print_worst("split/split4 evaluation vs parent", worst_eval);
    return bs_test_exit("test_split");
}
