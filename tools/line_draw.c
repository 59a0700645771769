/* Lines of render over the surface: control nets and triangle edges. */
#include "line_draw.h"

#include <stdlib.h>

void draw_nets(raster *r, const bs_surface *s)
{
    static const double ink[3] = {0.62, 0.08, 0.06}, dot[3] = {0.1, 0.1, 0.1};
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p), cnt = (m + 1) * (n + 1);
        double *net = malloc(3 * cnt * sizeof(double));
        if (net == NULL || bs_patch_get_ctrl(p, net, 3 * cnt, NULL, 0) != BS_OK) {
            free(net);
            continue;
        }
        for (size_t a = 0; a <= m; a++)
            for (size_t b = 0; b <= n; b++) {
                const double *x = net + 3 * (a * (n + 1) + b);
                if (a < m)
                    raster_line(r, x, net + 3 * ((a + 1) * (n + 1) + b), 1.5, ink);
                if (b < n)
                    raster_line(r, x, net + 3 * (a * (n + 1) + b + 1), 1.5, ink);
                raster_line(r, x, x, 5.0, dot);
            }
        free(net);
    }
}

void draw_wire(raster *r, const double *pos, const uint32_t *tri, size_t nt)
{
    static const double ink[3] = {0.08, 0.09, 0.14};
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            raster_line(r, pos + 3 * (size_t)tri[3 * t + (size_t)k], pos + 3 * (size_t)tri[3 * t + (size_t)(k + 1) % 3],
                        0.6, ink);
}
