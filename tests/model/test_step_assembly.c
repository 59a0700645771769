/* STEP assemblies. OpenCASCADE's assembly (data/step/assembly.step: a plate and a sub-assembly of
 * two cone pegs placed twice, see occt_assembly_gen.cpp) against the kernel's .ref and against the
 * placements it was built from, composed here: every point of every instance must lie on its part
 * moved by exactly one of them. Then small texts around a cube: MAPPED_ITEM placements and
 * representations joined without a motion, nesting composed, and the refusals (cycles, nesting
 * too deep, mixed length units, transformations other than placements, the cap on placed faces). */
#include "harness.h"
#include "step_text.h"

#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

/* ---- rigid motions: p -> r p + t ---- */

typedef struct motion {
    double r[9], t[3];
} motion;

static motion shift(double x, double y, double z)
{
    motion m = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, {x, y, z}};
    return m;
}

/* A turn by angle a about the line through c along axis 0 (x) or 2 (z). */
static motion turn(int axis, double a, const double *c)
{
    double co = cos(a), si = sin(a);
    motion m = shift(0, 0, 0);
    int i = axis == 0 ? 1 : 0, j = axis == 0 ? 2 : 1; /* the plane turned: (y, z) or (x, y) */
    m.r[3 * i + i] = co;
    m.r[3 * i + j] = -si;
    m.r[3 * j + i] = si;
    m.r[3 * j + j] = co;
    for (int k = 0; k < 3; k++)
        m.t[k] = c[k] - (m.r[3 * k] * c[0] + m.r[3 * k + 1] * c[1] + m.r[3 * k + 2] * c[2]);
    return m;
}

/* a after b */
static motion after(const motion *a, const motion *b)
{
    motion m;
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            m.r[3 * r + c] = a->r[3 * r] * b->r[c] + a->r[3 * r + 1] * b->r[3 + c] + a->r[3 * r + 2] * b->r[6 + c];
        m.t[r] = a->r[3 * r] * b->t[0] + a->r[3 * r + 1] * b->t[1] + a->r[3 * r + 2] * b->t[2] + a->t[r];
    }
    return m;
}

/* The point p moved back by m: r^T (p - t). */
static void back(const motion *m, const double *p, double *q)
{
    for (int c = 0; c < 3; c++)
        q[c] = m->r[c] * (p[0] - m->t[0]) + m->r[3 + c] * (p[1] - m->t[1]) + m->r[6 + c] * (p[2] - m->t[2]);
}

/* ---- points inside the faces of one instance ---- */

#define GRID 7
#define MAXPTS 4096

/* Points of the faces of instance `inst` (GRID x GRID over each face's box, those classified inside)
 * into pts; returns their count, and the instance's faces into *faces. */
static size_t instance_points(const bs_model *m, size_t inst, double *pts, size_t *faces)
{
    size_t n = 0;
    *faces = 0;
    for (size_t f = 0; f < bs_model_face_count(m); f++) {
        bs_face_info fi;
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK || fi.instance != inst)
            continue;
        (*faces)++;
        uint32_t id[GRID * GRID];
        double u[GRID * GRID], v[GRID * GRID], xyz[3][GRID * GRID];
        unsigned char where[GRID * GRID];
        for (int a = 0; a < GRID; a++)
            for (int b = 0; b < GRID; b++) {
                id[a * GRID + b] = (uint32_t)f;
                u[a * GRID + b] = fi.u0 + (fi.u1 - fi.u0) * (a + 0.5) / GRID;
                v[a * GRID + b] = fi.v0 + (fi.v1 - fi.v0) * (b + 0.5) / GRID;
            }
        bs_cview uv[2] = {{u, GRID * GRID, sizeof(double)}, {v, GRID * GRID, sizeof(double)}};
        bs_view pos[3];
        for (int c = 0; c < 3; c++)
            pos[c] = (bs_view){xyz[c], GRID * GRID, sizeof(double)};
        CHECK_STATUS(bs_model_classify(m, GRID * GRID, id, &uv[0], &uv[1], 1e-9, where), BS_OK);
        CHECK_STATUS(bs_model_face_eval(m, GRID * GRID, id, &uv[0], &uv[1], pos, NULL, NULL), BS_OK);
        for (int k = 0; k < GRID * GRID && n < MAXPTS; k++)
            if (where[k] == BS_TRIM_INSIDE) {
                for (size_t c = 0; c < 3; c++)
                    pts[3 * n + c] = xyz[c][k];
                n++;
            }
    }
    return n;
}

