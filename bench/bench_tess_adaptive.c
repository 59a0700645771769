/* Adaptive tessellation, one rate per patch (BS_TESS_PER_PATCH) against recursive subdivision
 * (BS_TESS_SUBDIVIDE), side by side on the tea set at absolute tolerances 1e-2, 1e-3 and 1e-4:
 * triangles, the worst chordal error over the tolerance, and the best wall-clock time of a few
 * calls. The error is the documented metric: the largest distance between a point of a triangle
 * and the surface at the point's (u,v), over the 21 barycentric points (i, j, k) / 5 of every
 * triangle (the surface evaluated by bs_patch_eval, one batch per run of triangles of a patch).
 * Usage: bench_tess_adaptive [REPEATS] (default 5). */
#define _POSIX_C_SOURCE 199309L
#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Worst chordal error of mesh m of surface s over the 21 points of every triangle; -1 on failure. */
static double worst_error(const bs_surface *s, const bs_mesh *m)
{
    size_t nv = bs_mesh_vertex_count(m), nt = bs_mesh_triangle_count(m);
    double *pos = malloc(3 * nv * sizeof(double) + 8), *cuv = malloc(6 * nt * sizeof(double) + 8);
    uint32_t *tri = malloc(3 * nt * sizeof(uint32_t) + 4), *tp = malloc(nt * sizeof(uint32_t) + 4);
    size_t cap = 21 * 4096;
    double *u = malloc(cap * sizeof(double)), *v = malloc(cap * sizeof(double));
    double *lin = malloc(3 * cap * sizeof(double)), *srf = malloc(3 * cap * sizeof(double));
    double worst = -1.0;
    ptrdiff_t s3 = 3 * sizeof(double), s2 = 2 * sizeof(double), s1 = sizeof(double);
    bs_view pv[3] = {{pos, nv, s3}, {pos + 1, nv, s3}, {pos + 2, nv, s3}};
    bs_view cv[2] = {{cuv, 3 * nt, s2}, {cuv + 1, 3 * nt, s2}};
    if (!pos || !cuv || !tri || !tp || !u || !v || !lin || !srf || bs_mesh_copy_positions(m, pv) != BS_OK ||
        bs_mesh_copy_corner_uv(m, cv) != BS_OK || bs_mesh_copy_triangles(m, tri, 3 * nt) != BS_OK ||
        bs_mesh_copy_triangle_patch_ids(m, tp, nt) != BS_OK)
        goto done;
    worst = 0.0;
    for (size_t t0 = 0; t0 < nt;) {
        size_t t1 = t0, n = 0;
        while (t1 < nt && tp[t1] == tp[t0] && t1 - t0 < 4096) {
            const double *c = cuv + 6 * t1;
            for (int i = 0; i <= 5; i++)
                for (int j = 0; i + j <= 5; j++, n++) {
                    double l[3] = {i / 5.0, j / 5.0, (5 - i - j) / 5.0};
                    u[n] = v[n] = 0.0;
                    lin[3 * n] = lin[3 * n + 1] = lin[3 * n + 2] = 0.0;
                    for (int k = 0; k < 3; k++) {
                        u[n] += l[k] * c[2 * k];
                        v[n] += l[k] * c[2 * k + 1];
                        for (int x = 0; x < 3; x++)
                            lin[3 * n + (size_t)x] += l[k] * pos[3 * (size_t)tri[3 * t1 + (size_t)k] + (size_t)x];
                    }
                }
            t1++;
        }
        bs_cview cu = {u, n, s1}, cvv = {v, n, s1};
        bs_view out[3] = {{srf, n, s3}, {srf + 1, n, s3}, {srf + 2, n, s3}};
        if (bs_patch_eval(bs_surface_get(s, tp[t0]), n, &cu, &cvv, out, NULL, NULL) != BS_OK) {
            worst = -1.0;
            goto done;
        }
        for (size_t k = 0; k < n; k++) {
            double dx = srf[3 * k] - lin[3 * k], dy = srf[3 * k + 1] - lin[3 * k + 1], dz = srf[3 * k + 2] - lin[3 * k + 2];
            worst = fmax(worst, sqrt(dx * dx + dy * dy + dz * dz));
        }
        t0 = t1;
    }
done:
    free(pos);
    free(cuv);
    free(tri);
    free(tp);
    free(u);
    free(v);
    free(lin);
    free(srf);
    return worst;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1)
        repeats = 1;
    static const double tols[] = {1e-2, 1e-3, 1e-4};
    static const int methods[] = {BS_TESS_PER_PATCH, BS_TESS_SUBDIVIDE};
    printf("%-9s %-9s | %-35s | %-35s | %s\n", "surface", "tolerance", "per-patch: triangles, error/tol, ms",
           "subdivide: triangles, error/tol, ms", "triangles subdivide/per-patch");
    const char *name;
    for (size_t k = 0; (name = bs_builtin_name(k)) != NULL; k++) {
        bs_surface *s = NULL;
        if (bs_surface_create_builtin(name, &s) != BS_OK)
            return 1;
        for (size_t t = 0; t < sizeof tols / sizeof tols[0]; t++) {
            size_t ntri[2];
            printf("%-9s %-9g", name, tols[t]);
            for (size_t q = 0; q < 2; q++) {
                bs_tess_options o;
                bs_tess_options_init(&o);
                o.method = methods[q];
                o.tolerance = tols[t];
                double best = INFINITY;
                bs_mesh *m = NULL;
                for (int r = 0; r < repeats; r++) {
                    bs_mesh_destroy(m);
                    m = NULL;
                    double t0 = now();
                    if (bs_surface_tessellate(s, &o, &m) != BS_OK)
                        return 1;
                    best = fmin(best, now() - t0);
                }
                ntri[q] = bs_mesh_triangle_count(m);
                printf(" | %10zu %6.3f %9.2f ms      ", ntri[q], worst_error(s, m) / tols[t], 1e3 * best);
                bs_mesh_destroy(m);
            }
            printf(" | %.3f\n", (double)ntri[1] / (double)ntri[0]);
        }
        bs_surface_destroy(s);
    }
    return 0;
}
