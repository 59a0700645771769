/*
 * Closest points, the kernels of the bicubic 3-D patch (the teapot's, the common case),
 * polynomial and rational: the halving, the box distance and the second-order bound of
 * closest_bound.c with constant sizes, laid out so that the compiler runs them over several
 * values at once (and compiled for AVX-512, AVX2 and baseline with BSI_CPU_DISPATCH). Each
 * performs the operations of the general code, except where said, so the rounding terms of
 * closest_bound.c hold.
 */
#include "query/closest.h"

#include <float.h>
#include <math.h>

/* Halving of a bicubic 3-D net (the teapot's), the same operations as split_line: a line along
 * u is a column of rows of 4 nc doubles, one along v 4 points of nc doubles in a row, so each
 * step of de Casteljau's algorithm runs over len (4 nc or nc) contiguous values at once. */
BSI_INLINE void halve4(const double *x, size_t len, double *l, double *h)
{
    double t[4][16];
    for (size_t k = 0; k < 4; k++)
        for (size_t e = 0; e < len; e++)
            t[k][e] = x[k * len + e];
    for (size_t e = 0; e < len; e++) {
        l[e] = t[0][e];
        h[3 * len + e] = t[3][e];
    }
    for (size_t r = 1; r <= 3; r++) {
        for (size_t k = 0; k + r <= 3; k++)
            for (size_t e = 0; e < len; e++)
                t[k][e] = 0.5 * (t[k][e] + t[k + 1][e]);
        for (size_t e = 0; e < len; e++) {
            l[r * len + e] = t[0][e];
            h[(3 - r) * len + e] = t[3 - r][e];
        }
    }
}

/* The halving of a net of nc doubles a point (3 or 4, a constant once inlined). */
BSI_INLINE void split_nc(const double *src, int dir, size_t nc, double *lo, double *hi)
{
    size_t row = 4 * nc;
    if (dir == BS_DIR_U)
        halve4(src, row, lo, hi);
    else
        for (size_t i = 0; i < 4; i++)
            halve4(src + i * row, nc, lo + i * row, hi + i * row);
}

BSI_HOT void bsi_cl_split3(const double *src, int dir, double *lo, double *hi)
{
    split_nc(src, dir, 3, lo, hi);
}

BSI_HOT void bsi_cl_split4(const double *src, int dir, double *lo, double *hi)
{
    split_nc(src, dir, 4, lo, hi);
}

/* bsi_cl_region's subdivision of a net of nc doubles a point: along u the rows of 4 nc values
 * at once, along v 4 points of nc. */
BSI_INLINE void region_nc(double *net, size_t nc, const double x[4])
{
    bsi_sub_line(net, 3, 4 * nc, 4 * nc, x[0], x[1]);
    for (size_t i = 0; i < 4; i++)
        bsi_sub_line(net + i * 4 * nc, 3, nc, nc, x[2], x[3]);
}

BSI_HOT void bsi_cl_region3(double *net, const double x[4]) { region_nc(net, 3, x); }

BSI_HOT void bsi_cl_region4(double *net, const double x[4]) { region_nc(net, 4, x); }

BSI_HOT double bsi_cl_box3(const double *net) { return bsi_cl_box_gap2(net, 16, 3); }

/* The Cartesian points of a rational net as closest_bound.c's cartesian() forms them (times the
 * weight's reciprocal), then their box. */
BSI_HOT double bsi_cl_box4(const double *net)
{
    double cart[48];
    for (size_t k = 0; k < 16; k++) {
        double inv = 1.0 / net[k * 4 + 3];
        for (size_t c = 0; c < 3; c++)
            cart[k * 3 + c] = net[k * 4 + c] * inv;
    }
    return bsi_cl_box_gap2(cart, 16, 3);
}


/* The products of the planes a, b, c (the net's coordinates times the binomials) into o, summed
 * over the three before they are added in, vectorised over j'. W's are taken with the weight
 * plane and two planes of zeros (x + 0 is x: the same bits as its products alone). */
BSI_INLINE void products(double (*a)[4], double (*b)[4], double (*c)[4], double o[7][8])
{
    for (int i = 0; i < 4; i++)
        for (int i2 = i; i2 < 4; i2++) {
            double f = i2 == i ? 1.0 : 2.0;
            for (int j = 0; j < 4; j++) {
                double a0 = f * a[i][j], a1 = f * b[i][j], a2 = f * c[i][j];
                double *row = &o[i + i2][j];
                for (int j2 = 0; j2 < 4; j2++)
                    row[j2] += a0 * a[i2][j2] + a1 * b[i2][j2] + a2 * c[i2][j2];
            }
        }
}

