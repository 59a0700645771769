/* Helpers shared by the evaluation tests: random nets, views over arrays, the accuracy bound,
 * reference normals and the teapot data. */
#ifndef BS_TEST_EVAL_UTIL_H
#define BS_TEST_EVAL_UTIL_H

#include "harness.h"
#include "reference.h"

#include <bezsurf.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EPS DBL_EPSILON

/* A random net of degree (m,n) in dim, coordinates in [-1,1); weights in [wlo,whi) or none. */
typedef struct tnet {
    size_t m, n, dim;
    double *ctrl, *w;
} tnet;

static inline tnet tnet_random(unsigned long long *rng, size_t m, size_t n, size_t dim, int rational,
                               double wlo, double whi)
{
    tnet t = {m, n, dim, NULL, NULL};
    size_t np = (m + 1) * (n + 1);
    t.ctrl = malloc(np * dim * sizeof(double));
    for (size_t k = 0; k < np * dim; k++)
        t.ctrl[k] = bs_test_rand(rng, -1.0, 1.0);
    if (rational) {
        t.w = malloc(np * sizeof(double));
        for (size_t k = 0; k < np; k++)
            t.w[k] = bs_test_rand(rng, wlo, whi);
    }
    return t;
}

static inline void tnet_free(tnet *t)
{
    free(t->ctrl);
    free(t->w);
}

static inline ref_net tnet_ref(const tnet *t)
{
    ref_net r = {t->m, t->n, t->dim, t->ctrl, t->w};
    return r;
}

static inline bs_patch *tnet_patch(const tnet *t)
{
    bs_patch *p = NULL;
    if (bs_patch_create(t->m, t->n, t->dim, t->ctrl, t->w, &p) != BS_OK)
        return NULL;
    return p;
}

static inline bs_cview cview_of(const double *x, size_t n)
{
    bs_cview c = {x, n, 0};
    return c;
}

/* dim packed views over soa[c*n + k]. */
static inline void views_of(double *soa, size_t dim, size_t n, bs_view *out)
{
    for (size_t c = 0; c < dim; c++) {
        out[c].data = soa + c * n;
        out[c].count = n;
        out[c].stride = 0;
    }
}

static inline double max_abs(const double *x, size_t n)
{
    double r = 0.0;
    for (size_t k = 0; k < n; k++)
        r = fmax(r, fabs(x[k]));
    return r;
}

/* m!/(m-k)!, 0 when k > m. */
static inline double falling(size_t m, unsigned k)
{
    if (k > m)
        return 0.0;
    double r = 1.0;
    for (unsigned i = 0; i < k; i++)
        r *= (double)(m - i);
    return r;
}

/* k! m^k: the factor of rational patches, whose derivatives do not vanish past the degree. */
static inline double rational_factor(size_t m, unsigned k)
{
    double r = 1.0;
    for (unsigned i = 1; i <= k; i++)
        r *= (double)i * (double)m;
    return r;
}

/* The documented accuracy bound (docs/accuracy.md) for d^(k+l)S/du^k dv^l, before its floor:
 * m!/(m-k)! n!/(n-l)! for polynomial patches, k! m^k l! n^l for rational ones (from 1.1). */
static inline double accuracy_bound(const tnet *t, unsigned k, unsigned l)
{
    size_t np = (t->m + 1) * (t->n + 1);
    double fk = t->w ? rational_factor(t->m, k) : falling(t->m, k);
    double fl = t->w ? rational_factor(t->n, l) : falling(t->n, l);
    double b = 2.0 * (double)(t->m + t->n + 1) * EPS * max_abs(t->ctrl, np * t->dim) *
               ldexp(1.0, (int)(k + l)) * fmax(fk, 1.0) * fmax(fl, 1.0);
    if (t->w != NULL) {
        double lo = INFINITY, hi = 0.0;
        for (size_t i = 0; i < np; i++) {
            lo = fmin(lo, t->w[i]);
            hi = fmax(hi, t->w[i]);
        }
        b *= pow(hi / lo, 1.0 + k + l);
    }
    return b;
}

/* The normal of p at one point (into nrm[3]) and its kind. */
static inline unsigned char normal1(const bs_patch *p, double u, double v, double *nrm)
{
    bs_cview cu = cview_of(&u, 1), cv = cview_of(&v, 1);
    bs_view vn[3];
    views_of(nrm, 3, 1, vn);
    unsigned char kind = 99;
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, NULL, vn, &kind), BS_OK);
    return kind;
}

/* Euclidean distance of a 3-vector from a long-double one. */
static inline double dist3(const double *a, const long double *b)
{
    long double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return (double)sqrtl(d0 * d0 + d1 * d1 + d2 * d2);
}

/* Reference unit normal at (u,v) from long-double first derivatives; 0 if S_u x S_v is 0. */
static inline int ref_normal(const ref_net *r, long double u, long double v, long double *nrm)
{
    long double a[3], b[3];
    ref_deriv(r, 1, 0, u, v, a);
    ref_deriv(r, 0, 1, u, v, b);
    long double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    long double len = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (len == 0.0L)
        return 0;
    for (int k = 0; k < 3; k++)
        nrm[k] = c[k] / len;
    return 1;
}

/* The teapot's 32 bicubic patches, 16 points x 3 each; returns the count read (0 on failure). */
static inline size_t load_bpt(const char *path, double (*ctrl)[48], size_t cap)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return 0;
    size_t np = 0;
    if (fscanf(f, "%zu", &np) != 1 || np > cap) {
        fclose(f);
        return 0;
    }
    for (size_t p = 0; p < np; p++) {
        unsigned du, dv;
        if (fscanf(f, "%u %u", &du, &dv) != 2 || du != 3 || dv != 3) {
            fclose(f);
            return 0;
        }
        for (int k = 0; k < 48; k++)
            if (fscanf(f, "%lf", &ctrl[p][k]) != 1) {
                fclose(f);
                return 0;
            }
    }
    fclose(f);
    return np;
}

/* The teapot's patches as objects (path: its .bpt file); returns the count made, 0 on failure.
 * Release each with bs_patch_destroy(). */
static inline size_t teapot_patches(const char *path, bs_patch *out[32])
{
    static double ctrl[32][48];
    size_t np = load_bpt(path, ctrl, 32);
    for (size_t k = 0; k < np; k++)
        if (bs_patch_create(3, 3, 3, ctrl[k], NULL, &out[k]) != BS_OK)
            return k;
    return np;
}

/* Grid parameters: u evenly spaced over [0,1] (0.3 alone when nu = 1), v random in
 * [-0.1, 1.1), so that the grid also extrapolates a little. */
static inline void grid_params(unsigned long long *rng, size_t nu, double *u, size_t nv, double *v)
{
    for (size_t a = 0; a < nu; a++)
        u[a] = nu == 1 ? 0.3 : (double)a / (double)(nu - 1);
    for (size_t b = 0; b < nv; b++)
        v[b] = bs_test_rand(rng, -0.1, 1.1);
}

#endif
