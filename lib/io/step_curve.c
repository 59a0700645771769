/* STEP points, directions, placements and curves (LINE, CIRCLE, ELLIPSE, B_SPLINE_CURVE_WITH_KNOTS
 * simple or in the rational complex form, TRIMMED_CURVE through its basis), in 3-D for edges and in
 * 2-D for parameter-space curves, with the parameter of a point (vertices on their edge's curve). */
#include "io/step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586

/* p -> r p (+ t when translate): a placed copy's points and directions. */
static void move(const stp_xf *m, int translate, double *p)
{
    double q[3];
    for (size_t r = 0; r < 3; r++)
        q[r] = m->r[3 * r] * p[0] + m->r[3 * r + 1] * p[1] + m->r[3 * r + 2] * p[2] + (translate ? m->t[r] : 0.0);
    memcpy(p, q, sizeof q);
}

static bs_status raw_point(const stp *s, size_t i, size_t dim, double *p)
{
    size_t list, co;
    bs_status st;
    if (!bsi_stp_part(s, i, "CARTESIAN_POINT", &list))
        return bsi_stp_fail(s, i, "%s", "expected a CARTESIAN_POINT");
    if ((st = bsi_stp_list(s, i, list, 1, "the coordinates", &co)) != BS_OK)
        return st;
    if (stp_at(s, co)->count != dim)
        return bsi_stp_fail(s, i, "expected %zu coordinates", dim);
    for (size_t c = 0; c < dim; c++)
        if ((st = bsi_stp_num(s, i, co, c, "a coordinate", &p[c])) != BS_OK)
            return st;
    return BS_OK;
}

static bs_status raw_direction(const stp *s, size_t i, size_t dim, double *d)
{
    size_t list, co;
    bs_status st;
    if (!bsi_stp_part(s, i, "DIRECTION", &list))
        return bsi_stp_fail(s, i, "%s", "expected a DIRECTION");
    if ((st = bsi_stp_list(s, i, list, 1, "the ratios", &co)) != BS_OK)
        return st;
    if (stp_at(s, co)->count != dim)
        return bsi_stp_fail(s, i, "expected %zu direction ratios", dim);
    double n = 0.0;
    for (size_t c = 0; c < dim; c++) {
        if ((st = bsi_stp_num(s, i, co, c, "a direction ratio", &d[c])) != BS_OK)
            return st;
        n = hypot(n, d[c]);
    }
    if (!(n > 0.0) || !isfinite(n))
        return bsi_stp_fail(s, i, "%s", "direction of zero length");
    for (size_t c = 0; c < dim; c++)
        d[c] /= n;
    return BS_OK;
}

bs_status bsi_stp_point(const stp *s, size_t i, size_t dim, double *p)
{
    bs_status st = raw_point(s, i, dim, p);
    if (st == BS_OK && dim == 3 && s->moved)
        move(&s->xf, 1, p);
    return st;
}

bs_status bsi_stp_direction(const stp *s, size_t i, size_t dim, double *d)
{
    bs_status st = raw_direction(s, i, dim, d);
    if (st == BS_OK && dim == 3 && s->moved)
        move(&s->xf, 0, d);
    return st;
}

/* An optional direction (argument k, `$` gives def), as the file writes it. */
static bs_status opt_direction(const stp *s, size_t i, size_t list, size_t k, size_t dim, const double *def, double *d)
{
    size_t n, r;
    if (bsi_stp_arg(s, list, k, &n) && stp_at(s, n)->kind == STP_UNSET) {
        memcpy(d, def, dim * sizeof *d);
        return BS_OK;
    }
    bs_status st = bsi_stp_ref(s, i, list, k, "a direction", &r);
    return st != BS_OK ? st : raw_direction(s, r, dim, d);
}

