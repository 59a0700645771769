/* Scattered evaluation across a surface: runs of equal patch ids go to the patch evaluators as
 * sub-views (data pointers advanced to the run's first element), one call per run. The
 * multi-threaded variants split the points (or each patch's grid rows) into pieces fixed by the
 * sizes alone, each written only by the thread that evaluates it. */
#include "core/internal.h"

#include <stdint.h>

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
    return bs_surface_eval_mt(s, n, ids, u, v, pos, du, dv, 1);
}

bs_status bs_surface_eval_normal(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                                 const bs_cview *v, const bs_view *pos, const bs_view *nrm, unsigned char *kind)
{
    return bs_surface_eval_normal_mt(s, n, ids, u, v, pos, nrm, kind, 1);
}

/* Points per piece of a multi-threaded call: enough to hide the hand-out, small enough to balance. */
#define POINT_PIECE ((size_t)4096)

/* A checked scattered call: positions and partials, or (normals set) positions, normals and kinds. */
typedef struct points_job {
    const bs_surface *s;
    size_t n;
    const uint32_t *ids;
    const bs_cview *u, *v;
    const bs_view *pos, *du, *dv, *nrm;
    unsigned char *kind;
    int normals;
} points_job;

/* Points first..end-1 of a checked call, one patch call per run of equal ids. */
static bs_status eval_range(const points_job *j, size_t first, size_t end)
{
    size_t dim = bs_surface_dim(j->s);
    bs_view spos[BS_MAX_DIM], sa[BS_MAX_DIM], sb[BS_MAX_DIM];
    while (first < end) {
        size_t len = run_length(j->ids, end, first);
        const bs_patch *p = bs_surface_get(j->s, j->ids[first]);
        bs_cview su = bsi_sub_cview(j->u, first), sv = bsi_sub_cview(j->v, first);
        const bs_view *pos = bsi_sub_views(j->pos, dim, first, spos);
        bs_status st = j->normals ? bs_patch_eval_normal(p, len, &su, &sv, pos, bsi_sub_views(j->nrm, 3, first, sa),
                                                         j->kind ? j->kind + first : NULL)
                                  : bs_patch_eval(p, len, &su, &sv, pos, bsi_sub_views(j->du, dim, first, sa),
                                                  bsi_sub_views(j->dv, dim, first, sb));
        if (st != BS_OK) /* not expected: every argument was checked above */
            return st;
        first += len;
    }
    return BS_OK;
}

static bs_status points_task(void *ctx, size_t item, size_t worker)
{
    (void)worker;
    const points_job *j = ctx;
    size_t first = item * POINT_PIECE, end = j->n - first < POINT_PIECE ? j->n : first + POINT_PIECE;
    return eval_range(j, first, end);
}

/* The pieces of a checked call with n > 0, each evaluated by one thread. */
static bs_status run_points(points_job *job, size_t threads)
{
    size_t pieces = job->n / POINT_PIECE + (job->n % POINT_PIECE != 0);
    return bsi_parallel(bsi_thread_count(threads, pieces), pieces, points_task, job);
}

bs_status bs_surface_eval_mt(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                             const bs_cview *v, const bs_view *pos, const bs_view *du, const bs_view *dv,
                             size_t threads)
{
    if (n == 0)
        return s == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    size_t dim = bs_surface_dim(s);
    bs_status st = check_args(s, n, ids, u, v, 0, pos, dim, du, dim, dv, dim);
    if (st != BS_OK)
        return st;
    points_job job = {s, n, ids, u, v, pos, du, dv, NULL, NULL, 0};
    return run_points(&job, threads);
}

bs_status bs_surface_eval_normal_mt(const bs_surface *s, size_t n, const uint32_t *ids, const bs_cview *u,
                                    const bs_cview *v, const bs_view *pos, const bs_view *nrm, unsigned char *kind,
                                    size_t threads)
{
    if (n == 0)
        return s == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    bs_status st = check_args(s, n, ids, u, v, 1, pos, 3, nrm, 3, NULL, 0);
    if (st != BS_OK)
        return st;
    points_job job = {s, n, ids, u, v, pos, NULL, NULL, nrm, kind, 1};
    return run_points(&job, threads);
}

/* Grid rows per piece of bs_surface_eval_grid: about POINT_PIECE points. */
static size_t rows_per_piece(size_t nv) { return nv >= POINT_PIECE ? 1 : POINT_PIECE / nv; }

typedef struct grid_job {
    const bs_surface *s;
    size_t nu, nv, pieces; /* pieces per patch */
    const bs_cview *u, *v;
    const bs_view *pos, *du, *dv, *nrm;
    unsigned char *kind;
} grid_job;

/* Rows of one patch's grid, written at (patch * nu + row) * nv. */
static bs_status grid_task(void *ctx, size_t item, size_t worker)
{
    (void)worker;
    const grid_job *j = ctx;
    size_t p = item / j->pieces, rows = rows_per_piece(j->nv), i0 = (item % j->pieces) * rows;
    size_t nr = j->nu - i0 < rows ? j->nu - i0 : rows, first = (p * j->nu + i0) * j->nv;
    size_t dim = bs_surface_dim(j->s);
    bs_view spos[BS_MAX_DIM], sdu[BS_MAX_DIM], sdv[BS_MAX_DIM], snrm[3];
    bs_cview su = bsi_sub_cview(j->u, i0);
    return bs_patch_eval_grid(bs_surface_get(j->s, p), nr, &su, j->nv, j->v, bsi_sub_views(j->pos, dim, first, spos),
                              bsi_sub_views(j->du, dim, first, sdu), bsi_sub_views(j->dv, dim, first, sdv),
                              bsi_sub_views(j->nrm, 3, first, snrm), j->kind ? j->kind + first : NULL);
}

bs_status bs_surface_eval_grid(const bs_surface *s, size_t nu, const bs_cview *u, size_t nv, const bs_cview *v,
                               const bs_view *pos, const bs_view *du, const bs_view *dv, const bs_view *nrm,
                               unsigned char *kind, size_t threads)
{
    if (s == NULL || u == NULL || v == NULL)
        return BS_ERR_INVALID_ARG;
    size_t np = bs_surface_count(s), dim = bs_surface_dim(s);
    if ((nrm != NULL || kind != NULL) && dim != 3)
        return BS_ERR_DIMENSION;
    bs_status st;
    if ((st = bsi_check_cview(u, nu)) != BS_OK || (st = bsi_check_cview(v, nv)) != BS_OK)
        return st;
    if (nu != 0 && nv != 0 && (nv > SIZE_MAX / nu || np > SIZE_MAX / (nu * nv)))
        return BS_ERR_SIZE;
    size_t total = np * nu * nv;
    if ((pos && (st = bsi_check_views(pos, dim, total)) != BS_OK) ||
        (du && (st = bsi_check_views(du, dim, total)) != BS_OK) ||
        (dv && (st = bsi_check_views(dv, dim, total)) != BS_OK) ||
        (nrm && (st = bsi_check_views(nrm, 3, total)) != BS_OK))
        return st;
    if (total == 0)
        return BS_OK;
    size_t rows = rows_per_piece(nv), pieces = nu / rows + (nu % rows != 0);
    grid_job job = {s, nu, nv, pieces, u, v, pos, du, dv, nrm, kind};
    return bsi_parallel(bsi_thread_count(threads, np * pieces), np * pieces, grid_task, &job);
}
