/*
 * Computed trims before the face exists: the surface from its definition (closed forms for the
 * analytic kinds, patches over the face's box or the surface's domain for the others).
 */
#include "model/pcurve_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586

/* Range of x . d over the Cartesian control points of a 3-D curve. */
static void dot_range(const bsi_curve *c, const double *d, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t i = 0; i < c->axis.n * (c->degree + 1); i++) {
        const double *h = c->hom + i * 4;
        double x = (h[0] * d[0] + h[1] * d[1] + h[2] * d[2]) / h[3];
        *lo = fmin(*lo, x);
        *hi = fmax(*hi, x);
    }
}

bs_status bsi_pc_default_box(const bsi_surface_def *def, const bsi_curve *edge, double *box)
{
    if (def->kind == BS_FACE_BSPLINE && def->bspline != NULL) {
        const bs_bspline *b = def->bspline;
        box[0] = b->knots_u[b->deg_u];
        box[1] = b->knots_u[b->count_u];
        box[2] = b->knots_v[b->deg_v];
        box[3] = b->knots_v[b->count_v];
        return BS_OK;
    }
    if (def->curve == NULL || def->curve->axis.n == 0)
        return BS_ERR_DOMAIN;
    const bsi_axis *a = &def->curve->axis;
    if (def->kind == BS_FACE_REVOLUTION) {
        box[0] = 0.0;
        box[1] = TWO_PI;
        box[2] = a->breaks[0];
        box[3] = a->breaks[a->n];
        return BS_OK;
    }
    if (def->kind != BS_FACE_EXTRUSION)
        return BS_ERR_DOMAIN;
    /* p = curve(u) + v dir gives v = (p.dir - curve(u).dir) / |dir|^2 */
    double dd = def->dir[0] * def->dir[0] + def->dir[1] * def->dir[1] + def->dir[2] * def->dir[2];
    double elo, ehi, clo, chi;
    if (!(dd > 0.0))
        return BS_ERR_DOMAIN;
    dot_range(edge, def->dir, &elo, &ehi);
    dot_range(def->curve, def->dir, &clo, &chi);
    double v0 = (elo - chi) / dd, v1 = (ehi - clo) / dd, margin = 1e-6 * (v1 - v0) + 1e-9;
    box[0] = a->breaks[0];
    box[1] = a->breaks[a->n];
    box[2] = v0 - margin;
    box[3] = v1 + margin;
    return BS_OK;
}

/* A plane's trim exactly: the edge's control points in the plane's (u, v), its own axis (trim
 * parameter = edge parameter, rational arcs stay exact). BS_ERR_DOMAIN when a control point lies
 * off the plane by more than tol (within tol each, the whole curve is: the convex hull). */
static bs_status plane_trim(const bsi_surface_def *def, int swap, const bsi_curve *edge, double tol,
                            bsi_trim *out)
{
    size_t np = edge->axis.n * (edge->degree + 1);
    for (size_t i = 0; i < np; i++) {
        const double *h = edge->hom + i * 4;
        double e[3] = {h[0] / h[3] - def->f.o[0], h[1] / h[3] - def->f.o[1], h[2] / h[3] - def->f.o[2]};
        if (!(fabs(e[0] * def->f.z[0] + e[1] * def->f.z[1] + e[2] * def->f.z[2]) <= tol))
            return BS_ERR_DOMAIN;
    }
    bsi_curve c;
    memset(&c, 0, sizeof c);
    bs_status st = bsi_axis_copy(&edge->axis, &c.axis);
    if (st != BS_OK)
        return st;
    /* NOLINTNEXTLINE(clang-analyzer-optin.portability.UnixAPI): np >= 1, axis.n >= 1 was checked */
    if ((c.hom = malloc(np * 3 * sizeof *c.hom)) == NULL) {
        bsi_axis_free(&c.axis);
        return BS_ERR_NO_MEMORY;
    }
    c.dim = 2;
    c.degree = edge->degree;
    for (size_t i = 0; i < np; i++) {
        const double *h = edge->hom + i * 4;
        double w = h[3], e[3] = {h[0] - w * def->f.o[0], h[1] - w * def->f.o[1], h[2] - w * def->f.o[2]};
        double a = e[0] * def->f.x[0] + e[1] * def->f.x[1] + e[2] * def->f.x[2];
        double b = e[0] * def->f.y[0] + e[1] * def->f.y[1] + e[2] * def->f.y[2];
        c.hom[i * 3 + 0] = swap ? b : a;
        c.hom[i * 3 + 1] = swap ? a : b;
        c.hom[i * 3 + 2] = w;
    }
    out->uv = c;
    out->computed = 1;
    return BS_OK;
}

bs_status bsi_pcurve_project_def(const bsi_surface_def *def, int swap, const double *box,
                                 const double *hint, const bsi_curve *edge, double tol,
                                 bsi_trim *out)
{
    memset(out, 0, sizeof *out);
    out->edge = BSI_NO_EDGE;
    if (def == NULL || edge == NULL || edge->dim != 3 || edge->axis.n == 0 || edge->hom == NULL)
        return BS_ERR_INVALID_ARG;
    if (!(tol > 0.0))
        return BS_ERR_INVALID_ARG;
    if (def->kind == BS_FACE_PLANE)
        return plane_trim(def, swap != 0, edge, tol, out);
    bsi_pc_surf S;
    memset(&S, 0, sizeof S);
    S.swap = swap != 0;
    double pc[2], canon[4], native[4];
    if (bsi_pc_closed_form(def)) {
        S.def = def;
        bsi_pc_periods(def, &pc[0], &pc[1]);
        S.period[0] = pc[S.swap];
        S.period[1] = pc[!S.swap];
        double own[4] = {0.0, S.period[0], 0.0, S.period[1]};
        return bsi_pc_fit(&S, edge, hint, box != NULL ? box : own, tol, out);
    }
    bs_status st = BS_OK;
    if (box != NULL) {
        memcpy(native, box, sizeof native);
        memcpy(canon, box, sizeof canon);
        if (S.swap)
            canon[0] = box[2], canon[1] = box[3], canon[2] = box[0], canon[3] = box[1];
    } else if ((st = bsi_pc_default_box(def, edge, canon)) == BS_OK) {
        memcpy(native, canon, sizeof native);
        if (S.swap)
            native[0] = canon[2], native[1] = canon[3], native[2] = canon[0], native[3] = canon[1];
    }
    if (st != BS_OK)
        return st;
    bs_surface *s;
    bsi_axis au, av;
    if (bs_surface_create(&s) != BS_OK)
        return BS_ERR_NO_MEMORY;
    if ((st = bsi_surface_def_patches(def, canon, s, &au, &av)) == BS_OK) {
        bsi_surface_def_periods(def, &pc[0], &pc[1]);
        S.s = s;
        S.au = &au;
        S.av = &av;
        memcpy(S.box, native, sizeof S.box);
        S.period[0] = pc[S.swap];
        S.period[1] = pc[!S.swap];
        st = bsi_pc_fit(&S, edge, hint, native, tol, out);
        bsi_axis_free(&au);
        bsi_axis_free(&av);
    }
    bs_surface_destroy(s);
    return st;
}
