/*
 * Ops layer, private to lib/ops/: nets as stacks of curves. Every exact operation (split,
 * sub-patch, elevation, hodograph, iso-curve) is a curve operation applied to each row or column
 * of the patch's homogeneous net; these helpers do the walking. Not installed.
 */
#ifndef BEZSURF_OPS_INTERNAL_H
#define BEZSURF_OPS_INTERNAL_H

#include "core/internal.h"

/* ---- Curve operations applied fibre by fibre to coordinate-major nets (lib/ops/fiber.c) ----
 * A net here is ncoord planes of (deg_u+1)(deg_v+1) doubles, as struct bs_patch's hom. A fibre is
 * one row of a plane along a direction: fixed j for BS_DIR_U (index i), fixed i for BS_DIR_V. */
#define BSI_FIBER_MAX (2 * BS_MAX_DEGREE + 1)

/* One coordinate of a curve: in[0..deg_in] -> out[0..deg_out] (deg_out < BSI_FIBER_MAX). */
typedef void (*bsi_fiber_op)(const double *in, size_t deg_in, double *out, size_t deg_out,
                             const void *ctx);

/* Apply op along dir to every fibre of every plane; out has degree deg_out along dir. */
void bsi_net_map(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                 size_t deg_out, bsi_fiber_op op, const void *ctx, double *out);

/* Copy fibre positions first..first+deg_out along dir of every plane into a net of degree deg_out. */
void bsi_net_slice(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                   size_t first, size_t deg_out, double *out);

/* Size in doubles of a net with ncoord planes and the given degrees. */
static inline size_t bsi_net_size(size_t ncoord, size_t deg_u, size_t deg_v)
{
    return ncoord * (deg_u + 1) * (deg_v + 1);
}

/* Raise a net's degree along dir by raise (deg + raise <= BS_MAX_DEGREE), writing a net of degree
 * deg + raise along dir to out (lib/ops/elevate.c). BS_ERR_NO_MEMORY on failure. */
bs_status bsi_elevate_net(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                          size_t raise, double *out);

#endif
