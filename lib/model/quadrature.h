/*
 * Adaptive Gauss-Kronrod quadrature of vector integrands (lib/model/quadrature.c), for the
 * model's area, volume and centroid (properties.c). Private to lib/model/.
 */
#ifndef BEZSURF_MODEL_QUADRATURE_H
#define BEZSURF_MODEL_QUADRATURE_H

#include "model/internal.h"

#define BSI_QUAD_NODES 15  /* points per rule: the integrand is called with this many at once */
#define BSI_QUAD_MAX_K 8   /* components of an integrand */
#define BSI_QUAD_DEPTH 64  /* intervals waiting at once (the depth of the bisection) */

/* f[i * k + c]: component c of the integrand at x[i], i < n. Returns 0 when it cannot be
 * evaluated there (the quadrature then fails). */
typedef int (*bsi_quad_fn)(void *ctx, size_t n, const double *x, double *f);

/* The integral of fn's k components over [a, b] (empty when b <= a: zeros), each within tol[c]
 * by the Kronrod-Gauss estimate, summed into result[c] with the estimates in err[c]. Returns 1,
 * or 0 when the integrand failed, more than max_intervals rules were needed, or an interval
 * could not be halved further. */
int bsi_quad(bsi_quad_fn fn, void *ctx, size_t k, double a, double b, const double *tol,
             size_t max_intervals, double *result, double *err);

#endif
