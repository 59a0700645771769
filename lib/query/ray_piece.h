/*
 * A piece of a sub-patch in a ray's frame (lib/query/ray_patch.c): its record, the arithmetic
 * the tests on it share, and Newton's search for a zero of (X1, X2) on it, started where the
 * bilinear patch of its corners meets the ray. Private to lib/query/; included by ray_patch.c
 * alone (its functions are inlined into each of that file's two cases, rational or not).
 */
#ifndef BEZSURF_QUERY_RAY_PIECE_H
#define BEZSURF_QUERY_RAY_PIECE_H

#include "query/locator.h"

#include <float.h>
#include <math.h>


#define NC 4 /* X1, X2, T, W */

/* hypot(x, y) by one square root where the squares are safe (within an ulp or so of hypot) */
static inline double norm2(double x, double y)
{
    double q = x * x + y * y;
    return q > 0x1p-1000 && q < 0x1p1000 ? sqrt(q) : hypot(x, y);
}

/* Inlined into each of the two cases of the search, rational or not (rat), so that every test
 * on rat is settled when compiling. */
#define SPECIALISE BSI_INLINE

/* x / w, as the rational nets form it; a polynomial net's weights are exactly 1 (the halvings
 * keep them so), so there it is x itself, the same bits without the division */
#define WDIV(rat, x, w) ((rat) ? (x) / (w) : (x))

/* A sub-patch waiting on the stack: its domain [s0, s0 + w] x [r0, r0 + wr] in the leaf, its
 * levels below the leaf (depth: halvings in both directions; level: all halvings), its nearest
 * t, and the slot holding its net (-1: the leaf's own). Pieces are square but next to a pole,
 * which is halved across the pole only (ray_patch.c). */
typedef struct pending {
    double s0, r0, w, wr, tlo;
    int depth, level, slot;
} pending;

/* Bernstein polynomials of degree deg at x and their derivatives. */
static inline void bernstein(size_t deg, double x, double *b, double *db)
{
    double y = 1.0 - x;
    if (deg == 3) {
        double xx = x * x, yy = y * y, xy = x * y;
        b[0] = yy * y;
        b[1] = 3.0 * xy * y;
        b[2] = 3.0 * xy * x;
        b[3] = xx * x;
        db[0] = -3.0 * yy;
        db[1] = 3.0 * (yy - 2.0 * xy);
        db[2] = 3.0 * (2.0 * xy - xx);
        db[3] = 3.0 * xx;
        return;
    }
    b[0] = 1.0;
    db[0] = 0.0;
    for (size_t r = 1; r <= deg; r++) {
        if (r == deg)
            for (size_t k = 0; k <= deg; k++)
                db[k] = (double)deg * ((k > 0 ? b[k - 1] : 0.0) - (k < deg ? b[k] : 0.0));
        b[r] = x * b[r - 1];
        for (size_t k = r - 1; k > 0; k--)
            b[k] = y * b[k] + x * b[k - 1];
        b[0] *= y;
    }
}

/* Row i of the projected net (n + 1 points) summed along r: x = (X1, X2, T, W) with the weights
 * bv (W only when rat), dx = (X1, X2) with dbv. Cubic rows written out: the same sums in the same
 * order. */
SPECIALISE void row_sums(const double *a, size_t n, int rat, const double *bv, const double *dbv,
                         double x[4], double dx[2])
{
    if (n == 3) {
        const double *b = a + NC, *c = b + NC, *d = c + NC;
        x[0] = bv[0] * a[0] + bv[1] * b[0] + bv[2] * c[0] + bv[3] * d[0];
        x[1] = bv[0] * a[1] + bv[1] * b[1] + bv[2] * c[1] + bv[3] * d[1];
        x[2] = bv[0] * a[2] + bv[1] * b[2] + bv[2] * c[2] + bv[3] * d[2];
        x[3] = rat ? bv[0] * a[3] + bv[1] * b[3] + bv[2] * c[3] + bv[3] * d[3] : 0.0;
        dx[0] = dbv[0] * a[0] + dbv[1] * b[0] + dbv[2] * c[0] + dbv[3] * d[0];
        dx[1] = dbv[0] * a[1] + dbv[1] * b[1] + dbv[2] * c[1] + dbv[3] * d[1];
        return;
    }
    x[0] = x[1] = x[2] = x[3] = dx[0] = dx[1] = 0.0;
    for (size_t j = 0; j <= n; j++) {
        const double *p = a + j * NC;
        x[0] += bv[j] * p[0];
        x[1] += bv[j] * p[1];
        x[2] += bv[j] * p[2];
        x[3] += rat ? bv[j] * p[3] : 0.0;
        dx[0] += dbv[j] * p[0];
        dx[1] += dbv[j] * p[1];
    }
}

