/*
 * Core layer, private to lib/core/: the Bernstein basis, the evaluation and derivative kernels
 * and the normal rule, shared by the files that evaluate (eval, eval_grid, deriv, normal). No
 * other layer includes this header: they evaluate through the public functions. Not installed.
 */
#ifndef BEZSURF_CORE_KERNELS_H
#define BEZSURF_CORE_KERNELS_H

#include "core/internal.h"

#include <math.h>

/* ---- Bernstein basis (lib/core/basis.c) ----
 * All by the triangular recurrence B(r,k) = (1-t) B(r-1,k) + t B(r-1,k-1), so every value is a
 * sum of non-negative terms for t in [0,1]. */

/* b[0..deg] = B(deg,i)(t). */
void bsi_bernstein(size_t deg, double t, double *b);
/* b[0..deg] = B(deg,i)(t) and, when deg > 0, bm[0..deg-1] = B(deg-1,i)(t) (the weights of the
 * first-derivative difference net). b is bit-identical to bsi_bernstein(deg, t, b). */
void bsi_bernstein_first(size_t deg, double t, double *b, double *bm);
/* bsi_bernstein_first for degree 3, written out: the operations of the recurrence without its
 * additions to 0.0 and multiplications by 1.0, which change no bit here (s = 1 - x is never -0.0,
 * so s, s*s and s*s*s are never -0.0 either, and |s| >= 2^-53 keeps s*s*s from underflowing to
 * zero), and save the grid's cubic loops three additions per point. */
BSI_INLINE void bsi_bernstein3_first(double x, double w[4], double wm[3])
{
    double s = 1.0 - x;
    double a0 = s, a1 = x;
    wm[0] = s * a0;
    wm[1] = x * a0 + s * a1;
    wm[2] = x * a1;
    w[0] = s * wm[0];
    w[1] = x * wm[0] + s * wm[1];
    w[2] = x * wm[1] + s * wm[2];
    w[3] = x * wm[2];
}
/* The weights of bsi_bernstein3_first at L parameters, point-innermost (w[i*L + k], as
 * bsi_block_weights lays them out), written out so that the loop vectorises. */
BSI_INLINE void bsi_weights3(size_t L, const double *restrict t, double *restrict w,
                             double *restrict wm)
{
    for (size_t k = 0; k < L; k++) {
        double a[4], am[3];
        bsi_bernstein3_first(t[k], a, am);
        wm[k] = am[0];
        wm[L + k] = am[1];
        wm[2 * L + k] = am[2];
        w[k] = a[0];
        w[L + k] = a[1];
        w[2 * L + k] = a[2];
        w[3 * L + k] = a[3];
    }
}
/* b[0..deg] = d^k/dt^k B(deg,i)(t): B(deg-k, .) differenced k times and scaled by deg!/(deg-k)!;
 * all zero when k > deg. */
void bsi_bernstein_deriv(size_t deg, unsigned k, double t, double *b);

/* ---- Evaluation kernels (lib/core/eval.c, lib/core/deriv.c) ---- */

/* Points per block of the scattered evaluators. Every point's arithmetic is the same whatever
 * its position in a block, so results do not depend on batch size. */
#define BSI_BLOCK ((size_t)8)

/* Parameters k0 .. k0+nb-1 (nb <= BSI_BLOCK) of a scattered call as one block: ub, vb and bad
 * get BSI_BLOCK entries; slots past nb and non-finite pairs become (0,0) with bad set for the
 * latter, so the kernels only ever see finite parameters (lib/core/eval.c). */
void bsi_load_block(const bs_cview *u, const bs_cview *v, size_t k0, size_t nb,
                    double *ub, double *vb, int *bad);

/* Bernstein weights of BSI_BLOCK parameters, point-innermost: w[i*B + k] = B(deg,i)(t[k]) and
 * wm[i*B + k] = B(deg-1,i)(t[k]) (lib/core/eval.c). The recurrence of bsi_bernstein_first, run on
 * all lanes at once with the same operations per lane, so the values are the same bits. */
void bsi_block_weights(size_t deg, const double *t, double *w, double *wm);

/* Homogeneous value h and, when first != 0, first partials hu, hv at BSI_BLOCK finite parameter
 * pairs; each output is [ncoord][BSI_BLOCK]. The u-direction is contracted first (per column j,
 * i ascending), then v (j ascending), with the derivatives taken from inline difference nets;
 * the grid evaluator repeats exactly this arithmetic. */
void bsi_eval_first_block(const bs_patch *p, const double *u, const double *v, int first,
                          double *h, double *hu, double *hv);

/* One point of one plane of a bicubic net from its weights in u (bu, bum) and v (bv, bvm): the
 * value, and the first partials when hu != NULL. This is the general loop of
 * bsi_eval_first_block with every index fixed: the same operations in the same order (same bits),
 * so that the compiler keeps everything in registers and vectorises over points. */