/* ---- OpenCASCADE's assembly ---- */

/* On the peg (OpenCASCADE's cone of radii 3 and 1.5 and height 8, its base at the origin)? */
static int on_peg(const double *p, double tol)
{
    double r = hypot(p[0], p[1]);
    if (fabs(p[2]) <= tol || fabs(p[2] - 8.0) <= tol)
        return r <= (p[2] < 4.0 ? 3.0 : 1.5) + tol;
    return p[2] > -tol && p[2] < 8.0 + tol && fabs(r - (3.0 - 1.5 * p[2] / 8.0)) <= tol;
}

/* On the plate (the box 40 x 20 x 4 less the hole of radius 3 about (10, 10))? */
static int on_plate(const double *p, double tol)
{
    const double hi[3] = {40.0, 20.0, 4.0};
    int on_side = 0;
    for (int c = 0; c < 3; c++) {
        if (p[c] < -tol || p[c] > hi[c] + tol)
            return 0;
        on_side |= fabs(p[c]) <= tol || fabs(p[c] - hi[c]) <= tol;
    }
    double r = hypot(p[0] - 10.0, p[1] - 10.0);
    return r >= 3.0 - tol && (on_side || fabs(r - 3.0) <= tol);
}

static double ref_value(FILE *f, const char *key)
{
    char line[256], k[32];
    double x = NAN;
    rewind(f);
    while (fgets(line, sizeof line, f) != NULL)
        if (sscanf(line, "%31s %lf", k, &x) == 2 && strcmp(k, key) == 0)
            return x;
    return NAN;
}

static void test_occt_assembly(void)
{
    bs_parse_error err;
    bs_model *m = NULL;
    memset(&err, 0, sizeof err);
    bs_status st = bs_model_read_step_file(BS_TEST_SOURCE_DIR "/data/step/assembly.step", &err, &m);
    CHECKF(st == BS_OK, "assembly.step: status %d, %s", st, err.message);
    FILE *ref = fopen(BS_TEST_SOURCE_DIR "/data/step/assembly.ref", "r");
    CHECK(ref != NULL);
    if (m == NULL || ref == NULL) {
        bs_model_destroy(m);
        if (ref != NULL)
            fclose(ref);
        return;
    }
    double area = NAN, volume = NAN, faces = ref_value(ref, "faces"), instances = ref_value(ref, "instances");
    CHECK_STATUS(bs_model_properties(m, 1e-10, &area, &volume, NULL), BS_OK);
    CHECKF((double)bs_model_face_count(m) == faces && bs_model_shell_count(m) == (size_t)instances,
           "%zu faces, %zu shells: the kernel's %g faces, %g instances", bs_model_face_count(m), bs_model_shell_count(m),
           faces, instances);
    CHECKF(fabs(area - ref_value(ref, "area")) <= 1e-9 * area && fabs(volume - ref_value(ref, "volume")) <= 1e-9 * volume,
           "area %.15g volume %.15g, the kernel's %.15g %.15g", area, volume, ref_value(ref, "area"), ref_value(ref, "volume"));
    fclose(ref);
    for (size_t s = 0; s < bs_model_shell_count(m); s++)
        CHECKF(bs_model_shell_closed(m, s) == 1, "shell %zu open", s);

    /* the placements the generator made, composed here */
    const double z0[3] = {0, 0, 0}, pivot[3] = {30, 10, 0};
    motion upright = shift(0, 0, 4), lying = turn(0, pi / 2, z0), sl = shift(8, 0, 4);
    motion in_pair[2] = {upright, after(&sl, &lying)};
    motion t2 = shift(-10, 3, 0), r2 = turn(2, 2.0, pivot);
    motion pair[2] = {shift(25, 5, 0), after(&t2, &r2)};
    motion world[4];
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            world[2 * a + b] = after(&pair[a], &in_pair[b]);
    int used[4] = {0, 0, 0, 0}, plates = 0;
    static double pts[3 * MAXPTS];
    const double tol = 1e-9 * 50.0;
    for (size_t inst = 0; inst < (size_t)instances; inst++) {
        size_t nf, n = instance_points(m, inst, pts, &nf);
        CHECKF(n >= 3 * nf && (nf == 7 || nf == 3), "instance %zu: %zu faces, %zu points inside", inst, nf, n);
        if (nf == 7) {
            int all = 1;
            for (size_t k = 0; k < n; k++)
                all &= on_plate(pts + 3 * k, tol);
            CHECKF(all, "instance %zu: the plate is not where it was placed", inst);
            plates++;
            continue;
        }
        int matches = 0;
        for (int w = 0; w < 4; w++) {
            int all = 1;
            for (size_t k = 0; k < n && all; k++) {
                double q[3];
                back(&world[w], pts + 3 * k, q);
                all &= on_peg(q, tol);
            }
            if (all) {
                matches++;
                used[w]++;
            }
        }
        CHECKF(matches == 1, "instance %zu: on the peg moved by %d of the placements, not 1", inst, matches);
    }
    CHECKF(plates == 1 && used[0] == 1 && used[1] == 1 && used[2] == 1 && used[3] == 1,
           "plates %d, pegs placed %d %d %d %d times", plates, used[0], used[1], used[2], used[3]);
    bs_model_destroy(m);
}

