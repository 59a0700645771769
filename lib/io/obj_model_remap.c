/* The parameters a face is written in. OBJ surfaces are polynomial in their parameters, so a face
 * is written as the B-spline of its patches over its breaks: along a straight direction that is
 * its native parameter, along an angular one (cylinders, cones, spheres, tori, revolutions) the
 * piecewise linear parameter x' = b_k + s (b_k+1 - b_k) of the patches' local s. A trim is written
 * exactly in those parameters when its angular coordinates are constant (their value mapped, the
 * other coordinate kept: seams, meridians, the circles that bound a cylinder), or when only one
 * coordinate varies, monotonically (then it is the segment between its mapped ends: a parallel of
 * a sphere, a circle of a torus); other trims on angular faces are refused. */
#include "io/obj_model.h"

/* The face's axis along native direction d (0: u, 1: v). */
static const bsi_axis *native_axis(const bsi_face *f, int d)
{
    return (d == 0) != (f->swap != 0) ? &f->au : &f->av;
}

int bsi_objm_map(const bsi_face *f, int d, double x, double *out)
{
    const bsi_axis *a = native_axis(f, d);
    if (a->kind == BSI_AXIS_LINEAR) {
        *out = x;
        return 1;
    }
    double lo = a->breaks[0], hi = a->breaks[a->n], slack = 1e-12 * (hi - lo);
    if (x < lo && x >= lo - slack)
        x = lo; /* rounding of a trim along the box's side */
    if (x > hi && x <= hi + slack)
        x = hi;
    size_t k;
    double s;
    if (!bsi_axis_locate(a, x, &k, &s))
        return 0;
    double b0 = a->breaks[k], b1 = a->breaks[k + 1];
    *out = s <= 0.0 ? b0 : s >= 1.0 ? b1 : b0 + s * (b1 - b0);
    return 1;
}

/* 1 when coordinate d of every control point of c is the same; *mono: monotone along the curve. */
static int constant(const bsi_curve *c, int d, int *mono)
{
    size_t n = c->axis.n * (c->degree + 1);
    double first = c->hom[(size_t)d] / c->hom[2], prev = first;
    int same = 1, up = 1, down = 1;
    for (size_t k = 1; k < n; k++) {
        double x = c->hom[3 * k + (size_t)d] / c->hom[3 * k + 2];
        same &= x == first;
        up &= x >= prev;
        down &= x <= prev;
        prev = x;
    }
    *mono = up || down;
    return same;
}

int bsi_objm_trim_form(const bsi_face *f, const bsi_curve *c)
{
    int angular[2], fixed[2], mono[2];
    for (int d = 0; d < 2; d++) {
        angular[d] = native_axis(f, d)->kind != BSI_AXIS_LINEAR;
        fixed[d] = constant(c, d, &mono[d]);
    }
    double x;
    for (int d = 0; d < 2; d++) /* the values that are written must map */
        if (angular[d] && fixed[d] && !bsi_objm_map(f, d, c->hom[d] / c->hom[2], &x))
            return -1;
    if ((!angular[0] || fixed[0]) && (!angular[1] || fixed[1]))
        return OBJM_AS_IS;
    for (int d = 0; d < 2; d++)
        if (fixed[1 - d] && mono[d]) {
            double p[2], q[2];
            bsi_curve_point(c, 0, 0.0, p);
            bsi_curve_point(c, c->axis.n - 1, 1.0, q);
            if (bsi_objm_map(f, d, p[d], &x) && bsi_objm_map(f, d, q[d], &x))
                return OBJM_SEGMENT;
        }
    return -1;
}
