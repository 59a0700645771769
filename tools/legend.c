/* Legend of a colour-mapped picture: see legend.h. The bar spans 15% to 85% of the height. */
#include "legend.h"
#include "colormap.h"
#include "font.h"
#include "raster.h"

#include <stdio.h>

#define LABEL_CHARS 9 /* "-1.23e-05" */

/* Dots of the font in pixels: 1 up to 449 pixels of height, 2 up to 749, ... */
static size_t dot(size_t h) { return (h + 150) / 300 > 1 ? (h + 150) / 300 : 1; }

size_t legend_strip(size_t w, size_t h)
{
    size_t s = dot(h), strip = 6 * s + 8 * s + 4 * s + (6 * LABEL_CHARS - 1) * s + 6 * s;
    return h >= 100 && 3 * strip <= w ? strip : 0;
}

static void label(unsigned char *rgb, size_t w, size_t h, size_t x, size_t y_mid, double value, size_t s)
{
    static const unsigned char ink[3] = {20, 20, 20};
    char text[32];
    snprintf(text, sizeof text, "%.3g", value);
    font_draw(rgb, w, h, x, y_mid - 7 * s / 2, text, s, ink);
}

void legend_draw(unsigned char *rgb, size_t w, size_t h, const char *title, double range)
{
    size_t strip = legend_strip(w, h), s = dot(h);
    if (strip == 0)
        return;
    static const unsigned char ink[3] = {20, 20, 20}, frame[3] = {110, 110, 110};
    size_t x0 = w - strip + 6 * s, x1 = x0 + 8 * s, y0 = h * 15 / 100, y1 = h * 85 / 100;
    font_draw(rgb, w, h, x0, y0 - 12 * s, title, s, ink);
    for (size_t y = y0 - 1; y <= y1 + 1; y++)
        for (size_t x = x0 - 1; x <= x1; x++) {
            unsigned char *px = rgb + 3 * (y * w + x);
            if (y < y0 || y > y1 || x < x0 || x == x1) {
                px[0] = frame[0], px[1] = frame[1], px[2] = frame[2];
                continue;
            }
            double c[3];
            colormap_diverging(1.0 - 2.0 * (double)(y - y0) / (double)(y1 - y0), c);
            for (int k = 0; k < 3; k++)
                px[k] = raster_to_byte(c[k]);
        }
    size_t xt = x1 + 4 * s;
    label(rgb, w, h, xt, y0, range, s);
    label(rgb, w, h, xt, (y0 + y1) / 2, 0.0, s);
    label(rgb, w, h, xt, y1, -range, s);
}