/* ---- small texts around a cube ---- */

/* The cube part: solid #3 in ADVANCED_BREP_SHAPE_REPRESENTATION #2, joined without a motion to
 * SHAPE_REPRESENTATION #4 that REPRESENTATION_MAP #6 maps; contexts in millimetres (#9) and in
 * inches (#11); placement #8 at the origin. */
#define PART                                                                                              \
    "#2 = ADVANCED_BREP_SHAPE_REPRESENTATION('cube',(#8,#3),#9);\n#3 = MANIFOLD_SOLID_BREP('',#1000);\n"  \
    "#4 = SHAPE_REPRESENTATION('part',(#8),#9);\n#5 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#4,#2);\n"  \
    "#6 = REPRESENTATION_MAP(#8,#4);\n#7 = CARTESIAN_POINT('',(0.,0.,0.));\n"                            \
    "#8 = AXIS2_PLACEMENT_3D('',#7,$,$);\n"                                                               \
    "#9 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#10)) "                     \
    "REPRESENTATION_CONTEXT('','') );\n#10 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n" \
    "#11 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#12)) "                    \
    "REPRESENTATION_CONTEXT('','') );\n#12 = ( CONVERSION_BASED_UNIT('INCH',#13) LENGTH_UNIT() "          \
    "NAMED_UNIT(#14) );\n#13 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#10);\n"                     \
    "#14 = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"                                                \
    "#15 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#16)) "                    \
    "REPRESENTATION_CONTEXT('','') );\n#16 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.) );\n"

/* HEAD, the part, `more` and TAIL in buf. */
static const char *cube_file(char *buf, size_t cap, const char *more)
{
    size_t n = (size_t)snprintf(buf, cap, "%s%s", HEAD, PART);
    n += cube(buf + n, cap - n, 1000, 0.0, 2.0);
    n += (size_t)snprintf(buf + n, cap - n, "%s%s", more, TAIL);
    return n < cap ? buf : NULL;
}

