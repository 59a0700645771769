/* Tensor-grid evaluation: Bernstein weights once per grid column and row, the u-direction
 * contracted once per row, then combined with each column's weights. The arithmetic per point is
 * exactly that of bsi_eval_first_block, so grid and scattered results are bit-identical. */
#include "internal.h"

#include <math.h>
#include <stdlib.h>

#define NMAX (BS_MAX_DEGREE + 1)
/* Columns handled per pass; bounds the scratch space whatever nv is. */
#define COLS 256

typedef struct grid_scratch {
    double *wv, *wvm;      /* [j][COLS] column weights, degree n and n-1 */
    double *q, *qu, *qv;   /* [c][j] the row contracted along u */
    double *h, *hu, *hv;   /* [c][COLS] homogeneous results of one pass */
    unsigned char *badv;   /* [COLS] non-finite v */
} grid_scratch;

/* Contract the u-direction for one row, as bsi_eval_first_block does per column j. */
static void contract_row(const bs_patch *p, const double *bu, const double *bum, int du, int dv,
                         double *q, double *qu, double *qv)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double *qc = q + c * n1, *quc = qu + c * n1, *qvc = qv + c * n1;
        for (size_t j = 0; j < n1; j++)
            qc[j] = quc[j] = qvc[j] = 0.0;
        for (size_t i = 0; i <= m; i++) {
            const double *row = net + i * n1;
            double w = bu[i];
            for (size_t j = 0; j < n1; j++)
                qc[j] += w * row[j];
            if (du && i < m) {
                double wm = bum[i];
                for (size_t j = 0; j < n1; j++)
                    quc[j] += wm * (row[j + n1] - row[j]);
            }
            if (dv)
                for (size_t j = 0; j < n; j++)
                    qvc[j] += w * (row[j + 1] - row[j]);
        }
    }
}

/* Combine a contracted row with the weights of nb columns, j ascending per point. */
static void combine_row(const bs_patch *p, const grid_scratch *g, size_t nb, int du, int dv)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    for (size_t c = 0; c < p->ncoord; c++) {
        double *h = g->h + c * COLS, *hu = g->hu + c * COLS, *hv = g->hv + c * COLS;
        for (size_t b = 0; b < nb; b++)
            h[b] = hu[b] = hv[b] = 0.0;
        for (size_t j = 0; j < n1; j++) {
            const double *w = g->wv + j * COLS, *wm = g->wvm + j * COLS;
            double qj = g->q[c * n1 + j];
            for (size_t b = 0; b < nb; b++)
                h[b] += w[b] * qj;
            if (du) {
                double quj = g->qu[c * n1 + j];
                for (size_t b = 0; b < nb; b++)
                    hu[b] += w[b] * quj;
            }
            if (dv && j < n) {
                double qvj = g->qv[c * n1 + j];
                for (size_t b = 0; b < nb; b++)
                    hv[b] += wm[b] * qvj;
            }
        }
        for (size_t b = 0; b < nb; b++) {
            hu[b] = du ? (double)m * hu[b] : 0.0;
            hv[b] = dv ? (double)n * hv[b] : 0.0;
        }
    }
}

static bs_status check_grid(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                            const bs_cview *v, const bs_view *pos, const bs_view *du,
                            const bs_view *dv, const bs_view *nrm, size_t *total)
{
    bs_status st;
    size_t dim = p->dim;
    if ((st = bsi_check_cview(u, nu)) != BS_OK || (st = bsi_check_cview(v, nv)) != BS_OK)
        return st;
    if (nu > SIZE_MAX / nv)
        return BS_ERR_SIZE;
    *total = nu * nv;
    if ((pos && (st = bsi_check_views(pos, dim, *total)) != BS_OK) ||
        (du && (st = bsi_check_views(du, dim, *total)) != BS_OK) ||
        (dv && (st = bsi_check_views(dv, dim, *total)) != BS_OK) ||
        (nrm && (st = bsi_check_views(nrm, 3, *total)) != BS_OK))
        return st;
    return BS_OK;
}

