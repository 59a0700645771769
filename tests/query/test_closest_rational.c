/* Closest points on rational patches whose weights span many binades: the answer is never
 * farther than a corner or a sampled point of the patch (plus tau), through
 * bs_patch_closest_point and through a locator, or the call says BS_ERR_PRECISION and writes
 * nothing. The hostile files rational_closest_wrong.bpt (weights 2^-9..2^9) and
 * wild_weights_1e14.bpt, wild_weights_1e20.bpt (1e-14..1e14, 1e-20..1e20), random rational
 * patches of degrees up to 5 with weight ratios up to 2^40, and a ratio beyond what is served. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static unsigned long long rng = 20261203;

static bs_surface *read_hostile(const char *name)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", BS_HOSTILE_DIR, name);
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_read_bpt_file(path, NULL, &s), BS_OK);
    return s;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* The smallest distance from q to the patch's points on a g x g grid (corners included). */
static double sampled(const bs_patch *p, const double *q, int g)
{
    double best = INFINITY;
    for (int i = 0; i <= g; i++)
        for (int j = 0; j <= g; j++) {
            double u = (double)i / g, v = (double)j / g, x[3];
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view o[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, o, NULL, NULL), BS_OK);
            best = fmin(best, dist3(x, q));
        }
    return best;
}

static double diagonal(const bs_patch *p)
{
    double ctrl[3 * 36], lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t np = (bs_patch_degree_u(p) + 1) * (bs_patch_degree_v(p) + 1);
    CHECK_STATUS(bs_patch_get_ctrl(p, ctrl, 3 * 36, NULL, 0), BS_OK);
    for (size_t k = 0; k < np; k++)
        for (size_t c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], ctrl[3 * k + c]);
            hi[c] = fmax(hi[c], ctrl[3 * k + c]);
        }
    return dist3(lo, hi);
}

/* The closest point to q on p alone and through a locator of p: both BS_OK and no farther than
 * bound + tau, or both BS_ERR_PRECISION with the outputs untouched. Returns 1 when answered. */
static int check_query(const bs_patch *p, const double *q, double bound, const char *what)
{
    double u = -7, v = -7, d = -7, pos[3] = {-7, -7, -7};
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}}, dv = {&d, 1, 0};
    bs_view pv[3] = {{&pos[0], 1, 0}, {&pos[1], 1, 0}, {&pos[2], 1, 0}};
    bs_status st = bs_patch_closest_point(p, 1, qv, uv, &dv, pv);
    CHECKF(st == BS_OK || st == BS_ERR_PRECISION, "%s: status %d", what, st);
    double tau = 1e-9 * (diagonal(p) + bound);
    if (st == BS_OK)
        CHECKF(d <= bound + tau, "%s: distance %.17g, a point of the patch at %.17g", what, d, bound);
    else
        CHECK(u == -7 && v == -7 && d == -7 && pos[0] == -7);
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    uint32_t id = 77;
    double d2 = -7;
    bs_view dv2 = {&d2, 1, 0};
    bs_status st2 = bs_locator_closest_point(L, 1, qv, &id, NULL, &dv2, NULL);
    CHECKF(st2 == st, "%s: locator status %d, patch %d", what, st2, st);
    if (st2 == BS_OK)
        CHECKF(id == 0 && d2 <= bound + tau, "%s: locator distance %.17g, bound %.17g", what, d2, bound);
    else
        CHECK(id == 77 && d2 == -7);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    return st == BS_OK;
}

static void hostile_files(void)
{
    bs_surface *s = read_hostile("rational_closest_wrong.bpt");
    if (s != NULL) {
        const bs_patch *p = bs_surface_get(s, 0);
        double q[3] = {-1.29058837890625, -1.02142333984375, 1.26995849609375};
        /* the corner (u,v) = (1,0), 1.1699 away; the wrong answer was 1.3189 */
        CHECK(check_query(p, q, sampled(p, q, 64), "rational_closest_wrong"));
        CHECK(sampled(p, q, 1) < 1.17);
        bs_surface_destroy(s);
    }
    const char *wild[2] = {"wild_weights_1e14.bpt", "wild_weights_1e20.bpt"};
    for (int k = 0; k < 2; k++) {
        s = read_hostile(wild[k]);
        if (s == NULL)
            continue;
        double q[3] = {0, 0, 0};
        /* the minimum is at most 1/sqrt(3) (near (u,v) = (1/r, 1/r^2)); 1.0 and 1.73 were given */
        CHECK(check_query(bs_surface_get(s, 0), q, 1.0 / sqrt(3.0), wild[k]));
        bs_surface_destroy(s);
    }
}

/* Random rational patches, weights 2^e with e uniform in [-emax, emax]. */
static void random_patches(int count, int emax)
{
    int answered = 0;
    for (int t = 0; t < count; t++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 5), n = (size_t)(bs_test_rand_u64(&rng) % 6);
        double ctrl[3 * 36], wt[36];
        size_t np = (m + 1) * (n + 1);
        for (size_t k = 0; k < np; k++) {
            for (size_t c = 0; c < 3; c++)
                ctrl[3 * k + c] = bs_test_rand(&rng, -1, 1);
            wt[k] = ldexp(1.0, (int)(bs_test_rand_u64(&rng) % (unsigned)(2 * emax + 1)) - emax);
        }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, wt, &p), BS_OK);
        if (p == NULL)
            continue;
        for (int r = 0; r < 4; r++) {
            double q[3];
            for (int c = 0; c < 3; c++)
                q[c] = bs_test_rand(&rng, -1.5, 1.5);
            char what[64];
            (void)snprintf(what, sizeof what, "random patch %d (%zu,%zu), query %d", t, m, n, r);
            answered += check_query(p, q, sampled(p, q, 24), what);
        }
        bs_patch_destroy(p);
    }
    printf("weights 2^-%d..2^%d: %d of %d queries answered, the others BS_ERR_PRECISION\n", emax,
           emax, answered, 4 * count);
}

/* A weight ratio beyond what the search can certify: BS_ERR_PRECISION, nothing written. */
static void beyond(void)
{
    double ctrl[12] = {-1, -1, -1, -1, 1, 1, 1, -1, 1, 1, 1, -1}, wt[4] = {1e-300, 1e300, 1, 1e-300};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, ctrl, wt, &p), BS_OK);
    double q[3] = {0, 0, 0};
    if (p != NULL)
        CHECK(check_query(p, q, INFINITY, "weights 1e-300..1e300") == 0);
    bs_patch_destroy(p);
    CHECK(bs_status_string(BS_ERR_PRECISION)[0] != 'u');
}

int main(void)
{
    hostile_files();
    random_patches(bs_test_quick() ? 20 : 150, 9);
    random_patches(bs_test_quick() ? 10 : 60, 40);
    beyond();
    return bs_test_exit("test_closest_rational");
}