/* The box of instance inst's faces (corners of their native boxes: the cube's faces are planes). */
static void instance_box(const bs_model *m, size_t inst, double *lo, double *hi)
{
    for (int c = 0; c < 3; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t f = 0; f < bs_model_face_count(m); f++) {
        bs_face_info fi;
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK || fi.instance != inst)
            continue;
        uint32_t id[4] = {(uint32_t)f, (uint32_t)f, (uint32_t)f, (uint32_t)f};
        double u[4] = {fi.u0, fi.u1, fi.u0, fi.u1}, v[4] = {fi.v0, fi.v0, fi.v1, fi.v1}, xyz[3][4];
        bs_cview cu = {u, 4, sizeof(double)}, cv = {v, 4, sizeof(double)};
        bs_view pos[3] = {{xyz[0], 4, sizeof(double)}, {xyz[1], 4, sizeof(double)}, {xyz[2], 4, sizeof(double)}};
        CHECK_STATUS(bs_model_face_eval(m, 4, id, &cu, &cv, pos, NULL, NULL), BS_OK);
        for (int k = 0; k < 4; k++)
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], xyz[c][k]);
                hi[c] = fmax(hi[c], xyz[c][k]);
            }
    }
}

/* Instance inst's box is lo + [0,2]^3 moved by nothing but a shift (or its corner lo, hi given). */
static int box_is(const bs_model *m, size_t inst, const double *lo, const double *hi)
{
    double a[3], b[3];
    instance_box(m, inst, a, b);
    int ok = 1;
    for (int c = 0; c < 3; c++)
        ok &= fabs(a[c] - lo[c]) <= 1e-12 && fabs(b[c] - hi[c]) <= 1e-12;
    return ok;
}

/* Each expected box (lo, hi: 3 each) held by exactly one instance, and all n instances closed
 * cubes of volume 8. */
static void expect_boxes(const char *what, const char *text, size_t n, const double (*lo)[3], const double (*hi)[3])
{
    bs_model *m = must_read(what, text);
    if (m == NULL)
        return;
    double volume = NAN;
    CHECK_STATUS(bs_model_properties(m, 1e-10, NULL, &volume, NULL), BS_OK);
    CHECKF(bs_model_face_count(m) == 6 * n && bs_model_shell_count(m) == n && fabs(volume - 8.0 * (double)n) <= 1e-9 * volume,
           "%s: %zu faces, %zu shells, volume %.15g (%zu cubes)", what, bs_model_face_count(m), bs_model_shell_count(m),
           volume, n);
    for (size_t s = 0; s < bs_model_shell_count(m); s++)
        CHECKF(bs_model_shell_closed(m, s) == 1, "%s: shell %zu open", what, s);
    for (size_t k = 0; k < n; k++) {
        int held = 0;
        for (size_t inst = 0; inst < n; inst++)
            held += box_is(m, inst, lo[k], hi[k]);
        CHECKF(held == 1, "%s: box %zu held by %d instances", what, k, held);
    }
    bs_model_destroy(m);
}

static char text[1 << 16];

