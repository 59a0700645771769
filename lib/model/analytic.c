/*
 * Planes, cylinders, cones, spheres and tori as exact rational Bezier patches over a parameter
 * box (the canonical parameters of lib/model/internal.h). An angular direction is cut into equal
 * pieces of at most a quarter turn, each the quadratic arc of weights (1, cos a, 1) over its
 * angle 2a; a straight direction is one linear piece. Every patch is the tensor product of the
 * two directions' rational curves, so it is the surface exactly. Revolutions, extrusions and
 * B-splines are in analytic_sweep.c; what both use is in analytic_grid.c.
 */
#include "model/analytic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A direction's control rows: an angular piece's three arc points or a linear piece's two ends,
 * as (first, second) coordinates with weights: for u, (cos, sin) of the angle or the value. */
typedef struct dir_rows {
    size_t n;               /* points: 3 (arc) or 2 (line) */
    double a[3], b[3], w[3];
} dir_rows;

static void rows_of(const bsi_axis *axis, size_t k, dir_rows *r)
{
    double lo = axis->breaks[k], hi = axis->breaks[k + 1];
    if (axis->kind == BSI_AXIS_ANGULAR) {
        r->n = 3;
        bsi_arc_points(lo, hi, r->a, r->b, r->w);
    } else {
        r->n = 2;
        r->a[0] = lo, r->a[1] = hi, r->b[0] = r->b[1] = 0.0, r->w[0] = r->w[1] = 1.0;
    }
}

/* The control point of row i (along u) and column j (along v) of an analytic kind. */
static void analytic_point(const bsi_surface_def *d, const dir_rows *ru, size_t i, const dir_rows *rv,
                           size_t j, double *p)
{
    const bsi_frame *f = &d->f;
    double x = 0.0, y = 0.0, z = 0.0; /* in the frame */
    switch (d->kind) {
    case BS_FACE_PLANE:
        x = ru->a[i], y = rv->a[j];
        break;
    case BS_FACE_CYLINDER:
        x = d->r * ru->a[i], y = d->r * ru->b[i], z = rv->a[j];
        break;
    case BS_FACE_CONE: {
        double radius = d->r + rv->a[j] * tan(d->r2);
        x = radius * ru->a[i], y = radius * ru->b[i], z = rv->a[j];
        break;
    }
    case BS_FACE_SPHERE: /* the meridian arc (rho, h) = r (cos v, sin v) */
        x = d->r * rv->a[j] * ru->a[i], y = d->r * rv->a[j] * ru->b[i], z = d->r * rv->b[j];
        break;
    default: { /* TORUS: the meridian circle of radius r2 about (r, 0) */
        double rho = d->r + d->r2 * rv->a[j];
        x = rho * ru->a[i], y = rho * ru->b[i], z = d->r2 * rv->b[j];
        break;
    }
    }
    for (int c = 0; c < 3; c++)
        p[c] = f->o[c] + x * f->x[c] + y * f->y[c] + z * f->z[c];
}

typedef struct analytic_job {
    const bsi_surface_def *def;
    const bsi_axis *au, *av;
} analytic_job;

static bs_status analytic_patch(void *ctx, size_t i, size_t j, bs_patch **out)
{
    const analytic_job *job = ctx;
    dir_rows ru, rv;
    rows_of(job->au, i, &ru);
    rows_of(job->av, j, &rv);
    int rational = ru.n == 3 || rv.n == 3;
    bs_patch *p = bsi_patch_alloc(ru.n - 1, rv.n - 1, 3, rational);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t a = 0; a < ru.n; a++)
        for (size_t b = 0; b < rv.n; b++) {
            size_t k = a * rv.n + b;
            analytic_point(job->def, &ru, a, &rv, b, p->ctrl + 3 * k);
            if (rational)
                p->weights[k] = ru.w[a] * rv.w[b];
        }
    bs_status st = bsi_patch_finish(p);
    if (st != BS_OK) {
        bs_patch_destroy(p);
        return st;
    }
    *out = p;
    return BS_OK;
}

