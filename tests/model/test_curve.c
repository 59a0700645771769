/* Trim and edge curves (lib/model/curve.c) against closed forms in long double: lines, circles
 * and ellipses at many parameters over several ranges (native radians and degrees), B-splines
 * (rational or not, clamped or not, repeated interior knots, ranges cut inside spans) against a
 * de Boor evaluation written here; copies, transforms, bounds, and every refusal. */
#include "harness.h"

#include "model/internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PI_L 3.141592653589793238462643383279502884L

/* Allocation failures on demand: the n-th allocation from now fails (0: none). */
#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
static size_t fail_in;
void *__wrap_malloc(size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_malloc(n);
}
#endif

static double worst; /* the largest error seen, relative to the curve's size */

static void near(const double *p, const long double *q, size_t dim, long double scale,
                 const char *what, double t)
{
    long double e = 0.0L;
    for (size_t j = 0; j < dim; j++) {
        long double d = fabsl((long double)p[j] - q[j]);
        e = d > e ? d : e;
    }
    e /= scale;
    if ((double)e > worst)
        worst = (double)e;
    CHECKF(e < 1e-14L, "%s at t = %.17g: relative error %.3Lg", what, t, e);
}

static int empty(const bsi_curve *c)
{
    return c->hom == NULL && c->axis.n == 0 && c->axis.breaks == NULL;
}

/* ---- conics ---- */
static void conic_case(size_t dim, double radians, double t0, double t1, double rx, double ry)
{
    double c2[2] = {0.25, -1.5}, x2[2] = {0.6, 0.8}, y2[2] = {-0.8, 0.6};
    double c3[3] = {1.0, 2.0, -3.0}, x3[3] = {2.0 / 3, 2.0 / 3, 1.0 / 3},
           y3[3] = {-2.0 / 3, 1.0 / 3, 2.0 / 3};
    const double *c = dim == 2 ? c2 : c3, *x = dim == 2 ? x2 : x3, *y = dim == 2 ? y2 : y3;
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_conic(dim, c, x, y, rx, ry, radians, t0, t1, &cv), BS_OK);
    if (cv.hom == NULL)
        return;
    /* pieces of equal width, each at most a quarter turn, as few as that allows */
    long double turn = (long double)radians * ((long double)t1 - t0);
    size_t want = (size_t)ceill(turn / (PI_L / 2) - 1e-12L);
    CHECKF(cv.axis.n == (want ? want : 1), "pieces %zu, want %zu", cv.axis.n, want);
    CHECK(cv.degree == 2 && cv.dim == dim && cv.axis.kind == BSI_AXIS_ANGULAR);
    for (size_t k = 0; k < cv.axis.n; k++) {
        long double a = 0.5L * radians * ((long double)cv.axis.breaks[k + 1] - cv.axis.breaks[k]);
        const double *h = cv.hom + k * 3 * (dim + 1);
        CHECK(a <= PI_L / 4 * (1 + 1e-12L));
        CHECK(h[dim] == 1.0 && h[3 * (dim + 1) - 1] == 1.0);
        CHECK(fabsl(h[2 * (dim + 1) - 1] - cosl(a)) < 1e-15L);
    }
    long double scale = rx > ry ? rx : ry;
    scale += 4.0L;
    for (int i = 0; i <= 400; i++) {
        double t = i == 400 ? t1 : t0 + (t1 - t0) * i / 400.0;
        long double phi = (long double)radians * t, q[3];
        for (size_t j = 0; j < dim; j++)
            q[j] = c[j] + rx * cosl(phi) * x[j] + ry * sinl(phi) * y[j];
        double p[3];
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        near(p, q, dim, scale, "conic", t);
    }
    double p[3] = {7, 7, 7};
    CHECK(bsi_curve_eval(&cv, t0 - (t1 - t0) * 1e-3, p) == 0 && p[0] == 7.0);
    CHECK(bsi_curve_eval(&cv, t1 + (t1 - t0) * 1e-3, p) == 0 && p[0] == 7.0);
    CHECK(bsi_curve_eval(&cv, NAN, p) == 0 && p[0] == 7.0);
    /* the control points' box holds the curve */
    double lo[3], hi[3];
    bsi_curve_bounds(&cv, lo, hi);
    for (int i = 0; i <= 50; i++) {
        double t = t0 + (t1 - t0) * i / 50.0;
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        for (size_t j = 0; j < dim; j++)
            CHECK(p[j] >= lo[j] - 1e-12 && p[j] <= hi[j] + 1e-12);
    }
    bsi_curve_free(&cv);
    CHECK(empty(&cv));
}

