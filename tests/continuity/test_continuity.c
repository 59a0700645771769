/* Continuity report: planar patches folded by a known angle, a patch split in two (C1), a handle
 * stretched (G1 but not C1), poles, open edges, the tea set's figures, and the error paths. */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

static bs_surface *surface_of(size_t np, const size_t *deg, const double *const *nets)
{
    bs_surface *s = NULL;
    bs_surface_create(&s);
    for (size_t k = 0; k < np; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(deg[2 * k], deg[2 * k + 1], 3, nets[k], NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    return s;
}

/* Two bilinear patches: A = [0,1]x[0,1] in z = 0, B hinged on A's side u = 1 and folded up by
 * theta. Both are planar, so the tangent planes meet at exactly theta everywhere. */
static void test_fold(double theta)
{
    double c = cos(theta), sn = sin(theta);
    double a[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    /* B's side u = 0 is A's side u = 1 walked backwards (v reversed) to exercise the reversal. */
    double b[12] = {1, 1, 0, 1, 0, 0, 1 + c, 1, sn, 1 + c, 0, sn};
    size_t deg[4] = {1, 1, 1, 1};
    const double *nets[2] = {a, b};
    bs_surface *s = surface_of(2, deg, nets);
    bs_edge_continuity e[4];
    bs_open_edge o[8];
    size_t ne = 99, no = 99;
    CHECK_STATUS(bs_surface_continuity(s, 1e-12, 7, e, 4, &ne, o, 8, &no), BS_OK);
    CHECK(ne == 1 && no == 6);
    if (ne == 1) {
        CHECK(e[0].patch_a == 0 && e[0].side_a == BS_SIDE_U1 && e[0].patch_b == 1 && e[0].side_b == BS_SIDE_U0);
        CHECK(e[0].reversed == 1 && e[0].c0_gap == 0.0 && e[0].samples == 7);
        CHECKF(fabs(e[0].g1_angle - fmin(theta, acos(-1.0) - theta)) < 1e-12, "angle %.17g for %.17g",
               e[0].g1_angle, theta);
        /* Outward derivatives: A's is (1,0,0), B's is -(c,0,sn): opposite only when theta = 0. */
        double expect = sqrt((1 - c) * (1 - c) + sn * sn);
        CHECKF(fabs(e[0].c1_defect - expect) < 1e-12, "defect %.17g, expected %.17g", e[0].c1_defect, expect);
        CHECK(e[0].c1 == (expect <= 1e-12));
    }
    /* Open edges: A's v0, v1, u0 and B's v0, u1, v1, in patch and side order. */
    CHECK(no == 6 && o[0].patch == 0 && o[0].side == BS_SIDE_V0 && o[1].side == BS_SIDE_V1 &&
          o[2].side == BS_SIDE_U0 && o[3].patch == 1 && o[3].side == BS_SIDE_V0);
    bs_surface_destroy(s);
}

/* de Casteljau split of a bicubic net at u = 1/2 (exact in binary): the halves meet C1. */
static void split_u(const double *net, double *lo, double *hi)
{
    for (size_t j = 0; j < 4; j++)
        for (size_t c = 0; c < 3; c++) {
            double b[4];
            for (size_t i = 0; i < 4; i++)
                b[i] = net[(i * 4 + j) * 3 + c];
            double t[4][4];
            for (size_t i = 0; i < 4; i++)
                t[0][i] = b[i];
            for (size_t r = 1; r < 4; r++)
                for (size_t i = 0; i + r < 4; i++)
                    t[r][i] = 0.5 * (t[r - 1][i] + t[r - 1][i + 1]);
            for (size_t i = 0; i < 4; i++) {
                lo[(i * 4 + j) * 3 + c] = t[i][0];
                hi[(i * 4 + j) * 3 + c] = t[3 - i][i];
            }
        }
}

static void test_split(void)
{
    unsigned long long seed = 99;
    double net[48], lo[48], hi[48];
    for (size_t i = 0; i < 4; i++)
        for (size_t j = 0; j < 4; j++) {
            net[(i * 4 + j) * 3 + 0] = (double)i + bs_test_rand(&seed, -0.2, 0.2);
            net[(i * 4 + j) * 3 + 1] = (double)j + bs_test_rand(&seed, -0.2, 0.2);
            net[(i * 4 + j) * 3 + 2] = bs_test_rand(&seed, -0.5, 0.5);
        }
    split_u(net, lo, hi);
    size_t deg[4] = {3, 3, 3, 3};
    const double *nets[2] = {lo, hi};
    bs_surface *s = surface_of(2, deg, nets);
    bs_edge_continuity e[2];
    size_t ne = 0, no = 0;
    CHECK_STATUS(bs_surface_continuity(s, 1e-12, 16, e, 2, &ne, NULL, 0, &no), BS_OK);
    CHECK(ne == 1 && no == 6);
    if (ne == 1) {
        CHECK(e[0].side_a == BS_SIDE_U1 && e[0].side_b == BS_SIDE_U0 && e[0].reversed == 0);
        CHECK(e[0].c0_gap == 0.0 && e[0].c1 == 1 && e[0].c1_defect < 1e-14 && e[0].flipped == 0);
        CHECKF(e[0].g1_angle < 1e-7, "angle %g", e[0].g1_angle);
    }
    bs_surface_destroy(s);
    /* Stretch hi's first handle row by 2 (collinear, longer): still G1, no longer C1. */
    for (size_t j = 0; j < 4; j++)
        for (size_t c = 0; c < 3; c++) {
            size_t b0 = j * 3 + c, b1 = (4 + j) * 3 + c;
            hi[b1] = hi[b0] + 2.0 * (hi[b1] - hi[b0]);
        }
    s = surface_of(2, deg, nets);
    CHECK_STATUS(bs_surface_continuity(s, 1e-12, 16, e, 2, &ne, NULL, 0, &no), BS_OK);
    CHECK(ne == 1 && e[0].c1 == 0 && e[0].c1_defect > 0.1 && e[0].g1_angle < 1e-7);
    bs_surface_destroy(s);
}

/* The tea set: seams meet exactly (C0 gap 0); the report is consistent with its counts. */
static void test_teaset(void)
{
    static const char *const names[] = {"teapot", "teacup", "teaspoon"};
    for (size_t f = 0; f < 3; f++) {
        bs_surface *s;
        CHECK_STATUS(bs_surface_create_builtin(names[f], &s), BS_OK);
        size_t ne = 0, no = 0;
        CHECK_STATUS(bs_surface_continuity(s, 0.0, 16, NULL, 0, &ne, NULL, 0, &no), BS_OK);
        bs_edge_continuity *e = malloc(ne * sizeof(*e) + 1);
        bs_open_edge *o = malloc(no * sizeof(*o) + 1);
        CHECK_STATUS(bs_surface_continuity(s, 0.0, 16, e, ne, &ne, o, no, &no), BS_OK);
        double gap = 0.0, g1 = 0.0;
        for (size_t k = 0; k < ne; k++) {
            gap = fmax(gap, e[k].c0_gap);
            g1 = fmax(g1, e[k].g1_angle);
            CHECK(e[k].patch_a <= e[k].patch_b && e[k].samples <= 16);
        }
        /* Every side is shared, open or a pole: 4 per patch. */
        CHECK(2 * ne + no <= 4 * bs_surface_count(s));
        CHECKF(gap == 0.0, "%s: C0 gap %g", names[f], gap);
        printf("%s: %zu shared edges, %zu open, max G1 angle %.3g degrees\n", names[f], ne, no,
               g1 * 180.0 / acos(-1.0));
        if (f == 0) {
            /* The teapot's 128 sides, counted from its geometry: 8 poles (the knob top, patches
             * 20-23, and the centre of the bottom, 28-31), 16 open sides (the rim top where the lid
             * sits, both ends of the handle and of the spout, the lid's lower edge), so
             * (128 - 8 - 16) / 2 = 52 shared edges. Newell's data is tangent-plane continuous:
             * every angle is rounding. */
            CHECKF(ne == 52 && no == 16, "teapot: %zu shared, %zu open", ne, no);
            CHECKF(g1 < 1e-12, "teapot: G1 angle %g", g1);
            size_t seen = 0;
            for (size_t k = 0; k < no; k++)
                seen += (o[k].patch <= 3 && o[k].side == BS_SIDE_U0) || (o[k].patch >= 24 && o[k].patch <= 27);
            CHECK(seen == 8);
        }
        free(e);
        free(o);
        bs_surface_destroy(s);
    }
}

/* The tea set's figures of docs/continuity.md (tol 1e-9, 32 samples), asserted: shared and open
 * edges, the largest G1 angle to its printed digits, the C1 edges. */
static void test_teaset_figures(void)
{
    static const struct { const char *name; size_t shared, open, c1; double degrees, half_digit; } fig[] = {
        {"teapot", 52, 16, 46, 2.1e-13, 0.05e-13}, {"teacup", 46, 12, 26, 59.04, 0.005},
        {"teaspoon", 28, 8, 0, 0.0244, 0.00005}};
    for (size_t f = 0; f < 3; f++) {
        bs_surface *s;
        CHECK_STATUS(bs_surface_create_builtin(fig[f].name, &s), BS_OK);
        bs_edge_continuity e[64];
        size_t ne = 0, no = 0, c1 = 0;
        CHECK_STATUS(bs_surface_continuity(s, 1e-9, 32, e, 64, &ne, NULL, 0, &no), BS_OK);
        double g1 = 0.0;
        for (size_t k = 0; k < ne && k < 64; k++) {
            g1 = fmax(g1, e[k].g1_angle * 180.0 / acos(-1.0));
            c1 += (size_t)e[k].c1;
        }
        CHECKF(ne == fig[f].shared && no == fig[f].open && c1 == fig[f].c1, "%s: %zu shared, %zu open, %zu C1",
               fig[f].name, ne, no, c1);
        CHECKF(fabs(g1 - fig[f].degrees) <= fig[f].half_digit, "%s: largest G1 angle %.4g degrees",
               fig[f].name, g1);
        bs_surface_destroy(s);
    }
}

static void test_errors(void)
{
    bs_surface *s;
    bs_surface_create_builtin("teacup", &s);
    size_t ne = 0, no = 0;
    CHECK_STATUS(bs_surface_continuity(NULL, 0.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_continuity(s, -1.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_continuity(s, NAN, 4, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_continuity(s, INFINITY, 4, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 0, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4097, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, NULL, NULL, 0, NULL), BS_OK);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_OK);
    /* Too small: nothing written, counts untouched. */
    bs_edge_continuity e[1];
    memset(e, 0x5a, sizeof e);
    size_t ne2 = 12345;
    if (ne > 1) {
        CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, e, ne - 1, &ne2, NULL, 0, NULL), BS_ERR_SIZE);
        CHECK(ne2 == 12345 && e[0].patch_a == 0x5a5a5a5au);
    }
    if (no > 0) {
        bs_open_edge o[1];
        CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, NULL, o, no - 1, &ne2), BS_ERR_SIZE);
        CHECK(ne2 == 12345);
    }
    bs_surface_destroy(s);
    /* Not 3-D; empty. */
    double net2[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    bs_patch *p;
    bs_patch_create(1, 1, 2, net2, NULL, &p);
    bs_surface_create(&s);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_OK);
    CHECK(ne == 0 && no == 0);
    bs_surface_add(s, p, NULL);
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_ERR_DIMENSION);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
}

