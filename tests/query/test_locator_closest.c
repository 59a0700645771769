/* Closest points on a whole surface through a locator, against brute force over the patches
 * (bs_patch_closest_point on every patch, the smallest distance kept): the tea set from points
 * near and far, a 2-D surface, an empty surface, NaN queries and the argument rules. */
#include "harness.h"
#include "shapes.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long rng = 4242;

/* The brute-force minimum distance from q to the surface. */
static double brute(const bs_surface *s, const double *q)
{
    size_t dim = bs_surface_dim(s);
    bs_cview qv[BS_MAX_DIM];
    for (size_t c = 0; c < dim; c++)
        qv[c] = (bs_cview){&q[c], 1, 0};
    double best = INFINITY;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        double d;
        bs_view dv = {&d, 1, 0};
        CHECK_STATUS(bs_patch_closest_point(bs_surface_get(s, i), 1, qv, NULL, &dv, NULL), BS_OK);
        best = fmin(best, d);
    }
    return best;
}

/* n queries q (dim arrays of n) through L, each against brute force. Returns the worst excess
 * over tau. */
static double against_brute(const bs_surface *s, const bs_locator *L, size_t n, double **q)
{
    size_t dim = bs_surface_dim(s);
    double *u = malloc(n * sizeof(double)), *v = malloc(n * sizeof(double)), *dist = malloc(n * sizeof(double));
    double *pos[BS_MAX_DIM];
    uint32_t *id = malloc(n * sizeof(uint32_t));
    bs_cview qv[BS_MAX_DIM];
    bs_view pv[BS_MAX_DIM], uv[2] = {{u, n, 0}, {v, n, 0}}, dv = {dist, n, 0};
    for (size_t c = 0; c < dim; c++) {
        pos[c] = malloc(n * sizeof(double));
        qv[c] = (bs_cview){q[c], n, 0};
        pv[c] = (bs_view){pos[c], n, 0};
    }
    CHECK_STATUS(bs_locator_closest_point(L, n, qv, id, uv, &dv, pv), BS_OK);
    double D = shape_diagonal(s), worst = 0;
    for (size_t k = 0; k < n; k++) {
        double x[BS_MAX_DIM], y[BS_MAX_DIM], b;
        for (size_t c = 0; c < dim; c++)
            x[c] = q[c][k];
        b = brute(s, x);
        CHECKF(id[k] < bs_surface_count(s), "no patch for query %zu", k);
        if (id[k] >= bs_surface_count(s))
            continue;
        double tau = 1e-9 * (D + b);
        worst = fmax(worst, (dist[k] - b) / tau);
        CHECKF(dist[k] <= b + tau, "query %zu: %.17g against brute force %.17g", k, dist[k], b);
        /* pos is bs_patch_eval's point at uv, dist its distance */
        bs_cview cu = {&u[k], 1, 0}, cv = {&v[k], 1, 0};
        bs_view yv[BS_MAX_DIM];
        for (size_t c = 0; c < dim; c++)
            yv[c] = (bs_view){&y[c], 1, 0};
        CHECK_STATUS(bs_patch_eval(bs_surface_get(s, id[k]), 1, &cu, &cv, yv, NULL, NULL), BS_OK);
        double e = 0;
        int same = u[k] >= 0 && u[k] <= 1 && v[k] >= 0 && v[k] <= 1;
        for (size_t c = 0; c < dim; c++) {
            same &= !memcmp(&y[c], &pos[c][k], sizeof(double));
            e += (y[c] - x[c]) * (y[c] - x[c]);
        }
        CHECK(same && fabs(dist[k] - sqrt(e)) <= 1e-15 * (dist[k] + D));
    }
    for (size_t c = 0; c < dim; c++)
        free(pos[c]);
    free(u);
    free(v);
    free(dist);
    free(id);
    return worst;
}

static void tea(const char *name, size_t n)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin(name, &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    double *q[3];
    for (int c = 0; c < 3; c++)
        q[c] = malloc(n * sizeof(double));
    for (size_t k = 0; k < n; k++) {
        /* near the surface (a surface point moved a little), inside its box, or far away */
        double scale = k % 3 == 0 ? 0.05 : k % 3 == 1 ? 2 : 20;
        uint32_t i = (uint32_t)(bs_test_rand_u64(&rng) % bs_surface_count(s));
        double u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1), x[3];
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval(bs_surface_get(s, i), 1, &cu, &cv, xv, NULL, NULL), BS_OK);
        for (int c = 0; c < 3; c++)
            q[c][k] = x[c] + bs_test_rand(&rng, -scale, scale);
    }
    double worst = against_brute(s, L, n, q);
    printf("%s: %zu queries against brute force over the patches, worst excess %.2g tau\n", name, n, worst);
    for (int c = 0; c < 3; c++)
        free(q[c]);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

