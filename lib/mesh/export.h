/*
 * The format writers behind bs_mesh_write and bs_mesh_write_memory (lib/mesh/export.c): each
 * writes a whole mesh into a sink, which records any failure. Private to lib/mesh/; not installed.
 */
#ifndef BEZSURF_MESH_EXPORT_H
#define BEZSURF_MESH_EXPORT_H

#include "mesh/internal.h"
#include "mesh/sink.h"

void bsi_export_obj(const bs_mesh *m, bsi_sink *s);
void bsi_export_ply(const bs_mesh *m, int binary, bsi_sink *s);
void bsi_export_stl(const bs_mesh *m, bsi_sink *s);

#endif
