/* The accuracy contract (docs/accuracy.md), measured against the long-double reference on random
 * nets of every degree up to 64: every coordinate of d^(k+l)S/du^k dv^l within
 * 2(m+n+1) eps max|P| 2^(k+l) m!/(m-k)! n!/(n-l)!, times (wmax/wmin)^(1+k+l) when rational;
 * unit normals within 1e-9. Prints the worst error as a fraction of the bound. */
#include "eval_util.h"

static double worst_poly, worst_rat, worst_normal;

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
    size_t nord = rational ? 5 : 10;
    for (size_t o = 0; o < nord; o++) {
        unsigned k = orders[o][0], l = orders[o][1];
        double res[BS_MAX_DIM * N];
        bs_view vo[BS_MAX_DIM];
        views_of(res, dim, N, vo);
        CHECK_STATUS(bs_patch_eval_deriv(p, k, l, N, &cu, &cv, vo), BS_OK);
        double bnd = accuracy_bound(&t, k, l);
        for (int q = 0; q < N; q++) {
            long double e[BS_MAX_DIM];
            ref_deriv(&r, k, l, u[q], v[q], e);
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
    /* every degree 0..64 in u, paired with a random one in v, both ways round */
    for (size_t m = 0; m <= BS_MAX_DEGREE; m++) {
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
    printf("accuracy: worst polynomial error %.3g of the bound, rational %.3g of the bound, "
           "worst normal error %.3g (contract 1e-9)\n",
           worst_poly, worst_rat, worst_normal);
    return bs_test_exit("test_accuracy");
}