static void test_conics(void)
{
    double deg = (double)(PI_L / 180);
    for (size_t dim = 2; dim <= 3; dim++) {
        conic_case(dim, deg, 0.0, 60.0, 2.0, 2.0);     /* under a quarter turn */
        conic_case(dim, deg, 10.0, 100.0, 2.0, 2.0);   /* exactly a quarter turn */
        conic_case(dim, deg, 30.0, 230.0, 3.0, 1.5);   /* over a quarter turn, an ellipse */
        conic_case(dim, deg, 0.0, 360.0, 1.0, 1.0);    /* a full turn */
        conic_case(dim, deg, -135.0, 45.0, 0.5, 2.0);  /* a negative start */
        conic_case(dim, deg, -720.0, -300.0, 1.0, 1.0);/* beyond a turn, all negative */
        conic_case(dim, 1.0, 0.0, 2 * (double)PI_L, 1.0, 1.0);
        conic_case(dim, 1.0, -1.0, 4.0, 5.0, 0.25);
        conic_case(dim, 1.0, 0.1, 0.2, 1e3, 1e3);      /* a short arc of a large circle */
    }
}

/* ---- lines ---- */
static void test_lines(void)
{
    double p[3] = {1.0, -2.0, 0.5}, d[3] = {0.3, 0.4, -1.2};
    for (size_t dim = 2; dim <= 3; dim++) {
        bsi_curve cv;
        CHECK_STATUS(bsi_curve_line(dim, p, d, -2.5, 7.0, &cv), BS_OK);
        CHECK(cv.axis.n == 1 && cv.degree == 1 && cv.axis.kind == BSI_AXIS_LINEAR);
        for (int i = 0; i <= 100; i++) {
            double t = -2.5 + 9.5 * i / 100.0, r[3];
            long double q[3];
            for (size_t j = 0; j < dim; j++)
                q[j] = (long double)p[j] + (long double)t * d[j];
            CHECK(bsi_curve_eval(&cv, t, r) == 1);
            near(r, q, dim, 10.0L, "line", t);
        }
        double lo[3], hi[3];
        bsi_curve_bounds(&cv, lo, hi);
        for (size_t j = 0; j < dim; j++) {
            double a = p[j] - 2.5 * d[j], b = p[j] + 7.0 * d[j];
            CHECK(lo[j] == (a < b ? a : b) && hi[j] == (a < b ? b : a));
        }
        bsi_curve_free(&cv);
    }
}

/* ---- B-splines against de Boor ---- */
typedef struct spline {
    size_t dim, deg, count;
    const double *knots, *ctrl, *w;
} spline;

static void de_boor(const spline *s, long double x, long double *q)
{
    size_t p = s->deg, i = p;
    while (i + 1 < s->count && !(x < s->knots[i + 1] && s->knots[i] < s->knots[i + 1]))
        i++;
    while (!(s->knots[i] < s->knots[i + 1])) /* x at the end of the domain: the last span */
        i--;
    long double d[BS_MAX_DEGREE + 1][4];
    for (size_t k = 0; k <= p; k++) {
        long double w = s->w ? s->w[i - p + k] : 1.0L;
        for (size_t c = 0; c < s->dim; c++)
            d[k][c] = w * s->ctrl[(i - p + k) * s->dim + c];
        d[k][s->dim] = w;
    }
    for (size_t r = 1; r <= p; r++)
        for (size_t k = p; k >= r; k--) {
            size_t j = i - p + k;
            long double a = (x - s->knots[j]) / ((long double)s->knots[j + p + 1 - r] - s->knots[j]);
            for (size_t c = 0; c <= s->dim; c++)
                d[k][c] = (1.0L - a) * d[k - 1][c] + a * d[k][c];
        }
    for (size_t c = 0; c < s->dim; c++)
        q[c] = d[p][c] / d[p][s->dim];
}

