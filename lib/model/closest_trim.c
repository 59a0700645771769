/*
 * Closest points on the boundaries of a model's faces: the part of a closest-point query on a
 * model that the search over the faces' patches leaves to its callers (lib/query/closest_grad.c).
 *
 * Each trim segment c(r), r in [0, 1], in native parameters, is a boundary curve C(r) = S(c(r))
 * in 3-D. A branch and bound over r keeps the nearest point found at the middles of the
 * intervals and bounds the distance over an interval [a, b] (h = b - a, middle r) from below:
 *   - first order, d(r) - M1 h / 2, M1 a bound of |C'| over the segment: always valid (C is
 *     continuous, also where it crosses from one patch to the next);
 *   - second order, where the interval maps into one patch (C is smooth there): with g = |C - q|^2,
 *     g >= g(r) - |g'(r)| h / 2 - G h^2 / 8, G = 2 M1^2 + 2 (d(r) + M1 h / 2) M2 >= |g''|, M2 a
 *     bound of |C''|. This bound is off by O(h^2) only, so the intervals around a minimum stop
 *     splitting at h ~ sqrt(tolerance) instead of h ~ tolerance.
 * M1 and M2 come from the chain rule over bounds computed once per segment: the segment's own
 * derivatives (c' and c'' of a rational Bezier curve from its control points), the native -> patch
 * map's (closed form per axis piece) and the patches' partials up to second order (from their
 * homogeneous nets). An interval is dropped when its bound is not below the best distance minus
 * the tolerance of the search on the patches, 0.5e-9 (D + best); a search that reaches its cap
 * (EVAL_CAP middles per query) or the deepest level is not certified.
 */
#include "model/classify_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define EVAL_CAP 200000
#define DEPTH 60
#define TOP 8 /* intervals of a piece's first level, sampled once */

/* What is known at one parameter r of a piece: C, C', the native (u, v) brought into the face's
 * box and the native ranges of the patch holding it (bsi_face_partials_cell). */
typedef struct sample {
    double C[3], dC[3], cell[6];
} sample;

typedef struct trim_piece {
    uint32_t face;
    const double *seg;     /* the segment's homogeneous points */
    size_t degree;
    double m1, m2;         /* bounds of |C'| and |C''| over r in [0, 1] */
    double du, dv;         /* bounds of |u'| and |v'| */
    int in_box[2];         /* the control points lie in the face's box along u, along v */
    double sd[4];          /* bounds of |s'|, |t'|, |s''|, |t''| (the patch's own parameters) */
    double slack;          /* a pole's piece: how far its image may be from one point (else 0) */
    sample top[TOP];       /* at the middles of [k, k+1] / TOP: the search's first level */
    int top_ok;            /* 1 when every one was found */
    double lo[3], hi[3];   /* a box holding C over the segment (the first level's balls) */
} trim_piece;

struct bsi_trim_search {
    const bs_model *m;
    trim_piece *pieces;
    size_t n;
    double diag;
};

/* Bounds b[5] of |S_s|, |S_t|, |S_ss|, |S_st|, |S_tt| over [0,1]^2 for the rational net of
 * (m+1) x (n+1) points pts (dim coordinates, row-major) with weights w (NULL: all 1). With H the
 * homogeneous net moved by a centre c0 and W its weights, S_s = (H_s - (S - c0) W_s) / W and
 * S_ss = (H_ss - 2 S_s W_s - (S - c0) W_ss) / W (S_st likewise), and each partial of H or W is at
 * most its largest Bezier coefficient, |S - c0| at most the largest |P - c0|. */
static void net_bounds(const double *pts, const double *w, size_t m, size_t n, size_t dim, double b[5])
{
    size_t n1 = n + 1;
    double c0[3] = {0.0, 0.0, 0.0}, R = 0.0, wmin = INFINITY;
    for (size_t c = 0; c < dim; c++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t k = 0; k < (m + 1) * n1; k++)
            lo = bsi_dmin(lo, pts[k * dim + c]), hi = bsi_dmax(hi, pts[k * dim + c]);
        c0[c] = 0.5 * (lo + hi);
    }
    for (size_t k = 0; k < (m + 1) * n1; k++) {
        double r2 = 0.0;
        for (size_t c = 0; c < dim; c++)
            r2 += (pts[k * dim + c] - c0[c]) * (pts[k * dim + c] - c0[c]);
        R = bsi_dmax(R, sqrt(r2));
        wmin = bsi_dmin(wmin, w ? w[k] : 1.0);
    }
    /* hb, wb: the largest coefficients of H_s, H_t, H_ss, H_st, H_tt and of W's: differences of
     * the net's values V = (w (P - c0), w), written out per kind */
