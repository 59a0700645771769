/* Meshes from arrays built above the mesh layer (mesh/build.h). */
#include "mesh/build.h"
#include "mesh/internal.h"

#include <stdlib.h>
#include <string.h>

void bsi_mesh_parts_free(bsi_mesh_parts *parts)
{
    free(parts->pos);
    free(parts->nrm);
    free(parts->uv);
    free(parts->vpatch);
    free(parts->tri);
    free(parts->tpatch);
    free(parts->xcorner);
    free(parts->xuv);
    memset(parts, 0, sizeof *parts);
}

bs_status bsi_mesh_adopt(bsi_mesh_parts *parts, bs_mesh **out)
{
    bs_mesh *m = calloc(1, sizeof *m);
    if (m == NULL) {
        bsi_mesh_parts_free(parts);
        return BS_ERR_NO_MEMORY;
    }
    m->nvert = parts->nvert;
    m->ntri = parts->ntri;
    m->nx = parts->nx;
    m->pos = parts->pos;
    m->nrm = parts->nrm;
    m->uv = parts->uv;
    m->vpatch = parts->vpatch;
    m->tri = parts->tri;
    m->tpatch = parts->tpatch;
    m->xcorner = parts->xcorner;
    m->xuv = parts->xuv;
    memset(parts, 0, sizeof *parts);
    *out = m;
    return BS_OK;
}
