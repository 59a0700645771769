/*
 * Curvature of a patch (bezsurf/query.h): the shape operator in an orthonormal tangent frame,
 * whose eigenvalues are the principal curvatures, by blocks of points; limit points are handed to
 * curvature_limit.c.
 */
#include "query/internal.h"

#include <math.h>
#include <stdlib.h>

void bsi_curv_regular(const bsi_partials *q, double inv_d, bsi_curv *out)
{
    const double *su = q->d[0], *sv = q->d[1], *nrm = q->nrm;
    double e = bsi_dot3(su, su), f = bsi_dot3(su, sv), cr[3];
    bsi_cross3(su, sv, cr);
    double w = bsi_dot3(cr, cr), rw = sqrt(w), ru = sqrt(e);
    double l = bsi_dot3(q->d[2], nrm), m = bsi_dot3(q->d[3], nrm), nn = bsi_dot3(q->d[4], nrm);
    /* The shape operator in the frame e1 = S_u/|S_u|, e2 = N x e1 (a symmetric matrix [a b; b c]):
     * no cancellation between the principal curvatures, unlike H +- sqrt(H^2 - K). */
    double a = l / e, b = (m * e - f * l) / (e * rw), c = (f * f * l / e - 2.0 * f * m + e * nn) / w;
    double mean = 0.5 * (a + c), s = hypot(0.5 * (a - c), b);
    out->k[0] = a * c - b * b;
    out->k[1] = mean;
    out->k[2] = mean - s;
    out->k[3] = mean + s;
    double e1[3] = {su[0] / ru, su[1] / ru, su[2] / ru}, e2[3];
    bsi_cross3(nrm, e1, e2);
    double scale = fabs(out->k[2]) + fabs(out->k[3]) + inv_d;
    if (2.0 * s <= 1e-10 * scale) { /* umbilic or planar: (dmin, dmax, N) = (e1, e2, N) */
        for (int i = 0; i < 3; i++) {
            out->dmin[i] = e1[i];
            out->dmax[i] = e2[i];
        }
        return;
    }
    /* The eigenvector of k_max, (k_max - c, b) or (b, k_max - a), whichever row of
     * [a - k_max, b; b, c - k_max] leaves the larger first entry (no cancellation, no trig). */
    double half = 0.5 * (a - c), x = a >= c ? half + s : b, y = a >= c ? b : s - half;
    double len = hypot(x, y), ct = x / len, st = y / len;
    for (int i = 0; i < 3; i++) { /* dmin x dmax = N, as e1 x e2 = N */
        out->dmax[i] = ct * e1[i] + st * e2[i];
        out->dmin[i] = st * e1[i] - ct * e2[i];
    }
}

void bsi_curv_partials(const bs_patch *p, const bsi_curv_nets *nets, size_t n, const double *u,
                       const double *v, double *scratch, bsi_partials *q, unsigned char *kind)
{
    static const unsigned ab[5][2] = {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    bs_cview cu = {u, n, 0}, cv = {v, n, 0};
    bs_view views[6][3]; /* S_u, S_v, S_uu, S_uv, S_vv, N, each through q's fields */
    for (int j = 0; j < 6; j++)
        for (int c = 0; c < 3; c++) {
            views[j][c].data = j < 5 ? &q[0].d[j][c] : &q[0].nrm[c];
            views[j][c].count = n;
            views[j][c].stride = (ptrdiff_t)sizeof(bsi_partials);
        }
    if (!p->rational) {
        /* the block evaluators (which allocate nothing for polynomial patches); second
         * derivatives as the points of their own patches when the caller made them */
        (void)bs_patch_eval(p, n, &cu, &cv, NULL, views[0], views[1]);
        for (int j = 2; j < 5; j++)
            if (nets != NULL && nets->d2[j - 2] != NULL)
                (void)bs_patch_eval(nets->d2[j - 2], n, &cu, &cv, views[j], NULL, NULL);
            else
                (void)bs_patch_eval_deriv(p, ab[j][0], ab[j][1], n, &cu, &cv, views[j]);
    } else {
        double *table = scratch + bsi_deriv_table_scratch(p, 2, 2); /* S^(a,b), a, b <= 2 */
        for (size_t k = 0; k < n; k++) {
            bsi_deriv_table(p, u[k], v[k], 2, 2, scratch, table);
            for (int j = 0; j < 5; j++)
                for (int c = 0; c < 3; c++)
                    q[k].d[j][c] = table[(ab[j][0] * 3 + ab[j][1]) * 3 + (unsigned)c];
        }
    }
    /* The normal and its kind as bs_patch_eval_normal gives them (the sign convention). Every
     * view was made here from valid memory: these calls cannot fail. */
    (void)bs_patch_eval_normal(p, n, &cu, &cv, NULL, views[5], kind);
}

/* Diagonal of the bounding box of the control points. */
static double net_diagonal(const bs_patch *p)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < p->nctrl; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], p->ctrl[3 * k + (size_t)c]);
            hi[c] = fmax(hi[c], p->ctrl[3 * k + (size_t)c]);
        }
    return hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
}