#define V(i, j, c) ((c) < dim ? (w ? w[(i) * n1 + (j)] : 1.0) * (pts[((i) * n1 + (j)) * dim + (c)] - c0[c]) \
                              : (w ? w[(i) * n1 + (j)] : 1.0))
    double hb[5] = {0}, wb[5] = {0};
    static const int di[5] = {1, 0, 2, 1, 0}, dj[5] = {0, 1, 0, 1, 2};
    for (int d = 0; d < 5; d++) {
        size_t a = (size_t)di[d], e = (size_t)dj[d];
        if (a > m || e > n)
            continue;
        double f = 1.0; /* m!/(m-a)! n!/(n-e)! */
        for (size_t k = 0; k < a; k++)
            f *= (double)(m - k);
        for (size_t k = 0; k < e; k++)
            f *= (double)(n - k);
        for (size_t i = 0; i + a <= m; i++)
            for (size_t j = 0; j + e <= n; j++) {
                double h2 = 0.0, wd = 0.0;
                for (size_t c = 0; c <= dim; c++) { /* c = dim: the weight */
                    double x = d == 0   ? V(i + 1, j, c) - V(i, j, c)
                               : d == 1 ? V(i, j + 1, c) - V(i, j, c)
                               : d == 2 ? V(i + 2, j, c) - 2.0 * V(i + 1, j, c) + V(i, j, c)
                               : d == 3 ? V(i + 1, j + 1, c) - V(i + 1, j, c) - V(i, j + 1, c) + V(i, j, c)
                                        : V(i, j + 2, c) - 2.0 * V(i, j + 1, c) + V(i, j, c);
                    if (c < dim)
                        h2 += x * x;
                    else
                        wd = fabs(x);
                }
                hb[d] = bsi_dmax(hb[d], f * sqrt(h2));
                wb[d] = bsi_dmax(wb[d], f * wd);
            }
    }
#undef V
    double up = 1.0 + 1e-12;
    b[0] = up * (hb[0] + R * wb[0]) / wmin;
    b[1] = up * (hb[1] + R * wb[1]) / wmin;
    b[2] = up * (hb[2] + 2.0 * b[0] * wb[0] + R * wb[2]) / wmin;
    b[3] = up * (hb[3] + b[0] * wb[1] + b[1] * wb[0] + R * wb[3]) / wmin;
    b[4] = up * (hb[4] + 2.0 * b[1] * wb[1] + R * wb[4]) / wmin;
}

/* The largest first and second derivatives of the native -> local map of an axis. */
static void axis_bounds(const bsi_axis *a, double *s1, double *s2)
{
    *s1 = *s2 = 0.0;
    for (size_t k = 0; k < a->n; k++) {
        double width = a->breaks[k + 1] - a->breaks[k];
        if (a->kind == BSI_AXIS_ANGULAR) {
            double half = 0.25 * a->radians * width, c = cos(half);
            *s1 = bsi_dmax(*s1, a->radians / (2.0 * sin(2.0 * half)));
            *s2 = bsi_dmax(*s2, a->radians * a->radians / (4.0 * c * c));
        } else {
            *s1 = bsi_dmax(*s1, 1.0 / width);
        }
    }
    *s1 *= 1.0 + 1e-12;
    *s2 *= 1.0 + 1e-12;
}

/* The point and its derivative at r of a 2-D segment of degree p. */
static void seg_eval(const double *seg, size_t p, double r, double *xy, double *dxy)
{
    double t[BSI_SEG_MAX];
    memcpy(t, seg, (p + 1) * 3 * sizeof *t);
    for (size_t lev = 1; lev < p; lev++)
        for (size_t i = 0; i + lev <= p; i++)
            for (size_t c = 0; c < 3; c++)
                t[i * 3 + c] = (1.0 - r) * t[i * 3 + c] + r * t[(i + 1) * 3 + c];
    if (p == 0) { /* a constant (trim segments are of degree 1 and up) */
        xy[0] = t[0] / t[2], xy[1] = t[1] / t[2], dxy[0] = dxy[1] = 0.0;
        return;
    }
    double h[3], dh[3];
    for (size_t c = 0; c < 3; c++) {
        h[c] = (1.0 - r) * t[c] + r * t[3 + c];
        dh[c] = (double)p * (t[3 + c] - t[c]);
    }
    for (size_t c = 0; c < 2; c++) {
        xy[c] = h[c] / h[2];
        dxy[c] = (dh[c] - xy[c] * dh[2]) / h[2];
    }
}

