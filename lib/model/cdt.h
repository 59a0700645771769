/*
 * Constrained Delaunay triangulation in the plane, for meshing a face in its parameter domain
 * (tess_face.c). Points have integer coordinates below 2^30 in magnitude, so that the orientation
 * test is exact in 64-bit integers: the triangulation's topology never depends on rounding. The
 * in-circle test, which only decides which of two valid triangulations is kept, is taken in long
 * double. Private to lib/model/.
 *
 * Use: bsi_cdt_init (points 0, 1, 2 are a triangle enclosing every point of magnitude up to
 * BSI_CDT_RANGE), bsi_cdt_insert the boundary points, bsi_cdt_force each boundary segment, then
 * bsi_cdt_mark_inside; after that, bsi_cdt_insert with BSI_CDT_GUARDED adds points inside the
 * domain only (never across a constraint), for refinement.
 */
#ifndef BEZSURF_MODEL_CDT_H
#define BEZSURF_MODEL_CDT_H

#include "bezsurf.h"

#include <stddef.h>
#include <stdint.h>

#define BSI_CDT_NONE UINT32_MAX
/* Largest magnitude of a point's coordinates (the enclosing triangle stays within 2^30). */
#define BSI_CDT_RANGE ((int64_t)1 << 28)

typedef struct bsi_cdt_tri {
    uint32_t v[3];           /* counter-clockwise */
    uint32_t nb[3];          /* neighbour across the edge opposite v[i], or BSI_CDT_NONE */
    unsigned char fixed[3];  /* that edge is a constraint */
    unsigned char inside;    /* in the domain (bsi_cdt_mark_inside) */
    unsigned char dead;      /* slot free */
    unsigned char done;      /* for the caller: nothing more to refine here */
    uint32_t mark;           /* scratch stamp */
} bsi_cdt_tri;

typedef struct bsi_cdt {
    int64_t *q;              /* 2 per point */
    uint32_t *vtri;          /* a live triangle holding each point */
    size_t np, pcap, vcap;
    bsi_cdt_tri *t;
    size_t nt, tcap;
    uint32_t *spare;         /* dead triangle slots */
    size_t nspare, spare_cap;
    uint32_t last;           /* where the next walk starts */
    uint32_t stamp;
    /* scratch of one insertion */
    uint32_t *cav;
    size_t ncav, cav_cap;
    uint32_t *edge;          /* 4 per boundary edge: from, to, outer triangle, fixed */
    size_t nedge, edge_cap;
    uint32_t *fresh;         /* new triangles */
    size_t nfresh, fresh_cap;
    uint32_t *chain;         /* constraint recovery: the two chains */
    size_t chain_cap;
} bsi_cdt;

/* Outcomes of bsi_cdt_insert besides a status. */
#define BSI_CDT_ADDED   0
#define BSI_CDT_EXISTS  1   /* the point is already there: *id is it */
#define BSI_CDT_BLOCKED 2   /* guarded: outside the domain, on a constraint, or across one */

/* Modes of bsi_cdt_insert. */
#define BSI_CDT_FREE    0   /* before the constraints: anywhere inside the enclosing triangle */
#define BSI_CDT_GUARDED 1   /* after bsi_cdt_mark_inside: walk from `hint` without crossing a
                               constraint; refused where the point would fall on a constraint */

bs_status bsi_cdt_init(bsi_cdt *c);
void bsi_cdt_free(bsi_cdt *c);
/* Orientation of (a, b, p): > 0 counter-clockwise, 0 collinear, exact. */
int bsi_cdt_orient(const bsi_cdt *c, uint32_t a, uint32_t b, const int64_t *p);
/* Insert the point (x, y) (|x|, |y| <= BSI_CDT_RANGE). *outcome is BSI_CDT_*, *id the point's id.
 * BS_ERR_NO_MEMORY; BS_ERR_DOMAIN if the triangulation is found broken (an unrecoverable
 * rounding case), after which it may not be used. */
bs_status bsi_cdt_insert(bsi_cdt *c, int64_t x, int64_t y, int mode, uint32_t hint, uint32_t *id,
                         int *outcome);
/* Make the segment a-b (distinct points) an edge of the triangulation and a constraint; points
 * lying on it split it. BS_ERR_DOMAIN if it crosses another constraint; BS_ERR_NO_MEMORY. */
bs_status bsi_cdt_force(bsi_cdt *c, uint32_t a, uint32_t b);
/* Inside = reached from the enclosing triangle across an odd number of constraints.
 * BS_ERR_DOMAIN if that is ambiguous (constraints that do not close into loops). */
bs_status bsi_cdt_mark_inside(bsi_cdt *c);

#endif