/* Outputs of point k: the curvature, or NaN everywhere. */
static void put(const bs_view *curv, const bs_view *dmin, const bs_view *dmax, size_t k,
                const bsi_curv *c, int defined)
{
    for (int i = 0; i < 4 && curv; i++)
        *bsi_at(&curv[i], k) = defined ? c->k[i] : NAN;
    for (int i = 0; i < 3 && dmin; i++)
        *bsi_at(&dmin[i], k) = defined ? c->dmin[i] : NAN;
    for (int i = 0; i < 3 && dmax; i++)
        *bsi_at(&dmax[i], k) = defined ? c->dmax[i] : NAN;
}

bs_status bs_patch_eval_curvature(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                                  const bs_view *curv, const bs_view *dmin, const bs_view *dmax,
                                  unsigned char *kind)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (p->dim != 3)
        return BS_ERR_DIMENSION;
    if (n == 0)
        return BS_OK;
    bs_status st;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK ||
        (curv && (st = bsi_check_views(curv, 4, n)) != BS_OK) ||
        (dmin && (st = bsi_check_views(dmin, 3, n)) != BS_OK) ||
        (dmax && (st = bsi_check_views(dmax, 3, n)) != BS_OK))
        return st;
    /* the one allocation, before anything is written */
    double *scratch = malloc((bsi_deriv_table_scratch(p, 2, 2) + 27) * sizeof(double));
    bsi_curv_nets nets = {{NULL, NULL, NULL}};
    int nets_ok = scratch != NULL;
    for (int j = 0; j < 3 && nets_ok && !p->rational; j++) /* S_uu, S_uv, S_vv */
        nets_ok = bs_patch_derivative(p, (unsigned)(2 - j), (unsigned)j, &nets.d2[j]) == BS_OK;
    if (!nets_ok) {
        free(scratch);
        for (int j = 0; j < 3; j++)
            bs_patch_destroy(nets.d2[j]);
        return BS_ERR_NO_MEMORY;
    }
    double inv_d = 1.0 / net_diagonal(p);
    enum { B = 32 };
    for (size_t k0 = 0; k0 < n; k0 += B) {
        size_t nb = n - k0 < B ? n - k0 : B, nf = 0;
        double ub[B], vb[B];
        size_t at[B];
        for (size_t k = 0; k < nb; k++) {
            double x = bsi_cget(u, k0 + k), y = bsi_cget(v, k0 + k);
            if (isfinite(x) && isfinite(y)) {
                ub[nf] = x;
                vb[nf] = y;
                at[nf++] = k0 + k;
            } else {
                put(curv, dmin, dmax, k0 + k, NULL, 0);
                if (kind)
                    kind[k0 + k] = BS_CURV_UNDEFINED;
            }
        }
        bsi_partials q[B];
        unsigned char nk[B];
        bsi_curv_partials(p, p->rational ? NULL : &nets, nf, ub, vb, scratch, q, nk);
        for (size_t k = 0; k < nf; k++) {
            bsi_curv c;
            unsigned char ck = BS_CURV_UNDEFINED;
            if (nk[k] == BS_NORMAL_REGULAR) {
                bsi_curv_regular(&q[k], inv_d, &c);
                ck = BS_CURV_REGULAR;
            } else if (nk[k] == BS_NORMAL_LIMIT) {
                ck = bsi_curv_limit(p, ub[k], vb[k], q[k].nrm, inv_d, scratch, &c);
            }
            put(curv, dmin, dmax, at[k], &c, ck != BS_CURV_UNDEFINED);
            if (kind)
                kind[at[k]] = ck;
        }
    }
    free(scratch);
    for (int j = 0; j < 3; j++)
        bs_patch_destroy(nets.d2[j]);
    return BS_OK;
}
