/* The diverging colour map of curvature pictures: blue for negative, light grey at 0, red for
 * positive, symmetric around 0; a darker grey for values that are not numbers. */
#ifndef BEZSURF_TOOLS_COLORMAP_H
#define BEZSURF_TOOLS_COLORMAP_H

/* Colour (linear, 0..1) of t in [-1, 1] (clamped outside); NaN gives the grey of undefined values. */
void colormap_diverging(double t, double rgb[3]);

#endif
