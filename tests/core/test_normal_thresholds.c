/* The zero tests of the normal rule (docs/normals.md), pinned from both sides: the rounding bound
 * they rest on holds (long-double reference, weight ratios up to 1e8); healthy points of rational
 * patches with a pole and far-apart weights are regular, with the accurate normal; and on patches
 * whose S_v is known exactly, |S_v| four times above a threshold gives a regular normal, four times
 * below it the limit normal, for the relative term 2^-30 n D and for the rounding term with its
 * weight ratio wmax / w(u,v). */
#include "eval_util.h"

#ifndef BS_DATA_DIR
#define BS_DATA_DIR "data"
#endif

#define TAU 0x1p-30

/* The rounding bound of S^(a,b) the zero tests use, with r = wmax / w(u,v):
 * 2(m+n+1) eps max|P| 2^(a+b) r^(a+b) a! m^a b! n^b, against the long-double reference on random
 * nets with weights spread up to 1e8 (log-uniform, or two values far apart). */
static void rounding_bound(void)
{
    unsigned long long rng = 11;
    double worst = 0.0;
    for (int t = 0; t < 400; t++) {
        size_t m = 1 + bs_test_rand_u64(&rng) % 4, n = 1 + bs_test_rand_u64(&rng) % 4, np = (m + 1) * (n + 1);
        tnet T = tnet_random(&rng, m, n, 3, 1, 1.0, 2.0);
        double spread = bs_test_rand(&rng, 0.0, 8.0 * log(10.0)), wmax = 0.0, pmax = 0.0;
        for (size_t k = 0; k < np; k++) {
            int two = (bs_test_rand_u64(&rng) & 1) != 0;
            T.w[k] = t % 2 ? exp(bs_test_rand(&rng, 0.0, spread)) : two ? exp(spread) : 1.0;
            wmax = fmax(wmax, T.w[k]);
            const double *q = T.ctrl + 3 * k;
            pmax = fmax(pmax, sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
        }
        bs_patch *p = tnet_patch(&T);
        ref_net r = tnet_ref(&T);
        for (int s = 0; s < 8; s++) {
            double u = s < 4 ? (double)(s & 1) : bs_test_rand(&rng, 0.0, 1.0);
            double v = s < 4 ? (double)(s >> 1) : bs_test_rand(&rng, 0.0, 1.0);
            double ratio = fmax(1.0, wmax / (double)ref_hom_deriv(&r, 3, 0, 0, u, v));
            for (unsigned a = 0; a <= 3; a++)
                for (unsigned b = 0; a + b <= 4; b++) {
                    if (a + b == 0)
                        continue;
                    double out[3];
                    long double e[3] = {0, 0, 0};
                    bs_cview cu = cview_of(&u, 1), cv = cview_of(&v, 1);
                    bs_view o[3];
                    views_of(out, 3, 1, o);
                    CHECK_STATUS(bs_patch_eval_deriv(p, a, b, 1, &cu, &cv, o), BS_OK);
                    CHECK(ref_deriv(&r, a, b, u, v, e));
                    double bound = 2.0 * (double)(m + n + 1) * EPS * pmax * ldexp(1.0, (int)(a + b)) *
                                   pow(ratio, a + b) * rational_factor(m, a) * rational_factor(n, b);
                    worst = fmax(worst, dist3(out, e) / bound);
                }
        }
        bs_patch_destroy(p);
        tnet_free(&T);
    }
    CHECKF(worst <= 1.0, "a derivative off by %g of the zero tests' rounding bound", worst);
    printf("rounding of S^(a,b), a + b <= 4, weights up to 1e8 apart: worst %.3g of the bound\n", worst);
}

/* A bicubic patch with a pole at u = 0 (row 0 one point) over a twisted strip, its weights 1 but
 * for row `heavy` at 5e5. */
static bs_patch *pole_patch(int heavy, double *net, double *w)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *q = net + (i * 4 + j) * 3, a = j * 0.5, r = i / 3.0;
            q[0] = i ? r * cos(a) + 0.1 * j : 0.0;
            q[1] = i ? r * sin(a) : 0.0;
            q[2] = i ? 0.3 * i + 0.05 * j * j : 0.0;
            w[i * 4 + j] = i == heavy ? 5e5 : 1.0;
        }
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(3, 3, 3, net, w, &p), BS_OK);
    return p;
}

/* Every point off the pole has S_u and S_v far from parallel. Where both are also above the
 * relative term of the zero test (16 x 2^-30 m D: all points but those next to a pole that carries
 * the heavy weight, whose parametrisation is slow there) the normal is regular and within 1e-9 of
 * the reference; no point is undefined; on the pole the limit normal, within 1e-6 of the
 * reference 1e-12 inside. */
