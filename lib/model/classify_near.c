/*
 * Classification, the ON test and the segment helpers: is the point of a face within tol in 3-D
 * of its boundary? A branch and bound along each trim with certified bounds of the speed of the
 * boundary on the surface (classify.c describes the method).
 */
#include "model/classify_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NEAR_DEPTH 40
#define NEAR_BUDGET 4000 /* evaluations of the surface per trim segment */

/* The piece [s0, s1] of the degree-p segment seg into out (de Casteljau, twice). */
void bsi_seg_piece(const double *seg, size_t p, double s0, double s1, double *out)
{
    double tmp[BSI_SEG_MAX];
    memcpy(out, seg, (p + 1) * 3 * sizeof *out);
    if (s1 < 1.0) { /* keep [0, s1] */
        memcpy(tmp, out, (p + 1) * 3 * sizeof *tmp);
        for (size_t r = 1; r <= p; r++) {
            for (size_t i = 0; i + r <= p; i++)
                for (size_t c = 0; c < 3; c++)
                    tmp[i * 3 + c] = (1.0 - s1) * tmp[i * 3 + c] + s1 * tmp[(i + 1) * 3 + c];
            memcpy(out + r * 3, tmp, 3 * sizeof *tmp);
        }
    }
    if (s0 > 0.0) { /* keep [s0 / s1, 1] of that */
        double s = s0 / s1;
        memcpy(tmp, out, (p + 1) * 3 * sizeof *tmp);
        for (size_t r = 1; r <= p; r++) {
            for (size_t i = 0; i + r <= p; i++)
                for (size_t c = 0; c < 3; c++)
                    tmp[i * 3 + c] = (1.0 - s) * tmp[i * 3 + c] + s * tmp[(i + 1) * 3 + c];
            memcpy(out + (p - r) * 3, tmp + (p - r) * 3, 3 * sizeof *tmp);
        }
    }
}

/* The halves of the degree-p piece h (homogeneous points) at its middle into lo and hi, which may
 * be h itself: one de Casteljau pass of midpoints gives both. */
void bsi_seg_halve(const double *h, size_t p, double *lo, double *hi)
{
    double tmp[BSI_SEG_MAX];
    memcpy(tmp, h, (p + 1) * 3 * sizeof *tmp);
    memcpy(lo, tmp, 3 * sizeof *tmp);
    memcpy(hi + p * 3, tmp + p * 3, 3 * sizeof *tmp);
    for (size_t r = 1; r <= p; r++) {
        /* point by point, coordinate by coordinate, two at a time (one vector operation) */
        size_t count = (p + 1 - r) * 3, k = 0;
        for (; k + 2 <= count; k += 2) {
            double a = (tmp[k] + tmp[k + 3]) * 0.5, b = (tmp[k + 1] + tmp[k + 4]) * 0.5; // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult): tmp holds the piece's (p+1) points
            tmp[k] = a;
            tmp[k + 1] = b;
        }
        if (k < count)
            tmp[k] = (tmp[k] + tmp[k + 3]) * 0.5;
        memcpy(lo + r * 3, tmp, 3 * sizeof *tmp);
        memcpy(hi + (p - r) * 3, tmp + (p - r) * 3, 3 * sizeof *tmp);
    }
}

/* The point at s of a 2-D segment (de Casteljau on homogeneous points). */
void bsi_seg_point(const double *seg, size_t p, double s, double *xy)
{
    if (s == 0.0 || s == 1.0) { /* an end: its control point (de Casteljau gives the same) */
        const double *e = seg + (s == 0.0 ? 0 : p * 3);
        xy[0] = e[0] / e[2];
        xy[1] = e[1] / e[2];
        return;
    }
    double tmp[BSI_SEG_MAX];
    memcpy(tmp, seg, (p + 1) * 3 * sizeof *tmp);
    for (size_t r = 1; r <= p; r++)
        for (size_t i = 0; i + r <= p; i++)
            for (size_t c = 0; c < 3; c++)
                tmp[i * 3 + c] = (1.0 - s) * tmp[i * 3 + c] + s * tmp[(i + 1) * 3 + c];
    xy[0] = tmp[0] / tmp[2];
    xy[1] = tmp[1] / tmp[2];
}

