/* Curvature as colours: see curvature_shade.h. */
#include "curvature_shade.h"
#include "colormap.h"

#include <math.h>
#include <stdlib.h>

bs_status curvature_at_vertices(const bs_surface *s, const bs_mesh *m, int gauss, double *out)
{
    size_t nv = bs_mesh_vertex_count(m), np = bs_surface_count(s);
    uint32_t *ids = malloc(nv * sizeof *ids + 1);
    size_t *start = calloc(np + 1, sizeof *start), *order = malloc(nv * sizeof *order + 1);
    double *u = malloc(nv * sizeof *u + 1), *v = malloc(nv * sizeof *v + 1);
    double *pu = malloc(nv * sizeof *pu + 1), *pv = malloc(nv * sizeof *pv + 1);
    double *kh = malloc(4 * nv * sizeof *kh + 1);
    bs_status st = BS_ERR_NO_MEMORY;
    bs_view uvw[2] = {{u, nv, sizeof(double)}, {v, nv, sizeof(double)}};
    if (ids && start && order && u && v && pu && pv && kh && (st = bs_mesh_copy_patch_ids(m, ids, nv)) == BS_OK &&
        (st = bs_mesh_copy_uv(m, uvw)) == BS_OK) {
        /* vertices grouped by patch (a counting sort), so each patch is asked once */
        for (size_t i = 0; i < nv; i++)
            if (ids[i] < np)
                start[ids[i] + 1]++;
        for (size_t p = 0; p < np; p++)
            start[p + 1] += start[p];
        for (size_t i = 0; i < nv; i++)
            if (ids[i] < np)
                order[start[ids[i]]++] = i;
        for (size_t i = 0; i < nv; i++)
            if (ids[i] >= np)
                out[i] = NAN;
        for (size_t p = 0, first = 0; st == BS_OK && p < np; first = start[p], p++) {
            size_t cnt = start[p] - first;
            for (size_t k = 0; k < cnt; k++) {
                pu[k] = u[order[first + k]];
                pv[k] = v[order[first + k]];
            }
            bs_cview cu = {pu, cnt, sizeof(double)}, cv = {pv, cnt, sizeof(double)};
            bs_view curv[4] = {{kh, cnt, sizeof(double)}, {kh + nv, cnt, sizeof(double)},
                               {kh + 2 * nv, cnt, sizeof(double)}, {kh + 3 * nv, cnt, sizeof(double)}};
            if (cnt > 0)
                st = bs_patch_eval_curvature(bs_surface_get(s, p), cnt, &cu, &cv, curv, NULL, NULL, NULL);
            for (size_t k = 0; st == BS_OK && k < cnt; k++)
                out[order[first + k]] = gauss ? kh[k] : kh[nv + k];
        }
    }
    free(ids);
    free(start);
    free(order);
    free(u);
    free(v);
    free(pu);
    free(pv);
    free(kh);
    return st;
}

void vertex_areas(const double *pos, size_t nv, const uint32_t *tri, size_t ntri, double *area)
{
    for (size_t i = 0; i < nv; i++)
        area[i] = 0.0;
    for (size_t t = 0; t < ntri; t++) {
        const double *a = pos + 3 * (size_t)tri[3 * t], *b = pos + 3 * (size_t)tri[3 * t + 1],
                     *c = pos + 3 * (size_t)tri[3 * t + 2];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double x = e[1] * f[2] - e[2] * f[1], y = e[2] * f[0] - e[0] * f[2], z = e[0] * f[1] - e[1] * f[0];
        double third = sqrt(x * x + y * y + z * z) / 6.0;
        for (int k = 0; k < 3; k++)
            area[tri[3 * t + (size_t)k]] += third;
    }
}

typedef struct weighted {
    double value, weight;
} weighted;

static int by_value(const void *a, const void *b)
{
    double x = ((const weighted *)a)->value, y = ((const weighted *)b)->value;
    return (x > y) - (x < y);
}

/* The value where the running weight of the sorted values reaches the fraction q of the total. */
static double weighted_percentile(const weighted *w, size_t m, double total, double q)
{
    double run = 0.0;
    for (size_t i = 0; i < m; i++) {
        run += w[i].weight;
        if (run >= q * total)
            return w[i].value;
    }
    return w[m - 1].value;
}

int curvature_summary(const double *val, const double *area, size_t n, curvature_range *out)
{
    weighted *w = malloc(n * sizeof *w + 1);
    if (w == NULL)
        return -1;
    size_t m = 0;
    double total = 0.0;
    for (size_t i = 0; i < n; i++)
        if (!isnan(val[i])) {
            w[m].value = val[i];
            w[m++].weight = area[i];
            total += area[i];
        }
    qsort(w, m, sizeof *w, by_value);
    out->undefined = n - m;
    out->range = 0.0;
    out->min = out->max = NAN;
    if (m > 0) {
        double lo = weighted_percentile(w, m, total, 0.05), hi = weighted_percentile(w, m, total, 0.95);
        out->range = fmax(fabs(lo), fabs(hi));
        out->min = w[0].value;
        out->max = w[m - 1].value;
    }
    free(w);
    return 0;
}

void curvature_colors(const double *val, size_t n, double range, double *rgb)
{
    for (size_t i = 0; i < n; i++)
        colormap_diverging(isnan(val[i]) ? NAN : range > 0.0 ? val[i] / range : 0.0, rgb + 3 * i);
}
