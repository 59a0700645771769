/* Diverging colour map: see colormap.h. */
#include "colormap.h"

#include <math.h>

void colormap_diverging(double t, double rgb[3])
{
    static const double neg[3] = {0.23, 0.30, 0.75}, zero[3] = {0.87, 0.87, 0.87}, pos[3] = {0.71, 0.02, 0.15},
                        undefined[3] = {0.45, 0.45, 0.45};
    if (isnan(t)) {
        for (int k = 0; k < 3; k++)
            rgb[k] = undefined[k];
        return;
    }
    double a = fmin(1.0, fabs(t));
    const double *end = t < 0 ? neg : pos;
    for (int k = 0; k < 3; k++)
        rgb[k] = (1.0 - a) * zero[k] + a * end[k];
}