/* ---- speed bounds ----
 * A rational Bezier C = H / W of degree n has C' = (n / W) sum_i B_i^{n-1} [w_{i+1} (P_{i+1} - P_i)
 * + (w_{i+1} - w_i) (P_i - C)] (from H' - C W', H - C W = 0), so
 * |C'| <= n (wmax max |P_{i+1} - P_i| + max |w_{i+1} - w_i| diameter) / wmin; the same holds
 * coordinate by coordinate, and along one direction of a patch with the differences taken along
 * that direction. */
static double speed_1d(const double *x, const double *w, size_t p)
{
    double wlo = INFINITY, whi = 0.0, lo = INFINITY, hi = -INFINITY, dx = 0.0, dw = 0.0;
    for (size_t i = 0; i <= p; i++) {
        wlo = bsi_dmin(wlo, w[i]), whi = bsi_dmax(whi, w[i]), lo = bsi_dmin(lo, x[i]), hi = bsi_dmax(hi, x[i]);
        if (i > 0)
            dx = bsi_dmax(dx, fabs(x[i] - x[i - 1])), dw = bsi_dmax(dw, fabs(w[i] - w[i - 1]));
    }
    return (double)p * (whi * dx + dw * (hi - lo)) / wlo;
}

/* Speeds along u and v of the 2-D piece h (homogeneous points) over its own [0, 1]. */
static void curve_speed(const double *h, size_t p, double *speed)
{
    double x[BS_MAX_DEGREE + 1], y[BS_MAX_DEGREE + 1], w[BS_MAX_DEGREE + 1];
    for (size_t i = 0; i <= p; i++) {
        w[i] = h[i * 3 + 2];
        x[i] = h[i * 3] / w[i];
        y[i] = h[i * 3 + 1] / w[i];
    }
    speed[0] = speed_1d(x, w, p);
    speed[1] = speed_1d(y, w, p);
}

/* Native -> local rate of piece k of an axis (the largest over the piece). */
static double axis_rate(const bsi_axis *a, size_t k)
{
    double width = a->breaks[k + 1] - a->breaks[k];
    if (a->kind == BSI_AXIS_ANGULAR)
        return a->radians / (2.0 * sin(0.5 * a->radians * width));
    return 1.0 / width;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Bound of |dS/ds| (dir 0) or |dS/dt| (dir 1) of a 3-D patch. */
static double patch_speed(const bs_patch *pt, int dir)
{
    size_t nu = pt->deg_u + 1, nv = pt->deg_v + 1, deg = dir == 0 ? pt->deg_u : pt->deg_v;
    if (deg == 0)
        return 0.0;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double wlo = INFINITY, whi = 0.0, dp = 0.0, dw = 0.0;
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            const double *q = pt->ctrl + (i * nv + j) * 3;
            double w = pt->weights ? pt->weights[i * nv + j] : 1.0;
            wlo = bsi_dmin(wlo, w), whi = bsi_dmax(whi, w);
            for (int c = 0; c < 3; c++)
                lo[c] = bsi_dmin(lo[c], q[c]), hi[c] = bsi_dmax(hi[c], q[c]);
            if ((dir == 0 && i == 0) || (dir == 1 && j == 0))
                continue;
            size_t prev = dir == 0 ? (i - 1) * nv + j : i * nv + j - 1;
            dp = bsi_dmax(dp, dist3(q, pt->ctrl + prev * 3));
            if (pt->weights != NULL)
                dw = bsi_dmax(dw, fabs(w - pt->weights[prev]));
        }
    return (double)deg * (whi * dp + dw * dist3(lo, hi)) / wlo;
}

