/* Bounds of the net, affine maps, and orientation changes (u/v swap, reversal): operations on the
 * Cartesian net that need no homogeneous arithmetic. */
#include "ops/internal.h"

bs_status bs_patch_bounds(const bs_patch *p, double *lo, double *hi)
{
    if (p == NULL || lo == NULL || hi == NULL)
        return BS_ERR_INVALID_ARG;
    double a[BS_MAX_DIM], b[BS_MAX_DIM];
    for (size_t c = 0; c < p->dim; c++)
        a[c] = b[c] = p->ctrl[c];
    for (size_t k = 1; k < p->nctrl; k++)
        for (size_t c = 0; c < p->dim; c++) {
            double x = p->ctrl[k * p->dim + c];
            a[c] = x < a[c] ? x : a[c];
            b[c] = x > b[c] ? x : b[c];
        }
    for (size_t c = 0; c < p->dim; c++) {
        lo[c] = a[c];
        hi[c] = b[c];
    }
    return BS_OK;
}

/* Finish q (ctrl and weights filled) into *out, or destroy it. */
static bs_status finish_into(bs_patch *q, bs_patch **out)
{
    bs_status st = bsi_patch_finish(q);
    if (st != BS_OK) {
        bs_patch_destroy(q);
        return st;
    }
    *out = q;
    return BS_OK;
}

bs_status bs_patch_transform(const bs_patch *p, const double *affine, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || affine == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    size_t dim = p->dim;
    bs_patch *q = bsi_patch_alloc(p->deg_u, p->deg_v, dim, p->rational);
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < p->nctrl; k++) {
        const double *x = p->ctrl + k * dim;
        for (size_t r = 0; r < dim; r++) {
            const double *row = affine + r * (dim + 1);
            double acc = row[dim];
            for (size_t c = 0; c < dim; c++)
                acc += row[c] * x[c];
            q->ctrl[k * dim + r] = acc;
        }
        if (p->rational)
            q->weights[k] = p->weights[k];
    }
    return finish_into(q, out);
}

bs_status bs_patch_swap_uv(const bs_patch *p, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    size_t m = p->deg_u, n = p->deg_v, dim = p->dim;
    bs_patch *q = bsi_patch_alloc(n, m, dim, p->rational);
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t src = i * (n + 1) + j, dst = j * (m + 1) + i;
            for (size_t c = 0; c < dim; c++)
                q->ctrl[dst * dim + c] = p->ctrl[src * dim + c];
            if (p->rational)
                q->weights[dst] = p->weights[src];
        }
    return finish_into(q, out);
}

bs_status bs_patch_reverse(const bs_patch *p, int dir, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL || (dir != BS_DIR_U && dir != BS_DIR_V))
        return BS_ERR_INVALID_ARG;
    size_t m = p->deg_u, n = p->deg_v, dim = p->dim;
    bs_patch *q = bsi_patch_alloc(m, n, dim, p->rational);
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t dst = i * (n + 1) + j;
            size_t src = dir == BS_DIR_U ? (m - i) * (n + 1) + j : i * (n + 1) + (n - j);
            for (size_t c = 0; c < dim; c++)
                q->ctrl[dst * dim + c] = p->ctrl[src * dim + c];
            if (p->rational)
                q->weights[dst] = p->weights[src];
        }
    return finish_into(q, out);
}
