/*
 * Tessellation phases 1 and 2: the rate of each patch under a tolerance, and the plan that samples
 * each side into slots, merges the slots of shared sides and poles and numbers the vertices.
 */
#include "mesh/tess.h"

#include <math.h>
#include <stdlib.h>

/* Second-difference bounds of the net: |S_uu| <= muu, |S_uv| <= muv, |S_vv| <= mvv everywhere,
 * in units of 1/sig (the net times sig, a power of two: exact). */
static void curvature_bounds(const bs_patch *p, double sig, double *muu, double *muv, double *mvv)
{
    size_t m = p->deg_u, n = p->deg_v, dim = p->dim;
    const double *P = p->ctrl;
    double a = 0.0, b = 0.0, c = 0.0;
#define AT(i, j, k) (P[((i) * (n + 1) + (j)) * dim + (k)] * sig)
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            double s2 = 0.0, t2 = 0.0, x2 = 0.0;
            for (size_t k = 0; k < dim; k++) {
                if (i + 2 <= m) {
                    double d = AT(i + 2, j, k) - 2.0 * AT(i + 1, j, k) + AT(i, j, k);
                    s2 += d * d;
                }
                if (j + 2 <= n) {
                    double d = AT(i, j + 2, k) - 2.0 * AT(i, j + 1, k) + AT(i, j, k);
                    t2 += d * d;
                }
                if (i + 1 <= m && j + 1 <= n) {
                    double d = AT(i + 1, j + 1, k) - AT(i + 1, j, k) - AT(i, j + 1, k) + AT(i, j, k);
                    x2 += d * d;
                }
            }
            a = fmax(a, sqrt(s2));
            c = fmax(c, sqrt(t2));
            b = fmax(b, sqrt(x2));
        }
#undef AT
    double scale = 1.0;
    if (p->rational) {
        double wlo = p->weights[0], whi = p->weights[0];
        for (size_t k = 1; k < p->nctrl; k++) {
            wlo = fmin(wlo, p->weights[k]);
            whi = fmax(whi, p->weights[k]);
        }
        scale = whi / wlo;
    }
    *muu = scale * (double)(m * (m ? m - 1 : 0)) * a;
    *muv = scale * (double)(m * n) * b;
    *mvv = scale * (double)(n * (n ? n - 1 : 0)) * c;
}

/* Segments needed along one direction; the 1.5 covers the stretch of stitched triangles. */
static size_t rate_for(double mdir, double mmix, double tol)
{
    double r = ceil(1.5 * sqrt((mdir + mmix) / (4.0 * tol)));
    if (!(r >= 1.0))
        return 1;
    return r >= (double)BS_TESS_MAX_RATE ? BS_TESS_MAX_RATE : (size_t)r;
}

double bsi_tess_max_abs_coord(const bs_surface *s)
{
    double mx = 0.0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        for (size_t k = 0; k < p->nctrl * p->dim; k++)
            mx = fmax(mx, fabs(p->ctrl[k]));
    }
    return mx;
}

void bsi_tess_adaptive_rates(const bs_patch *p, double tol, size_t *ru, size_t *rv)
{
    /* The rates depend on the ratio of the second differences to the tolerance only: for nets
     * beyond 2^256 or below 2^-256 both are taken times a power of two that brings the net near
     * 1, so that the squares of the differences neither overflow nor underflow (a box at 1e308
     * got one segment a side, 290 times over its tolerance); 1 in the usual range. */
    double big = 0.0, sig = 1.0, muu, muv, mvv;
    for (size_t k = 0; k < p->nctrl * p->dim; k++)
        big = fmax(big, fabs(p->ctrl[k]));
    if (big > 0.0 && (big < 0x1p-256 || big > 0x1p256)) {
        int e = 0;
        (void)frexp(big, &e);
        sig = ldexp(1.0, -e);
    }
    curvature_bounds(p, sig, &muu, &muv, &mvv);
    *ru = rate_for(muu, muv, tol * sig);
    *rv = rate_for(mvv, muv, tol * sig);
}

