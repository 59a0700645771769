/* Mesh export: the file and memory entry points, each running one of the format writers. */
#include "mesh/export.h"

#include <errno.h>

static int format_ok(int format)
{
    return format == BS_MESH_OBJ || format == BS_MESH_PLY || format == BS_MESH_PLY_ASCII ||
           format == BS_MESH_STL;
}

static void export_to(const bs_mesh *m, int format, bsi_sink *s)
{
    switch (format) {
    case BS_MESH_OBJ:       bsi_export_obj(m, s); break;
    case BS_MESH_PLY:       bsi_export_ply(m, 1, s); break;
    case BS_MESH_PLY_ASCII: bsi_export_ply(m, 0, s); break;
    default:                bsi_export_stl(m, s); break;
    }
}

bs_status bs_mesh_write(const bs_mesh *m, int format, const char *path)
{
    if (m == NULL || path == NULL || !format_ok(format))
        return BS_ERR_INVALID_ARG;
    if (format == BS_MESH_STL && m->ntri > UINT32_MAX)
        return BS_ERR_SIZE;
    bsi_out_file out;
    bs_status st = bsi_out_open(path, &out);
    if (st != BS_OK)
        return st;
    bsi_sink s = {out.f, NULL, 0, 0, 0};
    export_to(m, format, &s);
    if (s.err)
        errno = s.err;
    return bsi_out_close(&out, !s.err);
}

bs_status bs_mesh_write_memory(const bs_mesh *m, int format, void *buf, size_t cap, size_t *size)
{
    if (m == NULL || size == NULL || !format_ok(format))
        return BS_ERR_INVALID_ARG;
    if (format == BS_MESH_STL && m->ntri > UINT32_MAX)
        return BS_ERR_SIZE;
    bsi_sink count = {NULL, NULL, 0, 0, 0};
    export_to(m, format, &count);
    if (count.err)
        return BS_ERR_SIZE;
    if (buf == NULL) {
        *size = count.len;
        return BS_OK;
    }
    if (cap < count.len)
        return BS_ERR_SIZE;
    bsi_sink s = {NULL, buf, cap, 0, 0};
    export_to(m, format, &s);
    if (s.err || s.len != count.len)
        return BS_ERR_SIZE;
    *size = s.len;
    return BS_OK;
}
