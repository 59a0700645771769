/* Binary STL: 80-byte header, triangle count, then per triangle a facet normal computed from its
 * corners (the vertex normals have no place in STL), the three corners and a zero attribute. */
#include "mesh/export.h"

#include <math.h>
#include <string.h>

void bsi_export_stl(const bs_mesh *m, bsi_sink *s)
{
    char head[80];
    memset(head, ' ', sizeof head);
    memcpy(head, "libbezsurf mesh (binary STL)", 28); // NOLINT(bugprone-not-null-terminated-result): a space-padded header, not a string
    bsi_sink_put(s, head, sizeof head);
    bsi_sink_u32le(s, (uint32_t)m->ntri);
    for (size_t t = 0; t < m->ntri; t++) {
        const double *a = m->pos + 3 * (size_t)m->tri[3 * t], *b = m->pos + 3 * (size_t)m->tri[3 * t + 1];
        const double *c = m->pos + 3 * (size_t)m->tri[3 * t + 2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (size_t k = 0; k < 3; k++)
            bsi_sink_f32le(s, len > 0.0 ? n[k] / len : 0.0);
        for (size_t k = 0; k < 3; k++)
            bsi_sink_f32le(s, a[k]);
        for (size_t k = 0; k < 3; k++)
            bsi_sink_f32le(s, b[k]);
        for (size_t k = 0; k < 3; k++)
            bsi_sink_f32le(s, c[k]);
        unsigned char attr[2] = {0, 0};
        bsi_sink_put(s, attr, 2);
    }
}
