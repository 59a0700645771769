/*
 * The partials of a curvature (S_u, S_v, S_uu, S_uv, S_vv) of a 3-D patch at a chunk of points
 * in one pass, with the normal rule on its S_u and S_v: per column of the net the u direction is
 * contracted once per point for the first and second differences, then v. S_u and S_v are summed
 * exactly as bsi_eval_first_block and the bicubic kernels sum them (same bits), so the normal and
 * its kind are those of bs_patch_eval_normal. Rational patches take the same sums on the
 * homogeneous planes (w x, w y, w z, w), the values too, and then the quotient rule once per
 * point; S_u and S_v by bsi_project_first's operations.
 */
#include "core/kernels.h"

#define L BSI_PCHUNK
#define B BSI_BLOCK
#define NMAX (BS_MAX_DEGREE + 1)

/* One plane of a bicubic net at one point: out[0..4] = S_u, S_v, S_uu, S_uv, S_vv, out[5] the
 * value. The value, S_u and S_v are the sums of bsi_bicubic_point (lib/core/kernels.h) term for term. */
BSI_INLINE void bicubic2_point(const double *restrict net, const double bu[4],
                               const double bum[3], const double bumm[2], const double bv[4],
                               const double bvm[3], const double bvmm[2], double out[6])
{
#define P(i, j) net[(i) * 4 + (j)]
#define D(i, j) (P((i) + 1, j) - P(i, j))
#define E(i, j) (P(i, (j) + 1) - P(i, j))
#define QU(j) (bum[0] * D(0, j) + bum[1] * D(1, j) + bum[2] * D(2, j))
#define QV(j) (bu[0] * E(0, j) + bu[1] * E(1, j) + bu[2] * E(2, j) + bu[3] * E(3, j))
#define QUU(j) (bumm[0] * (D(1, j) - D(0, j)) + bumm[1] * (D(2, j) - D(1, j)))
#define Q(j) (bu[0] * P(0, j) + bu[1] * P(1, j) + bu[2] * P(2, j) + bu[3] * P(3, j))
    double qu0 = QU(0), qu1 = QU(1), qu2 = QU(2), qu3 = QU(3), qv0 = QV(0), qv1 = QV(1), qv2 = QV(2);
    out[0] = 3.0 * (bv[0] * qu0 + bv[1] * qu1 + bv[2] * qu2 + bv[3] * qu3);
    out[1] = 3.0 * (bvm[0] * qv0 + bvm[1] * qv1 + bvm[2] * qv2);
    out[2] = 6.0 * (bv[0] * QUU(0) + bv[1] * QUU(1) + bv[2] * QUU(2) + bv[3] * QUU(3));
    out[3] = 9.0 * (bvm[0] * (qu1 - qu0) + bvm[1] * (qu2 - qu1) + bvm[2] * (qu3 - qu2));
    out[4] = 6.0 * (bvmm[0] * (qv1 - qv0) + bvmm[1] * (qv2 - qv1));
    out[5] = bv[0] * Q(0) + bv[1] * Q(1) + bv[2] * Q(2) + bv[3] * Q(3);
#undef Q
#undef QUU
#undef QU
#undef QV
#undef P
#undef D
#undef E
}

/* Weights of degree 3, 2 (as the bicubic evaluators compute them) and 1 at L parameters. */
BSI_INLINE void weights3_second(const double *restrict t, double *restrict w,
                                double *restrict wm, double *restrict wmm)
{
    bsi_weights3(L, t, w, wm);
    for (size_t k = 0; k < L; k++) {
        wmm[k] = 1.0 - t[k];
        wmm[L + k] = t[k];
    }
}

/* One plane of a bicubic net at the L points of a chunk, partial j into the plane o + j*js L,
 * with value != 0 the value into h (a constant at each call: no test in the vectorised loop). */
BSI_INLINE void bicubic_plane(const double *restrict plane, const double *restrict bu,
                              const double *restrict bum, const double *restrict bumm,
                              const double *restrict bv, const double *restrict bvm,
                              const double *restrict bvmm, size_t js, double *restrict o,
                              int value, double *restrict h)
{
    double net[16]; /* a local copy: no run-time alias checks against o */
    for (size_t i = 0; i < 16; i++)
        net[i] = plane[i];
    for (size_t k = 0; k < L; k++) {
        double au[4] = {bu[k], bu[L + k], bu[2 * L + k], bu[3 * L + k]};
        double av[4] = {bv[k], bv[L + k], bv[2 * L + k], bv[3 * L + k]};
        double aum[3] = {bum[k], bum[L + k], bum[2 * L + k]};
        double avm[3] = {bvm[k], bvm[L + k], bvm[2 * L + k]};
        double aumm[2] = {bumm[k], bumm[L + k]}, avmm[2] = {bvmm[k], bvmm[L + k]};
        double r[6];
        bicubic2_point(net, au, aum, aumm, av, avm, avmm, r);
        o[k] = r[0];
        o[js * L + k] = r[1];
        o[2 * js * L + k] = r[2];
        o[3 * js * L + k] = r[3];
        o[4 * js * L + k] = r[4];
        if (value)
            h[k] = r[5];
    }
}