static void test_mapped_items(void)
{
    /* identity, turned a quarter about z and moved to x = 10, and the axis along x moved to y = 10 */
    const char *items = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20,#21,#22),#9);\n#20 = MAPPED_ITEM('',#6,#8);\n"
                        "#21 = MAPPED_ITEM('',#6,#30);\n#30 = AXIS2_PLACEMENT_3D('',#31,#32,#33);\n"
                        "#31 = CARTESIAN_POINT('',(10.,0.,0.));\n#32 = DIRECTION('',(0.,0.,1.));\n"
                        "#33 = DIRECTION('',(0.,1.,0.));\n#22 = MAPPED_ITEM('',#6,#40);\n"
                        "#40 = AXIS2_PLACEMENT_3D('',#41,#42,#33);\n#41 = CARTESIAN_POINT('',(0.,10.,0.));\n"
                        "#42 = DIRECTION('',(1.,0.,0.));\n";
    const double lo[3][3] = {{0, 0, 0}, {8, 0, 0}, {0, 10, 0}}, hi[3][3] = {{2, 2, 2}, {10, 2, 2}, {2, 12, 2}};
    expect_boxes("mapped items", cube_file(text, sizeof text, items), 3, lo, hi);

    /* a relationship with a transformation whose first placement is not the origin: F2 F1^-1 */
    const char *rel = "#1 = SHAPE_REPRESENTATION('asm',(#8),#9);\n"
                      "#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) "
                      "SHAPE_REPRESENTATION_RELATIONSHIP() );\n#61 = ITEM_DEFINED_TRANSFORMATION('','',#62,#64);\n"
                      "#62 = AXIS2_PLACEMENT_3D('',#63,$,$);\n#63 = CARTESIAN_POINT('',(1.,0.,0.));\n"
                      "#64 = AXIS2_PLACEMENT_3D('',#65,#66,#67);\n#65 = CARTESIAN_POINT('',(0.,0.,5.));\n"
                      "#66 = DIRECTION('',(0.,0.,1.));\n#67 = DIRECTION('',(0.,1.,0.));\n";
    const double rlo[1][3] = {{-2, -1, 5}}, rhi[1][3] = {{0, 1, 7}};
    expect_boxes("relationship with a transformation", cube_file(text, sizeof text, rel), 1, rlo, rhi);

    /* the assembly in metres, written as 1000 millimetres by another context: the same unit */
    const char *metres = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#15);\n#20 = MAPPED_ITEM('',#6,#8);\n";
    const double mlo[1][3] = {{0, 0, 0}}, mhi[1][3] = {{2, 2, 2}};
    must_refuse("part in mm, assembly in m", cube_file(text, sizeof text, metres), BS_ERR_UNSUPPORTED, 0, "mixed length units");
    const char *inch = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#11);\n#20 = MAPPED_ITEM('',#6,#8);\n";
    must_refuse("part in mm, assembly in inches", cube_file(text, sizeof text, inch), BS_ERR_UNSUPPORTED, 0,
                "mixed length units");
    const char *same = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#17);\n#20 = MAPPED_ITEM('',#6,#8);\n"
                       "#17 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#18)) "
                       "REPRESENTATION_CONTEXT('','') );\n#18 = ( CONVERSION_BASED_UNIT('MM',#19) LENGTH_UNIT() "
                       "NAMED_UNIT(#14) );\n#19 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(0.001),#16);\n";
    expect_boxes("millimetres written two ways", cube_file(text, sizeof text, same), 1, mlo, mhi);

    const char *op = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#6,#50);\n"
                     "#50 = CARTESIAN_TRANSFORMATION_OPERATOR_3D('','',$,#7,$,1.,$);\n";
    must_refuse("a transformation operator", cube_file(text, sizeof text, op), BS_ERR_UNSUPPORTED, 0, "AXIS2_PLACEMENT_3D");
    const char *fdt = "#1 = SHAPE_REPRESENTATION('asm',(#8),#9);\n"
                      "#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) "
                      "SHAPE_REPRESENTATION_RELATIONSHIP() );\n#61 = FUNCTIONALLY_DEFINED_TRANSFORMATION('','');\n";
    must_refuse("a functionally defined transformation", cube_file(text, sizeof text, fdt), BS_ERR_UNSUPPORTED, 0,
                "ITEM_DEFINED_TRANSFORMATION");
    const char *notrep = "#60 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#2,#3);\n";
    must_refuse("a relationship to a solid", cube_file(text, sizeof text, notrep), BS_ERR_PARSE, 0, "not a representation");
}

/* Solids with voids and surface models placed by an assembly, and the refusals of what an
 * assembly names: a map that is not a REPRESENTATION_MAP, a map of something that is not a
 * representation, a solid whose shell is not a shell. */
