/*
 * Curvature at limit points (collapsed edges, poles): the fundamental forms degenerate there, so
 * the curvature is taken as its limit along the line towards the domain centre. Along that line
 * it is an analytic function of the distance h wherever the limit exists, so samples at
 * h = 2^-3 .. 2^-10 (regular points) are extrapolated to h = 0 by Richardson's scheme; the
 * difference between the last two orders of the scheme measures the error. Where the curvature
 * still changes fast at those distances (on the teapot's collapsed edges it moves by 0.14 from
 * h = 2^-3 to 2^-10, and is nearly linear in h only below), the samples are taken nearer:
 * h = 2^-8 .. 2^-15, then 2^-13 .. 2^-20 (the regular rule stays accurate there: its shape
 * operator is formed in an orthonormal tangent frame). A limit that settles in none of them (a
 * cone's apex, where the curvature grows like 1/h) is reported undefined.
 */
#include "query/internal.h"

#include <math.h>

#define LEVELS 8
#define WINDOWS 3 /* sample windows, each 5 halvings nearer than the last */
#define LIMIT_TOL 1e-7 /* extrapolation error accepted, relative to |k_min| + |k_max| + 1/D */

/* Richardson extrapolation to h = 0 of f[j] = f(h0 2^-j), j < LEVELS; *err: the estimate's
 * distance to the previous orders. */
static double extrapolate(const double *f, double *err)
{
    double t[LEVELS][LEVELS];
    for (int j = 0; j < LEVELS; j++) {
        t[j][0] = f[j];
        for (int k = 1; k <= j; k++)
            t[j][k] = t[j][k - 1] + (t[j][k - 1] - t[j - 1][k - 1]) / (ldexp(1.0, k) - 1.0);
    }
    double best = t[LEVELS - 1][LEVELS - 1];
    *err = fabs(best - t[LEVELS - 1][LEVELS - 2]) + fabs(best - t[LEVELS - 2][LEVELS - 2]);
    return best;
}

/* Unit a, or 0 if a is (numerically) zero against the scale len. */
static int unit3(const double *a, double len, double *out)
{
    double n = sqrt(bsi_dot3(a, a));
    if (!(n > 1e-12 * len))
        return 0;
    for (int i = 0; i < 3; i++)
        out[i] = a[i] / n;
    return 1;
}

/* dmin from a tangent estimate t (projected onto the plane of nrm), dmax = nrm x dmin. */
static int frame(const double *t, const double *nrm, bsi_curv *out)
{
    double p[3], tn = bsi_dot3(t, nrm);
    for (int i = 0; i < 3; i++)
        p[i] = t[i] - tn * nrm[i];
    if (!unit3(p, 1.0, out->dmin))
        return 0;
    bsi_cross3(nrm, out->dmin, out->dmax);
    return 1;
}

/* The principal curvatures k[2] extrapolated from samples at h = 2^-first .. 2^-(first + 7)
 * along the line (du, dv) from (u, v), and the samples c[]: 1 when they settle, else 0. */
static int limit_from(const bs_patch *p, const bsi_nscale *sc, double u, double v, double du, double dv, int first,
                      double inv_d, bsi_curv *c, double *k)
{
    double us[LEVELS], vs[LEVELS];
    for (int j = 0; j < LEVELS; j++) {
        double h = ldexp(1.0, -(first + j));
        us[j] = u + h * du;
        vs[j] = v + h * dv;
    }
    double d[15 * BSI_PCHUNK], nv[3 * BSI_PCHUNK];
    unsigned char nk[BSI_PCHUNK];
    bsi_curv_partials_chunk(p, sc, LEVELS, us, vs, d, nv, nk);
    for (int j = 0; j < LEVELS; j++) {
        if (nk[j] != BS_NORMAL_REGULAR)
            return 0;
        bsi_partials q;
        bsi_curv_gather(d, nv, (size_t)j, &q);
        bsi_curv_regular(&q, inv_d, &c[j]);
        /* principal directions are lines: keep each sample's sign next to the first's */
        double smin = bsi_dot3(c[j].dmin, c[0].dmin) < 0.0 ? -1.0 : 1.0;
        for (int i = 0; i < 3; i++)
            c[j].dmin[i] *= smin;
    }
    double f[LEVELS], err[2];
    for (int i = 0; i < 2; i++) { /* k_min, k_max */
        for (int j = 0; j < LEVELS; j++)
            f[j] = c[j].k[2 + i];
        k[i] = extrapolate(f, &err[i]);
    }
    double scale = fabs(k[0]) + fabs(k[1]) + inv_d;
    return err[0] <= LIMIT_TOL * scale && err[1] <= LIMIT_TOL * scale;
}

unsigned char bsi_curv_limit(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                             const double nrm[3], double inv_d, bsi_curv *out)
{
    double du = 0.5 - u, dv = 0.5 - v;
    if (du == 0.0 && dv == 0.0)
        return BS_CURV_UNDEFINED; /* the centre itself: no line to follow */
    bsi_curv c[LEVELS];
    double k[2];
    int settled = 0;
    for (int w = 0; w < WINDOWS && !settled; w++)
        settled = limit_from(p, sc, u, v, du, dv, 3 + 5 * w, inv_d, c, k);
    if (!settled)
        return BS_CURV_UNDEFINED; /* no finite limit, or none found */
    double f[LEVELS], scale = fabs(k[0]) + fabs(k[1]) + inv_d;
    out->k[0] = k[0] * k[1];
    out->k[1] = 0.5 * (k[0] + k[1]);
    out->k[2] = fmin(k[0], k[1]);
    out->k[3] = fmax(k[0], k[1]);
    /* Umbilic at the accuracy limits reach: the rule's directions from the point's own partials
     * (S_u made unit, S_v where S_u vanishes); else the extrapolated direction of k_min. */
    double t[3];
    if (out->k[3] - out->k[2] <= 10.0 * LIMIT_TOL * scale) {
        bsi_partials here;
        double d[15 * BSI_PCHUNK], nv[3 * BSI_PCHUNK];
        unsigned char nk[BSI_PCHUNK];
        bsi_curv_partials_chunk(p, sc, 1, &u, &v, d, nv, nk);
        bsi_curv_gather(d, nv, 0, &here);
        double len = 1.0 / inv_d;
        if (unit3(here.d[0], len, t) && frame(t, nrm, out))
            return BS_CURV_LIMIT;
        if (unit3(here.d[1], len, t) && frame(t, nrm, out))
            return BS_CURV_LIMIT;
    }
    for (int i = 0; i < 3; i++) {
        double e;
        for (int j = 0; j < LEVELS; j++)
            f[j] = c[j].dmin[i];
        t[i] = extrapolate(f, &e);
    }
    return frame(t, nrm, out) ? BS_CURV_LIMIT : BS_CURV_UNDEFINED;
}
