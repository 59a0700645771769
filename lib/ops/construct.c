/* Patches built from Bezier curves: ruled patches and bilinearly blended Coons patches. Curves are
 * brought to a common degree by exact (one-step) degree elevation in homogeneous coordinates. */
#include "ops/internal.h"

#include <math.h>
#include <stdlib.h>

static bs_status check_curve(const bs_curve *c)
{
    if (c == NULL || c->ctrl == NULL)
        return BS_ERR_INVALID_ARG;
    if (c->degree > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (c->dim == 0 || c->dim > BS_MAX_DIM)
        return BS_ERR_DIMENSION;
    if (!bsi_all_finite(c->ctrl, (c->degree + 1) * c->dim))
        return BS_ERR_NONFINITE;
    if (c->weights != NULL)
        for (size_t k = 0; k <= c->degree; k++)
            if (!(isfinite(c->weights[k]) && c->weights[k] > 0.0))
                return BS_ERR_NONFINITE;
    return BS_OK;
}

/* Check every curve, then that they share one dim. */
static bs_status check_curves(const bs_curve *const *cs, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        bs_status st = check_curve(cs[k]);
        if (st != BS_OK)
            return st;
    }
    for (size_t k = 1; k < n; k++)
        if (cs[k]->dim != cs[0]->dim)
            return BS_ERR_INCOMPATIBLE;
    return BS_OK;
}

/* The curve's coordinate-major homogeneous net (ncoord planes of deg+1 values; planes w*P then w
 * when rational, weights 1 for a polynomial curve) elevated to degree deg. out holds ncoord*(deg+1). */
static bs_status curve_hom(const bs_curve *c, int rational, size_t deg, double *out)
{
    size_t dim = c->dim, d = c->degree, ncoord = dim + (rational ? 1u : 0u);
    double hom[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
    for (size_t k = 0; k <= d; k++) {
        double w = c->weights != NULL ? c->weights[k] : 1.0;
        for (size_t i = 0; i < dim; i++) {
            double h = rational ? w * c->ctrl[k * dim + i] : c->ctrl[k * dim + i];
            if (!isfinite(h))
                return BS_ERR_NONFINITE;
            hom[i * (d + 1) + k] = h;
        }
        if (rational)
            hom[dim * (d + 1) + k] = w;
    }
    return bsi_elevate_net(hom, ncoord, d, 0, BS_DIR_U, deg - d, out);
}

bs_status bs_patch_ruled(const bs_curve *c0, const bs_curve *c1, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    const bs_curve *cs[2] = {c0, c1};
    bs_status st = check_curves(cs, 2);
    if (st != BS_OK)
        return st;
    int rational = c0->weights != NULL || c1->weights != NULL;
    size_t dim = c0->dim, ncoord = dim + (rational ? 1u : 0u);
    size_t deg = c0->degree > c1->degree ? c0->degree : c1->degree;
    double e0[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)], e1[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
    st = curve_hom(c0, rational, deg, e0);
    if (st == BS_OK)
        st = curve_hom(c1, rational, deg, e1);
    if (st != BS_OK)
        return st;
    /* Net of degree (deg, 1): plane c, point (i, j) at c*2(deg+1) + 2i + j. */
    double net[2 * (BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
    for (size_t c = 0; c < ncoord; c++)
        for (size_t i = 0; i <= deg; i++) {
            net[c * 2 * (deg + 1) + 2 * i] = e0[c * (deg + 1) + i];
            net[c * 2 * (deg + 1) + 2 * i + 1] = e1[c * (deg + 1) + i];
        }
    return bsi_patch_from_hom(deg, 1, dim, rational, net, out);
}

/* Largest absolute control coordinate of the curves, at least 1: the scale of the corner test. */
static double corner_scale(const bs_curve *const *cs, size_t n)
{
    double s = 1.0;
    for (size_t k = 0; k < n; k++)
        for (size_t i = 0; i < (cs[k]->degree + 1) * cs[k]->dim; i++)
            s = fabs(cs[k]->ctrl[i]) > s ? fabs(cs[k]->ctrl[i]) : s;
    return s;
}

/* 1 if point a of curve ca and point b of curve cb agree within tol in every coordinate. */
static int meet(const bs_curve *ca, size_t a, const bs_curve *cb, size_t b, double tol)
{
    for (size_t c = 0; c < ca->dim; c++)
        if (!(fabs(ca->ctrl[a * ca->dim + c] - cb->ctrl[b * cb->dim + c]) <= tol))
            return 0;
    return 1;
}

bs_status bs_patch_coons(const bs_curve *v0, const bs_curve *v1, const bs_curve *u0,
                         const bs_curve *u1, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    const bs_curve *cs[4] = {v0, v1, u0, u1};
    bs_status st = check_curves(cs, 4);
    if (st != BS_OK)
        return st;
    for (size_t k = 0; k < 4; k++)
        if (cs[k]->weights != NULL)
            return BS_ERR_UNSUPPORTED;
    double tol = 1e-12 * corner_scale(cs, 4);
    if (!meet(v0, 0, u0, 0, tol) || !meet(v0, v0->degree, u1, 0, tol) ||
        !meet(v1, 0, u0, u0->degree, tol) || !meet(v1, v1->degree, u1, u1->degree, tol))
        return BS_ERR_INCOMPATIBLE;

    size_t dim = v0->dim;
    size_t m = v0->degree > v1->degree ? v0->degree : v1->degree;
    size_t n = u0->degree > u1->degree ? u0->degree : u1->degree;
    m = m > 0 ? m : 1;
    n = n > 0 ? n : 1;
    /* Elevated curves, coordinate-major: a[c*(m+1) + i] etc. */
    double a[(BS_MAX_DEGREE + 1) * BS_MAX_DIM], b[(BS_MAX_DEGREE + 1) * BS_MAX_DIM];
    double cc[(BS_MAX_DEGREE + 1) * BS_MAX_DIM], d[(BS_MAX_DEGREE + 1) * BS_MAX_DIM];
    if ((st = curve_hom(v0, 0, m, a)) != BS_OK || (st = curve_hom(v1, 0, m, b)) != BS_OK ||
        (st = curve_hom(u0, 0, n, cc)) != BS_OK || (st = curve_hom(u1, 0, n, d)) != BS_OK)
        return st;

    bs_patch *q = bsi_patch_alloc(m, n, dim, 0);
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t c = 0; c < dim; c++) {
        const double *A = a + c * (m + 1), *B = b + c * (m + 1);
        const double *C = cc + c * (n + 1), *D = d + c * (n + 1);
        double p00 = A[0], p10 = A[m], p01 = B[0], p11 = B[m];
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                double x;
                if (j == 0)
                    x = A[i];
                else if (j == n)
                    x = B[i];
                else if (i == 0)
                    x = C[j];
                else if (i == m)
                    x = D[j];
                else {
                    /* Ruled in v + ruled in u - bilinear, each elevated to (m, n). */
                    double s = (double)i / (double)m, t = (double)j / (double)n;
                    double ruled_v = (1.0 - t) * A[i] + t * B[i];
                    double ruled_u = (1.0 - s) * C[j] + s * D[j];
                    double bilin = (1.0 - s) * ((1.0 - t) * p00 + t * p01) + s * ((1.0 - t) * p10 + t * p11);
                    x = ruled_v + ruled_u - bilin;
                }
                q->ctrl[(i * (n + 1) + j) * dim + c] = x;
            }
    }
    st = bsi_patch_finish(q);
    if (st != BS_OK) {
        bs_patch_destroy(q);
        return st;
    }
    *out = q;
    return BS_OK;
}
