/* Scattered evaluation of positions and first partial derivatives. */
#include "core/kernels.h"

#include <float.h>
#include <math.h>

#define B BSI_BLOCK
#define NMAX (BS_MAX_DEGREE + 1)

/* bsi_block_weights on lanes 0 .. nl-1 of the block (stride B): in line, so that a whole block
 * (nl = B) vectorises and a single point (nl = 1) computes one lane, with the same operations. */
BSI_INLINE void weights_lanes(size_t deg, const double *t, double *w, double *wm, size_t nl)
{
    double s[B], saved[B];
    for (size_t k = 0; k < nl; k++) {
        s[k] = 1.0 - t[k];
        w[k] = 1.0;
    }
    for (size_t r = 1; r <= deg; r++) {
        if (r == deg)
            for (size_t i = 0; i < deg; i++)
                for (size_t k = 0; k < nl; k++)
                    wm[i * B + k] = w[i * B + k];
        for (size_t k = 0; k < nl; k++)
            saved[k] = 0.0;
        for (size_t i = 0; i < r; i++)
            for (size_t k = 0; k < nl; k++) {
                double tmp = w[i * B + k];
                w[i * B + k] = saved[k] + s[k] * tmp;
                saved[k] = t[k] * tmp;
            }
        for (size_t k = 0; k < nl; k++)
            w[r * B + k] = saved[k];
    }
}

void bsi_block_weights(size_t deg, const double *t, double *w, double *wm)
{
    weights_lanes(deg, t, w, wm, B);
}

/* Points per block of the bicubic paths: the set-up per coordinate is shared by more points. */
#define PB BSI_CHUNK

/* bs_patch_eval of a polynomial bicubic patch whose views are all packed: whole blocks go from
 * the caller's arrays to the caller's arrays in one loop per block, with the per-point
 * arithmetic of bsi_eval_first_block (bsi_bernstein3_first, bsi_bicubic_point: same bits). Non-finite
 * parameters give NaN, as in bs_patch_eval. Returns the points done, a multiple of PB. */
BSI_HOT static size_t bicubic_packed(const bs_patch *p, size_t n, const double *restrict u,
                                     const double *restrict v, double *const *pos,
                                     double *const *du, double *const *dv)
{
    size_t done = n - n % PB;
    int first = du != NULL || dv != NULL;
    for (size_t k0 = 0; k0 < done; k0 += PB) {
        double bu[4][PB], bum[3][PB], bv[4][PB], bvm[3][PB], x[PB], y[PB];
        size_t nbad = 0;
        for (size_t k = 0; k < PB; k++) {
            int ok = (fabs(u[k0 + k]) <= DBL_MAX) & (fabs(v[k0 + k]) <= DBL_MAX);
            nbad += !ok;
            x[k] = ok ? u[k0 + k] : 0.0;
            y[k] = ok ? v[k0 + k] : 0.0;
        }
        bsi_weights3(PB, x, bu[0], bum[0]);
        bsi_weights3(PB, y, bv[0], bvm[0]);
        for (size_t c = 0; c < p->dim; c++) {
            /* straight into the outputs; a result not asked for goes to scratch */
            double th[PB], thu[PB], thv[PB];
            double *h = pos != NULL ? pos[c] + k0 : th;
            double *hu = du != NULL ? du[c] + k0 : thu, *hv = dv != NULL ? dv[c] + k0 : thv;
            bsi_bicubic_block(PB, p->hom + c * p->nctrl, bu[0], bum[0], bv[0], bvm[0], h,
                          first ? hu : NULL, hv);
            for (size_t k = 0; nbad > 0 && k < PB; k++)
                if (!(fabs(u[k0 + k]) <= DBL_MAX) || !(fabs(v[k0 + k]) <= DBL_MAX))
                    h[k] = hu[k] = hv[k] = NAN;
        }
    }
    return done;
}

