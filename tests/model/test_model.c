/* Models of surfaces (bs_model_from_surface): faces, edges and shells from the surface's
 * topology; face evaluation and the native map against the patch evaluators; the argument rules
 * of the model accessors and evaluators; classification beside a trim of a flat and of a twisted
 * bilinear face (an OBJ model) against closed-form distances. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* A unit cube of six bilinear patches, each with its normal S_u x S_v pointing out; `skip` leaves
 * one face out (6: none). */
static bs_surface *cube(int skip)
{
    static const double corners[6][4][3] = {
        {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}, /* z = 0, normal -z */
        {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}, /* z = 1, +z */
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}}, /* y = 0, -y */
        {{0, 1, 0}, {0, 1, 1}, {1, 1, 0}, {1, 1, 1}}, /* y = 1, +y */
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 1, 1}}, /* x = 0, -x */
        {{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}}, /* x = 1, +x */
    };
    bs_surface *s = NULL;
    if (bs_surface_create(&s) != BS_OK)
        return NULL;
    for (int f = 0; f < 6; f++) {
        if (f == skip)
            continue;
        bs_patch *p = NULL;
        if (bs_patch_create(1, 1, 3, &corners[f][0][0], NULL, &p) != BS_OK ||
            bs_surface_add(s, p, NULL) != BS_OK) {
            bs_patch_destroy(p);
            bs_surface_destroy(s);
            return NULL;
        }
        bs_patch_destroy(p);
    }
    return s;
}

static void test_cube(void)
{
    bs_surface *s = cube(6);
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s); /* the model keeps its own copy */
    CHECK(bs_model_face_count(m) == 6);
    CHECK(bs_model_edge_count(m) == 12);
    CHECK(bs_model_shell_count(m) == 1);
    CHECK(bs_model_shell_closed(m, 0) == 1);
    CHECK(bs_model_shell_closed(m, 1) == -1);
    CHECK(bs_surface_count(bs_model_surface(m)) == 6);
    bs_face_info fi;
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(m, 5, &fi), BS_OK);
    CHECK(fi.kind == BS_FACE_BEZIER && fi.reversed == 0 && fi.shell == 0 && fi.instance == 0);
    CHECK(fi.first_patch == 5 && fi.patch_count == 1 && fi.loop_count == 1);
    CHECK(fi.u0 == 0.0 && fi.u1 == 1.0 && fi.v0 == 0.0 && fi.v1 == 1.0);
    bs_model_destroy(m);

    /* one face missing: the four edges around the hole are used once, the shell is open */
    s = cube(2);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s);
    CHECK(bs_model_face_count(m) == 5 && bs_model_edge_count(m) == 12);
    CHECK(bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == 0);
    bs_model_destroy(m);
}

/* The tea set's lids and bottoms have collapsed sides (poles): no edge there, and the teapot's
 * body, lid, spout and handle are separate sets of patches. */
static void test_teapot(void)
{
    bs_surface *s = NULL;
    bs_model *m = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    CHECK(bs_model_face_count(m) == bs_surface_count(s));
    size_t ns = bs_model_shell_count(m);
    CHECKF(ns >= 4 && ns <= 6, "%zu shells", ns);
    CHECK(bs_model_edge_count(m) > 0 && bs_model_edge_count(m) < 4 * bs_surface_count(s));

    /* face evaluation through the native map is the patch's evaluation, bit for bit */
    double u[5] = {0.0, 0.25, 0.5, 0.875, 1.0}, v[5] = {0.5, 0.0, 0.3, 1.0, 0.75};
    uint32_t faces[5] = {0, 7, 12, 20, 31};
    double px[5], py[5], pz[5], nx[5], ny[5], nz[5];
    bs_view pos[3] = {{px, 5, 0}, {py, 5, 0}, {pz, 5, 0}}, nrm[3] = {{nx, 5, 0}, {ny, 5, 0}, {nz, 5, 0}};
    bs_cview cu = {u, 5, 0}, cv = {v, 5, 0};
    unsigned char kind[5];
    CHECK_STATUS(bs_model_face_eval(m, 5, faces, &cu, &cv, pos, nrm, kind), BS_OK);
    for (int k = 0; k < 5; k++) {
        double q[3], n[3];
        unsigned char nk;
        bs_cview one_u = {&u[k], 1, 0}, one_v = {&v[k], 1, 0};
        bs_view qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}}, nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval_normal(bs_surface_get(s, faces[k]), 1, &one_u, &one_v, qv, nv, &nk), BS_OK);
        CHECK(q[0] == px[k] && q[1] == py[k] && q[2] == pz[k]);
        CHECK(n[0] == nx[k] && n[1] == ny[k] && n[2] == nz[k] && nk == kind[k]);
    }
    uint32_t patch[5];
    double s_[5], t_[5];
    bs_view st[2] = {{s_, 5, 0}, {t_, 5, 0}};
    CHECK_STATUS(bs_model_face_to_patch(m, 5, faces, &cu, &cv, patch, st), BS_OK);
    for (int k = 0; k < 5; k++)
        CHECK(patch[k] == faces[k] && s_[k] == u[k] && t_[k] == v[k]);

    /* outside the face's (0,1)^2 and NaN: no patch, NaN */
    double bad_u[2] = {1.5, NAN}, bad_v[2] = {0.5, 0.5};
    bs_cview bu = {bad_u, 2, 0}, bv = {bad_v, 2, 0};
    CHECK_STATUS(bs_model_face_to_patch(m, 2, faces, &bu, &bv, patch, st), BS_OK);
    CHECK(patch[0] == UINT32_MAX && patch[1] == UINT32_MAX && isnan(s_[0]) && isnan(t_[1]));
    CHECK_STATUS(bs_model_face_eval(m, 2, faces, &bu, &bv, pos, nrm, kind), BS_OK);
    CHECK(isnan(px[0]) && isnan(nz[1]) && kind[0] == BS_NORMAL_UNDEFINED);
    bs_model_destroy(m);
    bs_surface_destroy(s);
}

