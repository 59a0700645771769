/*
 * Piecewise rational Bezier curves: lines, circles and ellipses (quadratic rational arcs of at
 * most a quarter turn, weights (1, cos a, 1), on an ANGULAR axis so that native t is exactly the
 * angle's parameter), and B-splines (their Bezier spans on homogeneous points, the first and last
 * cut at the range's ends). Evaluation by de Casteljau on homogeneous points.
 */
#include "model/internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define HOM_MAX ((BS_MAX_DEGREE + 1) * 4) /* one segment's homogeneous points, dim <= 3 */

void bsi_curve_free(bsi_curve *c)
{
    bsi_axis_free(&c->axis);
    free(c->hom);
    c->hom = NULL;
}

static size_t hom_count(const bsi_curve *c)
{
    return c->axis.n * (c->degree + 1) * (c->dim + 1);
}

/* A curve of n segments on the axis *a (moved in), its points allocated and left to fill. */
static bs_status curve_alloc(size_t dim, size_t degree, bsi_axis *a, bsi_curve *out)
{
    out->dim = dim;
    out->degree = degree;
    out->axis = *a;
    memset(a, 0, sizeof *a);
    out->hom = malloc(hom_count(out) * sizeof *out->hom);
    if (out->hom == NULL) {
        bsi_curve_free(out);
        memset(out, 0, sizeof *out);
        return BS_ERR_NO_MEMORY;
    }
    return BS_OK;
}

bs_status bsi_curve_copy(const bsi_curve *src, bsi_curve *dst)
{
    memset(dst, 0, sizeof *dst);
    bsi_axis a;
    bs_status st = bsi_axis_copy(&src->axis, &a);
    if (st != BS_OK)
        return st;
    st = curve_alloc(src->dim, src->degree, &a, dst);
    if (st != BS_OK)
        return st;
    memcpy(dst->hom, src->hom, hom_count(dst) * sizeof *dst->hom);
    return BS_OK;
}

int bsi_curve_closed(const bsi_curve *c, double tol)
{
    if (c == NULL || c->axis.n == 0 || c->dim != 3)
        return 0;
    const double *a = c->hom, *z = c->hom + (c->axis.n * (c->degree + 1) - 1) * 4;
    double p[3] = {a[0] / a[3], a[1] / a[3], a[2] / a[3]}, q[3] = {z[0] / z[3], z[1] / z[3], z[2] / z[3]};
    return hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]) <= tol;
}

bs_status bsi_curve_repeat(const bsi_curve *src, bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    size_t n = src->axis.n;
    if (n == 0 || n > SIZE_MAX / 4)
        return BS_ERR_DOMAIN;
    double period = src->axis.breaks[n] - src->axis.breaks[0];
    bsi_axis a = src->axis;
    a.n = 3 * n;
    a.quarter = NULL; /* computed when asked: the breaks are new */
    a.breaks = malloc((a.n + 1) * sizeof *a.breaks);
    if (a.breaks == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < 3; k++) /* the breaks of copy k shifted by (k - 1) periods */
        for (size_t i = 0; i <= n; i++)
            a.breaks[k * n + i] = src->axis.breaks[i] + ((double)k - 1.0) * period;
    bs_status st = curve_alloc(src->dim, src->degree, &a, out);
    if (st != BS_OK)
        return st;
    for (size_t k = 0; k < 3; k++)
        memcpy(out->hom + k * hom_count(src), src->hom, hom_count(src) * sizeof *out->hom);
    return BS_OK;
}

static int all_finite(const double *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

bs_status bsi_curve_line(size_t dim, const double *p, const double *d, double t0, double t1,
                         bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    if (dim != 2 && dim != 3)
        return BS_ERR_DIMENSION;
    if (!all_finite(p, dim) || !all_finite(d, dim))
        return BS_ERR_NONFINITE;
    bsi_axis a;
    bs_status st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, t0, t1, NULL, 0, &a);
    if (st == BS_OK)
        st = curve_alloc(dim, 1, &a, out);
    if (st != BS_OK)
        return st;
    for (size_t c = 0; c < dim; c++) {
        out->hom[c] = p[c] + t0 * d[c];
        out->hom[dim + 1 + c] = p[c] + t1 * d[c];
    }
    out->hom[dim] = out->hom[2 * dim + 1] = 1.0;
    if (!all_finite(out->hom, hom_count(out))) {
        bsi_curve_free(out);
        memset(out, 0, sizeof *out);
        return BS_ERR_NONFINITE;
    }
    return BS_OK;
}

