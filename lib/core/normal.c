/* Unit normals: the regular rule S_u x S_v and the limit rule where that cross product vanishes
 * (docs/normals.md), and the scattered normal evaluator. */
#include "core/kernels.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define B BSI_BLOCK

/* A vector counts as zero below TAU times its scale; see docs/normals.md. */
#define TAU 0x1p-30
/* A Taylor coefficient counts as zero below CLEAN times the accuracy bound of its derivatives. */
#define CLEAN 4.0
/* Highest Taylor order of S_u x S_v tried along the approach direction. */
#define KMAX 6

/* min and max for the scans over a net, whose values are finite: the values of fmin and fmax,
 * without their calls. */
static inline double lower(double a, double b) { return b < a ? b : a; }
static inline double upper(double a, double b) { return b > a ? b : a; }

static double norm3(const double *a)
{
    /* Plain formula unless the squares could underflow or overflow. */
    double q = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    if (q > 0x1p-900 && q < 0x1p900)
        return sqrt(q);
    double s = fmax(fabs(a[0]), fmax(fabs(a[1]), fabs(a[2])));
    if (s == 0.0 || !isfinite(s))
        return s;
    double x = a[0] / s, y = a[1] / s, z = a[2] / s;
    return s * sqrt(x * x + y * y + z * z);
}

/* 1 for x within [2^-200, 2^200] (or 0 or not finite), else the power of two that brings x
 * near 1: products of such scaled vectors neither overflow nor underflow, and scaling by a
 * power of two changes no bit of a direction. Left at 1 in the usual range so that every
 * normal there keeps its bits. */
static double extreme_scale(double x)
{
    if (!(x > 0.0 && x <= DBL_MAX) || (x >= 0x1p-200 && x <= 0x1p200))
        return 1.0;
    int e = 0;
    (void)frexp(x, &e);
    return e > 0 ? ldexp(1.0, -e) : ldexp(ldexp(1.0, -e / 2), -e + e / 2);
}

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}


static double deriv_noise(const bs_patch *p, const bsi_nscale *sc, double r, int a, int b);

/* x^k for small k by repeated multiplication (no call to pow in the per-point paths). */
static double ipow(double x, int k)
{
    double r = 1.0;
    for (int i = 0; i < k; i++)
        r *= x;
    return r;
}

void bsi_normal_scale(const bs_patch *p, bsi_nscale *sc)
{
    /* D: diagonal of the net's bounding box; rho: weight ratio. m D bounds |S_u| of the polynomial
     * patch with the same net: the scale of the relative zero test, without rho, which would
     * make healthy derivatives of a patch with far-apart weights count as zero. */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < p->nctrl; k++)
        for (size_t c = 0; c < 3; c++) {
            lo[c] = lower(lo[c], p->ctrl[k * 3 + c]);
            hi[c] = upper(hi[c], p->ctrl[k * 3 + c]);
        }
    /* halves first: the extent of a net near DBL_MAX overflows; the scales are capped at
     * DBL_MAX, which keeps every zero test meaningful */
    double ext[3] = {0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1], 0.5 * hi[2] - 0.5 * lo[2]};
    double d = fmin(DBL_MAX, 2.0 * norm3(ext)), rho = 1.0, wmax = 1.0;
    if (p->rational) {
        double wmin = INFINITY;
        wmax = 0.0;
        for (size_t k = 0; k < p->nctrl; k++) {
            wmin = lower(wmin, p->weights[k]);
            wmax = upper(wmax, p->weights[k]);
        }
        rho = wmax / wmin;
    }
    double pmax = 0.0;
    for (size_t k = 0; k < p->nctrl; k++)
        pmax = upper(pmax, norm3(p->ctrl + 3 * k));
    sc->rho = rho;
    sc->noise = 2.0 * (double)(p->deg_u + p->deg_v + 1) * DBL_EPSILON * fmin(pmax, DBL_MAX);
    sc->lu = fmin(DBL_MAX, (double)(p->deg_u > 0 ? p->deg_u : 1) * d);
    sc->lv = fmin(DBL_MAX, (double)(p->deg_v > 0 ? p->deg_v : 1) * d);
    /* The rounding of a first derivative at (u,v) grows with r = wmax / w(u,v) <= rho, not with
     * the contract's rho^2 (which bounds every point at once): fu * r is the zero test's term. */
    sc->wmax = wmax;
    sc->fu = CLEAN * deriv_noise(p, sc, 1.0, 1, 0);
    sc->fv = CLEAN * deriv_noise(p, sc, 1.0, 0, 1);
    sc->zu = fmax(TAU * sc->lu, sc->fu * rho);
    sc->zv = fmax(TAU * sc->lv, sc->fv * rho);
}

