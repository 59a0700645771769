/*
 * bs_model_from_surface: each patch an untrimmed Bezier face on (0,1)^2 with a loop of its four
 * sides, sides shared in the surface's topology (lib/surface/topology.c) joined as one edge,
 * collapsed sides (poles) left without an edge, one shell per connected set of patches.
 */
#include "model/internal.h"

#include <math.h>
#include <stdlib.h>

/* The four sides of the unit square counter-clockwise, in BSI_SIDE_* order: start and direction. */
static const double side_start[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
static const double side_dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

static size_t find_root(size_t *parent, size_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Shell of each patch: the connected sets of the side links, numbered in patch order. */
static bs_status shells_of(const bsi_topology *topo, size_t n, size_t *shell)
{
    size_t *parent = malloc(n * sizeof *parent);
    if (parent == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t p = 0; p < n; p++)
        parent[p] = p;
    for (size_t p = 0; p < n; p++)
        for (int side = 0; side < 4; side++) {
            uint32_t q = topo->links[4 * p + (size_t)side].patch;
            if (q != BSI_NO_PATCH) {
                size_t a = find_root(parent, p), b = find_root(parent, q);
                parent[a > b ? a : b] = a > b ? b : a;
            }
        }
    size_t next = 0;
    for (size_t p = 0; p < n; p++) {
        size_t r = find_root(parent, p);
        shell[p] = r == p ? next++ : shell[r];
    }
    free(parent);
    return BS_OK;
}

/* The face of patch p: four line trims, each side's edge shared with its neighbour's. */
static bs_status add_patch_face(bs_model *m, const bs_surface *s, const bsi_topology *topo,
                                uint32_t *side_edge, size_t p, size_t shell)
{
    bsi_trim trims[4];
    bs_status st = BS_OK;
    int made = 0;
    for (int side = 0; side < 4; side++, made++) {
        const bsi_side_link *link = &topo->links[4 * p + (size_t)side];
        trims[side].reversed = 0;
        trims[side].computed = 0;
        trims[side].edge = BSI_NO_EDGE;
        if ((st = bsi_curve_line(2, side_start[side], side_dir[side], 0.0, 1.0, &trims[side].uv)) != BS_OK)
            break;
        if (link->collapsed)
            continue;
        uint32_t *mine = &side_edge[4 * p + (size_t)side];
        /* NOLINTNEXTLINE(clang-analyzer-core.UndefinedBinaryOperatorResult): all 4n set after the allocation */
        if (*mine == BSI_NO_EDGE && (st = bsi_model_add_edge(m, mine)) != BS_OK) {
            bsi_curve_free(&trims[side].uv);
            break;
        }
        if (link->patch != BSI_NO_PATCH)
            side_edge[4 * (size_t)link->patch + link->side] = *mine;
        trims[side].edge = *mine;
    }
    if (st != BS_OK) {
        for (int k = 0; k < made; k++)
            bsi_curve_free(&trims[k].uv);
        return st;
    }
    size_t four = 4;
    bsi_face_spec spec = {0};
    spec.patch = bs_surface_get(s, p);
    spec.shell = shell;
    spec.trims = trims;
    spec.ntrim = 4;
    spec.loop_len = &four;
    spec.nloop = 1;
    return bsi_model_add_face(m, &spec, NULL);
}

/* Matching tolerance of shared sides: relative to the surface's size, as the tessellator's. */
static double side_tolerance(const bs_surface *s)
{
    double size = 0.0;
    for (size_t p = 0; p < bs_surface_count(s); p++) {
        double lo[3], hi[3];
        if (bs_patch_bounds(bs_surface_get(s, p), lo, hi) == BS_OK)
            for (int c = 0; c < 3; c++)
                size = fmax(size, fmax(fabs(lo[c]), fabs(hi[c])));
    }
    return 1e-12 * size;
}

bs_status bs_model_from_surface(const bs_surface *s, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (s == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    size_t n = bs_surface_count(s);
    if (n == 0)
        return BS_ERR_SIZE;
    if (bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    bsi_topology topo;
    bs_status st = bsi_topology_build(s, side_tolerance(s), &topo);
    if (st != BS_OK)
        return st;
    bs_model *m = NULL;
    size_t *shell = malloc(n * sizeof *shell);
    uint32_t *side_edge = malloc(4 * n * sizeof *side_edge);
    if (shell == NULL || side_edge == NULL)
        st = BS_ERR_NO_MEMORY;
    for (size_t k = 0; side_edge != NULL && k < 4 * n; k++)
        side_edge[k] = BSI_NO_EDGE;
    if (st == BS_OK)
        st = shells_of(&topo, n, shell);
    if (st == BS_OK)
        st = bsi_model_create(&m);
    for (size_t p = 0; st == BS_OK && p < n; p++)
        st = add_patch_face(m, s, &topo, side_edge, p, shell[p]);
    if (st == BS_OK)
        st = bsi_model_finish(m);
    free(shell);
    free(side_edge);
    bsi_topology_free(&topo);
    if (st != BS_OK) {
        bs_model_destroy(m);
        return st;
    }
    *out = m;
    return BS_OK;
}
