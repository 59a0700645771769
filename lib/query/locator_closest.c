/*
 * Closest points on the surface of a locator (bs_locator_closest_point): the hierarchy is walked
 * nearest box first, boxes no nearer than the best distance so far are skipped, and each patch
 * reached is searched whole, once per query, by bsi_patch_closest_one (closest.c) with the
 * surface's diagonal as its scale, which only answers when it beats the best so far. The answers
 * are kept aside until every query is done, so that running out of memory on the way writes
 * nothing.
 */
#include "query/locator.h"

#include <math.h>
#include <stdlib.h>

#define STACK 128 /* as in locator_ray.c: far more than the depth of a median-split tree */
#define RETRY 64  /* a model's patches searched again once its trims' distance is known */

/* Distance from q to box (lo, hi) without overflow or underflow (+Inf only beyond DBL_MAX):
 * the gaps halved, then scaled by their largest. */
static double box_distance(const double *lo, const double *hi, const double *q, size_t dim)
{
    double g[BS_MAX_DIM], big = 0.0, s = 0.0;
    for (size_t c = 0; c < dim; c++) {
        g[c] = q[c] < lo[c] ? 0.5 * lo[c] - 0.5 * q[c] : q[c] > hi[c] ? 0.5 * q[c] - 0.5 * hi[c] : 0.0;
        big = g[c] > big ? g[c] : big;
    }
    if (big == 0.0)
        return 0.0;
    for (size_t c = 0; c < dim; c++)
        s += (g[c] / big) * (g[c] / big);
    return 2.0 * big * sqrt(s);
}

/* The closest patch and its (u, v) for the finite point q; *id stays UINT32_MAX when nothing
 * is found. stamp[i] == mark means patch i has been searched for this query. -1: out of memory,
 * -2: a patch's answer cannot be certified. */
static int closest(const bs_locator *L, const double *q, size_t *stamp, size_t mark, uint32_t *id,
                   double uv[2])
{
    struct {
        uint32_t node;
        double d;
    } stack[STACK];
    size_t dim = L->dim;
    double best = INFINITY;
    int top = 0;
    bsi_cl_part part = {NULL, NULL, L->trim, 0};
    uint32_t retry[RETRY]; /* faces' patches whose search could not end without the trims' best */
    size_t nretry = 0;
    if (L->trim) { /* a model's faces: held inside their trims, which are searched after */
        part.box = L->trim->box;
        part.point = L->trim->point;
    }
    stack[top].node = 0;
    stack[top++].d = box_distance(L->box, L->box + dim, q, dim);
    while (top > 0) {
        top--;
        if (!(stack[top].d < best))
            continue;
        const bsi_loc_node *nd = &L->nodes[stack[top].node];
        if (nd->count > 0) {
            for (uint32_t k = nd->first; k < nd->first + nd->count; k++) {
                uint32_t i = L->leaves[k].patch;
                if (stamp[i] == mark)
                    continue;
                stamp[i] = mark;
                part.patch = i;
                int r = bsi_patch_closest_part(L->patches[i], q, L->diag, &best, uv,
                                               L->trim ? &part : NULL);
                if (r == -2 && L->trim && nretry < RETRY) {
                    retry[nretry++] = i;
                    continue;
                }
                if (r < 0)
                    return r;
                if (r == 1)
                    *id = i;
            }
            continue;
        }
        double d[2];
        for (int c = 0; c < 2; c++) {
            const double *box = L->box + 2 * dim * (nd->first + (uint32_t)c);
            d[c] = box_distance(box, box + dim, q, dim);
        }
        int near = d[1] < d[0];
        for (int k = 0; k < 2; k++) { /* the farther child first, so the nearer is popped next */
            int c = k == 0 ? !near : near;
            if (d[c] < best && top < STACK) {
                stack[top].node = nd->first + (uint32_t)c;
                stack[top++].d = d[c];
            }
        }
    }
    if (L->trim) { /* the trims, then the faces whose search needed their distance */
        int r = L->trim->boundary(L->trim, q, &best, id, uv);
        for (size_t k = 0; k < nretry && r >= 0; k++) {
            part.patch = retry[k];
            r = bsi_patch_closest_part(L->patches[retry[k]], q, L->diag, &best, uv, &part);
            *id = r == 1 ? retry[k] : *id;
        }
        if (r < 0)
            return r;
    }
    return 0;
}