/* The rounding bound of S^(a,b) at a point whose weight ratio wmax / w(u,v) is r (docs/normals.md):
 * noise 2^(a+b) r^(a+b) times m!/(m-a)! n!/(n-b)! for polynomial patches (exactly zero beyond the
 * degree), a! m^a b! n^b for rational ones (whose derivatives do not vanish there). The quotient
 * rule brings one factor r per order; measured below 0.2 of this up to order 4 on nets with r up
 * to 1e8. */
static double deriv_noise(const bs_patch *p, const bsi_nscale *sc, double r, int a, int b)
{
    double f = sc->noise * ipow(2.0, a + b) * ipow(r, a + b); /* 2^k exact */
    size_t m = p->deg_u > 0 ? p->deg_u : 1, n = p->deg_v > 0 ? p->deg_v : 1;
    for (int k = 0; k < a; k++)
        f *= p->rational ? (double)(k + 1) * (double)m : (double)(p->deg_u > (size_t)k ? p->deg_u - (size_t)k : 1);
    for (int k = 0; k < b; k++)
        f *= p->rational ? (double)(k + 1) * (double)n : (double)(p->deg_v > (size_t)k ? p->deg_v - (size_t)k : 1);
    return f;
}

static unsigned char unit(const double *c, double *nrm, unsigned char kind)
{
    double len = norm3(c);
    if (!(len > 0.0) || !isfinite(len)) {
        nrm[0] = nrm[1] = nrm[2] = 0.0;
        return BS_NORMAL_UNDEFINED;
    }
    for (int k = 0; k < 3; k++)
        nrm[k] = c[k] / len;
    if (!isfinite(nrm[0]) || !isfinite(nrm[1]) || !isfinite(nrm[2])) {
        nrm[0] = nrm[1] = nrm[2] = 0.0;
        return BS_NORMAL_UNDEFINED;
    }
    return kind;
}

/* Lowest non-vanishing Taylor coefficient of S_u x S_v along the line (u,v) + s (du,dv), s > 0.
 * With A_k = D^k S_u / k!, B_k = D^k S_v / k! (D = du d/du + dv d/dv) the cross product is
 * sum_K s^K c_K, c_K = sum_k A_k x B_(K-k); its direction tends to that of the first c_K that is
 * not zero relative to sum_k |A_k||B_(K-k)|. */
