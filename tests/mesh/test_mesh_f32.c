/* Mesh read-back into float views: bs_mesh_copy_positions_f32, _normals_f32 and _uv_f32 give each
 * double of their double twins rounded to the nearest float, through packed, interleaved and
 * negative-stride views; bad views are refused with nothing written. */
#include "harness.h"

#include <bezsurf.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef bs_status (*copy_d)(const bs_mesh *, const bs_view *);
typedef bs_status (*copy_f)(const bs_mesh *, const bs_fview *);

/* f is d correctly rounded: the bits of (float)d, and no neighbour of f is nearer to d. */
static int rounded(double d, float f)
{
    float r = (float)d;
    if (memcmp(&r, &f, sizeof f) != 0 || !isfinite(f))
        return 0;
    double err = fabs((double)f - d);
    return err <= fabs((double)nextafterf(f, INFINITY) - d) &&
           err <= fabs((double)nextafterf(f, -INFINITY) - d);
}

/* One accessor pair on mesh m: k coordinates of n vertices, float views of the given stride. */
static void compare(const bs_mesh *m, size_t k, copy_d cd, copy_f cf, ptrdiff_t stride)
{
    size_t n = bs_mesh_vertex_count(m);
    ptrdiff_t bytes = stride == 0 ? (ptrdiff_t)sizeof(float) : stride;
    size_t step = (size_t)(bytes < 0 ? -bytes : bytes) / sizeof(float);
    double *d = malloc(3 * n * sizeof(double));
    float *f = malloc(3 * n * step * sizeof(float));
    bs_view dv[3];
    bs_fview fv[3];
    for (size_t c = 0; c < k; c++) {
        dv[c].data = d + c * n;
        dv[c].count = n;
        dv[c].stride = 0;
        float *base = f + c * n * step;
        fv[c].data = bytes < 0 ? base + (n - 1) * step : base;
        fv[c].count = n;
        fv[c].stride = stride;
    }
    CHECK_STATUS(cd(m, dv), BS_OK);
    CHECK_STATUS(cf(m, fv), BS_OK);
    size_t bad = 0;
    for (size_t c = 0; c < k; c++)
        for (size_t i = 0; i < n; i++)
            bad += !rounded(d[c * n + i], *(const float *)(const void *)((const char *)fv[c].data +
                                                                         (ptrdiff_t)i * bytes));
    CHECKF(bad == 0, "%zu coordinates, stride %td: %zu float(s) not the rounded double", k, stride, bad);
    free(d);
    free(f);
}

/* Interleaved x, y, z (stride 12) as a vertex buffer would hold them. */
static void test_values(const bs_mesh *m)
{
    ptrdiff_t strides[] = {0, 4, 12, -12};
    for (size_t s = 0; s < sizeof strides / sizeof strides[0]; s++) {
        compare(m, 3, bs_mesh_copy_positions, bs_mesh_copy_positions_f32, strides[s]);
        compare(m, 3, bs_mesh_copy_normals, bs_mesh_copy_normals_f32, strides[s]);
        compare(m, 2, bs_mesh_copy_uv, bs_mesh_copy_uv_f32, strides[s]);
    }
}

static void test_refused(const bs_mesh *m)
{
    size_t n = bs_mesh_vertex_count(m);
    float *buf = malloc(3 * (n + 1) * sizeof(float));
    memset(buf, 0x5a, 3 * (n + 1) * sizeof(float));
    bs_fview fv[3];
    for (size_t c = 0; c < 3; c++) {
        fv[c].data = buf + c * (n + 1);
        fv[c].count = n;
        fv[c].stride = 0;
    }
    fv[2].count = n - 1;
    CHECK_STATUS(bs_mesh_copy_positions_f32(m, fv), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_normals_f32(m, fv), BS_ERR_SIZE);
    fv[2].count = n;
    fv[1].count = n - 1;
    CHECK_STATUS(bs_mesh_copy_uv_f32(m, fv), BS_ERR_SIZE);
    fv[1].count = n;
    fv[0].data = (float *)(void *)((char *)buf + 1);
    CHECK_STATUS(bs_mesh_copy_positions_f32(m, fv), BS_ERR_INVALID_ARG);
    fv[0].data = buf;
    fv[1].stride = 2;
    CHECK_STATUS(bs_mesh_copy_uv_f32(m, fv), BS_ERR_INVALID_ARG);
    fv[1].stride = 0;
    CHECK_STATUS(bs_mesh_copy_positions_f32(m, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_copy_normals_f32(NULL, fv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_copy_uv_f32(NULL, fv), BS_ERR_INVALID_ARG);
    int untouched = 1;
    const unsigned char *bytes = (const unsigned char *)buf;
    for (size_t k = 0; k < 3 * (n + 1) * sizeof(float); k++)
        untouched &= bytes[k] == 0x5a;
    CHECK(untouched);
    free(buf);
}

int main(void)
{
    bs_surface *s = NULL;
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 9, 7, 0, &m), BS_OK);
    if (m != NULL) {
        CHECK(bs_mesh_vertex_count(m) > 100);
        test_values(m);
        test_refused(m);
    }
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
    return bs_test_exit("test_mesh_f32");
}