static void test_errors(void)
{
    bs_model *m = (bs_model *)&m;
    CHECK_STATUS(bs_model_from_surface(NULL, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_model_from_surface(s, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_ERR_SIZE);
    double net2[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p2 = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 2, net2, NULL, &p2), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p2, NULL), BS_OK);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_ERR_DIMENSION);
    CHECK(m == NULL);
    bs_patch_destroy(p2);
    bs_surface_destroy(s);

    bs_model_destroy(NULL);
    CHECK(bs_model_face_count(NULL) == 0 && bs_model_edge_count(NULL) == 0);
    CHECK(bs_model_shell_count(NULL) == 0 && bs_model_shell_closed(NULL, 0) == -1);
    CHECK(bs_model_surface(NULL) == NULL);

    s = cube(6);
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s);
    bs_face_info fi;
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(NULL, 0, &fi), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_info(m, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_info(m, 6, &fi), BS_ERR_DOMAIN);
    fi.size = sizeof fi - 1;
    CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_ERR_INVALID_ARG);
    /* a caller built against a later, longer struct: only the 1.2 fields are written */
    unsigned char longer[sizeof(bs_face_info) + 16];
    memset(longer, 0xAB, sizeof longer);
    bs_face_info *li = (bs_face_info *)(void *)longer;
    li->size = sizeof longer;
    CHECK_STATUS(bs_model_face_info(m, 0, li), BS_OK);
    CHECK(longer[sizeof(bs_face_info)] == 0xAB && longer[sizeof longer - 1] == 0xAB);

    double u = 0.5, v = 0.5, out[3];
    uint32_t face = 0, bad = 6;
    unsigned char where;
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0}, short_v = {&v, 0, 0};
    bs_view pos[3] = {{&out[0], 1, 0}, {&out[1], 1, 0}, {&out[2], 1, 0}};
    bs_view short_pos[3] = {{&out[0], 1, 0}, {&out[1], 0, 0}, {&out[2], 1, 0}};
    bs_view odd[3] = {{&out[0], 1, 3}, {&out[1], 1, 0}, {&out[2], 1, 0}};
    CHECK_STATUS(bs_model_face_eval(NULL, 1, &face, &cu, &cv, pos, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 1, NULL, &cu, &cv, pos, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, NULL, &cv, pos, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, NULL, pos, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 1, &bad, &cu, &cv, pos, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &short_v, pos, NULL, NULL), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, short_pos, NULL, NULL), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, NULL, short_pos, NULL), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, odd, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_eval(m, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_model_face_eval(NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_to_patch(m, 1, &bad, &cu, &cv, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_face_to_patch(m, 1, &face, &cu, &cv, NULL, short_pos), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, 1e-9, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, -1.0, &where), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, NAN, &where), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, INFINITY, &where), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, 1e-9, &where), BS_OK);
    CHECK(where == BS_TRIM_INSIDE);
    double nan_u = NAN;
    bs_cview cn = {&nan_u, 1, 0};
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cn, &cv, 1e-9, &where), BS_OK);
    CHECK(where == BS_TRIM_OUTSIDE);
    bs_model_destroy(m);
}

/* Points beside a trim of a flat face, S = (2u, 3v, 0), and of a twisted one, S = (2u, 3v, 1.5uv),
 * both trimmed to the square [0.2, 0.8]^2: ON within tol of the side u = 0.2, else on their side
 * of it. The distances in closed form: 2 |e| on the flat face; on the twisted one, from
 * (0.2 + e, v) to the side's point (0.2, v - d), sqrt(4 e^2 + 9 c^2 / 9.09) with c = 1.5 e v, the
 * least over d of 4 e^2 + 9 d^2 + (0.3 d + c)^2. A third face, S = (2u, 2v, 0) trimmed by a
 * circle, has its points 2 |e| from it at radius 0.25 + e; a fourth is the first of degree 4. */
