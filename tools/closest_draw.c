#include "closest_draw.h"

#include <stdlib.h>

/* A point of the cloud: coordinate c of point k from a splitmix64 stream, so the picture is the
 * same on every run. */
static double cloud_coord(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

bs_status closest_draw(raster *r, const bs_surface *s, size_t n, const double lo[3], const double hi[3])
{
    static const double query_ink[3] = {0.1, 0.1, 0.12}, line_ink[3] = {0.25, 0.3, 0.45},
                        foot_ink[3] = {0.75, 0.1, 0.08};
    double *q = malloc(6 * n * sizeof(double) + 1); /* n queries, then their n closest points */
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    unsigned long long state = 20261129;
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            double pad = 0.2 * (hi[c] - lo[c]);
            q[3 * k + (size_t)c] = lo[c] - pad + (hi[c] - lo[c] + 2 * pad) * cloud_coord(&state);
        }
    ptrdiff_t s3 = 3 * sizeof(double);
    bs_cview qv[3] = {{q, n, s3}, {q + 1, n, s3}, {q + 2, n, s3}};
    bs_view fv[3] = {{q + 3 * n, n, s3}, {q + 3 * n + 1, n, s3}, {q + 3 * n + 2, n, s3}};
    bs_locator *L = NULL;
    bs_status st = bs_locator_create(s, &L);
    if (st == BS_OK)
        st = bs_locator_closest_point(L, n, qv, NULL, NULL, NULL, fv);
    bs_locator_destroy(L);
    for (size_t k = 0; k < n && st == BS_OK; k++) {
        const double *a = q + 3 * k, *b = q + 3 * (n + k);
        raster_line(r, a, b, 1.0, line_ink);
        raster_line(r, a, a, 4.0, query_ink);
        raster_line(r, b, b, 4.0, foot_ink);
    }
    free(q);
    return st;
}
