/*
 * Closest points on a part of a patch (a trimmed face): the test that a box holds no local
 * minimum of f = |S - q|^2 over the patch's domain, from the sign of a partial derivative.
 *
 * Where the search is held to a part of the domain, a box that the part's boundary crosses
 * cannot be pruned by its bounds near the boundary's own closest point (f is lower just outside
 * the part), and splitting it only shrinks the gap like the box. But a closest point of the part
 * that is not on its boundary is a local minimum of f over the patch's domain; if f_u > 0 over
 * the whole box and the box does not reach u = 0, every point of it has a lower neighbour towards
 * smaller u inside the domain, so no such minimum is in it (likewise for f_u < 0 and u = 1, and
 * along v). Points on the part's boundary are found by the caller's search along it.
 *
 * The sign comes from Bernstein coefficients, which bound a polynomial over the box (the convex
 * hull property). With N and W of bsi_cl_fbound (f = N / W, W > 0), f_u has the sign of
 * P = N_u W - N W_u; the coefficients of N_u are K (N_(k+1)l - N_kl) (K = 2m the degree), those
 * of W_u likewise, and P lies in the interval product of the four ranges. For a polynomial patch
 * W = 1 and P = N_u. Each coefficient carries a bound on its error (bsi_cl_fbound's err and rel),
 * so a sign is only taken when the whole range, widened by them, clears zero. */
#include "query/closest.h"

#include <float.h>
#include <math.h>

/* The range [r[0], r[1]] of the Bernstein coefficients of N (with bsi_cl_fbound's absolute error
 * err) or W (relative error rel) in the unscaled form, and of their derivative along dir
 * ([r[2], r[3]]), each widened by its error. */
static void ranges(const bsi_cl *w, const double *co, double err, double rel, int dir, double *r)
{
    size_t K = 2 * w->m, L = 2 * w->n, n2 = L + 1, deg = dir == BS_DIR_U ? K : L;
    const double *b2m = w->binom + w->m + w->n + 2, *b2n = b2m + K + 1;
    double lo = INFINITY, hi = -INFINITY, dlo = INFINITY, dhi = -INFINITY, big = 0.0;
    for (size_t k = 0; k <= K; k++)
        for (size_t l = 0; l <= L; l++) {
            double x = co[k * n2 + l] / (b2m[k] * b2n[l]);
            lo = lesser(lo, x), hi = greater(hi, x), big = greater(big, fabs(x));
            size_t kk = dir == BS_DIR_U ? k + 1 : k, ll = dir == BS_DIR_U ? l : l + 1;
            if (kk > K || ll > L)
                continue;
            double y = co[kk * n2 + ll] / (b2m[kk] * b2n[ll]), d = (double)deg * (y - x);
            dlo = lesser(dlo, d), dhi = greater(dhi, d);
        }
    double e = err + rel * big + 4.0 * DBL_EPSILON * big; /* each coefficient's error */
    double de = (double)deg * (2.0 * e + 4.0 * DBL_EPSILON * big);
    r[0] = lo - e, r[1] = hi + e, r[2] = dlo - de, r[3] = dhi + de;
}

/* The range of the product of two ranges a and b. */
static void product(const double *a, const double *b, double *out)
{
    double p[4] = {a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1]};
    out[0] = lesser(lesser(p[0], p[1]), lesser(p[2], p[3]));
    out[1] = greater(greater(p[0], p[1]), greater(p[2], p[3]));
}

/* The sign of f's derivative along dir over the box of the last bsi_cl_fbound (b), 0 when not
 * shown. */
static int derivative_sign(const bsi_cl *w, const bsi_cl_bound *b, int dir)
{
    if ((dir == BS_DIR_U ? w->m : w->n) == 0)
        return 0;
    double rn[4], rw[4];
    ranges(w, w->nco, b->err, 0.0, dir, rn);
    if (w->nc == w->dim) /* W = 1 */
        return rn[2] > 0.0 ? 1 : rn[3] < 0.0 ? -1 : 0;
    ranges(w, w->wco, 0.0, b->rel, dir, rw);
    double a[2], c[2];
    product(rn + 2, rw, a); /* N_u W */
    product(rn, rw + 2, c); /* N W_u */
    double lo = a[0] - c[1], hi = a[1] - c[0], e = 4.0 * DBL_EPSILON * (fabs(lo) + fabs(hi));
    return lo > e ? 1 : hi < -e ? -1 : 0;
}

int bsi_cl_no_minimum(bsi_cl *w, const bsi_cl_bound *b, const double x[4])
{
    for (int dir = BS_DIR_U; dir <= BS_DIR_V; dir++) {
        int sg = derivative_sign(w, b, dir);
        const double *ends = x + (dir == BS_DIR_U ? 0 : 2);
        if ((sg > 0 && ends[0] > 0.0) || (sg < 0 && ends[1] < 1.0))
            return 1;
    }
    return 0;
}
