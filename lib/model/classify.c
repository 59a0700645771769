/*
 * Where native (u, v) lies with respect to a face's trim loops: BS_TRIM_INSIDE, OUTSIDE or ON.
 *
 * Candidates. NaN, or a point that no whole-period shift brings into the face's box, is OUTSIDE.
 * Along a periodic direction every shift u + k period inside the box is a candidate (a loop on a
 * cylinder may lie anywhere, e.g. over [-0.5, 5.5]); the point is INSIDE when one candidate is.
 * A face without loops is INSIDE its whole box.
 *
 * ON (3-D distance <= tol). P = S(u, v) on the surface; for each trim segment c(s), s in [0, 1],
 * a branch and bound over s: at the middle sm of a piece [s0, s1], D = |P - S(c(sm))| is a
 * distance to the boundary (ON when D <= tol), and every point of the piece is at least D - K / 2
 * from P, K = Lu |c_u'| + Lv |c_v'| a bound of the speed of S(c) over the piece's own [0, 1]: Lu,
 * Lv bound the surface's speed per native unit over the face's patches (the rational derivative
 * bound under "speed bounds" below, times the native -> local rate of the axis piece: 1 / width,
 * or radians / (2 sin a) on a quadratic arc of half angle a), the piece's speeds bound the same
 * way from its control points. A piece is dropped when D - K / 2 > tol: only the parts of the
 * boundary that can come within tol in 3-D are refined, wherever they lie in parameter space (a
 * pole: a degenerate trim along v = pi / 2 maps to one 3-D point; a seam: far in u, near in 3-D).
 * Refinement stops when K / 2 is a thousandth of tol (the piece is then farther than 0.999 tol:
 * a point that near is left to the parity below, which is exact) or after a fixed number of
 * evaluations per segment. Seam trims (a constant u, or v, of a periodic
 * direction whose twin lies one period away, or an edge used twice by this face) are not a
 * boundary of the face and are left out of this test only.
 *
 * INSIDE / OUTSIDE. Even-odd parity of the crossings of the ray {(x, v): x > u} with every trim
 * of every loop (the outer loop and the holes, in whatever orientation the file gives them):
 * each rational Bezier segment is cut in halves (de Casteljau on homogeneous points) until the
 * control points' box of a piece lies above the ray's line (y >= v), below it (y < v), left of
 * the point (x < u): no crossing, or right of it (x > u): a crossing exactly when its two ends lie
 * on different sides of the line. The ends' points are computed once per parameter and shared by
 * the two pieces meeting there, and chords close the gaps between segments and between trims (a
 * file's loop closes only within its tolerance), so the chain is closed and each of its crossings
 * counted once. This is exact for points off the curve (a piece clear of the point is always
 * reached); a point on the curve stops at a depth of 50 halvings, decided there by the chord.
 */
#include "model/internal.h"

#include <math.h>
#include <string.h>

#define HOM_MAX ((BS_MAX_DEGREE + 1) * 3) /* a 2-D segment's homogeneous points */
#define PARITY_DEPTH 50
#define NEAR_DEPTH 40
#define NEAR_BUDGET 4000 /* evaluations of the surface per trim segment */
#define MAX_SHIFTS 4     /* candidates per periodic direction */

/* Segment k of a 2-D curve: (degree + 1) homogeneous points (w x, w y, w). */
static const double *segment(const bsi_curve *c, size_t k)
{
    return c->hom + k * (c->degree + 1) * 3;
}