BSI_INLINE void bsi_bicubic_point(const double *restrict net, const double bu[4],
                                  const double bum[3], const double bv[4], const double bvm[3],
                                  double *h, double *hu, double *hv)
{
#define P(i, j) net[(i) * 4 + (j)]
#define D(i, j) (P((i) + 1, j) - P(i, j))
#define E(i, j) (P(i, (j) + 1) - P(i, j))
#define Q(j) (bu[0] * P(0, j) + bu[1] * P(1, j) + bu[2] * P(2, j) + bu[3] * P(3, j))
#define QU(j) (bum[0] * D(0, j) + bum[1] * D(1, j) + bum[2] * D(2, j))
#define QV(j) (bu[0] * E(0, j) + bu[1] * E(1, j) + bu[2] * E(2, j) + bu[3] * E(3, j))
    *h = bv[0] * Q(0) + bv[1] * Q(1) + bv[2] * Q(2) + bv[3] * Q(3);
    if (hu == NULL)
        return;
    *hu = 3.0 * (bv[0] * QU(0) + bv[1] * QU(1) + bv[2] * QU(2) + bv[3] * QU(3));
    *hv = 3.0 * (bvm[0] * QV(0) + bvm[1] * QV(1) + bvm[2] * QV(2));
#undef Q
#undef QU
#undef QV
#undef P
#undef D
#undef E
}

/* bsi_bicubic_point over a block of L lanes (weights [i*L + k]): value only when hu == NULL (two
 * loops, so each vectorises). */
BSI_INLINE void bsi_bicubic_block(size_t L, const double *restrict net, const double *restrict bu,
                                  const double *restrict bum, const double *restrict bv,
                                  const double *restrict bvm, double *restrict h,
                                  double *restrict hu, double *restrict hv)
{
    if (hu == NULL)
        for (size_t k = 0; k < L; k++) {
            double au[4] = {bu[k], bu[L + k], bu[2 * L + k], bu[3 * L + k]};
            double av[4] = {bv[k], bv[L + k], bv[2 * L + k], bv[3 * L + k]};
            bsi_bicubic_point(net, au, NULL, av, NULL, h + k, NULL, NULL);
        }
    else
        for (size_t k = 0; k < L; k++) {
            double au[4] = {bu[k], bu[L + k], bu[2 * L + k], bu[3 * L + k]};
            double av[4] = {bv[k], bv[L + k], bv[2 * L + k], bv[3 * L + k]};
            double aum[3] = {bum[k], bum[L + k], bum[2 * L + k]};
            double avm[3] = {bvm[k], bvm[L + k], bvm[2 * L + k]};
            bsi_bicubic_point(net, au, aum, av, avm, h + k, hu + k, hv + k);
        }
}

/* Points per chunk of the bicubic kernels, which share their set-up over more points. */
#define BSI_CHUNK ((size_t)32)

/* bsi_eval_first_block with first != 0 for a polynomial bicubic patch, on BSI_CHUNK finite
 * parameter pairs; outputs [dim][BSI_CHUNK]. The same arithmetic per point (same bits). */
void bsi_bicubic_first_chunk(const bs_patch *p, const double *u, const double *v, double *h,
                             double *hu, double *hv);

/* bsi_eval_first_block with first != 0 at one finite point (u, v): h, hu, hv get ncoord values
 * each, the same bits as the block and chunk paths give that point. */
void bsi_eval_first_one(const bs_patch *p, double u, double v, double *h, double *hu, double *hv);

/* Cartesian S (and S_u, S_v when su != NULL) of one point from its homogeneous values; element c
 * of h, hu, hv is at index c*stride. */
void bsi_project_first(const bs_patch *p, const double *h, const double *hu, const double *hv,
                       size_t stride, double *s, double *su, double *sv);


/* ---- Cubic rows of the grid evaluator (lib/core/grid_cubic.c) ----
 * Row u = t of a polynomial 3-D patch of degree 3 in v, from the row's coefficients along u
 * (q, qu, qv: 3 coordinates of 4, as contracted by the grid evaluator), at the nb columns vcol,
 * into packed arrays; the same operations per point as the grid's combine sums (same bits).
 * bsi_cubic_rows: positions into s0..s2 and, when u0 != NULL, S_u (scaled by m) into u0..u2
 * and S_v (by 3) into d0..d2. bsi_cubic_pos_normal: positions and the regular normal rule
 * (bsi_regular_normal) fused; flag[b] = 1.0 marks points left to bsi_normal, and their count is
 * returned. The _f32 twins store each double result rounded to float. */
/* The grid's contraction along u of one row (u-weights bu, and bum for S_u) for deg_v = 3: q, qu,
 * qv get 4 sums per coordinate, as the general contraction computes them (same bits). */
