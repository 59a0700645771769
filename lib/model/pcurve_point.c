/*
 * Points of computed trims: a surface in native parameters (closed forms of the analytic kinds,
 * else its patches through the face's axis maps) evaluated with its partials, the foot of a 3-D
 * point on it, and the 3-D edge with its derivative.
 */
#include "model/pcurve_internal.h"

#include <math.h>
#include <string.h>

#define TWO_PI 6.283185307179586

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

int bsi_pc_closed_form(const bsi_surface_def *def)
{
    return def != NULL && (def->kind == BS_FACE_CYLINDER || def->kind == BS_FACE_CONE ||
                           def->kind == BS_FACE_SPHERE || def->kind == BS_FACE_TORUS);
}

void bsi_pc_periods(const bsi_surface_def *def, double *pu, double *pv)
{
    *pu = TWO_PI;
    *pv = def->kind == BS_FACE_TORUS ? TWO_PI : 0.0;
}

/* p = o + a x + b y + c z */
static void frame_point(const bsi_frame *f, double a, double b, double c, double *p)
{
    for (int k = 0; k < 3; k++)
        p[k] = f->o[k] + a * f->x[k] + b * f->y[k] + c * f->z[k];
}

static void frame_vector(const bsi_frame *f, double a, double b, double c, double *p)
{
    for (int k = 0; k < 3; k++)
        p[k] = a * f->x[k] + b * f->y[k] + c * f->z[k];
}

/* Closed form point and canonical partials (the formulas of internal.h; planes need none: their
 * trims are exact, pcurve_def.c). */
static void closed_eval(const bsi_surface_def *d, double u, double v, double *p, double *du, double *dv)
{
    double cu = cos(u), su = sin(u), cv = cos(v), sv = sin(v), rho, t;
    switch (d->kind) {
    case BS_FACE_CYLINDER:
        frame_point(&d->f, d->r * cu, d->r * su, v, p);
        frame_vector(&d->f, -d->r * su, d->r * cu, 0.0, du);
        frame_vector(&d->f, 0.0, 0.0, 1.0, dv);
        break;
    case BS_FACE_CONE:
        t = tan(d->r2);
        rho = d->r + v * t;
        frame_point(&d->f, rho * cu, rho * su, v, p);
        frame_vector(&d->f, -rho * su, rho * cu, 0.0, du);
        frame_vector(&d->f, t * cu, t * su, 1.0, dv);
        break;
    case BS_FACE_SPHERE:
        frame_point(&d->f, d->r * cv * cu, d->r * cv * su, d->r * sv, p);
        frame_vector(&d->f, -d->r * cv * su, d->r * cv * cu, 0.0, du);
        frame_vector(&d->f, -d->r * sv * cu, -d->r * sv * su, d->r * cv, dv);
        break;
    default: /* TORUS */
        rho = d->r + d->r2 * cv;
        frame_point(&d->f, rho * cu, rho * su, d->r2 * sv, p);
        frame_vector(&d->f, -rho * su, rho * cu, 0.0, du);
        frame_vector(&d->f, -d->r2 * sv * cu, -d->r2 * sv * su, d->r2 * cv, dv);
        break;
    }
}

/* Canonical foot of q: exact for points on the surface, the nearest point for points near it (u is
 * arbitrary on the axis of a sphere or cone: the caller's pole flags say so). */
static void closed_inverse(const bsi_surface_def *d, const double *q, double *u, double *v)
{
    double e[3] = {q[0] - d->f.o[0], q[1] - d->f.o[1], q[2] - d->f.o[2]};
    double a = dot3(e, d->f.x), b = dot3(e, d->f.y), c = dot3(e, d->f.z), h = hypot(a, b);
    *u = atan2(b, a);
    switch (d->kind) {
    case BS_FACE_CYLINDER:
        *v = c;
        break;
    case BS_FACE_CONE: {
        /* the foot on the generator (r + v tan a, v) of the half-plane of q; past the apex the
         * generator of the opposite half-plane */
        double sa = sin(d->r2), ca = cos(d->r2);
        *v = (h - d->r) * sa * ca + c * ca * ca;
        if (d->r + *v * tan(d->r2) < 0.0) {
            *v = (-h - d->r) * sa * ca + c * ca * ca;
            *u += 0.5 * TWO_PI;
        }
        break;
    }
    case BS_FACE_SPHERE:
        *v = atan2(c, h);
        break;
    default: /* TORUS */
        *v = atan2(c, h - d->r);
        break;
    }
}

