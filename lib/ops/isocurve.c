/* Iso-parametric curves: de Casteljau along one direction on every fibre of the homogeneous net. */
#include "ops/internal.h"

#include <math.h>

static void fiber_point(const double *in, size_t deg_in, double *out, size_t deg_out, const void *ctx)
{
    double t = *(const double *)ctx, s = 1.0 - t;
    double b[BS_MAX_DEGREE + 1];
    (void)deg_out;
    for (size_t i = 0; i <= deg_in; i++)
        b[i] = in[i];
    for (size_t r = 1; r <= deg_in; r++)
        for (size_t i = 0; i + r <= deg_in; i++)
            b[i] = s * b[i] + t * b[i + 1];
    out[0] = b[0];
}

bs_status bs_patch_isocurve(const bs_patch *p, int dir, double t, double *ctrl, size_t ctrl_cap,
                            double *weights, size_t weights_cap)
{
    if (p == NULL || ctrl == NULL || (dir != BS_DIR_U && dir != BS_DIR_V))
        return BS_ERR_INVALID_ARG;
    if (!isfinite(t))
        return BS_ERR_DOMAIN;
    size_t dim = p->dim, count = (dir == BS_DIR_U ? p->deg_v : p->deg_u) + 1;
    if (ctrl_cap < count * dim || (weights != NULL && weights_cap < count))
        return BS_ERR_SIZE;

    double pts[(BS_MAX_DEGREE + 1) * BS_MAX_DIM], w[BS_MAX_DEGREE + 1];
    if (t == 0.0 || t == 1.0) {
        /* A boundary row (dir U) or column (dir V) of the net, copied exactly. */
        size_t last = dir == BS_DIR_U ? p->deg_u : p->deg_v, fixed = t == 0.0 ? 0 : last;
        for (size_t k = 0; k < count; k++) {
            size_t idx = dir == BS_DIR_U ? fixed * (p->deg_v + 1) + k : k * (p->deg_v + 1) + fixed;
            for (size_t c = 0; c < dim; c++)
                pts[k * dim + c] = p->ctrl[idx * dim + c];
            w[k] = p->rational ? p->weights[idx] : 1.0;
        }
    } else {
        double hom[(BS_MAX_DEGREE + 1) * (BS_MAX_DIM + 1)];
        bsi_net_map(p->hom, p->ncoord, p->deg_u, p->deg_v, dir, 0, fiber_point, &t, hom);
        for (size_t k = 0; k < count; k++) {
            w[k] = p->rational ? hom[dim * count + k] : 1.0;
            if (!(isfinite(w[k]) && w[k] > 0.0))
                return BS_ERR_NONFINITE;
            for (size_t c = 0; c < dim; c++) {
                double x = p->rational ? hom[c * count + k] / w[k] : hom[c * count + k];
                if (!isfinite(x))
                    return BS_ERR_NONFINITE;
                pts[k * dim + c] = x;
            }
        }
    }
    for (size_t k = 0; k < count * dim; k++)
        ctrl[k] = pts[k];
    if (weights != NULL)
        for (size_t k = 0; k < count; k++)
            weights[k] = w[k];
    return BS_OK;
}
