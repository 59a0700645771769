/* Tensor-grid evaluation: Bernstein weights once per grid column and row, the u-direction
 * contracted once per row (the row is then a degree-n curve in v per coordinate), then each point
 * is a short dot product with its column's weights, vectorised across the columns of the row and
 * written straight into packed output arrays. The arithmetic per point is exactly that of
 * bsi_eval_first_block, so grid and scattered results are bit-identical. */
#include "core/kernels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NMAX (BS_MAX_DEGREE + 1)
/* Columns handled per pass: the outputs of one row pass stay in the first-level cache. */
#define COLS ((size_t)256)

typedef struct grid_scratch {
    double *wv, *wvm;      /* [j][COLS] column weights, degree n and n-1 */
    double *q, *qu, *qv;   /* [c][j] the row contracted along u */
    double *h, *hu, *hv;   /* [c][COLS] homogeneous results of one pass */
    double *s, *su, *sv;   /* [c][COLS] Cartesian results not written in place */
    double *nrm;           /* [3][COLS] normals not written in place */
    float *f;              /* [9][COLS] float results not written in place */
    unsigned char *kind;   /* [COLS] normal kinds not written in place */
    unsigned char *badv;   /* [COLS] non-finite v */
} grid_scratch;

/* Contract the u-direction for one row, as bsi_eval_first_block does per column j (degree 3 in v
 * goes to bsi_contract_cubic instead: the same operations with the sums in registers). */
BSI_HOT static void contract_row(const bs_patch *p, const double *bu, const double *bum, int du,
                                 int dv, double *restrict q, double *restrict qu,
                                 double *restrict qv)
{
    size_t m = p->deg_u, n1 = p->deg_v + 1, n = n1 - 1;
    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double *qc = q + c * n1, *quc = qu + c * n1, *qvc = qv + c * n1;
        for (size_t j = 0; j < n1; j++)
            qc[j] = quc[j] = qvc[j] = -0.0;
        for (size_t i = 0; i <= m; i++) {
            const double *row = net + i * n1;
            double w = bu[i];
            for (size_t j = 0; j < n1; j++)
                qc[j] += w * row[j];
            if (du && i < m) {
                double wm = bum[i];
                for (size_t j = 0; j < n1; j++)
                    quc[j] += wm * (row[j + n1] - row[j]);
            }
            if (dv)
                for (size_t j = 0; j < n; j++)
                    qvc[j] += w * (row[j + 1] - row[j]);
        }
    }
}

/* dst[b] = scale * sum_j w[j][b] q[j], j ascending from -0.0 (so the first term is exact), the
 * scale applied last and only when scaled != 0. Small counts of terms are written out so that
 * the compiler keeps the sum in registers and vectorises over b. */
#define W(j) w[(j) * COLS + b]
#define COMBINE(NAME, EXPR)                                                                        \
    BSI_HOT static void NAME(size_t nb, const double *restrict w, const double *restrict q,        \
                             int scaled, double scale, double *restrict dst)                       \
    {                                                                                              \
        if (scaled)                                                                                \
            for (size_t b = 0; b < nb; b++)                                                        \
                dst[b] = scale * (EXPR);                                                           \
        else                                                                                       \
            for (size_t b = 0; b < nb; b++)                                                        \
                dst[b] = EXPR;                                                                     \
    }
COMBINE(combine1, W(0) * q[0])
COMBINE(combine2, W(0) * q[0] + W(1) * q[1])
COMBINE(combine3, W(0) * q[0] + W(1) * q[1] + W(2) * q[2])
COMBINE(combine4, W(0) * q[0] + W(1) * q[1] + W(2) * q[2] + W(3) * q[3])
COMBINE(combine5, W(0) * q[0] + W(1) * q[1] + W(2) * q[2] + W(3) * q[3] + W(4) * q[4])
#undef COMBINE
#undef W

/* Any number of terms: the same sum, accumulated in dst. */
BSI_HOT static void combine_any(size_t nt, size_t nb, const double *restrict w,
                                const double *restrict q, int scaled, double scale,
                                double *restrict dst)
{
    for (size_t b = 0; b < nb; b++)
        dst[b] = w[b] * q[0];
    for (size_t j = 1; j < nt; j++) {
        const double *wj = w + j * COLS;
        double qj = q[j];
        for (size_t b = 0; b < nb; b++)
            dst[b] += wj[b] * qj;
    }
    if (scaled)
        for (size_t b = 0; b < nb; b++)
            dst[b] = scale * dst[b];
}