static unsigned char limit_normal(const bs_patch *p, const bsi_nscale *sc, double r, double u, double v, const double *a0,
                                  const double *b0, double *nrm)
{
    enum { KD = KMAX + 1 };
    double du = 0.5 - u, dv = 0.5 - v; /* towards the centre of the domain */
    double big = fmax(fabs(du), fabs(dv));
    if (big == 0.0) {
        du = dv = 1.0;
    } else {
        du /= big;
        dv /= big;
    }
    double scratch[(KD + 1) * (BS_MAX_DEGREE + 1) * 2 + (BS_MAX_DEGREE + 1) + (KD + 1) * (KD + 1) * 4];
    double tab[(KD + 1) * (KD + 1) * 3];
    double A[KD][3], Bv[KD][3], binom[KD + 1], fact = 1.0, pu[KD + 1], pv[KD + 1];
    for (int k = 0; k <= KD; k++) { /* the values of ipow(du, k), ipow(dv, k) */
        pu[k] = ipow(du, k);
        pv[k] = ipow(dv, k);
    }
    /* every A_k and B_k times sig (a power of two, 1 unless the patch's scale is extreme): the
     * tests below compare cross products with products of lengths, which that leaves alone */
    double sig = extreme_scale(fmax(sc->lu, sc->lv));
    for (int c = 0; c < 3; c++) {
        A[0][c] = a0[c] * sig;
        Bv[0][c] = b0[c] * sig;
    }
    /* Order by order, so that the usual case (the first order settles it) needs partials up to
     * total order 2 only. A table entry does not depend on the table's size, so the terms are
     * the same whichever order stops the search. */
    for (int K = 1; K < KD; K++) {
        size_t kt = (size_t)K + 2; /* the table holds S^(a,b) for a, b <= K + 1 */
        bsi_deriv_table(p, u, v, (unsigned)K + 1, (unsigned)K + 1, scratch, tab);
        fact *= K;
        binom[0] = 1.0;
        for (int a = 1; a <= K; a++)
            binom[a] = binom[a - 1] * (K - a + 1) / a;
        double na = 0.0, nb = 0.0;
        for (int a = 0; a <= K; a++) {
            double w = fabs(binom[a] * pu[a] * pv[K - a]);
            na += w * deriv_noise(p, sc, r, a + 1, K - a);
            nb += w * deriv_noise(p, sc, r, a, K - a + 1);
        }
        for (int c = 0; c < 3; c++) {
            double sa = 0.0, sb = 0.0;
            for (int a = 0; a <= K; a++) {
                double w = binom[a] * pu[a] * pv[K - a];
                sa += w * tab[((size_t)(a + 1) * kt + (size_t)(K - a)) * 3 + (size_t)c];
                sb += w * tab[((size_t)a * kt + (size_t)(K - a + 1)) * 3 + (size_t)c];
            }
            A[K][c] = sa / fact * sig;
            Bv[K][c] = sb / fact * sig;
        }
        /* A term within rounding of zero is zero: noise must not pass for a direction. */
        if (norm3(A[K]) <= CLEAN * na / fact * sig)
            A[K][0] = A[K][1] = A[K][2] = 0.0;
        if (norm3(Bv[K]) <= CLEAN * nb / fact * sig)
            Bv[K][0] = Bv[K][1] = Bv[K][2] = 0.0;

        double ck[3] = {0.0, 0.0, 0.0}, mag = 0.0;
        for (int k = 0; k <= K; k++) {
            double x[3];
            cross3(A[k], Bv[K - k], x);
            for (int c = 0; c < 3; c++)
                ck[c] += x[c];
            mag += norm3(A[k]) * norm3(Bv[K - k]);
        }
        if (!isfinite(mag))
            break;
        if (mag > 0.0 && norm3(ck) > TAU * mag)
            return unit(ck, nrm, BS_NORMAL_LIMIT);
    }
    nrm[0] = nrm[1] = nrm[2] = 0.0;
    return BS_NORMAL_UNDEFINED;
}

/* wmax / w(u,v), the weight ratio that scales the rounding of S_u and S_v at the point, in
 * [1, rho]; rho outside the domain, where w is not a convex combination of the weights. */
static double local_ratio(const bs_patch *p, const bsi_nscale *sc, double u, double v)
{
    if (!p->rational || !(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0))
        return sc->rho;
    double bu[BS_MAX_DEGREE + 1], bv[BS_MAX_DEGREE + 1], w = 0.0;
    bsi_bernstein(p->deg_u, u, bu);
    bsi_bernstein(p->deg_v, v, bv);
    for (size_t i = 0; i <= p->deg_u; i++)
        for (size_t j = 0; j <= p->deg_v; j++)
            w += bu[i] * bv[j] * p->weights[i * (p->deg_v + 1) + j];
    double r = sc->wmax / w;
    return r > 1.0 ? (r < sc->rho ? r : sc->rho) : 1.0;
}

/* Squares that can be formed and multiplied in pairs without overflow or underflow. */
static int square_safe(double q) { return q > 0x1p-450 && q < 0x1p450; }

