/* Scattered evaluation of positions and first partial derivatives. */
#include "internal.h"

#include <math.h>

#define B BSI_BLOCK
#define NMAX (BS_MAX_DEGREE + 1)

/* Bernstein weights of BSI_BLOCK parameters, point-innermost: w[i*B + k] = B(deg,i)(t[k]) and
 * wm[i*B + k] = B(deg-1,i)(t[k]). The recurrence of bsi_bernstein_first, run on all lanes at
 * once with the same operations per lane, so the values are the same bits. */
static void block_weights(size_t deg, const double *t, double *w, double *wm)
{
    double s[B], saved[B];
    for (size_t k = 0; k < B; k++) {
        s[k] = 1.0 - t[k];
        w[k] = 1.0;
    }
    for (size_t r = 1; r <= deg; r++) {
        if (r == deg)
            for (size_t x = 0; x < deg * B; x++)
                wm[x] = w[x];
        for (size_t k = 0; k < B; k++)
            saved[k] = 0.0;
        for (size_t i = 0; i < r; i++)
            for (size_t k = 0; k < B; k++) {
                double tmp = w[i * B + k];
                w[i * B + k] = saved[k] + s[k] * tmp;
                saved[k] = t[k] * tmp;
            }
        for (size_t k = 0; k < B; k++)
            w[r * B + k] = saved[k];
    }
}

void bsi_eval_first_block(const bs_patch *p, const double *u, const double *v, int first,
                          double *h, double *hu, double *hv)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    double bu[NMAX * B], bum[NMAX * B], bv[NMAX * B], bvm[NMAX * B];
    block_weights(m, u, bu, bum);
    block_weights(n, v, bv, bvm);
    int du = first && m > 0, dv = first && n > 0;

    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double acc[B], accu[B], accv[B];
        for (size_t k = 0; k < B; k++)
            acc[k] = accu[k] = accv[k] = 0.0;
        /* Per column j: contract u (i ascending) into q, qu, qv held in registers, then add the
         * column's v-weighted share to the results (j ascending). */
        for (size_t j = 0; j <= n; j++) {
            double q[B], qu[B], qv[B];
            for (size_t k = 0; k < B; k++)
                q[k] = qu[k] = qv[k] = 0.0;
            if (!first) {
                for (size_t i = 0; i <= m; i++) {
                    double pij = net[i * n1 + j];
                    const double *wi = bu + i * B;
                    for (size_t k = 0; k < B; k++)
                        q[k] += wi[k] * pij;
                }
            } else {
                /* One pass over the column; each accumulator still sums i ascending. */
                int jv = dv && j < n;
                for (size_t i = 0; i <= m; i++) {
                    double pij = net[i * n1 + j];
                    double dvij = jv ? net[i * n1 + j + 1] - pij : 0.0;
                    double duij = du && i < m ? net[(i + 1) * n1 + j] - pij : 0.0;
                    const double *wi = bu + i * B, *wmi = bum + i * B;
                    for (size_t k = 0; k < B; k++) {
                        q[k] += wi[k] * pij;
                        qv[k] += wi[k] * dvij;
                    }
                    if (du && i < m)
                        for (size_t k = 0; k < B; k++)
                            qu[k] += wmi[k] * duij;
                }
            }
            const double *wj = bv + j * B, *wmj = bvm + j * B;
            for (size_t k = 0; k < B; k++)
                acc[k] += wj[k] * q[k];
            if (du)
                for (size_t k = 0; k < B; k++)
                    accu[k] += wj[k] * qu[k];
            if (dv && j < n)
                for (size_t k = 0; k < B; k++)
                    accv[k] += wmj[k] * qv[k];
        }
        for (size_t k = 0; k < B; k++) {
            h[c * B + k] = acc[k];
            if (first) {
                hu[c * B + k] = du ? (double)m * accu[k] : 0.0;
                hv[c * B + k] = dv ? (double)n * accv[k] : 0.0;
            }
        }
    }
}

void bsi_project_first(const bs_patch *p, const double *h, const double *hu, const double *hv,
                       size_t stride, double *s, double *su, double *sv)
{
    size_t dim = p->dim;
    if (!p->rational) {
        for (size_t c = 0; c < dim; c++) {
            s[c] = h[c * stride];
            if (su != NULL) {
                su[c] = hu[c * stride];
                sv[c] = hv[c * stride];
            }
        }
        return;
    }
    /* S = A / w; S_u = (A_u - w_u S) / w (quotient rule). */
    double w = h[dim * stride];
    for (size_t c = 0; c < dim; c++) {
        s[c] = h[c * stride] / w;
        if (su != NULL) {
            su[c] = (hu[c * stride] - hu[dim * stride] * s[c]) / w;
            sv[c] = (hv[c * stride] - hv[dim * stride] * s[c]) / w;
        }
    }
}

static void put(const bs_view *views, size_t dim, size_t idx, const double *val)
{
    if (views == NULL)
        return;
    for (size_t c = 0; c < dim; c++)
        *bsi_at(&views[c], idx) = val[c];
}

bs_status bs_patch_eval(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                        const bs_view *pos, const bs_view *du, const bs_view *dv)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (n == 0)
        return BS_OK;
    bs_status st;
    size_t dim = p->dim;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK)
        return st;
    if ((pos && (st = bsi_check_views(pos, dim, n)) != BS_OK) ||
        (du && (st = bsi_check_views(du, dim, n)) != BS_OK) ||
        (dv && (st = bsi_check_views(dv, dim, n)) != BS_OK))
        return st;
    int first = du != NULL || dv != NULL;
    double h[(BS_MAX_DIM + 1) * B], hu[(BS_MAX_DIM + 1) * B], hv[(BS_MAX_DIM + 1) * B];
    for (size_t k0 = 0; k0 < n; k0 += B) {
        size_t nb = n - k0 < B ? n - k0 : B;
        double ub[B], vb[B];
        int bad[B];
        for (size_t k = 0; k < B; k++) {
            ub[k] = vb[k] = 0.0;
            bad[k] = 0;
            if (k < nb) {
                ub[k] = bsi_cget(u, k0 + k);
                vb[k] = bsi_cget(v, k0 + k);
                bad[k] = !isfinite(ub[k]) || !isfinite(vb[k]);
                if (bad[k])
                    ub[k] = vb[k] = 0.0;
            }
        }
        bsi_eval_first_block(p, ub, vb, first, h, hu, hv);
        for (size_t k = 0; k < nb; k++) {
            double s[BS_MAX_DIM], su[BS_MAX_DIM], sv[BS_MAX_DIM];
            bsi_project_first(p, h + k, hu + k, hv + k, B, s, first ? su : NULL, sv);
            if (bad[k])
                for (size_t c = 0; c < dim; c++)
                    s[c] = su[c] = sv[c] = NAN;
            put(pos, dim, k0 + k, s);
            put(du, dim, k0 + k, su);
            put(dv, dim, k0 + k, sv);
        }
    }
    return BS_OK;
}
