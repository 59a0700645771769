/* Rays down the normal at points next to a pole (a side of the net collapsed to one point) must
 * hit no later than their height above the point: the two patches of tests/hostile/pole_miss.py
 * and pole_miss2.py (a rational bicubic patch and a polynomial (3,1) one, their u = 1 sides
 * collapsed), whose rays from h = 1/128 .. 2 above (u,v) = (1 - 2^-16, ...) were missed, points
 * 2^-8 .. 2^-30 from the pole, random patches of degrees up to 5, polynomial and rational,
 * with one side collapsed, and the patch of tests/hostile/fuzz_locator_ray_pole_miss.bin: a
 * rational (5,3) patch at 2^-239 whose v = 0 side is a pole and whose last two rows coincide
 * (points and weights), so that S_u vanishes along all of u = 1 (a cusp edge); its rays next to
 * that side were missed. Then singular corners, where the first differences of the net along u
 * and v are parallel (S_u and S_v parallel there, the normal from second derivatives): the patch of
 * tests/hostile/fuzz_locator_ray_miss_tiny.bin (a polynomial (5,2) net at 2^-1000, most of it two
 * repeated points, whose ray down the normal at (2^-19, 2^-19) was missed) at that scale and at
 * 1, and random patches with such a corner, rays from 2^-j D above points 2^-4 .. 2^-27 from it. Then
 * folds and poles with wild weights (fold_sides, pole_weights). */
#include "harness.h"
#include "shapes.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static unsigned long long rng = 1603;

/* pole_miss2.py: the net times 2^34 (exact) */
static const double raw2[8][3] = {{6591348736, 1756889088, -11759255552}, {11110711296, 13729529856, 6133121024},
       {15438708736, -347602944, -8838971392}, {1606418432, 16236150784, 16236150784},
       {16236150784, 16236150784, 16236150784}, {16213082112, 16236150784, 16239820800},
       {17179344896, 17179344896, 17179344896}, {17179344896, 17179344896, 17179344896}};
/* pole_miss.py: the net (x, y, z times 2^-65) and its weights */
static const double raw1[16][4] = {
{-2.5353085774750298e-20, -2.3634204461865107e-20, -8.6622353746553058e-21, 2},
{1.1521798752251122e-20, 2.3194971556599449e-20, -2.3634204461865107e-20, 1},
{-2.1863210770389074e-20, 1.1521798752251122e-20, 2.2347938609345149e-20, 0.5},
{-4.2351647362715017e-22, 5.0458017365734688e-22, 1.3483043984614351e-22, 0.5},
{3.4286636390322997e-21, 2.6912321229412755e-20, -1.2945376586454883e-21, 0.5},
{-3.8579703769473211e-21, 1.5412029173088012e-20, 1.5412029173088012e-20, 0.25},
{-1.9571093293004635e-20, 2.0958275180256062e-20, 2.0705157912814836e-20, 4},
{-3.1416319664763991e-21, 1.0383598229378156e-20, 7.3552900068215221e-21, 4},
{2.2046017685763294e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25},
{2.7104227131525058e-20, 2.7104227131525058e-20, 2.7104227131525058e-20, 0.25}};

/* fuzz_locator_ray_pole_miss.bin: the net as the fuzz target made it (about 2^-239) and its weights */
static const double raw3[24][4] = {
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 512},
{-6.6325774503125335e-73, -6.1904056202916979e-74, 6.278839986295865e-73, 0.015625},
{1.0081517724475051e-72, 5.5713650582625281e-73, -2.2108591501041778e-73, 512},
{-9.9930833584708838e-73, -1.0258386456483385e-72, -5.9251025222791966e-73, 256},
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 0.00390625},
{-7.9590929403750402e-74, 2.8298997121333476e-73, 1.0965861384516722e-72, 512},
{-1.8571216860875094e-73, -1.0612123920500054e-73, 1.0700558286504221e-72, 0.001953125},
{8.8434366004167113e-75, -8.2243960383875415e-73, 7.074749280333369e-74, 0.0625},
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 4},
{-8.9318709664208784e-73, -3.5373746401666845e-73, -9.0203053324250455e-73, 0.0625},
{-2.0339904180958436e-73, -1.0258386456483385e-72, 3.891112104183353e-73, 512},
{1.0788992652508388e-72, 1.4149498560666738e-73, 3.7142433721750187e-73, 2},
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 256},
{7.4284867443500375e-73, 5.3944963262541939e-73, -5.5713650582625281e-73, 64},
{-2.5645966141208463e-73, -9.9046489924667167e-73, -1.131959884853339e-72, 0.0078125},
{-8.2243960383875415e-73, 2.7414653461291805e-73, -1.131959884853339e-72, 0.001953125},
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125},
{-7.9590929403750402e-73, -2.6530309801250134e-74, 7.7822242083667059e-73, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125},
{-1.131959884853339e-72, -1.131959884853339e-72, -1.131959884853339e-72, 0.001953125}};