bs_status bsi_stp_placement(const stp *s, size_t i, size_t dim, bsi_frame *f)
{
    size_t list, r;
    bs_status st;
    static const double ez[3] = {0, 0, 1}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    memset(f, 0, sizeof *f);
    if (!bsi_stp_part(s, i, dim == 3 ? "AXIS2_PLACEMENT_3D" : "AXIS2_PLACEMENT_2D", &list))
        return bsi_stp_fail(s, i, "expected an AXIS2_PLACEMENT_%zuD", dim);
    if ((st = bsi_stp_ref(s, i, list, 1, "the location", &r)) != BS_OK || (st = raw_point(s, r, dim, f->o)) != BS_OK)
        return st;
    if (dim == 2) {
        if ((st = opt_direction(s, i, list, 2, 2, ex, f->x)) != BS_OK)
            return st;
        f->y[0] = -f->x[1];
        f->y[1] = f->x[0];
        f->z[2] = 1.0;
        return BS_OK;
    }
    double x[3] = {0, 0, 0};
    if ((st = opt_direction(s, i, list, 2, 3, ez, f->z)) != BS_OK ||
        (st = opt_direction(s, i, list, 3, 3, fabs(f->z[0]) < 0.9 ? ex : ey, x)) != BS_OK)
        return st;
    double d = x[0] * f->z[0] + x[1] * f->z[1] + x[2] * f->z[2];
    for (int c = 0; c < 3; c++)
        x[c] -= d * f->z[c];
    double n = hypot(hypot(x[0], x[1]), x[2]);
    if (!(n > 1e-12))
        return bsi_stp_fail(s, i, "%s", "reference direction parallel to the axis");
    for (int c = 0; c < 3; c++)
        f->x[c] = x[c] / n;
    f->y[0] = f->z[1] * f->x[2] - f->z[2] * f->x[1];
    f->y[1] = f->z[2] * f->x[0] - f->z[0] * f->x[2];
    f->y[2] = f->z[0] * f->x[1] - f->z[1] * f->x[0];
    if (s->moved) {
        move(&s->xf, 1, f->o);
        move(&s->xf, 0, f->x);
        move(&s->xf, 0, f->y);
        move(&s->xf, 0, f->z);
    }
    return BS_OK;
}

void bsi_stp_curve_free(stp_curve *c)
{
    free(c->data);
    memset(c, 0, sizeof *c);
}

/* B_SPLINE_CURVE_WITH_KNOTS, simple (name first) or the parts of the complex form. */
static bs_status bspline(const stp *s, size_t i, size_t dim, stp_curve *out)
{
    size_t bl, kl, pts, ml, kv, wl = 0, n = 0, r = 0, ofs = 0;
    double deg;
    bs_status st;
    if (bsi_stp_part(s, i, "B_SPLINE_CURVE", &bl)) {
        if (!bsi_stp_part(s, i, "B_SPLINE_CURVE_WITH_KNOTS", &kl))
            return bsi_stp_fail(s, i, "%s", "a B-spline curve without knots is not supported");
    } else {
        (void)bsi_stp_part(s, i, "B_SPLINE_CURVE_WITH_KNOTS", &bl);
        ofs = 1;
        kl = bl;
    }
    int rational = bsi_stp_part(s, i, "RATIONAL_B_SPLINE_CURVE", &wl);
    if ((st = bsi_stp_num(s, i, bl, ofs, "the degree", &deg)) != BS_OK ||
        (st = bsi_stp_list(s, i, bl, ofs + 1, "the control points", &pts)) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ofs ? 6 : 0, "the multiplicities", &ml)) != BS_OK ||
        (st = bsi_stp_list(s, i, kl, ofs ? 7 : 1, "the knots", &kv)) != BS_OK ||
        (rational && (st = bsi_stp_list(s, i, wl, 0, "the weights", &wl)) != BS_OK))
        return st;
    size_t count = stp_at(s, pts)->count;
    if (!(deg >= 1 && deg <= BS_MAX_DEGREE) || deg != floor(deg) || count < (size_t)deg + 1)
        return bsi_stp_fail(s, i, "degree must be 1..%d with more control points than the degree", BS_MAX_DEGREE);
    size_t p = (size_t)deg, nk = count + p + 1;
    if (stp_at(s, ml)->count != stp_at(s, kv)->count || (rational && stp_at(s, wl)->count != count))
        return bsi_stp_fail(s, i, "%s", "as many multiplicities as knots and weights as points needed");
    out->data = malloc((nk + (dim + 1) * count) * sizeof(double));
    if (out->data == NULL)
        return BS_ERR_NO_MEMORY;
    out->kind = STP_BSPLINE;
    out->dim = dim;
    out->degree = p;
    out->count = count;
    out->knots = out->data;
    out->ctrl = out->data + nk;
    out->weights = rational ? out->ctrl + dim * count : NULL;
    size_t at = 0;
    for (size_t k = 0; k < stp_at(s, ml)->count; k++) {
        double m, t;
        if ((st = bsi_stp_num(s, i, ml, k, "a multiplicity", &m)) != BS_OK ||
            (st = bsi_stp_num(s, i, kv, k, "a knot", &t)) != BS_OK)
            return st;
        if (!(m >= 1) || m > (double)(nk - at) || m != floor(m))
            return bsi_stp_fail(s, i, "%s", "multiplicities must add up to the points plus the degree plus one");
        for (size_t j = 0; j < (size_t)m; j++)
            out->knots[at++] = t;
    }
    if (at != nk)
        return bsi_stp_fail(s, i, "%s", "multiplicities must add up to the points plus the degree plus one");
    for (size_t k = 0; k < count; k++) {
        if ((st = bsi_stp_arg(s, pts, k, &n) ? bsi_stp_deref(s, i, n, "a control point", &r) : BS_ERR_PARSE) != BS_OK ||
            (st = bsi_stp_point(s, r, dim, out->ctrl + dim * k)) != BS_OK ||
            (rational && (st = bsi_stp_num(s, i, wl, k, "a weight", out->weights + k)) != BS_OK))
            return st;
        if (rational && !(out->weights[k] > 0.0))
            return bsi_stp_fail(s, i, "%s", "weights must be positive");
    }
    for (size_t k = 1; k < nk; k++)
        if (!(out->knots[k] >= out->knots[k - 1]))
            return bsi_stp_fail(s, i, "%s", "knots must not decrease");
    if (!(out->knots[p] < out->knots[count]))
        return bsi_stp_fail(s, i, "%s", "empty knot domain");
    return BS_OK;
}

