/* curv2 bodies and the loops made of them. A curv2 is kept as a B-spline (a Bezier curv2 as the
 * B-spline of its segments: each inner parameter value a knot of multiplicity degree) so that each
 * `trim u0 u1 k` cuts curve k to [u0, u1] with bsi_curve_bspline; u0 > u1 runs the curve backwards.
 * A loop must close: each trim ends where the next starts (OBJM_CLOSURE of the loop's size). */
#include "io/obj_model.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static bs_status fail_curve(objm *o, const char *msg)
{
    return bsi_fail(o->err, o->body_line, o->body_col, "%s", msg);
}

/* The knots of the open curv2 appended to cdata: the parm values of a B-spline, or those of a
 * Bezier curve's segments with multiplicity deg (deg + 1 at the ends). */
static bs_status curve_knots(objm *o, size_t deg, size_t count)
{
    const double *pv = o->parm[0].data;
    size_t np = o->parm[0].n;
    if (o->type == OBJM_BSPLINE) {
        if (!o->have_parm[0])
            return fail_curve(o, "a B-spline curve needs parm u (its knots)");
        if (count < deg + 1 || np != count + deg + 1)
            return fail_curve(o, "number of control points does not match the knots and degree");
        bs_status st = bsi_grow(&o->cdata, sizeof(double), np);
        if (st == BS_OK) {
            memcpy((double *)o->cdata.data + o->cdata.n, pv, np * sizeof(double));
            o->cdata.n += np;
        }
        return st;
    }
    static const double unit[2] = {0.0, 1.0};
    if (!o->have_parm[0])
        pv = unit, np = 2;
    if (np < 2)
        return fail_curve(o, "a parm statement needs at least two values");
    for (size_t k = 1; k < np; k++)
        if (!(pv[k] > pv[k - 1]))
            return fail_curve(o, "parameter values must increase");
    if ((count - 1) / deg != np - 1 || (count - 1) % deg != 0)
        return fail_curve(o, "number of control points does not match the degree and parameter values");
    bs_status st = bsi_grow(&o->cdata, sizeof(double), count + deg + 1);
    if (st != BS_OK)
        return st;
    double *k = (double *)o->cdata.data + o->cdata.n;
    for (size_t i = 0; i < np; i++)
        for (size_t r = 0; r < deg + (i == 0 || i == np - 1); r++)
            *k++ = pv[i];
    o->cdata.n += count + deg + 1;
    return BS_OK;
}

bs_status bsi_objm_end_curve(objm *o)
{
    size_t deg = o->deg[0], count = o->refs.n;
    if (deg == 0)
        return fail_curve(o, "a trimming curve's degree must be 1 or more");
    if (count == 0)
        return fail_curve(o, "a curve needs control points");
    size_t at = o->cdata.n;
    bs_status st = curve_knots(o, deg, count);
    if (st == BS_OK)
        st = bsi_grow(&o->cdata, sizeof(double), 3 * count);
    if (st == BS_OK)
        st = bsi_grow(&o->curves, sizeof(objm_curve), 1);
    if (st != BS_OK) {
        o->cdata.n = at;
        return st;
    }
    double *ctrl = (double *)o->cdata.data + o->cdata.n, *w = ctrl + 2 * count;
    for (size_t i = 0; i < count; i++) {
        const double *x = (const double *)o->vp.data + 4 * ((const size_t *)o->refs.data)[i];
        ctrl[2 * i] = x[0];
        ctrl[2 * i + 1] = x[1];
        w[i] = o->rat ? x[2] : 1.0;
    }
    const double *knots = (const double *)o->cdata.data + at;
    bsi_curve c;
    st = bsi_curve_bspline(2, deg, count, knots, ctrl, o->rat ? w : NULL, knots[deg], knots[count], &c);
    bsi_curve_free(&c);
    if (st != BS_OK) {
        o->cdata.n = at;
        if (st == BS_ERR_NONFINITE)
            return fail_curve(o, "weight times coordinate overflows");
        return st == BS_ERR_NO_MEMORY ? st
                                      : fail_curve(o, "knots must not decrease, repeat more than degree + 1 "
                                                      "times, or leave an empty domain");
    }
    o->cdata.n += 3 * count;
    objm_curve rec = {deg, count, at, o->rat, o->body_line, o->body_col};
    ((objm_curve *)o->curves.data)[o->curves.n++] = rec;
    return BS_OK;
}

