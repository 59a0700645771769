/* Degree elevation in one step per direction: Q_k = sum_i C(m,i) C(r,k-i) / C(m+r,k) P_i, a convex
 * combination, so the result is as accurate as one weighted sum. */
#include "ops/internal.h"

#include <stdlib.h>
#include <string.h>

/* Row n of Pascal's triangle in long double (exact up to n = 64 where long double has 64 bits). */
static void binomial_row(size_t n, long double *row)
{
    row[0] = 1.0L;
    for (size_t k = 1; k <= n; k++) {
        row[k] = 1.0L;
        for (size_t i = k - 1; i > 0; i--)
            row[i] += row[i - 1];
    }
}

typedef struct elevation {
    size_t m, r;
    const double *coef; /* coef[k*(m+1) + i] for k = 0..m+r, i = 0..m */
} elevation;

static void fiber_elevate(const double *in, size_t deg_in, double *out, size_t deg_out, const void *ctx)
{
    const elevation *e = ctx;
    for (size_t k = 0; k <= deg_out; k++) {
        size_t lo = k > e->r ? k - e->r : 0, hi = k < deg_in ? k : deg_in;
        double acc = 0.0;
        for (size_t i = lo; i <= hi; i++)
            acc += e->coef[k * (deg_in + 1) + i] * in[i];
        out[k] = acc;
    }
}

bs_status bsi_elevate_net(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                          size_t raise, double *out)
{
    size_t m = dir == BS_DIR_U ? deg_u : deg_v;
    if (raise == 0) {
        memcpy(out, in, bsi_net_size(ncoord, deg_u, deg_v) * sizeof(double));
        return BS_OK;
    }
    double *coef = malloc((m + raise + 1) * (m + 1) * sizeof(double));
    if (coef == NULL)
        return BS_ERR_NO_MEMORY;
    long double cm[BS_MAX_DEGREE + 1], cr[BS_MAX_DEGREE + 1], cmr[BS_MAX_DEGREE + 1];
    binomial_row(m, cm);
    binomial_row(raise, cr);
    binomial_row(m + raise, cmr);
    for (size_t k = 0; k <= m + raise; k++)
        for (size_t i = 0; i <= m; i++)
            coef[k * (m + 1) + i] =
                (i <= k && k - i <= raise) ? (double)(cm[i] * cr[k - i] / cmr[k]) : 0.0;
    elevation e = {m, raise, coef};
    bsi_net_map(in, ncoord, deg_u, deg_v, dir, m + raise, fiber_elevate, &e, out);
    free(coef);
    return BS_OK;
}

bs_status bs_patch_elevate(const bs_patch *p, size_t raise_u, size_t raise_v, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    if (raise_u > BS_MAX_DEGREE - p->deg_u || raise_v > BS_MAX_DEGREE - p->deg_v)
        return BS_ERR_DEGREE;
    size_t du = p->deg_u + raise_u, dv = p->deg_v + raise_v, nc = p->ncoord;
    double *mid = malloc(bsi_net_size(nc, du, p->deg_v) * sizeof(double));
    double *fin = malloc(bsi_net_size(nc, du, dv) * sizeof(double));
    bs_status st = BS_ERR_NO_MEMORY;
    if (mid != NULL && fin != NULL) {
        st = bsi_elevate_net(p->hom, nc, p->deg_u, p->deg_v, BS_DIR_U, raise_u, mid);
        if (st == BS_OK)
            st = bsi_elevate_net(mid, nc, du, p->deg_v, BS_DIR_V, raise_v, fin);
        if (st == BS_OK)
            st = bsi_patch_from_hom(du, dv, p->dim, p->rational, fin, out);
    }
    free(mid);
    free(fin);
    return st;
}
