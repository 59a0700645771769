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

/* block_weights for degree 3 written out: the same operations per lane (same bits). */
BSI_HOT static void weights3(const double *restrict t, double *restrict w, double *restrict wm)
{
    for (size_t k = 0; k < B; k++) {
        double x = t[k], s = 1.0 - x;
        double a0 = 0.0 + s * 1.0, a1 = x * 1.0;
        double b0 = 0.0 + s * a0, b1 = x * a0 + s * a1, b2 = x * a1;
        wm[k] = b0;
        wm[B + k] = b1;
        wm[2 * B + k] = b2;
        w[k] = 0.0 + s * b0;
        w[B + k] = x * b0 + s * b1;
        w[2 * B + k] = x * b1 + s * b2;
        w[3 * B + k] = x * b2;
    }
}

/* Bicubic value only, as the general loop below does it. */
BSI_HOT static void bicubic_value(const double *restrict net, const double *restrict bu,
                          const double *restrict bv, double *restrict h)
{
    for (size_t k = 0; k < B; k++) {
        double u0 = bu[k], u1 = bu[B + k], u2 = bu[2 * B + k], u3 = bu[3 * B + k];
#define Q(j) (u0 * net[j] + u1 * net[4 + (j)] + u2 * net[8 + (j)] + u3 * net[12 + (j)])
        h[k] = bv[k] * Q(0) + bv[B + k] * Q(1) + bv[2 * B + k] * Q(2) + bv[3 * B + k] * Q(3);
#undef Q
    }
}

/* Bicubic value and first partials: the general loop below with every index fixed, so the same
 * operations in the same order per point (same bits), kept in registers and vectorised over the
 * block's points. */
BSI_HOT static void bicubic_first(const double *restrict net, const double *restrict bu,
                          const double *restrict bum, const double *restrict bv,
                          const double *restrict bvm, double *restrict h, double *restrict hu,
                          double *restrict hv)
{
#define P(i, j) net[(i) * 4 + (j)]
#define D(i, j) (P((i) + 1, j) - P(i, j))
#define E(i, j) (P(i, (j) + 1) - P(i, j))
    for (size_t k = 0; k < B; k++) {
        double u0 = bu[k], u1 = bu[B + k], u2 = bu[2 * B + k], u3 = bu[3 * B + k];
        double m0 = bum[k], m1 = bum[B + k], m2 = bum[2 * B + k];
#define Q(j) (u0 * P(0, j) + u1 * P(1, j) + u2 * P(2, j) + u3 * P(3, j))
#define QU(j) (m0 * D(0, j) + m1 * D(1, j) + m2 * D(2, j))
#define QV(j) (u0 * E(0, j) + u1 * E(1, j) + u2 * E(2, j) + u3 * E(3, j))
#define V(j) bv[(j) * B + k]
#define VM(j) bvm[(j) * B + k]
        double acc = V(0) * Q(0) + V(1) * Q(1) + V(2) * Q(2) + V(3) * Q(3);
        double accu = V(0) * QU(0) + V(1) * QU(1) + V(2) * QU(2) + V(3) * QU(3);
        double accv = VM(0) * QV(0) + VM(1) * QV(1) + VM(2) * QV(2);
#undef Q
#undef QU
#undef QV
#undef V
#undef VM
        h[k] = acc;
        hu[k] = 3.0 * accu;
        hv[k] = 3.0 * accv;
    }
#undef P
#undef D
#undef E
}

BSI_HOT void bsi_eval_first_block(const bs_patch *p, const double *u, const double *v, int first,
                          double *h, double *hu, double *hv)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    double bu[NMAX * B], bum[NMAX * B], bv[NMAX * B], bvm[NMAX * B];
    if (m == 3 && n == 3) {
        weights3(u, bu, bum);
        weights3(v, bv, bvm);
        for (size_t c = 0; c < p->ncoord; c++) {
            if (first)
                bicubic_first(p->hom + c * p->nctrl, bu, bum, bv, bvm, h + c * B, hu + c * B, hv + c * B);
            else
                bicubic_value(p->hom + c * p->nctrl, bu, bv, h + c * B);
        }
        return;
    }
    block_weights(m, u, bu, bum);
    block_weights(n, v, bv, bvm);
    int du = first && m > 0, dv = first && n > 0;

    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double acc[B], accu[B], accv[B];
        for (size_t k = 0; k < B; k++)
            acc[k] = accu[k] = accv[k] = -0.0;
        /* Per column j: contract u (i ascending) into q, qu, qv held in registers, then add the
         * column's v-weighted share to the results (j ascending). */
        for (size_t j = 0; j <= n; j++) {
            double q[B], qu[B], qv[B];
            for (size_t k = 0; k < B; k++)
                q[k] = qu[k] = qv[k] = -0.0;
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
    double h[(BS_MAX_DIM + 1) * B], hu[(BS_MAX_DIM + 1) * B], hv[(BS_MAX_DIM + 1) * B];
    for (size_t k0 = 0; k0 < n; k0 += B) {
        size_t nb = n - k0 < B ? n - k0 : B;
        double ub[B], vb[B];
        int bad[B];
        bsi_load_block(u, v, k0, nb, ub, vb, bad);
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
