/*
 * Topology of a surface: which patch sides are shared with which neighbour.
 *
 * Two sides match when they have the same number of control points and every control point agrees
 * within tol per coordinate, walked forward or reversed (weights, when rational, must be
 * proportional). Sides of different degree are never matched, even when one is an exact degree
 * elevation of the other. A side whose control points all coincide within tol is collapsed (a pole)
 * and matches nothing. Each side is matched at most once, first come first served in patch order.
 *
 * Cost: each side gets a key that does not depend on its direction (the sum of the coordinates of
 * both end points); sides are sorted by key and only sides whose keys are within the tolerance
 * band are compared, so matching is O(S log S) for S sides unless many sides share one key.
 */
#include "surface/internal.h"

#include <math.h>
#include <stdlib.h>

typedef struct side_key {
    double key;
    uint32_t patch;
    unsigned char side;
} side_key;

/* Index into the packed net of the k-th control point along a side. */
static size_t side_ctrl_index(const bs_patch *p, int side, size_t k)
{
    size_t m = p->deg_u, n = p->deg_v;
    switch (side) {
    case BSI_SIDE_V0: return k * (n + 1);         /* (k, 0) */
    case BSI_SIDE_U1: return m * (n + 1) + k;     /* (m, k) */
    case BSI_SIDE_V1: return k * (n + 1) + n;     /* (k, n) */
    default:          return k;                   /* (0, k) */
    }
}

static size_t side_degree(const bs_patch *p, int side)
{
    return (side == BSI_SIDE_V0 || side == BSI_SIDE_V1) ? p->deg_u : p->deg_v;
}

static double weight_at(const bs_patch *p, size_t idx)
{
    return p->rational ? p->weights[idx] : 1.0;
}

static int side_collapsed(const bs_patch *p, int side, double tol)
{
    size_t d = side_degree(p, side), dim = p->dim;
    const double *first = p->ctrl + side_ctrl_index(p, side, 0) * dim;
    for (size_t k = 1; k <= d; k++) {
        const double *q = p->ctrl + side_ctrl_index(p, side, k) * dim;
        for (size_t c = 0; c < dim; c++)
            if (!(fabs(q[c] - first[c]) <= tol))
                return 0;
    }
    return 1;
}

/* 1 if side sa of a equals side sb of b, walked forward (rev = 0) or reversed (rev = 1). */
static int sides_equal(const bs_patch *a, int sa, const bs_patch *b, int sb, int rev, double tol)
{
    size_t d = side_degree(a, sa), dim = a->dim;
    if (side_degree(b, sb) != d)
        return 0;
    size_t a0 = side_ctrl_index(a, sa, 0), b0 = side_ctrl_index(b, sb, rev ? d : 0);
    double wa0 = weight_at(a, a0), wb0 = weight_at(b, b0);
    for (size_t k = 0; k <= d; k++) {
        size_t ia = side_ctrl_index(a, sa, k), ib = side_ctrl_index(b, sb, rev ? d - k : k);
        for (size_t c = 0; c < dim; c++)
            if (!(fabs(a->ctrl[ia * dim + c] - b->ctrl[ib * dim + c]) <= tol))
                return 0;
        /* Same rational curve: weights proportional (w_a(k) / w_a(0) == w_b(k) / w_b(0)). */
        double lhs = weight_at(a, ia) * wb0, rhs = weight_at(b, ib) * wa0;
        if (!(fabs(lhs - rhs) <= 1e-12 * fmax(fabs(lhs), fabs(rhs))))
            return 0;
    }
    return 1;
}

static double side_key_of(const bs_patch *p, int side, double *maxabs)
{
    size_t d = side_degree(p, side), dim = p->dim;
    const double *e0 = p->ctrl + side_ctrl_index(p, side, 0) * dim;
    const double *e1 = p->ctrl + side_ctrl_index(p, side, d) * dim;
    double key = 0.0;
    for (size_t c = 0; c < dim; c++) {
        key += e0[c] + e1[c];
        *maxabs = fmax(*maxabs, fmax(fabs(e0[c]), fabs(e1[c])));
    }
    return key;
}

static int cmp_key(const void *x, const void *y)
{
    const side_key *a = x, *b = y;
    if (a->key < b->key) return -1;
    if (a->key > b->key) return 1;
    /* Ties in patch order so that matching is deterministic. */
    if (a->patch != b->patch) return a->patch < b->patch ? -1 : 1;
    return (a->side > b->side) - (a->side < b->side);
}

bs_status bsi_topology_build(const bs_surface *s, double tol, bsi_topology *out)
{
    size_t np = bs_surface_count(s);
    out->npatch = 0;
    out->links = NULL;
    if (!(tol >= 0.0) || !isfinite(tol))
        tol = 0.0;
    if (np == 0)
        return BS_OK;
    bsi_side_link *links = malloc(4 * np * sizeof(*links));
    side_key *keys = malloc(4 * np * sizeof(*keys));
    if (links == NULL || keys == NULL) {
        free(links);
        free(keys);
        return BS_ERR_NO_MEMORY;
    }
    size_t nk = 0;
    double maxabs = 0.0; /* largest end-point coordinate, bounds the rounding of the keys */
    for (size_t i = 0; i < np; i++) {
        const bs_patch *p = bs_surface_get(s, i);
        for (int side = 0; side < 4; side++) {
            bsi_side_link *l = &links[4 * i + (size_t)side];
            l->patch = BSI_NO_PATCH;
            l->side = 0;
            l->reversed = 0;
            l->collapsed = (unsigned char)side_collapsed(p, side, tol);
            if (!l->collapsed) {
                keys[nk].key = side_key_of(p, side, &maxabs);
                keys[nk].patch = (uint32_t)i;
                keys[nk].side = (unsigned char)side;
                nk++;
            }
        }
    }
    qsort(keys, nk, sizeof(*keys), cmp_key);
    /* Matching keys differ by at most 2*dim*tol plus the rounding of two sums of 2*dim terms. */
    double dim2 = 2.0 * (double)bs_surface_dim(s);
    double slack = dim2 * tol + 4.0 * dim2 * 0x1p-52 * dim2 * maxabs;
    for (size_t a = 0; a < nk; a++) {
        bsi_side_link *la = &links[4 * (size_t)keys[a].patch + keys[a].side];
        if (la->patch != BSI_NO_PATCH)
            continue;
        const bs_patch *pa = bs_surface_get(s, keys[a].patch);
        for (size_t b = a + 1; b < nk && keys[b].key - keys[a].key <= slack; b++) {
            bsi_side_link *lb = &links[4 * (size_t)keys[b].patch + keys[b].side];
            if (lb->patch != BSI_NO_PATCH)
                continue;
            const bs_patch *pb = bs_surface_get(s, keys[b].patch);
            int rev;
            if (sides_equal(pa, keys[a].side, pb, keys[b].side, 0, tol))
                rev = 0;
            else if (sides_equal(pa, keys[a].side, pb, keys[b].side, 1, tol))
                rev = 1;
            else
                continue;
            la->patch = keys[b].patch;
            la->side = keys[b].side;
            la->reversed = (unsigned char)rev;
            lb->patch = keys[a].patch;
            lb->side = keys[a].side;
            lb->reversed = (unsigned char)rev;
            break;
        }
    }
    free(keys);
    out->npatch = np;
    out->links = links;
    return BS_OK;
}

void bsi_topology_free(bsi_topology *t)
{
    if (t == NULL)
        return;
    free(t->links);
    t->links = NULL;
    t->npatch = 0;
}
