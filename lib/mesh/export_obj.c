/* Wavefront OBJ: v, vt, vn per vertex and f v/vt/vn per triangle (1-based, shared indices). */
#include "mesh/export.h"

static void triple(bsi_sink *s, const char *tag, const double *x, size_t k)
{
    bsi_sink_str(s, tag);
    for (size_t c = 0; c < k; c++) {
        bsi_sink_str(s, " ");
        bsi_sink_double(s, x[c], 0); /* the shortest exact form, as the surface writers */
    }
    bsi_sink_str(s, "\n");
}

void bsi_export_obj(const bs_mesh *m, bsi_sink *s)
{
    bsi_sink_str(s, "# libbezsurf mesh: ");
    bsi_sink_uint(s, m->nvert);
    bsi_sink_str(s, " vertices, ");
    bsi_sink_uint(s, m->ntri);
    bsi_sink_str(s, " triangles\n");
    for (size_t k = 0; k < m->nvert; k++)
        triple(s, "v", m->pos + 3 * k, 3);
    for (size_t k = 0; k < m->nvert; k++)
        triple(s, "vt", m->uv + 2 * k, 2);
    for (size_t k = 0; k < m->nvert; k++)
        triple(s, "vn", m->nrm + 3 * k, 3);
    for (size_t t = 0; t < m->ntri; t++) {
        bsi_sink_str(s, "f");
        for (size_t c = 0; c < 3; c++) {
            size_t i = (size_t)m->tri[3 * t + c] + 1;
            bsi_sink_str(s, " ");
            bsi_sink_uint(s, i);
            bsi_sink_str(s, "/");
            bsi_sink_uint(s, i);
            bsi_sink_str(s, "/");
            bsi_sink_uint(s, i);
        }
        bsi_sink_str(s, "\n");
    }
}
