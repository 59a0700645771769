/*
 * Surfaces made from curves, as exact rational Bezier patches: a surface of revolution is each
 * Bezier segment of its curve times quadratic arcs about the axis; a surface of linear extrusion
 * each segment times a line; a B-spline surface its Bezier spans (bs_surface_add_bspline), cut at
 * the box. The curve direction keeps the curve's own map (linear, or the arcs of a conic).
 */
#include "model/analytic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct sweep_job {
    const bsi_surface_def *def;
    const bsi_axis *au, *av;
    const bsi_curve *curve;   /* cut to the box */
    const bs_surface *spans;  /* BSPLINE: every span of the B-spline */
    const double *span_box;   /* u0 u1 v0 v1 of each span */
    size_t spans_v;           /* spans along v */
} sweep_job;

/* REVOLUTION, canonical (angle u, curve v): arc a of piece i times curve point b of segment j. */
static bs_status revolution_patch(void *ctx, size_t i, size_t j, bs_patch **out)
{
    const sweep_job *job = ctx;
    const bsi_frame *f = &job->def->f;
    const bsi_curve *c = job->curve;
    double cx[3], cy[3], w[3];
    bsi_arc_points(job->au->breaks[i], job->au->breaks[i + 1], cx, cy, w);
    size_t np = c->degree + 1;
    bs_patch *p = bsi_patch_alloc(2, c->degree, 3, 1);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t b = 0; b < np; b++) {
        const double *h = c->hom + (j * np + b) * 4;
        double rel[3], radial[3], perp[3];
        for (int k = 0; k < 3; k++)
            rel[k] = h[k] / h[3] - f->o[k];
        double height = bsi_dot3(rel, f->z);
        for (int k = 0; k < 3; k++)
            radial[k] = rel[k] - height * f->z[k];
        bsi_cross3(f->z, radial, perp);
        for (size_t a = 0; a < 3; a++) {
            double *q = p->ctrl + 3 * (a * np + b);
            for (int k = 0; k < 3; k++)
                q[k] = f->o[k] + height * f->z[k] + cx[a] * radial[k] + cy[a] * perp[k];
            p->weights[a * np + b] = w[a] * h[3];
        }
    }
    bs_status st = bsi_patch_finish(p);
    if (st != BS_OK) {
        bs_patch_destroy(p);
        return st;
    }
    *out = p;
    return BS_OK;
}

/* EXTRUSION, canonical (curve u, length v): curve point a of segment i, moved v along dir. */
static bs_status extrusion_patch(void *ctx, size_t i, size_t j, bs_patch **out)
{
    const sweep_job *job = ctx;
    const bsi_curve *c = job->curve;
    size_t np = c->degree + 1;
    int rational = 0;
    for (size_t a = 0; a < np; a++)
        rational |= c->hom[(i * np + a) * 4 + 3] != 1.0;
    bs_patch *p = bsi_patch_alloc(c->degree, 1, 3, rational);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t a = 0; a < np; a++) {
        const double *h = c->hom + (i * np + a) * 4;
        for (size_t b = 0; b < 2; b++) {
            double v = job->av->breaks[j + b];
            for (int k = 0; k < 3; k++)
                p->ctrl[3 * (a * 2 + b) + (size_t)k] = h[k] / h[3] + v * job->def->dir[k];
            if (rational)
                p->weights[a * 2 + b] = h[3];
        }
    }
    bs_status st = bsi_patch_finish(p);
    if (st != BS_OK) {
        bs_patch_destroy(p);
        return st;
    }
    *out = p;
    return BS_OK;
}

/* The span of the sorted span starts lo[0..n) (stride `step`) holding x. */
static size_t span_holding(const double *lo, size_t n, size_t step, double x)
{
    size_t a = 0, b = n;
    while (b - a > 1) {
        size_t mid = a + (b - a) / 2;
        if (lo[mid * step] <= x)
            a = mid;
        else
            b = mid;
    }
    return a;
}