/* Bounds of |dS/du| and |dS/dv| per native unit over the face. */
void bsi_face_speed(const bs_model *m, const bsi_face *face, double lip[2])
{
    double la = 0.0, lb = 0.0;
    for (size_t i = 0; i < face->au.n; i++)
        for (size_t j = 0; j < face->av.n; j++) {
            const bs_patch *pt = bs_surface_get(m->surface, face->first_patch + i * face->av.n + j);
            la = bsi_dmax(la, patch_speed(pt, 0) * axis_rate(&face->au, i));
            lb = bsi_dmax(lb, patch_speed(pt, 1) * axis_rate(&face->av, j));
        }
    lip[0] = face->swap ? lb : la;
    lip[1] = face->swap ? la : lb;
}

/* ---- ON: within tol in 3-D of a trim that bounds the face ---- */
/* The one value of coordinate d along a trim, if it has one. */
static int constant_coord(const bsi_curve *c, size_t d, double *x)
{
    size_t np = c->axis.n * (c->degree + 1);
    double x0 = c->hom[d] / c->hom[2];
    for (size_t i = 1; i < np; i++)
        if (c->hom[i * 3 + d] / c->hom[i * 3 + 2] != x0)
            return 0;
    *x = x0;
    return 1;
}

int bsi_trim_is_seam(const bs_model *m, size_t f, size_t t)
{
    const bsi_face *face = &m->faces[f];
    uint32_t e = m->trims[t].edge;
    if (e != BSI_NO_EDGE && e < m->nedge && m->edges[e].face[0] == f && m->edges[e].face[1] == f)
        return 1;
    for (size_t d = 0; d < 2; d++) {
        double x, y, per = face->period[d];
        if (!(per > 0.0) || !constant_coord(&m->trims[t].uv, d, &x))
            continue;
        size_t t0 = m->loops[face->first_loop].first_trim;
        size_t t1 = t0;
        for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++)
            t1 = m->loops[l].first_trim + m->loops[l].trim_count;
        for (size_t o = t0; o < t1; o++)
            if (o != t && constant_coord(&m->trims[o].uv, d, &y) &&
                fabs(fabs(x - y) - per) <= 1e-9 * per)
                return 1;
    }
    return 0;
}

/* The Bernstein polynomials of degree n at s: by the recurrence of de Casteljau (n^2 / 2 steps)
 * up to cubics, else as binomial(n, i) s^i (1 - s)^(n - i) (3n products and n divisions; the
 * binomials exact in doubles up to degree 56, within a few units of rounding above). */
static void bernstein(size_t n, double s, double *b)
{
    b[0] = 1.0;
    if (n <= 3) {
        for (size_t j = 1; j <= n; j++) {
            double carry = 0.0;
            for (size_t k = 0; k < j; k++) {
                double t = b[k];
                b[k] = carry + (1.0 - s) * t;
                carry = s * t;
            }
            b[j] = carry;
        }
        return;
    }
    double up[BS_MAX_DEGREE + 1], down = 1.0, binom = 1.0;
    up[0] = 1.0;
    for (size_t i = 1; i <= n; i++)
        up[i] = up[i - 1] * s;
    for (size_t i = n + 1; i-- > 0;) { /* binom = binomial(n, i), down = (1 - s)^(n - i) */
        b[i] = binom * up[i] * down;
        binom = binom * (double)i / (double)(n - i + 1);
        down *= 1.0 - s;
    }
}

/* The point of face f at native (u, v) from its patch's homogeneous net (one point: cheaper than
 * the block evaluator), contracted row by row in each plane; 0 outside the face's patches. */