/* The piece [s0, s1] of the degree-p segment seg into out (de Casteljau, twice). */
static void piece(const double *seg, size_t p, double s0, double s1, double *out)
{
    double tmp[HOM_MAX];
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

/* The point at s of a 2-D segment (de Casteljau on homogeneous points). */
static void seg_point(const double *seg, size_t p, double s, double *xy)
{
    double tmp[HOM_MAX];
    memcpy(tmp, seg, (p + 1) * 3 * sizeof *tmp);
    for (size_t r = 1; r <= p; r++)
        for (size_t i = 0; i + r <= p; i++)
            for (size_t c = 0; c < 3; c++)
                tmp[i * 3 + c] = (1.0 - s) * tmp[i * 3 + c] + s * tmp[(i + 1) * 3 + c];
    xy[0] = tmp[0] / tmp[2];
    xy[1] = tmp[1] / tmp[2];
}

/* 1 when the chord a -> b crosses the ray (the same half-open rule as the pieces). */
static int chord_crosses(const double *a, const double *b, double u, double v)
{
    if ((a[1] >= v) == (b[1] >= v))
        return 0;
    return a[0] + (b[0] - a[0]) * (v - a[1]) / (b[1] - a[1]) > u;
}

/* ---- parity of the crossings with the ray from (u, v) towards +u ---- */
typedef struct span {
    double s0, s1;
    double a[2], b[2]; /* the points at s0 and s1 */
    int depth;
} span;

static int seg_parity(const double *seg, size_t p, double u, double v)
{
    span stack[PARITY_DEPTH + 2];
    size_t top = 0;
    int parity = 0;
    stack[top].s0 = 0.0;
    stack[top].s1 = 1.0;
    seg_point(seg, p, 0.0, stack[top].a);
    seg_point(seg, p, 1.0, stack[top].b);
    stack[top++].depth = 0;
    while (top > 0) {
        span sp = stack[--top];
        double pts[HOM_MAX];
        piece(seg, p, sp.s0, sp.s1, pts);
        /* the box of the control points and of the ends as computed: a piece judged above or
         * below the line has its ends on that side for its neighbours too */
        double xlo = fmin(sp.a[0], sp.b[0]), xhi = fmax(sp.a[0], sp.b[0]);
        double ylo = fmin(sp.a[1], sp.b[1]), yhi = fmax(sp.a[1], sp.b[1]);
        for (size_t i = 0; i <= p; i++) {
            double x = pts[i * 3] / pts[i * 3 + 2], y = pts[i * 3 + 1] / pts[i * 3 + 2];
            xlo = fmin(xlo, x), xhi = fmax(xhi, x), ylo = fmin(ylo, y), yhi = fmax(yhi, y);
        }
        if (yhi < v || ylo >= v || xhi < u)
            continue;
        int cross = (sp.a[1] >= v) != (sp.b[1] >= v);
        if (xlo > u) {
            parity ^= cross;
            continue;
        }
        if (sp.depth >= PARITY_DEPTH) { /* on the curve to rounding: the chord decides */
            parity ^= chord_crosses(sp.a, sp.b, u, v);
            continue;
        }
        double sm = 0.5 * (sp.s0 + sp.s1), mid[2];
        seg_point(seg, p, sm, mid);
        span left = sp, right = sp;
        left.s1 = right.s0 = sm;
        memcpy(left.b, mid, sizeof mid);
        memcpy(right.a, mid, sizeof mid);
        left.depth = right.depth = sp.depth + 1;
        stack[top++] = right;
        stack[top++] = left;
    }
    return parity;
}

/* Even-odd parity over every trim of every loop of the face: 1 inside. Each loop is closed by
 * chords between the end of one segment and the start of the next (zero or within the file's
 * tolerance), so that every crossing of the closed chain is counted once whatever the gaps. */
static int loops_parity(const bs_model *m, const bsi_face *face, double u, double v)
{
    int parity = 0;
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[l];
        double first[2] = {0.0, 0.0}, prev[2] = {0.0, 0.0};
        int started = 0;
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++) {
            const bsi_curve *c = &m->trims[t].uv;
            size_t n = c->axis.n, p = c->degree;
            if (n == 0)
                continue;
            double head[2], tail[2], lo[2], hi[2];
            seg_point(segment(c, 0), p, 0.0, m->trims[t].reversed ? tail : head);
            seg_point(segment(c, n - 1), p, 1.0, m->trims[t].reversed ? head : tail);
            if (started)
                parity ^= chord_crosses(prev, head, u, v);
            else
                memcpy(first, head, sizeof head), started = 1;
            memcpy(prev, tail, sizeof tail);
            bsi_curve_bounds(c, lo, hi);
            if (hi[1] < v || lo[1] >= v || hi[0] < u)
                continue;
            for (size_t k = 0; k < n; k++) {
                parity ^= seg_parity(segment(c, k), p, u, v);
                if (k + 1 < n) {
                    double a[2], b[2];
                    seg_point(segment(c, k), p, 1.0, a);
                    seg_point(segment(c, k + 1), p, 0.0, b);
                    parity ^= chord_crosses(a, b, u, v);
                }
            }
        }
        if (started)
            parity ^= chord_crosses(prev, first, u, v);
    }
    return parity;
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
        wlo = fmin(wlo, w[i]), whi = fmax(whi, w[i]), lo = fmin(lo, x[i]), hi = fmax(hi, x[i]);
        if (i > 0)
            dx = fmax(dx, fabs(x[i] - x[i - 1])), dw = fmax(dw, fabs(w[i] - w[i - 1]));
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
            wlo = fmin(wlo, w), whi = fmax(whi, w);
            for (int c = 0; c < 3; c++)
                lo[c] = fmin(lo[c], q[c]), hi[c] = fmax(hi[c], q[c]);
            if ((dir == 0 && i == 0) || (dir == 1 && j == 0))
                continue;
            size_t prev = dir == 0 ? (i - 1) * nv + j : i * nv + j - 1;
            dp = fmax(dp, dist3(q, pt->ctrl + prev * 3));
            if (pt->weights != NULL)
                dw = fmax(dw, fabs(w - pt->weights[prev]));
        }
    return (double)deg * (whi * dp + dw * dist3(lo, hi)) / wlo;
}

