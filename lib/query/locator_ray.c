/*
 * Rays against a locator (bs_locator_intersect): each ray is put in its own orthonormal frame,
 * the hierarchy is walked nearest box first, boxes beyond the best hit so far are skipped, and
 * the sub-patches reached are tested by ray_patch.c. The answer's point and normal are
 * bs_patch_eval_normal's (the same bits) on the locator's copy of the patch (limit normals at
 * poles), and t comes from that point.
 */
#include "query/locator.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define STACK 128 /* twice the depth of a median-split tree of up to 2^32 leaves, and more */

/* The ray o + t d for t in range, in its frame; 0 (a NaN miss) if something is not finite or
 * d = 0. |d| = len[0] len[1] (the largest component and the length of d over it, a product that
 * may overflow or underflow: t is divided by one and then the other). The search runs in lengths
 * along the unit direction; without a range it ends at t = DBL_MAX, the largest t there is
 * (DBL_MAX |d|: about 2e-12 for a direction of length 1e-320), so that a hit is never reported
 * with a t that overflows. */
static int make_ray(const double o[3], const double d[3], const double *range, bsi_ray *ray,
                    double len[2])
{
    double scale = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    /* t_max = +Inf is "no limit" (1.2); t_min stays finite */
    if (!bsi_all_finite(o, 3) || !bsi_all_finite(d, 3) ||
        (range && !(isfinite(range[0]) && (isfinite(range[1]) || range[1] == INFINITY))) || scale == 0.0)
        return 0;
    double dd[3] = {d[0] / scale, d[1] / scale, d[2] / scale}, l = sqrt(bsi_dot3(dd, dd));
    len[0] = scale;
    len[1] = l;
    for (int c = 0; c < 3; c++) {
        ray->o[c] = o[c];
        ray->d[c] = dd[c] / l;
        ray->inv[c] = 1.0 / ray->d[c];
    }
    /* e1, e2: the branch-free orthonormal basis of Duff et al. (2017) */
    double x = ray->d[0], y = ray->d[1], z = ray->d[2], sg = copysign(1.0, z);
    double a = -1.0 / (sg + z), b = x * y * a;
    ray->e1[0] = 1.0 + sg * x * x * a;
    ray->e1[1] = sg * b;
    ray->e1[2] = -sg * x;
    ray->e2[0] = b;
    ray->e2[1] = sg + y * y * a;
    ray->e2[2] = -y;
    ray->open = range == NULL;
    ray->tmin = range ? range[0] * scale * l : 0.0;
    ray->tmax = (range ? range[1] : DBL_MAX) * scale * l;
    return 1;
}

/* What the slab tests read of a ray, kept in the walk's own variables: per axis the origin, 1 / d,
 * and the offsets in a box (lower corner, then upper) of the faces the ray enters and leaves by. */
typedef struct slab_ray {
    double o[3], inv[3];
    size_t in[3], out[3];
    int zero[3], flat; /* components of d that are 0; some is */
} slab_ray;

static slab_ray slab_setup(const bsi_ray *ray)
{
    slab_ray r;
    for (int c = 0; c < 3; c++) {
        r.o[c] = ray->o[c];
        r.inv[c] = ray->inv[c];
        r.in[c] = (size_t)c + (ray->inv[c] > 0.0 ? 0 : 3);
        r.out[c] = (size_t)c + (ray->inv[c] > 0.0 ? 3 : 0);
        r.zero[c] = ray->d[c] == 0.0;
    }
    r.flat = r.zero[0] || r.zero[1] || r.zero[2];
    return r;
}

/* Where the ray enters box (lo, hi = lo + 3) within [t0, t1]; 0 if it does not. In line in the
 * walk, which calls it at three places. */
BSI_INLINE int slab(const double *lo, const slab_ray *r, double t0, double t1, double *tnear)
{
    if (r->flat) /* along a zero component: the origin must lie between the faces */
        for (int c = 0; c < 3; c++)
            if (r->zero[c] && (r->o[c] < lo[c] || r->o[c] > lo[3 + c]))
                return 0;
    /* entry and exit per axis (where d is 0, -Inf and +Inf, or NaN); a NaN (0 * Inf: a zero or
     * subnormal component meeting a box face) narrows nothing */
    double x0 = (lo[r->in[0]] - r->o[0]) * r->inv[0], y0 = (lo[r->out[0]] - r->o[0]) * r->inv[0];
    double x1 = (lo[r->in[1]] - r->o[1]) * r->inv[1], y1 = (lo[r->out[1]] - r->o[1]) * r->inv[1];
    double x2 = (lo[r->in[2]] - r->o[2]) * r->inv[2], y2 = (lo[r->out[2]] - r->o[2]) * r->inv[2];
    double a = x0 > -INFINITY ? x0 : -INFINITY, b = y0 < INFINITY ? y0 : INFINITY;
    a = x1 > a ? x1 : a;
    b = y1 < b ? y1 : b;
    a = x2 > a ? x2 : a;
    b = y2 < b ? y2 : b;
    /* widened by their rounding (a few ulp), so that no box is lost to it: the same as widening
     * each axis's values before taking the largest and the smallest, since the widening is
     * monotonic */
    a -= 4 * DBL_EPSILON * fabs(a);
    b += 4 * DBL_EPSILON * fabs(b);
    t0 = a > t0 ? a : t0;
    t1 = b < t1 ? b : t1;
    *tnear = t0;
    return t0 <= t1;
}