static void test_held_shapes(void)
{
    static char more[1 << 15];
    /* the cube with a void (a second cube, used reversed) in #70, placed twice: 4 shells, 2 x 7 */
    size_t n = (size_t)snprintf(more, sizeof more,
                                "#1 = SHAPE_REPRESENTATION('asm',(#8,#20,#21),#9);\n#20 = MAPPED_ITEM('',#72,#8);\n"
                                "#21 = MAPPED_ITEM('',#72,#40);\n#40 = AXIS2_PLACEMENT_3D('',#41,$,$);\n"
                                "#41 = CARTESIAN_POINT('',(5.,0.,0.));\n#72 = REPRESENTATION_MAP(#8,#70);\n"
                                "#70 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#71),#9);\n"
                                "#71 = BREP_WITH_VOIDS('',#1000,(#73));\n#73 = ORIENTED_CLOSED_SHELL('',*,#2000,.F.);\n");
    n += cube(more + n, sizeof more - n, 2000, 0.5, 1.5);
    (void)n;
    bs_model *m = must_read("voids placed twice", cube_file(text, sizeof text, more));
    double volume = NAN;
    if (m != NULL) {
        CHECK_STATUS(bs_model_properties(m, 1e-10, NULL, &volume, NULL), BS_OK);
        CHECKF(bs_model_shell_count(m) == 4 && fabs(volume - 14.0) <= 1e-9, "voids placed twice: %zu shells, volume %.15g",
               bs_model_shell_count(m), volume);
        bs_model_destroy(m);
    }
    /* the cube's shell as a surface model's (SHELL_BASED_SURFACE_MODEL) placed twice */
    (void)snprintf(more, sizeof more,
                   "#1 = SHAPE_REPRESENTATION('asm',(#8,#20,#21),#9);\n#20 = MAPPED_ITEM('',#72,#8);\n"
                   "#21 = MAPPED_ITEM('',#72,#40);\n#40 = AXIS2_PLACEMENT_3D('',#41,$,$);\n"
                   "#41 = CARTESIAN_POINT('',(5.,0.,0.));\n#72 = REPRESENTATION_MAP(#8,#70);\n"
                   "#70 = MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#71),#9);\n"
                   "#71 = SHELL_BASED_SURFACE_MODEL('',(#1000));\n");
    const double lo[2][3] = {{0, 0, 0}, {5, 0, 0}}, hi[2][3] = {{2, 2, 2}, {7, 2, 2}};
    expect_boxes("a surface model placed twice", cube_file(text, sizeof text, more), 2, lo, hi);

    const char *not_map = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#8,#8);\n";
    must_refuse("a mapped item of a placement", cube_file(text, sizeof text, not_map), BS_ERR_PARSE, 0,
                "expected a REPRESENTATION_MAP");
    const char *map_solid = "#1 = SHAPE_REPRESENTATION('asm',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#72,#8);\n"
                            "#72 = REPRESENTATION_MAP(#8,#3);\n";
    must_refuse("a map of a solid", cube_file(text, sizeof text, map_solid), BS_ERR_PARSE, 0, "not a representation");
    const char *bad_solid = "#70 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#71),#9);\n#71 = MANIFOLD_SOLID_BREP('',#8);\n";
    must_refuse("a solid of a placement", cube_file(text, sizeof text, bad_solid), BS_ERR_PARSE, 0, "is not a shell");
}

/* Assembly entities spoiled one at a time: a clean refusal naming what is wrong, or (units the
 * reader cannot tell) a model read as if the units agreed. */
