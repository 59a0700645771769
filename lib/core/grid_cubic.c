/* The loops of the grid evaluator for cubic rows of polynomial 3-D patches (lib/core/eval_grid.c):
 * all three coordinates of a point formed in registers from the row's contracted coefficients and
 * written straight into packed output arrays, as doubles or, for the float twin of the grid
 * evaluator, as the same doubles rounded to float in the loop. The operations per point are those
 * of the grid's combine4 sums (and of bsi_eval_first_block), so every output has the same bits. */
#include "core/kernels.h"

/* The row's sums of degree 3 in v, kept in registers (4 columns j as one vector) until all m+1
 * rows of the net are in: per element the operations of the general contraction, i ascending
 * from -0.0 (same bits). m is a parameter so that the bicubic case gets unrolled loops. */
BSI_INLINE void contract_cubic(const bs_patch *p, size_t m, const double *bu, const double *bum,
                               int du, int dv, double *restrict q, double *restrict qu,
                               double *restrict qv)
{
    for (size_t c = 0; c < p->ncoord; c++) {
        const double *net = p->hom + c * p->nctrl;
        double a[4] = {-0.0, -0.0, -0.0, -0.0}, au[4] = {-0.0, -0.0, -0.0, -0.0};
        double av[4] = {-0.0, -0.0, -0.0, -0.0};
        /* one loop per sum, so that each is a clean vector accumulation */
#pragma GCC unroll 4
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j < 4; j++)
                a[j] += bu[i] * net[4 * i + j];
#pragma GCC unroll 4
        for (size_t i = 0; du && i < m; i++)
            for (size_t j = 0; j < 4; j++)
                au[j] += bum[i] * (net[4 * i + 4 + j] - net[4 * i + j]);
#pragma GCC unroll 4
        for (size_t i = 0; dv && i <= m; i++)
            for (size_t j = 0; j < 3; j++)
                av[j] += bu[i] * (net[4 * i + j + 1] - net[4 * i + j]);
        for (size_t j = 0; j < 4; j++) {
            q[4 * c + j] = a[j];
            qu[4 * c + j] = au[j];
            qv[4 * c + j] = av[j];
        }
    }
}

BSI_HOT void bsi_contract_cubic(const bs_patch *p, const double *bu, const double *bum, int du,
                                int dv, double *restrict q, double *restrict qu,
                                double *restrict qv)
{
    if (p->deg_u == 3)
        contract_cubic(p, 3, bu, bum, du, dv, q, qu, qv);
    else
        contract_cubic(p, p->deg_u, bu, bum, du, dv, q, qu, qv);
}

/* The column weights of the point, recomputed from its parameter rather than loaded from a
 * table: the same bits (bsi_bernstein_first uses bsi_bernstein3_first), and when the outputs are
 * bound for main memory, seven loads per point stall behind the queued stores and cost up to
 * 2.4 times the time (docs/performance.md). */
#define CUBIC_WEIGHTS(t)                                                                           \
    double cw_[4], cwm_[3];                                                                        \
    bsi_bernstein3_first(t, cw_, cwm_);                                                            \
    double w0 = cw_[0], w1 = cw_[1], w2 = cw_[2], w3 = cw_[3];                                     \
    double v0 = cwm_[0], v1 = cwm_[1], v2 = cwm_[2];                                              \
    (void)v0, (void)v1, (void)v2
#define VAL(x) (w0 * (x)[0] + w1 * (x)[1] + w2 * (x)[2] + w3 * (x)[3])
#define DV(x) (3.0 * (v0 * (x)[0] + v1 * (x)[1] + v2 * (x)[2]))

/* Both kernels for one output type T (double, or float: each double result converted once).
 * ROWS and POS_NORMAL name the functions and T is a type: none can be in parentheses. */
// NOLINTBEGIN(bugprone-macro-parentheses)
#define CUBIC_KERNELS(ROWS, POS_NORMAL, T)                                                         \
    BSI_HOT void ROWS(size_t nb, const double *restrict vcol, const double *restrict q,           \
                      const double *restrict qu, const double *restrict qv, double m,              \
                      T *restrict s0, T *restrict s1, T *restrict s2, T *restrict u0,              \
                      T *restrict u1, T *restrict u2, T *restrict d0, T *restrict d1,              \
                      T *restrict d2)                                                              \
    {                                                                                              \
        if (u0 == NULL)                                                                            \
            for (size_t b = 0; b < nb; b++) {                                                      \
                CUBIC_WEIGHTS(vcol[b]);                                                            \
                s0[b] = (T)VAL(q);                                                                 \
                s1[b] = (T)VAL(q + 4);                                                             \
                s2[b] = (T)VAL(q + 8);                                                             \
            }                                                                                      \
        else                                                                                       \
            for (size_t b = 0; b < nb; b++) {                                                      \
                CUBIC_WEIGHTS(vcol[b]);                                                            \
                s0[b] = (T)VAL(q);                                                                 \
                s1[b] = (T)VAL(q + 4);                                                             \
                s2[b] = (T)VAL(q + 8);                                                             \
                u0[b] = (T)(m * VAL(qu));                                                          \
                u1[b] = (T)(m * VAL(qu + 4));                                                      \
                u2[b] = (T)(m * VAL(qu + 8));                                                      \
                d0[b] = (T)DV(qv);                                                                 \
                d1[b] = (T)DV(qv + 4);                                                             \
                d2[b] = (T)DV(qv + 8);                                                             \
            }                                                                                      \
    }                                                                                              \
    BSI_HOT size_t POS_NORMAL(size_t nb, const double *restrict vcol, const double *restrict q,   \
                              const double *restrict qu, const double *restrict qv, double m,      \
                              double zu2, double zv2, T *restrict s0, T *restrict s1,              \
                              T *restrict s2, T *restrict n0, T *restrict n1, T *restrict n2,      \
                              double *restrict flag)                                               \
    {                                                                                              \
        size_t nflag = 0;                                                                          \
        for (size_t b = 0; b < nb; b++) {                                                          \
            CUBIC_WEIGHTS(vcol[b]);                                                                \
            s0[b] = (T)VAL(q);                                                                     \
            s1[b] = (T)VAL(q + 4);                                                                 \
            s2[b] = (T)VAL(q + 8);                                                                 \
            bsi_rnormal r = bsi_regular_normal(m * VAL(qu), m * VAL(qu + 4), m * VAL(qu + 8),      \
                                               DV(qv), DV(qv + 4), DV(qv + 8), zu2, zv2);          \
            n0[b] = (T)r.n0;                                                                       \
            n1[b] = (T)r.n1;                                                                       \
            n2[b] = (T)r.n2;                                                                       \
            flag[b] = r.flag;                                                                      \
            nflag += r.flag != 0.0;                                                                \
        }                                                                                          \
        return nflag;                                                                              \
    }
// NOLINTEND(bugprone-macro-parentheses)

CUBIC_KERNELS(bsi_cubic_rows, bsi_cubic_pos_normal, double)
CUBIC_KERNELS(bsi_cubic_rows_f32, bsi_cubic_pos_normal_f32, float)