unsigned char bsi_normal(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                         const double *su, const double *sv, double *nrm)
{
    double a0[3], b0[3], c0[3];
    /* Fast path, one square root: the usual regular point, with squared lengths and thresholds. */
    double qa = su[0] * su[0] + su[1] * su[1] + su[2] * su[2];
    double qb = sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2];
    if (square_safe(qa) && square_safe(qb) && qa > sc->zu * sc->zu && qb > sc->zv * sc->zv) {
        cross3(su, sv, c0);
        double qc = c0[0] * c0[0] + c0[1] * c0[1] + c0[2] * c0[2];
        if (qc > (TAU * TAU) * (qa * qb)) {
            double inv = 1.0 / sqrt(qc); /* one division; the unit vector is good to 2 ulp */
            for (int k = 0; k < 3; k++)
                nrm[k] = c0[k] * inv;
            return BS_NORMAL_REGULAR;
        }
    }
    /* General path: scaled lengths, zero tests, then the limit rule. */
    double lu = norm3(su), lv = norm3(sv);
    if (!isfinite(lu) || !isfinite(lv)) {
        nrm[0] = nrm[1] = nrm[2] = 0.0;
        return BS_NORMAL_UNDEFINED;
    }
    /* A derivative within rounding of zero at this point, or tiny beside its scale, is zero. */
    double r = local_ratio(p, sc, u, v);
    double zu = fmax(TAU * sc->lu, sc->fu * r), zv = fmax(TAU * sc->lv, sc->fv * r);
    for (int c = 0; c < 3; c++) {
        a0[c] = lu <= zu ? 0.0 : su[c];
        b0[c] = lv <= zv ? 0.0 : sv[c];
    }
    /* the cross product of derivatives near the overflow or underflow thresholds (coordinates
     * beyond about 1e150 or below 1e-150): of the vectors scaled by powers of two, which keeps
     * its direction and the test below */
    double ea = extreme_scale(lu), eb = extreme_scale(lv), xa[3], xb[3];
    for (int c = 0; c < 3; c++) {
        xa[c] = a0[c] * ea;
        xb[c] = b0[c] * eb;
    }
    cross3(xa, xb, c0);
    double lc = norm3(c0);
    if (lc > TAU * norm3(xa) * norm3(xb))
        return unit(c0, nrm, BS_NORMAL_REGULAR);
    return limit_normal(p, sc, r, u, v, a0, b0, nrm);
}

/* The regular rule's arithmetic for ne points (flag 1.0 where it does not settle the point). */
BSI_HOT static void regular_kernel(size_t ne, const double *restrict a0, const double *restrict a1,
                           const double *restrict a2, const double *restrict b0,
                           const double *restrict b1, const double *restrict b2, double zu2,
                           double zv2, double *restrict n0, double *restrict n1,
                           double *restrict n2, double *restrict flag)
{
    for (size_t b = 0; b < ne; b++) {
        bsi_rnormal r = bsi_regular_normal(a0[b], a1[b], a2[b], b0[b], b1[b], b2[b], zu2, zv2);
        n0[b] = r.n0;
        n1[b] = r.n1;
        n2[b] = r.n2;
        flag[b] = r.flag;
    }
}

/* The regular case of bsi_normal for nb points at once, with the same operations per point (so
 * the same bits), vectorised over the points; the points it cannot settle (a derivative too short
 * or the cross product too small, or a square out of range) go through bsi_normal one by one.
 * Point b has parameters (u[b*ustep], v[b]). */
void bsi_normal_block(const bs_patch *p, const bsi_nscale *sc, size_t nb, const double *u,
                      size_t ustep, const double *v, const double *const *su,
                      const double *const *sv, double *const *nrm, unsigned char *kind)
{
    /* Inputs and outputs are distinct arrays (callers' contract). */
    const double *restrict a0 = su[0], *restrict a1 = su[1], *restrict a2 = su[2];
    const double *restrict b0 = sv[0], *restrict b1 = sv[1], *restrict b2 = sv[2];
    double *restrict n0 = nrm[0], *restrict n1 = nrm[1], *restrict n2 = nrm[2];
    unsigned char *restrict kd = kind;
    double zu2 = bsi_normal_floor(sc->zu), zv2 = bsi_normal_floor(sc->zv);
    enum { CHUNK = 64 };
    for (size_t s0 = 0; s0 < nb; s0 += CHUNK) {
        size_t ne = nb - s0 < CHUNK ? nb - s0 : CHUNK;
        /* 1.0 marks a point for the slow path (a double flag keeps the loop vectorisable). */
        double flag[CHUNK], nslow = 0.0;
        regular_kernel(ne, a0 + s0, a1 + s0, a2 + s0, b0 + s0, b1 + s0, b2 + s0, zu2, zv2, n0 + s0,
                       n1 + s0, n2 + s0, flag);
        for (size_t k = 0; k < ne; k++)
            nslow = nslow > flag[k] ? nslow : flag[k];
        for (size_t k = 0; k < ne; k++)
            kd[s0 + k] = BS_NORMAL_REGULAR;
        for (size_t k = 0; nslow > 0.0 && k < ne; k++) {
            size_t b = s0 + k;
            if (flag[k] == 0.0)
                continue;
            double x[3] = {a0[b], a1[b], a2[b]}, y[3] = {b0[b], b1[b], b2[b]}, r[3];
            kd[b] = bsi_normal(p, sc, u[b * ustep], v[b], x, y, r);
            n0[b] = r[0];
            n1[b] = r[1];
            n2[b] = r[2];
        }
    }
}