static void spline_case(const spline *s, double t0, double t1, const char *what)
{
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_bspline(s->dim, s->deg, s->count, s->knots, s->ctrl, s->w, t0, t1, &cv),
                 BS_OK);
    if (cv.hom == NULL)
        return;
    size_t inside = 0;
    for (size_t i = 0; i < s->count + s->deg + 1; i++)
        inside += s->knots[i] > t0 && s->knots[i] < t1 && (i == 0 || s->knots[i] > s->knots[i - 1]);
    CHECKF(cv.axis.n == inside + 1, "%s: %zu segments, want %zu", what, cv.axis.n, inside + 1);
    CHECK(cv.axis.breaks[0] == t0 && cv.axis.breaks[cv.axis.n] == t1 && cv.degree == s->deg);
    for (int i = 0; i <= 600; i++) {
        double t = i == 600 ? t1 : t0 + (t1 - t0) * i / 600.0, p[3];
        long double q[3];
        de_boor(s, t, q);
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        near(p, q, s->dim, 10.0L, what, t);
    }
    /* each segment's ends: the knots and the range's ends, from both sides where continuous */
    for (size_t k = 0; k < cv.axis.n; k++) {
        double p[3];
        long double q[3];
        bsi_curve_point(&cv, k, 0.0, p);
        de_boor(s, cv.axis.breaks[k], q);
        near(p, q, s->dim, 10.0L, what, cv.axis.breaks[k]);
    }
    bsi_curve copy;
    CHECK_STATUS(bsi_curve_copy(&cv, &copy), BS_OK);
    CHECK(copy.axis.n == cv.axis.n && copy.dim == cv.dim && copy.degree == cv.degree &&
          memcmp(copy.hom, cv.hom, cv.axis.n * (cv.degree + 1) * (cv.dim + 1) * sizeof(double)) == 0 &&
          memcmp(copy.axis.breaks, cv.axis.breaks, (cv.axis.n + 1) * sizeof(double)) == 0);
    bsi_curve_free(&copy);
    bsi_curve_free(&cv);
}

static const double ctrl2[] = {0, 0, 1, 2, 3, 2.5, 4, 0, 5, -1, 6.5, 1, 7, 3, 8, 2, 9, 0.5};
static const double ctrl3[] = {0, 0, 0, 1, 2, 1, 3, 2.5, -1, 4, 0, 2, 5, -1, 0.5,
                               6.5, 1, 1, 7, 3, -2, 8, 2, 0, 9, 0.5, 1};
static const double wts[] = {1, 0.5, 2, 1.5, 0.75, 1, 3, 0.25, 1};

static void test_bsplines(void)
{
    /* clamped cubic, 9 points: knots with a double interior knot */
    static const double k1[] = {0, 0, 0, 0, 1, 2, 2, 3.5, 4, 5, 5, 5, 5};
    /* unclamped (uniform) quadratic */
    static const double k2[] = {-1, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    /* degree 2 with a knot of multiplicity 3 inside: a break in the curve */
    static const double k3[] = {0, 0, 0, 1, 1, 1, 2, 3, 3.25, 4, 4, 4};
    /* degree 1, the polyline */
    static const double k4[] = {0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 8};
    /* degree 8, a single span */
    static const double k5[] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 2, 2, 2, 2, 2, 2, 2, 2};
    for (size_t dim = 2; dim <= 3; dim++) {
        const double *ctrl = dim == 2 ? ctrl2 : ctrl3;
        for (int rational = 0; rational < 2; rational++) {
            const double *w = rational ? wts : NULL;
            spline s1 = {dim, 3, 9, k1, ctrl, w}, s2 = {dim, 2, 9, k2, ctrl, w},
                   s3 = {dim, 2, 9, k3, ctrl, w}, s4 = {dim, 1, 9, k4, ctrl, w},
                   s5 = {dim, 8, 9, k5, ctrl, w};
            spline_case(&s1, 0.0, 5.0, "clamped cubic");
            spline_case(&s1, 0.3, 4.6, "clamped cubic cut");
            spline_case(&s1, 2.0, 3.5, "clamped cubic, one span at knots");
            spline_case(&s1, 2.2, 3.1, "clamped cubic, inside one span");
            spline_case(&s1, 0.5, 2.0, "clamped cubic, ending at a double knot");
            spline_case(&s2, 1.0, 7.0, "unclamped quadratic");
            spline_case(&s2, 1.5, 6.25, "unclamped quadratic cut");
            spline_case(&s3, 0.0, 4.0, "quadratic with a triple knot");
            spline_case(&s3, 0.5, 3.1, "quadratic with a triple knot, cut");
            spline_case(&s4, 0.0, 8.0, "polyline");
            spline_case(&s4, 0.5, 0.75, "polyline cut in one span");
            spline_case(&s5, 0.0, 2.0, "degree 8");
            spline_case(&s5, 0.4, 1.9, "degree 8 cut");
        }
    }
    /* the rational quadratic circle of 9 points (weights 1, sqrt(2)/2): every point at radius 2 */
    double r2 = sqrt(0.5);
    static const double kc[] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    double cc[18] = {2, 0, 2, 2, 0, 2, -2, 2, -2, 0, -2, -2, 0, -2, 2, -2, 2, 0};
    double wc[9] = {1, r2, 1, r2, 1, r2, 1, r2, 1};
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_bspline(2, 2, 9, kc, cc, wc, 0.3, 3.7, &cv), BS_OK);
    CHECK(cv.axis.n == 4);
    for (int i = 0; i <= 200; i++) {
        double t = 0.3 + 3.4 * i / 200.0, p[2];
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        long double r = sqrtl((long double)p[0] * p[0] + (long double)p[1] * p[1]);
        CHECKF(fabsl(r - 2.0L) < 1e-15L, "NURBS circle radius %.20Lg", r);
    }
    bsi_curve_free(&cv);
}

