/* Rays on the trimmed faces of models (bs_locator_create_model):
 * - every file of every CAD part of data/cad/ (STEP, STEP without PCURVEs, IGES 144, IGES 186)
 *   against the 400 rays of its .ref (OpenCASCADE's IntCurvesFace_ShapeIntersector): the same
 *   first hit within 1e-6 of the part's diagonal, or, where the two disagree, ours shown right on
 *   the exact faces: a hit of ours lies on the ray and inside its face by more than the trim
 *   tolerance, and where the kernel's hit is nearer, its point lies outside every face (its
 *   distance to our faces is checked by a ray from the kernel's point back along the ray);
 * - rays aimed at points on the trims of faces (edges between faces, the rims of holes), which
 *   must hit at that point, with the face's outward normal;
 * - rays aimed at points of the untrimmed surfaces just outside the trims (at least 1e-5 D: in
 *   holes, past edges), which must not hit that face there;
 * - the argument rules, and a closest point reported as a face and native parameters
 *   (test_model_closest.c checks closest points on every part). */
#include "harness.h"
#include "cad_model.h"

#include <bezsurf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct ray_ref {
    double o[3], d[3], t; /* t = +Inf: a miss */
} ray_ref;

/* The rays of NAME.ref; their count. */
static size_t read_rays(const char *part, ray_ref *rays, size_t cap, double *diag)
{
    char line[512];
    FILE *f = open_ref(part);
    if (f == NULL)
        return 0;
    size_t n = 0;
    while (fgets(line, sizeof line, f)) {
        char what[16];
        ray_ref r;
        (void)ref_box_diagonal(line, diag);
        if (n < cap && sscanf(line, "ray %lf %lf %lf %lf %lf %lf %15s %lf", &r.o[0], &r.o[1], &r.o[2],
                              &r.d[0], &r.d[1], &r.d[2], what, &r.t) >= 7) {
            if (strcmp(what, "hit") != 0)
                r.t = INFINITY;
            rays[n++] = r;
        }
    }
    fclose(f);
    return n;
}

/* One ray: its face (UINT32_MAX on a miss), native uv, t and normal. */
typedef struct hit {
    uint32_t face;
    double uv[2], t, n[3];
} hit;

static hit shoot(const bs_locator *L, const double *o, const double *d)
{
    hit h = {UINT32_MAX, {NAN, NAN}, NAN, {NAN, NAN, NAN}};
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_view uv[2] = {{&h.uv[0], 1, 0}, {&h.uv[1], 1, 0}}, tv = {&h.t, 1, 0};
    bs_view nv[3] = {{&h.n[0], 1, 0}, {&h.n[1], 1, 0}, {&h.n[2], 1, 0}};
    CHECK_STATUS(bs_locator_intersect(L, 1, ov, dv, NULL, &h.face, uv, &tv, nv), BS_OK);
    return h;
}