/* The sample at r of a piece: 0 where the face's patches are not found. */
static int sample_at(const bsi_trim_search *ts, const trim_piece *pc, double r, sample *x)
{
    double uv[2], duv[2], pu[3], pv[3];
    seg_eval(pc->seg, pc->degree, r, uv, duv);
    if (!bsi_face_partials_cell(ts->m, pc->face, uv[0], uv[1], x->C, pu, pv, x->cell))
        return 0;
    for (int c = 0; c < 3; c++)
        x->dC[c] = pu[c] * duv[0] + pv[c] * duv[1];
    return 1;
}

/* The diameter of the box of the control points of the patch sides of face that a trim piece
 * along a side of the face's box runs on, when the piece is such an iso-line: where the side is
 * collapsed (a pole), the piece's image is a point up to that diameter. -1 otherwise, and when
 * the diameter is not below 1e-12 of the patches' own size. */
static double pole_spread(const bs_model *m, const bsi_face *face, const trim_piece *pc)
{
    for (size_t d = 0; d < 2; d++) {
        double x = pc->seg[d] / pc->seg[2];
        int constant = 1;
        for (size_t i = 1; i <= pc->degree; i++)
            constant &= pc->seg[i * 3 + d] / pc->seg[i * 3 + 2] == x;
        int dir = (int)d ^ face->swap; /* canonical direction of the native coordinate d */
        const bsi_axis *ax = dir == 0 ? &face->au : &face->av;
        if (!constant || ax->n == 0 || (x != ax->breaks[0] && x != ax->breaks[ax->n]))
            continue;
        int high = x == ax->breaks[ax->n];
        size_t piece = high ? ax->n - 1 : 0, others = dir == 0 ? face->av.n : face->au.n;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        double size = 0.0;
        for (size_t k = 0; k < others; k++) {
            size_t i = dir == 0 ? piece : k, j = dir == 0 ? k : piece;
            const bs_patch *pt = bs_surface_get(m->surface, face->first_patch + i * face->av.n + j);
            size_t nv = pt->deg_v + 1, len = dir == 0 ? nv : pt->deg_u + 1;
            for (size_t e = 0; e < len; e++) {
                size_t row = dir == 0 ? (high ? pt->deg_u : 0) : e, col = dir == 0 ? e : (high ? pt->deg_v : 0);
                const double *p = pt->ctrl + (row * nv + col) * 3;
                for (int c = 0; c < 3; c++)
                    lo[c] = bsi_dmin(lo[c], p[c]), hi[c] = bsi_dmax(hi[c], p[c]);
            }
            for (size_t e = 0; e < pt->nctrl; e++)
                for (size_t c = 0; c < 3; c++)
                    size = bsi_dmax(size, fabs(pt->ctrl[e * 3 + c] - pt->ctrl[c]));
        }
        double spread = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2]));
        if (spread <= 1e-12 * size)
            return spread;
    }
    return -1.0;
}

/* Bounds of |C'| (m1) and |C''| (m2) from bounds b[5] of the patch's partials (net_bounds) and
 * sd[4] of the derivatives of the patch parameters along the curve: the chain rule. */
static void chain(const double *b, const double *sd, double *m1, double *m2)
{
    *m1 = b[0] * sd[0] + b[1] * sd[1];
    *m2 = b[2] * sd[0] * sd[0] + 2.0 * b[3] * sd[0] * sd[1] + b[4] * sd[1] * sd[1] + b[0] * sd[2] +
          b[1] * sd[3];
}

#define LOCAL_POINTS 100 /* nets of at most this many points get local bounds */

/* m1 and m2 over the native box nb (inside one patch):
 * net_bounds of the patch's sub-net over the box, its partials rescaled to the patch's own
 * parameters. Where weights vary wildly over a patch its global bounds are far too large
 * (1 / min w); the sub-net's weights vary little. 0 when not made (a large net). */