static bs_status unsupported(const stp *s, size_t i)
{
    int len;
    const char *name = bsi_stp_name(s, i, &len);
    (void)bsi_fail(s->err, stp_inst_at(s, i)->line, stp_inst_at(s, i)->col, "%.*s at line %u is not supported (#%zu)",
                   len > 60 ? 60 : len, name, (unsigned)stp_inst_at(s, i)->line, stp_inst_at(s, i)->id);
    return BS_ERR_UNSUPPORTED;
}

static bs_status conic(const stp *s, size_t i, size_t list, size_t dim, int ellipse, stp_curve *out)
{
    size_t r;
    bsi_frame f;
    bs_status st;
    if ((st = bsi_stp_ref(s, i, list, 1, "the position", &r)) != BS_OK || (st = bsi_stp_placement(s, r, dim, &f)) != BS_OK ||
        (st = bsi_stp_num(s, i, list, 2, "the radius", &out->rx)) != BS_OK)
        return st;
    out->ry = out->rx;
    if (ellipse && (st = bsi_stp_num(s, i, list, 3, "the second semi-axis", &out->ry)) != BS_OK)
        return st;
    if (!(out->rx > 0.0 && out->ry > 0.0) || !isfinite(out->rx) || !isfinite(out->ry))
        return bsi_stp_fail(s, i, "%s", "radii must be positive");
    out->kind = STP_CONIC;
    out->dim = dim;
    memcpy(out->c, f.o, sizeof f.o);
    memcpy(out->x, f.x, sizeof f.x);
    memcpy(out->y, f.y, sizeof f.y);
    return BS_OK;
}

bs_status bsi_stp_curve(stp *s, size_t i, size_t dim, int depth, stp_curve *out)
{
    size_t list, r, v;
    bs_status st;
    memset(out, 0, sizeof *out);
    if (bsi_stp_part(s, i, "LINE", &list)) {
        double mag;
        if ((st = bsi_stp_ref(s, i, list, 1, "the point", &r)) != BS_OK || (st = bsi_stp_point(s, r, dim, out->p)) != BS_OK ||
            (st = bsi_stp_ref(s, i, list, 2, "the vector", &v)) != BS_OK)
            return st;
        if (!bsi_stp_part(s, v, "VECTOR", &list))
            return bsi_stp_fail(s, v, "%s", "expected a VECTOR");
        if ((st = bsi_stp_ref(s, v, list, 1, "the direction", &r)) != BS_OK ||
            (st = bsi_stp_direction(s, r, dim, out->d)) != BS_OK || (st = bsi_stp_num(s, v, list, 2, "the magnitude", &mag)) != BS_OK)
            return st;
        if (!(mag > 0.0) || !isfinite(mag))
            return bsi_stp_fail(s, v, "%s", "magnitude must be positive");
        for (size_t c = 0; c < dim; c++)
            out->d[c] *= mag;
        out->kind = STP_LINE;
        out->dim = dim;
        return BS_OK;
    }
    if (bsi_stp_part(s, i, "CIRCLE", &list))
        return conic(s, i, list, dim, 0, out);
    if (bsi_stp_part(s, i, "ELLIPSE", &list))
        return conic(s, i, list, dim, 1, out);
    if (bsi_stp_is(s, i, "B_SPLINE_CURVE_WITH_KNOTS") || bsi_stp_is(s, i, "B_SPLINE_CURVE")) {
        if ((st = bspline(s, i, dim, out)) != BS_OK)
            bsi_stp_curve_free(out);
        return st;
    }
    if (bsi_stp_part(s, i, "TRIMMED_CURVE", &list)) {
        if (depth >= STP_DEPTH || s->busy[i])
            return bsi_stp_fail(s, i, "%s", "curve references nested too deep (a reference cycle)");
        if ((st = bsi_stp_ref(s, i, list, 1, "the basis curve", &r)) != BS_OK)
            return st;
        s->busy[i] = 1;
        st = bsi_stp_curve(s, r, dim, depth + 1, out);
        s->busy[i] = 0;
        return st;
    }
    return unsupported(s, i);
}

