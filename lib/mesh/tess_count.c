/*
 * Tessellation counts: the exact numbers of vertices, triangles, strips and strip indices the
 * laid-out tessellation will emit, in memory O(patches), so that budgets and the 32-bit index space
 * are checked before the slots and the output arrays are allocated.
 *
 * The plan merges slots in two disjoint kinds of sets: corners (through collapsed sides and the
 * ends of shared sides) and the inner samples of a side (pairwise with its neighbour's, never with
 * a corner, since collapsed sides have no neighbour). So a union-find over the 4 corners of each
 * patch and one name per shared pair of sides identify every side sample. Triangles only
 * degenerate where two corners of one triangle are side samples that are one vertex: at a pole, a
 * side shared with the same patch or corners merged. Only a few triangles of such patches are
 * visited one by one (all of them for grids of 1 or 2 segments in a direction); a patch costs O(1).
 */
#include "mesh/tess.h"

#include <stdlib.h>

/* Identity of a vertex of one patch's triangles: equal keys, one vertex. */
typedef struct vkey { size_t set, k; } vkey;

#define KEY_INTERIOR SIZE_MAX

static int same(vkey a, vkey b) { return a.set == b.set && a.k == b.k; }

/* Sample k of side s of patch p: its corner's set, or the shared pair of sides and the index on the
 * side that names the pair. */
static vkey side_key(const tess *t, size_t *corners, size_t p, int s, size_t k)
{
    const patch_plan *pl = &t->plan[p];
    const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
    size_t e = pl->e[s];
    if (k == 0 || k == e || l->collapsed) {
        vkey c = {uf_find(corners, 4 * p + side_end_corner(s, k == e && !l->collapsed)), 0};
        return c;
    }
    size_t id = 4 * p + (size_t)s;
    if (l->patch != BSI_NO_PATCH && 4 * (size_t)l->patch + l->side < id) {
        id = 4 * (size_t)l->patch + l->side;
        k = l->reversed ? e - k : k;
    }
    vkey v = {4 * t->np + id, k};
    return v;
}

/* Grid point (i,j) of patch p: a side sample on the border, else an interior point. */
static vkey grid_key(const tess *t, size_t *corners, size_t p, size_t i, size_t j)
{
    const patch_plan *pl = &t->plan[p];
    if (j == 0)
        return side_key(t, corners, p, BSI_SIDE_V0, i);
    if (j == pl->gv)
        return side_key(t, corners, p, BSI_SIDE_V1, i);
    if (i == 0)
        return side_key(t, corners, p, BSI_SIDE_U0, j);
    if (i == pl->gu)
        return side_key(t, corners, p, BSI_SIDE_U1, j);
    vkey v = {KEY_INTERIOR, i * (pl->gv + 1) + j};
    return v;
}

static int distinct(vkey a, vkey b, vkey c) { return !same(a, b) && !same(b, c) && !same(a, c); }

/* Triangles of quad (i,j) of a regular grid that no pole makes degenerate (0, 1 or 2). */
static size_t quad_triangles(const tess *t, size_t *corners, size_t p, size_t i, size_t j)
{
    vkey a = grid_key(t, corners, p, i, j), b = grid_key(t, corners, p, i + 1, j);
    vkey c = grid_key(t, corners, p, i + 1, j + 1), d = grid_key(t, corners, p, i, j + 1);
    return (size_t)distinct(a, b, d) + (size_t)distinct(d, b, c);
}

/* 1 if the patch's side samples are all different vertices: no pole, no side shared with another
 * side of the patch, four corners apart. Then none of its triangles degenerates. */
static int all_distinct(const tess *t, size_t *corners, size_t p)
{
    size_t root[4];
    for (int s = 0; s < 4; s++) {
        const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
        if (l->collapsed || l->patch == p)
            return 0;
        root[s] = uf_find(corners, 4 * p + (size_t)s);
    }
    return root[0] != root[1] && root[0] != root[2] && root[0] != root[3] && root[1] != root[2] &&
           root[1] != root[3] && root[2] != root[3];
}

/* Triangles of a regular grid that no repeated vertex drops. Along the middle of a side, a quad's
 * triangle has two side samples only if they are neighbours on that side, one vertex only at a
 * pole; so with 3 or more segments per direction only the four corner quads are visited. */