static void combine(size_t nt, size_t nb, const double *w, const double *q, int scaled,
                    double scale, double *dst)
{
    switch (nt) {
    case 1: combine1(nb, w, q, scaled, scale, dst); return;
    case 2: combine2(nb, w, q, scaled, scale, dst); return;
    case 3: combine3(nb, w, q, scaled, scale, dst); return;
    case 4: combine4(nb, w, q, scaled, scale, dst); return;
    case 5: combine5(nb, w, q, scaled, scale, dst); return;
    default: combine_any(nt, nb, w, q, scaled, scale, dst); return;
    }
}

/* The outputs of one call: double views, or float views for bs_patch_eval_grid_f32 (the same
 * doubles, each rounded to float when stored). */
enum { OUT_POS, OUT_DU, OUT_DV, OUT_NRM, NOUT };

typedef struct grid_call {
    const bs_patch *p;
    const bs_view *out[NOUT];   /* double outputs; all NULL for the float twin */
    const bs_fview *fout[NOUT]; /* float outputs; all NULL for doubles */
    double *dpk[NOUT][BS_MAX_DIM]; /* data of the packed double views, else NULL */
    float *fpk[NOUT][3];           /* data of the packed float views of the cubic loops, else NULL */
    unsigned char *kind;
    int f32, wpos;              /* floats wanted; positions wanted */
    int first, normals, wdu, wdv;
    int fused; /* bsi_cubic_pos_normal applies */
    int cubic; /* bsi_cubic_rows applies */
    bsi_nscale sc;
} grid_call;

/* Where coordinate c of output o goes: straight into the caller's array when it is packed,
 * otherwise into scratch (copied out by store()). */
BSI_INLINE double *target(const grid_call *gc, int o, size_t c, size_t idx0, double *scratch)
{
    return gc->dpk[o][c] != NULL ? gc->dpk[o][c] + idx0 : scratch;
}

BSI_INLINE float *ftarget(const grid_call *gc, int o, size_t c, size_t idx0, float *scratch)
{
    return gc->fpk[o][c] != NULL ? gc->fpk[o][c] + idx0 : scratch;
}

static void copy_out(const grid_call *gc, int o, size_t c, size_t idx0, const double *src, size_t nb)
{
    const bs_view *views = gc->out[o];
    const bs_fview *fviews = gc->fout[o];
    if (views != NULL)
        for (size_t b = 0; b < nb; b++)
            *bsi_at(&views[c], idx0 + b) = src[b]; // NOLINT(clang-analyzer-core.NullDereference): src is a row of scratch or of an output, never NULL
    if (fviews != NULL)
        for (size_t b = 0; b < nb; b++)
            *bsi_fat(&fviews[c], idx0 + b) = (float)src[b]; // NOLINT(clang-analyzer-core.NullDereference): as above
}

/* Doubles of coordinate c of output o to the caller (rounded to float for the float twin), when
 * they were not written in place. */
BSI_INLINE void store(const grid_call *gc, int o, size_t c, size_t idx0, const double *src, size_t nb)
{
    if (gc->dpk[o][c] == NULL && (gc->out[o] != NULL || gc->fout[o] != NULL))
        copy_out(gc, o, c, idx0, src, nb);
}

/* Floats of coordinate c of output o (from the cubic loops), when not written in place. */
BSI_INLINE void fstore(const grid_call *gc, int o, size_t c, size_t idx0, const float *src, size_t nb)
{
    const bs_fview *fviews = gc->fout[o];
    if (gc->fpk[o][c] == NULL && fviews != NULL)
        for (size_t b = 0; b < nb; b++)
            *bsi_fat(&fviews[c], idx0 + b) = src[b];
}

/* The packed views, whose arrays the loops write directly. */
static void find_packed(grid_call *gc)
{
    for (int o = 0; o < NOUT; o++) {
        size_t k = o == OUT_NRM ? 3 : gc->p->dim;
        for (size_t c = 0; c < BS_MAX_DIM; c++) {
            const bs_view *d = gc->out[o];
            const bs_fview *f = gc->fout[o];
            gc->dpk[o][c] = d != NULL && c < k && bsi_stride(d[c].stride) == (ptrdiff_t)sizeof(double)
                                ? d[c].data : NULL;
            if (c < 3)
                gc->fpk[o][c] = f != NULL && c < k && (f[c].stride == 0 || f[c].stride == (ptrdiff_t)sizeof(float))
                                    ? f[c].data : NULL;
        }
    }
}