BSI_HOT static void bicubic_chunk(const bs_patch *p, const double *u, const double *v, double *d)
{
    double bu[4 * L], bum[3 * L], bumm[2 * L], bv[4 * L], bvm[3 * L], bvmm[2 * L];
    weights3_second(u, bu, bum, bumm);
    weights3_second(v, bv, bvm, bvmm);
    for (size_t c = 0; c < 3; c++)
        bicubic_plane(p->hom + c * 16, bu, bum, bumm, bv, bvm, bvmm, 3, d + c * L, 0, NULL);
}

/* The four homogeneous planes of a rational bicubic net: values h[c L + k], partial j of plane c
 * at hd[(4 j + c) L + k]. */
BSI_HOT static void bicubic_rational_chunk(const bs_patch *p, const double *u, const double *v,
                                           double *h, double *hd)
{
    double bu[4 * L], bum[3 * L], bumm[2 * L], bv[4 * L], bvm[3 * L], bvmm[2 * L];
    weights3_second(u, bu, bum, bumm);
    weights3_second(v, bv, bvm, bvmm);
    for (size_t c = 0; c < 4; c++)
        bicubic_plane(p->hom + c * 16, bu, bum, bumm, bv, bvm, bvmm, 4, hd + c * L, 1, h + c * L);
}

/* Any degrees, on B points from element k0 of the chunk: partial j of plane c (c < nc) into
 * d[(js j + c) L + k0 + k], the value into h[c L + k0 + k] unless h is NULL. The value, S_u and
 * S_v: the accumulators of bsi_eval_first_block, in its order (-0.0 + x is x, so the sums match
 * the written-out ones). */
BSI_INLINE void general_body(const bs_patch *p, const double *u, const double *v, size_t k0,
                             size_t nc, size_t js, double *d, double *h)
{
    size_t m = p->deg_u, n = p->deg_v, n1 = n + 1;
    double bu[NMAX * B], bum[NMAX * B], bumm[NMAX * B], bv[NMAX * B], bvm[NMAX * B],
        bvmm[NMAX * B];
    bsi_block_weights(m, u + k0, bu, bum);
    bsi_block_weights(n, v + k0, bv, bvm);
    /* degrees m-2 and n-2 (their companions of degree m-1, n-1 again, into scratch) */
    double tmp[NMAX * B];
    if (m >= 2)
        bsi_block_weights(m - 1, u + k0, tmp, bumm);
    if (n >= 2)
        bsi_block_weights(n - 1, v + k0, tmp, bvmm);
    for (size_t c = 0; c < nc; c++) {
        const double *net = p->hom + c * p->nctrl;
        double au[B], av[B], auu[B], auv[B], avv[B], pu[B], pv[B], a0[B];
        for (size_t k = 0; k < B; k++)
            au[k] = av[k] = auu[k] = auv[k] = avv[k] = pu[k] = pv[k] = a0[k] = -0.0;
        for (size_t j = 0; j <= n; j++) {
            double qu[B], qv[B], quu[B], q0[B];
            for (size_t k = 0; k < B; k++)
                qu[k] = qv[k] = quu[k] = q0[k] = -0.0;
            for (size_t i = 0; i <= m; i++) {
                double pij = net[i * n1 + j];
                double e = j < n ? net[i * n1 + j + 1] - pij : 0.0;
                double du = i < m ? net[(i + 1) * n1 + j] - pij : 0.0;
                double duu = i + 1 < m ? net[(i + 2) * n1 + j] - net[(i + 1) * n1 + j] - du : 0.0;
                for (size_t k = 0; k < B; k++)
                    qv[k] += bu[i * B + k] * e;
                if (h != NULL)
                    for (size_t k = 0; k < B; k++)
                        q0[k] += bu[i * B + k] * pij;
                if (i < m)
                    for (size_t k = 0; k < B; k++)
                        qu[k] += bum[i * B + k] * du;
                if (i + 1 < m)
                    for (size_t k = 0; k < B; k++)
                        quu[k] += bumm[i * B + k] * duu;
            }
            for (size_t k = 0; k < B; k++) {
                au[k] += bv[j * B + k] * qu[k];
                auu[k] += bv[j * B + k] * quu[k];
            }
            if (h != NULL)
                for (size_t k = 0; k < B; k++)
                    a0[k] += bv[j * B + k] * q0[k];
            if (j < n)
                for (size_t k = 0; k < B; k++)
                    av[k] += bvm[j * B + k] * qv[k];
            if (j > 0) /* the differences in v of the columns' sums */
                for (size_t k = 0; k < B; k++)
                    auv[k] += bvm[(j - 1) * B + k] * (qu[k] - pu[k]);
            if (j > 0 && j < n)
                for (size_t k = 0; k < B; k++)
                    avv[k] += bvmm[(j - 1) * B + k] * (qv[k] - pv[k]);
            for (size_t k = 0; k < B; k++) {
                pu[k] = qu[k];
                pv[k] = qv[k];
            }
        }
        double fm = (double)m, fn = (double)n;
        for (size_t k = 0; k < B; k++) {
            d[(0 + c) * L + k0 + k] = m > 0 ? fm * au[k] : 0.0;
            d[(js + c) * L + k0 + k] = n > 0 ? fn * av[k] : 0.0;
            d[(2 * js + c) * L + k0 + k] = m > 1 ? fm * (fm - 1.0) * auu[k] : 0.0;
            d[(3 * js + c) * L + k0 + k] = m > 0 && n > 0 ? fm * fn * auv[k] : 0.0;
            d[(4 * js + c) * L + k0 + k] = n > 1 ? fn * (fn - 1.0) * avv[k] : 0.0;
        }
        for (size_t k = 0; h != NULL && k < B; k++)
            h[c * L + k0 + k] = a0[k];
    }
}

