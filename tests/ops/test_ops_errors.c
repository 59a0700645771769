/* Every error path of the exact operations: the documented status, new-handle outputs set to NULL,
 * caller buffers left untouched (filled with a sentinel beforehand). */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <string.h>

#define SENT -12345.0
static bs_patch *const SENTINEL = (bs_patch *)(void *)&bs_test_failures;

static const double net3[27] = {1, 0, 2, 1, 2, 4, 1, 3, 2, 2, 1, 0, 2, 2, 2, 2, 4, 0, 4, 1, 0, 3, 3, 2, 4, 4, 2};
static const double w9[9] = {1, 2, 1, 0.5, 1, 3, 1, 1, 2};

static void fill(double *x, size_t n) { for (size_t k = 0; k < n; k++) x[k] = SENT; }
static int untouched(const double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (x[k] != SENT)
            return 0;
    return 1;
}

static const double bad_t[] = {0.0, 1.0, -0.5, 1.5, NAN, INFINITY, -INFINITY, -0.0};

static void test_split_errors(bs_patch *p)
{
    bs_patch *lo = SENTINEL, *hi = SENTINEL;
    CHECK_STATUS(bs_patch_split(NULL, BS_DIR_U, 0.5, &lo, &hi), BS_ERR_INVALID_ARG);
    CHECK(lo == NULL && hi == NULL);
    hi = SENTINEL;
    CHECK_STATUS(bs_patch_split(p, BS_DIR_U, 0.5, NULL, &hi), BS_ERR_INVALID_ARG);
    CHECK(hi == NULL);
    lo = SENTINEL;
    CHECK_STATUS(bs_patch_split(p, BS_DIR_U, 0.5, &lo, NULL), BS_ERR_INVALID_ARG);
    CHECK(lo == NULL);
    lo = SENTINEL;
    CHECK_STATUS(bs_patch_split(p, BS_DIR_U, 0.5, &lo, &lo), BS_ERR_INVALID_ARG);
    CHECK(lo == NULL);
    const int bad_dir[] = {-1, 2, 100};
    for (int k = 0; k < 3; k++) {
        lo = hi = SENTINEL;
        CHECK_STATUS(bs_patch_split(p, bad_dir[k], 0.5, &lo, &hi), BS_ERR_INVALID_ARG);
        CHECK(lo == NULL && hi == NULL);
    }
    for (size_t k = 0; k < sizeof bad_t / sizeof bad_t[0]; k++)
        for (int dir = BS_DIR_U; dir <= BS_DIR_V; dir++) {
            lo = hi = SENTINEL;
            CHECK_STATUS(bs_patch_split(p, dir, bad_t[k], &lo, &hi), BS_ERR_DOMAIN);
            CHECK(lo == NULL && hi == NULL);
        }
}

static void test_split4_errors(bs_patch *p)
{
    bs_patch *q[4] = {SENTINEL, SENTINEL, SENTINEL, SENTINEL};
    CHECK_STATUS(bs_patch_split4(NULL, 0.5, 0.5, q), BS_ERR_INVALID_ARG);
    CHECK(q[0] == NULL && q[1] == NULL && q[2] == NULL && q[3] == NULL);
    CHECK_STATUS(bs_patch_split4(p, 0.5, 0.5, NULL), BS_ERR_INVALID_ARG);
    for (size_t k = 0; k < sizeof bad_t / sizeof bad_t[0]; k++) {
        for (int j = 0; j < 4; j++)
            q[j] = SENTINEL;
        CHECK_STATUS(bs_patch_split4(p, bad_t[k], 0.5, q), BS_ERR_DOMAIN);
        CHECK(q[0] == NULL && q[1] == NULL && q[2] == NULL && q[3] == NULL);
        for (int j = 0; j < 4; j++)
            q[j] = SENTINEL;
        CHECK_STATUS(bs_patch_split4(p, 0.5, bad_t[k], q), BS_ERR_DOMAIN);
        CHECK(q[0] == NULL && q[1] == NULL && q[2] == NULL && q[3] == NULL);
    }
}

