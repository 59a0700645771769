/* Normals the surface does not define at a vertex: the mesh gives the normalised sum of the
 * adjacent triangles' normals (their cross products, so weighted by area), as bs_mesh_copy_normals()
 * documents. The surface: a degree (6,6) patch whose 5 x 5 corner block of control points is one
 * point, so that S_u and S_v vanish to order 4 at that corner and every c_K of the limit rule up to
 * K = 6 is zero there (docs/normals.md): the corner's normal is UNDEFINED, while the triangles
 * around it have a non-zero area. The patch faces along x, so a repair that started from (0,0,1)
 * instead of from zero would tilt the normal towards z. */
#include "harness.h"
#include "mesh_data.h"

#include <math.h>

#define DEG 6

static bs_surface *collapsed_corner_block(void)
{
    double net[(DEG + 1) * (DEG + 1) * 3];
    for (int i = 0; i <= DEG; i++)
        for (int j = 0; j <= DEG; j++) {
            double *p = net + (i * (DEG + 1) + j) * 3;
            int block = i <= 4 && j <= 4;
            /* a gently curved sheet in the (y, z) plane, bulging along x */
            p[0] = block ? 0.0 : 0.05 * (i * j) / (DEG * DEG);
            p[1] = block ? 0.0 : (double)i / DEG;
            p[2] = block ? 0.0 : (double)j / DEG;
        }
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, DEG, DEG, net, NULL);
    return s;
}

static void cross_add(const double *a, const double *b, const double *c, double *sum)
{
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    sum[0] += e1[1] * e2[2] - e1[2] * e2[1];
    sum[1] += e1[2] * e2[0] - e1[0] * e2[2];
    sum[2] += e1[0] * e2[1] - e1[1] * e2[0];
}

int main(void)
{
    bs_surface *s = collapsed_corner_block();
    const bs_patch *p = bs_surface_get(s, 0);
    double u0[1] = {0.0}, v0[1] = {0.0}, n[3][1];
    unsigned char kind[1];
    bs_cview cu = {u0, 1, 0}, cv = {v0, 1, 0};
    bs_view nv[3] = {{n[0], 1, 0}, {n[1], 1, 0}, {n[2], 1, 0}};
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, NULL, nv, kind), BS_OK);
    CHECKF(kind[0] == BS_NORMAL_UNDEFINED, "the corner's normal kind is %d, not undefined", kind[0]);

    for (size_t rate = 2; rate <= 8; rate *= 2) {
        bs_mesh *m = NULL;
        CHECK_STATUS(bs_surface_tessellate_uniform(s, rate, rate, 0, &m), BS_OK);
        mesh_data d;
        read_mesh(m, &d);
        size_t corner = d.nv, around = 0;
        for (size_t k = 0; k < d.nv; k++)
            if (d.uv[2 * k] == 0.0 && d.uv[2 * k + 1] == 0.0)
                corner = k;
        CHECK(corner < d.nv);
        double sum[3] = {0.0, 0.0, 0.0};
        for (size_t t = 0; corner < d.nv && t < d.nt; t++) {
            const uint32_t *v = d.tri + 3 * t;
            if (v[0] == corner || v[1] == corner || v[2] == corner) {
                cross_add(d.pos + 3 * (size_t)v[0], d.pos + 3 * (size_t)v[1], d.pos + 3 * (size_t)v[2], sum);
                around++;
            }
        }
        double len = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
        CHECKF(around > 0 && len > 0.0, "rate %zu: no triangle of non-zero area at the corner", rate);
        CHECKF(fabs(sum[0]) / len > 0.99, "rate %zu: the triangles around the corner do not face along x", rate);
        for (int c = 0; corner < d.nv && len > 0.0 && c < 3; c++) {
            double got = d.nrm[3 * corner + (size_t)c], want = sum[c] / len;
            CHECKF(fabs(got - want) <= 1e-12, "rate %zu: repaired normal[%d] %.17g, the triangles' %.17g",
                   rate, c, got, want);
        }
        free_mesh(&d);
        bs_mesh_destroy(m);
    }
    bs_surface_destroy(s);
    return bs_test_exit("test_tess_repair");
}