static bs_status check_grid(const grid_call *gc, size_t nu, const bs_cview *u, size_t nv,
                            const bs_cview *v, size_t *total)
{
    bs_status st;
    if ((st = bsi_check_cview(u, nu)) != BS_OK || (st = bsi_check_cview(v, nv)) != BS_OK)
        return st;
    if (nu > SIZE_MAX / nv)
        return BS_ERR_SIZE;
    *total = nu * nv;
    for (int o = 0; o < NOUT; o++) {
        size_t k = o == OUT_NRM ? 3 : gc->p->dim;
        if ((gc->out[o] && (st = bsi_check_views(gc->out[o], k, *total)) != BS_OK) ||
            (gc->fout[o] && (st = bsi_check_fviews(gc->fout[o], k, *total)) != BS_OK))
            return st;
    }
    return BS_OK;
}

/* row_pass for cubic rows of polynomial 3-D patches asked for positions and normals only. Points
 * with non-finite parameters are left to row_pass (gc->fused is off when there are any). */
static void fused_row(const grid_call *gc, grid_scratch *g, double t, const double *vcol,
                      size_t nb, size_t idx0)
{
    double *ps[3], *pn[3];
    float *fs[3], *fn[3];
    unsigned char *kd = gc->kind != NULL ? gc->kind + idx0 : g->kind;
    double *flag = g->hu; /* free in this pass */
    double m = (double)gc->p->deg_u, zu2 = bsi_normal_floor(gc->sc.zu);
    double zv2 = bsi_normal_floor(gc->sc.zv);
    size_t nflag;
    for (size_t c = 0; c < 3; c++) {
        ps[c] = target(gc, OUT_POS, c, idx0, g->s + c * COLS);
        pn[c] = target(gc, OUT_NRM, c, idx0, g->nrm + c * COLS);
        fs[c] = ftarget(gc, OUT_POS, c, idx0, g->f + c * COLS);
        fn[c] = ftarget(gc, OUT_NRM, c, idx0, g->f + (3 + c) * COLS);
    }
    if (gc->f32)
        nflag = bsi_cubic_pos_normal_f32(nb, vcol, g->q, g->qu, g->qv, m, zu2, zv2, fs[0], fs[1],
                                         fs[2], fn[0], fn[1], fn[2], flag);
    else
        nflag = bsi_cubic_pos_normal(nb, vcol, g->q, g->qu, g->qv, m, zu2, zv2, ps[0], ps[1],
                                     ps[2], pn[0], pn[1], pn[2], flag);
    for (size_t b = 0; b < nb; b++)
        kd[b] = BS_NORMAL_REGULAR;
    for (size_t b = 0; nflag > 0 && b < nb; b++) { /* most rows have no flagged point */
        if (flag[b] == 0.0)
            continue;
        /* the derivatives again, by the same sums, for the full rule */
        double w[4], wm[3], su[3], sv[3], r[3];
        bsi_bernstein3_first(vcol[b], w, wm); /* the column's weights, as the loop formed them */
        for (size_t c = 0; c < 3; c++) {
            const double *qu = g->qu + 4 * c, *qv = g->qv + 4 * c;
            su[c] = m * (w[0] * qu[0] + w[1] * qu[1] + w[2] * qu[2] + w[3] * qu[3]);
            sv[c] = 3.0 * (wm[0] * qv[0] + wm[1] * qv[1] + wm[2] * qv[2]);
        }
        kd[b] = bsi_normal(gc->p, &gc->sc, t, vcol[b], su, sv, r);
        for (size_t c = 0; c < 3; c++) {
            if (gc->f32)
                fn[c][b] = (float)r[c];
            else
                pn[c][b] = r[c];
        }
    }
    for (size_t c = 0; c < 3; c++) {
        if (gc->f32) {
            fstore(gc, OUT_POS, c, idx0, fs[c], nb);
            fstore(gc, OUT_NRM, c, idx0, fn[c], nb);
        } else {
            store(gc, OUT_POS, c, idx0, ps[c], nb);
            store(gc, OUT_NRM, c, idx0, pn[c], nb);
        }
    }
}