/* fuzz_locator_ray_miss_tiny.bin: the net times 2^1000 (exact), rows of three points */
static const double raw4[18][3] = {
    {-1, -0.6953125, 0.9921875}, {0.9921875, 0.9921875, 0.9921875}, {0.9921875, 0.9921875, 0.9921875},
    {0.9921875, 0.9921875, 0.9921875}, {0.9921875, 0.9921875, 0.9921875}, {0.9921875, 0.9921875, 0.9921875},
    {0.9921875, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375},
    {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375},
    {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375},
    {0.0234375, 0.0234375, 0.0234375}, {0.0234375, 0.0234375, 0.0234375}, {0.9921875, 0.9921875, 0.9921875}};

static int rays, misses;

/* The ray from h above S(u,v) down the unit normal there (a regular normal, |d.N| = 1): a hit no
 * later than h (an earlier one may come from another part of the surface). */
static void shoot(const bs_locator *L, const bs_patch *p, double u, double v, double h,
                  double size, const char *what)
{
    double P[3], N[3], o[3], d[3], t = -1;
    unsigned char kind = 9;
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view pv[3] = {{&P[0], 1, 0}, {&P[1], 1, 0}, {&P[2], 1, 0}};
    bs_view nv[3] = {{&N[0], 1, 0}, {&N[1], 1, 0}, {&N[2], 1, 0}};
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, pv, nv, &kind), BS_OK);
    if (kind != BS_NORMAL_REGULAR)
        return;
    for (int c = 0; c < 3; c++) {
        o[c] = P[c] + h * N[c];
        d[c] = -N[c];
    }
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_view tv = {&t, 1, 0};
    uint32_t id = 7;
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &id, NULL, &tv, NULL), BS_OK);
    rays++;
    int ok = id == 0 && t <= h * (1 + 1e-9) + 2e-9 * size;
    misses += !ok;
    CHECKF(ok, "%s: (u,v) = (%.17g, %.17g), h = %g: patch %u t = %.17g", what, u, v, h, id, t);
}

/* Points 2^-k from the u = 1 pole, k = 8 .. 30, at several v, rays from h = 1/128 .. 2 times
 * size above them. */
static void sweep(const bs_patch *p, double size, const double *vs, int nvs, const char *what)
{
    bs_locator *L = shape_locator(p);
    if (L == NULL)
        return;
    for (int k = 8; k <= 30; k += bs_test_quick() ? 7 : 1)
        for (int j = 0; j < nvs; j++)
            for (double h = 1.0 / 128; h <= 2.0; h *= 2)
                shoot(L, p, 1.0 - ldexp(1.0, -k), vs[j], h * size, size, what);
    bs_locator_destroy(L);
}

static void reproducers(void)
{
    double c2[24], c1[48], w1[16], sc = ldexp(1.0, 65);
    for (int k = 0; k < 8; k++)
        for (int c = 0; c < 3; c++)
            c2[3 * k + c] = raw2[k][c] / 17179869184.0;
    for (int k = 0; k < 16; k++) {
        for (int c = 0; c < 3; c++)
            c1[3 * k + c] = raw1[k][c] * sc;
        w1[k] = raw1[k][3];
    }
    bs_patch *p2 = NULL, *p1 = NULL;
    CHECK_STATUS(bs_patch_create(3, 1, 3, c2, NULL, &p2), BS_OK);
    CHECK_STATUS(bs_patch_create(3, 3, 3, c1, w1, &p1), BS_OK);
    double v2[4] = {0.9999847412109375, 0.5, 0.125, 1.0 - 0x1p-30};
    double v1[4] = {0.3242034912109375, 0.9999847412109375, 0.5, 0x1p-20};
    if (p2 != NULL)
        sweep(p2, 1.0, v2, 4, "pole_miss2 (polynomial 3x1)");
    if (p1 != NULL)
        sweep(p1, 2.0, v1, 4, "pole_miss (rational bicubic)");
    bs_patch_destroy(p2);
    bs_patch_destroy(p1);
    double c3[72], w3[24];
    for (int k = 0; k < 24; k++) {
        for (int c = 0; c < 3; c++)
            c3[3 * k + c] = raw3[k][c];
        w3[k] = raw3[k][3];
    }
    bs_patch *p3 = NULL;
    CHECK_STATUS(bs_patch_create(5, 3, 3, c3, w3, &p3), BS_OK);
    double v3[4] = {0.98994974874371855, 0.5, 0.25, 1.0 - 0x1p-20};
    if (p3 != NULL)
        sweep(p3, 3.5647e-72, v3, 4, "fuzz_locator_ray_pole_miss (rational 5x3, cusp edge)");
    bs_patch_destroy(p3);
}

