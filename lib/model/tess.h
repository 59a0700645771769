/*
 * Tessellation of a model (bs_model_tessellate), private to lib/model/. Phases:
 *   1. edges (tess_edges.c)  every model edge sampled once, adaptively, on its first trim; the
 *                            other trims of the edge get the same 3-D points (their parameters
 *                            found by projection), so the faces on both sides share its vertices
 *   2. faces (tess_face.c)   each face triangulated in its native parameters, scaled to a metric
 *                            of the surface: its trim loops' samples as constraints of a
 *                            constrained Delaunay triangulation (cdt.c), refined inside by
 *                            points where a triangle errs or is too thin
 *   3. mesh  (tess_model.c)  vertices, normals, triangles outward, corner parameters
 */
#ifndef BEZSURF_MODEL_TESS_H
#define BEZSURF_MODEL_TESS_H

#include "model/internal.h"

#include <stddef.h>
#include <stdint.h>

#define TM_NONE UINT32_MAX

/* A mesh vertex of the edge phase: its point, and the face and native (u, v) it was made on. */
typedef struct tm_vertex {
    double p[3];
    uint32_t face;
    double uv[2];
} tm_vertex;

/* The samples of one trim, ascending in its own parameter: sample k has native (u, v)
 * uv[2 (first + k) ..] on the trim's face and vertex vid[first + k]. The (u, v) are the trim's,
 * or where the edge's faces meet when the file wrote its trims apart (tess_meet.c). */
typedef struct tm_trim {
    size_t first, count;
    int pole;          /* the trim's 3-D image is one point */
} tm_trim;

typedef struct tm_face_scale {
    double su, sv;     /* the metric: native u and v times these are roughly lengths */
} tm_face_scale;

typedef struct tm_edges {
    tm_vertex *vert;
    size_t nvert, vert_cap;
    uint32_t *model;       /* the model vertices (edge ends, poles), merged within j->merge */
    size_t nmodel, model_cap;
    double *grade;         /* NULL, or per model vertex (in the order of model[]) the length of
                              the shortest segment that ends there: no segment of an edge at
                              distance d from its end may be longer than grade + d */
    double *uv;
    uint32_t *vid;
    size_t nsample, sample_cap;
    tm_trim *trim;         /* one per trim of the model */
    uint32_t *trim_face;   /* the face of each trim */
} tm_edges;

/* One face's triangles: corners are edge-phase vertex ids, or TM_INNER | k for the face's own
 * k-th inner point; corner (u, v) are native. */
#define TM_INNER 0x80000000u
typedef struct tm_face_mesh {
    uint32_t *tri;     /* 3 per triangle, counter-clockwise in (u, v) */
    double *tuv;       /* 6 per triangle */
    size_t ntri;
    double *inner;     /* 5 per inner point: u, v, x, y, z */
    size_t ninner;
    double min_angle;  /* smallest corner angle in the metric (radians) */
} tm_face_mesh;

typedef struct tm_job {
    const bs_model *m;
    double tol;            /* absolute */
    double diag;           /* the model's diagonal */
    double merge;          /* points closer than this are one vertex */
    size_t max_points;     /* per face, 0: none */
    tm_face_scale *scale;  /* per face */
    tm_edges edges;
    tm_face_mesh *face;    /* per face */
} tm_job;

/* Distance of two 3-D points. */
double bsi_tm_dist3(const double *a, const double *b);
/* The metric of each face. BS_ERR_NO_MEMORY. */
bs_status bsi_tm_scales(tm_job *j);
/* Phase 1. BS_ERR_NO_MEMORY, BS_ERR_SIZE. */
bs_status bsi_tm_edges(tm_job *j);
void bsi_tm_edges_free(tm_edges *e);
/* Phase 2 for face f into j->face[f]. BS_ERR_DOMAIN when its loops cannot be triangulated
 * (crossing or open), BS_ERR_SIZE past max_points, BS_ERR_NO_MEMORY. */
bs_status bsi_tm_face(tm_job *j, size_t f);
void bsi_tm_face_free(tm_face_mesh *fm);

#endif
