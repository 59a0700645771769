/* Scattered evaluation across a surface: runs of equal patch ids go to the patch evaluators as
 * sub-views (data pointers advanced to the run's first element), one call per run. */
#include "core/internal.h"

static bs_cview sub_cview(const bs_cview *v, size_t first)
{
    bs_cview r = {(const double *)(const void *)((const char *)v->data + (ptrdiff_t)first * bsi_stride(v->stride)),
                  v->count - first, v->stride};
    return r;
}

/* Sub-views of k views starting at element first, into out[k]; NULL when views is NULL. */
static const bs_view *sub_views(const bs_view *views, size_t k, size_t first, bs_view *out)
{
    if (views == NULL)
        return NULL;
    for (size_t c = 0; c < k; c++) {
        out[c].data = bsi_at(&views[c], first);
        out[c].count = views[c].count - first;
        out[c].stride = views[c].stride;
    }
    return out;
}

/* Shared argument checks; on success every id is valid. */
static bs_status check_args(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                            const bs_cview *v, int normals, const bs_view *a, size_t ka,
                            const bs_view *b, size_t kb, const bs_view *c, size_t kc)
{
    if (s == NULL || ids == NULL || u == NULL || v == NULL)
        return BS_ERR_INVALID_ARG;
    if (normals && bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    bs_status st;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK)
        return st;
    if ((a && (st = bsi_check_views(a, ka, n)) != BS_OK) || (b && (st = bsi_check_views(b, kb, n)) != BS_OK) ||
        (c && (st = bsi_check_views(c, kc, n)) != BS_OK))
        return st;
    size_t count = bs_surface_count(s);
    for (size_t k = 0; k < n; k++)
        if (ids[k] >= count)
            return BS_ERR_INVALID_ARG;
    return BS_OK;
}

/* Length of the run of equal ids starting at first. */
static size_t run_length(const uint32_t *ids, size_t n, size_t first)
{
    size_t end = first + 1;
    while (end < n && ids[end] == ids[first])
        end++;
    return end - first;
}

bs_status bs_surface_eval(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                          const bs_cview *v, const bs_view *pos, const bs_view *du, const bs_view *dv)
{
    if (n == 0)
        return s == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    size_t dim = bs_surface_dim(s);
    bs_status st = check_args(s, n, ids, u, v, 0, pos, dim, du, dim, dv, dim);
    if (st != BS_OK)
        return st;
    bs_view spos[BS_MAX_DIM], sdu[BS_MAX_DIM], sdv[BS_MAX_DIM];
    for (size_t first = 0; first < n;) {
        size_t len = run_length(ids, n, first);
        bs_cview su = sub_cview(u, first), sv = sub_cview(v, first);
        st = bs_patch_eval(bs_surface_get(s, ids[first]), len, &su, &sv, sub_views(pos, dim, first, spos),
                           sub_views(du, dim, first, sdu), sub_views(dv, dim, first, sdv));
        if (st != BS_OK) /* not expected: every argument was checked above */
            return st;
        first += len;
    }
    return BS_OK;
}

bs_status bs_surface_eval_normal(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                                 const bs_cview *v, const bs_view *pos, const bs_view *nrm, unsigned char *kind)
{
    if (n == 0)
        return s == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    bs_status st = check_args(s, n, ids, u, v, 1, pos, 3, nrm, 3, NULL, 0);
    if (st != BS_OK)
        return st;
    bs_view spos[3], snrm[3];
    for (size_t first = 0; first < n;) {
        size_t len = run_length(ids, n, first);
        bs_cview su = sub_cview(u, first), sv = sub_cview(v, first);
        st = bs_patch_eval_normal(bs_surface_get(s, ids[first]), len, &su, &sv, sub_views(pos, 3, first, spos),
                                  sub_views(nrm, 3, first, snrm), kind ? kind + first : NULL);
        if (st != BS_OK)
            return st;
        first += len;
    }
    return BS_OK;
}