/* One `u0 u1 k` of a trim or hole statement as a trim (errors at k, at_k its offset). */
static bs_status one_trim(objm *o, const double *u, size_t at_k, size_t k, bsi_trim *t)
{
    const objm_curve *c = (const objm_curve *)o->curves.data + k;
    const double *knots = (const double *)o->cdata.data + c->at, *ctrl = knots + c->count + c->deg + 1;
    memset(t, 0, sizeof *t);
    t->edge = BSI_NO_EDGE;
    t->reversed = u[0] > u[1];
    double t0 = t->reversed ? u[1] : u[0], t1 = t->reversed ? u[0] : u[1];
    if (!(t0 < t1))
        return bsi_objm_fail(o, at_k, "%s", "the parameter range before this curve is empty");
    if (!(t0 >= knots[c->deg] && t1 <= knots[c->count]))
        return bsi_objm_fail(o, at_k, "%s", "the parameter range before this curve leaves the curve's domain");
    bs_status st = bsi_curve_bspline(2, c->deg, c->count, knots, ctrl, c->rat ? ctrl + 2 * c->count : NULL,
                                     t0, t1, &t->uv);
    if (st == BS_OK)
        st = bsi_objm_spend(o, t->uv.axis.n * (c->deg + 1), o->line, at_k - o->line_start + 1);
    if (st != BS_OK)
        bsi_curve_free(&t->uv);
    return st;
}

/* The point where trim t starts (end = 0) or ends (end = 1) along its loop. */
static void trim_end(const bsi_trim *t, int end, double *p)
{
    int last = end != t->reversed;
    bsi_curve_point(&t->uv, last ? t->uv.axis.n - 1 : 0, last ? 1.0 : 0.0, p);
}

/* Each trim of the loop ends where the next starts, the last where the first starts. */
static bs_status check_closed(objm *o, size_t line, size_t col, const bsi_trim *t, size_t n)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < n; k++) {
        double a[2], b[2];
        bsi_curve_bounds(&t[k].uv, a, b);
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], a[c]);
            hi[c] = fmax(hi[c], b[c]);
        }
    }
    /* and a few ulps of the coordinates, which rounding moves whatever the loop's size */
    double big = fmax(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fabs(lo[1]), fabs(hi[1])));
    double tol = OBJM_CLOSURE * fmax(hi[0] - lo[0], hi[1] - lo[1]) + 16 * DBL_EPSILON * big;
    for (size_t k = 0; k < n; k++) {
        double e[2], s[2];
        trim_end(&t[k], 1, e);
        trim_end(&t[(k + 1) % n], 0, s);
        if (!(fabs(e[0] - s[0]) <= tol && fabs(e[1] - s[1]) <= tol))
            return bsi_fail(o->err, line, col,
                            "loop not closed: curve %zu of the loop ends at (%.17g, %.17g), the next starts "
                            "at (%.17g, %.17g)", k + 1, e[0], e[1], s[0], s[1]);
    }
    return BS_OK;
}

bs_status bsi_objm_loop(objm *o, size_t kw, int outer)
{
    size_t first = o->trims.n, start, tlen, line = o->line, col = kw - o->line_start + 1;
    double u[2];
    int got = 0;
    bs_status st = bsi_grow(&o->loops, sizeof(objm_loop), 1);
    while (st == BS_OK && bsi_objm_token(o, &start, &tlen)) {
        if (got < 2) {
            st = bsi_objm_number(o, start, tlen, got ? "u1" : "u0", &u[got]);
            got++;
            continue;
        }
        got = 0;
        size_t k;
        if ((st = bsi_objm_index(o, start, tlen, o->curves.n, "curv2", &k)) != BS_OK ||
            (st = bsi_grow(&o->trims, sizeof(bsi_trim), 1)) != BS_OK)
            break;
        st = one_trim(o, u, start, k, (bsi_trim *)o->trims.data + o->trims.n);
        o->trims.n += st == BS_OK;
    }
    if (st == BS_OK && (got != 0 || o->trims.n == first))
        st = bsi_objm_fail(o, o->pos, "%s", got == 1 ? "expected u1" : got == 2 ? "expected a curv2 index"
                                                                            : "expected u0 u1 and a curv2 index");
    if (st == BS_OK)
        st = check_closed(o, line, col, (const bsi_trim *)o->trims.data + first, o->trims.n - first);
    if (st != BS_OK)
        return st;
    objm_loop rec = {first, o->trims.n - first, outer, line, col};
    ((objm_loop *)o->loops.data)[o->loops.n++] = rec;
    return BS_OK;
}

void bsi_objm_drop_loops(objm *o)
{
    for (size_t k = 0; k < o->trims.n; k++)
        bsi_curve_free(&((bsi_trim *)o->trims.data)[k].uv);
    o->trims.n = 0;
    o->loops.n = 0;
}
