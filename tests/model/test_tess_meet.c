/*
 * bsi_tm_meet, the point where two faces meet (lib/model/tess_meet.c), against the closed form:
 * the plane z = 0 and a cylinder about the x axis, of radius 1 through z = 0.5, meet on the lines
 * y = +-sqrt(3) / 2; the first face's point moves as little as it must; tangent faces, faces that
 * do not meet and a pole are refused.
 */
#include "harness.h"
#include "model/tess_edge.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static size_t add_face(bs_model *m, int kind, const double *o, const double *x, const double *y, const double *z,
                       double r, const double *box)
{
    bsi_surface_def def;
    memset(&def, 0, sizeof def);
    def.kind = kind;
    def.r = r;
    memcpy(def.f.o, o, sizeof def.f.o);
    memcpy(def.f.x, x, sizeof def.f.x);
    memcpy(def.f.y, y, sizeof def.f.y);
    memcpy(def.f.z, z, sizeof def.f.z);
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.def = &def;
    spec.box = box;
    size_t f = SIZE_MAX;
    CHECK_STATUS(bsi_model_add_face(m, &spec, &f), BS_OK);
    return f;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

int main(void)
{
    bs_model *m = NULL;
    CHECK_STATUS(bsi_model_create(&m), BS_OK);
    if (m == NULL)
        return bs_test_exit("test_tess_meet");
    const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    const double origin[3] = {0, 0, 0}, lifted[3] = {0, 0, 0.5}, up[3] = {0, 0, 1};
    const double plane_box[4] = {-4, 4, -4, 4}, cyl_box[4] = {0, 2 * PI, -4, 4};
    const double sph_box[4] = {0, 2 * PI, -PI / 2, PI / 2};
    /* the cylinder's axis is x: its frame (y, z, x), so u = 0 points along y */
    size_t plane = add_face(m, BS_FACE_PLANE, origin, ex, ey, ez, 0.0, plane_box);
    size_t cyl = add_face(m, BS_FACE_CYLINDER, lifted, ey, ez, ex, 1.0, cyl_box);
    size_t touching = add_face(m, BS_FACE_CYLINDER, up, ey, ez, ex, 1.0, cyl_box);
    size_t above = add_face(m, BS_FACE_PLANE, up, ex, ey, ez, 0.0, plane_box);
    size_t sphere = add_face(m, BS_FACE_SPHERE, origin, ex, ey, ez, 1.0, sph_box);
    double root = sqrt(3.0) / 2.0;
    /* from points 0.03 off the meeting line y = root, z = 0, at x = 1.25 */
    unsigned long long seed = 5;
    double worst = 0.0, worst_move = 0.0;
    for (int i = 0; i < 200; i++) {
        double x = bs_test_rand(&seed, -3.0, 3.0), off = bs_test_rand(&seed, -0.03, 0.03);
        /* the cylinder's point at angle -pi/6 + off (z = 0 there when off = 0) */
        double a = -PI / 6 + off, ua[2] = {a, x}, ub[2] = {x + 0.02, root - 0.02}, X[3], P[3];
        double start[3] = {x, cos(a), 0.5 + sin(a)};
        CHECK(bsi_face_point(m, cyl, ua[0], ua[1], P) && dist3(P, start) < 1e-12);
        if (!bsi_tm_meet(m, cyl, ua, plane, ub, 1e-13, X)) {
            CHECKF(0, "no meeting point from x = %g, off %g", x, off);
            continue;
        }
        double on_plane[3], on_cyl[3];
        CHECK(bsi_face_point(m, plane, ub[0], ub[1], on_plane) && bsi_face_point(m, cyl, ua[0], ua[1], on_cyl));
        double line[3] = {X[0], root, 0.0};
        double e = dist3(X, line) + dist3(X, on_plane) + dist3(X, on_cyl);
        worst = e > worst ? e : worst;
        /* the nearest point of the meeting line is (x, root, 0); the first face's point moves
         * along the cylinder's circle, so X stays at its x */
        double move = fabs(X[0] - x);
        worst_move = move > worst_move ? move : worst_move;
    }
    CHECKF(worst <= 1e-12, "meeting points off the line or the faces by %.3g", worst);
    CHECKF(worst_move <= 1e-3, "the first face's point moved along the line by %.3g", worst_move);
    /* the first face moves less than the second: from the plane's side, the plane's point */
    {
        double ua[2] = {1.0, root + 0.01}, ub[2] = {-PI / 6 + 0.01, 1.0}, X[3];
        CHECK(bsi_tm_meet(m, plane, ua, cyl, ub, 1e-13, X));
        CHECKF(fabs(X[1] - root) < 1e-12 && fabs(X[0] - 1.0) < 1e-3, "from the plane: (%g %g %g)", X[0], X[1], X[2]);
    }
    /* refusals: the cylinder about the axis through z = 1 touches the plane z = 0 along y = 0
     * (tangent faces); the planes z = 0 and z = 1 never meet; a pole of the sphere (no direction
     * to move in there) */
    {
        double ua[2] = {1.0, 0.01}, ub[2] = {-PI / 2 + 0.01, 1.0}, X[3];
        CHECK(!bsi_tm_meet(m, plane, ua, touching, ub, 1e-13, X));
        double pa[2] = {0.0, 0.0}, pb[2] = {0.1, 0.1};
        CHECK(!bsi_tm_meet(m, plane, pa, above, pb, 1e-13, X));
        double pole[2] = {0.3, PI / 2}, q[2] = {0.5, 0.5};
        CHECK(!bsi_tm_meet(m, sphere, pole, above, q, 1e-13, X));
        /* unmoved on refusal */
        CHECK(pole[0] == 0.3 && pole[1] == PI / 2 && q[0] == 0.5 && q[1] == 0.5);
    }
    bs_model_destroy(m);
    return bs_test_exit("test_tess_meet");
}