BSI_HOT void bsi_bicubic_first_chunk(const bs_patch *p, const double *u, const double *v,
                                     double *h, double *hu, double *hv)
{
    double bu[4][PB], bum[3][PB], bv[4][PB], bvm[3][PB];
    bsi_weights3(PB, u, bu[0], bum[0]);
    bsi_weights3(PB, v, bv[0], bvm[0]);
    for (size_t c = 0; c < p->dim; c++)
        bsi_bicubic_block(PB, p->hom + c * p->nctrl, bu[0], bum[0], bv[0], bvm[0], h + c * PB,
                      hu + c * PB, hv + c * PB);
}

/* The general case of bsi_eval_first_block on lanes 0 .. nl-1 (outputs at stride B), in line for
 * the block (nl = B, vectorised) and for one point (nl = 1: an eighth of the arithmetic, the
 * same bits). */
BSI_INLINE void first_lanes(const bs_patch *p, const double *u, const double *v, int first,
                            double *h, double *hu, double *hv, size_t nl)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    double bu[NMAX * B], bum[NMAX * B], bv[NMAX * B], bvm[NMAX * B];
    weights_lanes(m, u, bu, bum, nl);
    weights_lanes(n, v, bv, bvm, nl);
    int du = first && m > 0, dv = first && n > 0;

    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double acc[B], accu[B], accv[B];
        for (size_t k = 0; k < nl; k++)
            acc[k] = accu[k] = accv[k] = -0.0;
        /* Per column j: contract u (i ascending) into q, qu, qv held in registers, then add the
         * column's v-weighted share to the results (j ascending). */
        for (size_t j = 0; j <= n; j++) {
            double q[B], qu[B], qv[B];
            for (size_t k = 0; k < nl; k++)
                q[k] = qu[k] = qv[k] = -0.0;
            if (!first) {
                for (size_t i = 0; i <= m; i++) {
                    double pij = net[i * n1 + j];
                    const double *wi = bu + i * B;
                    for (size_t k = 0; k < nl; k++)
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
                    for (size_t k = 0; k < nl; k++) {
                        q[k] += wi[k] * pij;
                        qv[k] += wi[k] * dvij;
                    }
                    if (du && i < m)
                        for (size_t k = 0; k < nl; k++)
                            qu[k] += wmi[k] * duij;
                }
            }
            const double *wj = bv + j * B, *wmj = bvm + j * B;
            for (size_t k = 0; k < nl; k++)
                acc[k] += wj[k] * q[k];
            if (du)
                for (size_t k = 0; k < nl; k++)
                    accu[k] += wj[k] * qu[k];
            if (dv && j < n)
                for (size_t k = 0; k < nl; k++)
                    accv[k] += wmj[k] * qv[k];
        }
        for (size_t k = 0; k < nl; k++) {
            h[c * B + k] = acc[k];
            if (first) {
                hu[c * B + k] = du ? (double)m * accu[k] : 0.0;
                hv[c * B + k] = dv ? (double)n * accv[k] : 0.0;
            }
        }
    }
}

BSI_HOT void bsi_eval_first_block(const bs_patch *p, const double *u, const double *v, int first,
                          double *h, double *hu, double *hv)
{
    if (p->deg_u == 3 && p->deg_v == 3) {
        double bu[4 * B], bum[4 * B], bv[4 * B], bvm[4 * B];
        bsi_weights3(B, u, bu, bum);
        bsi_weights3(B, v, bv, bvm);
        for (size_t c = 0; c < p->ncoord; c++)
            bsi_bicubic_block(B, p->hom + c * p->nctrl, bu, bum, bv, bvm, h + c * B,
                          first ? hu + c * B : NULL, first ? hv + c * B : NULL);
        return;
    }
    first_lanes(p, u, v, first, h, hu, hv, B);
}

/* bsi_eval_first_block's lane 0 alone (u[0], v[0] finite; outputs at stride B, as the block's):
 * the same bits for a call of one point at an eighth of the cost. */