/* The second-order bound of a bicubic 3-D polynomial net (the teapot's): the operations of the
 * general bsi_cl_fbound below on constant sizes, with N's products summed over the three
 * coordinates before they are added in (the same rounding bound: each N_kl is a sum of at most
 * 48 products), vectorised over j'. */
BSI_HOT void bsi_cl_fbound3(bsi_cl *w, const double *net, bsi_cl_bound *b)
{
    static const double b3[4] = {1.0, 3.0, 3.0, 1.0};
    static const double b6[7] = {1.0, 6.0, 15.0, 20.0, 15.0, 6.0, 1.0};
    double y[3][4][4], o[7][8] = {{0.0}}, amax = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = b3[i] * b3[j], a2 = 0.0;
            for (int c = 0; c < 3; c++) {
                double x = net[(i * 4 + j) * 3 + c];
                y[c][i][j] = s * x;
                a2 += x * x;
            }
            amax = a2 > amax ? a2 : amax;
        }
    products(y[0], y[1], y[2], o);
    double err = (double)(16 * 3 + 16) * DBL_EPSILON * amax, rel = (double)(16 + 16) * DBL_EPSILON;
    double best = INFINITY;
    size_t arg = 0;
    for (int k = 0; k < 7; k++)
        for (int l = 0; l < 7; l++) {
            double ratio = o[k][l] / (b6[k] * b6[l]);
            w->nco[k * 7 + l] = o[k][l];
            w->fco[k * 7 + l] = ratio;
            if (ratio < best) {
                best = ratio;
                arg = (size_t)k * 7 + (size_t)l;
            }
        }
    /* min (N_kl - err) is the smallest ratio minus err: the rounding of a difference is monotone */
    bsi_cl_fbound_finish(w, b, best - err, arg, err, rel);
}

/* The second-order bound of a bicubic 3-D rational net: bsi_cl_fbound's rational branch on
 * constant sizes, N's products summed as in bsi_cl_fbound3. */
BSI_HOT void bsi_cl_fbound4(bsi_cl *w, const double *net, bsi_cl_bound *b)
{
    static const double b3[4] = {1.0, 3.0, 3.0, 1.0};
    static const double b6[7] = {1.0, 6.0, 15.0, 20.0, 15.0, 6.0, 1.0};
    double y[4][4][4], o[7][8] = {{0.0}}, ow[7][8] = {{0.0}}, amax = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            const double *x = net + (size_t)(i * 4 + j) * 4;
            double s = b3[i] * b3[j], a2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
            for (int c = 0; c < 4; c++)
                y[c][i][j] = s * x[c];
            a2 = a2 / (x[3] * x[3]) * (1.0 + 8.0 * DBL_EPSILON);
            amax = a2 > amax ? a2 : amax;
        }
    double zero[4][4] = {{0.0}};
    products(y[0], y[1], y[2], o);
    products(y[3], zero, zero, ow);
    /* err, the bound on every N_kl's error e W_kl (1 + rel) of bsi_cl_fbound, taken with W_kl at
     * most 1 + rel: the weights are scaled below 1 and W_kl is an average of their products */
    double e = (double)(16 * 3 + 16) * DBL_EPSILON * amax;
    double rel = (double)(16 + 16) * DBL_EPSILON, best = INFINITY, low = INFINITY;
    double err = e * (1.0 + rel) * (1.0 + rel);
    size_t arg = 0;
    for (int k = 0; k < 7; k++)
        for (int l = 0; l < 7; l++) {
            double scale = b6[k] * b6[l], num = o[k][l] / scale, den = ow[k][l] / scale;
            double ratio = num / den, ek = e * den * (1.0 + rel), lowk = num - ek;
            w->nco[k * 7 + l] = o[k][l];
            w->wco[k * 7 + l] = ow[k][l];
            w->fco[k * 7 + l] = ratio;
            if (ratio < best) {
                best = ratio;
                arg = (size_t)k * 7 + (size_t)l;
            }
            /* den > 0: the weights served are within 2^160 of each other (bsi_cl_depth), so
             * den > 2^-323 (the largest scaled to [1/2, 1)); the divisor rounded up for a positive
             * lowk, down for a negative one */
            lowk = lowk / (den * (1.0 + copysign(rel, lowk)));
            low = lowk < low ? lowk : low;
        }
    bsi_cl_fbound_finish(w, b, low, arg, err, rel);
}