/* The face point and outward normal at native uv; its classification with tolerance tol. */
static int face_point(const bs_model *m, uint32_t f, const double uv[2], double tol, double *p, double *n)
{
    bs_cview cu = {&uv[0], 1, 0}, cv = {&uv[1], 1, 0};
    bs_view pv[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
    bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
    CHECK_STATUS(bs_model_face_eval(m, 1, &f, &cu, &cv, pv, nv, NULL), BS_OK);
    unsigned char where = 9;
    CHECK_STATUS(bs_model_classify(m, 1, &f, &cu, &cv, tol, &where), BS_OK);
    return where;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static int agree_total, disagree_total, kernel_missed, kernel_wrong;

/* The .ref rays of one file of a part. */
static void ref_rays(const char *part, const char *file)
{
    static ray_ref rays[512];
    double D = 0.0;
    size_t n = read_rays(part, rays, 512, &D);
    bs_model *m = read_model(file);
    bs_locator *L = NULL;
    if (m == NULL || n == 0)
        goto done;
    CHECK_STATUS(bs_locator_create_model(m, &L), BS_OK);
    if (L == NULL)
        goto done;
    int agree = 0, disagree = 0;
    for (size_t k = 0; k < n; k += bs_test_quick() ? 8 : 1) {
        const ray_ref *r = &rays[k];
        hit h = shoot(L, r->o, r->d);
        double ours = h.face == UINT32_MAX ? INFINITY : h.t;
        if ((isinf(ours) && isinf(r->t)) || fabs(ours - r->t) <= 1e-6 * D) {
            agree++;
            continue;
        }
        disagree++;
        /* ours must be a true hit: on the ray, inside its face */
        if (h.face != UINT32_MAX) {
            double p[3], nn[3], x[3];
            int where = face_point(m, h.face, h.uv, 0.0, p, nn);
            for (int c = 0; c < 3; c++)
                x[c] = r->o[c] + h.t * r->d[c];
            CHECKF(dist3(p, x) <= 1e-9 * D && where != BS_TRIM_OUTSIDE,
                   "%s ray %zu: our hit at t = %.17g (face %u) is %g from the ray, class %d", file, k,
                   h.t, h.face, dist3(p, x), where);
        }
        if (r->t < ours) {
            /* the kernel's nearer hit: its point must not lie on our faces. A ray from just
             * before it, along the ray, would hit at once if it did */
            double o2[3];
            for (int c = 0; c < 3; c++)
                o2[c] = r->o[c] + (r->t - 1e-5 * D) * r->d[c];
            hit h2 = shoot(L, o2, r->d);
            CHECKF(h2.face == UINT32_MAX || h2.t > 2e-5 * D,
                   "%s ray %zu: the kernel's hit at t = %.17g was missed (ours %.17g)", file, k, r->t, ours);
            kernel_wrong++;
        } else
            kernel_missed++;
    }
    agree_total += agree;
    disagree_total += disagree;
    printf("%-22s %3d of %d rays agree with the kernel; %d differ\n", file, agree, agree + disagree, disagree);
done:
    bs_locator_destroy(L);
    bs_model_destroy(m);
}

/* Rays aimed down the normal at points of the trims of every face (where edges and hole rims
 * are): each must hit within 1e-6 D of its point, with an outward normal (a ray coming from
 * outside a closed solid meets an outward normal head on: n.d < 0). */
static void trim_rays(const char *part, const char *file)
{
    static ray_ref rays[512];
    double D = 0.0;
    (void)read_rays(part, rays, 512, &D);
    bs_model *m = read_model(file);
    bs_locator *L = NULL;
    if (m == NULL)
        return;
    CHECK_STATUS(bs_locator_create_model(m, &L), BS_OK);
    size_t nf = bs_model_face_count(m), shot = 0, missed = 0, outside = 0;
    for (uint32_t f = 0; f < nf && L; f++) {
        bs_face_info info;
        memset(&info, 0, sizeof info);
        info.size = sizeof info;
        CHECK_STATUS(bs_model_face_info(m, f, &info), BS_OK);
        const double box[4] = {info.u0, info.u1, info.v0, info.v1};
        /* points on the face's boundary: scan its native box along lines, keep points where the
         * classification changes from outside to inside, refined by bisection */
        for (int line = 1; line < 8; line += bs_test_quick() ? 3 : 1)
            for (int dir = 0; dir < 2; dir++) {
                double a[2], b[2];
                double fixed = dir == 0 ? box[2] + (box[3] - box[2]) * line / 8.0
                                        : box[0] + (box[1] - box[0]) * line / 8.0;
                int steps = bs_test_quick() ? 16 : 64;
                for (int step = 0; step < steps; step++) {
                    double x0 = step / (double)steps, x1 = (step + 1) / (double)steps, p[3], nn[3];
                    a[dir] = box[2 * dir] + (box[2 * dir + 1] - box[2 * dir]) * x0;
                    b[dir] = box[2 * dir] + (box[2 * dir + 1] - box[2 * dir]) * x1;
                    a[1 - dir] = b[1 - dir] = fixed;
                    int wa = face_point(m, f, a, 0.0, p, nn) == BS_TRIM_INSIDE;
                    int wb = face_point(m, f, b, 0.0, p, nn) == BS_TRIM_INSIDE;
                    if (wa == wb)
                        continue;
                    for (int it = 0; it < 50; it++) { /* the crossing, inside side kept */
                        double mid[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
                        int wm = face_point(m, f, mid, 0.0, p, nn) == BS_TRIM_INSIDE;
                        if (wm == wa)
                            memcpy(a, mid, sizeof a);
                        else
                            memcpy(b, mid, sizeof b);
                    }
                    const double *in = wa ? a : b;
                    face_point(m, f, in, 0.0, p, nn);
                    if (!(fabs(nn[0]) + fabs(nn[1]) + fabs(nn[2]) > 0.5))
                        continue; /* a pole: no normal to aim along */
                    double o[3], d[3];
                    for (int c = 0; c < 3; c++) {
                        o[c] = p[c] + 0.01 * D * nn[c];
                        d[c] = -nn[c];
                    }
                    hit h = shoot(L, o, d);
                    shot++;
                    /* a hit at the point itself (this face or the one across the edge), or an
                     * earlier one from another face between the origin and the point */
                    int ok = h.face != UINT32_MAX && h.t <= 0.01 * D + 1e-6 * D;
                    missed += !ok;
                    CHECKF(ok, "%s face %u: ray at the trim point (%.17g, %.17g) missed (face %u, t %.17g of %.17g)",
                           file, f, in[0], in[1], h.face, h.t, 0.01 * D);
                    if (ok && h.face == f && fabs(h.t - 0.01 * D) <= 1e-6 * D)
                        CHECKF(h.n[0] * d[0] + h.n[1] * d[1] + h.n[2] * d[2] < 0.0,
                               "%s face %u: the normal at a hit is not outward", file, f);
                    /* a point of the untrimmed surface just outside the trim (at least 1e-5 D from
                     * it), strictly inside the face's box (its sides may be a seam, where the
                     * point is the face's again): a ray down its normal must not hit this face
                     * there */
                    const double *out = wa ? b : a;
                    double off[2] = {out[0] - in[0], out[1] - in[1]}, x[2];
                    int found = 0;
                    for (int it = 0; it < 64 && !found; it++) {
                        off[0] *= 2;
                        off[1] *= 2;
                        x[0] = in[0] + off[0];
                        x[1] = in[1] + off[1];
                        if (!(x[0] > box[0] && x[0] < box[1] && x[1] > box[2] && x[1] < box[3]))
                            break;
                        found = face_point(m, f, x, 1e-5 * D, p, nn) == BS_TRIM_OUTSIDE;
                    }
                    if (!found || !(fabs(nn[0]) + fabs(nn[1]) + fabs(nn[2]) > 0.5))
                        continue;
                    for (int c = 0; c < 3; c++) {
                        o[c] = p[c] + 0.01 * D * nn[c];
                        d[c] = -nn[c];
                    }
                    h = shoot(L, o, d);
                    outside++;
                    CHECKF(!(h.face == f && fabs(h.t - 0.01 * D) <= 1e-6 * D),
                           "%s face %u: a ray at (%.17g, %.17g), outside the trim, hit the face there",
                           file, f, x[0], x[1]);
                }
            }
    }
    printf("%-22s %zu rays at trim points, %zu missed; %zu rays just outside trims\n", file, shot,
           missed, outside);
    bs_locator_destroy(L);
    bs_model_destroy(m);
}

static void arguments(void)
{
    bs_locator *L = (bs_locator *)1;
    CHECK_STATUS(bs_locator_create_model(NULL, &L), BS_ERR_INVALID_ARG);
    CHECK(L == NULL);
    bs_model *m = read_model("cone.step");
    if (m == NULL)
        return;
    CHECK_STATUS(bs_locator_create_model(m, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_create_model(m, &L), BS_OK);
    double q[3] = {0, 0, 100};
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    /* closest points: the face id and native (u, v); the top disc (z = 7) from the axis */
    double dist = 7, uv[2] = {7, 7}, dist2 = 0;
    uint32_t face = 7;
    bs_view dv = {&dist, 1, 0}, dv2 = {&dist2, 1, 0}, uvv[2] = {{&uv[0], 1, 0}, {&uv[1], 1, 0}};
    CHECK_STATUS(bs_locator_closest_point(L, 1, qv, &face, uvv, &dv, NULL), BS_OK);
    CHECK_STATUS(bs_locator_closest_point_mt(L, 1, qv, NULL, NULL, &dv2, NULL, 2), BS_OK);
    CHECKF(face == 1 && fabs(dist - 93.0) <= 1e-12 && dist2 == dist && fabs(uv[0]) <= 1e-12 &&
               fabs(uv[1]) <= 1e-12, "face %u at %g %g, %g", face, uv[0], uv[1], dist);
    /* no query point, a NaN one, a short view */
    CHECK_STATUS(bs_locator_closest_point(L, 1, NULL, NULL, NULL, &dv, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_locator_closest_point(L, 0, NULL, NULL, NULL, NULL, NULL), BS_OK);
    q[0] = NAN;
    CHECK_STATUS(bs_locator_closest_point(L, 1, qv, &face, uvv, &dv, NULL), BS_OK);
    CHECK(face == UINT32_MAX && isnan(dist) && isnan(uv[0]));
    bs_view shortv = {&dist, 0, 0};
    CHECK_STATUS(bs_locator_closest_point(L, 1, qv, NULL, NULL, &shortv, NULL), BS_ERR_SIZE);
    CHECK(bs_locator_dim(L) == 3);
    bs_locator_destroy(L);
    bs_model_destroy(m);
}

int main(void)
{
    static const char *const parts[] = {"bottle", "block", "sphere", "torus", "cone", "wedge", "bell", "duct"};
    static const char *const kinds[] = {".step", "-3d-edges.step", ".igs", "-brep.igs"};
    arguments();
    int quick = bs_test_quick();
    for (size_t p = 0; p < 8; p++)
        for (size_t k = 0; k < (quick ? 1u : 4u); k++) {
            char file[64];
            (void)snprintf(file, sizeof file, "%s%s", parts[p], kinds[k]);
            ref_rays(parts[p], file);
        }
    for (size_t p = 0; p < 8; p++) {
        char file[64];
        if (quick && p != 1 && p != 6) /* the block and the bell: holes, fillets, a revolution */
            continue;
        (void)snprintf(file, sizeof file, "%s.step", parts[p]);
        trim_rays(parts[p], file);
    }
    printf("rays: %d agree with the kernel, %d differ (%d hits the kernel missed, %d kernel hits "
           "not on the faces)\n", agree_total, disagree_total, kernel_missed, kernel_wrong);
    return bs_test_exit("test_model_locator");
}
