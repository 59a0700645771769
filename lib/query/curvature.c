/*
 * Curvature of a patch (bezsurf/query.h): the shape operator in an orthonormal tangent frame,
 * whose eigenvalues are the principal curvatures, by chunks of points (the partials in one pass,
 * the formulas vectorised over the chunk); limit points are handed to curvature_limit.c.
 */
#include "query/internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define L BSI_PCHUNK

/* The curvature at one regular point from its partials q (S_u, S_v, S_uu, S_uv, S_vv, 3 each)
 * and unit normal nrm, into o (K, H, k_min, k_max, dmin, dmax). Branch-free, so that a loop over
 * points vectorises. With exact, hypot; else sqrt(x^2 + y^2), returning 1.0 (o unusable) where
 * its squares could underflow or overflow: the caller then takes the exact path. */
BSI_INLINE double curv_formulas(const double *q, const double *nrm, double inv_d, int exact,
                                double *o)
{
    const double *su = q, *sv = q + 3;
    double e = bsi_dot3(su, su), f = bsi_dot3(su, sv), cr[3];
    bsi_cross3(su, sv, cr);
    double w = bsi_dot3(cr, cr), rw = sqrt(w), ru = sqrt(e);
    double l = bsi_dot3(q + 6, nrm), m = bsi_dot3(q + 9, nrm), nn = bsi_dot3(q + 12, nrm);
    /* The shape operator in the frame e1 = S_u/|S_u|, e2 = N x e1 (a symmetric matrix [a b; b c]):
     * no cancellation between the principal curvatures, unlike H +- sqrt(H^2 - K). */
    double a = l / e, b = (m * e - f * l) / (e * rw), c = (f * f * l / e - 2.0 * f * m + e * nn) / w;
    double half = 0.5 * (a - c), qs = half * half + b * b;
    double mean = 0.5 * (a + c), s = exact ? hypot(half, b) : sqrt(qs);
    /* bitwise & and |: no branches in the vectorised loop */
    int bad = !exact & !(((qs > 0x1p-900) & (qs < 0x1p900)) | ((half == 0.0) & (b == 0.0)));
    /* the fundamental forms' products need |S_u| and |S_v| within 2^-200 .. 2^200 (else the
     * exact path, which scales them) */
    double g = bsi_dot3(sv, sv);
    bad |= !exact & !((e > 0x1p-400) & (e < 0x1p400) & (g > 0x1p-400) & (g < 0x1p400));
    o[0] = a * c - b * b;
    o[1] = mean;
    o[2] = mean - s;
    o[3] = mean + s;
    double e1[3] = {su[0] / ru, su[1] / ru, su[2] / ru}, e2[3];
    bsi_cross3(nrm, e1, e2);
    double scale = fabs(o[2]) + fabs(o[3]) + inv_d;
    /* umbilic or planar: every direction is principal, (dmin, dmax, N) = (e1, e2, N) */
    int umbilic = 2.0 * s <= 1e-10 * scale;
    /* The eigenvector of k_max, (k_max - c, b) or (b, k_max - a), whichever row of
     * [a - k_max, b; b, c - k_max] leaves the larger first entry (no cancellation, no trig). */
    double xa = half + s, yb = s - half; /* both arms, then selects */
    double x = a >= c ? xa : b, y = a >= c ? b : yb, ql = x * x + y * y;
    double len = exact ? hypot(x, y) : sqrt(ql), ct = x / len, st = y / len;
    bad |= !exact & !umbilic & !((ql > 0x1p-900) & (ql < 0x1p900));
    /* dmin x dmax = N, as e1 x e2 = N (written out for the vectoriser) */
    double n0 = st * e1[0] - ct * e2[0], n1 = st * e1[1] - ct * e2[1], n2 = st * e1[2] - ct * e2[2];
    double x0 = ct * e1[0] + st * e2[0], x1 = ct * e1[1] + st * e2[1], x2 = ct * e1[2] + st * e2[2];
    o[4] = umbilic ? e1[0] : n0;
    o[5] = umbilic ? e1[1] : n1;
    o[6] = umbilic ? e1[2] : n2;
    o[7] = umbilic ? e2[0] : x0;
    o[8] = umbilic ? e2[1] : x1;
    o[9] = umbilic ? e2[2] : x2;
    return bad ? 1.0 : 0.0;
}