/* Topology, side counts (the larger rate of a shared side), grids and slot numbering. */
bs_status bsi_tess_layout(tess *t)
{
    size_t np = t->np;
    bs_status st = bsi_topology_build(t->s, 1e-9 * bsi_tess_max_abs_coord(t->s), &t->topo);
    if (st != BS_OK)
        return st;
    size_t nslot = 0;
    for (size_t p = 0; p < np; p++) {
        patch_plan *pl = &t->plan[p];
        for (int s = 0; s < 4; s++) {
            const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
            size_t own = (s == BSI_SIDE_V0 || s == BSI_SIDE_V1) ? pl->ru : pl->rv;
            if (l->patch != BSI_NO_PATCH) {
                const patch_plan *q = &t->plan[l->patch];
                size_t other = (l->side == BSI_SIDE_V0 || l->side == BSI_SIDE_V1) ? q->ru : q->rv;
                own = own > other ? own : other;
            }
            pl->e[s] = own;
        }
        pl->regular = pl->e[BSI_SIDE_V0] == pl->ru && pl->e[BSI_SIDE_V1] == pl->ru &&
                      pl->e[BSI_SIDE_U0] == pl->rv && pl->e[BSI_SIDE_U1] == pl->rv;
        pl->gu = pl->regular || pl->ru >= 2 ? pl->ru : 2;
        pl->gv = pl->regular || pl->rv >= 2 ? pl->rv : 2;
        pl->slot0 = nslot;
        size_t off = 4;
        for (int s = 0; s < 4; s++) {
            pl->side_off[s] = off;
            off += pl->e[s] - 1;
        }
        nslot += off;
    }
    t->nslot = nslot;
    return BS_OK;
}

/* Slots, union-find merges, vertex ids. */
bs_status bsi_tess_plan(tess *t)
{
    size_t np = t->np, nslot = t->nslot;
    /* at least one element: malloc(0) may return NULL, which is not a failure */
    t->parent = malloc((nslot ? nslot : 1) * sizeof(size_t));
    t->slot_vert = malloc((nslot ? nslot : 1) * sizeof(uint32_t));
    if (t->parent == NULL || t->slot_vert == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < nslot; k++)
        t->parent[k] = k;
    for (size_t p = 0; p < np; p++) {
        const patch_plan *pl = &t->plan[p];
        for (int s = 0; s < 4; s++) {
            const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
            size_t e = pl->e[s];
            if (l->collapsed)
                for (size_t k = 1; k <= e; k++)
                    uf_union(t->parent, side_slot(pl, s, 0), side_slot(pl, s, k));
            if (l->patch == BSI_NO_PATCH)
                continue;
            const patch_plan *q = &t->plan[l->patch];
            for (size_t k = 0; k <= e; k++)
                uf_union(t->parent, side_slot(pl, s, k), side_slot(q, l->side, l->reversed ? e - k : k));
        }
    }
    /* Vertex ids: per patch, its root slots, then its interior grid points. */
    size_t nvert = 0;
    for (size_t p = 0; p < np; p++) {
        patch_plan *pl = &t->plan[p];
        size_t end = p + 1 < np ? t->plan[p + 1].slot0 : nslot;
        pl->vert0 = nvert;
        for (size_t k = pl->slot0; k < end; k++)
            if (uf_find(t->parent, k) == k)
                t->slot_vert[k] = (uint32_t)nvert++;
        pl->inner0 = nvert;
        size_t gi = pl->gu - 1, gj = pl->gv - 1;
        if (gj != 0 && gi > (SIZE_MAX - nvert) / gj)
            return BS_ERR_SIZE;
        nvert += gi * gj;
        if (nvert > UINT32_MAX - 1)
            return BS_ERR_SIZE;
    }
    t->nvert = nvert;
    return BS_OK;
}
