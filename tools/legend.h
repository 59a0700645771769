/* The legend of a colour-mapped picture: the name of the quantity, a colour bar from +R at the top
 * through 0 to -R at the bottom, and those three values written beside it, in a strip on the right
 * of the picture. */
#ifndef BEZSURF_TOOLS_LEGEND_H
#define BEZSURF_TOOLS_LEGEND_H

#include <stddef.h>

/* Width in pixels of the legend's strip in a w x h picture; 0 if the picture is too small to hold
 * one (narrower than about 240 pixels or lower than 100). */
size_t legend_strip(size_t w, size_t h);

/* Draw the legend into the strip of the w x h RGB picture (3 bytes a pixel). */
void legend_draw(unsigned char *rgb, size_t w, size_t h, const char *title, double range);

#endif