void bsi_curv_regular(const bsi_partials *q, double inv_d, bsi_curv *out)
{
    /* Partials beyond 2^200 or below 2^-200 (coordinates past about 1e150 or under 1e-150):
     * the fundamental forms' products would overflow or underflow, so the formulas run on the
     * partials scaled by a power of two sig (lengths times sig, curvatures over sig), exact;
     * in the usual range sig = 1 and nothing changes. */
    double big = 0.0, o[10], x[15];
    for (int j = 0; j < 2; j++)
        for (int c = 0; c < 3; c++)
            big = fmax(big, fabs(q->d[j][c]));
    double sig = 1.0;
    if (big > 0.0 && big <= DBL_MAX && (big < 0x1p-200 || big > 0x1p200)) {
        int e = 0;
        (void)frexp(big, &e);
        sig = ldexp(1.0, -e);
    }
    for (int j = 0; j < 5; j++)
        for (int c = 0; c < 3; c++)
            x[3 * j + c] = q->d[j][c] * sig;
    (void)curv_formulas(x, q->nrm, inv_d / sig, 1, o);
    /* K = k_min k_max scales by sig^2 (in two steps: sig^2 may overflow), H, k_min, k_max by sig */
    o[0] = o[0] * sig * sig;
    for (int i = 1; i < 4; i++)
        o[i] *= sig;
    for (int i = 0; i < 4; i++)
        out->k[i] = o[i];
    for (int i = 0; i < 3; i++) {
        out->dmin[i] = o[4 + i];
        out->dmax[i] = o[7 + i];
    }
}

/* The fast formulas at nb points of a chunk (d, nrm as bsi_curv_partials_chunk fills them) into
 * out[i L + k]; flag[k] = 1.0 where point k needs bsi_curv_regular. */
BSI_HOT static void curv_chunk(size_t nb, const double *restrict d, const double *restrict nrm,
                               double inv_d, double *restrict out, double *restrict flag)
{
    /* written out: GCC vectorises no loop over k with inner loops in it */
#define D3(j) d[(j) * L + k], d[((j) + 1) * L + k], d[((j) + 2) * L + k]
    for (size_t k = 0; k < nb; k++) {
        double q[15] = {D3(0), D3(3), D3(6), D3(9), D3(12)}, o[10];
        double nv[3] = {nrm[k], nrm[L + k], nrm[2 * L + k]};
        flag[k] = curv_formulas(q, nv, inv_d, 0, o);
        out[k] = o[0];
        out[L + k] = o[1];
        out[2 * L + k] = o[2];
        out[3 * L + k] = o[3];
        out[4 * L + k] = o[4];
        out[5 * L + k] = o[5];
        out[6 * L + k] = o[6];
        out[7 * L + k] = o[7];
        out[8 * L + k] = o[8];
        out[9 * L + k] = o[9];
    }
#undef D3
}

void bsi_curv_gather(const double *d, const double *nrm, size_t k, bsi_partials *q)
{
    for (int j = 0; j < 5; j++)
        for (int c = 0; c < 3; c++)
            q->d[j][c] = d[(size_t)(3 * j + c) * L + k];
    for (int c = 0; c < 3; c++)
        q->nrm[c] = nrm[(size_t)c * L + k];
}

/* Diagonal of the bounding box of the control points. */
static double net_diagonal(const bs_patch *p)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < p->nctrl; k++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], p->ctrl[3 * k + (size_t)c]);
            hi[c] = fmax(hi[c], p->ctrl[3 * k + (size_t)c]);
        }
    return hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
}

/* Values x[k] to elements at[k] of a view, nf > 0 (a copy for a packed one). */
static void put_plane(const bs_view *view, const double *x, const size_t *at, size_t nf)
{
    if (bsi_stride(view->stride) == (ptrdiff_t)sizeof(double)) {
        double *dst = view->data;
        if (at[nf - 1] - at[0] == nf - 1) /* at ascends: no point left out */
            memcpy(dst + at[0], x, nf * sizeof(double));
        else
            for (size_t k = 0; k < nf; k++)
                dst[at[k]] = x[k];
        return;
    }
    for (size_t k = 0; k < nf; k++)
        *bsi_at(view, at[k]) = x[k];
}

/* Outputs of point k: the curvature, or NaN everywhere. */
static void put(const bs_view *curv, const bs_view *dmin, const bs_view *dmax, size_t k,
                const bsi_curv *c, int defined)
{
    for (int i = 0; i < 4 && curv; i++)
        *bsi_at(&curv[i], k) = defined ? c->k[i] : NAN;
    for (int i = 0; i < 3 && dmin; i++)
        *bsi_at(&dmin[i], k) = defined ? c->dmin[i] : NAN;
    for (int i = 0; i < 3 && dmax; i++)
        *bsi_at(&dmax[i], k) = defined ? c->dmax[i] : NAN;
}

