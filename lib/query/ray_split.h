/*
 * Which way to halve a piece of a ray's search (lib/query/ray_patch.c): across a side that is
 * singular (collapsed to a pole, or a cusp edge where the partial across it vanishes), or both
 * ways, deeper than regular pieces go, at a corner between two poles or a singular corner; and
 * where to cut a rational piece whose weights hand over from one side to the other. Private
 * to lib/query/; included by ray_patch.c alone, after ray_piece.h (inlined into each of that
 * file's two cases, rational or not).
 */
#ifndef BEZSURF_QUERY_RAY_SPLIT_H
#define BEZSURF_QUERY_RAY_SPLIT_H

#include "query/ray_piece.h"

/* The largest distance (max norm of X1, X2, T over W) between the points of the line of the net
 * from index a, count points step apart, and its first point. */
SPECIALISE double line_span(const double *net, size_t a, size_t count, size_t step, int rat)
{
    const double *p0 = net + a * NC;
    double x0 = WDIV(rat, p0[0], p0[3]), y0 = WDIV(rat, p0[1], p0[3]), z0 = WDIV(rat, p0[2], p0[3]);
    double span = 0.0;
    for (size_t k = 1; k < count; k++) {
        const double *p = net + (a + k * step) * NC;
        span = greater(span, greater(fabs(WDIV(rat, p[0], p[3]) - x0),
                                     greater(fabs(WDIV(rat, p[1], p[3]) - y0),
                                             fabs(WDIV(rat, p[2], p[3]) - z0))));
    }
    return span;
}

/* 1 if the points of two lines of the net, from indices a and b, count points step apart, lie
 * within ext of each other point by point (max norm of X1, X2, T over W). Most pieces fail at
 * their first points. */
SPECIALISE int lines_near(const double *net, size_t a, size_t b, size_t count, size_t step, int rat, double ext)
{
    for (size_t k = 0; k < count; k++) {
        const double *p = net + (a + k * step) * NC, *q = net + (b + k * step) * NC;
        for (int c = 0; c < 3; c++)
            if (!(fabs(WDIV(rat, p[c], p[3]) - WDIV(rat, q[c], q[3])) <= ext))
                return 0;
    }
    return 1;
}

/* 1 if the points of two lines of the net (from indices a and b, count points step apart) lie on
 * one straight line within ext: on the line through the first point and the farthest of the
 * other ends of the two lines (the lines' extent, so that the line's direction is accurate). A
 * side and the next line on one line make the partial across the side parallel to the side all
 * along it (the map folds there: a cone over a curve tangent to its generator, say). Most pieces
 * fail at their first points. */
SPECIALISE int lines_collinear(const double *net, size_t a, size_t b, size_t count, size_t step, int rat,
                               double ext)
{
    const double *p0 = net + a * NC;
    double o[3] = {WDIV(rat, p0[0], p0[3]), WDIV(rat, p0[1], p0[3]), WDIV(rat, p0[2], p0[3])};
    double dir[3] = {0.0, 0.0, 0.0}, far = 0.0;
    const size_t ends[3] = {a + (count - 1) * step, b, b + (count - 1) * step};
    for (int k = 0; k < 3; k++) {
        const double *p = net + ends[k] * NC;
        double x[3] = {WDIV(rat, p[0], p[3]) - o[0], WDIV(rat, p[1], p[3]) - o[1], WDIV(rat, p[2], p[3]) - o[2]};
        double len2 = bsi_dot3(x, x);
        if (len2 > far) {
            far = len2;
            for (int c = 0; c < 3; c++)
                dir[c] = x[c];
        }
    }
    if (far > 0.0) /* unit: off below is then a point's offset from the line */
        for (int c = 0; c < 3; c++)
            dir[c] /= sqrt(far);
    for (size_t k = 0; k < 2 * count; k++) {
        const double *p = net + ((k < count ? a : b) + (k % count) * step) * NC;
        double x[3] = {WDIV(rat, p[0], p[3]) - o[0], WDIV(rat, p[1], p[3]) - o[1], WDIV(rat, p[2], p[3]) - o[2]};
        double along = bsi_dot3(x, dir);
        double off[3] = {x[0] - along * dir[0], x[1] - along * dir[1], x[2] - along * dir[2]};
        if (!(bsi_dot3(off, off) <= ext * ext))
            return 0;
    }
    return 1;
}

/* 1 if a side of the net along dir (BS_DIR_U: a row, s = 0 or 1) is singular: collapsed to a point,
 * or equal to the next line of the net, where the partial across it vanishes along the whole side
 * (a cusp edge, such as a side whose last two rows of points coincide), or on one straight line
 * with the next line (a fold, lines_collinear). Within ext. */