static void test_spoiled_entities(void)
{
    static const struct {
        const char *what, *more;
        bs_status status;
        const char *words;
    } cases[] = {
        {"a relationship to an undefined representation", "#60 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#2,#999);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"a transformation that is not defined",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) SHAPE_REPRESENTATION_RELATIONSHIP() );\n",
         BS_ERR_PARSE, "refers to #61"},
        {"an item-defined transformation of one item",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) SHAPE_REPRESENTATION_RELATIONSHIP() );\n"
         "#61 = ITEM_DEFINED_TRANSFORMATION('','',#8);\n",
         BS_ERR_PARSE, "missing"},
        {"an item-defined transformation from a point",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) SHAPE_REPRESENTATION_RELATIONSHIP() );\n"
         "#61 = ITEM_DEFINED_TRANSFORMATION('','',#7,#8);\n",
         BS_ERR_UNSUPPORTED, "AXIS2_PLACEMENT_3D"},
        {"a relationship without its transformation",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION() SHAPE_REPRESENTATION_RELATIONSHIP() );\n",
         BS_ERR_PARSE, "missing"},
        {"a mapped item without a target", "#1 = SHAPE_REPRESENTATION('',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#6);\n",
         BS_ERR_PARSE, "missing"},
        {"a map without its representation",
         "#1 = SHAPE_REPRESENTATION('',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#72,#8);\n#72 = REPRESENTATION_MAP(#8);\n",
         BS_ERR_PARSE, "missing"},
        {"a solid without its shell", "#70 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#71),#9);\n#71 = MANIFOLD_SOLID_BREP('');\n",
         BS_ERR_PARSE, "missing"},
        {"a surface model of an undefined shell",
         "#70 = MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#71),#9);\n#71 = SHELL_BASED_SURFACE_MODEL('',(#999));\n",
         BS_ERR_PARSE, "refers to #999"},
        {"a surface model whose shells are not a list",
         "#70 = MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#71),#9);\n#71 = SHELL_BASED_SURFACE_MODEL('',#1000);\n",
         BS_ERR_PARSE, "must be a list"},
        {"an oriented shell without its shell",
         "#70 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#71),#9);\n#71 = BREP_WITH_VOIDS('',#1000,(#73));\n"
         "#73 = ORIENTED_CLOSED_SHELL('',*);\n",
         BS_ERR_PARSE, "missing"},
        {"a relationship to a representation without a context",
         "#60 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#2,#70);\n#70 = SHAPE_REPRESENTATION('',(#8),$);\n",
         BS_ERR_PARSE, "not a representation"},
        {"a relationship of a solid", "#60 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#3,#2);\n", BS_ERR_PARSE,
         "not a representation"},
        {"a relationship of an undefined representation", "#60 = SHAPE_REPRESENTATION_RELATIONSHIP('','',#999,#2);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"an item-defined transformation from an undefined item",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) SHAPE_REPRESENTATION_RELATIONSHIP() );\n"
         "#61 = ITEM_DEFINED_TRANSFORMATION('','',#999,#8);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"an item-defined transformation onto a point",
         "#1 = SHAPE_REPRESENTATION('',(#8),#9);\n#60 = ( REPRESENTATION_RELATIONSHIP('','',#2,#1) "
         "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#61) SHAPE_REPRESENTATION_RELATIONSHIP() );\n"
         "#61 = ITEM_DEFINED_TRANSFORMATION('','',#8,#7);\n",
         BS_ERR_UNSUPPORTED, "AXIS2_PLACEMENT_3D"},
        {"a placement at an undefined point",
         "#1 = SHAPE_REPRESENTATION('',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#6,#62);\n"
         "#62 = AXIS2_PLACEMENT_3D('',#999,$,$);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"a mapped item of an undefined map", "#1 = SHAPE_REPRESENTATION('',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#999,#8);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"a map from an undefined origin",
         "#1 = SHAPE_REPRESENTATION('',(#8,#20),#9);\n#20 = MAPPED_ITEM('',#72,#8);\n#72 = REPRESENTATION_MAP(#999,#4);\n",
         BS_ERR_PARSE, "refers to #999"},
        {"a part in metres by a general measure",
         "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
         "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#81)) REPRESENTATION_CONTEXT('','') );\n"
         "#81 = ( CONVERSION_BASED_UNIT('M',#83) LENGTH_UNIT() NAMED_UNIT(#14) );\n"
         "#83 = MEASURE_WITH_UNIT(LENGTH_MEASURE(1000.),#10);\n",
         BS_ERR_UNSUPPORTED, "mixed length units"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++)
        must_refuse(cases[k].what, cube_file(text, sizeof text, cases[k].more), cases[k].status, 0, cases[k].words);
    /* units the reader cannot read are not compared: an unknown prefix, a conversion without its
     * measure, a context without units or without a length unit */
    static const char *const units[] = {
        "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
        "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#81)) REPRESENTATION_CONTEXT('','') );\n"
        "#81 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MYRIA.,.METRE.) );\n",
        "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
        "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#81)) REPRESENTATION_CONTEXT('','') );\n"
        "#81 = ( CONVERSION_BASED_UNIT('X',$) LENGTH_UNIT() NAMED_UNIT(#14) );\n",
        "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
        "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) REPRESENTATION_CONTEXT('','') );\n",
        "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
        "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#82,$)) REPRESENTATION_CONTEXT('','') );\n"
        "#82 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );\n",
        "#1 = SHAPE_REPRESENTATION('',(#8,#20),#80);\n#20 = MAPPED_ITEM('',#6,#8);\n"
        "#80 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#81)) REPRESENTATION_CONTEXT('','') );\n"
        "#81 = ( CONVERSION_BASED_UNIT('X',#83) LENGTH_UNIT() NAMED_UNIT(#14) );\n#83 = LENGTH_MEASURE_WITH_UNIT('a',#10);\n",
    };
    const double lo[1][3] = {{0, 0, 0}}, hi[1][3] = {{2, 2, 2}};
    for (size_t k = 0; k < sizeof units / sizeof units[0]; k++)
        expect_boxes("units not compared", cube_file(text, sizeof text, units[k]), 1, lo, hi);
}

