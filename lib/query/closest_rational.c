/*
 * Closest points on rational patches: the closure at a minimum on an edge or at a corner without
 * convexity (the separable bound of closest_bound.c carried over to G = N - c W).
 */
#include "query/closest.h"

#include <float.h>
#include <math.h>

/* G(x* + d) >= G(x*) + gam . d + (A ds^2 + C dt^2) / 2 - B |ds dt| holds for any polynomial G
 * with those bounds on its second derivatives over the square (abc from bsi_cl_convex, on G's
 * own coefficients), gam its gradient at x*. For G = N - c W, gam = W(x*) g (N's gradient is
 * W g + f grad W, and f(x*) = c), W(x*) between the bounds wr[0] <= W <= wr[1] of the square's
 * coefficients (each off by the relative rounding wr[2]): a range that bsi_cl_separable_bound
 * takes as a centre and a radius. f - c = G / W is then at least that bound over min W where it
 * is negative. G(x*) itself is W(x*) (f(x*) - c), c off by at most wr[3]: the caller allows for
 * that once (its noise), the rest of it, up to wr[3] (max W / min W - 1), is taken off here. */
double bsi_cl_separable_weighted(const double uv[2], const double x[4], const double g[2],
                                 const double dg[2], const double abc[3], const double wr[4])
{
    /* lo = 0 (weights squared to 0) comes with abc unset (NAN): the bound is then -INFINITY */
    double lo = wr[0] * (1.0 - 2.0 * wr[2]), hi = wr[1] * (1.0 + 2.0 * wr[2]), gc[2], gr[2];
    for (size_t i = 0; i < 2; i++) {
        double a = lo * g[i], b = hi * g[i];
        gc[i] = 0.5 * (a + b);
        gr[i] = (0.5 * fabs(b - a) + hi * dg[i]) * (1.0 + 16.0 * DBL_EPSILON) +
                8.0 * DBL_EPSILON * fabs(gc[i]);
    }
    double least = bsi_cl_separable_bound(uv, x, gc, gr, abc);
    return (fmin(least, 0.0) / lo - wr[3] * (hi / lo - 1.0)) * (1.0 + 4.0 * DBL_EPSILON);
}
