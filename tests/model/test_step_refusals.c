/* The STEP reader's refusals, one small text each: the status, the line of the error and what its
 * message names; then small valid files built from one cone face (each entity read, and what the
 * model must be), units in degrees, a bound used backwards, an open shell. */
#include "harness.h"

#include <bezsurf.h>
#include <math.h>
#include <string.h>

#define HEAD "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\nENDSEC;\nDATA;\n"
#define TAIL "ENDSEC;\nEND-ISO-10303-21;\n"

typedef struct refusal {
    const char *text;
    bs_status status;
    size_t line;        /* 0: not checked */
    const char *names;  /* a fragment of the message */
} refusal;

/* A whole cone as the data/cad part writes it: its lateral face with two circles and a seam, and
 * the two discs; `SURF` and `UNIT` are replaced to make variants. */
static const char cone_body[] =
    "#1 = CLOSED_SHELL('',(#2,#40,#50));\n"
    "#2 = ADVANCED_FACE('',(#3),#30,.T.);\n"
    "#3 = FACE_BOUND('',#4,.T.);\n"
    "#4 = EDGE_LOOP('',(#5,#14,#22,#29));\n"
    "#5 = ORIENTED_EDGE('',*,*,#6,.F.);\n"
    "#6 = EDGE_CURVE('',#7,#7,#9,.T.);\n"
    "#7 = VERTEX_POINT('',#8);\n"
    "#8 = CARTESIAN_POINT('',(1.,0.,7.));\n"
    "#9 = CIRCLE('',#10,1.);\n"
    "#10 = AXIS2_PLACEMENT_3D('',#11,#12,#13);\n"
    "#11 = CARTESIAN_POINT('',(0.,0.,7.));\n"
    "#12 = DIRECTION('',(0.,0.,1.));\n"
    "#13 = DIRECTION('',(1.,0.,0.));\n"
    "#14 = ORIENTED_EDGE('',*,*,#15,.F.);\n"
    "#15 = EDGE_CURVE('',#16,#7,#18,.T.);\n"
    "#16 = VERTEX_POINT('',#17);\n"
    "#17 = CARTESIAN_POINT('',(4.,0.,0.));\n"
    "#18 = LINE('',#17,#19);\n"
    "#19 = VECTOR('',#20,1.);\n"
    "#20 = DIRECTION('',(-0.393919298579,0.,0.919145030018));\n"
    "#22 = ORIENTED_EDGE('',*,*,#23,.T.);\n"
    "#23 = EDGE_CURVE('',#16,#16,#24,.T.);\n"
    "#24 = CIRCLE('',#25,4.);\n"
    "#25 = AXIS2_PLACEMENT_3D('',#26,#12,#13);\n"
    "#26 = CARTESIAN_POINT('',(0.,0.,0.));\n"
    "#29 = ORIENTED_EDGE('',*,*,#15,.T.);\n"
    "#30 = CONICAL_SURFACE('',#31,4.,0.404891786285);\n"
    "#31 = AXIS2_PLACEMENT_3D('',#26,#32,#13);\n"
    "#32 = DIRECTION('',(0.,0.,-1.));\n"
    "#40 = ADVANCED_FACE('',(#41),#43,.T.);\n"
    "#41 = FACE_OUTER_BOUND('',#42,.T.);\n"
    "#42 = EDGE_LOOP('',(#5));\n"
    "#43 = PLANE('',#10);\n"
    "#50 = ADVANCED_FACE('',(#51),#53,.F.);\n"
    "#51 = FACE_OUTER_BOUND('',#52,.T.);\n"
    "#52 = EDGE_LOOP('',(#22));\n"
    "#53 = PLANE('',#25);\n";