/* `levels` assemblies #5000.., each placing the next `copies` times (copy c of level j moved by
 * c 3 2^j along x, or by 1 along x when copies is 1), the last placing the cube part; cycle: the
 * last level also places the first. */
static const char *nested(int levels, int copies, int cycle)
{
    size_t n = 0;
    char more[1 << 15];
#define PUT(...) (n += (size_t)snprintf(more + n, n < sizeof more ? sizeof more - n : 0, __VA_ARGS__))
    for (int j = 0; j < levels; j++) {
        int to = j + 1 < levels ? 5100 + j + 1 : 6;
        PUT("#%d = SHAPE_REPRESENTATION('',(#8", 5000 + j);
        for (int c = 0; c < copies; c++)
            PUT(",#%d", 5200 + 4 * j + c);
        PUT("%s),#9);\n", cycle && j == levels - 1 ? ",#5199" : "");
        PUT("#%d = REPRESENTATION_MAP(#8,#%d);\n", 5100 + j, 5000 + j);
        for (int c = 0; c < copies; c++) {
            double x = copies == 1 ? 1.0 : c * 3.0 * (double)(1 << j);
            PUT("#%d = MAPPED_ITEM('',#%d,#%d);\n#%d = AXIS2_PLACEMENT_3D('',#%d,$,$);\n"
                "#%d = CARTESIAN_POINT('',(%.17g,0.,0.));\n",
                5200 + 4 * j + c, to, 5400 + 4 * j + c, 5400 + 4 * j + c, 5600 + 4 * j + c,
                5600 + 4 * j + c, x);
        }
    }
    if (cycle)
        PUT("#5199 = MAPPED_ITEM('',#5100,#8);\n");
#undef PUT
    return n < sizeof more ? cube_file(text, sizeof text, more) : NULL;
}

static void test_nesting(void)
{
    const double lo[1][3] = {{10, 0, 0}}, hi[1][3] = {{12, 2, 2}};
    expect_boxes("nested 10 deep", nested(10, 1, 0), 1, lo, hi);
    double lo8[8][3], hi8[8][3];
    for (int k = 0; k < 8; k++) {
        lo8[k][0] = 3.0 * k;
        hi8[k][0] = 3.0 * k + 2.0;
        lo8[k][1] = lo8[k][2] = 0.0;
        hi8[k][1] = hi8[k][2] = 2.0;
    }
    expect_boxes("two copies at each of 3 levels", nested(3, 2, 0), 8, (const double(*)[3])lo8, (const double(*)[3])hi8);
    must_refuse("nested 40 deep", nested(40, 1, 0), BS_ERR_PARSE, 0, "deeper than 32");
    must_refuse("placed in a cycle", nested(3, 1, 1), BS_ERR_PARSE, 0, "cycle");
    /* 2^20 copies of the cube from a few kilobytes: refused before anything is placed */
    must_refuse("two copies at each of 20 levels", nested(20, 2, 0), BS_ERR_SIZE, 0, "faces, more than one per 32 bytes");
}

int main(void)
{
    test_occt_assembly();
    test_mapped_items();
    test_held_shapes();
    test_spoiled_entities();
    test_nesting();
    return bs_test_exit("test_step_assembly");
}
