/* PLY (binary little-endian or ASCII): vertices with position, normal, (u,v) and patch id; faces as
 * uchar-counted lists of uint indices. */
#include "mesh/export.h"

static void header(const bs_mesh *m, int binary, bsi_sink *s)
{
    bsi_sink_str(s, binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n");
    bsi_sink_str(s, "comment libbezsurf mesh\nelement vertex ");
    bsi_sink_uint(s, m->nvert);
    bsi_sink_str(s, "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float nx\nproperty float ny\nproperty float nz\n"
                    "property float u\nproperty float v\nproperty uint patch\nelement face ");
    bsi_sink_uint(s, m->ntri);
    bsi_sink_str(s, "\nproperty list uchar uint vertex_indices\nend_header\n");
}

void bsi_export_ply(const bs_mesh *m, int binary, bsi_sink *s)
{
    header(m, binary, s);
    for (size_t k = 0; k < m->nvert; k++) {
        double x[8] = {m->pos[3 * k], m->pos[3 * k + 1], m->pos[3 * k + 2], m->nrm[3 * k], m->nrm[3 * k + 1],
                       m->nrm[3 * k + 2], m->uv[2 * k], m->uv[2 * k + 1]};
        for (size_t c = 0; c < 8; c++) {
            if (binary) {
                bsi_sink_f32le(s, x[c]);
            } else {
                bsi_sink_double(s, x[c], 9);
                bsi_sink_str(s, " ");
            }
        }
        if (binary) {
            bsi_sink_u32le(s, m->vpatch[k]);
        } else {
            bsi_sink_uint(s, m->vpatch[k]);
            bsi_sink_str(s, "\n");
        }
    }
    for (size_t t = 0; t < m->ntri; t++) {
        if (binary) {
            unsigned char three = 3;
            bsi_sink_put(s, &three, 1);
            for (size_t c = 0; c < 3; c++)
                bsi_sink_u32le(s, m->tri[3 * t + c]);
        } else {
            bsi_sink_str(s, "3");
            for (size_t c = 0; c < 3; c++) {
                bsi_sink_str(s, " ");
                bsi_sink_uint(s, m->tri[3 * t + c]);
            }
            bsi_sink_str(s, "\n");
        }
    }
}