bs_status bs_patch_eval_curvature(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                                  const bs_view *curv, const bs_view *dmin, const bs_view *dmax,
                                  unsigned char *kind)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (p->dim != 3)
        return BS_ERR_DIMENSION;
    if (n == 0)
        return BS_OK;
    bs_status st;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK ||
        (curv && (st = bsi_check_views(curv, 4, n)) != BS_OK) ||
        (dmin && (st = bsi_check_views(dmin, 3, n)) != BS_OK) ||
        (dmax && (st = bsi_check_views(dmax, 3, n)) != BS_OK))
        return st;
    /* A net beyond 2^64 or below 2^-64 is evaluated as its copy scaled near 1: next to collapsed
     * sides and corners the partials of the limit samples differ by 2^40 and more, and their
     * products underflowed from about 2^-200 (and overflowed from 2^236) though each point's
     * formulas are scaled (a fuzz input gave UNDEFINED at 2^-255 .. 2^-199 and a limit elsewhere) */
    double sig = bsi_extreme_scale(p, 64, 64);
    if (sig != 1.0) { /* the scaled copy's, with K times sig^2 and H, k_min, k_max times sig */
        bs_patch *q = NULL;
        if ((st = bsi_scaled_patch(p, sig, &q)) == BS_OK)
            st = bs_patch_eval_curvature(q, n, u, v, curv, dmin, dmax, kind);
        bs_patch_destroy(q);
        for (size_t k = 0; st == BS_OK && curv != NULL && k < n; k++)
            for (size_t c = 0; c < 4; c++)
                *bsi_at(&curv[c], k) = c == 0 ? *bsi_at(&curv[c], k) * sig * sig : *bsi_at(&curv[c], k) * sig;
        return st;
    }
    double inv_d = 1.0 / net_diagonal(p);
    bsi_nscale sc;
    bsi_normal_scale(p, &sc);
    for (size_t k0 = 0; k0 < n; k0 += L) {
        size_t nb = n - k0 < L ? n - k0 : L, nf = 0;
        double ub[L], vb[L];
        size_t at[L];
        for (size_t k = 0; k < nb; k++) {
            double x = bsi_cget(u, k0 + k), y = bsi_cget(v, k0 + k);
            if (isfinite(x) && isfinite(y)) {
                ub[nf] = x;
                vb[nf] = y;
                at[nf++] = k0 + k;
            } else {
                put(curv, dmin, dmax, k0 + k, NULL, 0);
                if (kind)
                    kind[k0 + k] = BS_CURV_UNDEFINED;
            }
        }
        if (nf == 0)
            continue;
        double d[15 * L], nrm[3 * L], out[10 * L], flag[L];
        unsigned char nk[L], ck[L];
        bsi_curv_partials_chunk(p, &sc, nf, ub, vb, d, nrm, nk);
        curv_chunk(nf, d, nrm, inv_d, out, flag);
        for (size_t k = 0; k < nf; k++) {
            ck[k] = BS_CURV_REGULAR;
            if (nk[k] == BS_NORMAL_REGULAR && flag[k] == 0.0)
                continue;
            /* the rare points: squares out of range, limit or undefined normals */
            bsi_curv c;
            bsi_partials q;
            bsi_curv_gather(d, nrm, k, &q);
            if (nk[k] == BS_NORMAL_REGULAR)
                bsi_curv_regular(&q, inv_d, &c);
            else
                ck[k] = nk[k] == BS_NORMAL_LIMIT
                            ? bsi_curv_limit(p, &sc, ub[k], vb[k], q.nrm, inv_d, &c)
                            : BS_CURV_UNDEFINED;
            int defined = ck[k] != BS_CURV_UNDEFINED;
            for (size_t i = 0; i < 4; i++)
                out[i * L + k] = defined ? c.k[i] : NAN;
            for (size_t i = 0; i < 3; i++) {
                out[(4 + i) * L + k] = defined ? c.dmin[i] : NAN;
                out[(7 + i) * L + k] = defined ? c.dmax[i] : NAN;
            }
        }
        for (size_t i = 0; i < 4 && curv; i++)
            put_plane(&curv[i], out + i * L, at, nf);
        for (size_t i = 0; i < 3 && dmin; i++)
            put_plane(&dmin[i], out + (4 + i) * L, at, nf);
        for (size_t i = 0; i < 3 && dmax; i++)
            put_plane(&dmax[i], out + (7 + i) * L, at, nf);
        for (size_t k = 0; kind && k < nf; k++)
            kind[at[k]] = ck[k];
    }
    return BS_OK;
}
