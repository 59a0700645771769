/* Constructions from curves: a ruled patch contains its two curves and is straight across (the
 * exact ruled formula, rational too); a Coons patch interpolates its four boundary curves and
 * equals the bilinearly blended Coons formula everywhere. */
#include "ops_check.h"

static double worst_ruled, worst_coons;

typedef struct tcurve {
    bs_curve c;
    double ctrl[(BS_MAX_DEGREE + 1) * BS_MAX_DIM];
    double w[BS_MAX_DEGREE + 1];
} tcurve;

static void random_curve(tcurve *t, unsigned long long *rng, size_t deg, size_t dim, int rational)
{
    for (size_t k = 0; k < (deg + 1) * dim; k++)
        t->ctrl[k] = bs_test_rand(rng, -1, 1) + 0.3 * (double)(k % dim);
    for (size_t k = 0; k <= deg; k++)
        t->w[k] = bs_test_rand(rng, 0.25, 4.0);
    t->c.degree = deg;
    t->c.dim = dim;
    t->c.ctrl = t->ctrl;
    t->c.weights = rational ? t->w : NULL;
}

/* The curve's homogeneous point (w C, w) at s, in long double. */
static void curve_hom(const bs_curve *c, long double s, long double *h)
{
    ref_net r = {c->degree, 0, c->dim, c->ctrl, c->weights};
    for (size_t i = 0; i <= c->dim; i++)
        h[i] = ref_hom_deriv(&r, i, 0, 0, s, 0.0L);
}

static void test_ruled(void)
{
    unsigned long long rng = 71;
    static const size_t degs[][2] = {{0, 0}, {0, 4}, {3, 3}, {3, 7}, {12, 1}, {64, 20}};
    for (size_t d = 0; d < sizeof degs / sizeof degs[0]; d++)
        for (int rat = 0; rat < 4; rat++) { /* neither, c0, c1, both rational */
            size_t dim = 1 + (d + (size_t)rat) % 8;
            tcurve a, b;
            random_curve(&a, &rng, degs[d][0], dim, rat & 1);
            random_curve(&b, &rng, degs[d][1], dim, (rat >> 1) & 1);
            bs_patch *p = NULL;
            CHECK_STATUS(bs_patch_ruled(&a.c, &b.c, &p), BS_OK);
            if (p == NULL)
                continue;
            tnet net = tnet_of(p);
            size_t deg = degs[d][0] > degs[d][1] ? degs[d][0] : degs[d][1];
            CHECK(net.m == deg && net.n == 1 && (net.w != NULL) == (rat != 0));
            double maxabs = 0.0, wf = 1.0, wmin = 4.0, wmax = 0.25;
            for (size_t k = 0; k < (degs[d][0] + 1) * dim; k++)
                maxabs = fmax(maxabs, fabs(a.ctrl[k]));
            for (size_t k = 0; k < (degs[d][1] + 1) * dim; k++)
                maxabs = fmax(maxabs, fabs(b.ctrl[k]));
            if (rat) {
                for (size_t k = 0; k <= degs[d][0]; k++) {
                    wmin = fmin(wmin, a.c.weights ? a.w[k] : 1.0);
                    wmax = fmax(wmax, a.c.weights ? a.w[k] : 1.0);
                }
                for (size_t k = 0; k <= degs[d][1]; k++) {
                    wmin = fmin(wmin, b.c.weights ? b.w[k] : 1.0);
                    wmax = fmax(wmax, b.c.weights ? b.w[k] : 1.0);
                }
                wf = (wmax / wmin) * (wmax / wmin);
            }
            double bound = 4.0 * (double)(deg + 2) * OPS_EPS * maxabs * wf;
            ref_net r = tnet_ref(&net);
            long double h0[BS_MAX_DIM + 1], h1[BS_MAX_DIM + 1], x[BS_MAX_DIM];
            for (int k = 0; k < 8; k++) {
                long double u = (long double)bs_test_rand(&rng, 0, 1), v = k < 2 ? (long double)k : (long double)bs_test_rand(&rng, 0, 1);
                curve_hom(&a.c, u, h0);
                curve_hom(&b.c, u, h1);
                ref_eval(&r, u, v, x);
                /* homogeneous linear interpolation: S = (1-l) c0(u) + l c1(u), l = v w1 / ((1-v) w0 + v w1) */
                long double lam = v * h1[dim] / ((1 - v) * h0[dim] + v * h1[dim]);
                for (size_t c = 0; c < dim; c++) {
                    long double want = (1 - lam) * h0[c] / h0[dim] + lam * h1[c] / h1[dim];
                    double e = (double)fabsl(x[c] - want) / bound;
                    CHECKF(e <= 1.0, "ruled error %g of bound, degrees (%zu,%zu) rational %d", e, degs[d][0], degs[d][1], rat);
                    worst_ruled = e > worst_ruled ? e : worst_ruled;
                }
            }
            tnet_free(&net);
            bs_patch_destroy(p);
        }
}

