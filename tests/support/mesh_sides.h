/* The open sides of a surface found by brute force, independently of the library's topology, and
 * the side of the unit square an edge lies on: for the tests that check meshes for cracks. */
#ifndef BS_TEST_MESH_SIDES_H
#define BS_TEST_MESH_SIDES_H

#include <bezsurf.h>

#include <math.h>
#include <string.h>

/* Open sides of the surface by brute force: side (p,s) is open if no other side has the same
 * control points forward or reversed and the side is not collapsed. */
static int side_point(const bs_patch *p, const double *net, int s, size_t k, double *out)
{
    size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p);
    size_t d = (s == 0 || s == 2) ? m : n;
    if (k > d)
        return 0;
    size_t i = s == 0 ? k * (n + 1) : s == 1 ? m * (n + 1) + k : s == 2 ? k * (n + 1) + n : k;
    memcpy(out, net + 3 * i, 3 * sizeof(double));
    return (int)d;
}

static void open_sides(const bs_surface *s, unsigned char *open)
{
    size_t np = bs_surface_count(s);
    static double na[65 * 65 * 3], nb[65 * 65 * 3];
    for (size_t a = 0; a < np; a++)
        for (int sa = 0; sa < 4; sa++) {
            const bs_patch *pa = bs_surface_get(s, a);
            bs_patch_get_ctrl(pa, na, sizeof na / sizeof na[0], NULL, 0);
            double x0[3], x[3];
            int d = side_point(pa, na, sa, 0, x0), collapsed = 1;
            for (int k = 1; k <= d; k++) {
                side_point(pa, na, sa, (size_t)k, x);
                collapsed &= fabs(x[0] - x0[0]) + fabs(x[1] - x0[1]) + fabs(x[2] - x0[2]) < 1e-9;
            }
            int shared = 0;
            for (size_t b = 0; b < np && !collapsed && !shared; b++)
                for (int sb = 0; sb < 4 && !shared; sb++) {
                    if (b == a && sb == sa)
                        continue;
                    const bs_patch *pb = bs_surface_get(s, b);
                    bs_patch_get_ctrl(pb, nb, sizeof nb / sizeof nb[0], NULL, 0);
                    double y[3];
                    if (side_point(pb, nb, sb, 0, y) != d)
                        continue;
                    for (int rev = 0; rev < 2 && !shared; rev++) {
                        int eq = 1;
                        for (int k = 0; k <= d; k++) {
                            side_point(pa, na, sa, (size_t)k, x);
                            side_point(pb, nb, sb, (size_t)(rev ? d - k : k), y);
                            eq &= fabs(x[0] - y[0]) + fabs(x[1] - y[1]) + fabs(x[2] - y[2]) < 1e-9;
                        }
                        shared = eq;
                    }
                }
            open[4 * a + (size_t)sa] = (unsigned char)(!collapsed && !shared);
        }
}

/* Which side of the unit square both (u,v) pairs lie on, or -1. */
static int common_side(double u0, double v0, double u1, double v1)
{
    if (v0 == 0.0 && v1 == 0.0) return 0;
    if (u0 == 1.0 && u1 == 1.0) return 1;
    if (v0 == 1.0 && v1 == 1.0) return 2;
    if (u0 == 0.0 && u1 == 0.0) return 3;
    return -1;
}

#endif