SPECIALISE int singular_side(const double *net, size_t m, size_t n, int rat, int dir, double ext)
{
    size_t deg = dir == BS_DIR_U ? m : n, count = dir == BS_DIR_U ? n + 1 : m + 1;
    size_t step = dir == BS_DIR_U ? 1 : n + 1, next = dir == BS_DIR_U ? n + 1 : 1;
    size_t last = deg * next; /* the first point of the side s = 1 (or r = 1) */
    return line_span(net, 0, count, step, rat) <= ext || line_span(net, last, count, step, rat) <= ext ||
           lines_near(net, 0, next, count, step, rat, ext) ||
           lines_near(net, last, last - next, count, step, rat, ext) ||
           lines_collinear(net, 0, next, count, step, rat, ext) ||
           lines_collinear(net, last, last - next, count, step, rat, ext);
}

/* 1 if at a corner of the net the first differences along s and along r are parallel (or one
 * vanishes): both partials are then parallel there, the normal comes from second derivatives,
 * and the map (X1, X2) folds, so that no piece holding that corner is one to one. Parallel within
 * rel (1e-9 for the corner itself) and the rounding err of the points, which decides once the
 * pieces holding the corner are small. */
SPECIALISE int singular_corner(const double *net, size_t m, size_t n, int rat, double rel, double err)
{
    const size_t row = n + 1;
    for (int k = 0; k < 4; k++) {
        size_t i = k & 1 ? m : 0, j = k & 2 ? n : 0;
        size_t at = i * row + j, si = k & 1 ? at - row : at + row, rj = k & 2 ? at - 1 : at + 1;
        const double *p = net + at * NC, *ps = net + si * NC, *pr = net + rj * NC;
        double a[3], b[3], c[3];
        for (int q = 0; q < 3; q++) {
            double x = WDIV(rat, p[q], p[3]);
            a[q] = WDIV(rat, ps[q], ps[3]) - x;
            b[q] = WDIV(rat, pr[q], pr[3]) - x;
        }
        bsi_cross3(a, b, c);
        double la = sqrt(bsi_dot3(a, a)), lb = sqrt(bsi_dot3(b, b));
        if (!(sqrt(bsi_dot3(c, c)) > rel * la * lb + err * (la + lb)))
            return 1;
    }
    return 0;
}

/* 1 if every line of the net along dir (BS_DIR_U: the rows) lies within ext of the first: the
 * piece is then a curve across those lines, and halving it along s (for rows) only makes copies. */
SPECIALISE int lines_all_near(const double *net, size_t m, size_t n, int rat, int dir, double ext)
{
    size_t deg = dir == BS_DIR_U ? m : n, count = dir == BS_DIR_U ? n + 1 : m + 1;
    size_t step = dir == BS_DIR_U ? 1 : n + 1, next = dir == BS_DIR_U ? n + 1 : 1;
    for (size_t k = 1; k <= deg; k++)
        if (!lines_near(net, 0, k * next, count, step, rat, ext))
            return 0;
    return 1;
}

/* The direction to halve a piece in: first, a sliver (every line one way within 2^-4 of the
 * piece's extent of the first) along its length only (BS_DIR_V when its rows lie together);
 * else BS_DIR_U when a side s = const (a row of the net) is
 * singular (singular_side, within 1e-9 of the net's extent) and no side r = const is, BS_DIR_V
 * for the converse; -2 (both directions, down to POLE_DEPTH) when sides of both kinds are (a
 * corner between two poles) or a corner is singular (singular_corner), -1 (both, down to
 * MAX_DEPTH) when none is. Next to a cusp edge the map is quadratic across it and Newton's steps
 * are poor until a piece no longer holds the edge: halved across it, a piece a level holds the
 * edge and the one beside it, with a zero near the edge, is regular enough for Newton. Next to a
 * singular corner one piece a level holds the corner, and the hits 2^-k from it lie in pieces
 * of level k, deeper than MAX_DEPTH. Pieces beside a cusp edge become slivers: the ray passes
 * within a hair of the edge, so that every piece along it holds points near the ray; halved
 * across, the two halves keep the same box at every level and their number doubles until the
 * budget runs out, while halved along, all but the pieces where the ray passes are discarded. */