/* The kinds' rules on radii and angles. */
static int radii_valid(const bsi_surface_def *d)
{
    switch (d->kind) {
    case BS_FACE_CYLINDER:
    case BS_FACE_SPHERE: return isfinite(d->r) && d->r > 0.0;
    case BS_FACE_CONE: return isfinite(d->r) && d->r >= 0.0 && fabs(d->r2) < 1.5707963267948966;
    case BS_FACE_TORUS: return isfinite(d->r) && isfinite(d->r2) && d->r >= 0.0 && d->r2 > 0.0;
    default: return 1;
    }
}

bs_status bsi_surface_def_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                                  bsi_axis *au, bsi_axis *av)
{
    memset(au, 0, sizeof *au);
    memset(av, 0, sizeof *av);
    if (!(isfinite(box[0]) && isfinite(box[1]) && isfinite(box[2]) && isfinite(box[3]) && box[0] < box[1] &&
          box[2] < box[3]))
        return BS_ERR_DOMAIN;
    if (def->kind == BS_FACE_REVOLUTION || def->kind == BS_FACE_EXTRUSION || def->kind == BS_FACE_BSPLINE)
        return bsi_sweep_patches(def, box, s, au, av);
    if (def->kind < BS_FACE_PLANE || def->kind > BS_FACE_TORUS || !bsi_frame_valid(&def->f) || !radii_valid(def))
        return BS_ERR_DOMAIN;
    int ang_u = def->kind != BS_FACE_PLANE;
    int ang_v = def->kind == BS_FACE_SPHERE || def->kind == BS_FACE_TORUS;
    bs_status st = bsi_axis_make(ang_u ? BSI_AXIS_ANGULAR : BSI_AXIS_LINEAR, 1.0, box[0], box[1], NULL, 0, au);
    if (st == BS_OK)
        st = bsi_axis_make(ang_v ? BSI_AXIS_ANGULAR : BSI_AXIS_LINEAR, 1.0, box[2], box[3], NULL, 0, av);
    if (st == BS_OK) {
        analytic_job job = {def, au, av};
        st = bsi_patch_grid(s, au, av, &job, analytic_patch);
    }
    if (st != BS_OK) {
        bsi_axis_free(au);
        bsi_axis_free(av);
    }
    return st;
}

void bsi_surface_def_eval(const bsi_surface_def *d, double u, double v, double *p)
{
    if (d->kind == BS_FACE_REVOLUTION || d->kind == BS_FACE_EXTRUSION || d->kind == BS_FACE_BSPLINE) {
        bsi_sweep_eval(d, u, v, p);
        return;
    }
    double x, y, z;
    switch (d->kind) {
    case BS_FACE_PLANE: x = u, y = v, z = 0.0; break;
    case BS_FACE_CYLINDER: x = d->r * cos(u), y = d->r * sin(u), z = v; break;
    case BS_FACE_CONE: {
        double radius = d->r + v * tan(d->r2);
        x = radius * cos(u), y = radius * sin(u), z = v;
        break;
    }
    case BS_FACE_SPHERE: x = d->r * cos(v) * cos(u), y = d->r * cos(v) * sin(u), z = d->r * sin(v); break;
    default: {
        double rho = d->r + d->r2 * cos(v);
        x = rho * cos(u), y = rho * sin(u), z = d->r2 * sin(v);
        break;
    }
    }
    for (int c = 0; c < 3; c++)
        p[c] = d->f.o[c] + x * d->f.x[c] + y * d->f.y[c] + z * d->f.z[c];
}

void bsi_surface_def_periods(const bsi_surface_def *def, double *pu, double *pv)
{
    const double turn = 6.283185307179586;
    int u_turns = def->kind >= BS_FACE_CYLINDER && def->kind <= BS_FACE_REVOLUTION;
    *pu = u_turns ? turn : def->kind == BS_FACE_EXTRUSION ? def->curve_period : 0.0;
    *pv = def->kind == BS_FACE_TORUS ? turn : def->kind == BS_FACE_REVOLUTION ? def->curve_period : 0.0;
}
