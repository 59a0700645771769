/* The mesh object: counts and copies of its arrays into caller buffers. */
#include "mesh/internal.h"

#include <stdlib.h>

void bs_mesh_destroy(bs_mesh *m)
{
    if (m == NULL)
        return;
    free(m->pos);
    free(m->nrm);
    free(m->uv);
    free(m->xuv);
    free(m->xcorner);
    free(m->vpatch);
    free(m->tri);
    free(m->tpatch);
    free(m->strip_idx);
    free(m->strip_start);
    free(m);
}

size_t bs_mesh_vertex_count(const bs_mesh *m) { return m ? m->nvert : 0; }
size_t bs_mesh_triangle_count(const bs_mesh *m) { return m ? m->ntri : 0; }
size_t bs_mesh_strip_count(const bs_mesh *m) { return m ? m->nstrip : 0; }
size_t bs_mesh_strip_index_count(const bs_mesh *m) { return m ? m->nstrip_idx : 0; }

/* Scatter n packed k-tuples into k views (or, for the float twins, k float views, each value
 * rounded to float) after checking them all. */
static bs_status copy_tuples(const double *src, size_t n, size_t k, const bs_view *views,
                             const bs_fview *fviews)
{
    if (views == NULL && fviews == NULL)
        return BS_ERR_INVALID_ARG;
    if (n == 0)
        return BS_OK;
    bs_status st = views ? bsi_check_views(views, k, n) : bsi_check_fviews(fviews, k, n);
    if (st != BS_OK)
        return st;
    for (size_t c = 0; c < k; c++)
        for (size_t i = 0; i < n; i++) {
            if (views)
                *bsi_at(&views[c], i) = src[i * k + c];
            else
                *bsi_fat(&fviews[c], i) = (float)src[i * k + c];
        }
    return BS_OK;
}

static bs_status copy_ids(const uint32_t *src, size_t n, uint32_t *dst, size_t cap)
{
    if (dst == NULL)
        return BS_ERR_INVALID_ARG;
    if (cap < n)
        return BS_ERR_SIZE;
    for (size_t i = 0; i < n; i++)
        dst[i] = src[i];
    return BS_OK;
}

bs_status bs_mesh_copy_positions(const bs_mesh *m, const bs_view xyz[3])
{
    return m ? copy_tuples(m->pos, m->nvert, 3, xyz, NULL) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_normals(const bs_mesh *m, const bs_view nrm[3])
{
    return m ? copy_tuples(m->nrm, m->nvert, 3, nrm, NULL) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_uv(const bs_mesh *m, const bs_view uv[2])
{
    return m ? copy_tuples(m->uv, m->nvert, 2, uv, NULL) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_positions_f32(const bs_mesh *m, const bs_fview xyz[3])
{
    return m ? copy_tuples(m->pos, m->nvert, 3, NULL, xyz) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_normals_f32(const bs_mesh *m, const bs_fview nrm[3])
{
    return m ? copy_tuples(m->nrm, m->nvert, 3, NULL, nrm) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_uv_f32(const bs_mesh *m, const bs_fview uv[2])
{
    return m ? copy_tuples(m->uv, m->nvert, 2, NULL, uv) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_corner_uv(const bs_mesh *m, const bs_view uv[2])
{
    if (m == NULL || uv == NULL)
        return BS_ERR_INVALID_ARG;
    size_t n = 3 * m->ntri;
    if (n == 0)
        return BS_OK;
    bs_status st = bsi_check_views(uv, 2, n);
    if (st != BS_OK)
        return st;
    /* the vertex's (u,v), or the corner's own where the mesh lists it */
    for (size_t k = 0, x = 0; k < n; k++) {
        const double *src = m->uv + 2 * (size_t)m->tri[k];
        if (x < m->nx && m->xcorner[x] == k)
            src = m->xuv + 2 * x++;
        *bsi_at(&uv[0], k) = src[0];
        *bsi_at(&uv[1], k) = src[1];
    }
    return BS_OK;
}

bs_status bs_mesh_copy_patch_ids(const bs_mesh *m, uint32_t *ids, size_t cap)
{
    return m ? copy_ids(m->vpatch, m->nvert, ids, cap) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_triangles(const bs_mesh *m, uint32_t *idx, size_t cap)
{
    return m ? copy_ids(m->tri, 3 * m->ntri, idx, cap) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_triangle_patch_ids(const bs_mesh *m, uint32_t *ids, size_t cap)
{
    return m ? copy_ids(m->tpatch, m->ntri, ids, cap) : BS_ERR_INVALID_ARG;
}

bs_status bs_mesh_copy_strips(const bs_mesh *m, uint32_t *idx, size_t idx_cap, uint32_t *start,
                              size_t start_cap)
{
    if (m == NULL || idx == NULL || start == NULL)
        return BS_ERR_INVALID_ARG;
    if (idx_cap < m->nstrip_idx || start_cap < m->nstrip + 1)
        return BS_ERR_SIZE;
    for (size_t i = 0; i < m->nstrip_idx; i++)
        idx[i] = m->strip_idx[i];
    for (size_t k = 0; k <= m->nstrip; k++)
        start[k] = m->nstrip ? m->strip_start[k] : 0;
    return BS_OK;
}
