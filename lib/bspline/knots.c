/* Knot vectors: the checks of bezsurf/bspline.h, and the spans of the domain. */
#include "bspline/internal.h"

#include <math.h>

bs_status bsi_knots_check(size_t deg, size_t count, const double *t, bsi_knots *k)
{
    if (deg == 0 || deg > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (count < deg + 1 || count > SIZE_MAX - deg - 1)
        return BS_ERR_SIZE;
    size_t nknot = count + deg + 1, run = 1;
    for (size_t i = 0; i < nknot; i++) {
        if (!isfinite(t[i]))
            return BS_ERR_DOMAIN;
        if (i > 0) {
            if (t[i] < t[i - 1])
                return BS_ERR_DOMAIN;
            run = t[i] == t[i - 1] ? run + 1 : 1;
            if (run > deg + 1) /* a basis function with an empty support */
                return BS_ERR_DOMAIN;
        }
    }
    size_t nspan = 0;
    for (size_t i = deg; i < count; i++)
        nspan += t[i] < t[i + 1];
    /* knot differences are the blossom's denominators: past DBL_MAX (knots near +-DBL_MAX) every
     * patch point would come out Inf */
    if (nspan == 0 || !isfinite(t[nknot - 1] - t[0]))
        return BS_ERR_DOMAIN;
    k->deg = deg;
    k->count = count;
    k->t = t;
    k->nspan = nspan;
    return BS_OK;
}

void bsi_knots_spans(const bsi_knots *k, size_t *first)
{
    size_t a = 0;
    for (size_t i = k->deg; i < k->count; i++)
        if (k->t[i] < k->t[i + 1])
            first[a++] = i;
}

void bsi_span_bezier(const double *t, size_t p, size_t i, const double *in, size_t in_step,
                     size_t ncoord, double *out, size_t out_step)
{
    double d[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
    double lo = t[i], hi = t[i + 1];
    for (size_t m = 0; m <= p; m++) {
        for (size_t k = 0; k <= p; k++)
            for (size_t c = 0; c < ncoord; c++)
                d[k * ncoord + c] = in[(i - p + k) * in_step + c];
        /* de Boor's recurrence with the blossom's arguments, one per level: every step is a
         * convex combination, since each argument lies in [t[j], t[j+p+1-r]] */
        for (size_t r = 1; r <= p; r++) {
            double x = r <= p - m ? lo : hi;
            for (size_t k = p; k >= r; k--) {
                size_t j = i - p + k;
                double alpha = (x - t[j]) / (t[j + p + 1 - r] - t[j]);
                for (size_t c = 0; c < ncoord; c++)
                    d[k * ncoord + c] = (1.0 - alpha) * d[(k - 1) * ncoord + c] + alpha * d[k * ncoord + c];
            }
        }
        for (size_t c = 0; c < ncoord; c++)
            out[m * out_step + c] = d[p * ncoord + c];
    }
}