static void test_subpatch_errors(bs_patch *p, bs_patch *r)
{
    bs_patch *q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(NULL, 0, 1, 0, 1, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_subpatch(p, 0, 1, 0, 1, NULL), BS_ERR_INVALID_ARG);
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 3; k++)
        for (int which = 0; which < 4; which++) {
            double a[4] = {0.1, 0.7, 0.2, 0.9};
            a[which] = bad[k];
            q = SENTINEL;
            CHECK_STATUS(bs_patch_subpatch(p, a[0], a[1], a[2], a[3], &q), BS_ERR_DOMAIN);
            CHECK(q == NULL);
        }
    q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(p, 0.3, 0.3, 0, 1, &q), BS_ERR_DOMAIN);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(p, 0, 1, 0.0, -0.0, &q), BS_ERR_DOMAIN);
    CHECK(q == NULL);
    /* extrapolation far away overflows */
    q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(p, 0, 1e200, 0, 1, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);
    /* a rational patch extrapolated to where its weights are negative: along u the weights are
     * (1, 0.01, 1), whose blossom at (-3, 4) is -12 + 0.25 - 12 < 0 */
    double wneg[9] = {1, 1, 1, 0.01, 0.01, 0.01, 1, 1, 1};
    bs_patch *rn = NULL;
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, wneg, &rn), BS_OK);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(rn, 0.4, 0.6, 0, 1, &q), BS_OK); /* inside: fine */
    bs_patch_destroy(q);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_subpatch(rn, -3, 4, 0, 1, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);
    bs_patch_destroy(rn);
    (void)r;
}

static void test_elevate_derivative_errors(bs_patch *p, bs_patch *r)
{
    bs_patch *q = SENTINEL;
    CHECK_STATUS(bs_patch_elevate(NULL, 1, 1, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_elevate(p, 1, 1, NULL), BS_ERR_INVALID_ARG);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_elevate(p, BS_MAX_DEGREE - 1, 0, &q), BS_ERR_DEGREE);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_elevate(p, 0, (size_t)-1, &q), BS_ERR_DEGREE);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_elevate(p, BS_MAX_DEGREE - 2, BS_MAX_DEGREE - 2, &q), BS_OK); /* the limit itself */
    CHECK(bs_patch_degree_u(q) == BS_MAX_DEGREE && bs_patch_degree_v(q) == BS_MAX_DEGREE);
    bs_patch_destroy(q);

    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(NULL, 1, 0, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_derivative(p, 1, 0, NULL), BS_ERR_INVALID_ARG);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(p, BS_MAX_DEGREE + 1, 0, &q), BS_ERR_DEGREE);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(p, 0, 4000000000u, &q), BS_ERR_DEGREE);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(r, 1, 0, &q), BS_ERR_UNSUPPORTED);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(r, 0, 0, &q), BS_ERR_UNSUPPORTED);
    CHECK(q == NULL);
    /* the scaled differences overflow: 64!/0! * 2^64 * 1e300 */
    static double big[(BS_MAX_DEGREE + 1) * 1];
    for (int k = 0; k <= BS_MAX_DEGREE; k++)
        big[k] = k % 2 ? 1e300 : -1e300;
    bs_patch *b = NULL;
    CHECK_STATUS(bs_patch_create(BS_MAX_DEGREE, 0, 1, big, NULL, &b), BS_OK);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_derivative(b, BS_MAX_DEGREE, 0, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);
    bs_patch_destroy(b);
}