static int surface_point(const bs_model *m, size_t f, double u, double v, double *q)
{
    uint32_t id;
    double st[2], bu[BS_MAX_DEGREE + 1], bv[BS_MAX_DEGREE + 1], acc[4] = {0.0, 0.0, 0.0, 1.0};
    if (!bsi_face_locate(m, f, u, v, &id, st))
        return 0;
    const bs_patch *pt = bs_surface_get(m->surface, id);
    size_t nv = pt->deg_v + 1, nctrl = pt->nctrl;
    bernstein(pt->deg_u, st[0], bu);
    bernstein(pt->deg_v, st[1], bv);
    for (size_t c = 0; c < pt->ncoord; c++) {
        const double *plane = pt->hom + c * nctrl;
        double sum = 0.0;
        for (size_t i = 0; i <= pt->deg_u; i++, plane += nv) {
            double row = 0.0;
            for (size_t j = 0; j < nv; j++)
                row += bv[j] * plane[j];
            sum += bu[i] * row;
        }
        acc[c] = sum;
    }
    for (int c = 0; c < 3; c++)
        q[c] = acc[c] / acc[3];
    return 1;
}

typedef struct near_ctx {
    const bs_model *m;
    size_t f;
    const double *box;
    double p[3], lip[2], tol;
    int flat;                          /* the face is a parallelogram (flat_face) */
    double uv[2], ju[3], jv[3], slack; /* P's native point, the map's partials, its twist */
} near_ctx;

/* 1 when face f is one polynomial bilinear patch over linear axes (a plane's face): its point at
 * native (u, v) is then S(uv) + Ju (u - u_P) + Jv (v - v_P) to within the length of the twist
 * P11 - P10 - P01 + P00 (the bilinear term s t times it, s and t in [0, 1]). */
static int flat_face(const bs_model *m, const bsi_face *face, near_ctx *x)
{
    if (face->au.n != 1 || face->av.n != 1 || face->au.kind != BSI_AXIS_LINEAR ||
        face->av.kind != BSI_AXIS_LINEAR)
        return 0;
    const bs_patch *pt = bs_surface_get(m->surface, face->first_patch);
    if (pt->deg_u != 1 || pt->deg_v != 1 || pt->rational)
        return 0;
    const double *p00 = pt->ctrl, *p01 = pt->ctrl + 3, *p10 = pt->ctrl + 6, *p11 = pt->ctrl + 9;
    double ws = face->au.breaks[1] - face->au.breaks[0], wt = face->av.breaks[1] - face->av.breaks[0];
    double js[3], jt[3], twist = 0.0;
    for (int c = 0; c < 3; c++) {
        js[c] = (p10[c] - p00[c]) / ws;
        jt[c] = (p01[c] - p00[c]) / wt;
        double k = p11[c] - p10[c] - p01[c] + p00[c];
        twist += k * k;
    }
    memcpy(x->ju, face->swap ? jt : js, sizeof js);
    memcpy(x->jv, face->swap ? js : jt, sizeof jt);
    x->slack = sqrt(twist);
    return bsi_all_finite(x->ju, 3) && bsi_all_finite(x->jv, 3) && isfinite(x->slack);
}

/* On a flat face, the trim's image seen from P, Ju (u - u_P) + Jv (v - v_P), is the segment's
 * piece h mapped linearly, so it lies in the box of the mapped points: d, its distance at the
 * piece's first point (on the curve), and reach, such that d - reach is at most its distance
 * anywhere on the piece (the box's), both widened by the twist. */
static void flat_reach(const near_ctx *x, const double *h, size_t p, double *d, double *reach)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double first = 0.0, gap = 0.0;
    for (size_t i = 0; i <= p; i++) {
        double du = h[i * 3] / h[i * 3 + 2] - x->uv[0], dv = h[i * 3 + 1] / h[i * 3 + 2] - x->uv[1];
        for (int c = 0; c < 3; c++) {
            double q = x->ju[c] * du + x->jv[c] * dv;
            lo[c] = bsi_dmin(lo[c], q), hi[c] = bsi_dmax(hi[c], q);
            if (i == 0)
                first += q * q;
        }
    }
    for (int c = 0; c < 3; c++) {
        double g = lo[c] > 0.0 ? lo[c] : hi[c] < 0.0 ? -hi[c] : 0.0;
        gap += g * g;
    }
    *d = sqrt(first) + x->slack;
    *reach = *d - (sqrt(gap) - x->slack);
}

/* |P - S(c)| for the trim point c = (u, v) kept in the face's box; INFINITY where the surface is
 * not found. */
