/* Bounds (contain the surface, attained by the net), affine transforms (net and surface mapped,
 * weights kept), and orientation changes (exact reindexing, same surface). */
#include "ops_check.h"

static double worst_affine;

static void test_bounds(void)
{
    static const double net3[27] = {1, 0, 2, 1, 2, 4, 1, 3, 2, 2, 1, 0, 2, 2, 2, 2, 4, 0, 4, 1, 0, 3, 3, 2, 4, 4, 2};
    bs_patch *p = NULL;
    double lo[3], hi[3];
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_bounds(p, lo, hi), BS_OK);
    CHECK(lo[0] == 1 && lo[1] == 0 && lo[2] == 0 && hi[0] == 4 && hi[1] == 4 && hi[2] == 4);
    bs_patch_destroy(p);

    unsigned long long rng = 61;
    for (size_t d = 0; d < OPS_NDEGREES; d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.1, 10.0);
            p = tnet_patch(&net);
            double blo[BS_MAX_DIM], bhi[BS_MAX_DIM];
            CHECK_STATUS(bs_patch_bounds(p, blo, bhi), BS_OK);
            ref_net r = tnet_ref(&net);
            long double x[BS_MAX_DIM];
            int inside = 1;
            for (int k = 0; k < 20; k++) {
                ref_eval(&r, (long double)bs_test_rand(&rng, 0, 1), (long double)bs_test_rand(&rng, 0, 1), x);
                for (size_t c = 0; c < dim; c++)
                    inside &= x[c] >= (long double)blo[c] - 1e-15L && x[c] <= (long double)bhi[c] + 1e-15L;
            }
            CHECK(inside);
            for (size_t c = 0; c < dim; c++) { /* tight on the net: each bound is a control coordinate */
                int at_lo = 0, at_hi = 0, within = 1;
                for (size_t k = 0; k < tnet_count(&net); k++) {
                    double v = net.ctrl[k * dim + c];
                    at_lo |= v == blo[c];
                    at_hi |= v == bhi[c];
                    within &= v >= blo[c] && v <= bhi[c];
                }
                CHECK(at_lo && at_hi && within);
            }
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