SPECIALISE int pole_split(const double *net, size_t m, size_t n, int rat, const double lo[3],
                          const double hi[3])
{
    if (m == 0 || n == 0)
        return -1;
    double size = greater(hi[0] - lo[0], greater(hi[1] - lo[1], hi[2] - lo[2]));
    int rows = singular_side(net, m, n, rat, BS_DIR_U, 1e-9 * size);
    int cols = singular_side(net, m, n, rat, BS_DIR_V, 1e-9 * size);
    /* a sliver (a piece holding or beside a cusp edge, where the map is quadratic across it, or
     * next to a pole with wild weights, where pieces reach from the pole to the far side) is
     * halved along its length only: halved across, it would make two pieces no box can tell apart
     * at every level */
    int flat_s = lines_all_near(net, m, n, rat, BS_DIR_U, 0x1p-4 * size);
    int flat_r = lines_all_near(net, m, n, rat, BS_DIR_V, 0x1p-4 * size);
    if (flat_s != flat_r)
        return flat_s ? BS_DIR_V : BS_DIR_U;
    if (rows || cols)
        return rows && cols ? -2 : rows ? BS_DIR_U : BS_DIR_V;
    double big = greater(greater(fabs(lo[0]), fabs(hi[0])), greater(greater(fabs(lo[1]), fabs(hi[1])),
                                                                  greater(fabs(lo[2]), fabs(hi[2]))));
    return singular_corner(net, m, n, rat, 1e-9, 64 * DBL_EPSILON * big) ? -2 : -1;
}

/* Where to cut a rational piece along dir (BS_DIR_U: across its rows), as a fraction of its
 * width: 1/2, unless its weights hand over from one side to the other, the geometric mean of its
 * lines' end-weight ratios more than 16^deg away from 1. Then the cut lies where they hand over,
 * (1 - t)^deg w_first = t^deg w_last (a Moebius reparametrisation that balances the end weights
 * maps 1/2 there): halved, such a piece keeps a hull far larger than itself for level after level
 * (wild weights next to a pole: most of the domain maps within a hair of one side). Not inlined
 * into the two cases of the search: rare and cheap next to the halving. */
static double handover(const double *net, size_t m, size_t n, int rat, int dir)
{
    size_t deg = dir == BS_DIR_U ? m : n, count = dir == BS_DIR_U ? n + 1 : m + 1;
    size_t step = dir == BS_DIR_U ? 1 : n + 1, next = dir == BS_DIR_U ? n + 1 : 1;
    if (!rat || deg == 0)
        return 0.5;
    double lg = 0.0; /* log2 of the weights' ratio per degree */
    for (size_t k = 0; k < count; k++)
        lg += log2(net[k * step * NC + 3]) - log2(net[(k * step + deg * next) * NC + 3]);
    lg /= (double)(count * deg);
    if (!(fabs(lg) > 4.0))
        return 0.5;
    if (fabs(lg) > 40.0) /* cuts beyond 2^-40 of the width only add levels */
        return lg < 0.0 ? 0x1p-40 : 1.0 - 0x1p-40;
    double sig = exp2(lg);
    return sig / (1.0 + sig);
}

/* Cut a net of NC doubles a point at the fraction f of its width along dir into lo and hi:
 * bsi_net_halve's midpoints at f = 1/2 (the same bits in patches sharing a side), de
 * Casteljau's convex combinations elsewhere. */
static void net_cut(const double *net, size_t m, size_t n, int dir, double f, double *lo, double *hi)
{
    if (f == 0.5) {
        bsi_net_halve(net, m, n, NC, dir, lo, hi);
        return;
    }
    size_t deg = dir == BS_DIR_U ? m : n, step = dir == BS_DIR_U ? (n + 1) * NC : NC;
    size_t ncurve = dir == BS_DIR_U ? n + 1 : m + 1, cstep = dir == BS_DIR_U ? NC : (n + 1) * NC;
    double b[(BS_MAX_DEGREE + 1) * NC], g = 1.0 - f;
    for (size_t q = 0; q < ncurve; q++) {
        const double *in = net + q * cstep;
        size_t base = q * cstep;
        for (size_t k = 0; k <= deg; k++)
            for (size_t c = 0; c < NC; c++)
                b[k * NC + c] = in[k * step + c];
        for (size_t c = 0; c < NC; c++) {
            lo[base + c] = b[c];
            hi[base + deg * step + c] = b[deg * NC + c];
        }
        for (size_t r = 1; r <= deg; r++) {
            for (size_t k = 0; k + r <= deg; k++)
                for (size_t c = 0; c < NC; c++)
                    b[k * NC + c] = g * b[k * NC + c] + f * b[(k + 1) * NC + c];
            for (size_t c = 0; c < NC; c++) {
                lo[base + r * step + c] = b[c];
                hi[base + (deg - r) * step + c] = b[(deg - r) * NC + c];
            }
        }
    }
}

#endif
