/*
 * The locator's bounding-volume hierarchy: a binary tree over the sub-patches' boxes, built top
 * down by cutting each set at the median of the box centres along the axis whose two halves'
 * boxes have the least surface, down to at most two sub-patches per leaf node. The median cut keeps the tree balanced
 * (depth log2 of the sub-patches), so queries can walk it with a small fixed stack.
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
        st = BS_OK;
    }
    free(sorted);
    free(perm);
    free(cen);
    return st;
}