static void test_refusals(void)
{
    static const refusal cases[] = {
        {"", BS_ERR_PARSE, 1, "ISO-10303-21"},
        {"ISO-10303-21;\nHEADER;\n", BS_ERR_PARSE, 3, "end of file"},
        {"ISO-10303-21;\nDATA;\n", BS_ERR_PARSE, 2, "HEADER"},
        {HEAD "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n", BS_ERR_PARSE, 0, "end of file"},
        {HEAD "/* not closed\n", BS_ERR_PARSE, 6, "comment"},
        {HEAD "#1 = CARTESIAN_POINT('not closed,(0.,0.,0.));\n" TAIL, BS_ERR_PARSE, 6, "string"},
        {HEAD "#1 = CARTESIAN_POINT('',(0.,0.,1.5.2));\n" TAIL, BS_ERR_PARSE, 6, "number"},
        {HEAD "#1 = CARTESIAN_POINT('',(0.,0.,0.) 7);\n" TAIL, BS_ERR_PARSE, 6, "',' or ')'"},
        {HEAD "#1 = CARTESIAN_POINT('',(#));\n" TAIL, BS_ERR_PARSE, 6, "entity number"},
        {HEAD "#1 = A(.T);\n" TAIL, BS_ERR_PARSE, 6, "enumeration"},
        {HEAD "#1 = A(,);\n" TAIL, BS_ERR_PARSE, 6, "parameter"},
        {HEAD "#1 = (1);\n" TAIL, BS_ERR_PARSE, 6, "entity name"},
        {HEAD "1 = A();\n" TAIL, BS_ERR_PARSE, 6, "instance"},
        {HEAD "#1 = A(((((((((((((((((((((((((((((((((((1)))))))))))))))))))))))))))))))))));\n" TAIL, BS_ERR_PARSE, 6,
         "nested"},
        {HEAD "#1 = A(1);\n#1 = A(2);\n" TAIL, BS_ERR_PARSE, 0, "defined twice"},
        {HEAD "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL, BS_ERR_PARSE, 1, "no B-rep faces"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n" TAIL, BS_ERR_PARSE, 6, "#2"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL, BS_ERR_PARSE, 6, "not a face"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ORIENTED_FACE('',(),#3,.T.);\n" TAIL, BS_ERR_PARSE, 7, "oriented faces"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(),#3,.T.);\n#3 = OFFSET_SURFACE('',#4,1.,.F.);\n" TAIL,
         BS_ERR_UNSUPPORTED, 8, "OFFSET_SURFACE"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = EDGE_LOOP('',(#7));\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#7 = ORIENTED_EDGE('',*,*,#9,.T.);\n#8 = CARTESIAN_POINT('',(0.,0.,0.));\n"
              "#9 = EDGE_CURVE('',#10,#10,#11,.T.);\n#10 = VERTEX_POINT('',#8);\n#11 = TRIMMED_CURVE('',#12,(),(),.T.,.PARAMETER.);\n"
              "#12 = TRIMMED_CURVE('',#11,(),(),.T.,.PARAMETER.);\n" TAIL,
         BS_ERR_PARSE, 0, "cycle"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = EDGE_LOOP('',(#7));\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#7 = ORIENTED_EDGE('',*,*,#9,.T.);\n#8 = CARTESIAN_POINT('',(0.,0.,0.));\n"
              "#9 = EDGE_CURVE('',#10,#10,#11,.T.);\n#10 = VERTEX_POINT('',#8);\n#11 = HYPERBOLA('',#6,1.,1.);\n" TAIL,
         BS_ERR_UNSUPPORTED, 0, "HYPERBOLA"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = CYLINDRICAL_SURFACE('',#6,-1.);\n#5 = EDGE_LOOP('',());\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL,
         BS_ERR_PARSE, 9, "radius"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = EDGE_LOOP('',());\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL,
         BS_ERR_PARSE, 0, "empty loop"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = POLY_LOOP('',());\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL,
         BS_ERR_PARSE, 0, "EDGE_LOOP"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = VERTEX_LOOP('',#9);\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n#9 = VERTEX_POINT('',#8);\n" TAIL,
         BS_ERR_PARSE, 0, "unbounded"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = EDGE_LOOP('',(#7));\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#7 = ORIENTED_EDGE('',*,*,#9,.T.);\n#8 = CARTESIAN_POINT('',(0.,0.,0.));\n#9 = VERTEX_POINT('',#8);\n" TAIL,
         BS_ERR_PARSE, 0, "EDGE_CURVE"},
        {HEAD "#1 = CLOSED_SHELL('',(#2));\n#2 = ADVANCED_FACE('',(#3),#4,.T.);\n#3 = FACE_BOUND('',#5,.T.);\n"
              "#4 = PLANE('',#6);\n#5 = EDGE_LOOP('',(#8));\n#6 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
              "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n" TAIL,
         BS_ERR_PARSE, 0, "ORIENTED_EDGE"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        bs_parse_error err;
        bs_model *m = (bs_model *)&err;
        memset(&err, 0, sizeof err);
        bs_status st = bs_model_read_step(cases[k].text, strlen(cases[k].text), &err, &m);
        CHECKF(st == cases[k].status, "case %zu: status %d, wanted %d (%zu:%zu %s)", k, st, cases[k].status, err.line,
               err.column, err.message);
        CHECKF(m == NULL, "case %zu: a model on failure", k);
        CHECKF(cases[k].line == 0 || err.line == cases[k].line, "case %zu: line %zu, wanted %zu (%s)", k, err.line,
               cases[k].line, err.message);
        CHECKF(strstr(err.message, cases[k].names) != NULL, "case %zu: '%s' does not name '%s'", k, err.message,
               cases[k].names);
        bs_model_destroy(st == BS_OK ? m : NULL);
    }
}

/* The cone built above in a file, with `extra` appended to its DATA section. */
static bs_model *cone_with(const char *body, double *area, double *volume)
{
    char text[8192];
    int n = snprintf(text, sizeof text, "%s%s%s", HEAD, body, TAIL);
    bs_parse_error err;
    bs_model *m = NULL;
    memset(&err, 0, sizeof err);
    bs_status st = bs_model_read_step(text, (size_t)n, &err, &m);
    CHECKF(st == BS_OK, "cone: status %d at %zu:%zu %s", st, err.line, err.column, err.message);
    if (st == BS_OK)
        CHECK_STATUS(bs_model_properties(m, 1e-10, area, volume, NULL), BS_OK);
    return m;
}

static void test_cone(void)
{
    /* the truncated cone of data/cad/cone.step: radii 4 and 1, height 7 */
    const double pi = 3.14159265358979323846, slant = sqrt(49.0 + 9.0);
    const double area = pi * (16.0 + 1.0) + pi * (4.0 + 1.0) * slant, volume = pi * 7.0 * (16.0 + 4.0 + 1.0) / 3.0;
    double a = 0, v = 0;
    bs_model *m = cone_with(cone_body, &a, &v);
    CHECK(bs_model_face_count(m) == 3 && bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == 1);
    CHECKF(fabs(a - area) <= 1e-9 * area && fabs(v - volume) <= 1e-9 * volume, "cone: area %.15g (%.15g), volume %.15g (%.15g)",
           a, area, v, volume);
    bs_model_destroy(m);

    /* the same cone with its angles in degrees: the semi-angle given as 23.1986... degrees */
    static char degrees[4096];
    const char *cut = strstr(cone_body, "#30 = CONICAL_SURFACE");
    const char *rest = strstr(cut, "#31 =");
    (void)snprintf(degrees, sizeof degrees,
                   "%.*s#30 = CONICAL_SURFACE('',#31,4.,23.198590513648);\n%s"
                   "#60 = ( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNIT_ASSIGNED_CONTEXT((#61,#62)) "
                   "REPRESENTATION_CONTEXT('','') );\n"
                   "#61 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n"
                   "#62 = ( CONVERSION_BASED_UNIT('DEGREE',#63) NAMED_UNIT(#64) PLANE_ANGLE_UNIT() );\n"
                   "#63 = PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(1.745329251994E-02),#65);\n"
                   "#64 = DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.);\n"
                   "#65 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );\n",
                   (int)(cut - cone_body), cone_body, rest);
    m = cone_with(degrees, &a, &v);
    CHECKF(fabs(v - volume) <= 1e-9 * volume, "cone in degrees: volume %.15g (%.15g)", v, volume);
    bs_model_destroy(m);

    /* an open shell: the cone without its bottom disc */
    static char open_shell[4096];
    (void)snprintf(open_shell, sizeof open_shell, "%s", cone_body);
    char *list = strstr(open_shell, "(#2,#40,#50)");
    memcpy(list, "(#2,#40)    ", 12);
    m = cone_with(open_shell, &a, &v);
    CHECK(bs_model_face_count(m) == 2 && bs_model_shell_closed(m, 0) == 0 && isnan(v));
    bs_model_destroy(m);

    /* the lateral face's bound used backwards: the same face */
    static char backwards[4096];
    (void)snprintf(backwards, sizeof backwards, "%s", cone_body);
    char *bound = strstr(backwards, "#3 = FACE_BOUND('',#4,.T.)");
    memcpy(bound, "#3 = FACE_BOUND('',#4,.F.)", 26);
    m = cone_with(backwards, &a, &v);
    CHECKF(fabs(v - volume) <= 1e-9 * volume, "bound backwards: volume %.15g (%.15g)", v, volume);
    bs_model_destroy(m);
}

int main(void)
{
    test_refusals();
    test_cone();
    return bs_test_exit("test_step_refusals");
}
