/* Drawing for `bezsurf render --closest N`: a cloud of points around the surface, each joined to
 * its closest point on the surface (through a locator), so the projections can be seen. */
#ifndef BEZSURF_TOOLS_CLOSEST_DRAW_H
#define BEZSURF_TOOLS_CLOSEST_DRAW_H

#include "raster.h"

#include <bezsurf.h>

/* n points spread (deterministically) over the box lo..hi enlarged by a fifth on every side, each
 * drawn as a dark dot with a line to its closest point of s, a red dot. BS_OK or the locator's
 * status (nothing drawn then). */
bs_status closest_draw(raster *r, const bs_surface *s, size_t n, const double lo[3], const double hi[3]);

#endif
