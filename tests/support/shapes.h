/* Exact rational surfaces (radius r about the z axis), the scale D of a surface, the locator
 * of one patch and a plane surface of dim 2, shared by the query and surface tests. */
#ifndef BS_TEST_SHAPES_H
#define BS_TEST_SHAPES_H

#include "harness.h"

#include <bezsurf.h>

#include <math.h>

/* The quarter circle of radius 1 in the xy-plane from (1,0) to (0,1): points and weights. */
static const double shape_arc[3][2] = {{1, 0}, {1, 1}, {0, 1}};

/* The octant x, y, z >= 0 of the sphere of radius r centred at the origin, as a surface of
 * revolution, rational biquadratic: u along the meridian from the pole (0,0,r) (the collapsed side
 * u = 0) to the equator, v around the axis. Net and weights. */
static inline void shape_sphere_octant_net(double r, double ctrl[27], double w[9])
{
    const double h = sqrt(0.5), wa[3] = {1, h, 1};
    const double meridian[3][2] = {{0, r}, {r, r}, {r, 0}}; /* distance from the axis, height */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            ctrl[(i * 3 + j) * 3] = meridian[i][0] * shape_arc[j][0];
            ctrl[(i * 3 + j) * 3 + 1] = meridian[i][0] * shape_arc[j][1];
            ctrl[(i * 3 + j) * 3 + 2] = meridian[i][1];
            w[i * 3 + j] = wa[i] * wa[j];
        }
}

/* The same octant as a patch; NULL if it cannot be made. */
static inline bs_patch *shape_sphere_octant(double r)
{
    double ctrl[27], w[9];
    bs_patch *p = NULL;
    shape_sphere_octant_net(r, ctrl, w);
    return bs_patch_create(2, 2, 3, ctrl, w, &p) == BS_OK ? p : NULL;
}

/* A quarter of the cylinder, degree (1,2): u along the axis from z = 0 to `height`, v around. */
static inline void shape_cylinder_quarter(double r, double height, double ctrl[18], double w[6])
{
    const double h = sqrt(0.5), wa[3] = {1, h, 1};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++) {
            ctrl[(i * 3 + j) * 3] = r * shape_arc[j][0];
            ctrl[(i * 3 + j) * 3 + 1] = r * shape_arc[j][1];
            ctrl[(i * 3 + j) * 3 + 2] = height * i;
            w[i * 3 + j] = wa[j];
        }
}

/* D: the diagonal of the box of every control point of a surface. */
static inline double shape_diagonal(const bs_surface *s)
{
    size_t dim = bs_surface_dim(s);
    double lo[BS_MAX_DIM], hi[BS_MAX_DIM], d = 0;
    for (size_t c = 0; c < dim; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        double a[BS_MAX_DIM], b[BS_MAX_DIM];
        bs_patch_bounds(bs_surface_get(s, i), a, b);
        for (size_t c = 0; c < dim; c++) {
            lo[c] = fmin(lo[c], a[c]);
            hi[c] = fmax(hi[c], b[c]);
        }
    }
    for (size_t c = 0; c < dim; c++)
        d = hypot(d, hi[c] - lo[c]);
    return d;
}

/* A locator of patch p alone (it keeps its own copy); each step checked. */
static inline bs_locator *shape_locator(const bs_patch *p)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_locator_create(s, &L), BS_OK);
    bs_surface_destroy(s);
    return L;
}

/* A surface of one bilinear patch of dim 2 (the unit square of the plane): it has no normals.
 * Each step checked; release with bs_surface_destroy(). */
static inline bs_surface *shape_flat_surface(void)
{
    static const double net2[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p = NULL;
    bs_surface *s = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 2, net2, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    bs_patch_destroy(p);
    return s;
}

#endif