static void test_classify_near_side(void)
{
    static const char obj[] =
        "v 0 0 0\nv 2 0 0\nv 0 3 0\nv 2 3 0\nv 2 3 1.5\n"
        "vp 0.2 0.2\nvp 0.8 0.2\nvp 0.8 0.8\nvp 0.2 0.8\nvp 0.2 0.2\n"
        "cstype bezier\ndeg 1\ncurv2 1 2 3 4 5\nparm u 0 1 2 3 4\nend\n"
        "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1\nparm v 0 1\ntrim 0 4 1\nend\n"
        "surf 0 1 0 1 1 2 3 5\nparm u 0 1\nparm v 0 1\ntrim 0 4 1\nend\n"
        /* the circle of centre (0.5, 0.5) and radius 0.25 on S = (2u, 2v, 0) */
        "v 0 2 0\nv 2 2 0\n"
        "vp 0.75 0.5 1\nvp 0.75 0.75 0.70710678118654757\nvp 0.5 0.75 1\n"
        "vp 0.25 0.75 0.70710678118654757\nvp 0.25 0.5 1\nvp 0.25 0.25 0.70710678118654757\n"
        "vp 0.5 0.25 1\nvp 0.75 0.25 0.70710678118654757\nvp 0.75 0.5 1\n"
        "cstype rat bspline\ndeg 2\ncurv2 6 7 8 9 10 11 12 13 14\nparm u 0 0 0 1 1 2 2 3 3 4 4 4\nend\n"
        "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 6 7\nparm u 0 1\nparm v 0 1\ntrim 0 4 2\nend\n"
        /* S = (2u, 3v, 0) again, of degree 4 along u: judged on the surface, not as flat */
        "v 0 0 0\nv 0.5 0 0\nv 1 0 0\nv 1.5 0 0\nv 2 0 0\nv 0 3 0\nv 0.5 3 0\nv 1 3 0\nv 1.5 3 0\nv 2 3 0\n"
        "deg 4 1\nsurf 0 1 0 1 8 9 10 11 12 13 14 15 16 17\nparm u 0 1\nparm v 0 1\ntrim 0 4 1\nend\n";
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_obj(obj, sizeof obj - 1, NULL, &m), BS_OK);
    if (m == NULL)
        return;
    CHECK(bs_model_face_count(m) == 4);
    static const uint32_t beside[3] = {0, 1, 3};
    for (int which = 0; which < 3; which++) {
        uint32_t face = beside[which];
        double u = 0.5, v = 0.25, p[3];
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
        CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, pos, NULL, NULL), BS_OK);
        CHECKF(p[0] == 1.0 && p[1] == 0.75 && p[2] == (face == 1 ? 0.1875 : 0.0),
               "face %u at (0.5, 0.25): %g %g %g", (unsigned)face, p[0], p[1], p[2]);
        for (int k = 0; k < 28; k++) {
            double e = (k % 2 ? 1e-5 : 1e-3) * (k % 4 < 2 ? 1.0 : -1.0), c = 1.5 * e * (0.3 + 0.4 * (double)(k / 4) / 6.0);
            double d = face == 1 ? sqrt(4 * e * e + 9 * c * c / 9.09) : 2 * fabs(e);
            u = 0.2 + e, v = 0.3 + 0.4 * (double)(k / 4) / 6.0;
            unsigned char near = 9, far = 9;
            CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, 1.02 * d, &near), BS_OK);
            CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, 0.98 * d, &far), BS_OK);
            CHECKF(near == BS_TRIM_ON && far == (e > 0 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE),
                   "face %u at (%.17g, %.17g), distance %g: %d within 1.02, %d within 0.98", (unsigned)face,
                   u, v, d, near, far);
        }
    }
    uint32_t disc = 2;
    for (int k = 0; k < 40; k++) { /* beside the circle: 2 |e| from it */
        double a = 0.157 * k, e = (k % 2 ? 1e-5 : 1e-3) * (k % 4 < 2 ? 1.0 : -1.0), d = 2 * fabs(e);
        double u = 0.5 + (0.25 + e) * cos(a), v = 0.5 + (0.25 + e) * sin(a);
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        unsigned char near = 9, far = 9;
        CHECK_STATUS(bs_model_classify(m, 1, &disc, &cu, &cv, 1.02 * d, &near), BS_OK);
        CHECK_STATUS(bs_model_classify(m, 1, &disc, &cu, &cv, 0.98 * d, &far), BS_OK);
        CHECKF(near == BS_TRIM_ON && far == (e > 0 ? BS_TRIM_OUTSIDE : BS_TRIM_INSIDE),
               "circle at angle %g, distance %g: %d within 1.02, %d within 0.98", a, d, near, far);
    }
    bs_model_destroy(m);
}

int main(void)
{
    test_cube();
    test_teapot();
    test_errors();
    test_classify_near_side();
    return bs_test_exit("test_model");
}
