/*
 * Stages of the computed trims (pcurve.c calls pcurve_point.c): one surface seen in a face's
 * native (u, v), evaluated with its first partials and projected onto, and the 3-D edge evaluated
 * with its derivative. Private to lib/model/.
 */
#ifndef BEZSURF_MODEL_PCURVE_INTERNAL_H
#define BEZSURF_MODEL_PCURVE_INTERNAL_H

#include "model/internal.h"

/* A face's surface in native parameters: closed forms (def of kind CYLINDER .. TORUS), else the
 * patches s[first ..] over the canonical axes au, av (patch (i, j) = first + i * av->n + j). */
typedef struct bsi_pc_surf {
    const bsi_surface_def *def; /* closed forms, or NULL */
    const bs_surface *s;
    size_t first;
    const bsi_axis *au, *av;
    int swap;                   /* native (u, v) = canonical (v, u) */
    double box[4];              /* native u0 u1 v0 v1 the patches cover (unused by closed forms) */
    double period[2];           /* native periods, 0 if none */
    double scale;               /* a length of the surface's size, for relative thresholds */
} bsi_pc_surf;

#define BSI_PC_POLE_U 1 /* native u undefined at the point (a sphere's or cone's pole) */
#define BSI_PC_POLE_V 2

/* 1 when def has closed forms (CYLINDER, CONE, SPHERE, TORUS). */
int bsi_pc_closed_form(const bsi_surface_def *def);
/* Canonical periods of the closed-form kinds (2 pi for angles of closed directions). */
void bsi_pc_periods(const bsi_surface_def *def, double *pu, double *pv);
/* The point and native partials at native uv: 1, or 0 outside the patches. */
int bsi_pc_eval(const bsi_pc_surf *S, const double *uv, double *p, double *du, double *dv);
/* The foot of q on the surface: native uv with periodic directions unwrapped nearest start (when
 * start is not NULL; it is also the Newton start on patches), the distance and the BSI_PC_POLE_*
 * flags of the foot. With patches: Newton from start, accepted when it converges within tol of
 * q; otherwise (or with no start) the certified closest point over all patches.
 * BS_ERR_NO_MEMORY, BS_ERR_DOMAIN (no patch answers). */
bs_status bsi_pc_project(const bsi_pc_surf *S, const double *q, const double *start, double tol,
                         double *uv, double *dist, int *pole);
/* The 3-D edge's point and derivative d/dt at native t: 1, or 0 outside its range. At a break
 * between pieces the derivative is the later piece's, the earlier one's when left is 1. */
int bsi_pc_edge(const bsi_curve *c, double t, int left, double *p, double *dp);

/* The trim of edge on S (bsi_pcurve_project): the first foot near hint (NULL: anywhere), then
 * without a hint periodic directions placed by whole periods into place_box (NULL: left). */
bs_status bsi_pc_fit(const bsi_pc_surf *S, const bsi_curve *edge, const double *hint,
                     const double *place_box, double tol, bsi_trim *out);

/* The canonical domain of a surface of patches (BSPLINE, REVOLUTION, EXTRUSION) when the caller
 * gives no box; edge bounds an extrusion's v. BS_ERR_DOMAIN without a curve or a direction. */
bs_status bsi_pc_default_box(const bsi_surface_def *def, const bsi_curve *edge, double *box);

#endif
