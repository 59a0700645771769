/*
 * B-spline layer, private to lib/bspline/: checked knot vectors, their spans, and the Bezier
 * points of one span. Not installed.
 */
#ifndef BEZSURF_BSPLINE_INTERNAL_H
#define BEZSURF_BSPLINE_INTERNAL_H

#include "surface/internal.h"

/* One direction of a B-spline: degree p, count control points, count + p + 1 knots t. */
typedef struct bsi_knots {
    size_t deg, count;
    const double *t;
    size_t nspan; /* knot intervals of positive length in the domain [t[deg], t[count]] */
} bsi_knots;

/* Check one direction (the rules of bezsurf/bspline.h: BS_ERR_DEGREE, BS_ERR_SIZE,
 * BS_ERR_DOMAIN) and count its spans into k. */
bs_status bsi_knots_check(size_t deg, size_t count, const double *t, bsi_knots *k);

/* Knot index i of each span, t[i] < t[i+1], in order: first[0 .. k->nspan). */
void bsi_knots_spans(const bsi_knots *k, size_t *first);

/* The Bezier points of span [t[i], t[i+1]) of the degree-p curve whose control point k has its
 * ncoord coordinates at in[k * in_step + c] (only k = i-p .. i are read): point m (0..p) is the
 * blossom at (t[i] repeated p - m times, t[i+1] m times), written to out[m * out_step + c]. */
void bsi_span_bezier(const double *t, size_t p, size_t i, const double *in, size_t in_step,
                     size_t ncoord, double *out, size_t out_step);

#endif