BSI_HOT int bsi_cl_slack3(const bsi_cl *w) { return bsi_cl_slack(w, 3, 3); }

/* The degree-3 basis at t and its derivatives up to order k (b[a][i]), the operations of
 * bsi_bernstein_deriv (the same bits). */
BSI_INLINE void basis3(double t, unsigned k, double b[3][4])
{
    double s = 1.0 - t, q0 = s * s, q1 = t * s + s * t, q2 = t * t;
    b[0][0] = s * q0;
    b[0][1] = t * q0 + s * q1;
    b[0][2] = t * q1 + s * q2;
    b[0][3] = t * q2;
    if (k == 0)
        return;
    b[1][3] = 3.0 * q2;
    b[1][2] = 3.0 * (q1 - q2);
    b[1][1] = 3.0 * (q0 - q1);
    b[1][0] = 3.0 * (0.0 - q0);
    double c2 = 2.0 * t, c1 = 2.0 * (s - t), c0 = 2.0 * (0.0 - s);
    b[2][3] = 3.0 * c2;
    b[2][2] = 3.0 * (c1 - c2);
    b[2][1] = 3.0 * (c0 - c1);
    b[2][0] = 3.0 * (0.0 - c0);
}

/* bsi_deriv_table's homogeneous partials of a bicubic patch (hom its nc coordinate planes) for
 * k = ka = kb (0 or 2): u contracted first, then v, in bsi_deriv_table's order (the same bits);
 * out[(a (k+1) + b) nc + c]. */
BSI_INLINE void deriv3_k(const double *hom, double u, double v, unsigned k, size_t nc, double *out)
{
    double wu[3][4], wv[3][4];
    basis3(u, k, wu);
    basis3(v, k, wv);
    for (size_t c = 0; c < nc; c++) {
        const double *net = hom + c * 16;
        for (size_t a = 0; a <= k; a++) {
            double q[4] = {-0.0, -0.0, -0.0, -0.0};
            for (size_t i = 0; i < 4; i++)
                for (size_t j = 0; j < 4; j++)
                    q[j] += wu[a][i] * net[i * 4 + j];
            for (size_t b = 0; b <= k; b++) {
                double acc = -0.0;
                for (size_t j = 0; j < 4; j++)
                    acc += wv[b][j] * q[j];
                out[(a * (k + 1) + b) * nc + c] = acc;
            }
        }
    }
}

BSI_HOT void bsi_cl_deriv3(const double *hom, double u, double v, unsigned k, double *out)
{
    if (k == 0)
        deriv3_k(hom, u, v, 0, 3, out);
    else
        deriv3_k(hom, u, v, 2, 3, out);
}

/* bsi_deriv_table's quotient rule (Leibniz on A = w S) on the homogeneous partials hd of a
 * bicubic 3-D rational patch, k = ka = kb: the same operations in the same order (the same
 * bits), the binomials C(i,a) from a table. Not specialised by k (few operations). */
static void leibniz3(const double *hd, unsigned k, double *out)
{
    static const double binom[3][3] = {{1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {1.0, 2.0, 1.0}};
    size_t k1 = (size_t)k + 1;
    double w0 = hd[3];
    for (size_t i = 0; i <= k; i++)
        for (size_t j = 0; j <= k; j++)
            for (size_t c = 0; c < 3; c++) {
                double acc = hd[(i * k1 + j) * 4 + c];
                for (size_t a = 0; a <= i; a++)
                    for (size_t b = 0; b <= j; b++)
                        if (a || b)
                            acc -= binom[i][a] * binom[j][b] * hd[(a * k1 + b) * 4 + 3] *
                                   out[((i - a) * k1 + (j - b)) * 3 + c];
                out[(i * k1 + j) * 3 + c] = acc / w0;
            }
}

BSI_HOT void bsi_cl_deriv4(const double *hom, double u, double v, unsigned k, double *out)
{
    double hd[9 * 4];
    if (k == 0) {
        deriv3_k(hom, u, v, 0, 4, hd);
        leibniz3(hd, 0, out);
    } else {
        deriv3_k(hom, u, v, 2, 4, hd);
        leibniz3(hd, 2, out);
    }
}
