/*
 * Constraints of the triangulation (cdt.h): a segment made an edge by removing the triangles it
 * crosses and triangulating again the two polygons on its sides (Anglada 1997: for a base edge,
 * the polygon's vertex whose circle holds no other).
 */
#include "model/cdt_internal.h"

#include <stdlib.h>
#include <string.h>

/* Set the constraint flag on edge a-b (an edge of triangle t) from both sides. */
static void fix_edge(bsi_cdt *c, uint32_t t, uint32_t a, uint32_t b)
{
    bsi_cdt_tri *T = &c->t[t];
    for (int i = 0; i < 3; i++) {
        uint32_t x = T->v[NEXT(i)], y = T->v[PREV(i)];
        if ((x == a && y == b) || (x == b && y == a)) {
            T->fixed[i] = 1;
            uint32_t n = T->nb[i];
            if (n != BSI_CDT_NONE) {
                bsi_cdt_tri *N = &c->t[n];
                for (int j = 0; j < 3; j++)
                    if (N->v[j] != a && N->v[j] != b)
                        N->fixed[j] = 1;
            }
        }
    }
}

/* Triangulate the pseudo-polygon a, b, chain (chain to the left of a->b, in order from a to b)
 * into c->fresh. */
static bs_status fill_polygon(bsi_cdt *c, uint32_t a, uint32_t b, const uint32_t *chain, size_t k)
{
    if (k == 0)
        return BS_OK;
    size_t ci = 0;
    for (size_t j = 1; j < k; j++)
        if (bsi_cdt_incircle(c, a, b, chain[ci], c->q + 2 * (size_t)chain[j]) > 0.0L)
            ci = j;
    uint32_t t;
    bs_status st = bsi_cdt_new_tri(c, &t);
    if (st != BS_OK)
        return st;
    if (!bsi_grow_array((void **)&c->fresh, &c->fresh_cap, c->nfresh + 1, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    bsi_cdt_tri *T = &c->t[t];
    T->v[0] = a;
    T->v[1] = b;
    T->v[2] = chain[ci];
    c->fresh[c->nfresh++] = t;
    st = fill_polygon(c, a, chain[ci], chain, ci);
    if (st == BS_OK)
        st = fill_polygon(c, chain[ci], b, chain + ci + 1, k - ci - 1);
    return st;
}

bs_status bsi_cdt_force(bsi_cdt *c, uint32_t a, uint32_t b)
{
    if (a == b)
        return BS_OK;
    const int64_t *qa = c->q + 2 * (size_t)a, *qb = c->q + 2 * (size_t)b;
    /* the triangle of a's fan that the segment leaves a through */
    uint32_t t = c->vtri[a];
    size_t guard = c->nt + 8;
    uint32_t lo = BSI_CDT_NONE, hi = BSI_CDT_NONE;
    for (;;) {
        if (guard-- == 0 || t == BSI_CDT_NONE)
            return BS_ERR_DOMAIN;
        const bsi_cdt_tri *T = &c->t[t];
        int i = bsi_cdt_slot_of(T, a);
        if (i == 3)
            return BS_ERR_DOMAIN;
        uint32_t cv = T->v[NEXT(i)], dv = T->v[PREV(i)];
        if (cv == b || dv == b) {
            fix_edge(c, t, a, b);
            return BS_OK;
        }
        int oc = bsi_cdt_orient3(c, a, cv, b), od = bsi_cdt_orient3(c, a, dv, b);
        for (int s = 0; s < 2; s++) {
            uint32_t w = s ? dv : cv;
            const int64_t *qw = c->q + 2 * (size_t)w;
            if ((s ? od : oc) == 0 && w > 2 &&
                (qw[0] - qa[0]) * (qb[0] - qa[0]) + (qw[1] - qa[1]) * (qb[1] - qa[1]) > 0) {
                bs_status st = bsi_cdt_force(c, a, w);
                return st != BS_OK ? st : bsi_cdt_force(c, w, b);
            }
        }
        if (oc > 0 && od < 0) {
            lo = cv;
            hi = dv;
            break;
        }
        t = T->nb[NEXT(i)]; /* across a-d: the next triangle counter-clockwise around a */
    }
    /* walk along the segment, collecting the crossed triangles and the chains on both sides */
    size_t need = 2 * (c->nt + 2);
    if (!bsi_grow_array((void **)&c->chain, &c->chain_cap, need, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    uint32_t *upper = c->chain, *lower = c->chain + c->nt + 2;
    size_t nup = 0, nlow = 0;
    lower[nlow++] = lo;
    upper[nup++] = hi;
    bsi_cdt_next_stamp(c);
    c->ncav = 0;
    if (!bsi_cdt_push_cav(c, t))
        return BS_ERR_NO_MEMORY;
    for (;;) {
        const bsi_cdt_tri *T = &c->t[t];
        int i = 3;
        for (int j = 0; j < 3; j++)
            if (T->v[j] != lo && T->v[j] != hi)
                i = j;
        if (i == 3 || T->fixed[i] || T->nb[i] == BSI_CDT_NONE)
            return BS_ERR_DOMAIN; /* crosses a constraint */
        uint32_t n = T->nb[i];
        const bsi_cdt_tri *N = &c->t[n];
        uint32_t e = BSI_CDT_NONE;
        for (int j = 0; j < 3; j++)
            if (N->v[j] != lo && N->v[j] != hi)
                e = N->v[j];
        if (e == BSI_CDT_NONE || c->ncav > c->nt)
            return BS_ERR_DOMAIN;
        if (!bsi_cdt_push_cav(c, n))
            return BS_ERR_NO_MEMORY;
        if (e == b)
            break;
        int o = bsi_cdt_orient3(c, a, b, e);
        if (o == 0) {
            for (size_t k = 0; k < c->ncav; k++)
                c->t[c->cav[k]].mark = 0;
            bs_status st = bsi_cdt_force(c, a, e);
            return st != BS_OK ? st : bsi_cdt_force(c, e, b);
        }
        if (o > 0)
            upper[nup++] = hi = e;
        else
            lower[nlow++] = lo = e;
        t = n;
    }
    if (!bsi_cdt_collect_boundary(c))
        return BS_ERR_NO_MEMORY;
    unsigned char inside = c->t[c->cav[0]].inside;
    for (size_t k = 0; k < c->ncav; k++) {
        bs_status st = bsi_cdt_retire(c, c->cav[k]);
        if (st != BS_OK)
            return st;
    }
    /* the lower chain, from b back to a, lies to the left of b->a */
    for (size_t k = 0; k < nlow / 2; k++) {
        uint32_t s = lower[k];
        lower[k] = lower[nlow - 1 - k];
        lower[nlow - 1 - k] = s;
    }
    c->nfresh = 0;
    bs_status st = fill_polygon(c, a, b, upper, nup);
    if (st == BS_OK)
        st = fill_polygon(c, b, a, lower, nlow);
    if (st != BS_OK)
        return st;
    for (size_t k = 0; k < c->nfresh; k++) {
        bsi_cdt_tri *T = &c->t[c->fresh[k]];
        T->inside = inside;
        for (int i = 0; i < 3; i++) {
            uint32_t x = T->v[NEXT(i)], y = T->v[PREV(i)];
            T->fixed[i] = (x == a && y == b) || (x == b && y == a);
        }
    }
    bsi_cdt_link_fresh(c);
    c->last = c->fresh[0];
    return BS_OK;
}

