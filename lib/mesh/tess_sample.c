/*
 * Tessellation phase 3, and the normal repair of phase 5: every vertex's parameters, position and
 * normal, side samples as lists and each patch's interior as a tensor grid.
 */
#include "mesh/tess.h"

#include <math.h>
#include <stdlib.h>

/* A normal the mesh cannot keep: undefined, or not of unit length (overflow, NaN). */
static int normal_bad(unsigned char kind, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    return kind == BS_NORMAL_UNDEFINED || !(fabs(len - 1.0) < 1e-6);
}

/* out[3k + c] = the k-th of x, y, z (c = 0, 1, 2): flat, so that GCC vectorises the interleave */
BSI_INLINE void interleave3(size_t n, const double *restrict x, const double *restrict y,
                            const double *restrict z, double *restrict out)
{
    for (size_t k = 0; k < n; k++) {
        out[3 * k] = x[k];
        out[3 * k + 1] = y[k];
        out[3 * k + 2] = z[k];
    }
}

/* Move nr x nj grid results (rows i0.., by coordinate in w->soa) into the mesh's packed arrays at
 * vertex `first`, with their (u,v) and patch id; count the normals to repair. Compiled for each
 * vector width: a copy, the same bits. */
BSI_HOT static void store_block(const tess *t, tess_scratch *w, uint32_t patch, size_t first, size_t i0,
                                size_t nr, size_t nj)
{
    const double *restrict x = w->soa, *restrict y = x + GRID_CHUNK, *restrict z = y + GRID_CHUNK;
    const double *restrict nx = z + GRID_CHUNK, *restrict ny = nx + GRID_CHUNK, *restrict nz = ny + GRID_CHUNK;
    const double *restrict pv = w->pv + 1;
    double *restrict uv = t->uv + 2 * first;
    uint32_t *restrict vp = t->vpatch + first;
    const unsigned char *restrict kind = t->kind + first;
    size_t bad = 0, npt = nr * nj;
    interleave3(npt, x, y, z, t->pos + 3 * first);
    interleave3(npt, nx, ny, nz, t->nrm + 3 * first);
    for (size_t r = 0; r < nr; r++) {
        double u = w->pu[1 + i0 + r], *restrict row = uv + 2 * r * nj;
        for (size_t j = 0; j < nj; j++) {
            row[2 * j] = u;
            row[2 * j + 1] = pv[j];
        }
    }
    for (size_t k = 0; k < npt; k++)
        vp[k] = patch;
    /* |len^2 - 1| < 1e-6 implies |len - 1| < 1e-6: only the rest need normal_bad's square root */
    for (size_t k = 0; k < npt; k++) {
        double q = nx[k] * nx[k] + ny[k] * ny[k] + nz[k] * nz[k];
        if (!(fabs(q - 1.0) < 1e-6) || kind[k] == BS_NORMAL_UNDEFINED)
            bad += (size_t)normal_bad(kind[k], nx[k], ny[k], nz[k]);
    }
    w->nbad += bad;
}

/* Views of coordinates 0..2 of the packed triples x[3*first ...], n elements. */
static void triple_views(double *x, size_t first, size_t n, bs_view out[3])
{
    for (size_t c = 0; c < 3; c++) {
        out[c].data = x + 3 * first + c;
        out[c].count = n;
        out[c].stride = (ptrdiff_t)(3 * sizeof(double));
    }
}

