/*
 * The locator (bezsurf/query.h): copies of the surface's patches, each cut into 4 x 4 sub-patches
 * by exact halving of its homogeneous net, and a bounding-volume hierarchy over the sub-patches
 * (locator_bvh.c). Queries: locator_ray.c (rays), locator_closest.c (closest points).
 */
#include "query/locator.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The homogeneous net of p interleaved: point k is w P_0 .. w P_dim-1, w. */
static void hom_net(const bs_patch *p, double *out)
{
    size_t nc = p->dim + 1;
    for (size_t k = 0; k < p->nctrl; k++) {
        for (size_t c = 0; c < p->dim; c++)
            out[k * nc + c] = p->hom[c * p->nctrl + k];
        out[k * nc + p->dim] = p->rational ? p->hom[p->dim * p->nctrl + k] : 1.0;
    }
}

/* Quarter a (of 4) along dir: two halvings from net into out, through tmp. */
static void quarter(const double *net, size_t m, size_t n, size_t nc, int dir, unsigned a,
                    double *tmp, double *out)
{
    bsi_net_halve(net, m, n, nc, dir, a < 2 ? tmp : NULL, a < 2 ? NULL : tmp);
    bsi_net_halve(tmp, m, n, nc, dir, (a & 1) ? NULL : out, (a & 1) ? out : NULL);
}

/* The 16 leaves of patch i: nets (Cartesian points and weights) at L->nets + first net, and
 * their boxes padded by the rounding of the halvings and pad (absolute). A patch of scale sig
 * (not 1) is cut from its scaled copy, its boxes divided by sig and rounded outwards. */
static void cut_patch(bs_locator *L, uint32_t i, size_t *leaf, size_t *net_at, double *hom,
                      double *tmp, double *leaf_box, double pad)
{
    double sig;
    const bs_patch *p = bsi_loc_patch(L, i, &sig);
    pad = sig != 1.0 ? fmin(DBL_MAX, pad * sig) : pad;
    size_t m = p->deg_u, n = p->deg_v, nc = p->dim + 1, dim = p->dim, len = p->nctrl * nc;
    double *quarter_u = hom + len, *sub = quarter_u + len;
    hom_net(p, hom);
    for (unsigned a = 0; a < BSI_LOC_SPLIT; a++) {
        quarter(hom, m, n, nc, BS_DIR_U, a, tmp, quarter_u);
        for (unsigned b = 0; b < BSI_LOC_SPLIT; b++) {
            quarter(quarter_u, m, n, nc, BS_DIR_V, b, tmp, sub);
            bsi_loc_leaf *lf = &L->leaves[*leaf];
            lf->patch = i;
            lf->u0 = a / (double)BSI_LOC_SPLIT;
            lf->v0 = b / (double)BSI_LOC_SPLIT;
            lf->net = *net_at;
            double *out = L->nets + *net_at, *lo = leaf_box + 2 * dim * *leaf, *hi = lo + dim;
            double big = 0.0;
            for (size_t c = 0; c < dim; c++) {
                lo[c] = INFINITY;
                hi[c] = -INFINITY;
            }
            for (size_t k = 0; k < p->nctrl; k++) {
                double w = sub[k * nc + dim];
                for (size_t c = 0; c < dim; c++) {
                    double x = p->rational ? sub[k * nc + c] / w : sub[k * nc + c];
                    out[k * nc + c] = x;
                    lo[c] = fmin(lo[c], x);
                    hi[c] = fmax(hi[c], x);
                    big = fmax(big, fabs(x));
                }
                out[k * nc + dim] = w;
            }
            for (size_t c = 0; c < dim; c++) {
                lo[c] -= pad + 64 * DBL_EPSILON * big;
                hi[c] += pad + 64 * DBL_EPSILON * big;
                if (sig != 1.0) {
                    lo[c] = nextafter(lo[c] / sig, -INFINITY);
                    hi[c] = nextafter(hi[c] / sig, INFINITY);
                }
            }
            if (dim == 3)
                bsi_ray_leaf_cone(out, m, n, p->rational, &lf->cone);
            else
                lf->cone = BSI_NO_CONE;
            *net_at += len;
            ++*leaf;
        }
    }
}

/* Diagonal of the box of every control point of the patches. */
static double surface_diagonal(bs_patch *const *patches, size_t np, size_t dim)
{
    double lo[BS_MAX_DIM], hi[BS_MAX_DIM], s = 0.0;
    for (size_t c = 0; c < dim; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t i = 0; i < np; i++)
        for (size_t k = 0; k < patches[i]->nctrl; k++)
            for (size_t c = 0; c < dim; c++) {
                lo[c] = fmin(lo[c], patches[i]->ctrl[k * dim + c]);
                hi[c] = fmax(hi[c], patches[i]->ctrl[k * dim + c]);
            }
    for (size_t c = 0; c < dim; c++) /* halves: the extent itself may overflow */
        s = hypot(s, 0.5 * hi[c] - 0.5 * lo[c]);
    return fmin(DBL_MAX, 2.0 * s);
}