/* nb values of coordinate c to views[c] from element idx0 on (a plain loop for packed views). */
static void put_coord(const bs_view *views, size_t c, size_t idx0, const double *x, size_t nb)
{
    if (views == NULL)
        return;
    if (bsi_stride(views[c].stride) == (ptrdiff_t)sizeof(double)) {
        double *d = (double *)views[c].data + idx0;
        for (size_t k = 0; k < nb; k++)
            d[k] = x[k];
        return;
    }
    for (size_t k = 0; k < nb; k++)
        *bsi_at(&views[c], idx0 + k) = x[k];
}

void bsi_eval_normal_one(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                         double pos[3], double nrm[3], unsigned char *kind)
{
    double h[4], hu[4], hv[4], su[3], sv[3];
    bsi_eval_first_one(p, u, v, h, hu, hv);
    bsi_project_first(p, h, hu, hv, 1, pos, su, sv);
    const double *pu[3] = {su, su + 1, su + 2}, *pv[3] = {sv, sv + 1, sv + 2};
    double *pn[3] = {nrm, nrm + 1, nrm + 2};
    bsi_normal_block(p, sc, 1, &u, 1, &v, pu, pv, pn, kind);
}

double bsi_extreme_scale(const bs_patch *p, int lo, int hi)
{
    double big = 0.0;
    for (size_t k = 0; k < p->nctrl * p->dim; k++)
        big = upper(big, fabs(p->ctrl[k]));
    if (!(big > 0.0) || (big >= ldexp(1.0, -lo) && big <= ldexp(1.0, hi)))
        return 1.0;
    int e = 0;
    (void)frexp(big, &e);
    return ldexp(1.0, -e < 1000 ? -e : 1000);
}

bs_status bsi_scaled_patch(const bs_patch *p, double sig, bs_patch **out)
{
    double *ctrl = malloc(p->nctrl * p->dim * sizeof *ctrl);
    if (ctrl == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < p->nctrl * p->dim; k++)
        ctrl[k] = p->ctrl[k] * sig;
    bs_status st = bs_patch_create(p->deg_u, p->deg_v, p->dim, ctrl, p->rational ? p->weights : NULL, out);
    free(ctrl);
    return st;
}

/* bs_patch_eval_normal of a single point (u, v) with the patch's scale sc. */
static bs_status one_normal(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                            const bs_view *pos, const bs_view *nrm, unsigned char *kind)
{
    double s[3] = {NAN, NAN, NAN}, nv[3] = {NAN, NAN, NAN};
    unsigned char kd = BS_NORMAL_UNDEFINED;
    if (isfinite(u) && isfinite(v))
        bsi_eval_normal_one(p, sc, u, v, s, nv, &kd);
    for (size_t c = 0; c < 3; c++) {
        put_coord(pos, c, 0, &s[c], 1);
        put_coord(nrm, c, 0, &nv[c], 1);
    }
    if (kind != NULL)
        kind[0] = kd;
    return BS_OK;
}