/* x moved by whole periods into [lo, hi] when outside and a shift lands inside. */
static double into_box(double x, double lo, double hi, double period)
{
    if (!(period > 0.0) || (x >= lo && x <= hi) || !isfinite(x))
        return x;
    double shifted = x + period * round((0.5 * (lo + hi) - x) / period);
    return shifted >= lo && shifted <= hi ? shifted : x;
}

static int patch_eval(const bsi_pc_surf *S, const double *uv, double *p, double *du, double *dv)
{
    double x = into_box(uv[0], S->box[0], S->box[1], S->period[0]);
    double y = into_box(uv[1], S->box[2], S->box[3], S->period[1]);
    double cu = S->swap ? y : x, cv = S->swap ? x : y;
    size_t i, j;
    double st[2];
    if (!bsi_axis_locate(S->au, cu, &i, &st[0]) || !bsi_axis_locate(S->av, cv, &j, &st[1]))
        return 0;
    double ds[3], dt[3];
    bs_cview vu = {&st[0], 1, 0}, vv = {&st[1], 1, 0};
    bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
    bs_view vs[3] = {{&ds[0], 1, 0}, {&ds[1], 1, 0}, {&ds[2], 1, 0}};
    bs_view vt[3] = {{&dt[0], 1, 0}, {&dt[1], 1, 0}, {&dt[2], 1, 0}};
    if (bs_patch_eval(bs_surface_get(S->s, S->first + i * S->av->n + j), 1, &vu, &vv, pos, vs, vt) != BS_OK)
        return 0; /* LCOV_EXCL_LINE: the views are valid */
    double ru = bsi_axis_rate(S->au, i, cu), rv = bsi_axis_rate(S->av, j, cv);
    for (int c = 0; c < 3; c++) {
        (S->swap ? dv : du)[c] = ds[c] * ru;
        (S->swap ? du : dv)[c] = dt[c] * rv;
    }
    return 1;
}

int bsi_pc_eval(const bsi_pc_surf *S, const double *uv, double *p, double *du, double *dv)
{
    if (!(isfinite(uv[0]) && isfinite(uv[1])))
        return 0;
    if (S->def == NULL)
        return patch_eval(S, uv, p, du, dv);
    if (S->swap)
        closed_eval(S->def, uv[1], uv[0], p, dv, du);
    else
        closed_eval(S->def, uv[0], uv[1], p, du, dv);
    return 1;
}

/* Pole flags at a point from the lengths of the native partials. */
static int pole_flags(const double *du, const double *dv)
{
    double a = sqrt(dot3(du, du)), b = sqrt(dot3(dv, dv)), big = fmax(a, b);
    return (a <= 1e-9 * big ? BSI_PC_POLE_U : 0) | (b <= 1e-9 * big ? BSI_PC_POLE_V : 0);
}

/* Periodic directions of uv moved by whole periods nearest start. */
static void unwrap(const bsi_pc_surf *S, const double *start, double *uv)
{
    for (int k = 0; k < 2; k++)
        if (start != NULL && S->period[k] > 0.0)
            uv[k] += S->period[k] * round((start[k] - uv[k]) / S->period[k]);
}