static void test_isocurve_errors(bs_patch *p, bs_patch *r)
{
    double c[9], w[3];
    fill(c, 9);
    fill(w, 3);
    CHECK_STATUS(bs_patch_isocurve(NULL, BS_DIR_U, 0.5, c, 9, w, 3), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_U, 0.5, NULL, 9, w, 3), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_isocurve(p, 2, 0.5, c, 9, w, 3), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_isocurve(p, -1, 0.5, c, 9, w, 3), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_V, NAN, c, 9, w, 3), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_V, INFINITY, c, 9, w, 3), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_V, -INFINITY, c, 9, w, 3), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_U, 0.5, c, 8, w, 3), BS_ERR_SIZE);
    CHECK_STATUS(bs_patch_isocurve(r, BS_DIR_U, 0.5, c, 9, w, 2), BS_ERR_SIZE);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_U, 0.0, c, 0, NULL, 0), BS_ERR_SIZE);
    CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_U, 1e300, c, 9, w, 3), BS_ERR_NONFINITE); /* t^2 overflows */
    /* weights (1, 10, 1) along u: w(u) = 1 + 18u - 18u^2 < 0 at u = -3 */
    double wneg[9] = {1, 1, 1, 10, 10, 10, 1, 1, 1};
    bs_patch *rn = NULL;
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, wneg, &rn), BS_OK);
    CHECK_STATUS(bs_patch_isocurve(rn, BS_DIR_U, -3.0, c, 9, w, 3), BS_ERR_NONFINITE);
    bs_patch_destroy(rn);
    CHECK(untouched(c, 9) && untouched(w, 3));
}