static void eval_first_lane0(const bs_patch *p, const double *u, const double *v, int first,
                             double *h, double *hu, double *hv)
{
    if (p->deg_u == 3 && p->deg_v == 3) {
        double bu[4], bum[3], bv[4], bvm[3];
        bsi_bernstein3_first(u[0], bu, bum);
        bsi_bernstein3_first(v[0], bv, bvm);
        for (size_t c = 0; c < p->ncoord; c++)
            bsi_bicubic_point(p->hom + c * p->nctrl, bu, bum, bv, bvm, h + c * B,
                              first ? hu + c * B : NULL, hv + c * B);
        return;
    }
    first_lanes(p, u, v, first, h, hu, hv, 1);
}

/* The values alone of eval_first_lane0 (h[c * B]): the operations of first_lanes without the
 * partials, for the callers that evaluate point by point. */
static void values_one(const bs_patch *p, double u, double v, double *h)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    double bu[NMAX * B], bum[NMAX * B], bv[NMAX * B], bvm[NMAX * B];
    if (m == 3 && n == 3) {
        bsi_bernstein3_first(u, bu, bum);
        bsi_bernstein3_first(v, bv, bvm);
        for (size_t c = 0; c < p->ncoord; c++)
            bsi_bicubic_point(p->hom + c * p->nctrl, bu, NULL, bv, NULL, h + c * B, NULL, NULL);
        return;
    }
    weights_lanes(m, &u, bu, bum, 1);
    weights_lanes(n, &v, bv, bvm, 1);
    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double acc = -0.0;
        for (size_t j = 0; j <= n; j++) {
            double q = -0.0;
            for (size_t i = 0; i <= m; i++)
                q += bu[i * B] * net[i * n1 + j];
            acc += bv[j * B] * q;
        }
        h[c * B] = acc;
    }
}

/* bsi_eval_first_block with first != 0 at one finite point: outputs [ncoord], the same bits. */
void bsi_eval_first_one(const bs_patch *p, double u, double v, double *h, double *hu, double *hv)
{
    double hb[(BS_MAX_DIM + 1) * B], hub[(BS_MAX_DIM + 1) * B], hvb[(BS_MAX_DIM + 1) * B];
    eval_first_lane0(p, &u, &v, 1, hb, hub, hvb);
    for (size_t c = 0; c < p->ncoord; c++) {
        h[c] = hb[c * B];
        hu[c] = hub[c * B];
        hv[c] = hvb[c * B];
    }
}

void bsi_eval_point(const bs_patch *p, double u, double v, double *pos)
{
    double h[(BS_MAX_DIM + 1) * B];
    int ok = isfinite(u) && isfinite(v);
    values_one(p, ok ? u : 0.0, ok ? v : 0.0, h);
    bsi_project_first(p, h, NULL, NULL, B, pos, NULL, NULL);
    for (size_t c = 0; !ok && c < p->dim; c++)
        pos[c] = NAN;
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
    /* S = A / w; S_u = (A_u - w_u S) / w (quotient rule). The kernels fill all ncoord = dim + 1
     * planes of a rational patch, which the analyzer cannot see through p->ncoord. */
    double w = h[dim * stride]; // NOLINT(clang-analyzer-core.uninitialized.Assign)
    for (size_t c = 0; c < dim; c++) {
        s[c] = h[c * stride] / w; // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult)
        if (su != NULL) {
            su[c] = (hu[c * stride] - hu[dim * stride] * s[c]) / w;
            sv[c] = (hv[c * stride] - hv[dim * stride] * s[c]) / w;
        }
    }
}

/* Coordinate c of nb results src[c*B + k] to views[c] from element idx0 on (packed views take a
 * plain loop). */
