/*
 * Surface layer, shared with the layers above it (bspline, continuity, io, mesh, query): taking
 * patches in whole, and which patch sides of a surface are shared with a neighbour, and how.
 * Not installed.
 */
#ifndef BEZSURF_SURFACE_INTERNAL_H
#define BEZSURF_SURFACE_INTERNAL_H

#include "core/internal.h"

/* Append n patches to s, passing their ownership to s: all of them, or on failure none
 * (BS_ERR_INCOMPATIBLE when a dim differs from the surface's or each other's, BS_ERR_SIZE past
 * UINT32_MAX patches, BS_ERR_NO_MEMORY), the patches then still the caller's. */
bs_status bsi_surface_adopt(bs_surface *s, bs_patch **patches, size_t n);

/* ---- Topology of a surface: which patch sides are shared (lib/surface/topology.c) ----
 * Sides of the unit square, counter-clockwise; t is the side's own parameter. */
#define BSI_SIDE_V0 0 /* v = 0, t = u */
#define BSI_SIDE_U1 1 /* u = 1, t = v */
#define BSI_SIDE_V1 2 /* v = 1, t = u */
#define BSI_SIDE_U0 3 /* u = 0, t = v */
#define BSI_NO_PATCH UINT32_MAX

typedef struct bsi_side_link {
    uint32_t patch;          /* the neighbour across this side, or BSI_NO_PATCH (open side) */
    unsigned char side;      /* the neighbour's side (BSI_SIDE_*) */
    unsigned char reversed;  /* 1 if t here is 1 - t on the neighbour's side */
    unsigned char collapsed; /* 1 if the side's control points coincide (a pole): no neighbour */
} bsi_side_link;

typedef struct bsi_topology {
    size_t npatch;
    bsi_side_link *links; /* links[4*patch + side] */
} bsi_topology;

/* Match the sides of all patches of s whose boundary control points agree within tol (absolute,
 * per coordinate). BS_ERR_NO_MEMORY on failure (out is then empty). */
bs_status bsi_topology_build(const bs_surface *s, double tol, bsi_topology *out);
void bsi_topology_free(bsi_topology *t);

#endif
