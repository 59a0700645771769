/* The chordal error the adaptive tessellations promise, measured against the long-double oracle:
 * for the mesh tests that check a tolerance. */
#ifndef BS_TEST_CHORDAL_H
#define BS_TEST_CHORDAL_H

#include "mesh_data.h"
#include "reference.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>

/* The documented error: the largest distance between a point of a triangle and the surface at the
 * point's (u,v) (interpolated from the corners' (u,v) on the triangle's patch), over the 21 points
 * (i, j, k) / 5 of every triangle. */
static inline double chordal_error(const bs_surface *s, const mesh_data *d)
{
    static double store[65 * 65 * 3], wstore[65 * 65];
    long double worst = 0.0L;
    uint32_t last = UINT32_MAX;
    ref_net net = {0, 0, 3, store, NULL};
    for (size_t t = 0; t < d->nt; t++) {
        if (d->tpatch[t] != last) {
            const bs_patch *p = bs_surface_get(s, last = d->tpatch[t]);
            net.m = bs_patch_degree_u(p);
            net.n = bs_patch_degree_v(p);
            bs_patch_get_ctrl(p, store, 65 * 65 * 3, wstore, 65 * 65);
            net.w = bs_patch_is_rational(p) ? wstore : NULL;
        }
        const double *cu = d->cuv + 6 * t;
        for (int i = 0; i <= 5; i++)
            for (int j = 0; i + j <= 5; j++) {
                long double l[3] = {i / 5.0L, j / 5.0L, (5 - i - j) / 5.0L}, u = 0, v = 0, P[3] = {0, 0, 0}, S[3];
                for (int k = 0; k < 3; k++) {
                    u += l[k] * cu[2 * k];
                    v += l[k] * cu[2 * k + 1];
                    for (int c = 0; c < 3; c++)
                        P[c] += l[k] * d->pos[3 * (size_t)d->tri[3 * t + (size_t)k] + (size_t)c];
                }
                ref_eval(&net, u, v, S);
                long double e = sqrtl((S[0] - P[0]) * (S[0] - P[0]) + (S[1] - P[1]) * (S[1] - P[1]) +
                                      (S[2] - P[2]) * (S[2] - P[2]));
                worst = e > worst ? e : worst;
            }
    }
    return (double)worst;
}

#endif