bs_status bs_patch_eval_grid(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                             const bs_cview *v, const bs_view *pos, const bs_view *du,
                             const bs_view *dv, const bs_view *nrm, unsigned char *kind)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if ((nrm != NULL || kind != NULL) && p->dim != 3)
        return BS_ERR_DIMENSION;
    if (nu == 0 || nv == 0)
        return BS_OK;
    size_t total;
    bs_status st = check_grid(p, nu, u, nv, v, pos, du, dv, nrm, &total);
    if (st != BS_OK)
        return st;

    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1, nc = p->ncoord, dim = p->dim;
    int normals = nrm != NULL || kind != NULL;
    int first = du != NULL || dv != NULL || normals;
    int wdu = first && m > 0, wdv = first && n > 0;
    size_t ndouble = 2 * n1 * COLS + 3 * nc * n1 + 3 * nc * COLS;
    grid_scratch g;
    double *mem = malloc(ndouble * sizeof(double) + COLS);
    if (mem == NULL)
        return BS_ERR_NO_MEMORY;
    g.wv = mem;
    g.wvm = g.wv + n1 * COLS;
    g.q = g.wvm + n1 * COLS;
    g.qu = g.q + nc * n1;
    g.qv = g.qu + nc * n1;
    g.h = g.qv + nc * n1;
    g.hu = g.h + nc * COLS;
    g.hv = g.hu + nc * COLS;
    g.badv = (unsigned char *)(g.hv + nc * COLS);

    bsi_nscale sc;
    if (normals)
        bsi_normal_scale(p, &sc);
    for (size_t b0 = 0; b0 < nv; b0 += COLS) {
        size_t nb = nv - b0 < COLS ? nv - b0 : COLS;
        for (size_t b = 0; b < nb; b++) {
            double t = bsi_cget(v, b0 + b), w[NMAX], wm[NMAX];
            g.badv[b] = (unsigned char)!isfinite(t);
            bsi_bernstein_first(n, g.badv[b] ? 0.0 : t, w, wm);
            for (size_t j = 0; j <= n; j++)
                g.wv[j * COLS + b] = w[j];
            for (size_t j = 0; j < n; j++)
                g.wvm[j * COLS + b] = wm[j];
        }
        for (size_t a = 0; a < nu; a++) {
            double t = bsi_cget(u, a), bu[NMAX], bum[NMAX];
            int badu = !isfinite(t);
            bsi_bernstein_first(m, badu ? 0.0 : t, bu, bum);
            contract_row(p, bu, bum, wdu, wdv, g.q, g.qu, g.qv);
            combine_row(p, &g, nb, wdu, wdv);
            for (size_t b = 0; b < nb; b++) {
                size_t idx = a * nv + b0 + b;
                double s[BS_MAX_DIM], su[BS_MAX_DIM], sv[BS_MAX_DIM], nv3[3];
                unsigned char kd = BS_NORMAL_UNDEFINED;
                bsi_project_first(p, g.h + b, g.hu + b, g.hv + b, COLS, s, first ? su : NULL, sv);
                int bad = badu || g.badv[b];
                if (bad) {
                    for (size_t c = 0; c < dim; c++)
                        s[c] = su[c] = sv[c] = NAN;
                    nv3[0] = nv3[1] = nv3[2] = NAN;
                } else if (normals) {
                    kd = bsi_normal(p, &sc, t, bsi_cget(v, b0 + b), su, sv, nv3);
                }
                for (size_t c = 0; c < dim; c++) {
                    if (pos)
                        *bsi_at(&pos[c], idx) = s[c];
                    if (du)
                        *bsi_at(&du[c], idx) = su[c];
                    if (dv)
                        *bsi_at(&dv[c], idx) = sv[c];
                }
                if (nrm)
                    for (size_t c = 0; c < 3; c++)
                        *bsi_at(&nrm[c], idx) = nv3[c];
                if (kind)
                    kind[idx] = kd;
            }
        }
    }
    free(mem);
    return BS_OK;
}
