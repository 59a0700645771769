/* Lines that `bezsurf render` draws over the surface: the patches' control nets (--nets) and the
 * triangles' edges (--wire). */
#ifndef BEZSURF_TOOLS_LINE_DRAW_H
#define BEZSURF_TOOLS_LINE_DRAW_H

#include "raster.h"

#include <bezsurf.h>
#include <stdint.h>

/* Every patch's control net: its rows and columns in dark red, its points as dots. */
void draw_nets(raster *r, const bs_surface *s);

/* Every triangle's edges, thin and dark (an edge shared by two triangles is drawn twice, alike);
 * pos holds 3 coordinates a vertex, tri 3 vertex indices a triangle. */
void draw_wire(raster *r, const double *pos, const uint32_t *tri, size_t nt);

#endif
