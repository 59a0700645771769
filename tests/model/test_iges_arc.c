/* The IGES model reader's circular arcs (100) off the origin, centre x != y: a plane bounded by a
 * full circle and by a half circle closed by its diameter, against the closed forms of a disc and
 * a half disc (area, centroid) and the mesh's vertices, all within the radius of the centre and
 * the boundary's on the circle. */
#include "harness.h"
#include "iges_text.h"

#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The plane z = 1 (108) bounded (142, 3-D curve only) by the curve of entity 3 (DE 7) and on. */
#define PLANE_FACE {144, 0, 0, "144,3,1,0,5;"}, {108, 0, 0, "108,0.,0.,1.,1.,0,0.,0.,0.,0.;"}, \
                   {142, 0, 0, "142,0,3,0,7,2;"}

enum { CX = 3, CY = -1, R = 2 }; /* the arcs' centre (3, -1) at ZT 1 and radius */

/* Read e; its area and centroid against the closed forms; its mesh's vertices in the disc about the
 * centre (and above the diameter y = CY when half), the boundary's at the radius. */
static void check_disc(const char *what, const ent *e, size_t n, int half)
{
    bs_model *m = NULL;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_status st = read_ents(e, n, 0, &err, &m);
    CHECKF(st == BS_OK && bs_model_face_count(m) == 1, "%s: %d %s", what, (int)st, err.message);
    if (st != BS_OK)
        return;
    const double pi = 3.14159265358979323846;
    double area = 0.0, c[3] = {0, 0, 0}, want_area = (half ? 0.5 : 1.0) * pi * R * R;
    double want_cy = CY + (half ? 4.0 * R / (3.0 * pi) : 0.0); /* a half disc's centroid: 4r / 3 pi up */
    CHECK_STATUS(bs_model_properties(m, 1e-10, &area, NULL, c), BS_OK);
    CHECKF(fabs(area - want_area) < 1e-8, "%s: area %.17g, want %.17g", what, area, want_area);
    CHECKF(fabs(c[0] - CX) < 1e-8 && fabs(c[1] - want_cy) < 1e-8 && fabs(c[2] - 1.0) < 1e-8,
           "%s: centroid (%g, %g, %g), want (%d, %g, 1)", what, c[0], c[1], c[2], CX, want_cy);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = 1e-3;
    bs_mesh *mesh = NULL;
    CHECK_STATUS(bs_model_tessellate(m, &o, &mesh), BS_OK);
    size_t nv = mesh != NULL ? bs_mesh_vertex_count(mesh) : 0, outside = 0, on = 0;
    static double pos[3][4096];
    bs_view xyz[3] = {{pos[0], 4096, 0}, {pos[1], 4096, 0}, {pos[2], 4096, 0}};
    CHECKF(nv > 0 && nv <= 4096 && bs_mesh_copy_positions(mesh, xyz) == BS_OK, "%s: %zu vertices", what, nv);
    for (size_t k = 0; k < nv && nv <= 4096; k++) {
        double r = hypot(pos[0][k] - CX, pos[1][k] - CY);
        outside += r > R + 1e-9 || fabs(pos[2][k] - 1.0) > 1e-12 || (half && pos[1][k] < CY - 1e-12);
        on += fabs(r - R) <= 1e-9;
    }
    CHECKF(outside == 0 && on >= 8, "%s: %zu of %zu vertices outside the disc, %zu on its circle", what, outside, nv,
           on);
    printf("%s: %zu vertices, %zu on the circle\n", what, nv, on);
    bs_mesh_destroy(mesh);
    bs_model_destroy(m);
}

int main(void)
{
    static const ent circle[] = {PLANE_FACE, {100, 0, 0, "100,1.,3.,-1.,5.,-1.,5.,-1.;"}};
    check_disc("full circle", circle, 4, 0);
    /* counter-clockwise from (5, -1) to (1, -1): the upper half, then the diameter back (102) */
    static const ent half[] = {PLANE_FACE,
                               {102, 0, 0, "102,2,9,11;"},
                               {100, 0, 0, "100,1.,3.,-1.,5.,-1.,1.,-1.;"},
                               {110, 0, 0, "110,1.,-1.,1.,5.,-1.,1.;"}};
    check_disc("half circle", half, 6, 1);
    return bs_test_exit("test_iges_arc");
}
