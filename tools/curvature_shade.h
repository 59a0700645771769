/* Curvature as colours for `bezsurf render --curvature`: the mean or Gaussian curvature at each
 * vertex of a tessellation, a robust symmetric colour range, and the vertex colours. */
#ifndef BEZSURF_TOOLS_CURVATURE_SHADE_H
#define BEZSURF_TOOLS_CURVATURE_SHADE_H

#include <bezsurf.h>

/* The mean (gauss 0) or Gaussian (gauss 1) curvature at each vertex of m, a tessellation of s,
 * on the patch the vertex was evaluated on and at its (u,v); NaN where it is undefined. out has
 * room for bs_mesh_vertex_count(m) values. BS_OK or the library's status. */
bs_status curvature_at_vertices(const bs_surface *s, const bs_mesh *m, int gauss, double *out);

/* The area each vertex stands for: a third of the areas of the triangles around it (packed
 * positions, 3 indices a triangle), into area[0..nv). */
void vertex_areas(const double *pos, size_t nv, const uint32_t *tri, size_t ntri, double *area);

/* Summary of n vertex values: R, the larger magnitude of their 5th and 95th percentiles weighted by
 * the vertices' areas (percentiles of the surface, not of the vertices, which the adaptive
 * tessellation crowds where the curvature is high; 0 when no value is a number), their least and
 * greatest value, and how many are NaN. */
typedef struct curvature_range {
    double range, min, max;
    size_t undefined;
} curvature_range;

/* The summary, or -1 if out of memory. */
int curvature_summary(const double *val, const double *area, size_t n, curvature_range *out);

/* Vertex colours (3 packed, 0..1) of the diverging map for values over [-range, range]. */
void curvature_colors(const double *val, size_t n, double range, double *rgb);

#endif
