/* Exact rational surfaces shared by the query tests, radius r about the z axis. */
#ifndef BS_TEST_SHAPES_H
#define BS_TEST_SHAPES_H

#include <math.h>

/* The quarter circle of radius 1 in the xy-plane from (1,0) to (0,1): points and weights. */
static const double shape_arc[3][2] = {{1, 0}, {1, 1}, {0, 1}};

/* An octant of the sphere as a surface of revolution, rational biquadratic: u along the meridian
 * from the pole (0,0,r) (the collapsed side u = 0) to the equator, v around the axis. */
static inline void shape_sphere_octant(double r, double ctrl[27], double w[9])
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

#endif