static void test_affine(void)
{
    unsigned long long rng = 62;
    for (size_t d = 0; d < OPS_NDEGREES; d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (2 * d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            double a[BS_MAX_DIM * (BS_MAX_DIM + 1)];
            for (size_t k = 0; k < dim * (dim + 1); k++)
                a[k] = bs_test_rand(&rng, -2, 2);
            bs_patch *p = tnet_patch(&net), *q = NULL;
            CHECK_STATUS(bs_patch_transform(p, a, &q), BS_OK);
            if (q == NULL)
                continue;
            tnet got = tnet_of(q);
            CHECK(got.m == m && got.n == n && (got.w != NULL) == rational);
            if (rational)
                CHECK(memcmp(got.w, net.w, tnet_count(&net) * sizeof(double)) == 0);
            double pmax = tnet_maxabs(&net);
            for (size_t k = 0; k < tnet_count(&net); k++)
                for (size_t r = 0; r < dim; r++) {
                    long double acc = a[r * (dim + 1) + dim], mag = fabsl(acc);
                    for (size_t c = 0; c < dim; c++) {
                        acc += (long double)a[r * (dim + 1) + c] * net.ctrl[k * dim + c];
                        mag += fabsl((long double)a[r * (dim + 1) + c]) * pmax;
                    }
                    double e = (double)(fabsl(got.ctrl[k * dim + r] - acc) / ((long double)(dim + 2) * OPS_EPS * mag));
                    CHECKF(e <= 1.0, "transformed point error %g of bound", e);
                    worst_affine = e > worst_affine ? e : worst_affine;
                }
            /* the surface is mapped: S_q(u,v) = A S_p(u,v) + b */
            ref_net rp = tnet_ref(&net), rq = tnet_ref(&got);
            long double x[BS_MAX_DIM], y[BS_MAX_DIM];
            for (int k = 0; k < 4; k++) {
                long double u = (long double)bs_test_rand(&rng, 0, 1), v = (long double)bs_test_rand(&rng, 0, 1);
                ref_eval(&rp, u, v, x);
                ref_eval(&rq, u, v, y);
                for (size_t r = 0; r < dim; r++) {
                    long double acc = a[r * (dim + 1) + dim];
                    for (size_t c = 0; c < dim; c++)
                        acc += (long double)a[r * (dim + 1) + c] * x[c];
                    CHECK(fabsl(acc - y[r]) <= 1e-12L * (1 + fabsl(acc)));
                }
            }
            tnet_free(&got);
            bs_patch_destroy(q);
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

static void test_orientation(void)
{
    unsigned long long rng = 63;
    for (size_t d = 0; d < OPS_NDEGREES; d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (5 * d + (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            bs_patch *p = tnet_patch(&net), *s = NULL, *ru = NULL, *rv = NULL;
            CHECK_STATUS(bs_patch_swap_uv(p, &s), BS_OK);
            CHECK_STATUS(bs_patch_reverse(p, BS_DIR_U, &ru), BS_OK);
            CHECK_STATUS(bs_patch_reverse(p, BS_DIR_V, &rv), BS_OK);
            if (s && ru && rv) {
                tnet ts = tnet_of(s), tu = tnet_of(ru), tv = tnet_of(rv);
                CHECK(ts.m == n && ts.n == m && tu.m == m && tu.n == n && tv.m == m && tv.n == n);
                int ok_s = 1, ok_u = 1, ok_v = 1;
                for (size_t i = 0; i <= m; i++)
                    for (size_t j = 0; j <= n; j++) {
                        size_t src = i * (n + 1) + j;
                        size_t is = j * (m + 1) + i, iu = (m - i) * (n + 1) + j, iv = i * (n + 1) + (n - j);
                        ok_s &= memcmp(ts.ctrl + is * dim, net.ctrl + src * dim, dim * sizeof(double)) == 0;
                        ok_u &= memcmp(tu.ctrl + iu * dim, net.ctrl + src * dim, dim * sizeof(double)) == 0;
                        ok_v &= memcmp(tv.ctrl + iv * dim, net.ctrl + src * dim, dim * sizeof(double)) == 0;
                        if (rational) {
                            ok_s &= ts.w[is] == net.w[src];
                            ok_u &= tu.w[iu] == net.w[src];
                            ok_v &= tv.w[iv] == net.w[src];
                        }
                    }
                CHECK(ok_s && ok_u && ok_v);
                /* same surface, reparametrised */
                ref_net rp = tnet_ref(&net), rs = tnet_ref(&ts), rru = tnet_ref(&tu), rrv = tnet_ref(&tv);
                long double x[BS_MAX_DIM], y[BS_MAX_DIM], z[BS_MAX_DIM], w[BS_MAX_DIM];
                long double u = 0.3L, v = 0.8L;
                ref_eval(&rp, u, v, x);
                ref_eval(&rs, v, u, y);
                ref_eval(&rru, 1 - u, v, z);
                ref_eval(&rrv, u, 1 - v, w);
                double bound = ops_bound(m, n, &net);
                for (size_t c = 0; c < dim; c++)
                    CHECK(fabsl(x[c] - y[c]) <= bound && fabsl(x[c] - z[c]) <= bound && fabsl(x[c] - w[c]) <= bound);
                tnet_free(&ts);
                tnet_free(&tu);
                tnet_free(&tv);
            }
            bs_patch_destroy(s);
            bs_patch_destroy(ru);
            bs_patch_destroy(rv);
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

int main(void)
{
    test_bounds();
    test_affine();
    test_orientation();
    print_worst("affine transform of the net vs exact", worst_affine);
    return bs_test_exit("test_transform");
}
