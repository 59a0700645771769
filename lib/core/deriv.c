/* Mixed partial derivatives of any order at scattered points. */
#include "core/kernels.h"

#include <math.h>
#include <stdlib.h>

#define B BSI_BLOCK
#define NMAX (BS_MAX_DEGREE + 1)

static size_t min_sz(size_t a, size_t b) { return a < b ? a : b; }

size_t bsi_deriv_table_scratch(const bs_patch *p, unsigned ka, unsigned kb)
{
    size_t ma = min_sz(ka, p->deg_u) + 1, mb = min_sz(kb, p->deg_v) + 1;
    return ma * (p->deg_u + 1) + mb * (p->deg_v + 1) + (p->deg_v + 1) + ma * mb * p->ncoord;
}

void bsi_binomial_row(unsigned k, double *c)
{
    c[0] = 1.0;
    for (unsigned a = 1; a <= k; a++) {
        c[a] = 0.0;
        for (unsigned r = a; r > 0; r--)
            c[r] += c[r - 1];
    }
}

void bsi_deriv_table(const bs_patch *p, double u, double v, unsigned ka, unsigned kb,
                     double *scratch, double *out)
{
    size_t m = p->deg_u, n = p->deg_v, dim = p->dim, nc = p->ncoord;
    size_t ma = min_sz(ka, m), mb = min_sz(kb, n); /* homogeneous partials beyond are zero */
    double *wu = scratch, *wv = wu + (ma + 1) * (m + 1), *q = wv + (mb + 1) * (n + 1);
    double *hd = q + (n + 1); /* hd[(a*(mb+1) + b)*nc + c] */
    for (size_t a = 0; a <= ma; a++)
        bsi_bernstein_deriv(m, (unsigned)a, u, wu + a * (m + 1));
    for (size_t b = 0; b <= mb; b++)
        bsi_bernstein_deriv(n, (unsigned)b, v, wv + b * (n + 1));
    for (size_t c = 0; c < nc; c++) {
        const double *net = p->hom + c * p->nctrl;
        for (size_t a = 0; a <= ma; a++) {
            const double *w = wu + a * (m + 1);
            for (size_t j = 0; j <= n; j++)
                q[j] = -0.0;
            for (size_t i = 0; i <= m; i++)
                for (size_t j = 0; j <= n; j++)
                    q[j] += w[i] * net[i * (n + 1) + j];
            for (size_t b = 0; b <= mb; b++) {
                double acc = -0.0;
                for (size_t j = 0; j <= n; j++)
                    acc += wv[b * (n + 1) + j] * q[j];
                hd[(a * (mb + 1) + b) * nc + c] = acc;
            }
        }
    }
    size_t kb1 = (size_t)kb + 1;
    if (!p->rational) {
        for (size_t a = 0; a <= ka; a++)
            for (size_t b = 0; b <= kb; b++)
                for (size_t c = 0; c < dim; c++)
                    out[(a * kb1 + b) * dim + c] =
                        a <= ma && b <= mb ? hd[(a * (mb + 1) + b) * nc + c] : 0.0;
        return;
    }
    /* Leibniz on A = w S: S^(i,j) = (A^(i,j) - sum_{(a,b) != 0} C(i,a) C(j,b) w^(a,b) S^(i-a,j-b)) / w. */
    double w0 = hd[dim];
    double ci[NMAX], cj[NMAX];
    for (size_t i = 0; i <= ka; i++) {
        bsi_binomial_row((unsigned)i, ci);
        for (size_t j = 0; j <= kb; j++) {
            bsi_binomial_row((unsigned)j, cj);
            for (size_t c = 0; c < dim; c++) {
                double acc = i <= ma && j <= mb ? hd[(i * (mb + 1) + j) * nc + c] : 0.0;
                for (size_t a = 0; a <= min_sz(i, ma); a++)
                    for (size_t b = 0; b <= min_sz(j, mb); b++)
                        if (a || b)
                            acc -= ci[a] * cj[b] * hd[(a * (mb + 1) + b) * nc + dim] *
                                   out[((i - a) * kb1 + (j - b)) * dim + c];
                out[(i * kb1 + j) * dim + c] = acc / w0;
            }
        }
    }
}

/* Polynomial patches: one order, BSI_BLOCK points at a time, point-innermost loops. */
static void poly_block(const bs_patch *p, unsigned ku, unsigned kv, const double *u, const double *v,
                       double *res /* [dim][B] */)
{
    size_t m = p->deg_u, n = p->deg_v;
    double wu[NMAX * B], wv[NMAX * B], q[NMAX * B], b[NMAX];
    for (size_t k = 0; k < B; k++) {
        bsi_bernstein_deriv(m, ku, u[k], b);
        for (size_t i = 0; i <= m; i++)
            wu[i * B + k] = b[i];
        bsi_bernstein_deriv(n, kv, v[k], b);
        for (size_t j = 0; j <= n; j++)
            wv[j * B + k] = b[j];
    }
    for (size_t c = 0; c < p->dim; c++) {
        const double *net = p->hom + c * p->nctrl;
        for (size_t x = 0; x < (n + 1) * B; x++)
            q[x] = -0.0;
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                double pij = net[i * (n + 1) + j];
                for (size_t k = 0; k < B; k++)
                    q[j * B + k] += wu[i * B + k] * pij;
            }
        double acc[B];
        for (size_t k = 0; k < B; k++)
            acc[k] = -0.0;
        for (size_t j = 0; j <= n; j++)
            for (size_t k = 0; k < B; k++)
                acc[k] += wv[j * B + k] * q[j * B + k];
        for (size_t k = 0; k < B; k++)
            res[c * B + k] = acc[k];
    }
}

bs_status bs_patch_eval_deriv(const bs_patch *p, unsigned ku, unsigned kv, size_t n,
                              const bs_cview *u, const bs_cview *v, const bs_view *out)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (ku > BS_MAX_DEGREE || kv > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (n == 0)
        return BS_OK;
    bs_status st;
    size_t dim = p->dim;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK)
        return st;
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    if ((st = bsi_check_views(out, dim, n)) != BS_OK)
        return st;

    double *scratch = NULL, *table = NULL;
    size_t tsize = ((size_t)ku + 1) * ((size_t)kv + 1) * dim;
    if (p->rational) {
        scratch = malloc((bsi_deriv_table_scratch(p, ku, kv) + tsize) * sizeof(double));
        if (scratch == NULL)
            return BS_ERR_NO_MEMORY;
        table = scratch + bsi_deriv_table_scratch(p, ku, kv);
    }
    double res[BS_MAX_DIM * B];
    for (size_t k0 = 0; k0 < n; k0 += B) {
        size_t nb = n - k0 < B ? n - k0 : B;
        double ub[B], vb[B];
        int bad[B];
        bsi_load_block(u, v, k0, nb, ub, vb, bad);
        if (!p->rational) {
            poly_block(p, ku, kv, ub, vb, res);
        } else {
            for (size_t k = 0; k < nb; k++) {
                bsi_deriv_table(p, ub[k], vb[k], ku, kv, scratch, table);
                for (size_t c = 0; c < dim; c++)
                    res[c * B + k] = table[tsize - dim + c];
            }
        }
        for (size_t k = 0; k < nb; k++)
            for (size_t c = 0; c < dim; c++)
                *bsi_at(&out[c], k0 + k) = bad[k] ? NAN : res[c * B + k];
    }
    free(scratch);
    return BS_OK;
}