static size_t regular_triangles(const tess *t, size_t *corners, size_t p)
{
    const patch_plan *pl = &t->plan[p];
    size_t gu = pl->gu, gv = pl->gv, n = 0;
    if (gu < 3 || gv < 3) {
        for (size_t i = 0; i < gu; i++)
            for (size_t j = 0; j < gv; j++)
                n += quad_triangles(t, corners, p, i, j);
        return n;
    }
    n = 2 * (gu - 2) * (gv - 2);
    for (int s = 0; s < 4; s++) {
        size_t g = (s == BSI_SIDE_V0 || s == BSI_SIDE_V1) ? gu : gv;
        n += (t->topo.links[4 * p + (size_t)s].collapsed ? 1 : 2) * (g - 2);
    }
    return n + quad_triangles(t, corners, p, 0, 0) + quad_triangles(t, corners, p, gu - 1, 0) +
           quad_triangles(t, corners, p, 0, gv - 1) + quad_triangles(t, corners, p, gu - 1, gv - 1);
}

/* Triangles between side s and the inner grid whose two corners are side samples k, k + 1: all
 * but where both are one vertex (a pole, or a side of one segment between merged corners). */
static size_t outer_triangles(const tess *t, size_t *corners, size_t p, int s)
{
    size_t e = t->plan[p].e[s];
    if (t->topo.links[4 * p + (size_t)s].collapsed)
        return 0;
    return e > 1 || !same(side_key(t, corners, p, s, 0), side_key(t, corners, p, s, 1)) ? e : 0;
}

/* Counts of one patch (at most BS_TESS_MAX_RATE per direction: no overflow). */
static void patch_counts(const tess *t, size_t *corners, size_t p, tess_counts *c)
{
    const patch_plan *pl = &t->plan[p];
    size_t gu = pl->gu, gv = pl->gv;
    c->vertices = (gu - 1) * (gv - 1);
    for (int s = 0; s < 4; s++) {
        const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
        int owner = l->patch == BSI_NO_PATCH || 4 * (size_t)l->patch + l->side > 4 * p + (size_t)s;
        if (!l->collapsed && owner)
            c->vertices += pl->e[s] - 1;
    }
    if (pl->regular) {
        c->triangles = all_distinct(t, corners, p) ? 2 * gu * gv : regular_triangles(t, corners, p);
        c->strips = gu;
        c->strip_indices = 2 * gu * (gv + 1);
        return;
    }
    /* inner grid, then each side zipped to it: its outer triangles and g - 2 inner ones */
    size_t ring = 0;
    for (int s = 0; s < 4; s++) {
        size_t g = (s == BSI_SIDE_V0 || s == BSI_SIDE_V1) ? gu : gv;
        ring += outer_triangles(t, corners, p, s) + g - 2;
    }
    c->triangles = 2 * (gu - 2) * (gv - 2) + ring;
    c->strips = (gv > 2 ? gu - 2 : 0) + ring;
    c->strip_indices = (gv > 2 ? 2 * (gu - 2) * (gv - 1) : 0) + 3 * ring;
}

/* a += b, 0 on overflow. */
static int add_to(size_t *a, size_t b)
{
    if (b > SIZE_MAX - *a)
        return 0;
    *a += b;
    return 1;
}

bs_status bsi_tess_count(const tess *t, tess_counts *c)
{
    size_t np = t->np;
    size_t *corners = malloc((np ? 4 * np : 1) * sizeof(size_t));
    if (corners == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < 4 * np; k++)
        corners[k] = k;
    for (size_t p = 0; p < np; p++)
        for (int s = 0; s < 4; s++) {
            const bsi_side_link *l = &t->topo.links[4 * p + (size_t)s];
            size_t a0 = 4 * p + side_end_corner(s, 0), a1 = 4 * p + side_end_corner(s, 1);
            if (l->collapsed)
                uf_union(corners, a0, a1);
            if (l->patch == BSI_NO_PATCH)
                continue;
            size_t q = 4 * (size_t)l->patch;
            uf_union(corners, a0, q + side_end_corner(l->side, l->reversed));
            uf_union(corners, a1, q + side_end_corner(l->side, !l->reversed));
        }
    tess_counts sum = {0, 0, 0, 0};
    int ok = 1;
    for (size_t k = 0; k < 4 * np; k++)
        ok &= add_to(&sum.vertices, uf_find(corners, k) == k);
    for (size_t p = 0; p < np && ok; p++) {
        tess_counts one;
        patch_counts(t, corners, p, &one);
        ok = add_to(&sum.vertices, one.vertices) && add_to(&sum.triangles, one.triangles) &&
             add_to(&sum.strips, one.strips) && add_to(&sum.strip_indices, one.strip_indices);
    }
    free(corners);
    if (!ok)
        return BS_ERR_SIZE;
    if (!t->strips)
        sum.strips = sum.strip_indices = 0;
    *c = sum;
    return BS_OK;
}
