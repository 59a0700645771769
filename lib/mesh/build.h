/*
 * Meshes built above the mesh layer (the model tessellator, lib/model/): arrays the caller filled,
 * laid out as struct bs_mesh describes (mesh/internal.h), handed over to a new mesh. Not installed.
 */
#ifndef BEZSURF_MESH_BUILD_H
#define BEZSURF_MESH_BUILD_H

#include "bezsurf.h"

#include <stddef.h>
#include <stdint.h>

typedef struct bsi_mesh_parts {
    size_t nvert, ntri, nx;
    double *pos, *nrm, *uv;  /* 3, 3 and 2 per vertex */
    uint32_t *vpatch;        /* per vertex */
    uint32_t *tri, *tpatch;  /* 3 per triangle, and 1 */
    size_t *xcorner;         /* nx corners (3 * triangle + corner, ascending) with their own uv */
    double *xuv;             /* 2 per listed corner */
} bsi_mesh_parts;

/* A mesh owning the parts' arrays (each its own malloc block or NULL; the parts are emptied
 * either way). BS_ERR_NO_MEMORY (the arrays freed). */
bs_status bsi_mesh_adopt(bsi_mesh_parts *parts, bs_mesh **out);
/* Free the arrays of parts not handed over and empty them. */
void bsi_mesh_parts_free(bsi_mesh_parts *parts);

#endif
