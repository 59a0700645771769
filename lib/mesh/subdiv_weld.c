/*
 * Subdivision phase 2: the points of each patch and which of them are one vertex.
 *
 * A patch's points are its leaves' corners, plus, on a side shared with a neighbour, the corners
 * the neighbour's leaves put on that side (at SD_N - t when the side is reversed): both patches
 * then have the same points on the side. Points of shared sides are merged pairwise, all points of
 * a collapsed side into one (a pole), with a union-find whose roots are the lowest points, so each
 * vertex is evaluated once, on the lowest patch that has it, and both sides of an edge use it.
 * Points are kept sorted twice, by (u,v) and by (v,u), so the points on any horizontal or vertical
 * segment of a patch are one range of one array.
 */
#include "mesh/subdiv.h"

#include <stdlib.h>
#include <string.h>

#define IDX_BITS 24 /* a patch has fewer than 2^24 points: at most 1025^2 corners plus its sides */
#define IDX_MASK ((UINT64_C(1) << IDX_BITS) - 1)

/* Sort n 64-bit keys by their bits lo..hi-1 (LSD radix, stable); tmp holds n keys. */
static void sort_keys(uint64_t *a, uint64_t *tmp, size_t n, unsigned lo, unsigned hi)
{
    uint64_t *src = a, *dst = tmp;
    for (unsigned sh = lo; sh < hi; sh += 11) {
        size_t cnt[2048] = {0};
        uint64_t mask = hi - sh >= 11 ? 2047 : (UINT64_C(1) << (hi - sh)) - 1; /* bits from hi on are not key */
        for (size_t i = 0; i < n; i++)
            cnt[(src[i] >> sh) & mask]++;
        for (size_t k = 0, sum = 0; k < 2048; k++) {
            size_t c = cnt[k];
            cnt[k] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[cnt[(src[i] >> sh) & mask]++] = src[i];
        uint64_t *x = src;
        src = dst;
        dst = x;
    }
    if (src != a)
        memcpy(a, src, n * sizeof(uint64_t));
}

/* (u,v) of parameter t on side `side`. */
static void side_uv(int side, uint32_t t, uint32_t *u, uint32_t *v)
{
    switch (side) {
    case BSI_SIDE_V0: *u = t; *v = 0; break;
    case BSI_SIDE_U1: *u = SD_N; *v = t; break;
    case BSI_SIDE_V1: *u = t; *v = SD_N; break;
    default:          *u = 0; *v = t; break;
    }
}

static size_t lower_bound(const uint64_t *a, size_t n, uint64_t key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (a[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Points of patch p with v = b and u in [a0, a1) (along_u: a range of s->vu), or with u = b and v in
 * [a0, a1) (a range of s->uv): [*first, *last) within the patch. */
static void side_range(const subdiv *s, size_t p, int along_u, uint32_t b, uint32_t a0, uint32_t a1, size_t *first,
                       size_t *last)
{
    size_t n = s->pt0[p + 1] - s->pt0[p];
    if (along_u) {
        const uint64_t *vu = s->vu + s->pt0[p];
        *first = lower_bound(vu, n, SD_KEY(b, a0) << IDX_BITS);
        *last = lower_bound(vu, n, SD_KEY(b, a1) << IDX_BITS);
    } else {
        const uint64_t *uv = s->uv + s->pt0[p];
        *first = lower_bound(uv, n, SD_KEY(b, a0));
        *last = lower_bound(uv, n, SD_KEY(b, a1));
    }
}

/* Global index of point (u,v) of patch p (it must exist). */
static size_t point_index(const subdiv *s, size_t p, uint32_t u, uint32_t v)
{
    return s->pt0[p] + lower_bound(s->uv + s->pt0[p], s->pt0[p + 1] - s->pt0[p], SD_KEY(u, v));
}

/* Point k of a range found by side_range: its global index. */
static size_t range_point(const subdiv *s, size_t p, int along_u, size_t k)
{
    return s->pt0[p] + (along_u ? (size_t)(s->vu[s->pt0[p] + k] & IDX_MASK) : k);
}

/* Parameters of the leaf corners of patch p on side `side`, sorted, repeats removed. */
static size_t leaf_side_params(const subdiv *s, size_t p, int side, uint32_t *out)
{
    size_t n = 0;
    for (size_t k = s->leaf0[p]; k < s->leaf0[p + 1]; k++) {
        const sd_leaf *l = &s->leaf[k];
        int on = side == BSI_SIDE_V0 ? l->v0 == 0 : side == BSI_SIDE_U1 ? l->u1 == SD_N
               : side == BSI_SIDE_V1 ? l->v1 == SD_N : l->u0 == 0;
        if (!on)
            continue;
        int along_u = side == BSI_SIDE_V0 || side == BSI_SIDE_V1;
        out[n++] = along_u ? l->u0 : l->v0;
        out[n++] = along_u ? l->u1 : l->v1;
    }
    return n; /* repeats are removed with the patch's points */
}

/* Points of patch p into s->uv (from *fill on), sorted and unique, and each leaf corner's point
 * into s->corner; keys and tmp are scratch. A key carries 1 + the leaf corner's number above its
 * 40 bits of (u,v) (a patch has at most 2^22 leaf corners), 0 for a neighbour's side point. */
static bs_status patch_points(subdiv *s, size_t p, uint64_t *keys, uint64_t *tmp, uint32_t *par, size_t *fill)
{
    size_t n = 0;
    for (size_t k = s->leaf0[p]; k < s->leaf0[p + 1]; k++) {
        const sd_leaf *l = &s->leaf[k];
        uint64_t c = (uint64_t)(4 * (k - s->leaf0[p]) + 1) << (2 * SD_BITS);
        keys[n++] = c | SD_KEY(l->u0, l->v0);
        keys[n++] = (c + (UINT64_C(1) << (2 * SD_BITS))) | SD_KEY(l->u1, l->v0);
        keys[n++] = (c + (UINT64_C(2) << (2 * SD_BITS))) | SD_KEY(l->u1, l->v1);
        keys[n++] = (c + (UINT64_C(3) << (2 * SD_BITS))) | SD_KEY(l->u0, l->v1);
    }
    for (int side = 0; side < 4; side++) {
        const bsi_side_link *lk = &s->topo.links[4 * p + (size_t)side];
        if (lk->patch == BSI_NO_PATCH)
            continue;
        size_t np = leaf_side_params(s, lk->patch, lk->side, par);
        for (size_t k = 0; k < np; k++) {
            uint32_t u, v;
            side_uv(side, lk->reversed ? SD_N - par[k] : par[k], &u, &v);
            keys[n++] = SD_KEY(u, v);
        }
    }
    sort_keys(keys, tmp, n, 0, 2 * SD_BITS);
    const uint64_t low = (UINT64_C(1) << (2 * SD_BITS)) - 1;
    uint32_t *corner = s->corner + 4 * s->leaf0[p];
    uint64_t *uv = s->uv + *fill;
    size_t u = 0;
    for (size_t k = 0; k < n; k++) {
        if (u == 0 || (keys[k] & low) != uv[u - 1])
            uv[u++] = keys[k] & low;
        if (keys[k] >> (2 * SD_BITS))
            corner[(keys[k] >> (2 * SD_BITS)) - 1] = (uint32_t)(u - 1);
    }
    if (u > IDX_MASK)
        return BS_ERR_SIZE;
    for (size_t k = 0; k < u; k++) {
        uint64_t a = uv[k] >> SD_BITS, b = uv[k] & ((UINT64_C(1) << SD_BITS) - 1);
        keys[k] = (SD_KEY(b, a) << IDX_BITS) | k;
    }
    sort_keys(keys, tmp, u, IDX_BITS, IDX_BITS + 2 * SD_BITS);
    memcpy(s->vu + *fill, keys, u * sizeof(uint64_t));
    for (size_t r = 0; r < u; r++)
        s->vupos[*fill + (keys[r] & IDX_MASK)] = (uint32_t)r;
    *fill += u;
    return BS_OK;
}

/* Merge the points of shared and collapsed sides of patch p. */
static void merge_sides(subdiv *s, size_t p)
{
    for (int side = 0; side < 4; side++) {
        const bsi_side_link *lk = &s->topo.links[4 * p + (size_t)side];
        int along_u = side == BSI_SIDE_V0 || side == BSI_SIDE_V1;
        uint32_t b = side == BSI_SIDE_U1 || side == BSI_SIDE_V1 ? SD_N : 0;
        size_t first, last;
        side_range(s, p, along_u, b, 0, SD_N + 1, &first, &last);
        if (lk->collapsed) {
            for (size_t k = first; k < last; k++)
                uf_union(s->parent, range_point(s, p, along_u, first), range_point(s, p, along_u, k));
            continue;
        }
        if (lk->patch == BSI_NO_PATCH || lk->patch < p || (lk->patch == p && lk->side < side))
            continue;
        for (size_t k = first; k < last; k++) {
            size_t g = range_point(s, p, along_u, k);
            uint64_t key = s->uv[g];
            uint32_t t = (uint32_t)(along_u ? key >> SD_BITS : key & ((UINT64_C(1) << SD_BITS) - 1)), u, v;
            side_uv(lk->side, lk->reversed ? SD_N - t : t, &u, &v);
            uf_union(s->parent, g, point_index(s, lk->patch, u, v));
        }
    }
}

bs_status bsi_subdiv_weld(subdiv *s)
{
    size_t np = s->np, total = 0, most = 1;
    for (size_t p = 0; p < np; p++) {
        size_t n = 4 * (s->leaf0[p + 1] - s->leaf0[p]);
        for (int side = 0; side < 4; side++) {
            const bsi_side_link *lk = &s->topo.links[4 * p + (size_t)side];
            if (lk->patch != BSI_NO_PATCH)
                n += 2 * (s->leaf0[lk->patch + 1] - s->leaf0[lk->patch]);
        }
        total += n;
        most = n > most ? n : most;
    }
    s->pt0 = malloc((np + 1) * sizeof(size_t));
    s->vert0 = malloc((np + 1) * sizeof(size_t));
    s->uv = malloc((total ? total : 1) * sizeof(uint64_t));
    s->vu = malloc((total ? total : 1) * sizeof(uint64_t));
    s->vupos = malloc((total ? total : 1) * sizeof(uint32_t));
    s->corner = malloc((s->nleaf ? 4 * s->nleaf : 1) * sizeof(uint32_t));
    uint64_t *keys = malloc(most * sizeof(uint64_t)), *tmp = malloc(most * sizeof(uint64_t));
    uint32_t *par = malloc(most * sizeof(uint32_t));
    bs_status st = s->pt0 && s->vert0 && s->uv && s->vu && s->vupos && s->corner && keys && tmp && par ? BS_OK : BS_ERR_NO_MEMORY;
    size_t fill = 0;
    for (size_t p = 0; p < np && st == BS_OK; p++) {
        s->pt0[p] = fill;
        st = patch_points(s, p, keys, tmp, par, &fill);
    }
    free(keys);
    free(tmp);
    free(par);
    if (st != BS_OK)
        return st;
    s->pt0[np] = fill;
    if (fill >= UINT32_MAX)
        return BS_ERR_SIZE;
    s->parent = malloc((fill ? fill : 1) * sizeof(size_t));
    s->vid = malloc((fill ? fill : 1) * sizeof(uint32_t));
    if (s->parent == NULL || s->vid == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < fill; k++)
        s->parent[k] = k;
    for (size_t p = 0; p < np; p++)
        merge_sides(s, p);
    /* Vertices: the root points, in patch order (a set's root is in its lowest patch). */
    size_t nv = 0;
    for (size_t p = 0; p < np; p++) {
        s->vert0[p] = nv;
        for (size_t k = s->pt0[p]; k < s->pt0[p + 1]; k++) {
            size_t r = uf_find(s->parent, k);
            s->vid[k] = r == k ? (uint32_t)nv++ : s->vid[r];
        }
    }
    s->vert0[np] = nv;
    s->nvert = nv;
    return BS_OK;
}
