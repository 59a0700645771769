/*
 * Adaptive Gauss-Kronrod quadrature (7-point Gauss, 15-point Kronrod) of a vector integrand, for
 * the model's properties. An interval is accepted when, in every component, |K15 - G7| is within
 * that component's tolerance scaled by the interval's share of [a, b], or within the rounding of
 * the sums (64 ulps of the integral of |f|); else it is halved. The
 * intervals wait on an explicit stack (no recursion), and the work is capped.
 */
#include "model/quadrature.h"

#include <float.h>
#include <math.h>

/* Kronrod nodes on [-1, 1] (x[7] = 0), their weights, and the Gauss weights of the odd nodes. */
static const double xk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                             0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                             0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                             0.207784955007898467600689403773245, 0.0};
static const double wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                             0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                             0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                             0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/* K15 and G7 of the integrand over [a, b], and K15 of its absolute value (the scale of its
 * rounding); 0 when the integrand failed. */
static int rule(bsi_quad_fn fn, void *ctx, size_t k, double a, double b, double *kron, double *gauss,
                double *kabs)
{
    double x[BSI_QUAD_NODES], f[BSI_QUAD_NODES * BSI_QUAD_MAX_K];
    double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (size_t i = 0; i < 7; i++) {
        x[2 * i] = mid - half * xk[i];
        x[2 * i + 1] = mid + half * xk[i];
    }
    x[14] = mid;
    if (!fn(ctx, BSI_QUAD_NODES, x, f))
        return 0;
    for (size_t c = 0; c < k; c++) {
        double sk = wk[7] * f[14 * k + c], sg = wg[3] * f[14 * k + c], sa = wk[7] * fabs(f[14 * k + c]);
        for (int i = 0; i < 7; i++) {
            double f0 = f[(size_t)(2 * i) * k + c], f1 = f[(size_t)(2 * i + 1) * k + c];
            sk += wk[i] * (f0 + f1);
            sa += wk[i] * (fabs(f0) + fabs(f1));
            if (i % 2 == 1)
                sg += wg[i / 2] * (f0 + f1);
        }
        kron[c] = half * sk;
        gauss[c] = half * sg;
        kabs[c] = fabs(half) * sa;
    }
    return 1;
}

int bsi_quad(bsi_quad_fn fn, void *ctx, size_t k, double a, double b, const double *tol,
             size_t max_intervals, double *result, double *err)
{
    struct { double a, b; } stack[BSI_QUAD_DEPTH];
    size_t top = 0, used = 0;
    for (size_t c = 0; c < k; c++)
        result[c] = err[c] = 0.0;
    if (!(b > a))
        return 1;
    stack[top].a = a;
    stack[top].b = b;
    top++;
    while (top > 0) {
        top--;
        double lo = stack[top].a, hi = stack[top].b;
        double kron[BSI_QUAD_MAX_K], gauss[BSI_QUAD_MAX_K], kabs[BSI_QUAD_MAX_K];
        if (++used > max_intervals || !rule(fn, ctx, k, lo, hi, kron, gauss, kabs))
            return 0;
        double share = (hi - lo) / (b - a), mid = 0.5 * (lo + hi);
        int accept = 1;
        for (size_t c = 0; c < k; c++) {
            /* the estimate cannot fall below the rounding of the sums themselves */
            double e = fabs(kron[c] - gauss[c]), noise = 64.0 * DBL_EPSILON * kabs[c];
            if (!(e <= tol[c] * share || e <= noise))
                accept = 0;
        }
        /* an interval too short to halve, or a full stack: no further refinement is possible */
        if (!accept && (mid <= lo || mid >= hi || top + 2 > BSI_QUAD_DEPTH))
            return 0;
        if (accept) {
            for (size_t c = 0; c < k; c++) {
                result[c] += kron[c];
                err[c] += fabs(kron[c] - gauss[c]);
            }
            continue;
        }
        stack[top].a = mid;
        stack[top].b = hi;
        stack[top + 1].a = lo;
        stack[top + 1].b = mid;
        top += 2;
    }
    return 1;
}