/* Coordinate c of output o (positions, S_u, S_v) of a cubic row, unrolled: per row the choice of
 * target and the copy-out then cost a few instructions each. */
#define EACH_CUBIC_OUTPUT(o, c)                                                                    \
    _Pragma("GCC unroll 3") for (int o = 0; o < 3; o++) _Pragma("GCC unroll 3") for (size_t c = 0; c < 3; c++) // NOLINT(bugprone-macro-parentheses): o and c name the loop variables

/* row_pass for cubic rows of polynomial 3-D patches asked for positions and/or first partials
 * (gc->cubic is off when a parameter is not finite). */
static void cubic_row(const grid_call *gc, grid_scratch *g, const double *vcol, size_t nb,
                      size_t idx0)
{
    double m = (double)gc->p->deg_u;
    if (gc->f32) {
        float *fo[3][3];
        EACH_CUBIC_OUTPUT(o, c)
            fo[o][c] = ftarget(gc, o, c, idx0, g->f + (3 * (size_t)o + c) * COLS);
        bsi_cubic_rows_f32(nb, vcol, g->q, g->qu, g->qv, m, fo[0][0], fo[0][1], fo[0][2],
                           gc->first ? fo[1][0] : NULL, fo[1][1], fo[1][2], fo[2][0], fo[2][1],
                           fo[2][2]);
        EACH_CUBIC_OUTPUT(o, c)
            fstore(gc, o, c, idx0, fo[o][c], nb);
        return;
    }
    double *po[3][3];
    EACH_CUBIC_OUTPUT(o, c)
        po[o][c] = target(gc, o, c, idx0, g->h + (3 * (size_t)o + c) * COLS);
    bsi_cubic_rows(nb, vcol, g->q, g->qu, g->qv, m, po[0][0], po[0][1], po[0][2],
                   gc->first ? po[1][0] : NULL, po[1][1], po[1][2], po[2][0], po[2][1], po[2][2]);
    EACH_CUBIC_OUTPUT(o, c)
        store(gc, o, c, idx0, po[o][c], nb);
}

