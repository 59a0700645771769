/*
 * Helpers for the tests of the exact operations: random nets, and exact results computed in long
 * double (nets of sub-patches by blossoming, elevation and difference formulas) to compare the
 * library's results with. Nothing here calls the operations under test.
 */
#ifndef BS_TEST_OPS_CHECK_H
#define BS_TEST_OPS_CHECK_H

#include "harness.h"
#include "reference.h"

#include <bezsurf.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define OPS_EPS 0x1.0p-52

/* An owned copy of a net. */
typedef struct tnet {
    size_t m, n, dim;
    double *ctrl; /* (m+1)(n+1)dim, packed as in the API */
    double *w;    /* NULL or (m+1)(n+1) weights */
} tnet;

static inline size_t tnet_count(const tnet *t) { return (t->m + 1) * (t->n + 1); }

static inline tnet tnet_alloc(size_t m, size_t n, size_t dim, int rational)
{
    tnet t = {m, n, dim, NULL, NULL};
    t.ctrl = malloc((m + 1) * (n + 1) * dim * sizeof(double));
    if (rational)
        t.w = malloc((m + 1) * (n + 1) * sizeof(double));
    return t;
}

static inline void tnet_free(tnet *t)
{
    free(t->ctrl);
    free(t->w);
    t->ctrl = t->w = NULL;
}

/* Random coordinates in [-1,1) scaled by coordinate-dependent offsets (so no symmetry), weights
 * in [wlo, whi) when rational. */
static inline tnet tnet_random(unsigned long long *rng, size_t m, size_t n, size_t dim, int rational,
                               double wlo, double whi)
{
    tnet t = tnet_alloc(m, n, dim, rational);
    for (size_t k = 0; k < tnet_count(&t) * dim; k++)
        t.ctrl[k] = bs_test_rand(rng, -1.0, 1.0) * (1.0 + 0.25 * (double)(k % dim)) + 0.1 * (double)(k % 7);
    if (rational)
        for (size_t k = 0; k < tnet_count(&t); k++)
            t.w[k] = bs_test_rand(rng, wlo, whi);
    return t;
}

static inline bs_patch *tnet_patch(const tnet *t)
{
    bs_patch *p = NULL;
    if (bs_patch_create(t->m, t->n, t->dim, t->ctrl, t->w, &p) != BS_OK)
        return NULL;
    return p;
}

/* The net of a patch, read back through the accessors. */
static inline tnet tnet_of(const bs_patch *p)
{
    tnet t = tnet_alloc(bs_patch_degree_u(p), bs_patch_degree_v(p), bs_patch_dim(p), bs_patch_is_rational(p));
    (void)bs_patch_get_ctrl(p, t.ctrl, tnet_count(&t) * t.dim, t.w, t.w ? tnet_count(&t) : 0);
    return t;
}

static inline ref_net tnet_ref(const tnet *t)
{
    ref_net r = {t->m, t->n, t->dim, t->ctrl, t->w};
    return r;
}

static inline double tnet_maxabs(const tnet *t)
{
    double s = 0.0;
    for (size_t k = 0; k < tnet_count(t) * t->dim; k++)
        s = fabs(t->ctrl[k]) > s ? fabs(t->ctrl[k]) : s;
    return s;
}

/* (wmax/wmin)^2, 1 for a polynomial net. */
static inline double tnet_wfactor(const tnet *t)
{
    if (t->w == NULL)
        return 1.0;
    double lo = t->w[0], hi = t->w[0];
    for (size_t k = 1; k < tnet_count(t); k++) {
        lo = t->w[k] < lo ? t->w[k] : lo;
        hi = t->w[k] > hi ? t->w[k] : hi;
    }
    return (hi / lo) * (hi / lo);
}

static inline double tnet_wmax(const tnet *t)
{
    double hi = 1.0;
    if (t->w)
        for (size_t k = 0; k < tnet_count(t); k++)
            hi = t->w[k] > hi ? t->w[k] : hi;
    return hi;
}

/* The accuracy bound of the operations: 4 (m+n+1) eps max|P| (wmax/wmin)^2. */
static inline double ops_bound(size_t m, size_t n, const tnet *parent)
{
    return 4.0 * (double)(m + n + 1) * OPS_EPS * tnet_maxabs(parent) * tnet_wfactor(parent);
}

/* ---- Exact homogeneous nets in long double: dim+1 planes (w*P_c, then w; w = 1 if polynomial),
 * coordinate-major, point (i,j) at plane*(m+1)(n+1) + i(n+1) + j. ---- */
typedef struct lnet {
    size_t m, n, dim;
    long double *h;
} lnet;

static inline lnet lnet_of(const tnet *t)
{
    lnet l = {t->m, t->n, t->dim, NULL};
    size_t cnt = tnet_count(t);
    l.h = malloc((t->dim + 1) * cnt * sizeof(long double));
    for (size_t k = 0; k < cnt; k++) {
        long double w = t->w ? (long double)t->w[k] : 1.0L;
        for (size_t c = 0; c < t->dim; c++)
            l.h[c * cnt + k] = w * (long double)t->ctrl[k * t->dim + c];
        l.h[t->dim * cnt + k] = w;
    }
    return l;
}