bs_status bsi_tess_eval_list(const tess *t, uint32_t p, size_t first, size_t n, size_t *nbad)
{
    for (size_t id = first; id < first + n; id++)
        t->vpatch[id] = p;
    if (n == 0)
        return BS_OK;
    ptrdiff_t s2 = (ptrdiff_t)(2 * sizeof(double));
    bs_view pos[3], nrm[3];
    bs_cview cu = {t->uv + 2 * first, n, s2}, cv = {t->uv + 2 * first + 1, n, s2};
    triple_views(t->pos, first, n, pos);
    triple_views(t->nrm, first, n, nrm);
    bs_status st = bs_patch_eval_normal(bs_surface_get(t->s, p), n, &cu, &cv, pos, nrm, t->kind + first);
    if (st != BS_OK)
        return st;
    for (size_t id = first; id < first + n; id++) {
        const double *nr = t->nrm + 3 * id;
        *nbad += (size_t)normal_bad(t->kind[id], nr[0], nr[1], nr[2]);
    }
    return BS_OK;
}

/* Largest grid of any patch, per direction (at least 1). */
static size_t max_grid(const tess *t)
{
    size_t gmax = 1;
    for (size_t p = 0; p < t->np; p++) {
        gmax = t->plan[p].gu > gmax ? t->plan[p].gu : gmax;
        gmax = t->plan[p].gv > gmax ? t->plan[p].gv : gmax;
    }
    return gmax;
}

/* Patch p: its side samples' parameters, those samples (vertices vert0..inner0-1) as a list, its
 * interior as one grid in blocks of rows. Writes only patch p's vertices: patches run in parallel. */
static bs_status sample_patch(const tess *t, size_t p, tess_scratch *w)
{
    const patch_plan *pl = &t->plan[p];
    const bs_patch *patch = bs_surface_get(t->s, p);
    for (int s = 0; s < 4; s++)
        for (size_t k = 0; k <= pl->e[s]; k++) {
            size_t slot = side_slot(pl, s, k);
            if (t->parent[slot] != slot) /* roots are final after the plan: no path to compress */
                continue;
            uint32_t id = t->slot_vert[slot];
            side_param(pl, s, k, &t->uv[2 * (size_t)id], &t->uv[2 * (size_t)id + 1]);
        }
    bs_status st = bsi_tess_eval_list(t, (uint32_t)p, pl->vert0, pl->inner0 - pl->vert0, &w->nbad);
    size_t ni = pl->gu - 1, nj = pl->gv - 1;
    if (st != BS_OK || ni == 0 || nj == 0)
        return st;
    grid_params(w->pu, pl->gu);
    grid_params(w->pv, pl->gv);
    bs_view pos[3], nrm[3];
    /* blocks of whole rows, evaluated by coordinate, then interleaved into the mesh */
    size_t rows = GRID_CHUNK / nj;
    for (size_t i0 = 0; i0 < ni; i0 += rows) {
        size_t nr = ni - i0 < rows ? ni - i0 : rows, npt = nr * nj, first = pl->inner0 + i0 * nj;
        bs_cview gu = {w->pu + 1 + i0, nr, (ptrdiff_t)sizeof(double)};
        bs_cview gv = {w->pv + 1, nj, (ptrdiff_t)sizeof(double)};
        for (size_t c = 0; c < 3; c++) {
            pos[c].data = w->soa + c * GRID_CHUNK;
            nrm[c].data = w->soa + (3 + c) * GRID_CHUNK;
            pos[c].count = nrm[c].count = npt;
            pos[c].stride = nrm[c].stride = (ptrdiff_t)sizeof(double);
        }
        st = bs_patch_eval_grid(patch, nr, &gu, nj, &gv, pos, NULL, NULL, nrm, t->kind + first);
        if (st != BS_OK)
            return st;
        store_block(t, w, (uint32_t)p, first, i0, nr, nj);
    }
    return BS_OK;
}

typedef struct sample_job { const tess *t; tess_scratch *w; } sample_job;

static bs_status sample_task(void *ctx, size_t p, size_t worker)
{
    sample_job *job = ctx;
    return sample_patch(job->t, p, &job->w[worker]);
}

/* Scratch of `workers` threads in t->work, each for grids up to gmax (freed by bsi_tess_free); one
 * thread allocates no more than its block of rows (its parameters are t->pu, t->pv). */
