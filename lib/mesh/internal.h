/*
 * Mesh layer, private to lib/mesh/: the mesh object, filled by the tessellator and read by the
 * accessors and the exporters. Not installed.
 */
#ifndef BEZSURF_MESH_INTERNAL_H
#define BEZSURF_MESH_INTERNAL_H

#include "core/internal.h"

/* ---- Meshes (lib/mesh/mesh.c); filled by the tessellator (lib/mesh/tess*.c), read by the exporters ----
 * Arrays are packed: pos, nrm 3 per vertex, uv 2 per vertex, tri 3 per triangle; strip k is
 * strip_idx[strip_start[k] .. strip_start[k+1]). A triangle corner's (u,v) on the triangle's
 * patch is its vertex's uv, except for the corners listed in ascending order in xcorner (index
 * 3 * triangle + corner) with their own (u,v) in xuv (2 each): corners on a shared edge that the
 * neighbour's parameters own, and at poles. Every array is its own malloc block (NULL when empty)
 * freed by bs_mesh_destroy(). */
struct bs_mesh {
    size_t nvert, ntri, nstrip, nstrip_idx, nx;
    double *pos, *nrm, *uv, *xuv;
    size_t *xcorner;
    uint32_t *vpatch, *tri, *tpatch, *strip_idx, *strip_start;
};

#endif
