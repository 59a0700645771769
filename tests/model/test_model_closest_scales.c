/* Closest points on models over every scale and weight: the model of one random patch
 * (bs_model_from_surface: one face, its loop the patch's sides) against the patch itself. The
 * face is the whole patch, so the two locators answer the same closest point, each within
 * tau = 1e-9 (D + d) of the exact distance: their distances may differ by 2 tau at most. The
 * model's search takes the other road (boxes along the sides crossed by the trims, the search
 * along the trims), so this checks it against the surface's on polynomial and rational patches
 * of degrees 1 to 4, weights from 1 to a ratio of 1e6, coordinates from 1e-6 to 1e6 and far from
 * the origin, query points near and far. Neither may fail where the other answers. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PATCHES 240
#define QUERIES 50

static unsigned long long state = 0x9e3779b97f4a7c15ull;

static double uniform(void) /* in [0, 1) */
{
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(state >> 11) / 9007199254740992.0;
}

int main(void)
{
    static const double scales[] = {1e-6, 1.0, 1e6};
    size_t compared = 0, precision = 0;
    double worst = 0.0;
    size_t patches = bs_test_quick() ? PATCHES / 10 : PATCHES;
    for (size_t k = 0; k < patches; k++) {
        size_t m = 1 + (size_t)(uniform() * 4), n = 1 + (size_t)(uniform() * 4);
        double scale = scales[k % 3], offset = (k % 2) ? 1e3 * scale : 0.0;
        double ratio = k % 4 == 0 ? 1.0 : pow(10.0, 6.0 * uniform());
        double ctrl[25 * 3], w[25];
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                double *p = ctrl + 3 * (i * (n + 1) + j);
                p[0] = scale * ((double)i / (double)m + 0.2 * (uniform() - 0.5)) + offset;
                p[1] = scale * ((double)j / (double)n + 0.2 * (uniform() - 0.5)) - offset;
                p[2] = scale * 0.6 * (uniform() - 0.5);
                w[i * (n + 1) + j] = pow(ratio, uniform());
            }
        bs_patch *p = NULL;
        bs_surface *s = NULL;
        bs_model *model = NULL;
        bs_locator *Ls = NULL, *Lm = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, ratio > 1.0 ? w : NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_create(&s), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        CHECK_STATUS(bs_model_from_surface(s, &model), BS_OK);
        CHECK_STATUS(bs_locator_create(s, &Ls), BS_OK);
        CHECK_STATUS(bs_locator_create_model(model, &Lm), BS_OK);
        double diag = 0.0;
        for (size_t q = 0; q < QUERIES && Ls && Lm; q++) {
            /* near the patch (its box and just off it) or far away */
            double reach = q % 4 == 0 ? 30.0 : 1.5, x[3];
            x[0] = scale * reach * (uniform() - 0.3) + offset;
            x[1] = scale * reach * (uniform() - 0.3) - offset;
            x[2] = scale * reach * (uniform() - 0.5);
            bs_cview qv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
            double ds = NAN, dm = NAN;
            bs_view dsv = {&ds, 1, 0}, dmv = {&dm, 1, 0};
            bs_status a = bs_locator_closest_point(Ls, 1, qv, NULL, NULL, &dsv, NULL);
            bs_status b = bs_locator_closest_point(Lm, 1, qv, NULL, NULL, &dmv, NULL);
            CHECKF(a == b, "patch %zu query %zu: surface %s, model %s", k, q, bs_status_string(a),
                   bs_status_string(b));
            if (a != BS_OK || b != BS_OK) {
                precision++;
                continue;
            }
            if (diag == 0.0) { /* D of the contract: the box of the control points */
                double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
                for (size_t i = 0; i < (m + 1) * (n + 1); i++)
                    for (size_t c = 0; c < 3; c++)
                        lo[c] = fmin(lo[c], ctrl[3 * i + c]), hi[c] = fmax(hi[c], ctrl[3 * i + c]);
                diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                            (hi[2] - lo[2]) * (hi[2] - lo[2]));
            }
            double tau = 1e-9 * (diag + fmin(ds, dm));
            worst = fmax(worst, fabs(ds - dm) / tau);
            CHECKF(fabs(ds - dm) <= 2.0 * tau, "patch %zu (%zu x %zu, scale %g, weights to %g) query %zu: "
                   "surface %.17g, model %.17g", k, m, n, scale, ratio, q, ds, dm);
            compared++;
        }
        bs_locator_destroy(Lm);
        bs_locator_destroy(Ls);
        bs_model_destroy(model);
        bs_surface_destroy(s);
        bs_patch_destroy(p);
    }
    printf("%zu queries compared (%zu uncertified on both), worst difference %.3f tau\n", compared,
           precision, worst);
    CHECK(compared > patches * QUERIES * 9 / 10);
    return bs_test_exit("test_model_closest_scales");
}
