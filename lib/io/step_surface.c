/* STEP surfaces as the model's surface definitions: PLANE, CYLINDRICAL_SURFACE, CONICAL_SURFACE,
 * SPHERICAL_SURFACE, TOROIDAL_SURFACE, SURFACE_OF_REVOLUTION, SURFACE_OF_LINEAR_EXTRUSION and
 * B_SPLINE_SURFACE_WITH_KNOTS (simple or the rational complex form); others are refused by name. */
#include "io/step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HALF_PI 1.5707963267948966

void bsi_stp_surf_free(stp_surf *sf)
{
    bsi_curve_free(&sf->curve);
    free(sf->data);
    memset(sf, 0, sizeof *sf);
}

/* The swept curve of a revolution or extrusion, over a range wide enough for any face of the file. */
static bs_status swept(stp *s, size_t i, size_t r, stp_surf *sf)
{
    stp_curve c;
    bs_status st = bsi_stp_curve(s, r, 3, 0, &c);
    if (st != BS_OK)
        return st;
    double lo, hi, per = bsi_stp_curve_period(s, &c, &lo, &hi);
    if (per > 0.0) { /* three turns: room for trims on either side of a seam */
        lo = -per;
        hi = 2.0 * per;
        sf->def.curve_period = per;
    } else if (c.kind == STP_LINE) {
        double d = 0.0, len = hypot(hypot(c.d[0], c.d[1]), c.d[2]);
        for (int k = 0; k < 3; k++)
            d = hypot(d, fabs(c.p[k] - 0.5 * (s->lo[k] + s->hi[k])) + (s->hi[k] - s->lo[k]));
        lo = -2.0 * d / len;
        hi = 2.0 * d / len;
    }
    st = bsi_stp_curve_make(s, &c, lo, hi, &sf->curve);
    bsi_stp_curve_free(&c);
    if (st != BS_OK)
        return st == BS_ERR_NO_MEMORY ? st : bsi_stp_fail(s, i, "%s", "swept curve not usable");
    sf->def.curve = &sf->curve;
    return BS_OK;
}

/* The rows of control points of a B-spline surface (list of lists of references). */
static bs_status net(const stp *s, size_t i, size_t pts, size_t wl, stp_surf *sf, size_t cu, size_t cv, double *ctrl,
                     double *w)
{
    bs_status st;
    for (size_t a = 0; a < cu; a++) {
        size_t row, wrow = 0, n, r;
        if ((st = bsi_stp_list(s, i, pts, a, "a row of control points", &row)) != BS_OK ||
            (w && (st = bsi_stp_list(s, i, wl, a, "a row of weights", &wrow)) != BS_OK))
            return st;
        if (stp_at(s, row)->count != cv || (w && stp_at(s, wrow)->count != cv))
            return bsi_stp_fail(s, i, "%s", "rows of control points (and weights) must be of equal length");
        for (size_t b = 0; b < cv; b++) {
            if (!bsi_stp_arg(s, row, b, &n) || (st = bsi_stp_deref(s, i, n, "a control point", &r)) != BS_OK ||
                (st = bsi_stp_point(s, r, 3, ctrl + 3 * (a * cv + b))) != BS_OK ||
                (w && (st = bsi_stp_num(s, i, wrow, b, "a weight", w + a * cv + b)) != BS_OK))
                return st;
            if (w && !(w[a * cv + b] > 0.0))
                return bsi_stp_fail(s, i, "%s", "weights must be positive");
        }
    }
    (void)sf;
    return BS_OK;
}