/* Points 2^-a, 2^-b from the corner (0, 0), a and b in 4 .. 27, rays from size 2^-j above. */
static void corner_sweep(const bs_patch *p, double size, const char *what)
{
    bs_locator *L = shape_locator(p);
    if (L == NULL)
        return;
    int step = bs_test_quick() ? 8 : 3;
    for (int a = 4; a <= 27; a += step)
        for (int b = 4; b <= 27; b += step)
            for (int j = 0; j < 12; j += 3)
                shoot(L, p, ldexp(1.0, -a), ldexp(1.0, -b), ldexp(size, -j), size, what);
    bs_locator_destroy(L);
}

static void singular_corners(int count)
{
    double c4[54];
    for (int e = -1000; e <= 0; e += 1000) {
        for (int k = 0; k < 18; k++)
            for (int c = 0; c < 3; c++)
                c4[3 * k + c] = ldexp(raw4[k][c], e);
        bs_patch *p4 = NULL;
        CHECK_STATUS(bs_patch_create(5, 2, 3, c4, NULL, &p4), BS_OK);
        if (p4 != NULL)
            corner_sweep(p4, ldexp(2.8, e), e ? "fuzz_locator_ray_miss_tiny at 2^-1000" : "fuzz_locator_ray_miss_tiny");
        bs_patch_destroy(p4);
    }
    for (int t = 0; t < count; t++) { /* S_v parallel to S_u at (0, 0) */
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 5), n = 1 + (size_t)(bs_test_rand_u64(&rng) % 5);
        double ctrl[3 * 36], wt[36], lam = bs_test_rand(&rng, -2, 2);
        int rational = t % 2;
        for (size_t k = 0; k < (m + 1) * (n + 1); k++) {
            for (size_t c = 0; c < 3; c++)
                ctrl[3 * k + c] = bs_test_rand(&rng, -1, 1);
            wt[k] = rational ? ldexp(1.0, (int)(bs_test_rand_u64(&rng) % 9) - 4) : 1.0;
        }
        for (size_t c = 0; c < 3; c++) /* P(0,1) on the line through P(0,0) and P(1,0) */
            ctrl[3 + c] = ctrl[c] + lam * (ctrl[3 * (n + 1) + c] - ctrl[c]);
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? wt : NULL, &p), BS_OK);
        char what[64];
        (void)snprintf(what, sizeof what, "singular corner %d (%zu,%zu)%s", t, m, n, rational ? " rational" : "");
        if (p != NULL)
            corner_sweep(p, 2.0, what);
        bs_patch_destroy(p);
    }
}

/* fuzz_locator_ray_miss_weights.bin: a rational (1,2) net in units of 2^-7 (its u = 0 side a pole,
 * P(1,1) that pole too) and its weights */
static const double raw5[6][4] = {{-78, 45, 44, 0x1p-2},   {-78, 45, 44, 0x1p19},  {-78, 45, 44, 0x1p-21},
                                  {27, -115, -70, 0x1p6}, {-78, 45, 44, 0x1p-2}, {-128, 0, 127, 0x1p19}};

/* Points (u, 2^-k) next to the v = 0 side, k = 4 .. 30, rays from size 2^-j above. */
static void fold_sweep(const bs_patch *p, double size, const double *us, int nus, const char *what)
{
    bs_locator *L = shape_locator(p);
    if (L == NULL)
        return;
    for (int k = 4; k <= 30; k += bs_test_quick() ? 5 : 1)
        for (int i = 0; i < nus; i++)
            for (int j = 0; j < 12; j += 3)
                shoot(L, p, us[i], ldexp(1.0, -k), ldexp(size, -j), size, what);
    bs_locator_destroy(L);
}

