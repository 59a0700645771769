/*
 * Loops of computed trims made continuous: on periodic directions each trim is moved by whole
 * periods to start where the one before ends; on a direction that is closed but not periodic (a
 * closed B-spline: its first and last rows of control points agree), a trim lying on the seam is
 * put on the side (the domain's low or high end) where the loop goes on.
 */
#include "model/pcurve_internal.h"

#include <math.h>
#include <string.h>

/* The loop-direction start (end: at_end) of a trim's curve. */
static void trim_end(const bsi_trim *t, int at_end, double *uv)
{
    const bsi_curve *c = &t->uv;
    size_t last = c->axis.n * (c->degree + 1) - 1;
    const double *h = c->hom + ((t->reversed != 0) != (at_end != 0) ? last : 0) * 3;
    uv[0] = h[0] / h[2];
    uv[1] = h[1] / h[2];
}

static void shift(bsi_curve *c, size_t k, double by)
{
    for (size_t j = 0; j < c->axis.n * (c->degree + 1); j++)
        c->hom[j * 3 + k] += by * c->hom[j * 3 + 2];
}

void bsi_pcurve_close_loop(bsi_trim *trims, size_t n, const double *period)
{
    for (size_t i = 1; i < n; i++) {
        double end[2], start[2];
        trim_end(&trims[i - 1], 1, end);
        trim_end(&trims[i], 0, start);
        for (size_t k = 0; k < 2; k++) {
            double by = period[k] > 0.0 ? period[k] * round((end[k] - start[k]) / period[k]) : 0.0;
            if (by != 0.0)
                shift(&trims[i].uv, k, by);
        }
    }
}

static double dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* Whether a clamped B-spline's first and last rows (dir 0: along u) are the same points. */
static int bspline_closed(const bs_bspline *b, int dir, double tol)
{
    size_t cu = b->count_u, cv = b->count_v, n = dir == 0 ? cv : cu, last = dir == 0 ? cu - 1 : cv - 1;
    const double *t = dir == 0 ? b->knots_u : b->knots_v;
    size_t deg = dir == 0 ? b->deg_u : b->deg_v, count = dir == 0 ? cu : cv;
    if (b->dim != 3 || t[0] != t[deg] || t[count] != t[count + deg])
        return 0;
    for (size_t j = 0; j < n; j++) {
        size_t a = dir == 0 ? j : j * cv, z = dir == 0 ? last * cv + j : j * cv + last;
        if (!(dist3(b->ctrl + a * 3, b->ctrl + z * 3) <= tol))
            return 0;
    }
    return 1;
}

/* The canonical directions closed but not periodic, and the canonical domain along them. */
static void closed_dirs(const bsi_surface_def *def, double tol, int *closed, double *box)
{
    closed[0] = closed[1] = 0;
    if (def->kind == BS_FACE_BSPLINE && def->bspline != NULL) {
        const bs_bspline *b = def->bspline;
        closed[0] = bspline_closed(b, 0, tol);
        closed[1] = bspline_closed(b, 1, tol);
        box[0] = b->knots_u[b->deg_u], box[1] = b->knots_u[b->count_u];
        box[2] = b->knots_v[b->deg_v], box[3] = b->knots_v[b->count_v];
    } else if ((def->kind == BS_FACE_EXTRUSION || def->kind == BS_FACE_REVOLUTION) &&
               bsi_curve_closed(def->curve, tol)) {
        size_t k = def->kind == BS_FACE_REVOLUTION; /* the curve runs along u, or v */
        closed[k] = 1;
        box[2 * k] = def->curve->axis.breaks[0];
        box[2 * k + 1] = def->curve->axis.breaks[def->curve->axis.n];
    }
}

/* A trim lying on the seam of native direction k ([lo, hi]): -1 at lo, 1 at hi, 0 elsewhere. */
static int on_seam(const bsi_trim *t, size_t k, double lo, double hi)
{
    const bsi_curve *c = &t->uv;
    double eps = 1e-9 * (hi - lo);
    int at_lo = 1, at_hi = 1;
    for (size_t j = 0; j < c->axis.n * (c->degree + 1); j++) {
        double x = c->hom[j * 3 + k] / c->hom[j * 3 + 2];
        at_lo &= fabs(x - lo) <= eps;
        at_hi &= fabs(x - hi) <= eps;
    }
    return at_lo ? -1 : at_hi;
}

void bsi_pcurve_close_loop_def(const bsi_surface_def *def, int swap, const double *box, double tol,
                               bsi_trim *trims, size_t n)
{
    double pc[2], period[2], canon[4] = {0.0, 0.0, 0.0, 0.0};
    int closed[2];
    swap = swap != 0;
    if (bsi_pc_closed_form(def))
        bsi_pc_periods(def, &pc[0], &pc[1]);
    else
        bsi_surface_def_periods(def, &pc[0], &pc[1]);
    period[0] = pc[swap];
    period[1] = pc[!swap];
    bsi_pcurve_close_loop(trims, n, period);
    closed_dirs(def, tol, closed, canon);
    for (size_t k = 0; k < 2 && n > 1; k++) {
        size_t c = swap ? 1 - k : k; /* the canonical direction of native k */
        if (!closed[c] || period[k] > 0.0)
            continue;
        double lo = box != NULL ? box[2 * k] : canon[2 * c], hi = box != NULL ? box[2 * k + 1] : canon[2 * c + 1];
        for (size_t i = 0; i < n; i++) {
            int side = on_seam(&trims[i], k, lo, hi);
            if (side == 0)
                continue;
            double before[2], after[2];
            trim_end(&trims[(i + n - 1) % n], 1, before);
            trim_end(&trims[(i + 1) % n], 0, after);
            int want = fabs(before[k] - hi) + fabs(after[k] - hi) < fabs(before[k] - lo) + fabs(after[k] - lo) ? 1 : -1;
            if (want != side)
                shift(&trims[i].uv, k, want > 0 ? hi - lo : lo - hi);
        }
    }
}