/* ---- transforms ---- */
static void test_transform(void)
{
    double c[3] = {1, 2, 3}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_conic(3, c, x, y, 2.0, 1.0, 1.0, 0.0, 5.0, &cv), BS_OK);
    /* a turn of 90 degrees about z and a shift */
    double A[12] = {0, -1, 0, 1, 0, 0, 0, 0, 1, 10, 20, 30};
    bsi_curve_transform(&cv, A);
    for (int i = 0; i <= 100; i++) {
        double t = 5.0 * i / 100.0, p[3];
        long double e0 = 1 + 2 * cosl(t), e1 = 2 + sinl(t), q[3] = {-e1 + 10, e0 + 20, 33};
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        near(p, q, 3, 40.0L, "transformed ellipse", t);
    }
    bsi_curve_free(&cv);
    double c2[2] = {0, 0}, x2[2] = {1, 0}, y2[2] = {0, 1};
    CHECK_STATUS(bsi_curve_conic(2, c2, x2, y2, 1.0, 1.0, 1.0, -1.0, 2.0, &cv), BS_OK);
    double B[6] = {2, 1, -1, 0.5, 3, 4}; /* (x, y) -> (2x + y - 1, x/2 + 3y + 4) */
    bsi_curve_transform(&cv, B);
    for (int i = 0; i <= 100; i++) {
        double t = -1.0 + 3.0 * i / 100.0, p[2];
        long double q[2] = {2 * cosl(t) + sinl(t) - 1, 0.5L * cosl(t) + 3 * sinl(t) + 4};
        CHECK(bsi_curve_eval(&cv, t, p) == 1);
        near(p, q, 2, 10.0L, "affine circle", t);
    }
    bsi_curve_free(&cv);
}