/* Multiplicities ml and knots kv expanded into k[0 .. n). */
static bs_status knots(const stp *s, size_t i, size_t ml, size_t kv, double *k, size_t n)
{
    size_t at = 0;
    bs_status st;
    if (stp_at(s, ml)->count != stp_at(s, kv)->count)
        return bsi_stp_fail(s, i, "%s", "as many multiplicities as knots needed");
    for (size_t j = 0; j < stp_at(s, ml)->count; j++) {
        double m, t;
        if ((st = bsi_stp_num(s, i, ml, j, "a multiplicity", &m)) != BS_OK || (st = bsi_stp_num(s, i, kv, j, "a knot", &t)) != BS_OK)
            return st;
        if (!(m >= 1) || m > (double)(n - at) || m != floor(m))
            return bsi_stp_fail(s, i, "%s", "multiplicities must add up to the points plus the degree plus one");
        for (size_t q = 0; q < (size_t)m; q++)
            k[at++] = t;
    }
    if (at != n)
        return bsi_stp_fail(s, i, "%s", "multiplicities must add up to the points plus the degree plus one");
    for (size_t j = 1; j < n; j++)
        if (!(k[j] >= k[j - 1]))
            return bsi_stp_fail(s, i, "%s", "knots must not decrease");
    return BS_OK;
}

static bs_status bspline(const stp *s, size_t i, stp_surf *sf)
{
    size_t bl, kl, pts, wl = 0, ml[2], kv[2], ofs = 0;
    double deg[2];
    bs_status st;
    if (bsi_stp_part(s, i, "B_SPLINE_SURFACE", &bl)) {
        if (!bsi_stp_part(s, i, "B_SPLINE_SURFACE_WITH_KNOTS", &kl))
            return bsi_stp_fail(s, i, "%s", "a B-spline surface without knots is not supported");
    } else {
        (void)bsi_stp_part(s, i, "B_SPLINE_SURFACE_WITH_KNOTS", &bl);
        ofs = 1;
        kl = bl;
    }
    int rational = bsi_stp_part(s, i, "RATIONAL_B_SPLINE_SURFACE", &wl);
    size_t ko = ofs ? 8 : 0;
    if ((st = bsi_stp_num(s, i, bl, ofs, "the u degree", &deg[0])) != BS_OK ||
        (st = bsi_stp_num(s, i, bl, ofs + 1, "the v degree", &deg[1])) != BS_OK ||
        (st = bsi_stp_list(s, i, bl, ofs + 2, "the control points", &pts)) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ko, "the u multiplicities", &ml[0])) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ko + 1, "the v multiplicities", &ml[1])) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ko + 2, "the u knots", &kv[0])) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ko + 3, "the v knots", &kv[1])) != BS_OK ||
        (rational && (st = bsi_stp_list(s, i, wl, 0, "the weights", &wl)) != BS_OK))
        return st;
    size_t cu = stp_at(s, pts)->count, cv = 0, row;
    if (cu > 0 && bsi_stp_arg(s, pts, 0, &row))
        cv = stp_at(s, row)->count;
    for (int d = 0; d < 2; d++)
        if (!(deg[d] >= 1 && deg[d] <= BS_MAX_DEGREE) || deg[d] != floor(deg[d]))
            return bsi_stp_fail(s, i, "degrees must be 1..%d", BS_MAX_DEGREE);
    size_t pu = (size_t)deg[0], pv = (size_t)deg[1];
    if (cu < pu + 1 || cv < pv + 1 || (rational && stp_at(s, wl)->count != cu))
        return bsi_stp_fail(s, i, "%s", "more control points than the degree needed in each direction (and weights for each)");
    size_t nku = cu + pu + 1, nkv = cv + pv + 1, n = cu * cv;
    sf->data = malloc((nku + nkv + 4 * n) * sizeof(double));
    if (sf->data == NULL)
        return BS_ERR_NO_MEMORY;
    double *ku = sf->data, *kvv = ku + nku, *ctrl = kvv + nkv, *w = rational ? ctrl + 3 * n : NULL;
    if ((st = knots(s, i, ml[0], kv[0], ku, nku)) != BS_OK || (st = knots(s, i, ml[1], kv[1], kvv, nkv)) != BS_OK ||
        (st = net(s, i, pts, wl, sf, cu, cv, ctrl, w)) != BS_OK)
        return st;
    if (!(ku[pu] < ku[cu] && kvv[pv] < kvv[cv]))
        return bsi_stp_fail(s, i, "%s", "empty knot domain");
    bs_bspline b = {pu, pv, cu, cv, 3, ku, kvv, ctrl, w};
    sf->b = b;
    sf->def.kind = BS_FACE_BSPLINE;
    sf->def.bspline = &sf->b;
    sf->dom[0] = ku[pu];
    sf->dom[1] = ku[cu];
    sf->dom[2] = kvv[pv];
    sf->dom[3] = kvv[cv];
    return BS_OK;
}