static void put_block(const bs_view *views, size_t dim, size_t idx0, const double *src, size_t nb)
{
    if (views == NULL)
        return;
    for (size_t c = 0; c < dim; c++) {
        const double *x = src + c * B;
        if (bsi_stride(views[c].stride) == (ptrdiff_t)sizeof(double)) {
            double *d = (double *)views[c].data + idx0;
            for (size_t k = 0; k < nb; k++)
                d[k] = x[k];
        } else {
            for (size_t k = 0; k < nb; k++)
                *bsi_at(&views[c], idx0 + k) = x[k];
        }
    }
}

void bsi_load_block(const bs_cview *u, const bs_cview *v, size_t k0, size_t nb,
                    double *ub, double *vb, int *bad)
{
    if (nb == BSI_BLOCK && bsi_stride(u->stride) == (ptrdiff_t)sizeof(double) &&
        bsi_stride(v->stride) == (ptrdiff_t)sizeof(double)) {
        /* a whole block from packed arrays: the same values, without a branch per point */
        const double *x = (const double *)u->data + k0, *y = (const double *)v->data + k0;
        for (size_t k = 0; k < BSI_BLOCK; k++) {
            int ok = (fabs(x[k]) <= DBL_MAX) & (fabs(y[k]) <= DBL_MAX);
            bad[k] = !ok;
            ub[k] = ok ? x[k] : 0.0;
            vb[k] = ok ? y[k] : 0.0;
        }
        return;
    }
    for (size_t k = 0; k < BSI_BLOCK; k++) {
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
    size_t k0 = 0;
    double *ps[BS_MAX_DIM], *pu[BS_MAX_DIM], *pv[BS_MAX_DIM];
    if (!p->rational && p->deg_u == 3 && p->deg_v == 3 &&
        bsi_stride(u->stride) == (ptrdiff_t)sizeof(double) &&
        bsi_stride(v->stride) == (ptrdiff_t)sizeof(double) && (pos == NULL || bsi_packed_views(pos, dim, ps)) &&
        (du == NULL || bsi_packed_views(du, dim, pu)) && (dv == NULL || bsi_packed_views(dv, dim, pv)))
        k0 = bicubic_packed(p, n, u->data, v->data, pos ? ps : NULL, du ? pu : NULL,
                            dv ? pv : NULL);
    double h[(BS_MAX_DIM + 1) * B], hu[(BS_MAX_DIM + 1) * B], hv[(BS_MAX_DIM + 1) * B];
    for (; k0 < n; k0 += B) {
        size_t nb = n - k0 < B ? n - k0 : B;
        double ub[B], vb[B];
        int bad[B];
        bsi_load_block(u, v, k0, nb, ub, vb, bad);
        if (nb == 1 && !first) /* a single point (a call of one, or a tail of one): one lane */
            values_one(p, ub[0], vb[0], h);
        else if (nb == 1)
            eval_first_lane0(p, ub, vb, 1, h, hu, hv);
        else
            bsi_eval_first_block(p, ub, vb, first, h, hu, hv);
        if (p->rational)
            for (size_t k = 0; k < nb; k++) {
                /* in place: S replaces A, S_u and S_v replace A_u and A_v */
                double s[BS_MAX_DIM], su[BS_MAX_DIM], sv[BS_MAX_DIM];
                bsi_project_first(p, h + k, hu + k, hv + k, B, s, first ? su : NULL, sv);
                for (size_t c = 0; c < dim; c++) {
                    h[c * B + k] = s[c];
                    if (first) {
                        hu[c * B + k] = su[c];
                        hv[c * B + k] = sv[c];
                    }
                }
            }
        for (size_t k = 0; k < nb; k++)
            if (bad[k])
                for (size_t c = 0; c < dim; c++)
                    h[c * B + k] = hu[c * B + k] = hv[c * B + k] = NAN;
        put_block(pos, dim, k0, h, nb);
        put_block(du, dim, k0, hu, nb);
        put_block(dv, dim, k0, hv, nb);
    }
    return BS_OK;
}