/* A 2-D surface (two bilinear patches side by side) and a rational sphere octant. */
static void others(void)
{
    const double a[8] = {0, 0, 0, 1, 1, 0, 1, 1}, b[8] = {1, 0, 1, 1, 3, -1, 2, 2};
    bs_patch *p = NULL, *r = NULL;
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_patch_create(1, 1, 2, a, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    bs_patch_destroy(p);
    CHECK_STATUS(bs_patch_create(1, 1, 2, b, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    bs_patch_destroy(p);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    double qx[60], qy[60], *q[2] = {qx, qy};
    for (int k = 0; k < 60; k++) {
        qx[k] = bs_test_rand(&rng, -2, 5);
        qy[k] = bs_test_rand(&rng, -2, 3);
    }
    double worst = against_brute(s, L, 60, q);
    printf("2-D surface: 60 queries, worst excess %.2g tau\n", worst);
    bs_locator_destroy(L);
    bs_surface_destroy(s);

    CHECK((r = shape_sphere_octant(2.5)) != NULL);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, r, NULL), BS_OK);
    bs_patch_destroy(r);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    double sx[40], sy[40], sz[40], *sq[3] = {sx, sy, sz};
    for (int k = 0; k < 40; k++) {
        sx[k] = bs_test_rand(&rng, -1, 4);
        sy[k] = bs_test_rand(&rng, -1, 4);
        sz[k] = bs_test_rand(&rng, -1, 4);
    }
    worst = against_brute(s, L, 40, sq);
    printf("sphere octant: 40 queries, worst excess %.2g tau\n", worst);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
}

/* NaN queries, an empty surface, and the argument rules. */
static void rules(void)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teacup", &s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    bs_surface_destroy(s);
    double x[3] = {1, NAN, 2}, y[3] = {0, 0, INFINITY}, z[3] = {3, 0, 0}, u[3], v[3], d[3], p[3][3];
    uint32_t id[3];
    bs_cview qv[3] = {{x, 3, 0}, {y, 3, 0}, {z, 3, 0}};
    bs_view uv[2] = {{u, 3, 0}, {v, 3, 0}}, dv = {d, 3, 0};
    bs_view pv[3] = {{p[0], 3, 0}, {p[1], 3, 0}, {p[2], 3, 0}};
    CHECK_STATUS(bs_locator_closest_point(L, 3, qv, id, uv, &dv, pv), BS_OK);
    CHECK(id[0] < 26 && isfinite(d[0]) && isfinite(u[0]));
    for (int k = 1; k < 3; k++)
        CHECK(id[k] == UINT32_MAX && isnan(u[k]) && isnan(v[k]) && isnan(d[k]) && isnan(p[0][k]) &&
              isnan(p[1][k]) && isnan(p[2][k]));
    /* arguments: nothing written on failure */
    memset(d, 0, sizeof d);
    bs_view short_d = {d, 2, 0}, odd = {(double *)(void *)((char *)d + 4), 3, 0};
    CHECK_STATUS(bs_locator_closest_point(NULL, 3, qv, id, uv, &dv, pv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_closest_point(L, 3, NULL, id, uv, &dv, pv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_closest_point(L, 0, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_locator_closest_point(L, 3, qv, id, uv, &short_d, pv), BS_ERR_SIZE);
    CHECK_STATUS(bs_locator_closest_point(L, 3, qv, id, uv, &odd, pv), BS_ERR_INVALID_ARG);
    bs_cview short_q[3] = {qv[0], {y, 2, 0}, qv[2]};
    CHECK_STATUS(bs_locator_closest_point(L, 3, short_q, id, uv, &dv, pv), BS_ERR_SIZE);
    CHECK(d[0] == 0 && d[1] == 0 && d[2] == 0);
    CHECK_STATUS(bs_locator_closest_point(L, 3, qv, NULL, NULL, &dv, NULL), BS_OK);
    CHECK(isfinite(d[0]) && isnan(d[1]));
    bs_locator_destroy(L);

    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_locator_closest_point(L, 3, qv, id, uv, &dv, NULL), BS_OK);
    for (int k = 0; k < 3; k++)
        CHECK(id[k] == UINT32_MAX && d[k] == INFINITY && isnan(u[k]) && isnan(v[k]));
    bs_locator_destroy(L);
}

int main(void)
{
    tea("teapot", 300);
    tea("teacup", 150);
    tea("teaspoon", 150);
    others();
    rules();
    return bs_test_exit("test_locator_closest");
}
