/*
 * The locator's bounding-volume hierarchy: a binary tree over the sub-patches' boxes, built top
 * down by cutting each set at the median of the box centres along the axis whose two halves'
 * boxes have the least surface, down to at most two sub-patches per leaf node. The median cut
 * keeps the tree balanced (depth log2 of the sub-patches), so queries can walk it with a small
 * fixed stack. Closest points walk it as it is; rays walk it collapsed into a wide tree of up to
 * four children a node (their boxes side by side, for one vector test), whose slots reach down
 * to single sub-patches where there is room.
 */
#include "query/locator.h"

#include <math.h>
#include <stdlib.h>


typedef struct builder {
    bs_locator *L;
    const double *leaf_box; /* 2*dim per leaf */
    const double *cen;      /* dim per leaf: box centres */
    uint32_t *perm;         /* the leaves in tree order */
    size_t next;            /* the next free node */
} builder;

/* Put the element of rank k (by centre along axis) of perm[lo..hi) at k, smaller before it. */
static void select_rank(const builder *b, size_t axis, size_t lo0, size_t hi0, size_t k0)
{
    size_t dim = b->L->dim;
    uint32_t *a = b->perm;
    ptrdiff_t lo = (ptrdiff_t)lo0, hi = (ptrdiff_t)hi0 - 1, k = (ptrdiff_t)k0;
    while (lo < hi) {
        double pivot = b->cen[a[lo + (hi - lo) / 2] * dim + axis];
        ptrdiff_t i = lo, j = hi;
        while (i <= j) { /* Hoare partition: [lo, j] <= pivot, [i, hi] >= pivot */
            while (b->cen[a[i] * dim + axis] < pivot)
                i++;
            while (b->cen[a[j] * dim + axis] > pivot)
                j--;
            if (i <= j) {
                uint32_t t = a[i];
                a[i++] = a[j];
                a[j--] = t;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            return;
    }
}

/* Surface of the box of leaves perm[lo..hi): the sum over pairs of axes of the products of the
 * box's extents (half the area of a 3-D box). */
static double half_surface(const builder *b, size_t lo, size_t hi)
{
    size_t dim = b->L->dim;
    double blo[BS_MAX_DIM], bhi[BS_MAX_DIM], s = 0.0;
    for (size_t c = 0; c < dim; c++) {
        blo[c] = INFINITY;
        bhi[c] = -INFINITY;
    }
    for (size_t k = lo; k < hi; k++) {
        const double *lb = b->leaf_box + 2 * dim * b->perm[k];
        for (size_t c = 0; c < dim; c++) {
            blo[c] = fmin(blo[c], lb[c]);
            bhi[c] = fmax(bhi[c], lb[dim + c]);
        }
    }
    for (size_t c = 0; c < dim; c++)
        for (size_t e = c + 1; e < dim; e++)
            s += (bhi[c] - blo[c]) * (bhi[e] - blo[e]);
    return s;
}

/* Node ni over perm[lo..hi): its box, and its children or its leaves. */
static void build_node(builder *b, size_t ni, size_t lo, size_t hi)
{
    bs_locator *L = b->L;
    size_t dim = L->dim;
    double *box = L->box + 2 * dim * ni, clo[BS_MAX_DIM], chi[BS_MAX_DIM];
    for (size_t c = 0; c < dim; c++) {
        box[c] = clo[c] = INFINITY;
        box[dim + c] = chi[c] = -INFINITY;
    }
    for (size_t k = lo; k < hi; k++) {
        const double *lb = b->leaf_box + 2 * dim * b->perm[k], *cen = b->cen + dim * b->perm[k];
        for (size_t c = 0; c < dim; c++) {
            box[c] = fmin(box[c], lb[c]);
            box[dim + c] = fmax(box[dim + c], lb[dim + c]);
            clo[c] = fmin(clo[c], cen[c]);
            chi[c] = fmax(chi[c], cen[c]);
        }
    }
    if (hi - lo <= BSI_LOC_LEAF_MAX) {
        L->nodes[ni].first = (uint32_t)lo;
        L->nodes[ni].count = (uint32_t)(hi - lo);
        return;
    }
    /* the median cut along the axis whose two halves' boxes have the least surface (area for
     * 3-D boxes; the sum of their half-perimeters' products in general): fewer rays cross both */
    size_t axis = 0, mid = lo + (hi - lo) / 2, child = b->next;
    double best = INFINITY;
    for (size_t c = 0; c < dim; c++) {
        if (!(chi[c] > clo[c]))
            continue;
        select_rank(b, c, lo, hi, mid);
        double cost = half_surface(b, lo, mid) + half_surface(b, mid, hi);
        if (cost < best) {
            best = cost;
            axis = c;
        }
    }
    select_rank(b, axis, lo, hi, mid);
    b->next += 2;
    L->nodes[ni].first = (uint32_t)child;
    L->nodes[ni].count = 0;
    build_node(b, child, lo, mid);
    build_node(b, child + 1, mid, hi);
}

/* A slot's candidate while a wide node is made: a binary node (inner or leaf node), or one
 * sub-patch (BSI_WIDE_PATCH). */
typedef struct slot_cand {
    uint32_t ref;
    unsigned char kind;
} slot_cand;

/* The box of a candidate: its node's, or its sub-patch's own. */
static const double *cand_box(const bs_locator *L, slot_cand c)
{
    return c.kind == BSI_WIDE_PATCH ? L->leaf_box + 6 * (size_t)c.ref : L->box + 6 * (size_t)c.ref;
}

static double cand_surface(const bs_locator *L, slot_cand c)
{
    const double *b = cand_box(L, c);
    double x = b[3] - b[0], y = b[4] - b[1], z = b[5] - b[2];
    return x * y + y * z + z * x;
}

/* Wide node *next (then the ones below it) from inner binary node b: its two children, each
 * node among them replaced by its own children (an inner node's two, a leaf node's sub-patches)
 * while there is room, the largest box first (the one most rays enter); returns its index. */
static uint32_t collapse(bs_locator *L, uint32_t b, uint32_t *next)
{
    uint32_t wi = (*next)++, n = 2;
    slot_cand cand[BSI_LOC_WIDE] = {{L->nodes[b].first, 0}, {L->nodes[b].first + 1, 0}};
    for (;;) {
        int pick = -1;
        for (uint32_t k = 0; k < n; k++) {
            if (cand[k].kind != 0) /* a sub-patch: nothing below it */
                continue;
            const bsi_loc_node *nd = &L->nodes[cand[k].ref];
            uint32_t grow = nd->count == 0 ? 1 : nd->count - 1; /* slots the expansion adds */
            if (n + grow <= BSI_LOC_WIDE &&
                (pick < 0 || cand_surface(L, cand[k]) > cand_surface(L, cand[pick])))
                pick = (int)k;
        }
        if (pick < 0)
            break;
        const bsi_loc_node *nd = &L->nodes[cand[pick].ref];
        uint32_t first = nd->first, count = nd->count == 0 ? 2 : nd->count;
        unsigned char kind = nd->count == 0 ? 0 : BSI_WIDE_PATCH;
        cand[pick] = (slot_cand){first, kind};
        for (uint32_t q = 1; q < count; q++)
            cand[n++] = (slot_cand){first + q, kind};
    }
    bsi_loc_wide *w = &L->wide[wi];
    w->n = n;
    for (uint32_t k = 0; k < BSI_LOC_WIDE; k++)
        for (int c = 0; c < 3; c++) { /* empty slots: a box no ray enters */
            w->lo[c][k] = k < n ? cand_box(L, cand[k])[c] : INFINITY;
            w->hi[c][k] = k < n ? cand_box(L, cand[k])[3 + c] : -INFINITY;
        }
    for (uint32_t k = 0; k < n; k++) {
        int inner = cand[k].kind == 0 && L->nodes[cand[k].ref].count == 0;
        w->ref[k] = inner ? collapse(L, cand[k].ref, next) : cand[k].ref;
        w->leaf[k] = inner ? 0 : cand[k].kind == BSI_WIDE_PATCH ? BSI_WIDE_PATCH : BSI_WIDE_NODE;
    }
    return wi;
}

/* The rays' tree of a 3-D locator (L->wide), at most one wide node per inner binary node. The
 * binary root is always an inner node: every patch gives BSI_LOC_SPLIT^2 sub-patches, more than
 * a leaf node holds. */
typedef char bsi_root_is_inner[BSI_LOC_SPLIT * BSI_LOC_SPLIT > BSI_LOC_LEAF_MAX ? 1 : -1];
static bs_status build_wide(bs_locator *L)
{
    L->wide = malloc(L->nnode * sizeof *L->wide);
    if (L->wide == NULL)
        return BS_ERR_NO_MEMORY;
    uint32_t next = 0;
    (void)collapse(L, 0, &next);
    bsi_loc_wide *fit = realloc(L->wide, next * sizeof *L->wide); /* the nodes used */
    if (fit == NULL)
        return BS_ERR_NO_MEMORY; /* as any allocation of the locator (L->wide freed with it) */
    L->wide = fit;
    return BS_OK;
}

/* Nodes of the tree over n leaves: the median cut makes it a function of n alone. */
static size_t node_count(size_t n)
{
    return n <= BSI_LOC_LEAF_MAX ? 1 : 1 + node_count(n / 2) + node_count(n - n / 2);
}

bs_status bsi_loc_build_bvh(bs_locator *L, const double *leaf_box)
{
    size_t dim = L->dim, n = L->nleaf, nodes = node_count(n);
    L->nodes = malloc(nodes * sizeof *L->nodes);
    L->box = malloc(nodes * 2 * dim * sizeof(double));
    double *cen = malloc(n * dim * sizeof(double));
    uint32_t *perm = malloc(n * sizeof *perm);
    bsi_loc_leaf *sorted = malloc(n * sizeof *sorted);
    L->leaf_box = malloc(n * 2 * dim * sizeof(double));
    bs_status st = BS_ERR_NO_MEMORY;
    if (L->nodes && L->box && cen && perm && sorted && L->leaf_box) {
        for (size_t k = 0; k < n; k++) {
            perm[k] = (uint32_t)k;
            for (size_t c = 0; c < dim; c++)
                cen[k * dim + c] = 0.5 * leaf_box[2 * dim * k + c] + 0.5 * leaf_box[2 * dim * k + dim + c];
        }
        builder b = {L, leaf_box, cen, perm, 1};
        build_node(&b, 0, 0, n);
        L->nnode = b.next;
        for (size_t k = 0; k < n; k++) {
            sorted[k] = L->leaves[perm[k]];
            for (size_t c = 0; c < 2 * dim; c++)
                L->leaf_box[2 * dim * k + c] = leaf_box[2 * dim * perm[k] + c];
        }
        bsi_loc_leaf *old = L->leaves;
        L->leaves = sorted;
        sorted = old;
        st = dim == 3 ? build_wide(L) : BS_OK;
    }
    free(sorted);
    free(perm);
    free(cen);
    return st;
}
