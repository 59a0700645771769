/*
 * Shared by the exact surfaces' two files (analytic.c: planes .. tori; analytic_sweep.c:
 * revolutions, extrusions, B-splines). Private to lib/model/.
 */
#ifndef BEZSURF_MODEL_ANALYTIC_H
#define BEZSURF_MODEL_ANALYTIC_H

#include "model/internal.h"

/* The quadratic arc of the unit circle from angle a0 to a1 (at most a half turn): control
 * points (cx[k], cy[k]) and weights w[k], k = 0..2, in the standard form (1, cos half, 1). */
void bsi_arc_points(double a0, double a1, double *cx, double *cy, double *w);
/* 1 when the frame's axes are orthonormal within 1e-9, right-handed, and its origin finite. */
int bsi_frame_valid(const bsi_frame *f);
/* Make patch (i, j) of a grid of au->n x av->n patches; BS_OK or the failure. */
typedef bs_status (*bsi_grid_patch_fn)(void *ctx, size_t i, size_t j, bs_patch **out);
/* Make every patch of the grid, then append them all to s (nothing appended on failure). */
bs_status bsi_patch_grid(bs_surface *s, const bsi_axis *au, const bsi_axis *av, void *ctx,
                         bsi_grid_patch_fn make);
/* bsi_surface_def_patches and bsi_surface_def_eval for REVOLUTION, EXTRUSION and BSPLINE. */
bs_status bsi_sweep_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                            bsi_axis *au, bsi_axis *av);
void bsi_sweep_eval(const bsi_surface_def *def, double u, double v, double *p);

#endif
