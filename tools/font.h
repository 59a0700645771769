/* A 5 x 7 bitmap font for the numbers and names written into pictures (digits, + - . e and the
 * letters of "H (mean)" and "K (Gauss)", the lower case letters); other characters are drawn as
 * blanks. */
#ifndef BEZSURF_TOOLS_FONT_H
#define BEZSURF_TOOLS_FONT_H

#include <stddef.h>

/* Width in pixels of text drawn at the given scale (each glyph 5 x 7 dots, one dot of spacing). */
size_t font_width(const char *text, size_t scale);

/* Draw text into a w x h RGB image (3 bytes a pixel), its top-left corner at (x, y), each dot
 * scale x scale pixels; what falls outside the image is not drawn. */
void font_draw(unsigned char *rgb, size_t w, size_t h, size_t x, size_t y, const char *text, size_t scale,
               const unsigned char color[3]);

#endif