static bs_status scratch_alloc(tess *t, size_t workers, size_t gmax)
{
    t->work = workers > 1 ? calloc(workers, sizeof(tess_scratch)) : &t->work1;
    if (t->work == NULL)
        return BS_ERR_NO_MEMORY;
    t->nwork = workers;
    t->work1 = (tess_scratch){t->pu, t->pv, NULL, 0};
    for (size_t k = 0; k < workers; k++) {
        tess_scratch *w = &t->work[k];
        w->pu = workers > 1 ? malloc((gmax + 1) * sizeof(double)) : t->pu;
        w->pv = workers > 1 ? malloc((gmax + 1) * sizeof(double)) : t->pv;
        w->soa = malloc(6 * GRID_CHUNK * sizeof(double));
        if (!w->pu || !w->pv || !w->soa)
            return BS_ERR_NO_MEMORY;
    }
    return BS_OK;
}

/* The mesh's vertex arrays, then every patch sampled, on up to t->threads threads. */
bs_status bsi_tess_evaluate(tess *t)
{
    size_t nv = t->nvert, gmax = max_grid(t), workers = bsi_thread_count(t->threads, t->np);
    t->pos = malloc((nv ? nv : 1) * 3 * sizeof(double));
    t->nrm = malloc((nv ? nv : 1) * 3 * sizeof(double));
    t->uv = malloc((nv ? nv : 1) * 2 * sizeof(double));
    t->vpatch = malloc((nv ? nv : 1) * sizeof(uint32_t));
    t->kind = malloc(nv ? nv : 1);
    t->pu = malloc((gmax + 1) * sizeof(double)); /* for the emission phase */
    t->pv = malloc((gmax + 1) * sizeof(double));
    if (!t->pos || !t->nrm || !t->uv || !t->vpatch || !t->kind || !t->pu || !t->pv)
        return BS_ERR_NO_MEMORY;
    bs_status st = scratch_alloc(t, workers, gmax);
    if (st != BS_OK)
        return st;
    sample_job job = {t, t->work};
    st = bsi_parallel(workers, t->np, sample_task, &job);
    for (size_t k = 0; k < workers; k++)
        t->nbad += t->work[k].nbad;
    return st;
}

/* Normals the surface does not define at a vertex (kind UNDEFINED, or not unit) become the
 * normalised sum of the adjacent triangles' normals, (0,0,1) when those cancel. */
void bsi_tess_repair_normals(tess *t)
{
    if (t->nbad == 0)
        return; /* bsi_tess_evaluate() checked every vertex */
    size_t bad = 0;
    for (size_t k = 0; k < t->nvert; k++) {
        double *n = t->nrm + 3 * k;
        if (normal_bad(t->kind[k], n[0], n[1], n[2])) {
            t->kind[k] = BS_NORMAL_UNDEFINED;
            n[0] = n[1] = n[2] = 0.0;
            bad++;
        }
    }
    if (bad == 0)
        return;
    for (size_t f = 0; f < t->tri.n / 3; f++) {
        const uint32_t *v = t->tri.v + 3 * f;
        const double *a = t->pos + 3 * (size_t)v[0], *b = t->pos + 3 * (size_t)v[1], *c = t->pos + 3 * (size_t)v[2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double fn[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            if (t->kind[v[k]] == BS_NORMAL_UNDEFINED)
                for (int c2 = 0; c2 < 3; c2++)
                    t->nrm[3 * (size_t)v[k] + (size_t)c2] += fn[c2];
    }
    for (size_t k = 0; k < t->nvert; k++) {
        if (t->kind[k] != BS_NORMAL_UNDEFINED)
            continue;
        double *n = t->nrm + 3 * k;
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.0 && isfinite(len)) {
            n[0] /= len;
            n[1] /= len;
            n[2] /= len;
        } else {
            n[0] = 0.0;
            n[1] = 0.0;
            n[2] = 1.0;
        }
    }
}