bs_status bsi_curve_conic(size_t dim, const double *c, const double *x, const double *y, double rx,
                          double ry, double radians, double t0, double t1, bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    if (dim != 2 && dim != 3)
        return BS_ERR_DIMENSION;
    if (!all_finite(c, dim) || !all_finite(x, dim) || !all_finite(y, dim))
        return BS_ERR_NONFINITE;
    if (!(isfinite(rx) && isfinite(ry) && rx > 0.0 && ry > 0.0))
        return BS_ERR_DOMAIN;
    bsi_axis a;
    bs_status st = bsi_axis_make(BSI_AXIS_ANGULAR, radians, t0, t1, NULL, 0, &a);
    if (st == BS_OK)
        st = curve_alloc(dim, 2, &a, out);
    if (st != BS_OK)
        return st;
    for (size_t k = 0; k < out->axis.n; k++) {
        double b0 = out->axis.breaks[k], b1 = out->axis.breaks[k + 1];
        double half = 0.5 * radians * (b1 - b0), w = cos(half);
        /* the start, the middle (pushed out by 1 / cos a: the tangents' meeting point), the end */
        double ang[3] = {radians * b0, radians * b0 + half, radians * b1};
        double scale[3] = {1.0, 1.0 / w, 1.0}, wt[3] = {1.0, w, 1.0};
        double *h = out->hom + k * 3 * (dim + 1);
        for (size_t i = 0; i < 3; i++) {
            double cx = rx * cos(ang[i]) * scale[i], cy = ry * sin(ang[i]) * scale[i];
            for (size_t j = 0; j < dim; j++)
                h[i * (dim + 1) + j] = wt[i] * (c[j] + cx * x[j] + cy * y[j]);
            h[i * (dim + 1) + dim] = wt[i];
        }
    }
    if (!all_finite(out->hom, hom_count(out))) {
        bsi_curve_free(out);
        memset(out, 0, sizeof *out);
        return BS_ERR_NONFINITE;
    }
    return BS_OK;
}

/* De Casteljau at s on the degree-p points h (n coordinates each): the left part [0, s] into h
 * when keep_left, else the right part [s, 1]. */
static void cut(double *h, size_t p, size_t n, double s, int keep_left)
{
    double tmp[HOM_MAX];
    memcpy(tmp, h, (p + 1) * n * sizeof *h);
    for (size_t r = 1; r <= p; r++) {
        for (size_t i = 0; i + r <= p; i++)
            for (size_t c = 0; c < n; c++)
                tmp[i * n + c] = (1.0 - s) * tmp[i * n + c] + s * tmp[(i + 1) * n + c];
        if (keep_left)
            memcpy(h + r * n, tmp, n * sizeof *h);
        else
            memcpy(h + (p - r) * n, tmp + (p - r) * n, n * sizeof *h);
    }
}

/* The homogeneous control points of a B-spline: w * point, then w. */
static bs_status homogeneous(size_t dim, size_t count, const double *ctrl, const double *weights,
                             double **out)
{
    *out = NULL;
    if (count > SIZE_MAX / sizeof(double) / (dim + 1))
        return BS_ERR_SIZE;
    for (size_t k = 0; k < count; k++) {
        double w = weights != NULL ? weights[k] : 1.0;
        if (!(isfinite(w) && w > 0.0))
            return BS_ERR_NONFINITE;
        for (size_t c = 0; c < dim; c++)
            if (!isfinite(ctrl[k * dim + c]) || !isfinite(w * ctrl[k * dim + c]))
                return BS_ERR_NONFINITE;
    }
    /* count >= degree + 1 >= 2 (bsi_knots_check), never a size of 0 */
    /* NOLINTNEXTLINE(clang-analyzer-optin.portability.UnixAPI) */
    double *h = malloc(count * (dim + 1) * sizeof *h);
    if (h == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < count; k++) {
        double w = weights != NULL ? weights[k] : 1.0;
        for (size_t c = 0; c < dim; c++)
            h[k * (dim + 1) + c] = w * ctrl[k * dim + c];
        h[k * (dim + 1) + dim] = w;
    }
    *out = h;
    return BS_OK;
}