/* A pole: a patch whose side u = 0 collapses to a point is neither shared nor open there. */
static void test_pole(void)
{
    double cone[12] = {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 0};
    size_t deg[2] = {1, 1};
    const double *nets[1] = {cone};
    bs_surface *s = surface_of(1, deg, nets);
    size_t ne = 9, no = 9;
    CHECK_STATUS(bs_surface_continuity(s, 0.0, 4, NULL, 0, &ne, NULL, 0, &no), BS_OK);
    CHECK(ne == 0 && no == 3);
    bs_surface_destroy(s);
}

/* The shared edges of two bilinear patches under tol, measured with `samples` samples, into
 * e[0..1]. */
static size_t pair_edges(const double *a, const double *b, double tol, size_t samples, bs_edge_continuity e[2])
{
    size_t deg[4] = {1, 1, 1, 1}, ne = 0, no = 0;
    const double *nets[2] = {a, b};
    bs_surface *s = surface_of(2, deg, nets);
    CHECK_STATUS(bs_surface_continuity(s, tol, samples, e, 2, &ne, NULL, 0, &no), BS_OK);
    bs_surface_destroy(s);
    return ne;
}

/* A flat square and a twisted neighbour: B's side u = 0 is A's side u = 1, B's far side lies flat
 * at v = 0 and folded by theta at v = 1, so the planes meet at atan2(v sin theta, 1 - v +
 * v cos theta) along the edge. The samples are at t = (k + 1/2) / samples: with one sample the
 * angle is theta / 2 exactly (v = 1/2), with two the larger of v = 1/4 and 3/4. */
