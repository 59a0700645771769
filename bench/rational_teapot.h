/* The benchmarks' rational teapot: a bicubic teapot patch with the same net and weight
 * 1 + 0.5 (k % 3) on control point k (NULL on failure). */
#ifndef BENCH_RATIONAL_TEAPOT_H
#define BENCH_RATIONAL_TEAPOT_H

#include <bezsurf.h>

static inline bs_patch *rational_copy(const bs_patch *q)
{
    double ctrl[16 * 3], w[16];
    if (bs_patch_get_ctrl(q, ctrl, 48, NULL, 0) != BS_OK)
        return NULL;
    for (size_t k = 0; k < 16; k++)
        w[k] = 1.0 + 0.5 * (double)(k % 3);
    bs_patch *p;
    return bs_patch_create(3, 3, 3, ctrl, w, &p) == BS_OK ? p : NULL;
}

#endif