static void pole_with_far_weights(void)
{
    static const double us[] = {1e-4, 1e-3, 0.01, 0.1, 0.5, 1.0}, vs[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    double net[48], w[16], worst = 0.0;
    int slow = 0;
    for (int heavy = 0; heavy < 4; heavy++) {
        bs_patch *p = pole_patch(heavy, net, w);
        double lo[3], hi[3];
        CHECK_STATUS(bs_patch_bounds(p, lo, hi), BS_OK);
        long double diag = sqrtl((long double)(hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                 (hi[2] - lo[2]) * (hi[2] - lo[2]));
        ref_net r = {3, 3, 3, net, w};
        for (size_t a = 0; a < sizeof us / sizeof us[0]; a++)
            for (size_t b = 0; b < sizeof vs / sizeof vs[0]; b++) {
                double n[3];
                long double e[3] = {0, 0, 0}, su[3], sv[3];
                unsigned char kind = normal1(p, us[a], vs[b], n);
                CHECK(ref_normal(&r, us[a], vs[b], e));
                ref_deriv(&r, 1, 0, us[a], vs[b], su);
                ref_deriv(&r, 0, 1, us[a], vs[b], sv);
                long double c[3] = {su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2],
                                    su[0] * sv[1] - su[1] * sv[0]};
                long double sine = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) /
                                   sqrtl((su[0] * su[0] + su[1] * su[1] + su[2] * su[2]) *
                                         (sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2]));
                CHECKF(sine > 0.1L, "the premise: heavy row %d (%g,%g) sine %Lg", heavy, us[a], vs[b], sine);
                long double big = 16.0L * TAU * 3.0L * diag;
                CHECKF(kind != BS_NORMAL_UNDEFINED, "heavy row %d (%g,%g): undefined", heavy, us[a], vs[b]);
                if (su[0] * su[0] + su[1] * su[1] + su[2] * su[2] <= big * big ||
                    sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2] <= big * big) {
                    slow++;
                    continue;
                }
                CHECKF(kind == BS_NORMAL_REGULAR, "heavy row %d (%g,%g): kind %d", heavy, us[a], vs[b], kind);
                if (kind != BS_NORMAL_REGULAR)
                    continue;
                worst = fmax(worst, dist3(n, e));
                CHECKF(dist3(n, e) <= 1e-9, "heavy row %d (%g,%g): off by %g", heavy, us[a], vs[b], dist3(n, e));
            }
        double n[3];
        long double e[3] = {0, 0, 0};
        CHECK(normal1(p, 0.0, 0.25, n) == BS_NORMAL_LIMIT);
        CHECK(ref_normal(&r, 1e-12L, 0.25L + 1e-12L * 0.25L / 0.5L, e));
        CHECKF(dist3(n, e) <= 1e-6, "heavy row %d: limit normal off by %g", heavy, dist3(n, e));
        bs_patch_destroy(p);
    }
    CHECK(slow == 15); /* u = 1e-4, 1e-3 and 0.01 next to the heavy pole */
    printf("pole patches with weights 5e5 apart: regular normals within %.3g of the reference, %d slow points\n",
           worst, slow);
}

/* S = f(u) (1, v, 0) from a bilinear net with a pole at u = 0 (P00 = P01 = 0, P10 = (1,0,0),
 * P11 = (1,1,0)) and weights w0 on the pole, w1 on the other row: f = u w1 / ((1-u) w0 + u w1),
 * S_v = (0, f, 0), and the normal is (0,0,1) everywhere, regular or limit. */
static bs_patch *ruled_pole(double w0, double w1)
{
    double net[12] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0}, w[4] = {w0, w0, w1, w1};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, w0 == w1 ? NULL : w, &p), BS_OK);
    return p;
}

static void expect_kind(const bs_patch *p, double u, unsigned char want, const char *what)
{
    double n[3];
    unsigned char kind = normal1(p, u, 0.5, n);
    CHECKF(kind == want, "%s at u = %g: kind %d, expected %d", what, u, kind, want);
    CHECKF(n[0] == 0.0 && n[1] == 0.0 && fabs(n[2] - 1.0) <= 4 * EPS, "%s at u = %g: normal (%g,%g,%g)", what, u,
           n[0], n[1], n[2]);
}

/* With D = sqrt 2, n = 1, max|P| = sqrt 2: S_v is zero when
 * |S_v| <= max(2^-30 sqrt 2, 4 * 2(m+n+1) eps sqrt 2 * 2 r) = max(2^-30, 48 eps r) sqrt 2. */
