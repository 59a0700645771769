/* Ray-cast drawing: see raycast.h. The rays go to the locator a row of samples at a time. */
#include "raycast.h"

#include <math.h>
#include <stdlib.h>

bs_status raycast_draw(raster *r, const bs_locator *L, double unit, const double rgb[3], size_t *hits)
{
    size_t W = r->W;
    double *org = malloc(3 * W * sizeof(double)), *dir = malloc(3 * W * sizeof(double));
    double *t = malloc(W * sizeof(double)), *nrm = malloc(3 * W * sizeof(double));
    uint32_t *patch = malloc(W * sizeof(uint32_t));
    bs_status st = org && dir && t && nrm && patch ? BS_OK : BS_ERR_NO_MEMORY;
    ptrdiff_t s3 = 3 * sizeof(double);
    const bs_cview ov[3] = {{org, W, s3}, {org + 1, W, s3}, {org + 2, W, s3}};
    const bs_cview dv[3] = {{dir, W, s3}, {dir + 1, W, s3}, {dir + 2, W, s3}};
    const bs_view tv = {t, W, sizeof(double)};
    const bs_view nv[3] = {{nrm, W, s3}, {nrm + 1, W, s3}, {nrm + 2, W, s3}};
    *hits = 0;
    for (size_t y = 0; st == BS_OK && y < r->H; y++) {
        for (size_t x = 0; x < W; x++) {
            raster_ray(r, x, y, org + 3 * x, dir + 3 * x);
            for (int c = 0; c < 3; c++) /* into the locator's coordinates (unit a power of two) */
                org[3 * x + (size_t)c] /= unit;
        }
        st = bs_locator_intersect(L, W, ov, dv, NULL, patch, NULL, &tv, nv);
        for (size_t x = 0; st == BS_OK && x < W; x++)
            if (patch[x] != UINT32_MAX && isfinite(t[x])) {
                raster_put(r, x, y, r->reach - t[x] * unit, nrm + 3 * x, rgb);
                ++*hits;
            }
    }
    free(org);
    free(dir);
    free(t);
    free(nrm);
    free(patch);
    return st;
}