/* The analytic surfaces: kind, the radii read after the position, angular directions. */
static bs_status analytic(stp *s, size_t i, size_t list, int kind, int radii, stp_surf *sf)
{
    size_t r;
    bs_status st = bsi_stp_ref(s, i, list, 1, "the position", &r);
    if (st != BS_OK || (st = bsi_stp_placement(s, r, 3, &sf->def.f)) != BS_OK)
        return st;
    double *rad[2] = {&sf->def.r, &sf->def.r2};
    for (int k = 0; k < radii; k++)
        if ((st = bsi_stp_num(s, i, list, 2 + (size_t)k, k ? "the second radius" : "the radius", rad[k])) != BS_OK)
            return st;
    sf->def.kind = kind;
    if (kind == BS_FACE_CONE)
        sf->def.r2 *= s->angle;
    if (kind != BS_FACE_PLANE)
        sf->scale[0] = s->angle;
    if (kind == BS_FACE_SPHERE || kind == BS_FACE_TORUS)
        sf->scale[1] = s->angle;
    if (kind == BS_FACE_SPHERE) {
        sf->dom[2] = -HALF_PI;
        sf->dom[3] = HALF_PI;
    }
    int bad = (kind != BS_FACE_PLANE && !(sf->def.r >= 0.0)) || !isfinite(sf->def.r) || !isfinite(sf->def.r2) ||
              (kind == BS_FACE_CONE && !(fabs(sf->def.r2) < HALF_PI)) || (kind == BS_FACE_TORUS && !(sf->def.r2 > 0.0)) ||
              ((kind == BS_FACE_CYLINDER || kind == BS_FACE_SPHERE) && !(sf->def.r > 0.0));
    return bad ? bsi_stp_fail(s, i, "%s", "radius or angle out of range") : BS_OK;
}

