/*
 * The locator's batch queries on several threads. The queries are cut into pieces fixed by their
 * number alone, and each piece is answered by the single-threaded entry point on sub-views of the
 * caller's, so every answer is the same bits whatever the thread count (queries never depend on
 * each other) and the locator, immutable, needs no lock.
 */
#include "query/locator.h"

/* Queries per piece: a closest point costs tens of microseconds, a ray a few, so that a piece
 * hides the hand-out and the pieces still balance on a few cores. */
#define CLOSEST_PIECE ((size_t)64)
#define RAY_PIECE ((size_t)512)

static size_t piece_count(size_t n, size_t piece) { return n / piece + (n % piece != 0); }

typedef struct closest_job {
    const bs_locator *L;
    size_t n;
    const bs_cview *q;
    uint32_t *patch;
    const bs_view *uv, *dist, *pos;
} closest_job;

static bs_status closest_task(void *ctx, size_t item, size_t worker)
{
    (void)worker;
    const closest_job *j = ctx;
    size_t first = item * CLOSEST_PIECE, len = j->n - first < CLOSEST_PIECE ? j->n - first : CLOSEST_PIECE;
    bs_cview q[BS_MAX_DIM];
    bs_view uv[2], dist[1], pos[BS_MAX_DIM];
    for (size_t c = 0; c < j->L->dim; c++)
        q[c] = bsi_sub_cview(&j->q[c], first);
    return bs_locator_closest_point(j->L, len, q, j->patch ? j->patch + first : NULL,
                                    bsi_sub_views(j->uv, 2, first, uv), bsi_sub_views(j->dist, 1, first, dist),
                                    bsi_sub_views(j->pos, j->L->dim, first, pos));
}

bs_status bs_locator_closest_point_mt(const bs_locator *L, size_t n, const bs_cview *q, uint32_t *patch,
                                      const bs_view *uv, const bs_view *dist, const bs_view *pos,
                                      size_t threads)
{
    bs_status st = bsi_loc_closest_check(L, n, q, uv, dist, pos);
    if (st != BS_OK || n == 0)
        return st;
    size_t pieces = piece_count(n, CLOSEST_PIECE), workers = bsi_thread_count(threads, pieces);
    if (workers == 1) /* one call: nothing is written when memory runs out */
        return bs_locator_closest_point(L, n, q, patch, uv, dist, pos);
    closest_job job = {L, n, q, patch, uv, dist, pos};
    return bsi_parallel(workers, pieces, closest_task, &job);
}

typedef struct ray_job {
    const bs_locator *L;
    size_t n;
    const bs_cview *org, *dir, *trange;
    uint32_t *patch;
    const bs_view *uv, *t, *nrm;
} ray_job;

static bs_status ray_task(void *ctx, size_t item, size_t worker)
{
    (void)worker;
    const ray_job *j = ctx;
    size_t first = item * RAY_PIECE, len = j->n - first < RAY_PIECE ? j->n - first : RAY_PIECE;
    bs_cview org[3], dir[3], range[2];
    bs_view uv[2], t[1], nrm[3];
    for (int c = 0; c < 3; c++) {
        org[c] = bsi_sub_cview(&j->org[c], first);
        dir[c] = bsi_sub_cview(&j->dir[c], first);
    }
    for (int c = 0; c < 2 && j->trange; c++)
        range[c] = bsi_sub_cview(&j->trange[c], first);
    return bs_locator_intersect(j->L, len, org, dir, j->trange ? range : NULL,
                                j->patch ? j->patch + first : NULL, bsi_sub_views(j->uv, 2, first, uv),
                                bsi_sub_views(j->t, 1, first, t), bsi_sub_views(j->nrm, 3, first, nrm));
}

bs_status bs_locator_intersect_mt(const bs_locator *L, size_t n, const bs_cview *org, const bs_cview *dir,
                                  const bs_cview *trange, uint32_t *patch, const bs_view *uv,
                                  const bs_view *t, const bs_view *nrm, size_t threads)
{
    bs_status st = bsi_loc_intersect_check(L, n, org, dir, trange, uv, t, nrm);
    if (st != BS_OK || n == 0)
        return st;
    size_t pieces = piece_count(n, RAY_PIECE), workers = bsi_thread_count(threads, pieces);
    if (workers == 1)
        return bs_locator_intersect(L, n, org, dir, trange, patch, uv, t, nrm);
    ray_job job = {L, n, org, dir, trange, patch, uv, t, nrm};
    return bsi_parallel(workers, pieces, ray_task, &job);
}