/* One row pass: nb columns of row u = t starting at output index idx0. */
static void row_pass(const grid_call *gc, grid_scratch *g, double t, int badu, const double *vcol,
                     int anybadv, size_t nb, size_t idx0)
{
    const bs_patch *p = gc->p;
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1, dim = p->dim;
    double bu[NMAX], bum[NMAX];
    bsi_bernstein_first(m, badu ? 0.0 : t, bu, bum);
    if (n == 3)
        bsi_contract_cubic(p, bu, bum, gc->wdu, gc->wdv, g->q, g->qu, g->qv);
    else
        contract_row(p, bu, bum, gc->wdu, gc->wdv, g->q, g->qu, g->qv);
    if (gc->fused) {
        fused_row(gc, g, t, vcol, nb, idx0);
        return;
    }
    if (gc->cubic) {
        cubic_row(gc, g, vcol, nb, idx0);
        return;
    }
    int rational = p->rational, first = gc->first;
    /* Set below for every coordinate; NULL until then, so no indeterminate pointer is ever passed. */
    double *ps[BS_MAX_DIM] = {NULL}, *pu[BS_MAX_DIM] = {NULL}, *pv[BS_MAX_DIM] = {NULL};
    for (size_t c = 0; c < p->ncoord; c++) {
        /* Polynomial patches write Cartesian results directly; rational ones go through h. */
        int cart = !rational && c < dim;
        double *h = cart ? target(gc, OUT_POS, c, idx0, g->h + c * COLS) : g->h + c * COLS;
        double *hu = cart ? target(gc, OUT_DU, c, idx0, g->hu + c * COLS) : g->hu + c * COLS;
        double *hv = cart ? target(gc, OUT_DV, c, idx0, g->hv + c * COLS) : g->hv + c * COLS;
        if (gc->wpos || rational || !first)
            combine(n1, nb, g->wv, g->q + c * n1, 0, 1.0, h);
        if (first) {
            if (gc->wdu)
                combine(n1, nb, g->wv, g->qu + c * n1, 1, (double)m, hu);
            else
                memset(hu, 0, nb * sizeof *hu); /* +0.0 */
            if (gc->wdv)
                combine(n, nb, g->wvm, g->qv + c * n1, 1, (double)n, hv);
            else
                memset(hv, 0, nb * sizeof *hv);
        }
        if (cart) {
            ps[c] = h;
            pu[c] = hu;
            pv[c] = hv;
        }
    }
    if (rational) {
        /* S = A / w; S_u = (A_u - w_u S) / w (quotient rule), as bsi_project_first. */
        const double *w = g->h + dim * COLS, *wu = g->hu + dim * COLS, *wv = g->hv + dim * COLS;
        for (size_t c = 0; c < dim; c++) {
            const double *h = g->h + c * COLS, *hu = g->hu + c * COLS, *hv = g->hv + c * COLS;
            double *s = ps[c] = target(gc, OUT_POS, c, idx0, g->s + c * COLS);
            for (size_t b = 0; b < nb; b++)
                s[b] = h[b] / w[b];
            if (first) {
                double *su = pu[c] = target(gc, OUT_DU, c, idx0, g->su + c * COLS);
                double *sv = pv[c] = target(gc, OUT_DV, c, idx0, g->sv + c * COLS);
                for (size_t b = 0; b < nb; b++) {
                    su[b] = (hu[b] - wu[b] * s[b]) / w[b];
                    sv[b] = (hv[b] - wv[b] * s[b]) / w[b];
                }
            }
        }
    }
    double *pn[3] = {NULL, NULL, NULL};
    unsigned char *kd = NULL;
    if (gc->normals) {
        for (size_t c = 0; c < 3; c++)
            pn[c] = target(gc, OUT_NRM, c, idx0, g->nrm + c * COLS);
        kd = gc->kind != NULL ? gc->kind + idx0 : g->kind;
        bsi_normal_block(p, &gc->sc, nb, &t, 0, vcol, (const double *const *)pu,
                         (const double *const *)pv, pn, kd);
    }
    /* Non-finite parameters: NaN results, undefined normals. */
    if (badu || anybadv)
        for (size_t b = 0; b < nb; b++) {
            if (!badu && !g->badv[b])
                continue;
            for (size_t c = 0; c < dim; c++) {
                if (gc->wpos || rational || !first) /* then ps[c] was set above */
                    ps[c][b] = NAN; // NOLINT(clang-analyzer-core.NullDereference)
                if (first)
                    pu[c][b] = pv[c][b] = NAN; // NOLINT(clang-analyzer-core.NullDereference): set above when first
            }
            if (gc->normals) {
                pn[0][b] = pn[1][b] = pn[2][b] = NAN;
                kd[b] = BS_NORMAL_UNDEFINED;
            }
        }
    for (size_t c = 0; c < dim; c++) {
        store(gc, OUT_POS, c, idx0, ps[c], nb);
        store(gc, OUT_DU, c, idx0, pu[c], nb);
        store(gc, OUT_DV, c, idx0, pv[c], nb);
    }
    for (size_t c = 0; c < 3 && gc->normals; c++)
        store(gc, OUT_NRM, c, idx0, pn[c], nb);
}

