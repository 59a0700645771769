/* Subdivision: splitting at a parameter (de Casteljau) and sub-patches over any rectangle
 * (blossoming). Rational patches are processed in homogeneous coordinates. */
#include "ops/internal.h"

#include <math.h>
#include <stdlib.h>

/* The whole de Casteljau triangle at t: out[0..deg] is the net over [0,t], out[deg..2 deg] the
 * net over [t,1]. Both halves read the shared point out[deg], so their common boundary is
 * identical bit for bit. */
static void fiber_split(const double *in, size_t deg, double *out, size_t deg_out, const void *ctx)
{
    double t = *(const double *)ctx, s = 1.0 - t;
    double b[BS_MAX_DEGREE + 1];
    (void)deg_out;
    for (size_t i = 0; i <= deg; i++)
        b[i] = in[i];
    out[0] = b[0];
    out[2 * deg] = b[deg];
    for (size_t r = 1; r <= deg; r++) {
        for (size_t i = 0; i + r <= deg; i++)
            b[i] = s * b[i] + t * b[i + 1];
        out[r] = b[0];
        out[2 * deg - r] = b[deg - r];
    }
}

/* Sub-curve over [t0,t1] by blossoming: out[i] = blossom(t0^(deg-i), t1^i). Level L of the t0
 * triangle is a degree deg-L curve in the remaining arguments; deg-L steps at t1 finish it. */
static void fiber_blossom(const double *in, size_t deg, double *out, size_t deg_out, const void *ctx)
{
    const double *tt = ctx;
    double t0 = tt[0], s0 = 1.0 - t0, t1 = tt[1], s1 = 1.0 - t1;
    double cur[BS_MAX_DEGREE + 1], tmp[BS_MAX_DEGREE + 1];
    (void)deg_out;
    for (size_t i = 0; i <= deg; i++)
        cur[i] = in[i];
    for (size_t level = 0; level <= deg; level++) {
        size_t k = deg - level; /* degree still open: this level gives out[k] */
        for (size_t i = 0; i <= k; i++)
            tmp[i] = cur[i];
        for (size_t r = 1; r <= k; r++)
            for (size_t i = 0; i + r <= k; i++)
                tmp[i] = s1 * tmp[i] + t1 * tmp[i + 1];
        out[k] = tmp[0];
        for (size_t i = 0; i < k; i++)
            cur[i] = s0 * cur[i] + t0 * cur[i + 1];
    }
}

static int valid_dir(int dir) { return dir == BS_DIR_U || dir == BS_DIR_V; }
static int open_unit(double t) { return t > 0.0 && t < 1.0; } /* false for NaN */

/* Split the homogeneous net (ncoord planes, degree (du,dv)) along dir into lo and hi nets of the
 * same degrees. Returns BS_ERR_NO_MEMORY on failure. */
static bs_status split_net(const double *net, size_t ncoord, size_t du, size_t dv, int dir, double t,
                           double *lo, double *hi)
{
    size_t deg = dir == BS_DIR_U ? du : dv;
    size_t big_u = dir == BS_DIR_U ? 2 * du : du, big_v = dir == BS_DIR_U ? dv : 2 * dv;
    double *both = malloc(bsi_net_size(ncoord, big_u, big_v) * sizeof(double));
    if (both == NULL)
        return BS_ERR_NO_MEMORY;
    bsi_net_map(net, ncoord, du, dv, dir, 2 * deg, fiber_split, &t, both);
    bsi_net_slice(both, ncoord, big_u, big_v, dir, 0, deg, lo);
    bsi_net_slice(both, ncoord, big_u, big_v, dir, deg, deg, hi);
    free(both);
    return BS_OK;
}

/* Make patches from n homogeneous nets; on failure destroy those made and set all to NULL. */
static bs_status patches_from_nets(const bs_patch *p, size_t n, double *const *nets, bs_patch **res)
{
    bs_status st = BS_OK;
    for (size_t k = 0; k < n && st == BS_OK; k++)
        st = bsi_patch_from_hom(p->deg_u, p->deg_v, p->dim, p->rational, nets[k], &res[k]);
    if (st != BS_OK)
        for (size_t k = 0; k < n; k++) {
            bs_patch_destroy(res[k]);
            res[k] = NULL;
        }
    return st;
}

