/*
 * Rays: the locator on the exact teapot against Embree 3 on the teapot tessellated by this
 * library at 64 x 64 segments per patch (bs_surface_tessellate_uniform, single-precision
 * triangles), the same N x N camera rays, one thread (rtcIntersect1 ray by ray, Embree made with
 * one thread too; bs_locator_intersect over the batch), CPU time. Embree answers on the mesh, the
 * locator on the surface: hit counts differ a little at the silhouette. Built only when Embree 3
 * is found.
 * Then as many incoherent rays, from random points of the teapot's box in random directions,
 * through both.
 * Usage: bench_rays_embree [N]
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "rays_camera.h"

#include <bezsurf.h>
#include <embree3/rtcore.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The teapot's 64 x 64 mesh as an Embree scene, or NULL. */
static RTCScene embree_scene(RTCDevice dev, const bs_surface *s, size_t *ntri)
{
    bs_mesh *m = NULL;
    if (bs_surface_tessellate_uniform(s, 64, 64, 0, &m) != BS_OK)
        return NULL;
    size_t nv = bs_mesh_vertex_count(m), nt = bs_mesh_triangle_count(m);
    double *xyz = malloc(3 * nv * sizeof(double));
    RTCScene scene = rtcNewScene(dev);
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv);
    unsigned *ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt);
    bs_view v[3] = {{xyz, nv, 0}, {xyz + nv, nv, 0}, {xyz + 2 * nv, nv, 0}};
    int ok = xyz && vb && ib && bs_mesh_copy_positions(m, v) == BS_OK &&
             bs_mesh_copy_triangles(m, (uint32_t *)ib, 3 * nt) == BS_OK;
    for (size_t k = 0; ok && k < nv; k++)
        for (int c = 0; c < 3; c++)
            vb[3 * k + (size_t)c] = (float)xyz[(size_t)c * nv + k];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    free(xyz);
    bs_mesh_destroy(m);
    *ntri = nt;
    if (!ok) {
        rtcReleaseScene(scene);
        return NULL;
    }
    return scene;
}

/* Seconds Embree takes for rays 0 .. n-1 (o + t d, t from tnear), counting its hits. */
static double embree_rays(RTCScene scene, size_t n, double *const o[3], double *const d[3],
                          float tnear, size_t *hits)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    double t0 = now();
    *hits = 0;
    for (size_t k = 0; k < n; k++) {
        struct RTCRayHit rh;
        rh.ray.org_x = (float)o[0][k];
        rh.ray.org_y = (float)o[1][k];
        rh.ray.org_z = (float)o[2][k];
        rh.ray.dir_x = (float)d[0][k];
        rh.ray.dir_y = (float)d[1][k];
        rh.ray.dir_z = (float)d[2][k];
        rh.ray.tnear = tnear;
        rh.ray.tfar = INFINITY;
        rh.ray.mask = (unsigned)-1;
        rh.ray.flags = 0;
        rh.ray.time = 0.0f;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        *hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    return now() - t0;
}

/* Seconds the locator takes for the same rays (one batch), counting its hits; -1 on failure. */
static double locator_rays(const bs_locator *L, size_t n, double *const o[3], double *const d[3],
                           double *t, uint32_t *id, size_t *hits)
{
    bs_cview ov[3], dv[3];
    for (int c = 0; c < 3; c++) {
        ov[c] = (bs_cview){o[c], n, 0};
        dv[c] = (bs_cview){d[c], n, 0};
    }
    bs_view tv = {t, n, 0};
    double t0 = now();
    if (bs_locator_intersect(L, n, ov, dv, NULL, id, NULL, &tv, NULL) != BS_OK)
        return -1.0;
    double tl = now() - t0;
    *hits = 0;
    for (size_t k = 0; k < n; k++)
        *hits += id[k] != UINT32_MAX;
    return tl;
}

/* n incoherent rays: origins uniform in the box lo..hi, directions uniform on the sphere (a
 * fixed xorshift sequence, so every run and both tracers take the same rays). */
static void box_rays(size_t n, const double lo[3], const double hi[3], double *o[3], double *d[3])
{
    uint64_t x = 0x9e3779b97f4a7c15u;
    for (size_t k = 0; k < n; k++) {
        double r[5];
        for (int i = 0; i < 5; i++) {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            r[i] = (double)(x >> 11) * 0x1p-53;
        }
        double z = 2.0 * r[3] - 1.0, a = 6.283185307179586 * r[4], s = sqrt(1.0 - z * z);
        for (int c = 0; c < 3; c++)
            o[c][k] = lo[c] + r[c] * (hi[c] - lo[c]);
        d[0][k] = s * cos(a);
        d[1][k] = s * sin(a);
        d[2][k] = z;
    }
}

int main(int argc, char **argv)
{
    size_t N = argc > 1 ? (size_t)atol(argv[1]) : 1024, n = N * N, ntri = 0, hits_e, hits_l;
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    double *o[3], *d[3], *t = malloc(n * sizeof(double));
    uint32_t *id = malloc(n * sizeof(uint32_t));
    for (int c = 0; c < 3; c++) {
        o[c] = malloc(n * sizeof(double));
        d[c] = malloc(n * sizeof(double));
        if (!o[c] || !d[c])
            return 1;
    }
    if (N == 0 || !t || !id || bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    camera_rays(N, o, d);
    RTCDevice dev = rtcNewDevice("threads=1"); /* one thread, as the locator */
    double t0 = now();
    RTCScene scene = embree_scene(dev, s, &ntri);
    double build_e = now() - t0;
    t0 = now();
    if (scene == NULL || bs_locator_create(s, &L) != BS_OK)
        return 1;
    double build_l = now() - t0;

    double te = embree_rays(scene, n, o, d, 0.0f, &hits_e), tl = locator_rays(L, n, o, d, t, id, &hits_l);
    if (tl < 0)
        return 1;
    printf("%zux%zu primary rays at the teapot, one thread, CPU time\n", N, N);
    printf("Embree 3, %zu triangles (64x64 per patch): built in %.1f ms (with tessellation), %.0f rays/s (%zu hits)\n",
           ntri, build_e * 1e3, (double)n / te, hits_e);
    printf("locator, exact surface:                built in %.1f ms, %.0f rays/s (%zu hits): %.2f of Embree's rate\n",
           build_l * 1e3, (double)n / tl, hits_l, te / tl);

    /* incoherent rays: as many, from random points of the teapot's box in random directions */
    double box[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        double lo[3], hi[3];
        if (bs_patch_bounds(bs_surface_get(s, i), lo, hi) != BS_OK)
            return 1;
        for (int c = 0; c < 3; c++) {
            box[c] = fmin(box[c], lo[c]);
            box[3 + c] = fmax(box[3 + c], hi[c]);
        }
    }
    box_rays(n, box, box + 3, o, d);
    te = embree_rays(scene, n, o, d, 0.0f, &hits_e);
    tl = locator_rays(L, n, o, d, t, id, &hits_l);
    if (tl < 0)
        return 1;
    printf("%zu random rays through the teapot's box (incoherent)\n", n);
    printf("Embree 3: %.0f rays/s (%zu hits)\n", (double)n / te, hits_e);
    printf("locator:  %.0f rays/s (%zu hits): %.2f of Embree's rate\n", (double)n / tl, hits_l, te / tl);
    rtcReleaseScene(scene);
    rtcReleaseDevice(dev);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    for (int c = 0; c < 3; c++) {
        free(o[c]);
        free(d[c]);
    }
    free(t);
    free(id);
    return 0;
}
