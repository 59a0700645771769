/* Scattered positions and normals of polynomial bicubic patches from packed arrays, chunk by
 * chunk: the positions go straight to the caller's arrays, the regular normal rule runs over the
 * chunk's S_u and S_v vectorised into the caller's normal arrays, and only the points it does not
 * settle (and non-finite parameters) are handled one by one afterwards. Per point the operations of
 * bs_patch_eval_normal's general loop (bsi_bicubic_first_chunk, bsi_normal_block): the same bits,
 * without the copies through block buffers. */
#include "core/kernels.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define PB BSI_CHUNK
/* Points per chunk while enough remain: the per-chunk set-up of each coordinate (its net's
 * differences and their broadcasts) is then shared by more points; the last ones go in chunks of
 * PB. Every point gets the same operations whatever its chunk. */
#define PMAX (4 * BSI_CHUNK)

/* The L points (L <= PMAX) from k0 on. */
BSI_INLINE void normal_chunk(const bs_patch *p, const bsi_nscale *sc, size_t L, size_t k0,
                             const double *restrict u, const double *restrict v,
                             double *const *pos, double *const *nrm, unsigned char *kind)
{
    double zu2 = bsi_normal_floor(sc->zu), zv2 = bsi_normal_floor(sc->zv);
    double bu[4 * PMAX], bum[3 * PMAX], bv[4 * PMAX], bvm[3 * PMAX], x[PMAX], y[PMAX];
    double hu[3][PMAX], hv[3][PMAX], th[PMAX], tn[3][PMAX], flag[PMAX];
    long nbad = 0, nslow = 0;
    for (size_t k = 0; k < L; k++) {
        long ok = (fabs(u[k0 + k]) <= DBL_MAX) & (fabs(v[k0 + k]) <= DBL_MAX);
        nbad |= !ok;
        x[k] = ok ? u[k0 + k] : 0.0; /* the general loop's stand-in for a bad pair */
        y[k] = ok ? v[k0 + k] : 0.0;
    }
    bsi_weights3(L, x, bu, bum);
    bsi_weights3(L, y, bv, bvm);
    for (size_t c = 0; c < 3; c++) { /* positions not asked for go to scratch (th: written, not read) */
        // cppcheck-suppress legacyUninitvar
        double *out = pos != NULL ? pos[c] + k0 : th;
        bsi_bicubic_block(L, p->hom + c * p->nctrl, bu, bum, bv, bvm, out, hu[c], hv[c]);
    }
    double *restrict n0 = nrm != NULL ? nrm[0] + k0 : tn[0];
    double *restrict n1 = nrm != NULL ? nrm[1] + k0 : tn[1];
    double *restrict n2 = nrm != NULL ? nrm[2] + k0 : tn[2];
    for (size_t k = 0; k < L; k++) {
        bsi_rnormal r = bsi_regular_normal(hu[0][k], hu[1][k], hu[2][k], hv[0][k], hv[1][k],
                                           hv[2][k], zu2, zv2);
        n0[k] = r.n0;
        n1[k] = r.n1;
        n2[k] = r.n2;
        flag[k] = r.flag;
        nslow |= r.flag != 0.0;
    }
    if (kind != NULL)
        memset(kind + k0, BS_NORMAL_REGULAR, L);
    /* the rare points: the general rule (limit normals, poles, extreme lengths) */
    for (size_t k = 0; nslow && k < L; k++) {
        if (flag[k] == 0.0)
            continue;
        double su[3] = {hu[0][k], hu[1][k], hu[2][k]}, sv[3] = {hv[0][k], hv[1][k], hv[2][k]};
        double r[3];
        unsigned char kd = bsi_normal(p, sc, x[k], y[k], su, sv, r);
        n0[k] = r[0];
        n1[k] = r[1];
        n2[k] = r[2];
        if (kind != NULL)
            kind[k0 + k] = kd;
    }
    for (size_t k = 0; nbad && k < L; k++) {
        if (fabs(u[k0 + k]) <= DBL_MAX && fabs(v[k0 + k]) <= DBL_MAX)
            continue;
        for (size_t c = 0; pos != NULL && c < 3; c++)
            pos[c][k0 + k] = NAN;
        n0[k] = n1[k] = n2[k] = NAN;
        if (kind != NULL)
            kind[k0 + k] = BS_NORMAL_UNDEFINED;
    }
}

BSI_HOT size_t bsi_bicubic_normal_packed(const bs_patch *p, const bsi_nscale *sc, size_t n,
                                         const double *restrict u, const double *restrict v,
                                         double *const *pos, double *const *nrm,
                                         unsigned char *kind)
{
    size_t k0 = 0;
    for (; n - k0 >= PMAX; k0 += PMAX)
        normal_chunk(p, sc, PMAX, k0, u, v, pos, nrm, kind);
    for (; n - k0 >= PB; k0 += PB)
        normal_chunk(p, sc, PB, k0, u, v, pos, nrm, kind);
    return k0;
}