/* Gauss-Newton from start towards the foot of q on the patches: 1 when it settles within tol. */
static int newton(const bsi_pc_surf *S, const double *q, const double *start, double tol, double *uv)
{
    double x[2] = {start[0], start[1]}, p[3], du[3], dv[3];
    double small = 1e-13 * S->scale + 1e-3 * tol;
    for (int it = 0; it < 40; it++) {
        if (!patch_eval(S, x, p, du, dv))
            return 0;
        double r[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        double a11 = dot3(du, du), a12 = dot3(du, dv), a22 = dot3(dv, dv);
        double b1 = dot3(du, r), b2 = dot3(dv, r), det = a11 * a22 - a12 * a12;
        double step[2] = {0.0, 0.0};
        if (det > 1e-18 * a11 * a22) {
            step[0] = (a22 * b1 - a12 * b2) / det;
            step[1] = (a11 * b2 - a12 * b1) / det;
        } else if (a22 >= a11 && a22 > 0.0) { /* a pole: move along the one direction there is */
            step[1] = b2 / a22;
        } else if (a11 > 0.0) {
            step[0] = b1 / a11;
        } else {
            return 0;
        }
        for (size_t k = 0; k < 2; k++) {
            x[k] += step[k];
            if (!(S->period[k] > 0.0))
                x[k] = fmin(fmax(x[k], S->box[2 * k]), S->box[2 * k + 1]);
        }
        double moved = hypot(hypot(step[0] * du[0] + step[1] * dv[0], step[0] * du[1] + step[1] * dv[1]),
                             step[0] * du[2] + step[1] * dv[2]);
        if (moved <= small) {
            if (!patch_eval(S, x, p, du, dv))
                return 0; /* LCOV_EXCL_LINE: x was evaluated just before, clamped into the box */
            if (hypot(hypot(q[0] - p[0], q[1] - p[1]), q[2] - p[2]) > tol)
                return 0;
            uv[0] = x[0];
            uv[1] = x[1];
            return 1;
        }
    }
    return 0;
}

/* The certified closest point over all patches, as native parameters. */
static bs_status global_foot(const bsi_pc_surf *S, const double *q, double *uv)
{
    double best = INFINITY;
    size_t np = S->au->n * S->av->n;
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    for (size_t k = 0; k < np; k++) {
        double st[2], d;
        bs_view uvv[2] = {{&st[0], 1, 0}, {&st[1], 1, 0}}, dv = {&d, 1, 0};
        bs_status status = bs_patch_closest_point(bs_surface_get(S->s, S->first + k), 1, qv, uvv, &dv, NULL);
        if (status != BS_OK)
            return status; /* LCOV_EXCL_LINE: only BS_ERR_NO_MEMORY */
        if (isnan(d))
            return BS_ERR_NO_MEMORY; /* q is finite: the search ran out of memory */
        if (d < best) {
            size_t i = k / S->av->n, j = k % S->av->n;
            double cu = bsi_axis_native(S->au, i, st[0]), cv = bsi_axis_native(S->av, j, st[1]);
            uv[0] = S->swap ? cv : cu;
            uv[1] = S->swap ? cu : cv;
            best = d;
        }
    }
    return best < INFINITY ? BS_OK : BS_ERR_DOMAIN;
}

bs_status bsi_pc_project(const bsi_pc_surf *S, const double *q, const double *start, double tol,
                         double *uv, double *dist, int *pole)
{
    double p[3], du[3], dv[3], x[2] = {0.0, 0.0};
    if (S->def != NULL) {
        closed_inverse(S->def, q, &x[S->swap], &x[!S->swap]);
        unwrap(S, start, x);
    } else if (start == NULL || !newton(S, q, start, tol, x)) {
        bs_status status = global_foot(S, q, x);
        if (status != BS_OK)
            return status;
        unwrap(S, start, x);
    }
    if (!bsi_pc_eval(S, x, p, du, dv))
        return BS_ERR_DOMAIN; /* LCOV_EXCL_LINE: feet lie in the box */
    uv[0] = x[0];
    uv[1] = x[1];
    *dist = hypot(hypot(q[0] - p[0], q[1] - p[1]), q[2] - p[2]);
    *pole = pole_flags(du, dv);
    return BS_OK;
}

int bsi_pc_edge(const bsi_curve *c, double t, int left, double *p, double *dp)
{
    size_t k;
    double s;
    if (c->dim != 3 || !bsi_axis_locate(&c->axis, t, &k, &s))
        return 0;
    if (left && k > 0 && t == c->axis.breaks[k]) { /* the piece ending there */
        k--;
        s = 1.0;
    }
    /* de Casteljau on the homogeneous points, keeping the last two for the derivative */
    size_t n = c->degree;
    double h[BS_MAX_DEGREE + 1][4];
    memcpy(h, c->hom + k * (n + 1) * 4, (n + 1) * 4 * sizeof(double));
    for (size_t r = 1; r < n; r++)
        for (size_t i = 0; i + r <= n; i++)
            for (int j = 0; j < 4; j++)
                h[i][j] = (1.0 - s) * h[i][j] + s * h[i + 1][j];
    double pt[4], d[4];
    for (int j = 0; j < 4; j++) {
        pt[j] = (1.0 - s) * h[0][j] + s * h[1][j];
        d[j] = (double)n * (h[1][j] - h[0][j]);
    }
    double rate = bsi_axis_rate(&c->axis, k, t);
    for (int j = 0; j < 3; j++) {
        p[j] = pt[j] / pt[3];
        dp[j] = (d[j] - p[j] * d[3]) / pt[3] * rate;
    }
    return 1;
}