/* BSPLINE: piece (i, j) of the box is inside one span: that span, cut to it. */
static bs_status bspline_patch(void *ctx, size_t i, size_t j, bs_patch **out)
{
    const sweep_job *job = ctx;
    double u0 = job->au->breaks[i], u1 = job->au->breaks[i + 1];
    double v0 = job->av->breaks[j], v1 = job->av->breaks[j + 1];
    size_t nv = job->spans_v, nu = bs_surface_count(job->spans) / nv;
    size_t a = span_holding(job->span_box, nu, 4 * nv, 0.5 * (u0 + u1));
    size_t b = span_holding(job->span_box + 2, nv, 4, 0.5 * (v0 + v1));
    const double *sb = job->span_box + 4 * (a * nv + b);
    const bs_patch *span = bs_surface_get(job->spans, a * nv + b);
    double s0 = (u0 - sb[0]) / (sb[1] - sb[0]), s1 = (u1 - sb[0]) / (sb[1] - sb[0]);
    double t0 = (v0 - sb[2]) / (sb[3] - sb[2]), t1 = (v1 - sb[2]) / (sb[3] - sb[2]);
    if (s0 <= 0.0 && s1 >= 1.0 && t0 <= 0.0 && t1 >= 1.0)
        return bs_patch_clone(span, out);
    return bs_patch_subpatch(span, fmax(s0, 0.0), fmin(s1, 1.0), fmax(t0, 0.0), fmin(t1, 1.0), out);
}

/* The box's part inside [lo, hi] along one direction: 0 when empty. */
static int clip(double *x0, double *x1, double lo, double hi)
{
    *x0 = fmax(*x0, lo);
    *x1 = fmin(*x1, hi);
    return *x0 < *x1;
}

static bs_status bspline_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                                 bsi_axis *au, bsi_axis *av)
{
    const bs_bspline *b = def->bspline;
    size_t nu, nv;
    bs_status st = bs_bspline_span_count(b, &nu, &nv);
    if (st != BS_OK)
        return st;
    if (b->dim != 3)
        return BS_ERR_DIMENSION;
    double u0 = box[0], u1 = box[1], v0 = box[2], v1 = box[3];
    if (!clip(&u0, &u1, b->knots_u[b->deg_u], b->knots_u[b->count_u]) ||
        !clip(&v0, &v1, b->knots_v[b->deg_v], b->knots_v[b->count_v]))
        return BS_ERR_DOMAIN;
    bs_surface *all = NULL;
    double *span_box = malloc(4 * nu * nv * sizeof *span_box);
    if (span_box == NULL || bs_surface_create(&all) != BS_OK) {
        free(span_box);
        return BS_ERR_NO_MEMORY;
    }
    st = bs_surface_add_bspline(all, b, span_box, 4 * nu * nv, NULL);
    if (st == BS_OK)
        st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, u0, u1, b->knots_u, b->count_u + b->deg_u + 1, au);
    if (st == BS_OK)
        st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, v0, v1, b->knots_v, b->count_v + b->deg_v + 1, av);
    if (st == BS_OK) {
        sweep_job job = {def, au, av, NULL, all, span_box, nv};
        st = bsi_patch_grid(s, au, av, &job, bspline_patch);
    }
    bs_surface_destroy(all);
    free(span_box);
    return st;
}