/* Four random curves whose corners meet exactly. */
static void coons_curves(tcurve *cv, unsigned long long *rng, const size_t *deg, size_t dim)
{
    for (int k = 0; k < 4; k++)
        random_curve(&cv[k], rng, deg[k], dim, 0);
    /* v0(0) = u0(0), v0(1) = u1(0), v1(0) = u0(1), v1(1) = u1(1); a degree-0 side is one point */
    if (deg[2] == 0)
        memcpy(cv[1].ctrl, cv[0].ctrl, dim * sizeof(double));
    if (deg[3] == 0)
        memcpy(cv[1].ctrl + deg[1] * dim, cv[0].ctrl + deg[0] * dim, dim * sizeof(double));
    memcpy(cv[2].ctrl, cv[0].ctrl, dim * sizeof(double));
    memcpy(cv[3].ctrl, cv[0].ctrl + deg[0] * dim, dim * sizeof(double));
    memcpy(cv[2].ctrl + deg[2] * dim, cv[1].ctrl, dim * sizeof(double));
    memcpy(cv[3].ctrl + deg[3] * dim, cv[1].ctrl + deg[1] * dim, dim * sizeof(double));
}

static void curve_point(const bs_curve *c, long double s, long double *x)
{
    long double h[BS_MAX_DIM + 1];
    curve_hom(c, s, h);
    for (size_t i = 0; i < c->dim; i++)
        x[i] = h[i];
}