bs_status bs_patch_eval_normal(const bs_patch *p, size_t n, const bs_cview *u, const bs_cview *v,
                               const bs_view *pos, const bs_view *nrm, unsigned char *kind)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (p->dim != 3)
        return BS_ERR_DIMENSION;
    if (n == 0)
        return BS_OK;
    bs_status st;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK)
        return st;
    if ((pos && (st = bsi_check_views(pos, 3, n)) != BS_OK) ||
        (nrm && (st = bsi_check_views(nrm, 3, n)) != BS_OK))
        return st;
    double sig = bsi_extreme_scale(p, SMALL_NET, LARGE_NET);
    if (sig != 1.0) { /* normals and kinds of the scaled copy, positions of p itself */
        bs_patch *q = NULL;
        if ((st = bsi_scaled_patch(p, sig, &q)) == BS_OK)
            st = bs_patch_eval_normal(q, n, u, v, NULL, nrm, kind);
        if (st == BS_OK && pos != NULL)
            st = bs_patch_eval(p, n, u, v, pos, NULL, NULL);
        bs_patch_destroy(q);
        return st;
    }
    bsi_nscale sc;
    bsi_normal_scale(p, &sc);
    if (n == 1) /* one point: bsi_eval_normal_one, the bits of the loop below without its chunk */
        return one_normal(p, &sc, bsi_cget(u, 0), bsi_cget(v, 0), pos, nrm, kind);
    /* Polynomial bicubic patches go in chunks of BSI_CHUNK points, others in blocks of
     * BSI_BLOCK: the same arithmetic per point either way. */
    int chunked = !p->rational && p->deg_u == 3 && p->deg_v == 3;
    size_t L = chunked ? BSI_CHUNK : B, k0 = 0;
    double *op[3], *on[3];
    /* packed arrays: whole chunks straight from the caller's arrays to the caller's arrays */
    if (chunked && bsi_stride(u->stride) == (ptrdiff_t)sizeof(double) &&
        bsi_stride(v->stride) == (ptrdiff_t)sizeof(double) && (pos == NULL || bsi_packed_views(pos, 3, op)) &&
        (nrm == NULL || bsi_packed_views(nrm, 3, on)))
        k0 = bsi_bicubic_normal_packed(p, &sc, n, u->data, v->data, pos ? op : NULL, nrm ? on : NULL, kind);
    double h[4 * BSI_CHUNK], hu[4 * BSI_CHUNK], hv[4 * BSI_CHUNK];
    for (; k0 < n; k0 += L) {
        size_t nb = n - k0 < L ? n - k0 : L;
        double ub[BSI_CHUNK], vb[BSI_CHUNK];
        int bad[BSI_CHUNK] = {0}; /* filled below block by block; zero keeps the analyzer sure */
        for (size_t s = 0; s < L; s += B)
            bsi_load_block(u, v, k0 + s, nb > s ? (nb - s < B ? nb - s : B) : 0, ub + s, vb + s,
                           bad + s);
        if (chunked)
            bsi_bicubic_first_chunk(p, ub, vb, h, hu, hv);
        else
            bsi_eval_first_block(p, ub, vb, 1, h, hu, hv);
        if (p->rational)
            for (size_t k = 0; k < nb; k++) {
                double s[3], su[3], sv[3];
                bsi_project_first(p, h + k, hu + k, hv + k, L, s, su, sv);
                for (size_t c = 0; c < 3; c++) {
                    h[c * L + k] = s[c];
                    hu[c * L + k] = su[c];
                    hv[c * L + k] = sv[c];
                }
            }
        double nv[3 * BSI_CHUNK];
        unsigned char kd[BSI_CHUNK];
        const double *pu[3] = {hu, hu + L, hu + 2 * L}, *pv[3] = {hv, hv + L, hv + 2 * L};
        double *pn[3] = {nv, nv + L, nv + 2 * L};
        bsi_normal_block(p, &sc, nb, ub, 1, vb, pu, pv, pn, kd);
        for (size_t k = 0; k < nb; k++)
            if (bad[k]) {
                h[k] = h[L + k] = h[2 * L + k] = nv[k] = nv[L + k] = nv[2 * L + k] = NAN;
                kd[k] = BS_NORMAL_UNDEFINED;
            }
        for (size_t c = 0; c < 3; c++) {
            put_coord(pos, c, k0, h + c * L, nb);
            put_coord(nrm, c, k0, nv + c * L, nb);
        }
        for (size_t k = 0; kind != NULL && k < nb; k++)
            kind[k0 + k] = kd[k];
    }
    return BS_OK;
}