/* ---- refusals: the status, and the output left empty ---- */
static void test_refusals(void)
{
    double p[3] = {0, 0, 0}, d[3] = {1, 0, 0}, y[3] = {0, 1, 0}, bad[3] = {0, NAN, 0};
    double big[3] = {1e308, 0, 0};
    bsi_curve cv;
    CHECK_STATUS(bsi_curve_line(1, p, d, 0, 1, &cv), BS_ERR_DIMENSION);
    CHECK(empty(&cv));
    CHECK_STATUS(bsi_curve_line(4, p, d, 0, 1, &cv), BS_ERR_DIMENSION);
    CHECK_STATUS(bsi_curve_line(3, bad, d, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK_STATUS(bsi_curve_line(3, p, bad, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK_STATUS(bsi_curve_line(3, p, d, 1, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_line(3, p, d, 0, NAN, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_line(3, big, big, 0, 10, &cv), BS_ERR_NONFINITE);
    CHECK(empty(&cv));

    CHECK_STATUS(bsi_curve_conic(4, p, d, y, 1, 1, 1, 0, 1, &cv), BS_ERR_DIMENSION);
    CHECK_STATUS(bsi_curve_conic(3, bad, d, y, 1, 1, 1, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK_STATUS(bsi_curve_conic(3, p, bad, y, 1, 1, 1, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK_STATUS(bsi_curve_conic(3, p, d, bad, 1, 1, 1, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, 0, 1, 1, 0, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, 1, -1, 1, 0, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, INFINITY, 1, 1, 0, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, 1, NAN, 1, 0, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, 1, 1, 0, 0, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, p, d, y, 1, 1, 1, 2, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_conic(3, big, d, y, 1e308, 1e308, 1, 0, 1, &cv), BS_ERR_NONFINITE);
    CHECK(empty(&cv));

    static const double k[] = {0, 0, 0, 1, 2, 2, 2};
    double c[8] = {0, 0, 1, 1, 2, 0, 3, 1}, w[4] = {1, 1, 1, 1};
    CHECK_STATUS(bsi_curve_bspline(1, 2, 4, k, c, NULL, 0, 2, &cv), BS_ERR_DIMENSION);
    CHECK_STATUS(bsi_curve_bspline(2, 0, 4, k, c, NULL, 0, 2, &cv), BS_ERR_DEGREE);
    CHECK_STATUS(bsi_curve_bspline(2, BS_MAX_DEGREE + 1, 4, k, c, NULL, 0, 2, &cv), BS_ERR_DEGREE);
    CHECK_STATUS(bsi_curve_bspline(2, 4, 4, k, c, NULL, 0, 2, &cv), BS_ERR_SIZE);
    static const double kdown[] = {0, 0, 0, 1, 0.5, 2, 2};
    static const double knan[] = {0, 0, 0, NAN, 2, 2, 2};
    static const double kmult[] = {0, 0, 0, 0, 2, 2, 2}; /* multiplicity 4 > degree + 1 */
    static const double kflat[] = {1, 1, 1, 1, 1, 1, 1};
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, kdown, c, NULL, 0, 2, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, knan, c, NULL, 0, 2, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, kmult, c, NULL, 0, 2, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, kflat, c, NULL, 0, 2, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, NULL, -0.5, 2, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, NULL, 0, 2.5, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, NULL, 1, 1, &cv), BS_ERR_DOMAIN);
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, NULL, NAN, 1, &cv), BS_ERR_DOMAIN);
    w[2] = 0.0;
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, w, 0, 2, &cv), BS_ERR_NONFINITE);
    w[2] = -1.0;
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, w, 0, 2, &cv), BS_ERR_NONFINITE);
    w[2] = NAN;
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, w, 0, 2, &cv), BS_ERR_NONFINITE);
    w[2] = 1e300;
    c[4] = 1e300; /* w x overflows */
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, w, 0, 2, &cv), BS_ERR_NONFINITE);
    c[4] = INFINITY;
    CHECK_STATUS(bsi_curve_bspline(2, 2, 4, k, c, NULL, 0, 2, &cv), BS_ERR_NONFINITE);
    CHECK(empty(&cv));
}

#ifdef BS_WRAP_MALLOC
/* Every allocation of each constructor fails in turn: NO_MEMORY and an empty output. */
static void test_no_memory(void)
{
    double p[3] = {0, 0, 0}, d[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    static const double k[] = {0, 0, 0, 1, 2, 2, 2};
    double c[8] = {0, 0, 1, 1, 2, 0, 3, 1};
    bsi_curve src;
    CHECK_STATUS(bsi_curve_conic(2, p, d, y, 1, 1, 1, 0, 6, &src), BS_OK);
    int failures = 0;
    for (size_t n = 1; n <= 3; n++) {
        bsi_curve cv;
        bs_status st;
        fail_in = n;
        st = bsi_curve_line(2, p, d, 0, 1, &cv);
        failures += st == BS_ERR_NO_MEMORY;
        CHECK(st == (n <= 2 ? BS_ERR_NO_MEMORY : BS_OK) && (st == BS_OK || empty(&cv)));
        bsi_curve_free(&cv);
        fail_in = n;
        st = bsi_curve_conic(3, p, d, y, 1, 1, 1, 0, 1, &cv);
        CHECK(st == (n <= 2 ? BS_ERR_NO_MEMORY : BS_OK) && (st == BS_OK || empty(&cv)));
        bsi_curve_free(&cv);
        fail_in = n;
        st = bsi_curve_copy(&src, &cv);
        CHECK(st == (n <= 2 ? BS_ERR_NO_MEMORY : BS_OK) && (st == BS_OK || empty(&cv)));
        bsi_curve_free(&cv);
        fail_in = n;
        st = bsi_curve_bspline(2, 2, 4, k, c, NULL, 0, 2, &cv);
        CHECK(st == (n <= 3 ? BS_ERR_NO_MEMORY : BS_OK) && (st == BS_OK || empty(&cv)));
        bsi_curve_free(&cv);
    }
    fail_in = 0;
    CHECK(failures == 2);
    bsi_curve_free(&src);
}
#endif

int main(void)
{
    test_conics();
    test_lines();
    test_bsplines();
    test_transform();
    test_refusals();
#ifdef BS_WRAP_MALLOC
    test_no_memory();
#endif
    printf("test_curve: largest error relative to the curve's size %.3g\n", worst);
    return bs_test_exit("test_curve");
}