/* The first hit of the ray: hit->t stays +Inf on a miss. */
static void trace(const bs_locator *L, const bsi_ray *ray, double *scratch, bsi_ray_hit *hit)
{
    struct {
        uint32_t node;
        double tnear;
    } stack[STACK];
    int top = 0;
    size_t dim = L->dim;
    double tn;
    slab_ray sr = slab_setup(ray);
    hit->t = INFINITY;
    if (L->nnode == 0 || !slab(L->box, &sr, ray->tmin, ray->tmax, &tn))
        return;
    stack[top].node = 0;
    stack[top++].tnear = tn;
    while (top > 0) {
        top--;
        if (stack[top].tnear > hit->t)
            continue;
        const bsi_loc_node *nd = &L->nodes[stack[top].node];
        if (nd->count > 0) {
            /* each sub-patch's own box first: most that the node's box lets through miss
             * theirs; the nearer entered first, the other skipped if a hit comes before it */
            double tl[BSI_LOC_LEAF_MAX];
            int inl[BSI_LOC_LEAF_MAX], order[BSI_LOC_LEAF_MAX] = {0, 1};
            for (uint32_t q = 0; q < nd->count; q++) {
                const double *box = L->leaf_box + 2 * dim * (nd->first + q);
                inl[q] = slab(box, &sr, ray->tmin, lesser(ray->tmax, hit->t), &tl[q]);
            }
            if (nd->count == 2 && inl[1] && (!inl[0] || tl[1] < tl[0])) {
                order[0] = 1;
                order[1] = 0;
            }
            for (uint32_t q = 0; q < nd->count; q++)
                if (inl[order[q]] && tl[order[q]] <= hit->t) // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult,clang-analyzer-core.uninitialized.ArraySubscript): q < count <= BSI_LOC_LEAF_MAX, each set above
                    bsi_ray_leaf(L, nd->first + (uint32_t)order[q], ray, scratch, hit);
            continue;
        }
        double tc[2];
        int in[2];
        for (int c = 0; c < 2; c++) {
            const double *box = L->box + 2 * dim * (nd->first + (uint32_t)c);
            in[c] = slab(box, &sr, ray->tmin, lesser(ray->tmax, hit->t), &tc[c]);
        }
        int near = in[1] && (!in[0] || tc[1] < tc[0]);
        for (int q = 0; q < 2; q++) { /* the farther child first, so the nearer is popped next */
            int c = q == 0 ? !near : near;
            if (in[c] && top < STACK) {
                stack[top].node = nd->first + (uint32_t)c;
                stack[top++].tnear = tc[c];
            }
        }
    }
}

/* (pos / sig - o).d, formed in the units of pos (a patch's scaled copy) while o sig is finite, so
 * that a subnormal patch's hit keeps its bits. */
static double hit_t(const bsi_ray *ray, const double pos[3], double sig)
{
    double a[3], os[3] = {ray->o[0] * sig, ray->o[1] * sig, ray->o[2] * sig};
    int far = !bsi_all_finite(os, 3); /* a patch below 2^-1000 seen from beyond 2^23 */
    for (int c = 0; c < 3; c++)
        a[c] = far ? pos[c] / sig - ray->o[c] : pos[c] - os[c];
    return far ? bsi_dot3(a, ray->d) : bsi_dot3(a, ray->d) / sig;
}

