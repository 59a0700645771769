/* The accuracy contract (docs/accuracy.md), measured against the long-double reference on random
 * nets of every degree up to 64: every coordinate of d^(k+l)S/du^k dv^l within
 * 2(m+n+1) eps max|P| 2^(k+l) m!/(m-k)! n!/(n-l)! (k! m^k l! n^l when rational, times
 * (wmax/wmin)^(1+k+l)), never below 4 ulp of the largest exact derivative of the same order;
 * unit normals within 1e-9. Prints the worst error as a fraction of the bound. BS_TEST_QUICK (as
 * under memcheck): every fourth degree in u. */
#include "eval_util.h"

static double worst_poly, worst_rat, worst_normal;
static int floors_used; /* points where only the 4-ulp floor of the bound was met */

/* 4 ulp of the largest exact derivative of total order ord at (u,v), any coordinate. */
static double order_floor(const ref_net *r, unsigned ord, size_t dim, double u, double v)
{
    long double big = 0.0L, any[BS_MAX_DIM];
    for (unsigned a = 0; a <= ord; a++) {
        ref_deriv(r, a, ord - a, u, v, any);
        for (size_t c = 0; c < dim; c++)
            big = fmaxl(big, fabsl(any[c]));
    }
    return big > 0.0L ? ldexp(4.0, ilogb((double)big) - 52) : 0.0;
}

static void check_net(unsigned long long *rng, size_t m, size_t n, size_t dim, int rational)
{
    tnet t = tnet_random(rng, m, n, dim, rational, 0.5, 2.0);
    ref_net r = tnet_ref(&t);
    bs_patch *p = tnet_patch(&t);
    enum { N = 3 };
    double u[N], v[N];
    for (int k = 0; k < N; k++) {
        u[k] = bs_test_rand(rng, 0, 1);
        v[k] = bs_test_rand(rng, 0, 1);
    }
    u[0] = 0.0;
    v[1] = 1.0;
    bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
    unsigned orders[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {0, 2}, {2, 1}, {3, 0}, {0, 3}, {5, 4}};
    size_t nord = 10; /* rational ones past their degree too (the 1.1 bound) */
    for (size_t o = 0; o < nord; o++) {
        unsigned k = orders[o][0], l = orders[o][1];
        double res[BS_MAX_DIM * N];
        bs_view vo[BS_MAX_DIM];
        views_of(res, dim, N, vo);
        CHECK_STATUS(bs_patch_eval_deriv(p, k, l, N, &cu, &cv, vo), BS_OK);
        double bnd0 = accuracy_bound(&t, k, l);
        for (int q = 0; q < N; q++) {
            long double e[BS_MAX_DIM];
            ref_deriv(&r, k, l, u[q], v[q], e);
            /* The bound's floor, 4 ulp of the largest exact derivative of the same order k + l
             * here, is computed only where the bound before it is not met (it is costly). */
            double bnd = bnd0;
            for (size_t c = 0; c < dim; c++)
                if ((double)fabsl(res[c * N + (size_t)q] - e[c]) > bnd0 && bnd == bnd0)
                    bnd = fmax(bnd0, order_floor(&r, k + l, dim, u[q], v[q]));
            floors_used += bnd != bnd0;
            for (size_t c = 0; c < dim; c++) {
                double err = (double)fabsl(res[c * N + (size_t)q] - e[c]);
                if (bnd > 0) {
                    double f = err / bnd;
                    if (rational)
                        worst_rat = fmax(worst_rat, f);
                    else
                        worst_poly = fmax(worst_poly, f);
                }
                CHECKF(bnd > 0 ? err <= bnd : err == 0.0, "deg (%zu,%zu) rational %d order (%u,%u): err %g bound %g",
                       m, n, rational, k, l, err, bnd);
            }
        }
    }
    bs_patch_destroy(p);
    tnet_free(&t);
}

/* Normals of graph-like nets z = f(x,y) (a normal exists everywhere) at random points. */
static void check_normals(unsigned long long *rng, size_t m, size_t n, int rational)
{
    tnet t = tnet_random(rng, m, n, 3, rational, 0.5, 2.0);
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            double *P = t.ctrl + (i * (n + 1) + j) * 3;
            P[0] = (double)i / (double)(m ? m : 1) + 0.3 / (double)(m + 1) * P[0];
            P[1] = (double)j / (double)(n ? n : 1) + 0.3 / (double)(n + 1) * P[1];
        }
    ref_net r = tnet_ref(&t);
    bs_patch *p = tnet_patch(&t);
    enum { N = 8 };
    double u[N], v[N], nrm[3 * N];
    unsigned char kind[N];
    for (int k = 0; k < N; k++) {
        u[k] = bs_test_rand(rng, 0, 1);
        v[k] = bs_test_rand(rng, 0, 1);
    }
    bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
    bs_view vn[3];
    views_of(nrm, 3, N, vn);
    CHECK_STATUS(bs_patch_eval_normal(p, N, &cu, &cv, NULL, vn, kind), BS_OK);
    for (int k = 0; k < N; k++) {
        long double e[3] = {0, 0, 0};
        CHECK(kind[k] == BS_NORMAL_REGULAR);
        CHECK(ref_normal(&r, u[k], v[k], e));
        long double d0 = nrm[k] - e[0], d1 = nrm[N + k] - e[1], d2 = nrm[2 * N + k] - e[2];
        double d = (double)sqrtl(d0 * d0 + d1 * d1 + d2 * d2);
        worst_normal = fmax(worst_normal, d);
        CHECKF(d <= 1e-9, "deg (%zu,%zu) rational %d: normal off by %g", m, n, rational, d);
    }
    bs_patch_destroy(p);
    tnet_free(&t);
}

int main(void)
{
    unsigned long long rng = 900;
    /* every degree 0..64 in u (every fourth under BS_TEST_QUICK), paired with a random one in v,
     * both ways round */
    for (size_t m = 0; m <= BS_MAX_DEGREE; m += bs_test_quick() ? 4 : 1) {
        size_t n = (size_t)(bs_test_rand_u64(&rng) % (BS_MAX_DEGREE + 1));
        size_t dim = 1 + (size_t)(bs_test_rand_u64(&rng) % BS_MAX_DIM);
        check_net(&rng, m, n, dim, 0);
        check_net(&rng, n, m, dim, 0);
        check_net(&rng, m, n, 3, 1);
        if (m > 0 && n > 0) /* degree 0 in a direction: a curve, no normal */
            check_normals(&rng, m, n, (int)(m % 2));
    }
    check_net(&rng, 64, 64, 8, 0);
    check_net(&rng, 64, 64, 3, 1);
    /* rational patches of low degree: orders up to (5,4), far past the degree, where the 1.0
     * bound (falling factorials) vanished below half an ulp */
    for (int k = 0; k < 200; k++)
        check_net(&rng, 1 + (size_t)(k % 3), 1 + (size_t)(k / 3 % 3), 3, 1);
    printf("accuracy: worst polynomial error %.3g of the bound, rational %.3g of the bound, "
           "worst normal error %.3g (contract 1e-9); %d point(s) met only the 4-ulp floor\n",
           worst_poly, worst_rat, worst_normal, floors_used);
    return bs_test_exit("test_accuracy");
}