static int local_bounds(const bsi_trim_search *ts, const trim_piece *pc, const double nb[4],
                        double *m1, double *m2)
{
    uint32_t id, id2;
    double a[2], b[2];
    if (!bsi_face_locate(ts->m, pc->face, nb[0], nb[2], &id, a) ||
        !bsi_face_locate(ts->m, pc->face, nb[1], nb[3], &id2, b) || id != id2)
        return 0;
    const bs_patch *pt = bs_surface_get(ts->m->surface, id);
    size_t m = pt->deg_u, n = pt->deg_v, nv = n + 1, nc = pt->ncoord, count = (m + 1) * nv;
    if (count > LOCAL_POINTS)
        return 0;
    double h[LOCAL_POINTS * 4], pts[LOCAL_POINTS * 3], w[LOCAL_POINTS], box[4], bd[5];
    for (size_t k = 0; k < count; k++)
        for (size_t e = 0; e < nc; e++)
            h[k * nc + e] = pt->hom[e * count + k];
    for (size_t d = 0; d < 2; d++) { /* at least a sliver wide: the rescaling divides by it */
        double lo = bsi_dmin(a[d], b[d]), hi = bsi_dmax(a[d], b[d]);
        if (hi - lo < 1e-9)
            lo = bsi_dmax(0.0, lo - 1e-9), hi = bsi_dmin(1.0, hi + 1e-9);
        box[2 * d] = lo, box[2 * d + 1] = hi;
    }
    for (size_t j = 0; j <= n; j++)
        bsi_sub_line(h + j * nc, m, nv * nc, nc, box[0], box[1]);
    for (size_t i = 0; i <= m; i++)
        bsi_sub_line(h + i * nv * nc, n, nc, nc, box[2], box[3]);
    for (size_t k = 0; k < count; k++) {
        w[k] = pt->rational ? h[k * nc + 3] : 1.0;
        for (size_t e = 0; e < 3; e++)
            pts[k * 3 + e] = h[k * nc + e] / w[k];
    }
    net_bounds(pts, pt->rational ? w : NULL, m, n, 3, bd);
    double ds = box[1] - box[0], dt = box[3] - box[2];
    bd[0] /= ds, bd[1] /= dt, bd[2] /= ds * ds, bd[3] /= ds * dt, bd[4] /= dt * dt;
    chain(bd, pc->sd, m1, m2);
    return isfinite(*m1) && isfinite(*m2);
}

/* Bounds of piece pc (its face, segment and degree set): du, dv, m1, m2, the ball. */
static void piece_bounds(const bsi_trim_search *ts, trim_piece *pc, const double *face_b,
                         const double *axis_b)
{
    const bsi_face *face = &ts->m->faces[pc->face];
    size_t p = pc->degree;
    double x[BS_MAX_DEGREE + 1], w[BS_MAX_DEGREE + 1], cb[2][5];
    for (size_t d = 0; d < 2; d++) {
        for (size_t i = 0; i <= p; i++) {
            w[i] = pc->seg[i * 3 + 2];
            x[i] = pc->seg[i * 3 + d] / w[i];
        }
        net_bounds(x, w, p, 0, 1, cb[d]); /* cb[d][0] >= |x'|, cb[d][2] >= |x''| */
    }
    pc->du = cb[0][0];
    pc->dv = cb[1][0];
    for (size_t d = 0; d < 2; d++) {
        pc->in_box[d] = 1;
        for (size_t i = 0; i <= p; i++) {
            double y = pc->seg[i * 3 + d] / pc->seg[i * 3 + 2];
            pc->in_box[d] &= y >= face->box[2 * d] && y <= face->box[2 * d + 1];
        }
    }
    /* canonical directions (s along au, t along av) */
    int sw = face->swap;
    double a1 = cb[sw][0], a2 = cb[sw][2], b1 = cb[!sw][0], b2 = cb[!sw][2];
    double su = axis_b[0] * a1, sv = axis_b[2] * b1; /* bounds of |s'| and |t'| */
    double suu = axis_b[1] * a1 * a1 + axis_b[0] * a2, svv = axis_b[3] * b1 * b1 + axis_b[2] * b2;
    pc->sd[0] = su, pc->sd[1] = sv, pc->sd[2] = suu, pc->sd[3] = svv;
    chain(face_b, pc->sd, &pc->m1, &pc->m2);
    double spread = pole_spread(ts->m, face, pc);
    if (spread >= 0.0) { /* the image is a point (a pole) within spread */
        pc->m1 = pc->m2 = 0.0;
        pc->slack = spread;
    }
    pc->top_ok = isfinite(pc->m1) && isfinite(pc->m2);
    double reach = 0.5 * pc->m1 / TOP * (1.0 + 1e-9);
    for (int c = 0; c < 3; c++)
        pc->lo[c] = INFINITY, pc->hi[c] = -INFINITY;
    for (size_t k = 0; k < TOP && pc->top_ok; k++) {
        sample *at = &pc->top[k];
        pc->top_ok = sample_at(ts, pc, ((double)k + 0.5) / TOP, at);
        for (int c = 0; c < 3 && pc->top_ok; c++) {
            pc->lo[c] = bsi_dmin(pc->lo[c], at->C[c] - reach - pc->slack);
            pc->hi[c] = bsi_dmax(pc->hi[c], at->C[c] + reach + pc->slack);
        }
    }
}