static void test_coons(void)
{
    unsigned long long rng = 72;
    static const size_t degs[][4] = {{1, 1, 1, 1}, {3, 3, 3, 3}, {2, 5, 0, 0}, {3, 1, 4, 2}, {0, 2, 3, 1}, {20, 7, 13, 64}};
    for (size_t d = 0; d < sizeof degs / sizeof degs[0]; d++) {
        size_t dim = 1 + (3 * d) % 8;
        tcurve cv[4];
        coons_curves(cv, &rng, degs[d], dim);
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_OK);
        if (p == NULL)
            continue;
        tnet net = tnet_of(p);
        size_t m = degs[d][0] > degs[d][1] ? degs[d][0] : degs[d][1], n = degs[d][2] > degs[d][3] ? degs[d][2] : degs[d][3];
        m = m ? m : 1;
        n = n ? n : 1;
        CHECK(net.m == m && net.n == n && net.w == NULL);
        double maxabs = 0.0;
        for (int k = 0; k < 4; k++)
            for (size_t i = 0; i < (degs[d][k] + 1) * dim; i++)
                maxabs = fmax(maxabs, fabs(cv[k].ctrl[i]));
        double bound = 3 * 4.0 * (double)(m + n + 1) * OPS_EPS * maxabs; /* three terms of size max|P| */
        ref_net r = tnet_ref(&net);
        long double x[BS_MAX_DIM], a[BS_MAX_DIM], b[BS_MAX_DIM], c0[BS_MAX_DIM], c1[BS_MAX_DIM];
        long double p00[BS_MAX_DIM], p10[BS_MAX_DIM], p01[BS_MAX_DIM], p11[BS_MAX_DIM];
        curve_point(&cv[0].c, 0, p00);
        curve_point(&cv[0].c, 1, p10);
        curve_point(&cv[1].c, 0, p01);
        curve_point(&cv[1].c, 1, p11);
        for (int k = 0; k < 12; k++) {
            long double u = (long double)bs_test_rand(&rng, 0, 1), v = (long double)bs_test_rand(&rng, 0, 1);
            if (k < 2) /* on the four boundaries */
                v = (long double)k;
            else if (k < 4)
                u = (long double)(k - 2);
            ref_eval(&r, u, v, x);
            curve_point(&cv[0].c, u, a);
            curve_point(&cv[1].c, u, b);
            curve_point(&cv[2].c, v, c0);
            curve_point(&cv[3].c, v, c1);
            for (size_t c = 0; c < dim; c++) {
                long double want = (1 - v) * a[c] + v * b[c] + (1 - u) * c0[c] + u * c1[c] -
                                   ((1 - u) * (1 - v) * p00[c] + u * (1 - v) * p10[c] + (1 - u) * v * p01[c] + u * v * p11[c]);
                double e = (double)fabsl(x[c] - want) / bound;
                CHECKF(e <= 1.0, "Coons error %g of bound, case %zu", e, d);
                worst_coons = e > worst_coons ? e : worst_coons;
            }
        }
        /* boundary rows and columns are the elevated curves: their end points are the curves' exactly */
        CHECK(memcmp(net.ctrl, cv[0].ctrl, dim * sizeof(double)) == 0);
        CHECK(memcmp(net.ctrl + ((m + 1) * (n + 1) - 1) * dim, cv[1].ctrl + degs[d][1] * dim, dim * sizeof(double)) == 0);
        tnet_free(&net);
        bs_patch_destroy(p);
    }
}

static void test_coons_corners_and_rational(void)
{
    unsigned long long rng = 73;
    const size_t deg[4] = {3, 2, 2, 4};
    tcurve cv[4];
    coons_curves(cv, &rng, deg, 3);
    bs_patch *sentinel = (bs_patch *)&sentinel, *p = sentinel;
    /* a corner off by far more than the tolerance */
    cv[3].ctrl[deg[3] * 3 + 1] += 1e-6;
    CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_ERR_INCOMPATIBLE);
    CHECK(p == NULL);
    /* within the tolerance 1e-12 * max(1, max|P|) */
    cv[3].ctrl[deg[3] * 3 + 1] = cv[1].ctrl[deg[1] * 3 + 1] + 1e-14;
    CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_OK);
    bs_patch_destroy(p);
    /* the tolerance pinned from both sides, on curves scaled up so that max|P| sets it */
    double big = 0.0;
    for (int k = 0; k < 4; k++)
        for (size_t i = 0; i < (deg[k] + 1) * 3; i++)
            big = fmax(big, fabs(cv[k].ctrl[i] *= 1e3));
    double corner = cv[1].ctrl[deg[1] * 3 + 1];
    cv[3].ctrl[deg[3] * 3 + 1] = corner + 0.4e-12 * big;
    CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_OK);
    bs_patch_destroy(p);
    cv[3].ctrl[deg[3] * 3 + 1] = corner + 3e-12 * big;
    CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_ERR_INCOMPATIBLE);
    cv[3].ctrl[deg[3] * 3 + 1] = corner;
    p = sentinel;
    cv[2].c.weights = cv[2].w;
    CHECK_STATUS(bs_patch_coons(&cv[0].c, &cv[1].c, &cv[2].c, &cv[3].c, &p), BS_ERR_UNSUPPORTED);
    CHECK(p == NULL);
}

int main(void)
{
    test_ruled();
    test_coons();
    test_coons_corners_and_rational();
    print_worst("ruled patch vs exact ruled formula", worst_ruled);
    print_worst("Coons patch vs exact Coons formula", worst_coons);
    return bs_test_exit("test_construct");
}