/* Bounds of |dS/du| and |dS/dv| per native unit over the face. */
static void face_speed(const bs_model *m, const bsi_face *face, double *lip)
{
    double la = 0.0, lb = 0.0;
    for (size_t i = 0; i < face->au.n; i++)
        for (size_t j = 0; j < face->av.n; j++) {
            const bs_patch *pt = bs_surface_get(m->surface, face->first_patch + i * face->av.n + j);
            la = fmax(la, patch_speed(pt, 0) * axis_rate(&face->au, i));
            lb = fmax(lb, patch_speed(pt, 1) * axis_rate(&face->av, j));
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

static int is_seam(const bs_model *m, size_t f, size_t t)
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

typedef struct near_ctx {
    const bs_model *m;
    size_t f;
    const double *box;
    double p[3], lip[2], tol;
} near_ctx;

/* |P - S(c(s))| with c(s) kept in the face's box; INFINITY where the surface is not found. */
static double distance_at(const near_ctx *x, const double *seg, size_t p, double s)
{
    double uv[2], q[3];
    seg_point(seg, p, s, uv);
    uv[0] = fmin(fmax(uv[0], x->box[0]), x->box[1]);
    uv[1] = fmin(fmax(uv[1], x->box[2]), x->box[3]);
    if (!bsi_face_point(x->m, x->f, uv[0], uv[1], q))
        return INFINITY;
    return dist3(x->p, q);
}

/* Within tol of P somewhere on the segment: each piece [s0, s1] is at least D - K / 2 from P, D
 * the distance at its middle, K the bound of the piece's 3-D speed over its own [0, 1]. */
static int seg_near(const near_ctx *x, const double *seg, size_t p)
{
    struct { double s0, s1; int depth; } stack[NEAR_DEPTH + 2];
    size_t top = 0, budget = NEAR_BUDGET;
    stack[top].s0 = 0.0;
    stack[top].s1 = 1.0;
    stack[top++].depth = 0;
    while (top > 0 && budget-- > 0) {
        double s0 = stack[top - 1].s0, s1 = stack[top - 1].s1;
        int depth = stack[--top].depth;
        double sm = 0.5 * (s0 + s1), pts[HOM_MAX], speed[2];
        double d = distance_at(x, seg, p, sm);
        if (d <= x->tol)
            return 1;
        piece(seg, p, s0, s1, pts);
        curve_speed(pts, p, speed);
        double reach = 0.5 * (x->lip[0] * speed[0] + x->lip[1] * speed[1]);
        if (!(d - reach <= x->tol) || reach <= 1e-3 * x->tol || depth >= NEAR_DEPTH)
            continue;
        stack[top].s0 = sm, stack[top].s1 = s1, stack[top++].depth = depth + 1;
        stack[top].s0 = s0, stack[top].s1 = sm, stack[top++].depth = depth + 1;
    }
    return 0;
}

static int near_boundary(const bs_model *m, size_t f, double u, double v, double tol)
{
    const bsi_face *face = &m->faces[f];
    near_ctx x;
    x.m = m, x.f = f, x.box = face->box, x.tol = tol;
    if (!bsi_face_point(m, f, u, v, x.p))
        return 0;
    face_speed(m, face, x.lip);
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[l];
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++) {
            const bsi_curve *c = &m->trims[t].uv;
            if (c->axis.n == 0 || is_seam(m, f, t))
                continue;
            for (size_t k = 0; k < c->axis.n; k++)
                if (seg_near(&x, segment(c, k), c->degree))
                    return 1;
        }
    }
    return 0;
}

/* ---- the candidates ---- */
/* Values of x shifted by whole periods into [lo, hi] (x itself when not periodic): their count. */
static size_t shifts(double x, double lo, double hi, double period, double *out)
{
    if (!(period > 0.0)) {
        out[0] = x;
        return x >= lo && x <= hi;
    }
    size_t n = 0;
    double y = bsi_wrap(x, lo, period);
    while (y <= hi && n < MAX_SHIFTS) {
        out[n++] = y;
        y += period;
    }
    return n;
}

int bsi_face_classify(const bs_model *m, size_t f, double u, double v, double tol)
{
    const bsi_face *face = &m->faces[f];
    if (isnan(u) || isnan(v))
        return BS_TRIM_OUTSIDE;
    double us[MAX_SHIFTS], vs[MAX_SHIFTS];
    size_t nu = shifts(u, face->box[0], face->box[1], face->period[0], us);
    size_t nv = shifts(v, face->box[2], face->box[3], face->period[1], vs);
    if (nu == 0 || nv == 0)
        return BS_TRIM_OUTSIDE;
    if (face->loop_count == 0)
        return BS_TRIM_INSIDE;
    if (near_boundary(m, f, us[0], vs[0], tol))
        return BS_TRIM_ON;
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++)
            if (loops_parity(m, face, us[i], vs[j]))
                return BS_TRIM_INSIDE;
    return BS_TRIM_OUTSIDE;
}