static void test_twist(void)
{
    double th = 0.8, c = cos(th), sn = sin(th);
    double a[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    double b[12] = {1, 0, 0, 1, 1, 0, 2, 0, 0, 1 + c, 1, sn};
    bs_edge_continuity e[2];
    CHECK(pair_edges(a, b, 1e-12, 1, e) == 1 && e[0].samples == 1 && e[0].flipped == 0);
    CHECKF(fabs(e[0].g1_angle - th / 2) < 1e-14, "one sample: angle %.17g, expected %.17g", e[0].g1_angle, th / 2);
    CHECK(pair_edges(a, b, 1e-12, 2, e) == 1);
    double expect = atan2(0.75 * sn, 0.25 + 0.75 * c);
    CHECKF(fabs(e[0].g1_angle - expect) < 1e-14, "two samples: angle %.17g, expected %.17g", e[0].g1_angle, expect);
}

/* C1 means a defect within tol, pinned from both sides: a fold by 1e-6 (defect about 1e-6, small
 * enough that the tolerance matches no other side) is C1 under tol = its defect, not under 3/4 of
 * it. */
static void test_c1_tolerance(void)
{
    double th = 1e-6, c = cos(th), sn = sin(th);
    double a[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0}, b[12] = {1, 0, 0, 1, 1, 0, 1 + c, 0, sn, 1 + c, 1, sn};
    bs_edge_continuity e[2];
    CHECK(pair_edges(a, b, 1e-9, 2, e) == 1);
    double d = e[0].c1_defect;
    CHECK(d > 0.0 && e[0].c1 == 0);
    CHECK(pair_edges(a, b, d, 2, e) == 1 && e[0].c1 == 1);
    CHECK(pair_edges(a, b, 0.75 * d, 2, e) == 1 && e[0].c1 == 0);
}

/* The C0 gap is the largest distance between matched control points: one point of the shared side
 * moved by 1e-10 (the edge still matched under tol 1e-9) gives exactly that. */
static void test_gap(void)
{
    double a[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0}, b[12] = {1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0};
    b[5] = 1e-10; /* B's (0,1), A's (1,1) */
    bs_edge_continuity e[2];
    CHECK(pair_edges(a, b, 1e-9, 4, e) == 1 && e[0].c0_gap == 1e-10);
}

/* Normals at right angles (dot product exactly 0) are not opposite; an edge whose normals are all
 * undefined (nets on a line) uses no sample and is not flipped. */
static void test_flipped_edges(void)
{
    double a[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0}, b[12] = {1, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1};
    bs_edge_continuity e[2];
    CHECK(pair_edges(a, b, 1e-12, 5, e) == 1 && e[0].samples == 5 && e[0].flipped == 0);
    CHECK(fabs(e[0].g1_angle - acos(-1.0) / 2) < 1e-15);
    double la[12] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, lb[12] = {2, 0, 0, 3, 0, 0, 4, 0, 0, 5, 0, 0};
    CHECK(pair_edges(la, lb, 1e-12, 5, e) >= 1 && e[0].samples == 0 && e[0].flipped == 0);
}

/* Sides whose control points differ by up to 2 ulps of the largest coordinate are one edge under a
 * tolerance of 2 ulps (random coordinates of mixed magnitudes, so the keys that sort the sides
 * round differently). */
static void test_ulp_tolerance(void)
{
    unsigned long long seed = 99;
    int missed = 0;
    for (int k = 0; k < 4000; k++) {
        double a[12], b[12], big = 0.0;
        for (int i = 0; i < 12; i++) {
            a[i] = bs_test_rand(&seed, -1.0, 1.0) * ldexp(1.0, (int)(bs_test_rand_u64(&seed) % 8));
            big = fmax(big, fabs(a[i]));
        }
        /* B's side u = 0 is A's side u = 1, each coordinate moved by up to 2 ulps of |A| */
        for (int i = 0; i < 6; i++) {
            double x = a[6 + i];
            int steps = (int)(bs_test_rand_u64(&seed) % 5) - 2;
            for (; steps > 0; steps--)
                x = nextafter(x, INFINITY);
            for (; steps < 0; steps++)
                x = nextafter(x, -INFINITY);
            b[i] = x;
            b[6 + i] = a[6 + i] + 3.0;
        }
        double tol = 2.0 * (nextafter(big, INFINITY) - big);
        bs_edge_continuity e[4];
        size_t ne = 0, no = 0, deg[4] = {1, 1, 1, 1};
        const double *nets[2] = {a, b};
        bs_surface *s = surface_of(2, deg, nets);
        CHECK_STATUS(bs_surface_continuity(s, tol, 2, e, 4, &ne, NULL, 0, &no), BS_OK);
        missed += ne == 0;
        bs_surface_destroy(s);
    }
    CHECKF(missed == 0, "%d of 4000 edges within a few ulps not matched", missed);
}

/* The worst case of the keys' rounding, built rather than searched for: every coordinate of B's
 * side one ulp u below A's (tol = u), on values whose sums round away from each other, so that
 * the sorting keys differ by 8 u, more than the 2 dim tol = 6 u that exact sums could differ by.
 * The side is still found: the keys' slack counts their rounding. */
static void test_key_rounding(void)
{
    const double X = 1024.0, u = 0x1p-42; /* u: the ulp of X */
    const double e0[3] = {X, 1.5 * X, 1.75 * X}, e1[3] = {1.25 * X, 1.5 * X, 1.875 * X};
    double a[12], b[12];
    for (int c = 0; c < 3; c++) {
        a[c] = 0.25 * e0[c]; /* A's far side (u = 0), away from the others */
        a[3 + c] = 0.25 * e1[c];
        a[6 + c] = e0[c]; /* A's side u = 1 */
        a[9 + c] = e1[c];
        b[c] = e0[c] - u; /* B's side u = 0 */
        b[3 + c] = e1[c] - u;
        b[6 + c] = e0[c] + (c == 2 ? 300.0 : 0.0); /* B's far side, lifted */
        b[9 + c] = e1[c] + (c == 2 ? 300.0 : 0.0);
    }
    double ka = 0.0, kb = 0.0; /* the keys as lib/surface/topology.c forms them */
    for (int c = 0; c < 3; c++) {
        ka += a[6 + c] + a[9 + c];
        kb += b[c] + b[3 + c];
    }
    CHECKF(ka - kb > 6.0 * u, "the keys differ by only %g u: the case lost its point", (ka - kb) / u);
    bs_edge_continuity e[2];
    CHECKF(pair_edges(a, b, u, 2, e) == 1, "sides one ulp apart under a tolerance of one ulp not matched");
}

/* The frozen layout documented in docs/continuity.md (bindings rely on it). */
static void test_layout(void)
{
    CHECK(sizeof(bs_edge_continuity) == 56 && offsetof(bs_edge_continuity, samples) == 28 &&
          offsetof(bs_edge_continuity, c0_gap) == 32 && offsetof(bs_edge_continuity, c1_defect) == 48);
    CHECK(sizeof(bs_open_edge) == 8 && offsetof(bs_open_edge, side) == 4);
    CHECK(sizeof(bs_parse_error) == 2 * sizeof(size_t) + 96);
}

int main(void)
{
    test_layout();
    test_fold(0.0);
    test_fold(0.3);
    test_fold(1.2);
    test_fold(2.5); /* beyond 90 degrees: the tangent planes meet at pi - theta */
    test_split();
    test_teaset();
    test_teaset_figures();
    test_errors();
    test_pole();
    test_twist();
    test_flipped_edges();
    test_ulp_tolerance();
    test_key_rounding();
    test_gap();
    test_c1_tolerance();
    return bs_test_exit("test_continuity");
}