bs_status bsi_curve_bspline(size_t dim, size_t degree, size_t count, const double *knots,
                            const double *ctrl, const double *weights, double t0, double t1,
                            bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    if (dim != 2 && dim != 3)
        return BS_ERR_DIMENSION;
    bsi_knots kn;
    bs_status st = bsi_knots_check(degree, count, knots, &kn);
    if (st != BS_OK)
        return st;
    if (!(t0 >= knots[degree] && t1 <= knots[count] && t0 < t1))
        return BS_ERR_DOMAIN;
    double *h;
    st = homogeneous(dim, count, ctrl, weights, &h);
    if (st != BS_OK)
        return st;
    bsi_axis a;
    st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, t0, t1, knots, count + degree + 1, &a);
    if (st == BS_OK)
        st = curve_alloc(dim, degree, &a, out);
    if (st != BS_OK) {
        free(h);
        return st;
    }
    size_t n = dim + 1, i = degree;
    for (size_t k = 0; k < out->axis.n; k++) {
        double b0 = out->axis.breaks[k], b1 = out->axis.breaks[k + 1];
        /* the span holding [b0, b1]: every knot inside the range is a break */
        while (!(knots[i] <= b0 && b0 < knots[i + 1]))
            i++;
        double *seg = out->hom + k * (degree + 1) * n;
        bsi_span_bezier(knots, degree, i, h, n, n, seg, n);
        double lo = knots[i], len = knots[i + 1] - lo;
        if (b1 < knots[i + 1])
            cut(seg, degree, n, (b1 - lo) / len, 1);
        if (b0 > lo)
            cut(seg, degree, n, (b0 - lo) / (b1 - lo), 0);
    }
    free(h);
    return BS_OK;
}

void bsi_curve_transform(bsi_curve *c, const double *affine)
{
    size_t n = c->dim + 1, np = c->axis.n * (c->degree + 1);
    for (size_t k = 0; k < np; k++) {
        double *h = c->hom + k * n, q[3] = {0.0, 0.0, 0.0};
        for (size_t r = 0; r < c->dim; r++) {
            const double *row = affine + r * 3; /* (a b c; d e f) in 2-D: the third is the shift */
            double s = (c->dim == 3 ? affine[9 + r] : row[2]) * h[c->dim];
            for (size_t j = 0; j < c->dim; j++)
                s += row[j] * h[j];
            q[r] = s;
        }
        memcpy(h, q, c->dim * sizeof *h);
    }
}

void bsi_curve_point(const bsi_curve *c, size_t k, double s, double *p)
{
    size_t n = c->dim + 1, deg = c->degree;
    double tmp[HOM_MAX];
    memcpy(tmp, c->hom + k * (deg + 1) * n, (deg + 1) * n * sizeof *tmp);
    for (size_t r = 1; r <= deg; r++)
        for (size_t i = 0; i + r <= deg; i++)
            for (size_t j = 0; j < n; j++)
                tmp[i * n + j] = (1.0 - s) * tmp[i * n + j] + s * tmp[(i + 1) * n + j];
    for (size_t j = 0; j < c->dim; j++)
        p[j] = tmp[j] / tmp[c->dim];
}

int bsi_curve_eval(const bsi_curve *c, double t, double *p)
{
    size_t k;
    double s;
    if (!bsi_axis_locate(&c->axis, t, &k, &s))
        return 0;
    bsi_curve_point(c, k, s, p);
    return 1;
}

void bsi_curve_bounds(const bsi_curve *c, double *lo, double *hi)
{
    size_t n = c->dim + 1, np = c->axis.n * (c->degree + 1);
    for (size_t j = 0; j < c->dim; j++) {
        lo[j] = np > 0 ? INFINITY : 0.0;
        hi[j] = np > 0 ? -INFINITY : 0.0;
    }
    for (size_t k = 0; k < np; k++)
        for (size_t j = 0; j < c->dim; j++) {
            double x = c->hom[k * n + j] / c->hom[k * n + c->dim];
            lo[j] = x < lo[j] ? x : lo[j];
            hi[j] = x > hi[j] ? x : hi[j];
        }
}
