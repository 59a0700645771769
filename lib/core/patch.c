/* The patch object: creation, validation, copies and accessors. */
#include "core/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

bs_patch *bsi_patch_alloc(size_t deg_u, size_t deg_v, size_t dim, int rational)
{
    /* Degrees <= BS_MAX_DEGREE and dim <= BS_MAX_DIM keep every size below far from overflow. */
    size_t nctrl = (deg_u + 1) * (deg_v + 1);
    size_t ncoord = dim + (rational ? 1u : 0u);
    size_t ndouble = nctrl * dim + (rational ? nctrl : 0) + nctrl * ncoord;
    /* The doubles follow the header, rounded up so they are aligned. */
    size_t head = (sizeof(bs_patch) + sizeof(double) - 1) / sizeof(double) * sizeof(double);
    bs_patch *p = malloc(head + ndouble * sizeof(double));
    if (p == NULL)
        return NULL;
    double *data = (double *)(void *)((char *)p + head);
    p->deg_u = deg_u;
    p->deg_v = deg_v;
    p->dim = dim;
    p->nctrl = nctrl;
    p->ncoord = ncoord;
    p->rational = rational;
    p->ctrl = data;
    p->weights = rational ? data + nctrl * dim : NULL;
    p->hom = data + nctrl * dim + (rational ? nctrl : 0);
    return p;
}

bs_status bsi_patch_finish(bs_patch *p)
{
    size_t nctrl = p->nctrl, dim = p->dim;
    if (!bsi_all_finite(p->ctrl, nctrl * dim))
        return BS_ERR_NONFINITE;
    for (size_t k = 0; k < nctrl; k++) {
        double w = p->rational ? p->weights[k] : 1.0;
        if (!(isfinite(w) && w > 0.0))
            return BS_ERR_NONFINITE;
        for (size_t c = 0; c < dim; c++) {
            double h = p->rational ? w * p->ctrl[k * dim + c] : p->ctrl[k * dim + c];
            if (!isfinite(h))
                return BS_ERR_NONFINITE;
            p->hom[c * nctrl + k] = h;
        }
        if (p->rational)
            p->hom[dim * nctrl + k] = w;
    }
    return BS_OK;
}

static bs_status check_shape(size_t deg_u, size_t deg_v, size_t dim)
{
    if (deg_u > BS_MAX_DEGREE || deg_v > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (dim == 0 || dim > BS_MAX_DIM)
        return BS_ERR_DIMENSION;
    return BS_OK;
}

bs_status bs_patch_create(size_t deg_u, size_t deg_v, size_t dim,
                          const double *ctrl, const double *weights, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (ctrl == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st = check_shape(deg_u, deg_v, dim);
    if (st != BS_OK)
        return st;
    bs_patch *p = bsi_patch_alloc(deg_u, deg_v, dim, weights != NULL);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    memcpy(p->ctrl, ctrl, p->nctrl * dim * sizeof(double));
    if (weights != NULL)
        memcpy(p->weights, weights, p->nctrl * sizeof(double));
    st = bsi_patch_finish(p);
    if (st != BS_OK) {
        free(p);
        return st;
    }
    *out = p;
    return BS_OK;
}

bs_status bsi_patch_from_hom(size_t deg_u, size_t deg_v, size_t dim, int rational,
                             const double *hom, bs_patch **out)
{
    *out = NULL;
    bs_status st = check_shape(deg_u, deg_v, dim);
    if (st != BS_OK)
        return st;
    bs_patch *p = bsi_patch_alloc(deg_u, deg_v, dim, rational);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    size_t nctrl = p->nctrl;
    for (size_t k = 0; k < nctrl; k++) {
        double w = rational ? hom[dim * nctrl + k] : 1.0;
        if (rational)
            p->weights[k] = w;
        for (size_t c = 0; c < dim; c++)
            p->ctrl[k * dim + c] = rational ? hom[c * nctrl + k] / w : hom[c * nctrl + k];
    }
    st = bsi_patch_finish(p);
    if (st != BS_OK) {
        free(p);
        return st;
    }
    *out = p;
    return BS_OK;
}

void bs_patch_destroy(bs_patch *p) { free(p); }

bs_status bs_patch_clone(const bs_patch *p, bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    bs_patch *q = bsi_patch_alloc(p->deg_u, p->deg_v, p->dim, p->rational);
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    size_t ndouble = p->nctrl * p->dim + (p->rational ? p->nctrl : 0) + p->nctrl * p->ncoord;
    memcpy(q->ctrl, p->ctrl, ndouble * sizeof(double));
    *out = q;
    return BS_OK;
}

size_t bs_patch_degree_u(const bs_patch *p) { return p ? p->deg_u : 0; }
size_t bs_patch_degree_v(const bs_patch *p) { return p ? p->deg_v : 0; }
size_t bs_patch_dim(const bs_patch *p) { return p ? p->dim : 0; }
int bs_patch_is_rational(const bs_patch *p) { return p ? p->rational : 0; }

bs_status bs_patch_get_ctrl(const bs_patch *p, double *ctrl, size_t ctrl_cap,
                            double *weights, size_t weights_cap)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if ((ctrl != NULL && ctrl_cap < p->nctrl * p->dim) || (weights != NULL && weights_cap < p->nctrl))
        return BS_ERR_SIZE;
    if (ctrl != NULL)
        memcpy(ctrl, p->ctrl, p->nctrl * p->dim * sizeof(double));
    if (weights != NULL) {
        for (size_t k = 0; k < p->nctrl; k++)
            weights[k] = p->rational ? p->weights[k] : 1.0;
    }
    return BS_OK;
}