BSI_HOT static void general_block(const bs_patch *p, const double *u, const double *v,
                                  size_t k0, double *d)
{
    general_body(p, u, v, k0, 3, 3, d, NULL);
}

/* The four homogeneous planes of a rational net, laid out as bicubic_rational_chunk's. */
BSI_HOT static void general_rational_block(const bs_patch *p, const double *u, const double *v,
                                           size_t k0, double *h, double *hd)
{
    general_body(p, u, v, k0, 4, 4, hd, h);
}

/* One coordinate of the quotient rule at one point: x the values (A, A_u, A_v, A_uu, A_uv, A_vv)
 * of its plane, w those of the weight plane; o the partials of S. S_u and S_v by
 * bsi_project_first's operations (the normal's bits). */
BSI_INLINE void quotient(const double x[6], const double w[6], double o[5])
{
    double s = x[0] / w[0];
    double su = (x[1] - w[1] * s) / w[0], sv = (x[2] - w[2] * s) / w[0];
    o[0] = su;
    o[1] = sv;
    o[2] = (x[3] - 2.0 * w[1] * su - w[3] * s) / w[0];
    o[3] = (x[4] - w[2] * su - w[1] * sv - w[4] * s) / w[0];
    o[4] = (x[5] - 2.0 * w[2] * sv - w[5] * s) / w[0];
}

/* The partials of S (layout of bsi_curv_partials_chunk) from the homogeneous ones at the L
 * points of a chunk, vectorised over the points. */
BSI_HOT static void rational_project(const double *restrict h, const double *restrict hd,
                                     double *restrict d)
{
#define HOM(c) {h[(c) * L + k], hd[(c) * L + k], hd[(4 + (c)) * L + k], hd[(8 + (c)) * L + k], \
                hd[(12 + (c)) * L + k], hd[(16 + (c)) * L + k]}
#define PUT(c) d[(c) * L + k] = o[0], d[(3 + (c)) * L + k] = o[1], d[(6 + (c)) * L + k] = o[2], \
               d[(9 + (c)) * L + k] = o[3], d[(12 + (c)) * L + k] = o[4]
    for (size_t k = 0; k < L; k++) {
        double w[6] = HOM(3), x0[6] = HOM(0), x1[6] = HOM(1), x2[6] = HOM(2), o[5];
        quotient(x0, w, o);
        PUT(0);
        quotient(x1, w, o);
        PUT(1);
        quotient(x2, w, o);
        PUT(2);
    }
#undef HOM
#undef PUT
}

void bsi_curv_partials_chunk(const bs_patch *p, const bsi_nscale *sc, size_t nb, const double *u,
                             const double *v, double *d, double *nrm, unsigned char *kind)
{
    double ub[L], vb[L]; /* the points, padded with (0,0) */
    for (size_t k = 0; k < L; k++) {
        ub[k] = k < nb ? u[k] : 0.0;
        vb[k] = k < nb ? v[k] : 0.0;
    }
    if (p->rational) {
        double h[4 * L], hd[20 * L];
        if (p->deg_u == 3 && p->deg_v == 3)
            bicubic_rational_chunk(p, ub, vb, h, hd);
        else
            for (size_t k0 = 0; k0 < L; k0 += B)
                general_rational_block(p, ub, vb, k0, h, hd);
        rational_project(h, hd, d);
    } else if (p->deg_u == 3 && p->deg_v == 3)
        bicubic_chunk(p, ub, vb, d);
    else
        for (size_t k0 = 0; k0 < L; k0 += B)
            general_block(p, ub, vb, k0, d);
    const double *su[3] = {d, d + L, d + 2 * L}, *sv[3] = {d + 3 * L, d + 4 * L, d + 5 * L};
    double *pn[3] = {nrm, nrm + L, nrm + 2 * L};
    bsi_normal_block(p, sc, nb, ub, 1, vb, su, sv, pn, kind);
}
