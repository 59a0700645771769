/* Hodographs: the Bezier patch of a partial derivative of a polynomial patch, whose net is the
 * scaled forward-difference net m!/(m-k)! n!/(n-l)! Delta^(k,l) P. */
#include "ops/internal.h"

#include <stdlib.h>

typedef struct difference {
    size_t order;
    double scale; /* deg!/(deg-order)! */
} difference;

static void fiber_difference(const double *in, size_t deg_in, double *out, size_t deg_out, const void *ctx)
{
    const difference *d = ctx;
    double b[BS_MAX_DEGREE + 1];
    for (size_t i = 0; i <= deg_in; i++)
        b[i] = in[i];
    for (size_t r = 0; r < d->order; r++)
        for (size_t i = 0; i + r < deg_in; i++)
            b[i] = b[i + 1] - b[i];
    for (size_t i = 0; i <= deg_out; i++)
        out[i] = d->scale * b[i]; // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult): deg_out <= deg_in
}

/* deg!/(deg-order)!, rounded once (long double carries the product exactly or nearly so). */
static double falling_factorial(size_t deg, size_t order)
{
    long double f = 1.0L;
    for (size_t r = 0; r < order; r++)
        f *= (long double)(deg - r);
    return (double)f;
}

static bs_status zero_patch(size_t dim, bs_patch **out)
{
    bs_patch *z = bsi_patch_alloc(0, 0, dim, 0);
    if (z == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t c = 0; c < dim; c++)
        z->ctrl[c] = 0.0;
    bs_status st = bsi_patch_finish(z);
    if (st != BS_OK) {
        bs_patch_destroy(z);
        return st;
    }
    *out = z;
    return BS_OK;
}

bs_status bs_patch_derivative(const bs_patch *p, unsigned ku, unsigned kv, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    if (ku > BS_MAX_DEGREE || kv > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (p->rational)
        return BS_ERR_UNSUPPORTED;
    if (ku > p->deg_u || kv > p->deg_v)
        return zero_patch(p->dim, out);
    size_t du = p->deg_u - ku, dv = p->deg_v - kv, nc = p->ncoord;
    double *mid = malloc(bsi_net_size(nc, du, p->deg_v) * sizeof(double));
    double *fin = malloc(bsi_net_size(nc, du, dv) * sizeof(double));
    bs_status st = BS_ERR_NO_MEMORY;
    if (mid != NULL && fin != NULL) {
        difference dif_u = {ku, falling_factorial(p->deg_u, ku)};
        difference dif_v = {kv, falling_factorial(p->deg_v, kv)};
        bsi_net_map(p->hom, nc, p->deg_u, p->deg_v, BS_DIR_U, du, fiber_difference, &dif_u, mid);
        bsi_net_map(mid, nc, du, p->deg_v, BS_DIR_V, dv, fiber_difference, &dif_v, fin);
        st = bsi_patch_from_hom(du, dv, p->dim, 0, fin, out);
    }
    free(mid);
    free(fin);
    return st;
}
