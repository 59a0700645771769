/* Exact shapes, and the scale D of a surface, shared by the query tests. */
#ifndef BS_TEST_SHAPES_H
#define BS_TEST_SHAPES_H

#include <bezsurf.h>

#include <math.h>

/* The octant x, y, z >= 0 of the sphere of radius r centred at the origin, as a surface of
 * revolution (rational biquadratic): u along the meridian from the pole (the collapsed side
 * u = 0), v around the z axis. NULL if the patch cannot be made. */
static inline bs_patch *shape_sphere_octant(double r)
{
    const double h = sqrt(0.5);
    const double q[3][3] = {{0, 0, r}, {r, 0, r}, {r, 0, 0}}, wq[3] = {1, h, 1};
    const double a[3][2] = {{1, 0}, {1, 1}, {0, 1}}, wa[3] = {1, h, 1};
    double ctrl[27], w[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            ctrl[(i * 3 + j) * 3] = q[i][0] * a[j][0];
            ctrl[(i * 3 + j) * 3 + 1] = q[i][0] * a[j][1];
            ctrl[(i * 3 + j) * 3 + 2] = q[i][2];
            w[i * 3 + j] = wq[i] * wa[j];
        }
    bs_patch *p = NULL;
    return bs_patch_create(2, 2, 3, ctrl, w, &p) == BS_OK ? p : NULL;
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

#endif
