/* Drawing for `bezsurf render --rays`: one ray per sample of the raster, cast at the patches
 * through a locator (no tessellation) and shaded with the exact normal at the hit, with the same
 * camera, depth and lights as the tessellated drawing. */
#ifndef BEZSURF_TOOLS_RAYCAST_H
#define BEZSURF_TOOLS_RAYCAST_H

#include "raster.h"

#include <bezsurf.h>

/* Cast the rays of every sample of r (framed already) at the surface L holds, whose coordinates
 * are the picture's divided by unit (a power of two), and shade the hits in the colour rgb
 * (0..1); *hits receives their number. BS_OK or the locator's status. */
bs_status raycast_draw(raster *r, const bs_locator *L, double unit, const double rgb[3], size_t *hits);

#endif
