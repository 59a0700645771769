/*
 * Tessellation by recursive subdivision (BS_TESS_SUBDIVIDE), private to lib/mesh/. Phases, on one
 * `subdiv`:
 *   1. trees   (subdiv_tree.c)  each patch cut into a tree of sub-rectangles (halves or thirds per
 *                               direction) until a bound on the triangles' chordal error meets the
 *                               tolerance; the leaves are kept
 *   2. weld    (subdiv_weld.c)  the leaves' corners of each patch, plus the corners its neighbour
 *                               puts on a shared side, become points; points that are one place
 *                               (shared sides, poles) are merged; vertex ids
 *   3. emit    (subdiv_emit.c)  each leaf triangulated with every point on its sides, so leaves of
 *                               different size meet without T-junctions; counted first, then emitted
 *                               into the output of mesh/tess.h and finished as the other methods
 * Parameters are integers k on a grid of SD_N steps per patch direction (u = k / SD_N): splits into
 * halves and thirds stay on the grid, and t on one side of a shared edge is SD_N - t on the other,
 * exactly. Not installed.
 */
#ifndef BEZSURF_MESH_SUBDIV_H
#define BEZSURF_MESH_SUBDIV_H

#include "mesh/tess.h"

#include <stddef.h>
#include <stdint.h>

/* 2^10 * 3^6: every leaf width of a tree whose total split per direction is at most
 * BS_TESS_MAX_RATE (a product of 2s and 3s) is a whole number of steps. */
#define SD_N ((uint32_t)746496)
/* Bits of one parameter in a point key (SD_N < 2^20). */
#define SD_BITS 20
#define SD_KEY(a, b) (((uint64_t)(a) << SD_BITS) | (uint64_t)(b))

typedef struct sd_leaf { uint32_t u0, u1, v0, v1; } sd_leaf;

typedef struct subdiv {
    const bs_surface *s;
    size_t np;
    double tol;
    size_t max_tri;   /* 0, or refuse (BS_ERR_SIZE) as soon as the leaves surely give more triangles */
    size_t tri_lower; /* 2 per leaf that touches no pole and does not span its patch: a lower bound */
    size_t max_vert;  /* likewise for vertices */
    size_t vert_lower; /* leaves whose corner (u0,v0) is inside their patch: one vertex each */
    bsi_topology topo;
    /* phase 1: leaves of patch p are leaf[leaf0[p] .. leaf0[p+1]) */
    sd_leaf *leaf;
    size_t nleaf, leaf_cap;
    size_t *leaf0;
    /* phase 2: points of patch p are uv[pt0[p] .. pt0[p+1]), keys SD_KEY(u, v) ascending; vu holds
     * the same points as SD_KEY(v, u) << 24 | (index within the patch), ascending */
    uint64_t *uv, *vu;
    size_t *pt0;
    uint32_t *vupos;  /* per point: its place in vu, within the patch */
    uint32_t *corner; /* 4 per leaf: its corners (u0,v0) (u1,v0) (u1,v1) (u0,v1), points within the patch */
    size_t *parent;   /* union-find over all points; a set's root is its lowest point */
    uint32_t *vid;    /* vertex id of every point */
    unsigned char *kind; /* per leaf: how it is triangulated (subdiv_emit.c) */
    size_t *vert0;    /* np + 1: the points' vertices evaluated on patch p */
    size_t *cen0;     /* np + 1: the leaf centres' vertices of patch p (after all points') */
    size_t nvert, ntri;
} subdiv;

/* Phase 1: the leaves of every patch under tolerance s->tol. BS_ERR_SIZE past 2^31 leaves, or as
 * soon as s->tri_lower exceeds s->max_tri or s->vert_lower s->max_vert (when not 0). */
bs_status bsi_subdiv_trees(subdiv *s);
/* Phase 2: points, merges and vertex ids of points (s->vid); leaf kinds and centre vertices come
 * from bsi_subdiv_classify. */
bs_status bsi_subdiv_weld(subdiv *s);
/* Phase 3a: each leaf's triangulation, the vertex ids of leaf centres (s->nvert), and s->ntri for
 * the leaves whose triangles cannot degenerate. */
bs_status bsi_subdiv_classify(subdiv *s);
/* Phase 3b: with t == NULL add the triangles of the other leaves to s->ntri; else emit them into t. */
bs_status bsi_subdiv_emit(subdiv *s, tess *t);
/* (u,v) of the leaf centres' vertices into uv (2 per vertex, indexed by vertex id). */
void bsi_subdiv_centres(const subdiv *s, double *uv);
void bsi_subdiv_free(subdiv *s);

/* The whole method (subdiv.c), tol absolute: the counts only (past a budget, lower bounds already
 * over it, found as soon as the trees show it), or the mesh, refused with BS_ERR_SIZE before the
 * mesh's arrays are allocated when it would have more than max_vertices vertices or max_triangles
 * triangles (0: no budget) or exceed 32-bit indices; vertices sampled on up to `threads` threads
 * (0 = one per online CPU). */
bs_status bsi_tess_subdivide_count(const bs_surface *s, double tol, size_t max_vertices, size_t max_triangles,
                                   size_t *vertices, size_t *triangles);
bs_status bsi_tess_subdivide(const bs_surface *s, double tol, int flags, size_t max_vertices, size_t max_triangles,
                             size_t threads, bs_mesh **out);

#endif