static void test_bounds_transform_orientation_errors(bs_patch *p)
{
    double lo[3], hi[3];
    fill(lo, 3);
    fill(hi, 3);
    CHECK_STATUS(bs_patch_bounds(NULL, lo, hi), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_bounds(p, NULL, hi), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_bounds(p, lo, NULL), BS_ERR_INVALID_ARG);
    CHECK(untouched(lo, 3) && untouched(hi, 3));

    double a[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    bs_patch *q = SENTINEL;
    CHECK_STATUS(bs_patch_transform(NULL, a, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_transform(p, NULL, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_transform(p, a, NULL), BS_ERR_INVALID_ARG);
    const double bad[] = {NAN, INFINITY, 1e308};
    for (int k = 0; k < 3; k++) {
        double b[12];
        memcpy(b, a, sizeof b);
        b[k == 2 ? 5 : 3] = bad[k]; /* b_0 non-finite, or A[1][1] so large that 4e308 overflows */
        q = SENTINEL;
        CHECK_STATUS(bs_patch_transform(p, b, &q), BS_ERR_NONFINITE);
        CHECK(q == NULL);
    }

    q = SENTINEL;
    CHECK_STATUS(bs_patch_swap_uv(NULL, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_swap_uv(p, NULL), BS_ERR_INVALID_ARG);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_reverse(NULL, BS_DIR_U, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_reverse(p, 2, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_reverse(p, BS_DIR_V, NULL), BS_ERR_INVALID_ARG);
}

static void test_curve_errors(void)
{
    double c0[12] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, c1[9] = {0, 1, 0, 1, 1, 0, 3, 1, 0};
    double cw[4] = {1, 2, 2, 1};
    bs_curve a = {3, 3, c0, NULL}, b = {2, 3, c1, NULL};
    bs_patch *q = SENTINEL;
    /* the valid pair works */
    CHECK_STATUS(bs_patch_ruled(&a, &b, &q), BS_OK);
    bs_patch_destroy(q);

    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(NULL, &b, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&a, NULL, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_ruled(&a, &b, NULL), BS_ERR_INVALID_ARG);
    bs_curve t = a;
    t.ctrl = NULL;
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&t, &b, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    t = a;
    t.degree = BS_MAX_DEGREE + 1;
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&t, &b, &q), BS_ERR_DEGREE);
    CHECK(q == NULL);
    t = a;
    t.dim = 0;
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&b, &t, &q), BS_ERR_DIMENSION);
    CHECK(q == NULL);
    t.dim = BS_MAX_DIM + 1;
    CHECK_STATUS(bs_patch_ruled(&b, &t, &q), BS_ERR_DIMENSION);
    t = a;
    t.dim = 2; /* 3 points of 2-D from c0's first 6... still readable: 4 points x 2 = 8 doubles */
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&t, &b, &q), BS_ERR_INCOMPATIBLE);
    CHECK(q == NULL);
    double cn[12];
    memcpy(cn, c0, sizeof cn);
    cn[7] = NAN;
    t = a;
    t.ctrl = cn;
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&t, &b, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);
    const double bad_w[] = {0.0, -1.0, NAN, INFINITY};
    for (int k = 0; k < 4; k++) {
        double w[4] = {1, 2, 2, 1};
        w[2] = bad_w[k];
        t = a;
        t.weights = w;
        q = SENTINEL;
        CHECK_STATUS(bs_patch_ruled(&b, &t, &q), BS_ERR_NONFINITE);
        CHECK(q == NULL);
    }
    double huge[12];
    memcpy(huge, c0, sizeof huge);
    huge[3] = 1e308;
    t = a;
    t.ctrl = huge;
    t.weights = cw; /* 2 * 1e308 overflows in homogeneous form */
    q = SENTINEL;
    CHECK_STATUS(bs_patch_ruled(&t, &b, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);

    /* Coons: v0 = a (y = 0), v1 = (0,1,0)..(3,1,0), u0 from (0,0,0) to (0,1,0), u1 from (3,0,0) to (3,1,0) */
    double v1c[6] = {0, 1, 0, 3, 1, 0}, u0c[6] = {0, 0, 0, 0, 1, 0}, u1c[9] = {3, 0, 0, 4, 0.5, 1, 3, 1, 0};
    bs_curve v1 = {1, 3, v1c, NULL}, u0 = {1, 3, u0c, NULL}, u1 = {2, 3, u1c, NULL};
    q = SENTINEL;
    CHECK_STATUS(bs_patch_coons(&a, &v1, &u0, &u1, &q), BS_OK);
    bs_patch_destroy(q);
    const bs_curve *set[4] = {&a, &v1, &u0, &u1};
    for (int k = 0; k < 4; k++) {
        const bs_curve *s[4] = {set[0], set[1], set[2], set[3]};
        s[k] = NULL;
        q = SENTINEL;
        CHECK_STATUS(bs_patch_coons(s[0], s[1], s[2], s[3], &q), BS_ERR_INVALID_ARG);
        CHECK(q == NULL);
        bs_curve tw = *set[k];
        tw.weights = cw;
        s[k] = &tw;
        q = SENTINEL;
        CHECK_STATUS(bs_patch_coons(s[0], s[1], s[2], s[3], &q), BS_ERR_UNSUPPORTED);
        CHECK(q == NULL);
        bs_curve td = *set[k];
        td.degree = 100;
        s[k] = &td;
        q = SENTINEL;
        CHECK_STATUS(bs_patch_coons(s[0], s[1], s[2], s[3], &q), BS_ERR_DEGREE);
        CHECK(q == NULL);
        bs_curve tn = *set[k];
        tn.dim = 9;
        s[k] = &tn;
        CHECK_STATUS(bs_patch_coons(s[0], s[1], s[2], s[3], &q), BS_ERR_DIMENSION);
        tn.dim = 1;
        CHECK_STATUS(bs_patch_coons(s[0], s[1], s[2], s[3], &q), BS_ERR_INCOMPATIBLE);
    }
    CHECK_STATUS(bs_patch_coons(&a, &v1, &u0, &u1, NULL), BS_ERR_INVALID_ARG);
    double u1bad[9] = {3, 0, 0, 4, 0.5, 1, 3, 1, 1e-9}; /* corner v1(1) = u1(1) misses by 1e-9 */
    bs_curve u1b = {2, 3, u1bad, NULL};
    q = SENTINEL;
    CHECK_STATUS(bs_patch_coons(&a, &v1, &u0, &u1b, &q), BS_ERR_INCOMPATIBLE);
    CHECK(q == NULL);
    double v1n[6] = {0, 1, 0, 3, INFINITY, 0};
    bs_curve v1nf = {1, 3, v1n, NULL};
    q = SENTINEL;
    CHECK_STATUS(bs_patch_coons(&a, &v1nf, &u0, &u1, &q), BS_ERR_NONFINITE);
    CHECK(q == NULL);
}

int main(void)
{
    bs_patch *p = NULL, *r = NULL;
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, w9, &r), BS_OK);
    test_split_errors(p);
    test_split_errors(r);
    test_split4_errors(p);
    test_subpatch_errors(p, r);
    test_elevate_derivative_errors(p, r);
    test_isocurve_errors(p, r);
    test_bounds_transform_orientation_errors(p);
    test_curve_errors();
    bs_patch_destroy(p);
    bs_patch_destroy(r);
    return bs_test_exit("test_ops_errors");
}
