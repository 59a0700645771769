/*
 * The edge phase's helpers (tess_edges.c, tess_curve.c, tess_poles.c), private to them: trims
 * carried onto their faces as 3-D curves, and the vertices the phase makes.
 */
#ifndef BEZSURF_MODEL_TESS_EDGE_H
#define BEZSURF_MODEL_TESS_EDGE_H

#include "model/tess.h"

typedef struct curve3 {
    const bs_model *m;
    size_t face;
    const bsi_curve *uv;
    double t0, t1;     /* the trim's range */
} curve3;

/* The trim's (u, v) at t and its point on the face: 1, or 0 when off the face. */
int bsi_tm_curve_at(const curve3 *c, double t, double *uv, double *p);
void bsi_tm_curve_init(curve3 *c, const tm_job *j, size_t t);
/* The parameter in [lo, hi] (either order) of c's point nearest p, from guess (Gauss-Newton). */
double bsi_tm_project(const curve3 *c, const double *p, double lo, double hi, double guess);
bs_status bsi_tm_new_vertex(tm_edges *e, const double *p, uint32_t face, const double *uv, uint32_t *id);
/* A model vertex at p: an existing one within j->merge, else a new one; *grade its grading
 * (INFINITY in the first pass). */
bs_status bsi_tm_model_vertex(tm_job *j, const double *p, uint32_t face, const double *uv, uint32_t *id,
                              double *grade);
/* 1 when trim t's image is within j->merge of one point, *P. */
int bsi_tm_is_pole(const tm_job *j, size_t t, double *P);
/* A pole trim's samples: uniform in its parameter, all the pole's vertex. */
bs_status bsi_tm_sample_pole(tm_job *j, size_t t, const double *P);
/* The point X where faces fa and fb meet, from (u, v) uva on fa and uvb on fb near it, both
 * moved there: 1, or 0 where Newton does not bring the two points within eps (nearly tangent
 * faces, poles, off a face). */
int bsi_tm_meet(const bs_model *m, size_t fa, double *uva, size_t fb, double *uvb, double eps, double *X);
/* e->grade from the samples of a first pass. */
bs_status bsi_tm_grading(tm_edges *e);

#endif