/* Folds: sides v = 0 on one straight line with the next column of the net, so that S_v is parallel
 * to S_u all along the side (the map folds there). The fuzz input's net at 2^711 and at 1 (its side
 * v = 0 and the next column lie on the line through the pole and P(1,0); the rays at (0.166, 2^-19)
 * and (0.633, 2^-17) were missed), then random nets, half of them rational with weights 2^-8 .. 2^8. */
static void fold_sides(int count)
{
    for (int e = 711; e >= 0; e -= 711) {
        double c5[18], w5[6], us[3] = {0x1.539e3b2d066eap-3, 0x1.442e4fc240525p-1, 0.5};
        for (int k = 0; k < 6; k++) {
            for (int c = 0; c < 3; c++)
                c5[3 * k + c] = ldexp(raw5[k][c], e - 7);
            w5[k] = raw5[k][3];
        }
        bs_patch *p5 = NULL;
        CHECK_STATUS(bs_patch_create(1, 2, 3, c5, w5, &p5), BS_OK);
        if (p5 != NULL)
            fold_sweep(p5, ldexp(4.0, e), us, 3, e ? "fuzz_locator_ray_miss_weights at 2^711" : "fuzz_locator_ray_miss_weights");
        bs_patch_destroy(p5);
    }
    for (int t = 0; t < count; t++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 5), n = 2 + (size_t)(bs_test_rand_u64(&rng) % 4);
        double ctrl[3 * 36], wt[36], base[3], dir[3];
        int rational = t % 2;
        for (size_t c = 0; c < 3; c++) {
            base[c] = bs_test_rand(&rng, -1, 1);
            dir[c] = bs_test_rand(&rng, -1, 1);
        }
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                size_t k = i * (n + 1) + j;
                double lam = bs_test_rand(&rng, -1, 1);
                for (size_t c = 0; c < 3; c++)
                    ctrl[3 * k + c] = j <= 1 ? base[c] + lam * dir[c] : bs_test_rand(&rng, -1, 1);
                wt[k] = rational ? ldexp(1.0, (int)(bs_test_rand_u64(&rng) % 17) - 8) : 1.0;
            }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? wt : NULL, &p), BS_OK);
        double us[3] = {bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), 0.5};
        char what[64];
        (void)snprintf(what, sizeof what, "fold %d (%zu,%zu)%s", t, m, n, rational ? " rational" : "");
        if (p != NULL)
            fold_sweep(p, 2.0, us, 3, what);
        bs_patch_destroy(p);
    }
}

/* fuzz_locator_ray_miss_pole_weights.bin and ..._pole_weights2.bin: rational (1,2) nets in units of
 * 2^-7 whose u = 0 side is a pole, with weights 2^41 and 2^39 apart, at 2^711 and 2^-240 */
static const double raw6[2][6][4] = {
    {{127, -121, 0, 0x1p-37}, {127, -121, 0, 0x1p-31}, {127, -121, 0, 0x1p4},
     {-128, 0, 127, 0x1p-7}, {127, 127, 127, 0x1p-7}, {127, -95, 127, 0x1p-7}},
    {{-78, -70, 28, 0x1p19}, {-78, -70, 28, 0x1p12}, {-78, -70, 28, 0x1p-9},
     {124, 43, 13, 0x1p-4}, {127, 127, 20, 0x1p-18}, {105, 96, 13, 0x1p21}}};

/* Points (2^-a, v) next to the u = 0 pole, a = 1 .. 29, at v = 2^-a, 1 - 2^-a and the vs given,
 * rays from size 2^-j above. */
static void pole_weight_sweep(const bs_patch *p, double size, const double *vs, int nvs, const char *what)
{
    bs_locator *L = shape_locator(p);
    if (L == NULL)
        return;
    for (int a = 1; a <= 29; a += bs_test_quick() ? 6 : 2)
        for (int i = 0; i < nvs + 2; i++)
            for (int j = 0; j < 12; j += 4) {
                double u = ldexp(1.0, -a), v = i == 0 ? u : i == 1 ? 1.0 - u : vs[i - 2];
                shoot(L, p, u, v, ldexp(size, -j), size, what);
            }
    bs_locator_destroy(L);
}

/* Poles with wild weights: where the weights hand over from the pole's row to the next (u about
 * the ratio of their weights, different along v), nearly the whole domain maps within a hair of
 * the far side, and the pieces next to v = 0 reach from there to the pole until they are far
 * narrower in v than in u (they are halved along v alone then: pole_split in
 * lib/query/ray_split.h). The two fuzz nets at their scales and at 1, then random (1..2, 2..3)
 * nets with their u = 0 side a pole and weights 2^-40 .. 2^40 (2^-12 .. 2^12 above degree (2,2), as
 * fuzz_locator draws them). */