/* Outputs of ray k: the hit, or a miss with t = tmiss (+Inf, or NaN for an invalid ray). */
static void put(const bs_locator *L, size_t k, const bsi_ray *ray, const double len[2],
                const bsi_ray_hit *hit, double tmiss, uint32_t *patch, const bs_view *uv,
                const bs_view *t, const bs_view *nrm, unsigned char *kind)
{
    double u = NAN, v = NAN, tt = tmiss, nv[3] = {NAN, NAN, NAN};
    uint32_t id = UINT32_MAX;
    unsigned char kd = BS_NORMAL_UNDEFINED;
    if (hit && isfinite(hit->t)) {
        const bsi_loc_leaf *leaf = &L->leaves[hit->leaf];
        const double side = 1.0 / BSI_LOC_SPLIT;
        double pos[3];
        id = leaf->patch;
        u = leaf->u0 + hit->s * side;
        v = leaf->v0 + hit->r * side;
        /* bs_patch_eval_normal's bits, with the patch's normal scale made once (of its scaled
         * copy beyond 2^512 or below 2^-900, and pos that copy's) */
        double sig;
        bsi_eval_normal_one(bsi_loc_patch(L, id, &sig), &L->nscale[id], u, v, pos, nv, &kd);
        /* t of the point reported, kept within the range the hit was found in */
        tt = fmin(DBL_MAX, fmin(ray->tmax, fmax(ray->tmin, hit_t(ray, pos, sig))) / len[0] / len[1]);
        if (L->trim) { /* a model's: its face, native parameters and outward normal */
            double fuv[2];
            L->trim->to_face(L->trim, id, u, v, &id, fuv, nv);
            u = fuv[0];
            v = fuv[1];
        }
    }
    if (kind)
        kind[k] = kd;
    if (patch)
        patch[k] = id;
    if (uv) {
        *bsi_at(&uv[0], k) = u;
        *bsi_at(&uv[1], k) = v;
    }
    if (t)
        *bsi_at(t, k) = tt;
    for (int c = 0; c < 3 && nrm; c++)
        *bsi_at(&nrm[c], k) = nv[c];
}

static bs_status check_cviews(const bs_cview *v, size_t k, size_t n)
{
    bs_status st = BS_OK;
    for (size_t c = 0; c < k && st == BS_OK; c++)
        st = bsi_check_cview(&v[c], n);
    return st;
}

bs_status bsi_loc_intersect_check(const bs_locator *L, size_t n, const bs_cview *org, const bs_cview *dir,
                                  const bs_cview *trange, const bs_view *uv, const bs_view *t,
                                  const bs_view *nrm)
{
    if (L == NULL)
        return BS_ERR_INVALID_ARG;
    if (L->dim != 3 && L->dim != 0)
        return BS_ERR_DIMENSION;
    if (n == 0)
        return BS_OK;
    if (org == NULL || dir == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st;
    if ((st = check_cviews(org, 3, n)) != BS_OK || (st = check_cviews(dir, 3, n)) != BS_OK ||
        (trange && (st = check_cviews(trange, 2, n)) != BS_OK) ||
        (uv && (st = bsi_check_views(uv, 2, n)) != BS_OK) ||
        (t && (st = bsi_check_views(t, 1, n)) != BS_OK) ||
        (nrm && (st = bsi_check_views(nrm, 3, n)) != BS_OK))
        return st;
    return BS_OK;
}

bs_status bs_locator_intersect(const bs_locator *L, size_t n, const bs_cview *org,
                               const bs_cview *dir, const bs_cview *trange, uint32_t *patch,
                               const bs_view *uv, const bs_view *t, const bs_view *nrm)
{
    return bs_locator_intersect_kind(L, n, org, dir, trange, patch, uv, t, nrm, NULL);
}

bs_status bs_locator_intersect_kind(const bs_locator *L, size_t n, const bs_cview *org,
                                    const bs_cview *dir, const bs_cview *trange, uint32_t *patch,
                                    const bs_view *uv, const bs_view *t, const bs_view *nrm,
                                    unsigned char *kind)
{
    bs_status st = bsi_loc_intersect_check(L, n, org, dir, trange, uv, t, nrm);
    if (st != BS_OK || n == 0)
        return st;
    double *scratch = NULL;
    if (L->nleaf > 0 && (scratch = malloc(bsi_ray_leaf_scratch(L->max_ctrl) * sizeof(double))) == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < n; k++) {
        double o[3], d[3], range[2], len[2] = {1.0, 1.0};
        for (int c = 0; c < 3; c++) {
            o[c] = bsi_cget(&org[c], k);
            d[c] = bsi_cget(&dir[c], k);
        }
        for (int c = 0; c < 2 && trange; c++)
            range[c] = bsi_cget(&trange[c], k);
        bsi_ray ray;
        if (!make_ray(o, d, trange ? range : NULL, &ray, len)) {
            put(L, k, NULL, len, NULL, NAN, patch, uv, t, nrm, kind);
            continue;
        }
        bsi_ray_hit hit = {INFINITY, 0.0, 0.0, 0};
        if (L->nleaf > 0)
            trace(L, &ray, scratch, &hit);
        put(L, k, &ray, len, &hit, INFINITY, patch, uv, t, nrm, kind);
    }
    free(scratch);
    return BS_OK;
}