/* Outputs of query k: pos as bs_patch_eval gives it at uv, dist |pos - q|; NaN (and distance
 * +Inf on an empty surface) where there is no answer. */
static void put(const bs_locator *L, size_t k, const double *q, uint32_t id, const double at[2],
                double none, uint32_t *patch, const bs_view *uv, const bs_view *dist,
                const bs_view *pos)
{
    double x[BS_MAX_DIM], d = none;
    for (size_t c = 0; c < L->dim; c++)
        x[c] = NAN;
    if (id != UINT32_MAX) {
        bs_cview cu = {&at[0], 1, 0}, cv = {&at[1], 1, 0};
        bs_view xv[BS_MAX_DIM];
        for (size_t c = 0; c < L->dim; c++)
            xv[c] = (bs_view){&x[c], 1, 0};
        (void)bs_patch_eval(L->patches[id], 1, &cu, &cv, xv, NULL, NULL);
        d = 0.0;
        for (size_t c = 0; c < L->dim; c++)
            d = hypot(d, x[c] - q[c]);
    }
    double u = id != UINT32_MAX ? at[0] : NAN, v = id != UINT32_MAX ? at[1] : NAN;
    if (L->trim && id != UINT32_MAX) { /* a model's: its face and native parameters */
        double fuv[2], nrm[3] = {0.0, 0.0, 0.0};
        L->trim->to_face(L->trim, id, u, v, &id, fuv, nrm);
        u = fuv[0];
        v = fuv[1];
    }
    if (patch)
        patch[k] = id;
    if (uv) {
        *bsi_at(&uv[0], k) = u;
        *bsi_at(&uv[1], k) = v;
    }
    if (dist)
        *bsi_at(dist, k) = d;
    for (size_t c = 0; pos && c < L->dim; c++)
        *bsi_at(&pos[c], k) = x[c];
}

/* Query point k into x; 1 if it is finite. */
static int query_point(const bs_cview *q, size_t k, size_t dim, double *x)
{
    int finite = 1;
    for (size_t c = 0; c < dim; c++) {
        x[c] = bsi_cget(&q[c], k);
        finite &= isfinite(x[c]) != 0;
    }
    return finite;
}

bs_status bsi_loc_closest_check(const bs_locator *L, size_t n, const bs_cview *q, const bs_view *uv,
                                const bs_view *dist, const bs_view *pos)
{
    if (L == NULL)
        return BS_ERR_INVALID_ARG;
    if (n == 0)
        return BS_OK;
    if (q == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st = BS_OK;
    for (size_t c = 0; c < L->dim && st == BS_OK; c++)
        st = bsi_check_cview(&q[c], n);
    if (st != BS_OK || (uv && (st = bsi_check_views(uv, 2, n)) != BS_OK) ||
        (dist && (st = bsi_check_views(dist, 1, n)) != BS_OK) ||
        (pos && (st = bsi_check_views(pos, L->dim, n)) != BS_OK))
        return st;
    return BS_OK;
}

bs_status bs_locator_closest_point(const bs_locator *L, size_t n, const bs_cview *q,
                                   uint32_t *patch, const bs_view *uv, const bs_view *dist,
                                   const bs_view *pos)
{
    bs_status st = bsi_loc_closest_check(L, n, q, uv, dist, pos);
    if (st != BS_OK || n == 0)
        return st;
    size_t dim = L->dim;
    /* the answers (patch, u, v) of every query, and a mark per patch */
    uint32_t *ids = malloc(n * sizeof *ids);
    double *at = malloc(2 * n * sizeof *at);
    size_t *stamp = calloc(L->npatch + 1, sizeof *stamp);
    st = ids && at && stamp ? BS_OK : BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < n && st == BS_OK; k++) {
        double x[BS_MAX_DIM];
        ids[k] = UINT32_MAX;
        int r = query_point(q, k, dim, x) && L->nnode > 0
                    ? closest(L, x, stamp, k + 1, &ids[k], &at[2 * k])
                    : 0;
        st = r == -1 ? BS_ERR_NO_MEMORY : r == -2 ? BS_ERR_PRECISION : BS_OK;
    }
    for (size_t k = 0; k < n && st == BS_OK; k++) {
        double x[BS_MAX_DIM];
        int finite = query_point(q, k, dim, x);
        put(L, k, x, ids[k], &at[2 * k], finite && L->nnode == 0 ? INFINITY : NAN, patch, uv, dist, pos);
    }
    free(stamp);
    free(at);
    free(ids);
    return st;
}