static double distance_at(const near_ctx *x, double u, double v)
{
    double q[3];
    u = bsi_dmin(bsi_dmax(u, x->box[0]), x->box[1]);
    v = bsi_dmin(bsi_dmax(v, x->box[2]), x->box[3]);
    if (!surface_point(x->m, x->f, u, v, q))
        return INFINITY;
    return dist3(x->p, q);
}

#define NEAR_LOCAL_PIECES BSI_CUBIC_PIECES(NEAR_DEPTH)

/* Within tol of P somewhere on the segment: each piece [s0, s1] is at least D - K / 2 from P, D
 * the distance at its middle, K the bound of the piece's 3-D speed over its own [0, 1] (on a flat
 * face, D - reach of flat_reach, without evaluating the surface). The pieces
 * waiting are kept whole beside the stack and halved where taken (one pass of midpoints, which
 * also gives the middle); for higher degrees their block is allocated at the first halving, and
 * without it each piece is cut from the segment and its middle evaluated (two passes and one),
 * the same answer but for rounding. */
static int seg_near(const near_ctx *x, const double *seg, size_t p)
{
    struct { double s0, s1; int depth; } stack[NEAR_DEPTH + 2];
    size_t top = 0, budget = NEAR_BUDGET, len = (p + 1) * 3;
    double local[NEAR_LOCAL_PIECES], cut[BSI_SEG_MAX];
    int small = len * (NEAR_DEPTH + 2) <= NEAR_LOCAL_PIECES, asked = small, found = 0;
    double *pieces = small ? local : NULL;
    if (small)
        memcpy(local, seg, len * sizeof *local);
    stack[top].s0 = 0.0;
    stack[top].s1 = 1.0;
    stack[top++].depth = 0;
    while (top > 0 && budget-- > 0 && !found) {
        double s0 = stack[top - 1].s0, s1 = stack[top - 1].s1;
        int depth = stack[--top].depth;
        double sm = 0.5 * (s0 + s1), d, reach;
        double *piece = pieces != NULL ? pieces + top * len : cut;
        int halved = 0, root_halved = 0; /* the second half in place, the first on top */
        if (pieces == NULL)
            bsi_seg_piece(seg, p, s0, s1, cut);
        if (x->flat) {
            flat_reach(x, piece, p, &d, &reach);
        } else {
            double speed[2], mid[2];
            curve_speed(piece, p, speed);
            if (pieces != NULL) {
                bsi_seg_halve(piece, p, piece + len, piece);
                halved = 1;
                mid[0] = piece[0] / piece[2], mid[1] = piece[1] / piece[2];
            } else if (!asked && 2 * len <= NEAR_LOCAL_PIECES) {
                /* the whole segment above cubic, before its block: halved into local (unused
                 * then), kept for the block; its middle has the bits of the point at 1/2 */
                bsi_seg_halve(seg, p, local + len, local);
                root_halved = 1;
                mid[0] = local[0] / local[2], mid[1] = local[1] / local[2];
            } else {
                bsi_seg_point(seg, p, sm, mid);
            }
            d = distance_at(x, mid[0], mid[1]);
            reach = 0.5 * (x->lip[0] * speed[0] + x->lip[1] * speed[1]);
        }
        if (d <= x->tol) {
            found = 1;
            continue;
        }
        if (!(d - reach <= x->tol) || reach <= 1e-3 * x->tol || depth >= NEAR_DEPTH)
            continue;
        if (!asked && top == 0) { /* the first halving, of the whole segment */
            asked = 1;
            pieces = malloc((size_t)(NEAR_DEPTH + 2) * len * sizeof *pieces);
            if (pieces != NULL && root_halved)
                memcpy(pieces, local, 2 * len * sizeof *pieces);
            else if (pieces != NULL)
                bsi_seg_halve(seg, p, pieces + len, pieces);
        } else if (pieces != NULL && !halved) {
            bsi_seg_halve(piece, p, piece + len, piece);
        }
        stack[top].s0 = sm, stack[top].s1 = s1, stack[top++].depth = depth + 1;
        stack[top].s0 = s0, stack[top].s1 = sm, stack[top++].depth = depth + 1;
    }
    if (pieces != local)
        free(pieces);
    return found;
}