void bsi_trim_search_free(bsi_trim_search *ts)
{
    if (ts != NULL)
        free(ts->pieces);
    free(ts);
}

bs_status bsi_trim_search_create(const bs_model *m, double diag, bsi_trim_search **out)
{
    *out = NULL;
    bsi_trim_search *ts = calloc(1, sizeof *ts);
    size_t count = 0;
    for (size_t t = 0; t < m->ntrim; t++)
        count += m->trims[t].uv.axis.n;
    if (ts == NULL || (ts->pieces = malloc((count > 0 ? count : 1) * sizeof *ts->pieces)) == NULL) {
        free(ts);
        return BS_ERR_NO_MEMORY;
    }
    ts->m = m;
    ts->diag = diag;
    for (size_t f = 0; f < m->nface; f++) {
        const bsi_face *face = &m->faces[f];
        double fb[5] = {0}, ab[4];
        for (size_t k = 0; k < face->patch_count; k++) {
            const bs_patch *pt = bs_surface_get(m->surface, face->first_patch + k);
            double b[5];
            net_bounds(pt->ctrl, pt->weights, pt->deg_u, pt->deg_v, 3, b);
            for (int d = 0; d < 5; d++)
                fb[d] = bsi_dmax(fb[d], b[d]);
        }
        axis_bounds(&face->au, &ab[0], &ab[1]);
        axis_bounds(&face->av, &ab[2], &ab[3]);
        for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++)
            for (size_t t = m->loops[l].first_trim;
                 t < m->loops[l].first_trim + m->loops[l].trim_count; t++) {
                const bsi_curve *c = &m->trims[t].uv;
                if (bsi_trim_is_seam(m, f, t))
                    continue; /* not a boundary: both sides are the face */
                for (size_t k = 0; k < c->axis.n; k++) {
                    trim_piece *pc = &ts->pieces[ts->n++];
                    pc->face = (uint32_t)f;
                    pc->seg = bsi_trim_segment(c, k);
                    pc->degree = c->degree;
                    pc->slack = 0.0;
                    piece_bounds(ts, pc, fb, ab);
                }
            }
    }
    *out = ts;
    return BS_OK;
}

/* The native box nb (u0 u1 v0 v1) holding the piece's curve over an interval: around the
 * sample's point, half-widths (hu, hv), cut to the face's box along a direction where the
 * segment's control points lie in it (so does the curve); 1 when it lies in the sample's patch. */
static int interval_box(const bsi_trim_search *ts, const trim_piece *pc, const sample *x,
                        double hu, double hv, double nb[4])
{
    const double *c = x->cell, *box = ts->m->faces[pc->face].box;
    double half[2] = {hu, hv};
    int in = 1;
    for (size_t d = 0; d < 2; d++) {
        nb[2 * d] = c[4 + d] - half[d], nb[2 * d + 1] = c[4 + d] + half[d];
        if (pc->in_box[d])
            nb[2 * d] = bsi_dmax(nb[2 * d], box[2 * d]), nb[2 * d + 1] = bsi_dmin(nb[2 * d + 1], box[2 * d + 1]);
        in &= nb[2 * d] >= c[2 * d] && nb[2 * d + 1] <= c[2 * d + 1];
    }
    return in;
}

typedef struct interval {
    double a, b;
    const sample *known; /* the sample at its middle when known, else NULL */
    double m1, m2;       /* bounds of |C'| and |C''| over it: the piece's, or local ones */
    unsigned depth;
    int local;           /* 1: m1 and m2 are local (their parent's, whose box holds its own) */
} interval;