/* The projected net at (s, r): f = (X1, X2, T, W) (W = 1 for a polynomial net), and the partials
 * of X1, X2 (all Newton needs: the zeros of X1, X2 are those of X1/W, X2/W). */
SPECIALISE void eval_body(const double *net, size_t m, size_t n, int rat, double s, double r,
                          double f[NC], double fs[2], double fr[2])
{
    double bu[BS_MAX_DEGREE + 1], dbu[BS_MAX_DEGREE + 1], bv[BS_MAX_DEGREE + 1], dbv[BS_MAX_DEGREE + 1];
    dbv[0] = dbv[1] = dbv[2] = dbv[3] = 0.0; /* all filled below; the compiler cannot tell */
    bernstein(m, s, bu, dbu);
    bernstein(n, r, bv, dbv);
    double f0 = 0.0, f1 = 0.0, f2 = 0.0, f3 = 0.0, s0 = 0.0, s1 = 0.0, r0 = 0.0, r1 = 0.0;
    for (size_t i = 0; i <= m; i++) {
        double x[4], dx[2];
        row_sums(net + i * (n + 1) * NC, n, rat, bv, dbv, x, dx);
        f0 += bu[i] * x[0];
        f1 += bu[i] * x[1];
        f2 += bu[i] * x[2];
        f3 += bu[i] * x[3];
        s0 += dbu[i] * x[0];
        s1 += dbu[i] * x[1];
        r0 += bu[i] * dx[0];
        r1 += bu[i] * dx[1];
    }
    f[0] = f0;
    f[1] = f1;
    f[2] = f2;
    f[3] = rat ? f3 : 1.0;
    fs[0] = s0;
    fs[1] = s1;
    fr[0] = r0;
    fr[1] = r1;
}

/* eval_body, compiled apart for bicubic nets (every loop of a fixed length) */
SPECIALISE void eval_net(const double *net, size_t m, size_t n, int rat, double s, double r,
                         double f[NC], double fs[2], double fr[2])
{
    if (m == 3 && n == 3)
        eval_body(net, 3, 3, rat, s, r, f, fs, fr);
    else
        eval_body(net, m, n, rat, s, r, f, fs, fr);
}

static inline double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/* Where the bilinear patch of the piece's four corners (X1, X2) / W meets the origin, as a point
 * of the leaf's domain (s, r) inside the piece; the piece's centre when there is no such point.
 * Newton's start: for a piece that is nearly flat it is within a step or two of the zero. */
SPECIALISE void bilinear_start(const double *net, size_t m, size_t n, int rat, const pending *e,
                               double *s, double *r)
{
    const double *c00 = net, *c10 = net + m * (n + 1) * NC, *c01 = net + n * NC;
    const double *c11 = net + (m * (n + 1) + n) * NC;
    double a[2] = {WDIV(rat, c00[0], c00[3]), WDIV(rat, c00[1], c00[3])};
    double b[2] = {WDIV(rat, c10[0], c10[3]), WDIV(rat, c10[1], c10[3])};
    double d[2] = {WDIV(rat, c01[0], c01[3]), WDIV(rat, c01[1], c01[3])};
    double c[2] = {WDIV(rat, c11[0], c11[3]), WDIV(rat, c11[1], c11[3])};
    /* a + u E + v F + u v G = 0 (u along s, v along r) */
    double ex = b[0] - a[0], ey = b[1] - a[1], fx = d[0] - a[0], fy = d[1] - a[1];
    double gx = a[0] - b[0] + c[0] - d[0], gy = a[1] - b[1] + c[1] - d[1], hx = -a[0], hy = -a[1];
    double k2 = cross2(gx, gy, fx, fy), k1 = cross2(ex, ey, fx, fy) + cross2(hx, hy, gx, gy);
    double k0 = cross2(hx, hy, ex, ey), u = 0.5, v = 0.5;
    if (fabs(k2) <= 1e-12 * fabs(k1))
        v = -k0 / k1;
    else {
        double disc = sqrt(k1 * k1 - 4.0 * k0 * k2), v1 = (-k1 - disc) / (2.0 * k2);
        v = v1 >= 0.0 && v1 <= 1.0 ? v1 : (-k1 + disc) / (2.0 * k2);
    }
    double dx = ex + gx * v, dy = ey + gy * v;
    u = fabs(dx) >= fabs(dy) ? (hx - fx * v) / dx : (hy - fy * v) / dy;
    /* NaN (no real root, a degenerate piece) goes to the centre */
    u = u >= 0.0 && u <= 1.0 ? u : 0.5;
    v = v >= 0.0 && v <= 1.0 ? v : 0.5;
    *s = e->s0 + u * e->w;
    *r = e->r0 + v * e->wr;
}

