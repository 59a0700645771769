/*
 * The canonical (u, v) of the point of a plane, cylinder, cone, sphere or torus nearest a given
 * point, in closed form. In the frame the point is (a, b, c); the surface's points in the plane
 * through the axis and the point are those of the meridian at u = atan2(b, a) (radius h = |(a, b)|
 * on the point's side) and those of the meridian at u + pi, whose signed radius is negative there
 * (a cone past its apex, a spindle torus's inner lobes): the nearer of the two feet wins.
 */
#include "model/internal.h"

#include <float.h>
#include <math.h>

#define TURN 6.283185307179586
#define HALF_TURN 3.141592653589793

/* x moved by whole turns to the one nearest near, or into [0, 2 pi) when near is NULL or NaN. */
static double unwrap(double x, const double *near)
{
    int own = near == NULL || !isfinite(*near);
    double y = x + TURN * round(((own ? HALF_TURN : *near) - x) / TURN);
    if (own && y >= TURN) /* x = 0 (or just below) rounds up to 2 pi */
        y -= TURN;
    return y;
}

int bsi_surface_def_inverse(const bsi_surface_def *def, const double *p, const double *hint, double *uv)
{
    if (def->kind < BS_FACE_PLANE || def->kind > BS_FACE_TORUS || !bsi_all_finite(p, 3))
        return 0;
    const bsi_frame *f = &def->f;
    double e[3] = {p[0] - f->o[0], p[1] - f->o[1], p[2] - f->o[2]};
    double a = bsi_dot3(e, f->x), b = bsi_dot3(e, f->y), c = bsi_dot3(e, f->z), h = hypot(a, b);
    if (def->kind == BS_FACE_PLANE) {
        uv[0] = a, uv[1] = b;
        return 1;
    }
    /* u is undefined on the axis: there h is rounding of the point's coordinates */
    double scale = fmax(fmax(fabs(a), fabs(b)), fmax(fabs(c), fabs(def->r)));
    if (!(h > 16.0 * DBL_EPSILON * scale))
        return 0;
    double u = atan2(b, a), v;
    switch (def->kind) {
    case BS_FACE_CYLINDER:
        v = c;
        break;
    case BS_FACE_CONE: {
        /* the meridian (r + v t, v) at u and (-(r + v t), v) at u + pi; their feet */
        double t = tan(def->r2), n2 = 1.0 + t * t;
        double v1 = ((h - def->r) * t + c) / n2, v2 = (c - (h + def->r) * t) / n2;
        double d1 = hypot(def->r + v1 * t - h, v1 - c), d2 = hypot(def->r + v2 * t + h, v2 - c);
        v = v1;
        if (d2 < d1) {
            v = v2;
            u += HALF_TURN;
        }
        break;
    }
    case BS_FACE_SPHERE:
        v = atan2(c, h);
        break;
    default: { /* TORUS: the core circle through (r, 0) at u, through (-r, 0) at u + pi */
        double d1 = fabs(hypot(h - def->r, c) - def->r2), d2 = fabs(hypot(h + def->r, c) - def->r2);
        double x = h - def->r;
        if (d2 < d1) {
            x = -(h + def->r);
            u += HALF_TURN;
        }
        if (!(hypot(x, c) > 16.0 * DBL_EPSILON * scale))
            return 0; /* on the core circle: v undefined */
        v = unwrap(atan2(c, x), hint != NULL ? hint + 1 : NULL);
        break;
    }
    }
    uv[0] = unwrap(u, hint);
    uv[1] = v;
    return 1;
}