static void pole_weights(int count)
{
    static const int scale[2] = {711, -240};
    for (int f = 0; f < 2; f++)
        for (int e = scale[f]; e != 1; e = e ? 0 : 1) {
            double c6[18], w6[6], vs[1] = {0x1.adab187134be6p-1};
            for (int k = 0; k < 6; k++) {
                for (int c = 0; c < 3; c++)
                    c6[3 * k + c] = ldexp(raw6[f][k][c], e - 7);
                w6[k] = raw6[f][k][3];
            }
            bs_patch *p6 = NULL;
            char what[64];
            (void)snprintf(what, sizeof what, "fuzz_locator_ray_miss_pole_weights%s at 2^%d", f ? "2" : "", e);
            CHECK_STATUS(bs_patch_create(1, 2, 3, c6, w6, &p6), BS_OK);
            if (p6 != NULL)
                pole_weight_sweep(p6, ldexp(4.0, e), vs, 1, what);
            bs_patch_destroy(p6);
        }
    for (int t = 0; t < count; t++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 2), n = 2 + (size_t)(bs_test_rand_u64(&rng) % 2);
        double ctrl[3 * 16], wt[16], pole[3];
        int wexp = m * n <= 4 ? 40 : 12; /* as fuzz_locator draws them */
        for (size_t c = 0; c < 3; c++)
            pole[c] = bs_test_rand(&rng, -1, 1);
        for (size_t k = 0; k < (m + 1) * (n + 1); k++) {
            for (size_t c = 0; c < 3; c++)
                ctrl[3 * k + c] = k <= n ? pole[c] : bs_test_rand(&rng, -1, 1);
            wt[k] = ldexp(1.0, (int)(bs_test_rand_u64(&rng) % (unsigned)(2 * wexp + 1)) - wexp);
        }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, wt, &p), BS_OK);
        double vs[2] = {bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1)};
        char what[64];
        (void)snprintf(what, sizeof what, "wild pole weights %d (%zu,%zu)", t, m, n);
        if (p != NULL)
            pole_weight_sweep(p, 2.0, vs, 2, what);
        bs_patch_destroy(p);
    }
}

/* Random patches with the u = 1 side collapsed to one point (cusp 0), or equal to the row before it,
 * points and weights (cusp 1: S_u vanishes all along u = 1, a cusp edge). */
static void random_poles(int count, int cusp)
{
    for (int t = 0; t < count; t++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 5), n = 1 + (size_t)(bs_test_rand_u64(&rng) % 5);
        double ctrl[3 * 36], wt[36], pole[3];
        int rational = t % 2;
        for (size_t c = 0; c < 3; c++)
            pole[c] = bs_test_rand(&rng, -1, 1);
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                size_t k = i * (n + 1) + j;
                for (size_t c = 0; c < 3; c++)
                    ctrl[3 * k + c] = i == m ? (cusp ? ctrl[3 * (k - n - 1) + c] : pole[c]) : bs_test_rand(&rng, -1, 1);
                wt[k] = rational ? ldexp(1.0, (int)(bs_test_rand_u64(&rng) % 9) - 4) : 1.0;
                if (cusp && i == m)
                    wt[k] = wt[k - n - 1];
            }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? wt : NULL, &p), BS_OK);
        if (p == NULL)
            continue;
        double vs[3] = {bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), 1.0 - 0x1p-16};
        char what[64];
        (void)snprintf(what, sizeof what, "random %s %d (%zu,%zu)%s", cusp ? "cusp edge" : "pole", t, m, n,
                       rational ? " rational" : "");
        sweep(p, 0.5, vs, 3, what);
        bs_patch_destroy(p);
    }
}

int main(void)
{
    reproducers();
    random_poles(bs_test_quick() ? 6 : 40, 0);
    random_poles(bs_test_quick() ? 6 : 40, 1);
    singular_corners(bs_test_quick() ? 4 : 24);
    fold_sides(bs_test_quick() ? 4 : 24);
    pole_weights(bs_test_quick() ? 8 : 300);
    printf("%d rays down normals next to poles, cusp edges, singular corners and folds, %d missed or hit later\n", rays, misses);
    return bs_test_exit("test_ray_poles");
}