static inline long double *lnet_at(const lnet *l, size_t c, size_t i, size_t j)
{
    return &l->h[c * (l->m + 1) * (l->n + 1) + i * (l->n + 1) + j];
}

/* Blossom of a curve b[0..deg] at the multiset (t0 repeated deg-k times, t1 k times). */
static inline long double ld_blossom(const long double *b, size_t deg, size_t k, long double t0, long double t1)
{
    long double tmp[BS_MAX_DEGREE + 1];
    memcpy(tmp, b, (deg + 1) * sizeof(long double));
    for (size_t r = 1; r <= deg; r++) {
        long double t = r <= k ? t1 : t0;
        for (size_t i = 0; i + r <= deg; i++)
            tmp[i] = (1.0L - t) * tmp[i] + t * tmp[i + 1];
    }
    return tmp[0];
}

/* The net over [t0,t1] along dir (exact sub-curve of every fibre), in place. */
static inline void lnet_sub(lnet *l, int dir, long double t0, long double t1)
{
    size_t deg = dir == BS_DIR_U ? l->m : l->n, nfib = (dir == BS_DIR_U ? l->n : l->m) + 1;
    long double b[BS_MAX_DEGREE + 1], q[BS_MAX_DEGREE + 1];
    for (size_t c = 0; c <= l->dim; c++)
        for (size_t f = 0; f < nfib; f++) {
            for (size_t k = 0; k <= deg; k++)
                b[k] = dir == BS_DIR_U ? *lnet_at(l, c, k, f) : *lnet_at(l, c, f, k);
            for (size_t k = 0; k <= deg; k++)
                q[k] = ld_blossom(b, deg, k, t0, t1);
            for (size_t k = 0; k <= deg; k++)
                *(dir == BS_DIR_U ? lnet_at(l, c, k, f) : lnet_at(l, c, f, k)) = q[k];
        }
}

/* Compare a result net with an exact homogeneous one: Cartesian coordinates within bound, weights
 * within wbound. Returns the worst error as a fraction of its bound (CHECKed <= 1 by callers). */
static inline double compare_net(const tnet *got, const lnet *exact, double bound, double wbound)
{
    double worst = 0.0;
    if (got->m != exact->m || got->n != exact->n || got->dim != exact->dim)
        return INFINITY;
    size_t cnt = tnet_count(got);
    for (size_t k = 0; k < cnt; k++) {
        long double w = exact->h[got->dim * cnt + k];
        if (got->w) {
            double e = (double)fabsl((long double)got->w[k] - w) / wbound;
            worst = e > worst ? e : worst;
        } else if (fabsl(w - 1.0L) > 1e-15L) { /* exactly 1 up to long-double rounding */
            return INFINITY;
        }
        for (size_t c = 0; c < got->dim; c++) {
            long double x = exact->h[c * cnt + k] / w;
            double e = (double)fabsl((long double)got->ctrl[k * got->dim + c] - x) / bound;
            if (!(e <= worst))
                worst = e; /* also catches NaN */
        }
    }
    return worst;
}

/* Worst |S_got(s,r) - S_parent(u,v)| / bound over random (s,r), with (u,v) = map(s,r). */
static inline double compare_eval(const tnet *got, const tnet *parent, unsigned long long *rng, int npts,
                                  long double u0, long double u1, long double v0, long double v1,
                                  double bound)
{
    ref_net a = tnet_ref(got), b = tnet_ref(parent);
    long double x[BS_MAX_DIM], y[BS_MAX_DIM];
    double worst = 0.0;
    for (int k = 0; k < npts; k++) {
        long double s = (long double)bs_test_rand(rng, 0.0, 1.0), r = (long double)bs_test_rand(rng, 0.0, 1.0);
        if (k == 0)
            s = r = 0.0L;
        if (k == 1)
            s = r = 1.0L;
        ref_eval(&a, s, r, x);
        ref_eval(&b, u0 + s * (u1 - u0), v0 + r * (v1 - v0), y);
        for (size_t c = 0; c < got->dim; c++) {
            double e = (double)fabsl(x[c] - y[c]) / bound;
            if (!(e <= worst))
                worst = e;
        }
    }
    return worst;
}

/* Mixed degree pairs the tests run through: degree 0, non-square, high degrees. */
static const size_t ops_degrees[][2] = {{0, 0}, {0, 3}, {1, 0}, {1, 1}, {2, 5}, {3, 3}, {7, 2},
                                        {4, 9}, {20, 11}, {13, 20}, {64, 3}, {2, 64}, {64, 64}};
#define OPS_NDEGREES (sizeof ops_degrees / sizeof ops_degrees[0])

/* The quick sample (BS_TEST_QUICK: memcheck, sanitizers) leaves out the (64, 64) pair, most of the
 * cost of a sweep of splits or sub-patches; (64, 3) and (2, 64) keep degree 64 in it. It is the
 * last pair, so the random nets of the others are the same. */
static inline int ops_degree_skipped(size_t d)
{
    return bs_test_quick() && ops_degrees[d][0] == 64 && ops_degrees[d][1] == 64;
}

static inline void print_worst(const char *what, double worst)
{
    printf("  %-40s worst error = %.4f of the bound\n", what, worst);
}

#endif