bs_status bsi_sweep_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                            bsi_axis *au, bsi_axis *av)
{
    bs_status st;
    if (def->kind == BS_FACE_BSPLINE) {
        st = def->bspline == NULL ? BS_ERR_INVALID_ARG : bspline_patches(def, box, s, au, av);
    } else {
        const bsi_curve *c = def->curve;
        int revolve = def->kind == BS_FACE_REVOLUTION;
        double lo = revolve ? box[2] : box[0], hi = revolve ? box[3] : box[1];
        if (c == NULL || c->dim != 3 || c->axis.n == 0)
            return BS_ERR_INVALID_ARG;
        if (!clip(&lo, &hi, c->axis.breaks[0], c->axis.breaks[c->axis.n]) ||
            (revolve && !(fabs(bsi_dot3(def->f.z, def->f.z) - 1.0) <= 1e-9 && bsi_all_finite(def->f.o, 3))) ||
            (!revolve && !(bsi_all_finite(def->dir, 3) && bsi_dot3(def->dir, def->dir) > 0.0)))
            return BS_ERR_DOMAIN;
        bsi_curve cut;
        if ((st = bsi_curve_cut(c, lo, hi, &cut)) != BS_OK)
            return st;
        bsi_axis *along = revolve ? av : au, *across = revolve ? au : av;
        st = bsi_axis_copy(&cut.axis, along);
        if (st == BS_OK)
            st = bsi_axis_make(revolve ? BSI_AXIS_ANGULAR : BSI_AXIS_LINEAR, 1.0, revolve ? box[0] : box[2],
                               revolve ? box[1] : box[3], NULL, 0, across);
        if (st == BS_OK) {
            sweep_job job = {def, au, av, &cut, NULL, NULL, 0};
            st = bsi_patch_grid(s, au, av, &job, revolve ? revolution_patch : extrusion_patch);
        }
        bsi_curve_free(&cut);
    }
    if (st != BS_OK) {
        bsi_axis_free(au);
        bsi_axis_free(av);
    }
    return st;
}

/* Nonzero B-spline basis functions of degree p at x in span i (knots t): N[0..p] (de Boor). */
static void basis(const double *t, size_t p, size_t i, double x, double *N)
{
    double left[BS_MAX_DEGREE + 1], right[BS_MAX_DEGREE + 1];
    N[0] = 1.0;
    for (size_t j = 1; j <= p; j++) {
        left[j] = x - t[i + 1 - j];
        right[j] = t[i + j] - x;
        double saved = 0.0;
        for (size_t r = 0; r < j; r++) {
            double tmp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
}

/* The knot span of x: the last i with t[i] <= x < t[i+1] in [p, count), the domain's end in the last. */
static size_t find_span(const double *t, size_t p, size_t count, double x)
{
    size_t i = p;
    while (i + 1 < count && t[i + 1] <= x)
        i++;
    return i;
}

void bsi_sweep_eval(const bsi_surface_def *d, double u, double v, double *p)
{
    if (d->kind == BS_FACE_BSPLINE) {
        const bs_bspline *b = d->bspline;
        size_t iu = find_span(b->knots_u, b->deg_u, b->count_u, u), iv = find_span(b->knots_v, b->deg_v, b->count_v, v);
        double Nu[BS_MAX_DEGREE + 1], Nv[BS_MAX_DEGREE + 1], num[3] = {0, 0, 0}, den = 0.0;
        basis(b->knots_u, b->deg_u, iu, u, Nu);
        basis(b->knots_v, b->deg_v, iv, v, Nv);
        for (size_t a = 0; a <= b->deg_u; a++)
            for (size_t c = 0; c <= b->deg_v; c++) {
                size_t k = (iu - b->deg_u + a) * b->count_v + (iv - b->deg_v + c);
                double w = (b->weights ? b->weights[k] : 1.0) * Nu[a] * Nv[c];
                for (int x = 0; x < 3; x++)
                    num[x] += w * b->ctrl[3 * k + (size_t)x];
                den += w;
            }
        for (int x = 0; x < 3; x++)
            p[x] = num[x] / den;
        return;
    }
    double q[3];
    if (!bsi_curve_eval(d->curve, d->kind == BS_FACE_REVOLUTION ? v : u, q)) {
        p[0] = p[1] = p[2] = NAN;
        return;
    }
    if (d->kind == BS_FACE_EXTRUSION) {
        for (int k = 0; k < 3; k++)
            p[k] = q[k] + v * d->dir[k];
        return;
    }
    const bsi_frame *f = &d->f;
    double rel[3], radial[3], perp[3];
    for (int k = 0; k < 3; k++)
        rel[k] = q[k] - f->o[k];
    double height = bsi_dot3(rel, f->z);
    for (int k = 0; k < 3; k++)
        radial[k] = rel[k] - height * f->z[k];
    bsi_cross3(f->z, radial, perp);
    for (int k = 0; k < 3; k++)
        p[k] = f->o[k] + height * f->z[k] + cos(u) * radial[k] + sin(u) * perp[k];
}