static void thresholds_pinned(void)
{
    /* polynomial: |S_v| = u exactly, the relative term decides */
    bs_patch *p = ruled_pole(1.0, 1.0);
    double t = TAU * sqrt(2.0);
    expect_kind(p, 4.0 * t, BS_NORMAL_REGULAR, "|S_v| = 4 x 2^-30 n D");
    expect_kind(p, t / 4.0, BS_NORMAL_LIMIT, "|S_v| = 2^-30 n D / 4");
    bs_patch_destroy(p);

    /* heavy row away from the pole: r = w1 / w(u) and f = u w1 / w(u), so f / (48 eps sqrt 2 r) =
     * u / (48 eps sqrt 2); the rounding term (1.5e-6) is far above the relative one (1.3e-9) */
    double w1 = 1e8, unit = 48.0 * EPS * sqrt(2.0);
    p = ruled_pole(1.0, w1);
    expect_kind(p, 4.0 * unit, BS_NORMAL_REGULAR, "rounding term, |S_v| 4 x above");
    expect_kind(p, unit / 4.0, BS_NORMAL_LIMIT, "rounding term, |S_v| 4 x below");
    bs_patch_destroy(p);

    /* heavy pole: r = w0 / w(u) stays near 1 (not the patch's 1e8), so the relative term decides:
     * f = u / w(u) = 4 x 2^-30 sqrt 2 is regular */
    p = ruled_pole(w1, 1.0);
    double u = 4.0 * t * w1 / (1.0 - 4.0 * t * (1.0 - w1)); /* f(u) = 4t solved for u */
    expect_kind(p, u, BS_NORMAL_REGULAR, "heavy pole, |S_v| 4 x 2^-30 n D");
    u = 0.25 * t * w1 / (1.0 - 0.25 * t * (1.0 - w1));
    expect_kind(p, u, BS_NORMAL_LIMIT, "heavy pole, |S_v| 2^-30 n D / 4");
    bs_patch_destroy(p);
}

/* Scaling a net by a power of two scales S_u and S_v exactly, so the normals and their kinds are
 * those of the unscaled net (within 8 ulps), also where the square of |S_u x S_v| is subnormal
 * (nets scaled by 2^-266: |S_u x S_v| near 2^-527) or overflows (2^+255): lengths are taken with a
 * rescaling there, not from a square that lost its bits. The teapot's 32 patches. */
static void scaled_nets(void)
{
    static double ctrl[32][48];
    size_t np = load_bpt(BS_DATA_DIR "/teapot.bpt", ctrl, 32);
    CHECK(np == 32);
    static const int powers[] = {-266, 255};
    int differ = 0;
    for (size_t k = 0; k < np; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl[k], NULL, &p), BS_OK);
        for (int e = 0; e < 2; e++) {
            double net[48];
            for (int i = 0; i < 48; i++)
                net[i] = ldexp(ctrl[k][i], powers[e]);
            bs_patch *q = NULL;
            CHECK_STATUS(bs_patch_create(3, 3, 3, net, NULL, &q), BS_OK);
            for (int a = 0; a <= 4; a++)
                for (int b = 0; b <= 4; b++) {
                    double n1[3], n2[3];
                    unsigned char k1 = normal1(p, a / 4.0, b / 4.0, n1), k2 = normal1(q, a / 4.0, b / 4.0, n2);
                    long double ref[3] = {n1[0], n1[1], n1[2]};
                    differ += k1 != k2 || !(dist3(n2, ref) <= 8 * EPS);
                }
            bs_patch_destroy(q);
        }
        bs_patch_destroy(p);
    }
    CHECKF(differ == 0, "%d normals of scaled teapot patches differ from the unscaled ones", differ);
}

/* A corner where S, S_u, S_v and all second partials but none of the third vanish (the net's points
 * with i + j <= 2 are one point): S_u x S_v starts at order 4 along the diagonal (A_2 x B_2), so the
 * limit rule needs its higher orders; the limit normal is that of the reference just inside. */
static void high_order_corner(void)
{
    double net[48];
    unsigned long long seed = 5;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            for (int c = 0; c < 3; c++)
                net[(i * 4 + j) * 3 + c] = i + j <= 2 ? 0.0 : (c == 0 ? i : c == 1 ? j : 0.0) + bs_test_rand(&seed, 0.0, 0.3);
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(3, 3, 3, net, NULL, &p), BS_OK);
    ref_net r = {3, 3, 3, net, NULL};
    double n[3];
    long double e[3] = {0, 0, 0};
    CHECK(normal1(p, 0.0, 0.0, n) == BS_NORMAL_LIMIT);
    CHECK(ref_normal(&r, 1e-7L, 1e-7L, e));
    CHECKF(dist3(n, e) <= 1e-5, "high-order corner: limit normal off by %g", dist3(n, e));
    bs_patch_destroy(p);
}

int main(void)
{
    rounding_bound();
    pole_with_far_weights();
    thresholds_pinned();
    scaled_nets();
    high_order_corner();
    return bs_test_exit("test_normal_thresholds");
}