/* The branch and bound along one piece against *best (see the top); *evals counts the middles
 * sampled. 1 when a nearer point was found (face and uv set), 0 when none, -2 when not
 * certified. */
static int piece_search(const bsi_trim_search *ts, const trim_piece *pc, const double *q,
                        double *best, double *uv_best, size_t *evals)
{
    interval stack[DEPTH + TOP + 2];
    size_t top = 0;
    int found = 0;
    for (size_t k = TOP; k-- > 0;)
        stack[top++] = (interval){(double)k / TOP, (double)(k + 1) / TOP, &pc->top[k], pc->m1, pc->m2,
                                  3, 0};
    while (top > 0) {
        interval iv = stack[--top];
        double r = 0.5 * (iv.a + iv.b), h = iv.b - iv.a;
        sample fresh;
        const sample *x = iv.known;
        if (x == NULL) {
            if (++*evals > EVAL_CAP || !sample_at(ts, pc, r, &fresh))
                return -2;
            x = &fresh;
        }
        double g = 0.0, gp = 0.0, mag = 0.0;
        for (int c = 0; c < 3; c++) {
            double e = x->C[c] - q[c];
            g += e * e;
            gp += 2.0 * e * x->dC[c];
            mag = bsi_dmax(mag, fabs(x->C[c]) + fabs(q[c]));
        }
        double d = sqrt(g);
        if (d < *best) {
            *best = d;
            uv_best[0] = x->cell[4];
            uv_best[1] = x->cell[5];
            found = 1;
        }
        double hu = 0.5 * h * pc->du, hv = 0.5 * h * pc->dv, m1 = iv.m1, m2 = iv.m2;
        double lb = d - 0.5 * m1 * h, floor = *best - 0.5e-9 * (ts->diag + *best);
        double noise = 64.0 * DBL_EPSILON * mag + pc->slack; /* the evaluation's rounding */
        double nb[4];
        int one = interval_box(ts, pc, x, hu, hv, nb);
        /* the bounds it has, then local ones made anew (every fourth level when it has some) */
        for (int pass = 0; pass < 2 && one; pass++) {
            if (pass == 1 && (lb - noise >= floor || (iv.local && iv.depth % 4 != 0) ||
                              !local_bounds(ts, pc, nb, &m1, &m2)))
                break;
            iv.local |= pass == 1;
            double G = 2.0 * m1 * m1 + 2.0 * (d + 0.5 * m1 * h) * m2;
            double glb = g - fabs(gp) * 0.5 * h * (1.0 + 1e-9) - G * h * h / 8.0;
            lb = bsi_dmax(lb, bsi_dmax(d - 0.5 * m1 * h, sqrt(bsi_dmax(glb, 0.0))));
        }
        if (lb - noise >= floor)
            continue;
        if (iv.depth >= DEPTH)
            return -2;
        if (!(one && iv.local)) /* a child keeps local bounds only inside this box */
            m1 = pc->m1, m2 = pc->m2, iv.local = 0;
        stack[top++] = (interval){r, iv.b, NULL, m1, m2, iv.depth + 1, iv.local};
        stack[top++] = (interval){iv.a, r, NULL, m1, m2, iv.depth + 1, iv.local};
    }
    return found;
}

/* The distance from q to the box (lo, hi). */
static double box_gap(const double *lo, const double *hi, const double *q)
{
    double s = 0.0;
    for (int c = 0; c < 3; c++) {
        double g = bsi_dmax(0.0, bsi_dmax(lo[c] - q[c], q[c] - hi[c]));
        s += g * g;
    }
    return sqrt(s);
}

int bsi_trim_search_closest(const bsi_trim_search *ts, const double *q, double *best_d,
                            uint32_t *patch, double st[2])
{
    size_t evals = 0;
    int found = 0;
    uint32_t face = 0;
    double uv[2] = {0.0, 0.0};
    for (size_t k = 0; k < ts->n; k++) {
        const trim_piece *pc = &ts->pieces[k];
        if (!pc->top_ok)
            return -2;
        if (box_gap(pc->lo, pc->hi, q) >= *best_d)
            continue;
        int r = piece_search(ts, pc, q, best_d, uv, &evals);
        if (r < 0)
            return r;
        if (r == 1) {
            found = 1;
            face = pc->face;
        }
    }
    if (found && !bsi_face_locate(ts->m, face, uv[0], uv[1], patch, st))
        return -2;
    return found;
}