static bs_status axis1(const stp *s, size_t i, bsi_frame *f)
{
    size_t list, r;
    bs_status st;
    if (!bsi_stp_part(s, i, "AXIS1_PLACEMENT", &list))
        return bsi_stp_fail(s, i, "%s", "expected an AXIS1_PLACEMENT");
    if ((st = bsi_stp_ref(s, i, list, 1, "the location", &r)) != BS_OK || (st = bsi_stp_point(s, r, 3, f->o)) != BS_OK ||
        (st = bsi_stp_ref(s, i, list, 2, "the axis", &r)) != BS_OK || (st = bsi_stp_direction(s, r, 3, f->z)) != BS_OK)
        return st;
    double e[3] = {fabs(f->z[0]) < 0.9 ? 1.0 : 0.0, fabs(f->z[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    double d = e[0] * f->z[0] + e[1] * f->z[1];
    for (int c = 0; c < 3; c++)
        f->x[c] = e[c] - d * f->z[c];
    double n = hypot(hypot(f->x[0], f->x[1]), f->x[2]);
    for (int c = 0; c < 3; c++)
        f->x[c] /= n;
    f->y[0] = f->z[1] * f->x[2] - f->z[2] * f->x[1];
    f->y[1] = f->z[2] * f->x[0] - f->z[0] * f->x[2];
    f->y[2] = f->z[0] * f->x[1] - f->z[1] * f->x[0];
    return BS_OK;
}

bs_status bsi_stp_surface(stp *s, size_t i, stp_surf *sf)
{
    size_t list, r, v, dr;
    bs_status st;
    memset(sf, 0, sizeof *sf);
    sf->scale[0] = sf->scale[1] = 1.0;
    sf->dom[0] = sf->dom[2] = -INFINITY;
    sf->dom[1] = sf->dom[3] = INFINITY;
    sf->def.f.x[0] = sf->def.f.y[1] = sf->def.f.z[2] = 1.0;
    if (bsi_stp_part(s, i, "PLANE", &list))
        st = analytic(s, i, list, BS_FACE_PLANE, 0, sf);
    else if (bsi_stp_part(s, i, "CYLINDRICAL_SURFACE", &list))
        st = analytic(s, i, list, BS_FACE_CYLINDER, 1, sf);
    else if (bsi_stp_part(s, i, "CONICAL_SURFACE", &list))
        st = analytic(s, i, list, BS_FACE_CONE, 2, sf);
    else if (bsi_stp_part(s, i, "SPHERICAL_SURFACE", &list))
        st = analytic(s, i, list, BS_FACE_SPHERE, 1, sf);
    else if (bsi_stp_part(s, i, "TOROIDAL_SURFACE", &list))
        st = analytic(s, i, list, BS_FACE_TORUS, 2, sf);
    else if (bsi_stp_is(s, i, "B_SPLINE_SURFACE_WITH_KNOTS") || bsi_stp_is(s, i, "B_SPLINE_SURFACE"))
        st = bspline(s, i, sf);
    else if (bsi_stp_part(s, i, "SURFACE_OF_REVOLUTION", &list)) {
        sf->def.kind = BS_FACE_REVOLUTION;
        sf->scale[0] = s->angle;
        if ((st = bsi_stp_ref(s, i, list, 1, "the swept curve", &r)) == BS_OK &&
            (st = bsi_stp_ref(s, i, list, 2, "the axis", &v)) == BS_OK && (st = axis1(s, v, &sf->def.f)) == BS_OK)
            st = swept(s, i, r, sf);
    } else if (bsi_stp_part(s, i, "SURFACE_OF_LINEAR_EXTRUSION", &list)) {
        double mag;
        sf->def.kind = BS_FACE_EXTRUSION;
        if ((st = bsi_stp_ref(s, i, list, 1, "the swept curve", &r)) == BS_OK &&
            (st = bsi_stp_ref(s, i, list, 2, "the extrusion vector", &v)) == BS_OK) {
            if (!bsi_stp_part(s, v, "VECTOR", &list))
                st = bsi_stp_fail(s, v, "%s", "expected a VECTOR");
            else if ((st = bsi_stp_ref(s, v, list, 1, "the direction", &dr)) == BS_OK &&
                     (st = bsi_stp_direction(s, dr, 3, sf->def.dir)) == BS_OK &&
                     (st = bsi_stp_num(s, v, list, 2, "the magnitude", &mag)) == BS_OK) {
                if (!(mag > 0.0) || !isfinite(mag))
                    st = bsi_stp_fail(s, v, "%s", "magnitude must be positive");
                for (int c = 0; c < 3; c++)
                    sf->def.dir[c] *= mag;
                if (st == BS_OK)
                    st = swept(s, i, r, sf);
            }
        }
    } else {
        int len;
        const char *name = bsi_stp_name(s, i, &len);
        (void)bsi_fail(s->err, stp_inst_at(s, i)->line, stp_inst_at(s, i)->col, "%.*s at line %u is not supported (#%zu)",
                       len > 60 ? 60 : len, name, (unsigned)stp_inst_at(s, i)->line, stp_inst_at(s, i)->id);
        st = BS_ERR_UNSUPPORTED;
    }
    if (st != BS_OK)
        bsi_stp_surf_free(sf);
    return st;
}