/* Both public grid evaluators: out (doubles) or fout (floats) holds the four outputs. */
static bs_status eval_grid(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                           const bs_cview *v, const bs_view *const out[NOUT],
                           const bs_fview *const fout[NOUT], unsigned char *kind)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    int wnrm = out[OUT_NRM] != NULL || fout[OUT_NRM] != NULL;
    if ((wnrm || kind != NULL) && p->dim != 3)
        return BS_ERR_DIMENSION;
    if (nu == 0 || nv == 0)
        return BS_OK;
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1, nc = p->ncoord, total;
    grid_call gc;
    gc.p = p;
    for (int o = 0; o < NOUT; o++) {
        gc.out[o] = out[o];
        gc.fout[o] = fout[o];
    }
    bs_status st = check_grid(&gc, nu, u, nv, v, &total);
    if (st != BS_OK)
        return st;
    find_packed(&gc);
    int wdu = out[OUT_DU] != NULL || fout[OUT_DU] != NULL;
    int wdv = out[OUT_DV] != NULL || fout[OUT_DV] != NULL;
    gc.kind = kind;
    gc.f32 = fout[OUT_POS] != NULL || fout[OUT_DU] != NULL || fout[OUT_DV] != NULL ||
             fout[OUT_NRM] != NULL;
    gc.wpos = out[OUT_POS] != NULL || fout[OUT_POS] != NULL;
    gc.normals = wnrm || kind != NULL;
    gc.first = wdu || wdv || gc.normals;
    gc.wdu = gc.first && m > 0;
    gc.wdv = gc.first && n > 0;
    if (gc.normals)
        bsi_normal_scale(p, &gc.sc);

    size_t ndouble = 2 * n1 * COLS + 3 * nc * n1 + 3 * nc * COLS + 3 * nc * COLS + 3 * COLS + COLS;
    size_t nfloat = 9 * COLS;
    grid_scratch g;
    double *mem = malloc(ndouble * sizeof(double) + nfloat * sizeof(float) + 2 * COLS);
    if (mem == NULL)
        return BS_ERR_NO_MEMORY;
    g.wv = mem;
    g.wvm = g.wv + n1 * COLS;
    g.q = g.wvm + n1 * COLS;
    g.qu = g.q + nc * n1;
    g.qv = g.qu + nc * n1;
    g.h = g.qv + nc * n1;
    g.hu = g.h + nc * COLS;
    g.hv = g.hu + nc * COLS;
    g.s = g.hv + nc * COLS;
    g.su = g.s + nc * COLS;
    g.sv = g.su + nc * COLS;
    g.nrm = g.sv + nc * COLS;
    double *vcol = g.nrm + 3 * COLS;
    g.f = (float *)(void *)(vcol + COLS);
    g.kind = (unsigned char *)(g.f + nfloat);
    g.badv = g.kind + COLS;

    int anybadu = 0;
    for (size_t a = 0; a < nu; a++)
        anybadu |= !isfinite(bsi_cget(u, a));
    for (size_t b0 = 0; b0 < nv; b0 += COLS) {
        size_t nb = nv - b0 < COLS ? nv - b0 : COLS;
        int anybadv = 0;
        for (size_t b = 0; b < nb; b++) {
            double t = bsi_cget(v, b0 + b);
            g.badv[b] = (unsigned char)!isfinite(t);
            anybadv |= g.badv[b];
            vcol[b] = g.badv[b] ? 0.0 : t;
        }
        int cubic = !p->rational && p->dim == 3 && n == 3 && m > 0 && !anybadu && !anybadv;
        gc.fused = cubic && gc.normals && !wdu && !wdv;
        /* positions, or positions and first partials, of cubic rows without normals */
        gc.cubic = cubic && !gc.normals && (gc.wpos || gc.first);
        /* the column weights, but for cubic rows, which form them in their loops */
        for (size_t b = 0; b < nb && !gc.fused && !gc.cubic; b++) {
            double w[NMAX], wm[NMAX];
            bsi_bernstein_first(n, vcol[b], w, wm);
            for (size_t j = 0; j <= n; j++)
                g.wv[j * COLS + b] = w[j];
            for (size_t j = 0; j < n; j++)
                g.wvm[j * COLS + b] = wm[j];
        }
        for (size_t a = 0; a < nu; a++) {
            double t = bsi_cget(u, a);
            int badu = !isfinite(t);
            row_pass(&gc, &g, badu ? 0.0 : t, badu, vcol, anybadv, nb, a * nv + b0);
        }
    }
    free(mem);
    return BS_OK;
}

bs_status bs_patch_eval_grid(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                             const bs_cview *v, const bs_view *pos, const bs_view *du,
                             const bs_view *dv, const bs_view *nrm, unsigned char *kind)
{
    return eval_grid(p, nu, u, nv, v, (const bs_view *const[NOUT]){pos, du, dv, nrm},
                     (const bs_fview *const[NOUT]){NULL, NULL, NULL, NULL}, kind);
}

bs_status bs_patch_eval_grid_f32(const bs_patch *p, size_t nu, const bs_cview *u, size_t nv,
                                 const bs_cview *v, const bs_fview *pos, const bs_fview *du,
                                 const bs_fview *dv, const bs_fview *nrm, unsigned char *kind)
{
    return eval_grid(p, nu, u, nv, v, (const bs_view *const[NOUT]){NULL, NULL, NULL, NULL},
                     (const bs_fview *const[NOUT]){pos, du, dv, nrm}, kind);
}