double bsi_stp_curve_period(const stp *s, const stp_curve *c, double *lo, double *hi)
{
    if (c->kind == STP_CONIC) {
        *lo = 0.0;
        *hi = TWO_PI / s->angle;
        return *hi;
    }
    if (c->kind == STP_BSPLINE) {
        *lo = c->knots[c->degree];
        *hi = c->knots[c->count];
    } else {
        *lo = -INFINITY;
        *hi = INFINITY;
    }
    return 0.0;
}

/* The B-spline's point at t (de Boor on homogeneous points). */
static void deboor(const stp_curve *c, double t, double *p)
{
    size_t deg = c->degree, span = deg, dim = c->dim;
    while (span + 1 < c->count && t >= c->knots[span + 1])
        span++;
    double h[BS_MAX_DEGREE + 1][4] = {{0}}; /* 2-D curves leave the third coordinate 0 */
    for (size_t j = 0; j <= deg; j++) {
        double w = c->weights ? c->weights[span - deg + j] : 1.0;
        for (size_t k = 0; k < dim; k++)
            h[j][k] = w * c->ctrl[(span - deg + j) * dim + k];
        h[j][3] = w;
    }
    for (size_t r = 1; r <= deg; r++)
        for (size_t j = deg; j >= r; j--) {
            size_t i = span - deg + j;
            double den = c->knots[i + deg - r + 1] - c->knots[i];
            double a = den > 0.0 ? (t - c->knots[i]) / den : 0.0;
            for (size_t k = 0; k < 4; k++)
                h[j][k] = (1.0 - a) * h[j - 1][k] + a * h[j][k];
        }
    for (size_t k = 0; k < dim; k++)
        p[k] = h[deg][k] / h[deg][3];
}

static double dist2(const stp_curve *c, double t, const double *p)
{
    double q[3], d = 0.0;
    deboor(c, t, q);
    for (size_t k = 0; k < c->dim; k++)
        d += (q[k] - p[k]) * (q[k] - p[k]);
    return d;
}

double bsi_stp_curve_param(const stp *s, const stp_curve *c, const double *p)
{
    double q[3] = {0, 0, 0};
    for (size_t k = 0; k < c->dim; k++)
        q[k] = p[k] - (c->kind == STP_LINE ? c->p[k] : c->c[k]);
    if (c->kind == STP_LINE) {
        double dd = 0.0, qd = 0.0;
        for (size_t k = 0; k < c->dim; k++)
            dd += c->d[k] * c->d[k], qd += q[k] * c->d[k];
        return qd / dd;
    }
    if (c->kind == STP_CONIC) {
        double a = 0.0, b = 0.0;
        for (size_t k = 0; k < c->dim; k++)
            a += q[k] * c->x[k], b += q[k] * c->y[k];
        double phi = atan2(b / c->ry, a / c->rx);
        if (phi < 0.0)
            phi += TWO_PI;
        if (phi > TWO_PI * (1.0 - 1e-12)) /* a point just below the start is at the start */
            phi = 0.0;
        return phi / s->angle;
    }
    /* B-spline: the nearest of samples, then golden-section search between its neighbours */
    double lo = c->knots[c->degree], hi = c->knots[c->count], best = lo, bd = INFINITY;
    size_t n = 8 * (c->count + 1);
    for (size_t k = 0; k <= n; k++) {
        double t = lo + (hi - lo) * (double)k / (double)n, d = dist2(c, t, p);
        if (d < bd)
            bd = d, best = t;
    }
    double a = fmax(lo, best - (hi - lo) / (double)n), b = fmin(hi, best + (hi - lo) / (double)n);
    const double g = 0.6180339887498949;
    for (int it = 0; it < 80; it++) {
        double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (dist2(c, x1, p) < dist2(c, x2, p))
            b = x2;
        else
            a = x1;
    }
    return 0.5 * (a + b);
}

bs_status bsi_stp_curve_make(const stp *s, const stp_curve *c, double t0, double t1, bsi_curve *out)
{
    if (c->kind == STP_LINE)
        return bsi_curve_line(c->dim, c->p, c->d, t0, t1, out);
    if (c->kind == STP_CONIC)
        return bsi_curve_conic(c->dim, c->c, c->x, c->y, c->rx, c->ry, s->angle, t0, t1, out);
    double lo = c->knots[c->degree], hi = c->knots[c->count];
    return bsi_curve_bspline(c->dim, c->degree, c->count, c->knots, c->ctrl, c->weights, fmax(t0, lo), fmin(t1, hi), out);
}