/* The scaled copies of the patches beyond 2^512 or below 2^-900 (L->scaled), for rays. */
static bs_status scale_extremes(bs_locator *L)
{
    bs_status st = BS_OK;
    for (size_t i = 0; i < L->npatch && st == BS_OK; i++) {
        double sig = L->dim == 3 ? bsi_extreme_scale(L->patches[i], SMALL_NET, LARGE_NET) : 1.0;
        if (sig == 1.0)
            continue;
        if (L->scaled == NULL && (L->scaled = calloc(L->npatch, sizeof *L->scaled)) == NULL)
            return BS_ERR_NO_MEMORY;
        L->scaled[i].sig = sig;
        st = bsi_scaled_patch(L->patches[i], sig, &L->scaled[i].copy);
    }
    return st;
}

/* Leaves, their nets and the hierarchy of a locator whose patches are copied. */
static bs_status build(bs_locator *L)
{
    size_t dim = L->dim, nets = 0, max_len = 0;
    for (size_t i = 0; i < L->npatch; i++) {
        size_t len = L->patches[i]->nctrl * (dim + 1);
        nets += (size_t)BSI_LOC_SPLIT * BSI_LOC_SPLIT * len;
        max_len = len > max_len ? len : max_len;
        L->max_ctrl = L->patches[i]->nctrl > L->max_ctrl ? L->patches[i]->nctrl : L->max_ctrl;
    }
    L->nleaf = L->npatch * BSI_LOC_SPLIT * BSI_LOC_SPLIT;
    L->diag = surface_diagonal(L->patches, L->npatch, dim);
    L->leaves = malloc(L->nleaf * sizeof *L->leaves);
    /* build() runs only for a surface with patches, each of one control point at least */
    L->nets = malloc(nets * sizeof(double)); // NOLINT(clang-analyzer-optin.portability.UnixAPI): nets > 0
    double *leaf_box = malloc(L->nleaf * 2 * dim * sizeof(double));
    double *work = malloc(4 * max_len * sizeof(double)); // NOLINT(clang-analyzer-optin.portability.UnixAPI): max_len > 0
    bs_status st = scale_extremes(L);
    if (st == BS_OK && !(L->leaves && L->nets && leaf_box && work))
        st = BS_ERR_NO_MEMORY;
    if (st == BS_OK) {
        size_t leaf = 0, net_at = 0;
        for (uint32_t i = 0; i < L->npatch; i++)
            cut_patch(L, i, &leaf, &net_at, work, work + 3 * max_len, leaf_box, 1e-12 * L->diag);
        st = bsi_loc_build_bvh(L, leaf_box);
    }
    if (st == BS_OK && dim == 3) {
        st = (L->nscale = malloc(L->npatch * sizeof *L->nscale)) ? BS_OK : BS_ERR_NO_MEMORY;
        for (size_t i = 0; st == BS_OK && i < L->npatch; i++) {
            double sig;
            bsi_normal_scale(bsi_loc_patch(L, i, &sig), &L->nscale[i]);
        }
    }
    free(work);
    free(leaf_box);
    return st;
}

bs_status bs_locator_create(const bs_surface *s, bs_locator **out)
{
    if (out)
        *out = NULL;
    if (s == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    size_t np = bs_surface_count(s);
    if (np > UINT32_MAX / (BSI_LOC_SPLIT * BSI_LOC_SPLIT * 2)) /* nodes are counted in 32 bits */
        return BS_ERR_NO_MEMORY;
    bs_locator *L = calloc(1, sizeof *L);
    if (L == NULL)
        return BS_ERR_NO_MEMORY;
    L->dim = bs_surface_dim(s);
    if (np > 0 && (L->patches = calloc(np, sizeof *L->patches)) == NULL) { // NOLINT(bugprone-sizeof-expression): an array of patch pointers
        free(L);
        return BS_ERR_NO_MEMORY;
    }
    bs_status st = BS_OK;
    for (size_t i = 0; i < np && st == BS_OK; i++, L->npatch = i)
        st = bs_patch_clone(bs_surface_get(s, i), &L->patches[i]);
    if (st == BS_OK && np > 0)
        st = build(L);
    if (st != BS_OK) {
        bs_locator_destroy(L);
        return st;
    }
    *out = L;
    return BS_OK;
}

void bs_locator_destroy(bs_locator *L)
{
    if (L == NULL)
        return;
    for (size_t i = 0; i < L->npatch; i++)
        bs_patch_destroy(L->patches[i]);
    free(L->patches);
    free(L->leaves);
    free(L->nets);
    free(L->nodes);
    free(L->box);
    free(L->leaf_box);
    free(L->wide);
    free(L->nscale);
    for (size_t i = 0; L->scaled && i < L->npatch; i++)
        bs_patch_destroy(L->scaled[i].copy);
    free(L->scaled);
    if (L->trim)
        L->trim->release(L->trim);
    free(L);
}

size_t bs_locator_dim(const bs_locator *L)
{
    return L ? L->dim : 0;
}