bs_status bs_patch_split(const bs_patch *p, int dir, double t, bs_patch **lo, bs_patch **hi)
{
    if (lo != NULL)
        *lo = NULL;
    if (hi != NULL)
        *hi = NULL;
    if (p == NULL || lo == NULL || hi == NULL || lo == hi || !valid_dir(dir))
        return BS_ERR_INVALID_ARG;
    if (!open_unit(t))
        return BS_ERR_DOMAIN;
    size_t size = bsi_net_size(p->ncoord, p->deg_u, p->deg_v);
    double *buf = malloc(2 * size * sizeof(double));
    if (buf == NULL)
        return BS_ERR_NO_MEMORY;
    double *nets[2] = {buf, buf + size};
    bs_patch *res[2] = {NULL, NULL};
    bs_status st = split_net(p->hom, p->ncoord, p->deg_u, p->deg_v, dir, t, nets[0], nets[1]);
    if (st == BS_OK)
        st = patches_from_nets(p, 2, nets, res);
    free(buf);
    if (st == BS_OK) {
        *lo = res[0];
        *hi = res[1];
    }
    return st;
}

bs_status bs_patch_split4(const bs_patch *p, double u, double v, bs_patch *out[4])
{
    if (out != NULL)
        for (int k = 0; k < 4; k++)
            out[k] = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    if (!open_unit(u) || !open_unit(v))
        return BS_ERR_DOMAIN;
    size_t size = bsi_net_size(p->ncoord, p->deg_u, p->deg_v);
    double *buf = malloc(6 * size * sizeof(double));
    if (buf == NULL)
        return BS_ERR_NO_MEMORY;
    double *ulo = buf, *uhi = buf + size;
    double *nets[4] = {buf + 2 * size, buf + 3 * size, buf + 4 * size, buf + 5 * size};
    bs_patch *res[4] = {NULL, NULL, NULL, NULL};
    size_t nc = p->ncoord, du = p->deg_u, dv = p->deg_v;
    bs_status st = split_net(p->hom, nc, du, dv, BS_DIR_U, u, ulo, uhi);
    if (st == BS_OK)
        st = split_net(ulo, nc, du, dv, BS_DIR_V, v, nets[0], nets[2]);
    if (st == BS_OK)
        st = split_net(uhi, nc, du, dv, BS_DIR_V, v, nets[1], nets[3]);
    if (st == BS_OK)
        st = patches_from_nets(p, 4, nets, res);
    free(buf);
    if (st == BS_OK)
        for (int k = 0; k < 4; k++)
            out[k] = res[k];
    return st;
}

bs_status bs_patch_subpatch(const bs_patch *p, double u0, double u1, double v0, double v1,
                            bs_patch **out)
{
    if (out != NULL)
        *out = NULL;
    if (p == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    if (!isfinite(u0) || !isfinite(u1) || !isfinite(v0) || !isfinite(v1) || u0 == u1 || v0 == v1)
        return BS_ERR_DOMAIN;
    size_t size = bsi_net_size(p->ncoord, p->deg_u, p->deg_v);
    double *buf = malloc(2 * size * sizeof(double));
    if (buf == NULL)
        return BS_ERR_NO_MEMORY;
    const double tu[2] = {u0, u1}, tv[2] = {v0, v1};
    bsi_net_map(p->hom, p->ncoord, p->deg_u, p->deg_v, BS_DIR_U, p->deg_u, fiber_blossom, tu, buf);
    bsi_net_map(buf, p->ncoord, p->deg_u, p->deg_v, BS_DIR_V, p->deg_v, fiber_blossom, tv, buf + size);
    bs_status st = bsi_patch_from_hom(p->deg_u, p->deg_v, p->dim, p->rational, buf + size, out);
    free(buf);
    return st;
}