/* Newton (damped) on (X1, X2) inside [s0, s0 + w] x [r0, r0 + w] from (s, r): 1 when the point
 * closest to the ray found is within tol of it. Either way *s, *r, *t receive that point and g its
 * (X1, X2). */
SPECIALISE int newton(const double *net, size_t m, size_t n, int rat, const pending *e, double s,
                      double r, double floor_dist, double tol, double *s_out, double *r_out,
                      double *t_out, double g[2])
{
    double pad = e->w * 0x1p-30, padr = e->wr * 0x1p-30;
    double slo = greater(0.0, e->s0 - pad), shi = lesser(1.0, e->s0 + e->w + pad);
    double rlo = greater(0.0, e->r0 - padr), rhi = lesser(1.0, e->r0 + e->wr + padr);
    double best = INFINITY;
    int worse = 0; /* steps in a row that found nothing nearer */
    *s_out = s;
    *r_out = r;
    *t_out = INFINITY;
    for (int it = 0; it < 24; it++) {
        double f[NC], fs[2], fr[2];
        eval_net(net, m, n, rat, s, r, f, fs, fr);
        double dist = WDIV(rat, norm2(f[0], f[1]), f[3]);
        if (dist < best) {
            worse = dist < 0.5 * best ? 0 : worse + 1;
            best = dist;
            *s_out = s;
            *r_out = r;
            *t_out = WDIV(rat, f[2], f[3]);
            g[0] = f[0];
            g[1] = f[1];
        }
        else
            worse++;
        if (!(dist > floor_dist) || worse >= 4) /* converged, or no longer converging */
            break;
        /* J step = -f where J is clearly regular (its columns more than about 1e-10 rad from
         * parallel; the 1-norms bound the lengths, without square roots): next to a pole X_s
         * and X_r may be nearly parallel and very different in size, where the damping below,
         * relative to the larger, would stall the step along the smaller; else
         * (J^T J + lambda I) step = -J^T f, finite also where X_r vanishes */
        double dj = fs[0] * fr[1] - fs[1] * fr[0], ds = 0.0, dr = 0.0;
        int full = fabs(dj) > 1e-10 * (fabs(fs[0]) + fabs(fs[1])) * (fabs(fr[0]) + fabs(fr[1])) && isfinite(dj);
        if (full) {
            ds = -(fr[1] * f[0] - fr[0] * f[1]) / dj;
            dr = -(fs[0] * f[1] - fs[1] * f[0]) / dj;
            /* a step out of the piece is the damped one: where the map is nearly singular (a
             * sliver of a surface, thinner than the accepted distance of a hit) the full step
             * reaches for a zero far away and would be cut short at a corner, while the damped
             * one finds the point of the piece nearest to the ray */
            full = s + ds >= slo && s + ds <= shi && r + dr >= rlo && r + dr <= rhi;
        }
        if (!full) {
            double a11 = fs[0] * fs[0] + fs[1] * fs[1], a12 = fs[0] * fr[0] + fs[1] * fr[1];
            double a22 = fr[0] * fr[0] + fr[1] * fr[1];
            double g1 = fs[0] * f[0] + fs[1] * f[1], g2 = fr[0] * f[0] + fr[1] * f[1];
            double lambda = 1e-13 * (a11 + a22) + DBL_MIN;
            a11 += lambda;
            a22 += lambda;
            double det = a11 * a22 - a12 * a12;
            if (!(det > 0.0) || !isfinite(det))
                break;
            ds = -(a22 * g1 - a12 * g2) / det;
            dr = -(a11 * g2 - a12 * g1) / det;
        }
        /* as fmin(shi, fmax(slo, x)): a NaN step goes to slo */
        double s1 = lesser(greater(s + ds, slo), shi), r1 = lesser(greater(r + dr, rlo), rhi);
        if (s1 == s && r1 == r)
            break;
        s = s1;
        r = r1;
    }
    return best <= tol;
}


#endif
