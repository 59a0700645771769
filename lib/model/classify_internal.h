/*
 * Stages of the classification of face parameters (classify.c calls classify_near.c): the
 * segments of 2-D trims cut and evaluated on homogeneous points, and the test of 3-D nearness to
 * the boundary. Private to lib/model/; the method is described at the top of classify.c.
 */
#ifndef BEZSURF_MODEL_CLASSIFY_INTERNAL_H
#define BEZSURF_MODEL_CLASSIFY_INTERNAL_H

#include "model/internal.h"

#define BSI_SEG_MAX ((BS_MAX_DEGREE + 1) * 3) /* a 2-D segment's homogeneous points */

/* min and max without the library calls (no NaN reaches them) */
static inline double bsi_dmin(double a, double b)
{
    return a < b ? a : b;
}

static inline double bsi_dmax(double a, double b)
{
    return a > b ? a : b;
}

/* Segment k of a 2-D curve: (degree + 1) homogeneous points (w x, w y, w). */
static inline const double *bsi_trim_segment(const bsi_curve *c, size_t k)
{
    return c->hom + k * (c->degree + 1) * 3;
}

/* The piece [s0, s1] (0 <= s0 < s1 <= 1) of the degree-p segment seg into out. */
void bsi_seg_piece(const double *seg, size_t p, double s0, double s1, double *out);
/* The halves of the degree-p piece h at its middle into lo and hi, either of which may be h. */
void bsi_seg_halve(const double *h, size_t p, double *lo, double *hi);
/* Room for the pieces of a segment up to cubic waiting in a halving search depth levels deep,
 * which the searches keep on the C stack (higher degrees take a heap block). */
#define BSI_CUBIC_PIECES(depth) ((size_t)((depth) + 2) * 4 * 3)
/* The point at s of a degree-p segment: u and v. */
void bsi_seg_point(const double *seg, size_t p, double s, double *xy);
/* 1 when the point of face f at native (u, v) (in the face's box) is within tol in 3-D of a trim
 * that bounds the face (seams too when seams is 1), found by a certified branch and bound. */
int bsi_face_near_boundary(const bs_model *m, size_t f, double u, double v, double tol, int seams);

#endif
