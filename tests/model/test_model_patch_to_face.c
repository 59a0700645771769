/* bs_model_patch_to_face: points of the model's patches back to native face parameters. On the
 * CAD parts, each patch point's native (u,v) is evaluated by its face (bs_model_face_eval) and
 * compared with the patch's own point (bs_patch_eval), and mapped forward again
 * (bs_model_face_to_patch) to the same patch and (s,t); on a model of a surface the map is the
 * identity; the argument rules. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <string.h>

#define GRID 5

static double diagonal(const bs_surface *s)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        double a[3], b[3];
        if (bs_patch_bounds(bs_surface_get(s, i), a, b) != BS_OK)
            continue;
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], a[c]);
            hi[c] = fmax(hi[c], b[c]);
        }
    }
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

static void check_part(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s-brep.igs", BS_CAD_DIR, name);
    bs_model *m = NULL;
    CHECKF(bs_model_read_iges_file(path, NULL, &m) == BS_OK, "%s", path);
    if (m == NULL)
        return;
    const bs_surface *s = bs_model_surface(m);
    double diag = diagonal(s), worst_pos = 0.0, worst_st = 0.0;
    size_t points = 0;
    for (size_t p = 0; p < bs_surface_count(s); p++) {
        uint32_t patch[GRID * GRID], face[GRID * GRID], back[GRID * GRID];
        double sv[GRID * GRID], tv[GRID * GRID], u[GRID * GRID], v[GRID * GRID];
        double px[3][GRID * GRID], fx[3][GRID * GRID], s2[GRID * GRID], t2[GRID * GRID];
        for (int i = 0; i < GRID; i++)
            for (int j = 0; j < GRID; j++) {
                /* inside (0,1): at a break the forward map picks the later piece */
                patch[i * GRID + j] = (uint32_t)p;
                sv[i * GRID + j] = (i + 0.5) / GRID;
                tv[i * GRID + j] = (j + 0.5) / GRID;
            }
        size_t n = GRID * GRID;
        bs_cview cs = {sv, n, 0}, ct = {tv, n, 0};
        bs_view uv[2] = {{u, n, 0}, {v, n, 0}};
        CHECK_STATUS(bs_model_patch_to_face(m, n, patch, &cs, &ct, face, uv), BS_OK);
        bs_face_info fi;
        fi.size = sizeof fi;
        CHECK_STATUS(bs_model_face_info(m, face[0], &fi), BS_OK);
        CHECKF(fi.first_patch <= p && p < fi.first_patch + fi.patch_count, "%s patch %zu", name, p);
        bs_view pv[3] = {{px[0], n, 0}, {px[1], n, 0}, {px[2], n, 0}};
        bs_view fv[3] = {{fx[0], n, 0}, {fx[1], n, 0}, {fx[2], n, 0}};
        CHECK_STATUS(bs_patch_eval(bs_surface_get(s, p), n, &cs, &ct, pv, NULL, NULL), BS_OK);
        bs_cview cu = {u, n, 0}, cv = {v, n, 0};
        CHECK_STATUS(bs_model_face_eval(m, n, face, &cu, &cv, fv, NULL, NULL), BS_OK);
        bs_view st[2] = {{s2, n, 0}, {t2, n, 0}};
        CHECK_STATUS(bs_model_face_to_patch(m, n, face, &cu, &cv, back, st), BS_OK);
        for (size_t k = 0; k < n; k++) {
            CHECKF(face[k] == face[0], "%s patch %zu", name, p);
            double d = 0.0;
            for (int c = 0; c < 3; c++)
                d += (px[c][k] - fx[c][k]) * (px[c][k] - fx[c][k]);
            worst_pos = fmax(worst_pos, sqrt(d) / diag);
            worst_st = fmax(worst_st, fmax(fabs(s2[k] - sv[k]), fabs(t2[k] - tv[k])));
            CHECKF(back[k] == p, "%s patch %zu: back to %u", name, p, back[k]);
            points++;
        }
    }
    CHECKF(worst_pos < 1e-12, "%s: %.3g of the diagonal", name, worst_pos);
    CHECKF(worst_st < 1e-12, "%s: (s,t) back within %.3g", name, worst_st);
    printf("%s: %zu points on %zu patches, positions within %.2g of the diagonal, (s,t) within %.2g\n",
           name, points, bs_surface_count(s), worst_pos, worst_st);
    bs_model_destroy(m);
}

/* A model of a surface: each patch its own face on (0,1)^2, the map the identity. */
static void test_identity_and_errors(void)
{
    static const double net[2][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}},
                                        {{1, 0, 0}, {1, 1, 0}, {2, 0, 1}, {2, 1, 1}}};
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    for (int k = 0; k < 2; k++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(1, 1, 3, &net[k][0][0], NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s);
    uint32_t patch[5] = {0, 1, 1, 0, 1}, face[5];
    double sv[5] = {0.0, 1.0, 0.25, 1.5, NAN}, tv[5] = {0.5, 0.0, 0.75, 0.5, 0.5}, u[5], v[5];
    bs_cview cs = {sv, 5, 0}, ct = {tv, 5, 0};
    bs_view uv[2] = {{u, 5, 0}, {v, 5, 0}};
    CHECK_STATUS(bs_model_patch_to_face(m, 5, patch, &cs, &ct, face, uv), BS_OK);
    for (int k = 0; k < 3; k++)
        CHECK(face[k] == patch[k] && u[k] == sv[k] && v[k] == tv[k]);
    /* outside [0,1] and NaN: no face, NaN */
    CHECK(face[3] == UINT32_MAX && isnan(u[3]) && isnan(v[3]));
    CHECK(face[4] == UINT32_MAX && isnan(u[4]) && isnan(v[4]));
    CHECK_STATUS(bs_model_patch_to_face(m, 3, patch, &cs, &ct, NULL, NULL), BS_OK);

    /* the argument rules */
    CHECK_STATUS(bs_model_patch_to_face(m, 0, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_model_patch_to_face(NULL, 0, NULL, NULL, NULL, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_patch_to_face(NULL, 1, patch, &cs, &ct, face, uv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_patch_to_face(m, 1, NULL, &cs, &ct, face, uv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_patch_to_face(m, 1, patch, NULL, &ct, face, uv), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_patch_to_face(m, 1, patch, &cs, NULL, face, uv), BS_ERR_INVALID_ARG);
    uint32_t bad = 2;
    CHECK_STATUS(bs_model_patch_to_face(m, 1, &bad, &cs, &ct, face, uv), BS_ERR_INVALID_ARG);
    bs_cview short_s = {sv, 1, 0};
    CHECK_STATUS(bs_model_patch_to_face(m, 2, patch, &short_s, &ct, face, uv), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_patch_to_face(m, 2, patch, &cs, &short_s, face, uv), BS_ERR_SIZE);
    bs_view short_uv[2] = {{u, 1, 0}, {v, 5, 0}};
    CHECK_STATUS(bs_model_patch_to_face(m, 2, patch, &cs, &ct, face, short_uv), BS_ERR_SIZE);
    bs_view odd_uv[2] = {{(double *)((char *)u + 1), 1, 0}, {v, 5, 0}};
    CHECK_STATUS(bs_model_patch_to_face(m, 1, patch, &cs, &ct, face, odd_uv), BS_ERR_INVALID_ARG);
    bs_model_destroy(m);
}

int main(void)
{
    static const char *const parts[] = {"block", "bottle", "cone", "sphere", "torus", "wedge", "duct", "bell"};
    test_identity_and_errors();
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++)
        check_part(parts[k]);
    return bs_test_exit("test_model_patch_to_face");
}