/* Within tol of P somewhere on the trim: runs of segments are dropped together when the box of
 * their control points (in the face's box) is farther than tol from P in 3-D: at least
 * |P - S(centre)| - Lu du - Lv dv, (du, dv) the box's half-widths. */
static int trim_near(const near_ctx *x, const bsi_curve *c)
{
    size_t stack[2 * (sizeof(size_t) * 8 + 1)][2], top = 0;
    stack[top][0] = 0, stack[top++][1] = c->axis.n;
    while (top > 0) {
        size_t k0 = stack[--top][0], k1 = stack[top][1];
        if (k1 - k0 == 1) {
            if (seg_near(x, bsi_trim_segment(c, k0), c->degree))
                return 1;
            continue;
        }
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (size_t i = k0 * (c->degree + 1); i < k1 * (c->degree + 1); i++)
            for (size_t d = 0; d < 2; d++) {
                double y = c->hom[i * 3 + d] / c->hom[i * 3 + 2];
                lo[d] = bsi_dmin(lo[d], y), hi[d] = bsi_dmax(hi[d], y);
            }
        for (size_t d = 0; d < 2; d++) {
            lo[d] = bsi_dmin(bsi_dmax(lo[d], x->box[2 * d]), x->box[2 * d + 1]);
            hi[d] = bsi_dmin(bsi_dmax(hi[d], x->box[2 * d]), x->box[2 * d + 1]);
        }
        double q[3];
        if (surface_point(x->m, x->f, 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), q) &&
            dist3(x->p, q) - 0.5 * (x->lip[0] * (hi[0] - lo[0]) + x->lip[1] * (hi[1] - lo[1])) > x->tol)
            continue;
        size_t mid = k0 + (k1 - k0) / 2;
        stack[top][0] = mid, stack[top++][1] = k1;
        stack[top][0] = k0, stack[top++][1] = mid;
    }
    return 0;
}

/* 1 when (u, v) lies exactly on the trim c, an iso-line (one coordinate constant): the common
 * case of a point found on a side of a patch, answered without a search. */
static int on_iso_line(const bsi_curve *c, double u, double v)
{
    double at[2] = {u, v}, x, lo[2], hi[2];
    for (size_t d = 0; d < 2; d++)
        if (at[d] == c->hom[d] / c->hom[2] && constant_coord(c, d, &x)) {
            bsi_curve_bounds(c, lo, hi);
            if (at[1 - d] >= lo[1 - d] && at[1 - d] <= hi[1 - d])
                return 1;
        }
    return 0;
}

int bsi_face_near_boundary(const bs_model *m, size_t f, double u, double v, double tol, int seams)
{
    const bsi_face *face = &m->faces[f];
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++)
        for (size_t t = m->loops[l].first_trim; t < m->loops[l].first_trim + m->loops[l].trim_count; t++)
            if (m->trims[t].uv.axis.n > 0 && on_iso_line(&m->trims[t].uv, u, v) &&
                (seams || !bsi_trim_is_seam(m, f, t))) /* the seam test scans the face's trims */
                return 1;
    near_ctx x;
    x.m = m, x.f = f, x.box = face->box, x.tol = tol;
    if (!surface_point(m, f, u, v, x.p))
        return 0;
    x.lip[0] = face->lip[0], x.lip[1] = face->lip[1];
    x.flat = flat_face(m, face, &x) && x.slack <= 1e-4 * tol; /* a parallelogram to rounding */
    x.uv[0] = u, x.uv[1] = v;
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[l];
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++) {
            const bsi_curve *c = &m->trims[t].uv;
            if (c->axis.n == 0 || (!seams && bsi_trim_is_seam(m, f, t)))
                continue;
            if (trim_near(&x, c))
                return 1;
        }
    }
    return 0;
}