void bsi_contract_cubic(const bs_patch *p, const double *bu, const double *bum, int du, int dv,
                        double *q, double *qu, double *qv);
#define BSI_CUBIC_KERNELS(ROWS, POS_NORMAL, T)                                                      \
    void ROWS(size_t nb, const double *vcol, const double *q, const double *qu, const double *qv,  \
              double m, T *s0, T *s1, T *s2, T *u0, T *u1, T *u2, T *d0, T *d1, T *d2);            \
    size_t POS_NORMAL(size_t nb, const double *vcol, const double *q, const double *qu,            \
                      const double *qv, double m, double zu2, double zv2, T *s0, T *s1, T *s2,     \
                      T *n0, T *n1, T *n2, double *flag)
BSI_CUBIC_KERNELS(bsi_cubic_rows, bsi_cubic_pos_normal, double);
BSI_CUBIC_KERNELS(bsi_cubic_rows_f32, bsi_cubic_pos_normal_f32, float);

/* ---- Packed views ---- */

/* Element 0 of each of the k views when all are packed (stride 0 or 8), else 0. */
static inline int bsi_packed_views(const bs_view *views, size_t k, double **data)
{
    for (size_t c = 0; c < k; c++) {
        if (bsi_stride(views[c].stride) != (ptrdiff_t)sizeof(double))
            return 0;
        data[c] = views[c].data;
    }
    return 1;
}

/* ---- Normals (lib/core/normal.c) ---- */

/* The normal rule at one point from its S_u and S_v: writes nrm[3], returns the kind. */
unsigned char bsi_normal(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                         const double *su, const double *sv, double *nrm);
/* bsi_normal at nb points, the regular case vectorised: su[c][b], sv[c][b] in, nrm[c][b] and
 * kind[b] out; point b is at (u[b*ustep], v[b]). Same bits as bsi_normal point by point. */
void bsi_normal_block(const bs_patch *p, const bsi_nscale *sc, size_t nb, const double *u,
                      size_t ustep, const double *v, const double *const *su,
                      const double *const *sv, double *const *nrm, unsigned char *kind);
/* bs_patch_eval_normal of a polynomial bicubic 3-D patch from packed parameter arrays into packed
 * outputs (pos[3], nrm[3], kind; each may be NULL), in whole chunks (4 BSI_CHUNK points, then
 * BSI_CHUNK) from the caller's arrays to the caller's arrays (lib/core/normal_chunk.c). Same bits
 * as the general loop. Returns the points done, a multiple of BSI_CHUNK. */
size_t bsi_bicubic_normal_packed(const bs_patch *p, const bsi_nscale *sc, size_t n,
                                 const double *u, const double *v, double *const *pos,
                                 double *const *nrm, unsigned char *kind);
/* ---- The regular normal rule at one point (lib/core/normal.c, lib/core/eval_grid.c) ----
 * N = (S_u x S_v) / |S_u x S_v| with the fast tests of bsi_normal; flag 0.0 when settled, 1.0
 * when the point needs bsi_normal. Inline so that every vectorised caller does the same
 * operations (and gets the same bits). lo_u, lo_v: the lower bounds of |S_u|^2 and |S_v|^2 from
 * bsi_normal_floor, each test of a lower bound done once. */
/* The larger of 2^-450 (squares safe to multiply) and z^2 for a zero threshold z of bsi_nscale,
 * NaN when z^2 is, so that q > bsi_normal_floor(z) is exactly q > 2^-450 && q > z^2. */
static inline double bsi_normal_floor(double z)
{
    double z2 = z * z;
    return !(z2 <= 0x1p-450) ? z2 : 0x1p-450;
}
typedef struct bsi_rnormal {
    double n0, n1, n2, flag;
} bsi_rnormal;
static inline bsi_rnormal bsi_regular_normal(double x0, double x1, double x2, double y0,
                                             double y1, double y2, double lo_u, double lo_v)
{
    double qa = x0 * x0 + x1 * x1 + x2 * x2;
    double qb = y0 * y0 + y1 * y1 + y2 * y2;
    double c0 = x1 * y2 - x2 * y1, c1 = x2 * y0 - x0 * y2, c2 = x0 * y1 - x1 * y0;
    double qc = c0 * c0 + c1 * c1 + c2 * c2;
    long ok = (qa > lo_u) & (qa < 0x1p450) & (qb > lo_v) & (qb < 0x1p450) &
              (qc > 0x1p-60 * (qa * qb));
    double inv = 1.0 / sqrt(qc);
    bsi_rnormal r;
    r.n0 = c0 * inv;
    r.n1 = c1 * inv;
    r.n2 = c2 * inv;
    r.flag = ok ? 0.0 : 1.0;
    return r;
}

#endif
