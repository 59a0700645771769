/*
 * Rays against a locator (bs_locator_intersect): each ray is put in its own orthonormal frame,
 * the hierarchy's wide tree is walked nearest box first (four boxes tested at once), boxes
 * beyond the best hit so far are skipped, and the sub-patches reached are tested by ray_patch.c.
 * The answer's point and normal are bs_patch_eval_normal's (the same bits) on the locator's copy
 * of the patch (limit normals at poles), and t comes from that point.
 */
#include "query/locator.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define STACK 256 /* three pending boxes per level of a wide tree at most 64 deep, and more */

/* The ray o + t d for t in range, in its frame; 0 (a NaN miss) if something is not finite or
 * d = 0. |d| = len[0] len[1] (the largest component and the length of d over it, a product that
 * may overflow or underflow: t is divided by one and then the other). The search runs in lengths
 * along the unit direction; without a range it ends at t = DBL_MAX, the largest t there is
 * (DBL_MAX |d|: about 2e-12 for a direction of length 1e-320), so that a hit is never reported
 * with a t that overflows. */
static int make_ray(const double o[3], const double d[3], const double *range, bsi_ray *ray,
                    double len[2])
{
    double scale = greater(fabs(d[0]), greater(fabs(d[1]), fabs(d[2]))); /* fmax's for finite d */
    /* t_max = +Inf is "no limit" (1.2); t_min stays finite */
    if (!bsi_finite3(o) || !bsi_finite3(d) ||
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

/* Where the ray enters and leaves the box whose faces it enters by are near[c], leaves by far[c],
 * cut to [*t0, *t1]: the entry into *tn, the exit into *t1 (the box is entered when *tn <= *t1).
 * In line in slab() and in each lane of wide_slab(), so both give the same bits. */
BSI_INLINE void slab_span(const double near[3], const double far[3], const slab_ray *r,
                          const double *t0, double *t1, double *tn)
{
    /* entry and exit per axis (where d is 0, -Inf and +Inf, or NaN); a NaN (0 * Inf: a zero or
     * subnormal component meeting a box face) narrows nothing */
    double x0 = (near[0] - r->o[0]) * r->inv[0], y0 = (far[0] - r->o[0]) * r->inv[0];
    double x1 = (near[1] - r->o[1]) * r->inv[1], y1 = (far[1] - r->o[1]) * r->inv[1];
    double x2 = (near[2] - r->o[2]) * r->inv[2], y2 = (far[2] - r->o[2]) * r->inv[2];
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
    *tn = a > *t0 ? a : *t0;
    *t1 = b < *t1 ? b : *t1;
}

/* Where the ray enters box (lo, hi = lo + 3) within [t0, t1]; 0 if it does not (the sub-patches'
 * own boxes of a leaf node that the wide tree keeps whole). */
BSI_INLINE int slab(const double *lo, const slab_ray *r, double t0, double t1, double *tnear)
{
    if (r->flat) /* along a zero component: the origin must lie between the faces */
        for (int c = 0; c < 3; c++)
            if (r->zero[c] && (r->o[c] < lo[c] || r->o[c] > lo[3 + c]))
                return 0;
    const double near[3] = {lo[r->in[0]], lo[r->in[1]], lo[r->in[2]]};
    const double far[3] = {lo[r->out[0]], lo[r->out[1]], lo[r->out[2]]};
    double t;
    slab_span(near, far, r, &t0, &t1, &t);
    *tnear = t;
    return t <= t1;
}

/* slab() on the four boxes of a wide node at once, lane by lane with the same operations (so the
 * same entries, the same boxes let through), in loops of fixed length that the compiler runs in
 * vector registers; chosen per CPU at load time. in[k] for slots k < w->n only. */
BSI_HOT static void wide_slab(const bsi_loc_wide *restrict w, const slab_ray *restrict r, double t0,
                              double t1, double *restrict tn, int *restrict in)
{
    double tf[BSI_LOC_WIDE];
    const double *near[3], *far[3];
    for (int c = 0; c < 3; c++) { /* the faces entered by, as slab_setup's offsets */
        near[c] = r->inv[c] > 0.0 ? w->lo[c] : w->hi[c];
        far[c] = r->inv[c] > 0.0 ? w->hi[c] : w->lo[c];
    }
    for (size_t k = 0; k < BSI_LOC_WIDE; k++) {
        const double nk[3] = {near[0][k], near[1][k], near[2][k]}, fk[3] = {far[0][k], far[1][k], far[2][k]};
        tf[k] = t1;
        slab_span(nk, fk, r, &t0, &tf[k], &tn[k]);
    }
    for (size_t k = 0; k < BSI_LOC_WIDE; k++)
        in[k] = k < w->n && tn[k] <= tf[k];
    if (r->flat) /* along a zero component: the origin must lie between the faces */
        for (size_t k = 0; k < BSI_LOC_WIDE; k++)
            for (int c = 0; c < 3; c++)
                if (r->zero[c] && (r->o[c] < w->lo[c][k] || r->o[c] > w->hi[c][k]))
                    in[k] = 0;
}

/* The sub-patches of binary leaf node nd: each one's own box first (most that the node's box
 * lets through miss theirs); the nearer entered first, the other skipped if a hit comes before it. */
static void visit_leaves(const bs_locator *L, const bsi_loc_node *nd, const bsi_ray *ray,
                         const slab_ray *sr, double *scratch, bsi_ray_hit *hit)
{
    double tl[BSI_LOC_LEAF_MAX];
    int inl[BSI_LOC_LEAF_MAX], order[BSI_LOC_LEAF_MAX] = {0, 1};
    for (uint32_t q = 0; q < nd->count; q++) {
        const double *box = L->leaf_box + 6 * (size_t)(nd->first + q);
        inl[q] = slab(box, sr, ray->tmin, lesser(ray->tmax, hit->t), &tl[q]);
    }
    if (nd->count == 2 && inl[1] && (!inl[0] || tl[1] < tl[0])) {
        order[0] = 1;
        order[1] = 0;
    }
    for (uint32_t q = 0; q < nd->count; q++)
        if (inl[order[q]] && tl[order[q]] <= hit->t) // NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult,clang-analyzer-core.uninitialized.ArraySubscript): q < count <= BSI_LOC_LEAF_MAX, each set above
            bsi_ray_leaf(L, nd->first + (uint32_t)order[q], ray, scratch, hit);
}

/* The first hit of the ray: hit->t stays +Inf on a miss. The wide tree is walked nearest box
 * first; boxes entered beyond the best hit so far are skipped. At equal entries the earlier slot
 * goes first, so the walk, and the hit kept at a tie of t, is the same for every run. */
static void trace(const bs_locator *L, const bsi_ray *ray, double *scratch, bsi_ray_hit *hit)
{
    struct {
        uint32_t ref;
        unsigned char leaf;
        double tnear;
    } stack[STACK];
    int top = 0;
    slab_ray sr = slab_setup(ray);
    hit->t = INFINITY;
    if (L->nnode == 0)
        return;
    stack[top].ref = 0;
    stack[top].leaf = 0;
    stack[top++].tnear = -INFINITY;
    while (top > 0) {
        top--;
        if (stack[top].tnear > hit->t)
            continue;
        if (stack[top].leaf == BSI_WIDE_PATCH) { /* its own box entered before the best hit */
            bsi_ray_leaf(L, stack[top].ref, ray, scratch, hit);
            continue;
        }
        if (stack[top].leaf == BSI_WIDE_NODE) {
            visit_leaves(L, &L->nodes[stack[top].ref], ray, &sr, scratch, hit);
            continue;
        }
        const bsi_loc_wide *w = &L->wide[stack[top].ref];
        double tn[BSI_LOC_WIDE];
        int in[BSI_LOC_WIDE], order[BSI_LOC_WIDE] = {0, 1, 2, 3}, nin = 0;
        wide_slab(w, &sr, ray->tmin, lesser(ray->tmax, hit->t), tn, in);
        for (int k = 0; k < BSI_LOC_WIDE; k++) { /* the boxes entered, nearest first */
            if (!in[k])
                continue;
            int at = nin++;
            for (; at > 0 && tn[order[at - 1]] > tn[k]; at--)
                order[at] = order[at - 1];
            order[at] = k;
        }
        for (int q = nin - 1; q >= 0 && top < STACK; q--) { /* the farthest first, so the nearest is popped next */
            stack[top].ref = w->ref[order[q]];
            stack[top].leaf = w->leaf[order[q]];
            stack[top++].tnear = tn[order[q]];
        }
    }
}

/* (pos / sig - o).d, formed in the units of pos (a patch's scaled copy) while o sig is finite, so
 * that a subnormal patch's hit keeps its bits. */
static double hit_t(const bsi_ray *ray, const double pos[3], double sig)
{
    double a[3], os[3] = {ray->o[0] * sig, ray->o[1] * sig, ray->o[2] * sig};
    int far = !bsi_finite3(os); /* a patch below 2^-1000 seen from beyond 2^23 */
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
         * copy beyond 2^512 or below 2^-900, and pos that copy's); without normals and kinds the
         * position alone, whose bits are the same (bs_patch_eval's) */
        double sig;
        const bs_patch *p = bsi_loc_patch(L, id, &sig);
        if (nrm || kind)
            bsi_eval_normal_one(p, &L->nscale[id], u, v, pos, nv, &kd);
        else
            bsi_eval_point(p, u, v, pos);
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
