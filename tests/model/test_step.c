/* The STEP reader: the 16 STEP files of data/cad/ against their .ref (faces, one closed shell, area
 * and volume, the sphere's points on the sphere); then small texts, one per entity read and per
 * refusal: the lexer's syntax, the CAD cone edited one entity at a time (curves, surfaces, units,
 * bounds), cubes written here (voids, open shells, holes) and the status, line and message of
 * every refusal. */
#include "harness.h"
#include "step_text.h"

#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static const double pi = 3.14159265358979323846;

/* ---- helpers ---- */

static char *read_text(const char *name)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, name);
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    char *buf = NULL;
    size_t len = 0, cap = 0;
    for (;;) {
        if (len + 4096 + 1 > cap) {
            cap = 2 * cap + 8192;
            char *b = realloc(buf, cap);
            if (b == NULL) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = b;
        }
        size_t got = fread(buf + len, 1, 4096, f);
        len += got;
        if (got == 0)
            break;
    }
    fclose(f);
    buf[len] = '\0';
    return buf;
}

/* text with the first occurrence of each edits[2k] replaced by edits[2k + 1] (NULL ends the list);
 * *line: the line where the first edit starts. NULL when an edit's text is not found. */
static char *edit(const char *text, const char *const *edits, size_t *line)
{
    char *cur = malloc(strlen(text) + 1);
    if (cur == NULL)
        return NULL;
    memcpy(cur, text, strlen(text) + 1);
    for (size_t k = 0; edits[k] != NULL; k += 2) {
        char *at = strstr(cur, edits[k]);
        CHECKF(at != NULL, "edit: '%s' not found", edits[k]);
        if (at == NULL) {
            free(cur);
            return NULL;
        }
        if (k == 0 && line != NULL) {
            *line = 1;
            for (const char *p = cur; p < at; p++)
                *line += *p == '\n';
        }
        size_t pre = (size_t)(at - cur), olen = strlen(edits[k]), nlen = strlen(edits[k + 1]);
        char *next = malloc(strlen(cur) - olen + nlen + 1);
        if (next == NULL) {
            free(cur);
            return NULL;
        }
        memcpy(next, cur, pre);
        memcpy(next + pre, edits[k + 1], nlen);
        memcpy(next + pre + nlen, at + olen, strlen(at + olen) + 1);
        free(cur);
        cur = next;
    }
    return cur;
}

static void properties(const bs_model *m, double *area, double *volume)
{
    *area = *volume = NAN;
    if (m != NULL)
        CHECK_STATUS(bs_model_properties(m, 1e-10, area, volume, NULL), BS_OK);
}

static int near(double a, double b, double rel) { return fabs(a - b) <= rel * fabs(b); }

/* ---- the CAD parts ---- */

typedef struct part_ref {
    size_t faces;
    double area, volume;
} part_ref;

static int read_ref(const char *part, part_ref *r)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s.ref", BS_CAD_DIR, part);
    FILE *f = fopen(path, "r");
    int ok = f != NULL && fscanf(f, "%*[^\n]\nfaces %zu area %lf volume %lf", &r->faces, &r->area, &r->volume) == 3;
    if (f != NULL)
        fclose(f);
    return ok;
}

/* Points of the sphere's face on the sphere of centre (1, 2, 3), radius 5. */
static void sphere_points(const bs_model *m)
{
    bs_face_info fi;
    memset(&fi, 0, sizeof fi);
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_OK);
    CHECK(fi.kind == BS_FACE_SPHERE);
    double worst = 0.0;
    for (int a = 0; a <= 8; a++)
        for (int b = 0; b <= 8; b++) {
            double u = fi.u0 + (fi.u1 - fi.u0) * a / 8.0, v = fi.v0 + (fi.v1 - fi.v0) * b / 8.0, p[3];
            uint32_t face = 0;
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
            CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, pos, NULL, NULL), BS_OK);
            double r = sqrt((p[0] - 1) * (p[0] - 1) + (p[1] - 2) * (p[1] - 2) + (p[2] - 3) * (p[2] - 3));
            worst = fmax(worst, fabs(r - 5.0));
        }
    CHECKF(worst <= 1e-12, "sphere: a point %.3g off the sphere", worst);
}

static void test_parts(void)
{
    static const char *const parts[] = {"cone", "sphere", "torus", "wedge", "bell", "duct", "block", "bottle"};
    size_t nparts = bs_test_quick() ? 4 : 8;
    for (size_t k = 0; k < nparts; k++) {
        part_ref ref;
        CHECKF(read_ref(parts[k], &ref), "%s.ref not read", parts[k]);
        size_t edges[2] = {0, 0};
        for (int form = 0; form < 2; form++) {
            char name[64];
            (void)snprintf(name, sizeof name, "%s%s.step", parts[k], form ? "-3d-edges" : "");
            char path[512];
            (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, name);
            bs_parse_error err;
            bs_model *m = NULL;
            bs_status st = bs_model_read_step_file(path, &err, &m);
            CHECKF(st == BS_OK, "%s: status %d at %zu:%zu %s", name, st, err.line, err.column, err.message);
            if (st != BS_OK)
                continue;
            size_t nf = bs_model_face_count(m), ne = bs_model_edge_count(m);
            edges[form] = ne;
            CHECKF(nf == ref.faces, "%s: %zu faces, the .ref %zu", name, nf, ref.faces);
            CHECKF(bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == 1, "%s: one closed shell", name);
            /* a closed shell of nf faces: at least one edge, and (every edge on two faces, every face at
             * most a few dozen edges) not more than 20 per face */
            CHECKF(ne >= 1 && ne <= 20 * nf, "%s: %zu edges for %zu faces", name, ne, nf);
            double a, v;
            properties(m, &a, &v);
            /* 1e-9 of the kernel's figures, but: its duct area and bell volume are off by 4e-8 and 2e-8
             * (every file gives ours); the duct's and bell's B-spline trims agree with each other to
             * 3e-9; trims computed from 3-D edges are within 1e-7 of the part's size of them */
            int duct = strcmp(parts[k], "duct") == 0, bell = strcmp(parts[k], "bell") == 0;
            double tol = form == 1 || duct || bell ? 1e-8 : 1e-9;
            CHECKF(near(a, ref.area, duct ? 1e-7 : tol), "%s: area %.15g, the .ref %.15g", name, a, ref.area);
            CHECKF(near(v, ref.volume, bell ? 1e-7 : tol), "%s: volume %.15g, the .ref %.15g", name, v, ref.volume);
            if (duct || bell)
                printf("%s: %s %.15g, the kernel's %.15g (relative %.2g)\n", name, duct ? "area" : "volume",
                       duct ? a : v, duct ? ref.area : ref.volume, duct ? (a - ref.area) / ref.area : (v - ref.volume) / ref.volume);
            if (strcmp(parts[k], "sphere") == 0)
                sphere_points(m);
            bs_model_destroy(m);
        }
        CHECKF(edges[0] == edges[1], "%s: %zu edges with PCURVEs, %zu without", parts[k], edges[0], edges[1]);
    }
}

/* ---- a square of side 2 in the plane z = 0, one face of an open shell ---- */

static const char square[] =
    "#1 = SHELL_BASED_SURFACE_MODEL('',(#2));\n"
    "#2 = OPEN_SHELL('',(#3));\n"
    "#3 = ADVANCED_FACE('',(#4),#6,.T.);\n"
    "#4 = FACE_OUTER_BOUND('',#5,.T.);\n"
    "#5 = EDGE_LOOP('',(#11,#12,#13,#14));\n"
    "#6 = PLANE('',#7);\n"
    "#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);\n"
    "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n"
    "#9 = DIRECTION('',(0.,0.,1.));\n"
    "#10 = DIRECTION('',(1.,0.,0.));\n"
    "#11 = ORIENTED_EDGE('',*,*,#21,.T.);\n"
    "#12 = ORIENTED_EDGE('',*,*,#22,.T.);\n"
    "#13 = ORIENTED_EDGE('',*,*,#23,.T.);\n"
    "#14 = ORIENTED_EDGE('',*,*,#24,.T.);\n"
    "#21 = EDGE_CURVE('',#31,#32,#41,.T.);\n"
    "#22 = EDGE_CURVE('',#32,#33,#42,.T.);\n"
    "#23 = EDGE_CURVE('',#33,#34,#43,.T.);\n"
    "#24 = EDGE_CURVE('',#34,#31,#44,.T.);\n"
    "#31 = VERTEX_POINT('',#51);\n"
    "#32 = VERTEX_POINT('',#52);\n"
    "#33 = VERTEX_POINT('',#53);\n"
    "#34 = VERTEX_POINT('',#54);\n"
    "#41 = LINE('',#51,#61);\n"
    "#42 = LINE('',#52,#62);\n"
    "#43 = LINE('',#53,#63);\n"
    "#44 = LINE('',#54,#64);\n"
    "#51 = CARTESIAN_POINT('',(0.,0.,0.));\n"
    "#52 = CARTESIAN_POINT('',(2.,0.,0.));\n"
    "#53 = CARTESIAN_POINT('',(2.,2.,0.));\n"
    "#54 = CARTESIAN_POINT('',(0.,2.,0.));\n"
    "#61 = VECTOR('',#71,2.);\n"
    "#62 = VECTOR('',#72,2.);\n"
    "#63 = VECTOR('',#73,2.);\n"
    "#64 = VECTOR('',#74,2.);\n"
    "#71 = DIRECTION('',(1.,0.,0.));\n"
    "#72 = DIRECTION('',(0.,1.,0.));\n"
    "#73 = DIRECTION('',(-1.,0.,0.));\n"
    "#74 = DIRECTION('',(0.,-1.,0.));\n";

/* The square's file, edited: HEAD, square, TAIL as one text with edits applied. */
static char *square_with(const char *const *edits, size_t *line)
{
    static char whole[8192];
    (void)snprintf(whole, sizeof whole, "%s%s%s", HEAD, square, TAIL);
    static const char *const none[] = {NULL};
    return edit(whole, edits != NULL ? edits : none, line);
}

/* The square read after edits: its area, one open shell of one face. */
static void square_reads(const char *what, const char *const *edits, double area)
{
    char *text = square_with(edits, NULL);
    bs_model *m = must_read(what, text);
    double a, v;
    properties(m, &a, &v);
    /* edges projected onto a surface of revolution: within the reader's tolerance (1e-7 of the file's
     * extent), elsewhere exact */
    if (m != NULL)
        CHECKF(bs_model_face_count(m) == 1 && bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == 0 &&
                   isnan(v) && near(a, area, strstr(what, "revolution") != NULL ? 1e-6 : 1e-12),
               "%s: %zu faces, area %.15g (%.15g), volume %g", what, bs_model_face_count(m), a, area, v);
    bs_model_destroy(m);
    free(text);
}

#define E(...) ((const char *const[]){__VA_ARGS__, NULL})

/* The lexer: what the syntax allows, read to the same square. */
static void test_syntax(void)
{
    square_reads("plain", NULL, 4.0);
    /* comments everywhere, strings with '' and binary strings, user keywords, typed values */
    square_reads("comments and strings",
                 E("HEADER;\n", "HEADER; /* a comment */\nFILE_NAME('it''s','2026',('a'),(''),'p','q',$);\n",
                   "#3 = ADVANCED_FACE('',", "/* before */ #3 /* in */ = /**/ ADVANCED_FACE('it''s ''q''',",
                   "#8 = CARTESIAN_POINT('',", "#8 = CARTESIAN_POINT(\"0A\",", "#9 = DIRECTION('',(0.,0.,1.));",
                   "#9 = DIRECTION('',(0.E+00,+0.0,1.0E0));\n#99 = !USER_THING('',(1,-2,+3.5e-1,.ENUM.,$,*,\"\"));",
                   "#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71,LENGTH_MEASURE(2.));"),
                 4.0);
    /* a complex instance, nested lists, a named DATA section, a second DATA section, spaces */
    square_reads("complex and sections",
                 E("#6 = PLANE('',#7);", "#6 = ( GEOMETRIC_REPRESENTATION_ITEM() PLANE('',#7) SURFACE() );",
                   "#10 = DIRECTION", "#98 = A((((1),(2,(3))),()),'',B(C(1)));\n#97 = ();\n#10 = DIRECTION",
                   "DATA;\n", "DATA(('name'),('schema'));\n", "ENDSEC;\nEND-ISO",
                   "ENDSEC;\nDATA;\n#500 = CARTESIAN_POINT('',(5.,5.,5.));\nENDSEC;\n\t\r\nEND-ISO"),
                 4.0);
    /* an edge given backwards (the curve against the edge, the edge against the loop) */
    square_reads("edge backwards",
                 E("#11 = ORIENTED_EDGE('',*,*,#21,.T.);", "#11 = ORIENTED_EDGE('',*,*,#21,.F.);",
                   "#21 = EDGE_CURVE('',#31,#32,#41,.T.);", "#21 = EDGE_CURVE('',#32,#31,#41,.F.);"),
                 4.0);
    /* the loop used backwards in a FACE_BOUND marked .F.: the same face */
    square_reads("bound backwards",
                 E("#4 = FACE_OUTER_BOUND('',#5,.T.);", "#4 = FACE_OUTER_BOUND('',#5,.F.);", "#3 = ADVANCED_FACE('',(#4),#6,.T.);",
                   "#3 = ADVANCED_FACE('',(#4),#6,.F.);", "(#11,#12,#13,#14)", "(#14,#13,#12,#11)",
                   "#11 = ORIENTED_EDGE('',*,*,#21,.T.);", "#11 = ORIENTED_EDGE('',*,*,#21,.F.);",
                   "#12 = ORIENTED_EDGE('',*,*,#22,.T.);", "#12 = ORIENTED_EDGE('',*,*,#22,.F.);",
                   "#13 = ORIENTED_EDGE('',*,*,#23,.T.);", "#13 = ORIENTED_EDGE('',*,*,#23,.F.);",
                   "#14 = ORIENTED_EDGE('',*,*,#24,.T.);", "#14 = ORIENTED_EDGE('',*,*,#24,.F.);"),
                 4.0);
    /* a hole, both bounds FACE_BOUND, the inner listed first and used backwards: the outer found by
     * its box */
    square_reads("hole",
                 E("#3 = ADVANCED_FACE('',(#4),#6,.T.);", "#3 = ADVANCED_FACE('',(#80,#4),#6,.T.);",
                   "#4 = FACE_OUTER_BOUND(", "#4 = FACE_BOUND(", "#74 = DIRECTION('',(0.,-1.,0.));",
                   "#74 = DIRECTION('',(0.,-1.,0.));\n#80 = FACE_BOUND('',#115,.F.);\n"
                   "#115 = EDGE_LOOP('',(#111,#112,#113,#114));\n#111 = ORIENTED_EDGE('',*,*,#91,.T.);\n"
                   "#112 = ORIENTED_EDGE('',*,*,#92,.T.);\n#113 = ORIENTED_EDGE('',*,*,#93,.T.);\n"
                   "#114 = ORIENTED_EDGE('',*,*,#94,.T.);\n#91 = EDGE_CURVE('',#81,#82,#95,.T.);\n"
                   "#92 = EDGE_CURVE('',#82,#83,#96,.T.);\n#93 = EDGE_CURVE('',#83,#84,#97,.T.);\n"
                   "#94 = EDGE_CURVE('',#84,#81,#98,.T.);\n#81 = VERTEX_POINT('',#85);\n#82 = VERTEX_POINT('',#86);\n"
                   "#83 = VERTEX_POINT('',#87);\n#84 = VERTEX_POINT('',#88);\n#85 = CARTESIAN_POINT('',(0.5,0.5,0.));\n"
                   "#86 = CARTESIAN_POINT('',(1.5,0.5,0.));\n#87 = CARTESIAN_POINT('',(1.5,1.5,0.));\n"
                   "#88 = CARTESIAN_POINT('',(0.5,1.5,0.));\n#95 = LINE('',#85,#101);\n#96 = LINE('',#86,#102);\n"
                   "#97 = LINE('',#87,#103);\n#98 = LINE('',#88,#104);\n#101 = VECTOR('',#71,1.);\n"
                   "#102 = VECTOR('',#72,1.);\n#103 = VECTOR('',#73,1.);\n#104 = VECTOR('',#74,1.);"),
                 3.0);
    /* a face given as FACE_SURFACE, a placement with its directions left out */
    square_reads("FACE_SURFACE", E("#3 = ADVANCED_FACE(", "#3 = FACE_SURFACE(", "#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);",
                                   "#7 = AXIS2_PLACEMENT_3D('',#8,$,$);"),
                 4.0);
    /* the square's edges as B-splines of degree 1 and as trimmed lines */
    square_reads("B-spline and trimmed edges",
                 E("#41 = LINE('',#51,#61);", "#41 = B_SPLINE_CURVE_WITH_KNOTS('',1,(#51,#52),.POLYLINE_FORM.,.F.,.F.,(2,2),"
                                              "(0.,1.),.UNSPECIFIED.);",
                   "#42 = LINE('',#52,#62);", "#42 = TRIMMED_CURVE('',#45,(#52),(#53),.T.,.CARTESIAN.);\n"
                                              "#45 = TRIMMED_CURVE('',#46,(),(),.T.,.PARAMETER.);\n#46 = LINE('',#52,#62);"),
                 4.0);
}

/* ---- the lexer's refusals: status BS_ERR_PARSE at line and column (0: not checked) ---- */

typedef struct lex_case {
    const char *text;
    size_t line, column;
    const char *names;
} lex_case;

static void test_lexer_refusals(void)
{
    static const lex_case cases[] = {
        {"", 1, 1, "ISO-10303-21"},
        {"ISO-10303-21", 1, 13, "end of file"},
        {"ISO-10303-21;\nHEADER", 2, 7, "end of file"},
        {"ISO-10303-21;\nFOO;", 2, 1, "HEADER;"},
        {"ISO-10303-21;\nHEADER;\nFILE_NAME('a')\nENDSEC;", 4, 1, "';' after a header entry"},
        {"ISO-10303-21;\nHEADER;\n  ENDSEC\nDATA;", 4, 1, "';' after ENDSEC"},
        {"ISO-10303-21;\nHEADER;\n /* open", 3, 2, "comment not closed"},
        {"ISO-10303-21;\nHEADER;\n(1);", 3, 1, "entity name"},
        {"ISO-10303-21;\nHEADER;\nENDSEC;\nEND-ISO-10303-21;\n", 4, 17, "a DATA section"},
        {"ISO-10303-21;\nHEADER;\nENDSEC;\nFOO;", 4, 1, "DATA;"},
        {"ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nFOO;", 6, 1, "DATA or END-ISO-10303-21;"},
        {"ISO-10303-21;\nHEADER;\nENDSEC;\nDATA('x';", 4, 9, "',' or ')'"},
        {"ISO-10303-21;\nHEADER;\nENDSEC;\nDATA ENDSEC;", 4, 6, "';' after DATA"},
        {HEAD "ENDSEC;\nEND-ISO-10303-21", 7, 17, "';' after END-ISO-10303-21"},
        {HEAD "ENDSEC\n#1", 7, 1, "';' after ENDSEC"},
        {HEAD "X = A();", 6, 1, "an instance #N"},
        {HEAD "#= A();", 6, 2, "an entity number after '#'"},
        {HEAD "#99999999999999999999999999 = A();", 6, 2, "an entity number"},
        {HEAD "#1 A();", 6, 4, "'='"},
        {HEAD "#1 = A()\n#2 = B();", 7, 1, "';' after an instance"},
        {HEAD "#1 = A;", 6, 7, "'('"},
        {HEAD "#1 = A(B);", 6, 9, "'(' after a keyword"},
        {HEAD "#1 = A(1 2);", 6, 10, "',' or ')'"},
        {HEAD "#1 = A(#);", 6, 9, "an entity number after '#'"},
        {HEAD "#1 = A(.T);", 6, 8, "an enumeration"},
        {HEAD "#1 = A(..);", 6, 8, "an enumeration"},
        {HEAD "#1 = A(.T", 6, 8, "an enumeration"},
        {HEAD "#1 = A(1,\n  'abc", 7, 3, "string not closed"},
        {HEAD "#1 = A(1.2.3);", 6, 8, "bad number '1.2.3'"},
        {HEAD "#1 = A(1.E999);", 6, 8, "bad number"},
        {HEAD "#1 = A(+);", 6, 8, "bad number"},
        {HEAD "#1 = A(-.E1);", 6, 8, "bad number"},
        {HEAD "#1 = A(@);", 6, 8, "a parameter"},
        {HEAD "#1 = A(1,);", 6, 10, "a parameter"},
        {HEAD "#1 = ( A() 5 );", 6, 12, "an entity name"},
        {HEAD "#1 = ( A() ", 6, 12, "end of file"},
        {HEAD "#1 = A(1 /* open", 6, 10, "comment not closed"},
        {HEAD "#1 = A(1,\n", 7, 1, "end of file"},
        {HEAD "#1 = A(B(C(1)", 6, 14, "end of file"},
        {HEAD "#1 = A(1);\n#1 = A(2);\n" TAIL, 7, 1, "#1 A: entity number defined twice"},
        {HEAD "#1 = A(((((((((((((((((((((((((((((((((1)))))))))))))))))))))))))))))))));\n" TAIL, 6, 39,
         "nested deeper than 32"},
        {HEAD "#1 = A(B(B(B(B(B(B(B(B(B(B(B(B(B(B(B(B(B(1)))))))))))))))))));\n" TAIL, 6, 40, "nested deeper"},
        {HEAD "#1 = CARTESIAN_POINT('',(0.,0.,0.));\n#2 = ();\n" TAIL, 1, 1,
         "no B-rep faces: 0 ADVANCED_FACE in 0 shells among 2 entities"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        bs_parse_error err;
        bs_model *m = NULL;
        memset(&err, 0, sizeof err);
        bs_status st = bs_model_read_step(cases[k].text, strlen(cases[k].text), &err, &m);
        CHECKF(st == BS_ERR_PARSE && m == NULL, "lexer case %zu: status %d (%s)", k, st, err.message);
        CHECKF(err.line == cases[k].line && err.column == cases[k].column, "lexer case %zu: %zu:%zu, wanted %zu:%zu (%s)",
               k, err.line, err.column, cases[k].line, cases[k].column, err.message);
        CHECKF(strstr(err.message, cases[k].names) != NULL, "lexer case %zu: '%s' does not name '%s'", k, err.message,
               cases[k].names);
    }
    /* NUL bytes inside the text are refused where they are; one final NUL is the end of the text */
    static const char nul[] = HEAD "#1 = A(1,\0);\n" TAIL;
    bs_parse_error err;
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_step(nul, sizeof nul - 1, &err, &m), BS_ERR_PARSE);
    CHECKF(err.line == 6 && err.column == 10 && strstr(err.message, "a parameter") != NULL, "NUL: %zu:%zu %s", err.line,
           err.column, err.message);
    char *whole = square_with(NULL, NULL);
    if (whole != NULL) {
        m = NULL;
        CHECK_STATUS(bs_model_read_step(whole, strlen(whole) + 1, &err, &m), BS_OK);
        CHECK(bs_model_face_count(m) == 1);
        bs_model_destroy(m);
        /* the text cut anywhere: a clean failure with a place */
        size_t len = strlen(whole), cuts = 0;
        for (size_t cut = 0; cut < len; cut += bs_test_quick() ? 37 : 7) {
            m = NULL;
            memset(&err, 0, sizeof err);
            bs_status st = bs_model_read_step(whole, cut, &err, &m);
            cuts += st == BS_ERR_PARSE && m == NULL && err.line >= 1;
            CHECKF(st == BS_ERR_PARSE && m == NULL && err.line >= 1, "cut at %zu: status %d (%s)", cut, st, err.message);
            bs_model_destroy(m);
        }
        CHECK(cuts > 10);
    }
    free(whole);
    /* arguments */
    m = (bs_model *)&err;
    CHECK_STATUS(bs_model_read_step(NULL, 1, &err, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    CHECK_STATUS(bs_model_read_step("", 0, &err, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_step(NULL, 0, NULL, &m), BS_ERR_PARSE);
    CHECK_STATUS(bs_model_read_step_file(NULL, &err, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_step_file(BS_CAD_DIR "/no-such-file.step", &err, &m), BS_ERR_IO);
    CHECK(m == NULL);
}

/* ---- the square's refusals: each an edit, with the line of the entity named ---- */

typedef struct square_case {
    const char *from, *to;  /* one edit of the square */
    bs_status status;
    const char *where;      /* the instance the error is at ("#6 =", NULL: the edit's line) */
    const char *names;
} square_case;

static size_t line_of(const char *text, const char *what)
{
    const char *at = strstr(text, what);
    size_t line = 1;
    for (const char *p = text; at != NULL && p < at; p++)
        line += *p == '\n';
    return at != NULL ? line : 0;
}

#define FACE3 "#3 = ADVANCED_FACE('',(#4),#6,.T.);"
#define BOUND4 "#4 = FACE_OUTER_BOUND('',#5,.T.);"
#define EDGE21 "#21 = EDGE_CURVE('',#31,#32,#41,.T.);"
#define LINE41 "#41 = LINE('',#51,#61);"
#define PLANE6 "#6 = PLANE('',#7);"
#define BSC "B_SPLINE_CURVE_WITH_KNOTS('',"
#define BSS "#6 = B_SPLINE_SURFACE_WITH_KNOTS('',"
#define SQ_NET "((#51,#54),(#52,#53))"
#define RATS(w) "#6 = ( BOUNDED_SURFACE() B_SPLINE_SURFACE(1,1," SQ_NET ",.UNSPECIFIED.,.F.,.F.,.F.) " \
                "B_SPLINE_SURFACE_WITH_KNOTS((2,2),(2,2),(0.,2.),(0.,2.),.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() " \
                "RATIONAL_B_SPLINE_SURFACE(" w ") REPRESENTATION_ITEM('') SURFACE() );"
#define RATC(w, k) "#41 = ( BOUNDED_CURVE() B_SPLINE_CURVE(1,(#51,#52),.POLYLINE_FORM.,.F.,.F.) " \
                   "B_SPLINE_CURVE_WITH_KNOTS((2,2),(" k "),.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() " \
                   "RATIONAL_B_SPLINE_CURVE(" w ") REPRESENTATION_ITEM('') );"
#define EXTR "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#62);"

static void test_square_refusals(void)
{
    static const square_case cases[] = {
        /* shells and faces */
        {"#2 = OPEN_SHELL('',(#3));", "#2 = OPEN_SHELL('',#3);", BS_ERR_PARSE, NULL, "#2 OPEN_SHELL: the faces must be a list"},
        {"#2 = OPEN_SHELL('',(#3));", "#2 = OPEN_SHELL('',(#3,5));", BS_ERR_PARSE, NULL, "a face must be a reference #N"},
        {"#2 = OPEN_SHELL('',(#3));", "#2 = OPEN_SHELL('',(#300));", BS_ERR_PARSE, NULL, "refers to #300, which is not defined"},
        {"#2 = OPEN_SHELL('',(#3));", "#2 = OPEN_SHELL('',(#5));", BS_ERR_PARSE, NULL, "#5 is not a face"},
        {FACE3, "#3 = ORIENTED_FACE('',(#4),#6,.T.);", BS_ERR_PARSE, NULL, "oriented faces are not supported"},
        {FACE3, "#3 = ADVANCED_FACE('',#4,#6,.T.);", BS_ERR_PARSE, NULL, "the bounds must be a list"},
        {FACE3, "#3 = ADVANCED_FACE('',(#4));", BS_ERR_PARSE, NULL, "the surface missing"},
        {FACE3, "#3 = ADVANCED_FACE('',(#4),#6,.U.);", BS_ERR_PARSE, NULL, "the sense must be .T. or .F."},
        {FACE3, "#3 = ADVANCED_FACE('',(#4),#6,1);", BS_ERR_PARSE, NULL, "the sense must be .T. or .F."},
        {FACE3, "#3 = ADVANCED_FACE('',(#4),#6,.TRUE.);", BS_ERR_PARSE, NULL, "the sense must be .T. or .F."},
        {FACE3, "#3 = ADVANCED_FACE('',(#4,'b'),#6,.T.);", BS_ERR_PARSE, NULL, "a bound must be a reference"},
        {FACE3, "#3 = ADVANCED_FACE('',(#5),#6,.T.);", BS_ERR_PARSE, "#5 =", "#5 EDGE_LOOP: expected a FACE_BOUND"},
        {BOUND4, "#4 = FACE_OUTER_BOUND('',#5);", BS_ERR_PARSE, NULL, "the orientation missing"},
        {BOUND4, "#4 = FACE_OUTER_BOUND('',#6,.T.);", BS_ERR_PARSE, "#6 =", "#6 PLANE: expected an EDGE_LOOP"},
        {BOUND4, "#4 = FACE_OUTER_BOUND('',#8,.T.);\n#900 = VERTEX_LOOP('',#31);", BS_ERR_PARSE, "#8 =", "expected an EDGE_LOOP"},
        {BOUND4, "#4 = FACE_OUTER_BOUND('',#900,.T.);\n#900 = VERTEX_LOOP('',#31);", BS_ERR_PARSE, "#3 =",
         "#3 ADVANCED_FACE: a face without edges on an unbounded surface"},
        {"#5 = EDGE_LOOP('',(#11,#12,#13,#14));", "#5 = EDGE_LOOP('',#11);", BS_ERR_PARSE, NULL, "the edges must be a list"},
        {"#5 = EDGE_LOOP('',(#11,#12,#13,#14));", "#5 = EDGE_LOOP('',());", BS_ERR_PARSE, NULL, "an empty loop"},
        {"#5 = EDGE_LOOP('',(#11,#12,#13,#14));", "#5 = EDGE_LOOP('',(#11,#12,#13,$));", BS_ERR_PARSE, NULL,
         "an oriented edge must be a reference"},
        {"#5 = EDGE_LOOP('',(#11,#12,#13,#14));", "#5 = EDGE_LOOP('',(#11,#12,#13,#21));", BS_ERR_PARSE, "#21 =",
         "expected an ORIENTED_EDGE"},
        {"#11 = ORIENTED_EDGE('',*,*,#21,.T.);", "#11 = ORIENTED_EDGE('',*,*,#21);", BS_ERR_PARSE, NULL, "the orientation missing"},
        {"#11 = ORIENTED_EDGE('',*,*,#21,.T.);", "#11 = ORIENTED_EDGE('',*,*,#31,.T.);", BS_ERR_PARSE, "#31 =",
         "expected an EDGE_CURVE"},
        {EDGE21, "#21 = EDGE_CURVE('',#51,#32,#41,.T.);", BS_ERR_PARSE, "#51 =", "expected a VERTEX_POINT"},
        {EDGE21, "#21 = EDGE_CURVE('',#31,#32,#41,$);", BS_ERR_PARSE, NULL, "the sense must be .T. or .F."},
        {EDGE21, "#21 = EDGE_CURVE('',#31,#32);", BS_ERR_PARSE, NULL, "the edge geometry missing"},
        {"#31 = VERTEX_POINT('',#51);", "#31 = VERTEX_POINT('',#61);", BS_ERR_PARSE, "#61 =", "expected a CARTESIAN_POINT"},
        {"#31 = VERTEX_POINT('',#51);", "#31 = VERTEX_POINT('');", BS_ERR_PARSE, NULL, "the point missing"},
        /* points, directions, placements */
        {"#51 = CARTESIAN_POINT('',(0.,0.,0.));", "#51 = CARTESIAN_POINT('',(0.,0.));", BS_ERR_PARSE, NULL, "expected 3 coordinates"},
        {"#51 = CARTESIAN_POINT('',(0.,0.,0.));", "#51 = CARTESIAN_POINT('',(0.,0.,'z'));", BS_ERR_PARSE, NULL,
         "a coordinate must be a number"},
        {"#51 = CARTESIAN_POINT('',(0.,0.,0.));", "#51 = CARTESIAN_POINT('',0.);", BS_ERR_PARSE, NULL,
         "the coordinates must be a list"},
        {"#71 = DIRECTION('',(1.,0.,0.));", "#71 = DIRECTION('',(0.,0.,0.));", BS_ERR_PARSE, NULL, "direction of zero length"},
        {"#71 = DIRECTION('',(1.,0.,0.));", "#71 = DIRECTION('',(1.,0.));", BS_ERR_PARSE, NULL, "expected 3 direction ratios"},
        {"#71 = DIRECTION('',(1.,0.,0.));", "#71 = DIRECTION('',(1.,0.,.X.));", BS_ERR_PARSE, NULL, "a direction ratio must be"},
        {"#71 = DIRECTION('',(1.,0.,0.));", "#71 = DIRECTION('',1.);", BS_ERR_PARSE, NULL, "the ratios must be a list"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#51,2.);", BS_ERR_PARSE, "#51 =", "expected a DIRECTION"},
        {PLANE6, "#6 = PLANE('',#8);", BS_ERR_PARSE, "#8 =", "expected an AXIS2_PLACEMENT_3D"},
        {PLANE6, "#6 = PLANE('');", BS_ERR_PARSE, NULL, "the position missing"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('',#8,#9,#9);", BS_ERR_PARSE, NULL,
         "reference direction parallel to the axis"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('',#9,#9,#10);", BS_ERR_PARSE, "#9 =",
         "expected a CARTESIAN_POINT"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('',#8,#9,5.);", BS_ERR_PARSE, NULL,
         "a direction must be a reference"},
        /* lines and vectors */
        {LINE41, "#41 = LINE('',#51,#71);", BS_ERR_PARSE, "#71 =", "expected a VECTOR"},
        {LINE41, "#41 = LINE('',#51);", BS_ERR_PARSE, NULL, "the vector missing"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71,0.);", BS_ERR_PARSE, NULL, "magnitude must be positive"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71,LENGTH_MEASURE(-2.));", BS_ERR_PARSE, NULL, "magnitude must be positive"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71,'2');", BS_ERR_PARSE, NULL, "the magnitude must be a number"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71,A(1.,2.));", BS_ERR_PARSE, NULL, "the magnitude must be a number"},
        /* curves */
        {LINE41, "#41 = HYPERBOLA('',#7,1.,1.);", BS_ERR_UNSUPPORTED, NULL, "HYPERBOLA at line"},
        {LINE41, "#41 = ();", BS_ERR_UNSUPPORTED, NULL, "() at line"},
        {LINE41, "#41 = CIRCLE('',#7,0.);", BS_ERR_PARSE, NULL, "radii must be positive"},
        {LINE41, "#41 = ELLIPSE('',#7,1.);", BS_ERR_PARSE, NULL, "the second semi-axis missing"},
        {LINE41, "#41 = ELLIPSE('',#7,1.,-1.);", BS_ERR_PARSE, NULL, "radii must be positive"},
        {LINE41, "#41 = CIRCLE('',#7);", BS_ERR_PARSE, NULL, "the radius missing"},
        {LINE41, "#41 = TRIMMED_CURVE('',#47);\n#47 = TRIMMED_CURVE('',#41);", BS_ERR_PARSE, NULL,
         "#41 TRIMMED_CURVE: curve references nested too deep (a reference cycle)"},
        {LINE41, "#41 = TRIMMED_CURVE('',#41);", BS_ERR_PARSE, NULL, "a reference cycle"},
        {LINE41, "#41 = TRIMMED_CURVE('');", BS_ERR_PARSE, NULL, "the basis curve missing"},
        {LINE41, "#41 = " BSC "0,(#51,#52),.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "degree must be 1.."},
        {LINE41, "#41 = " BSC "1.5,(#51,#52),.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "degree must be 1.."},
        {LINE41, "#41 = " BSC "2,(#51,#52),.U.,.F.,.F.,(3,3),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "more control points"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,2),(0.),.U.);", BS_ERR_PARSE, NULL, "as many multiplicities"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,3),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,1),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,1.5),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(0,4),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,2),(1.,0.),.U.);", BS_ERR_PARSE, NULL, "knots must not decrease"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,2),(1.,1.),.U.);", BS_ERR_PARSE, NULL, "empty knot domain"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,'a'),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "a multiplicity must be"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,2),(0.,$),.U.);", BS_ERR_PARSE, NULL, "a knot must be"},
        {LINE41, "#41 = " BSC "1,(#51,7),.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "a control point must be"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.,(2,2));", BS_ERR_PARSE, NULL, "the knots missing"},
        {LINE41, "#41 = " BSC "1,#51,.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "the control points must be"},
        {LINE41, RATC("(1.,0.)", "0.,1."), BS_ERR_PARSE, NULL, "weights must be positive"},
        {LINE41, RATC("(1.,-1.)", "0.,1."), BS_ERR_PARSE, NULL, "weights must be positive"},
        {LINE41, RATC("(1.)", "0.,1."), BS_ERR_PARSE, NULL, "weights as points"},
        {LINE41, RATC("1.", "0.,1."), BS_ERR_PARSE, NULL, "the weights must be a list"},
        {LINE41, RATC("(1.,'w')", "0.,1."), BS_ERR_PARSE, NULL, "a weight must be a number"},
        {LINE41, "#41 = ( BOUNDED_CURVE() B_SPLINE_CURVE(1,(#51,#52),.U.,.F.,.F.) BEZIER_CURVE() CURVE() );",
         BS_ERR_PARSE, NULL, "a B-spline curve without knots is not supported"},
        /* surfaces */
        {PLANE6, "#6 = OFFSET_SURFACE('',#600,1.,.F.);", BS_ERR_UNSUPPORTED, NULL, "OFFSET_SURFACE at line"},
        {PLANE6, "#6 = CYLINDRICAL_SURFACE('',#7,0.);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = CONICAL_SURFACE('',#7,1.,1.6);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = CONICAL_SURFACE('',#7,-1.,0.5);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = TOROIDAL_SURFACE('',#7,5.,0.);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = SPHERICAL_SURFACE('',#7,0.);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = SPHERICAL_SURFACE('',#7);", BS_ERR_PARSE, NULL, "the radius missing"},
        {PLANE6, "#6 = TOROIDAL_SURFACE('',#7,5.);", BS_ERR_PARSE, NULL, "the second radius missing"},
        {PLANE6, "#6 = CYLINDRICAL_SURFACE('',#7,1.);", BS_ERR_PARSE, "#21 =", "the edge is not on the face's surface"},
        {PLANE6, BSS "0,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "degrees must be 1.."},
        {PLANE6, BSS "1,2," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(3,3),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL,
         "more control points than the degree"},
        {PLANE6, BSS "1,1,((#51,#54),(#52)),.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL,
         "rows of control points"},
        {PLANE6, BSS "1,1,((#51,#54),#52),.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL,
         "a row of control points must be a list"},
        {PLANE6, BSS "1,1,((#51,#54),(#52,5)),.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL,
         "a control point must be"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.),(0.,2.),.U.);", BS_ERR_PARSE, NULL,
         "as many multiplicities as knots"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,1),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,3),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,'k'),.U.);", BS_ERR_PARSE, NULL, "a knot must be"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(2.,0.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "knots must not decrease"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(2.,2.),.U.);", BS_ERR_PARSE, NULL, "empty knot domain"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.));", BS_ERR_PARSE, NULL, "the v knots missing"},
        {PLANE6, RATS("((1.,1.),(1.,0.))"), BS_ERR_PARSE, NULL, "weights must be positive"},
        {PLANE6, RATS("((1.,1.),(1.))"), BS_ERR_PARSE, NULL, "rows of control points (and weights)"},
        {PLANE6, RATS("((1.,1.))"), BS_ERR_PARSE, NULL, "more control points than the degree"},
        {PLANE6, RATS("((1.,1.),1.)"), BS_ERR_PARSE, NULL, "a row of weights must be a list"},
        {PLANE6, RATS("((1.,1.),(1.,'w'))"), BS_ERR_PARSE, NULL, "a weight must be a number"},
        {PLANE6, "#6 = ( B_SPLINE_SURFACE(1,1," SQ_NET ",.U.,.F.,.F.,.F.) BEZIER_SURFACE() );", BS_ERR_PARSE, NULL,
         "a B-spline surface without knots is not supported"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#620);\n#620 = VECTOR('',#72,0.);", BS_ERR_PARSE, "#620 =", "magnitude must be positive"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#72);", BS_ERR_PARSE, "#72 =", "expected a VECTOR"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41);", BS_ERR_PARSE, NULL, "the extrusion vector missing"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#7,#62);", BS_ERR_UNSUPPORTED, "#7 =", "AXIS2_PLACEMENT_3D at line"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41,#7);", BS_ERR_PARSE, "#7 =", "expected an AXIS1_PLACEMENT"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41);", BS_ERR_PARSE, NULL, "the axis missing"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41,#600);\n#600 = AXIS1_PLACEMENT('',#51,#51);", BS_ERR_PARSE, "#51 =",
         "expected a DIRECTION"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41,#600);\n#600 = AXIS1_PLACEMENT('',#9,#9);", BS_ERR_PARSE, "#9 =",
         "expected a CARTESIAN_POINT"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#7,#600);\n#600 = AXIS1_PLACEMENT('',#51,#9);", BS_ERR_UNSUPPORTED, "#7 =",
         "is not supported"},
        /* every argument of the surfaces and curves missing or of the wrong kind */
        {PLANE6, BSS "1.5,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "degrees must be 1.."},
        {PLANE6, BSS "1,99," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "degrees must be 1.."},
        {PLANE6, BSS "1,1,(),.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "more control points"},
        {PLANE6, BSS "1,2," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "more control points"},
        {PLANE6, "#6 = B_SPLINE_SURFACE_WITH_KNOTS('');", BS_ERR_PARSE, NULL, "the u degree missing"},
        {PLANE6, BSS "1);", BS_ERR_PARSE, NULL, "the v degree missing"},
        {PLANE6, BSS "1,1,#51);", BS_ERR_PARSE, NULL, "the control points must be a list"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.);", BS_ERR_PARSE, NULL, "the u multiplicities missing"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2));", BS_ERR_PARSE, NULL, "the v multiplicities missing"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2));", BS_ERR_PARSE, NULL, "the u knots missing"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,'m'),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "a multiplicity must be"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(3,2),(2,2),(0.,2.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "must add up"},
        {PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(1.,1.),(0.,2.),.U.);", BS_ERR_PARSE, NULL, "empty knot domain"},
        {PLANE6, RATS("1."), BS_ERR_PARSE, NULL, "the weights must be a list"},
        {PLANE6, "#6 = CYLINDRICAL_SURFACE('',#7,-1.);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = TOROIDAL_SURFACE('',#7,1.,-1.);", BS_ERR_PARSE, NULL, "radius or angle out of range"},
        {PLANE6, "#6 = CONICAL_SURFACE('',#7,1.,'a');", BS_ERR_PARSE, NULL, "the second radius must be a number"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('');", BS_ERR_PARSE, NULL, "the swept curve missing"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('');", BS_ERR_PARSE, NULL, "the swept curve missing"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#620);\n#620 = VECTOR('');", BS_ERR_PARSE, "#620 =", "the direction missing"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#620);\n#620 = VECTOR('',#51,1.);", BS_ERR_PARSE, "#51 =",
         "expected a DIRECTION"},
        {PLANE6, "#6 = SURFACE_OF_LINEAR_EXTRUSION('',#41,#620);\n#620 = VECTOR('',#72);", BS_ERR_PARSE, "#620 =",
         "the magnitude missing"},
        {PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41,#600);\n#600 = AXIS1_PLACEMENT('',#51);", BS_ERR_PARSE, "#600 =",
         "the axis missing"},
        {"#71 = DIRECTION('',(1.,0.,0.));", "#71 = DIRECTION('',(1.5E308,1.5E308,0.));", BS_ERR_PARSE, NULL,
         "direction of zero length"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('',#8);", BS_ERR_PARSE, NULL, "a direction missing"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('',#8,#8,#10);", BS_ERR_PARSE, "#8 =",
         "expected a DIRECTION"},
        {"#7 = AXIS2_PLACEMENT_3D('',#8,#9,#10);", "#7 = AXIS2_PLACEMENT_3D('');", BS_ERR_PARSE, NULL, "the location missing"},
        {LINE41, "#41 = LINE('');", BS_ERR_PARSE, NULL, "the point missing"},
        {LINE41, "#41 = LINE('',#71,#61);", BS_ERR_PARSE, "#71 =", "expected a CARTESIAN_POINT"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('');", BS_ERR_PARSE, NULL, "the direction missing"},
        {"#61 = VECTOR('',#71,2.);", "#61 = VECTOR('',#71);", BS_ERR_PARSE, NULL, "the magnitude missing"},
        {LINE41, "#41 = CIRCLE('');", BS_ERR_PARSE, NULL, "the position missing"},
        {LINE41, "#41 = CIRCLE('',#8,1.);", BS_ERR_PARSE, "#8 =", "expected an AXIS2_PLACEMENT_3D"},
        {LINE41, "#41 = B_SPLINE_CURVE_WITH_KNOTS('');", BS_ERR_PARSE, NULL, "the degree missing"},
        {LINE41, "#41 = " BSC "1);", BS_ERR_PARSE, NULL, "the control points missing"},
        {LINE41, "#41 = " BSC "1,(#51,#52),.U.,.F.,.F.);", BS_ERR_PARSE, NULL, "the multiplicities missing"},
        {LINE41, "#41 = " BSC "1,(#51,#71),.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, "#71 =", "expected a CARTESIAN_POINT"},
        {LINE41, "#41 = " BSC "99,(#51,#52),.U.,.F.,.F.,(2,2),(0.,1.),.U.);", BS_ERR_PARSE, NULL, "degree must be 1.."},
        {EDGE21, "#21 = EDGE_CURVE('',#31);", BS_ERR_PARSE, NULL, "a vertex missing"},
        {FACE3, "#3 = ADVANCED_FACE('',(#4),#6,.T.);\n#992 = ORIENTED_CLOSED_SHELL('',*,#2);", BS_ERR_PARSE, "#992 =",
         "the orientation missing"},
        {FACE3, "#3 = ADVANCED_FACE('',(#4),#6,.T.);\n#992 = ORIENTED_CLOSED_SHELL('',*);", BS_ERR_PARSE, "#992 =",
         "the shell missing"},
    };
    static char whole[8192];
    (void)snprintf(whole, sizeof whole, "%s%s%s", HEAD, square, TAIL);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char what[48];
        (void)snprintf(what, sizeof what, "square case %zu", k);
        size_t line = 0;
        char *text = edit(whole, (const char *const[]){cases[k].from, cases[k].to, NULL}, &line);
        if (text != NULL && cases[k].where != NULL)
            line = line_of(text, cases[k].where);
        must_refuse(what, text, cases[k].status, line, cases[k].names);
        free(text);
    }
    /* a chain of trimmed curves deeper than the reader follows */
    char chain[4096];
    size_t n = (size_t)snprintf(chain, sizeof chain, "#41 = TRIMMED_CURVE('',#1001);\n");
    for (int k = 1; k <= 20; k++)
        n += (size_t)snprintf(chain + n, sizeof chain - n, "#%d = TRIMMED_CURVE('',#%d);\n", 1000 + k, 1001 + k);
    (void)snprintf(chain + n, sizeof chain - n, "#1021 = LINE('',#51,#61);");
    char *text = edit(whole, E(LINE41, chain), NULL);
    must_refuse("trimmed chain", text, BS_ERR_PARSE, 0, "nested too deep");
    free(text);
}

/* ---- surfaces on the square, cubes, the cone edited ---- */

static void test_square_surfaces(void)
{
    /* the square's plane as a B-spline surface of degree 1, plain and rational (weights along v:
     * the same square), as an extrusion of its first edge and as a revolution about a far axis */
    square_reads("B-spline surface", E(PLANE6, BSS "1,1," SQ_NET ",.U.,.F.,.F.,.F.,(2,2),(2,2),(0.,2.),(0.,2.),.U.);"), 4.0);
    square_reads("rational B-spline surface", E(PLANE6, RATS("((1.,2.),(1.,2.))")), 4.0);
    square_reads("rational B-spline edge", E(LINE41, RATC("(1.,3.)", "0.,1.")), 4.0);
    square_reads("extrusion", E(PLANE6, EXTR), 4.0);
    square_reads("revolution", E(PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#41,#600);\n#600 = AXIS1_PLACEMENT('',#601,#9);\n"
                                         "#601 = CARTESIAN_POINT('',(-3.,-1.,0.));"),
                 4.0);
    square_reads("revolution of a B-spline", E(PLANE6, "#6 = SURFACE_OF_REVOLUTION('',#602,#600);\n"
                                                       "#600 = AXIS1_PLACEMENT('',#601,#9);\n"
                                                       "#601 = CARTESIAN_POINT('',(-3.,5.,0.));\n"
                                                       "#602 = " BSC "1,(#603,#604),.U.,.F.,.F.,(2,2),(0.,1.),.U.);\n"
                                                       "#603 = CARTESIAN_POINT('',(-2.,5.,0.));\n"
                                                       "#604 = CARTESIAN_POINT('',(12.,5.,0.));"),
                 4.0);
}

static void test_cubes(void)
{
    static char text[65536];
    size_t n = (size_t)snprintf(text, sizeof text, "%s#1 = MANIFOLD_SOLID_BREP('',#1000);\n", HEAD);
    n += cube(text + n, sizeof text - n, 1000, 0.0, 2.0);
    (void)snprintf(text + n, sizeof text - n, "%s", TAIL);
    bs_model *m = must_read("cube", text);
    double a, v;
    properties(m, &a, &v);
    CHECKF(bs_model_face_count(m) == 6 && bs_model_edge_count(m) == 12 && bs_model_shell_closed(m, 0) == 1 &&
               near(a, 24.0, 1e-12) && near(v, 8.0, 1e-12),
           "cube: %zu faces, %zu edges, area %.15g, volume %.15g", bs_model_face_count(m), bs_model_edge_count(m), a, v);
    bs_model_destroy(m);

    /* a B-rep with a void: the inner cube's shell used reversed (ORIENTED_CLOSED_SHELL .F.) */
    n = (size_t)snprintf(text, sizeof text, "%s#1 = BREP_WITH_VOIDS('',#1000,(#2));\n#2 = ORIENTED_CLOSED_SHELL('',*,#2000,.F.);\n",
                         HEAD);
    n += cube(text + n, sizeof text - n, 1000, 0.0, 2.0);
    n += cube(text + n, sizeof text - n, 2000, 0.5, 1.5);
    (void)snprintf(text + n, sizeof text - n, "%s", TAIL);
    m = must_read("cube with a void", text);
    properties(m, &a, &v);
    CHECKF(bs_model_face_count(m) == 12 && bs_model_shell_count(m) == 2 && bs_model_shell_closed(m, 0) == 1 &&
               bs_model_shell_closed(m, 1) == 1 && near(a, 30.0, 1e-12) && near(v, 7.0, 1e-12),
           "cube with a void: %zu faces, %zu shells, area %.15g, volume %.15g (7)", bs_model_face_count(m),
           bs_model_shell_count(m), a, v);
    bs_model_destroy(m);
}

/* The cone of data/cad/ (radii 4 and 1, height 7) edited: it must keep its area and volume. */
static void cone_reads(const char *what, const char *file, const char *const *edits)
{
    const double area = pi * 17.0 + pi * 5.0 * sqrt(58.0), volume = pi * 7.0 * 21.0 / 3.0;
    char *orig = read_text(file);
    CHECKF(orig != NULL, "%s not read", file);
    char *text = orig != NULL ? edit(orig, edits, NULL) : NULL;
    bs_model *m = must_read(what, text);
    double a, v;
    properties(m, &a, &v);
    if (m != NULL)
        CHECKF(bs_model_face_count(m) == 3 && bs_model_shell_closed(m, 0) == 1 && near(a, area, 1e-9) && near(v, volume, 1e-9),
               "%s: %zu faces, area %.15g (%.15g), volume %.15g (%.15g)", what, bs_model_face_count(m), a, area, v, volume);
    bs_model_destroy(m);
    free(text);
    free(orig);
}

#define UNIT115 "#115 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );"
#define DEGREES(id, measure) "#" id " = ( CONVERSION_BASED_UNIT('DEGREE',#900) NAMED_UNIT(#901) PLANE_ANGLE_UNIT() );\n" \
    "#900 = " measure "(PLANE_ANGLE_MEASURE(1.745329251994E-02),#902);\n#901 = DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.);\n" \
    "#902 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );"
#define NURBS_CIRCLE(id, c) "#" id " = ( BOUNDED_CURVE() B_SPLINE_CURVE(2,(#910,#911,#912,#913,#914,#915,#916,#917,#910)," \
    ".CIRCULAR_ARC.,.T.,.F.) B_SPLINE_CURVE_WITH_KNOTS((3,2,2,2,3),(0.,1.5707963267949,3.14159265358979," \
    "4.71238898038469,6.28318530717959),.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() " \
    "RATIONAL_B_SPLINE_CURVE((1.,0.707106781186548,1.,0.707106781186548,1.,0.707106781186548,1.,0.707106781186548,1.)) " \
    "REPRESENTATION_ITEM('') );\n#910 = CARTESIAN_POINT('',(" c "));\n"

static void test_cone(void)
{
    /* angles in degrees: the unit, the cone's semi-angle and the seam's PCURVE at -360 degrees */
    cone_reads("cone in degrees", "cone.step",
               E(UNIT115, DEGREES("115", "PLANE_ANGLE_MEASURE_WITH_UNIT"), "#31 = CONICAL_SURFACE('',#32,4.,0.404891786285);",
                 "#31 = CONICAL_SURFACE('',#32,4.,23.198590513648);", "(-6.28318530718,0.)", "(-360.,0.)"));
    cone_reads("cone in degrees, edges projected", "cone-3d-edges.step",
               E("#70 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );", DEGREES("70", "MEASURE_WITH_UNIT"),
                 "#45 = CONICAL_SURFACE('',#46,4.,0.404891786285);", "#45 = CONICAL_SURFACE('',#46,4.,23.198590513648);"));
    /* the top circle as an ellipse, as a trimmed circle, as a rational B-spline */
    cone_reads("ellipse", "cone.step", E("#25 = CIRCLE('',#26,1.);", "#25 = ELLIPSE('',#26,1.,1.);"));
    cone_reads("trimmed circle", "cone.step",
               E("#25 = CIRCLE('',#26,1.);", "#25 = TRIMMED_CURVE('',#920,(PARAMETER_VALUE(0.)),(#23),.T.,.PARAMETER.);\n"
                                             "#920 = CIRCLE('',#26,1.);"));
    static const char *const top_nurbs[] = {"#25 = CIRCLE('',#26,1.);", NURBS_CIRCLE("25", "1.,0.,7.")
        "#911 = CARTESIAN_POINT('',(1.,1.,7.));\n#912 = CARTESIAN_POINT('',(0.,1.,7.));\n"
        "#913 = CARTESIAN_POINT('',(-1.,1.,7.));\n#914 = CARTESIAN_POINT('',(-1.,0.,7.));\n"
        "#915 = CARTESIAN_POINT('',(-1.,-1.,7.));\n#916 = CARTESIAN_POINT('',(0.,-1.,7.));\n"
        "#917 = CARTESIAN_POINT('',(1.,-1.,7.));", NULL};
    cone_reads("rational B-spline circle", "cone.step", top_nurbs);
    static const char *const bottom_nurbs[] = {"#39 = CIRCLE('',#40,4.);", NURBS_CIRCLE("39", "4.,0.,0.")
        "#911 = CARTESIAN_POINT('',(4.,4.,0.));\n#912 = CARTESIAN_POINT('',(0.,4.,0.));\n"
        "#913 = CARTESIAN_POINT('',(-4.,4.,0.));\n#914 = CARTESIAN_POINT('',(-4.,0.,0.));\n"
        "#915 = CARTESIAN_POINT('',(-4.,-4.,0.));\n#916 = CARTESIAN_POINT('',(0.,-4.,0.));\n"
        "#917 = CARTESIAN_POINT('',(4.,-4.,0.));", NULL};
    cone_reads("rational B-spline circle, projected", "cone-3d-edges.step", bottom_nurbs);
    /* the seam as a B-spline of degree 1 */
    cone_reads("B-spline seam", "cone.step",
               E("#59 = LINE('',#60,#61);", "#59 = " BSC "1,(#60,#27),.POLYLINE_FORM.,.F.,.F.,(2,2),(0.,7.615773105864),"
                                            ".UNSPECIFIED.);"));
    /* the lateral face as a surface of revolution of the seam line about the axis */
    cone_reads("surface of revolution", "cone-3d-edges.step",
               E("#45 = CONICAL_SURFACE('',#46,4.,0.404891786285);", "#45 = SURFACE_OF_REVOLUTION('',#33,#930);\n"
                                                                     "#930 = AXIS1_PLACEMENT('',#47,#42);"));
    /* ... and as a rational B-spline surface: a quadratic circle in u, a line in v */
    static char surf[4096];
    size_t n = (size_t)snprintf(surf, sizeof surf, "#45 = ( BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,(");
    static const double cx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, cy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
    for (int k = 0; k < 9; k++)
        n += (size_t)snprintf(surf + n, sizeof surf - n, "%s(#%d,#%d)", k ? "," : "", 940 + 2 * (k % 8), 941 + 2 * (k % 8));
    n += (size_t)snprintf(surf + n, sizeof surf - n,
                          "),.UNSPECIFIED.,.T.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((3,2,2,2,3),(2,2),(0.,1.,2.,3.,4.),"
                          "(0.,1.),.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE((");
    for (int k = 0; k < 9; k++)
        n += (size_t)snprintf(surf + n, sizeof surf - n, "%s(%s,%s)", k ? "," : "", k % 2 ? "0.707106781186548" : "1.",
                              k % 2 ? "0.707106781186548" : "1.");
    n += (size_t)snprintf(surf + n, sizeof surf - n, ")) REPRESENTATION_ITEM('') SURFACE() );\n");
    for (int k = 0; k < 8; k++)
        n += (size_t)snprintf(surf + n, sizeof surf - n, "#%d = CARTESIAN_POINT('',(%g,%g,0.));\n#%d = CARTESIAN_POINT('',(%g,%g,7.));\n",
                              940 + 2 * k, 4 * cx[k], 4 * cy[k], 941 + 2 * k, cx[k], cy[k]);
    cone_reads("rational B-spline surface", "cone-3d-edges.step",
               E("#45 = CONICAL_SURFACE('',#46,4.,0.404891786285);", surf));

    /* the plane angle unit refused */
    static const struct {
        const char *unit;
        const char *where, *names;
    } units[] = {
        {"#115 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.STERADIAN.) );", "#115 =", "must be the radian"},
        {"#115 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($) );", "#115 =", "must be the radian"},
        {"#115 = ( NAMED_UNIT(*) PLANE_ANGLE_UNIT() );", "#115 =", "plane angle unit not understood"},
        {"#115 = ( CONVERSION_BASED_UNIT('DEGREE',#12) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );", "#12 =",
         "expected a PLANE_ANGLE_MEASURE_WITH_UNIT"},
        {"#115 = ( CONVERSION_BASED_UNIT('DEGREE') NAMED_UNIT(*) PLANE_ANGLE_UNIT() );", "#115 =", "the conversion factor missing"},
        {"#115 = ( CONVERSION_BASED_UNIT('X',#900) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );\n"
         "#900 = PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(0.),#902);\n#902 = ( PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );",
         "#900 =", "plane angle conversion factor out of range"},
        {"#115 = ( CONVERSION_BASED_UNIT('X',#900) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );\n"
         "#900 = PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(1E5),#902);\n#902 = ( PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) );",
         "#900 =", "out of range"},
        {"#115 = ( CONVERSION_BASED_UNIT('X',#900) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );\n"
         "#900 = PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(1.),#115);", "#115 =", "units defined in a cycle"},
        {"#115 = ( CONVERSION_BASED_UNIT('X',#900) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );\n"
         "#900 = PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(1.),#12);", "#12 =", "plane angle unit not understood"},
        {"#115 = ( CONVERSION_BASED_UNIT('X',#900) NAMED_UNIT(*) PLANE_ANGLE_UNIT() );\n"
         "#900 = PLANE_ANGLE_MEASURE_WITH_UNIT('one',#12);", "#900 =", "the factor must be a number"},
    };
    char *orig = read_text("cone.step");
    for (size_t k = 0; orig != NULL && k < sizeof units / sizeof units[0]; k++) {
        char what[32];
        (void)snprintf(what, sizeof what, "unit case %zu", k);
        char *text = edit(orig, (const char *const[]){UNIT115, units[k].unit, NULL}, NULL);
        must_refuse(what, text, BS_ERR_PARSE, text != NULL ? line_of(text, units[k].where) : 0, units[k].names);
        free(text);
    }
    /* a PCURVE's representation refused, an associated geometry that is no PCURVE skipped */
    static const struct {
        const char *from, *to, *where, *names;
    } pc[] = {
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31,#37);", "#37 =", "expected a DEFINITIONAL_REPRESENTATION"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31);", "#30 =", "the parameter-space curve missing"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31,#950);\n#950 = DEFINITIONAL_REPRESENTATION('',(),#41);", "#950 =",
         "no curve in the representation"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31,#950);\n#950 = DEFINITIONAL_REPRESENTATION('',#37,#41);", "#950 =",
         "the items must be a list"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31,#950);\n#950 = DEFINITIONAL_REPRESENTATION('',(#951),#41);\n"
                                      "#951 = LINE('',#27,#39);", "#27 =", "expected 2 coordinates"},
#define PC951(c) "#30 = PCURVE('',#31,#950);\n#950 = DEFINITIONAL_REPRESENTATION('',(#951),#41);\n#951 = " c
        {"#30 = PCURVE('',#31,#36);", PC951("CIRCLE('',#50,0.);"), "#951 =", "radii must be positive"},
        {"#30 = PCURVE('',#31,#36);", PC951("CIRCLE('',#26,1.);"), "#26 =", "expected an AXIS2_PLACEMENT_2D"},
        {"#30 = PCURVE('',#31,#36);", PC951("CIRCLE('',#952,1.);\n#952 = AXIS2_PLACEMENT_2D('',#51,#28);"), "#28 =",
         "expected 2 direction ratios"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('');", "#30 =", "the basis surface missing"},
        {"#30 = PCURVE('',#31,#36);", "#30 = PCURVE('',#31,#950);\n#950 = DEFINITIONAL_REPRESENTATION('',(5),#41);", "#950 =",
         "the curve must be a reference"},
        {"#24 = SURFACE_CURVE('',#25,(#30,#42),.PCURVE_S1.);", "#24 = SURFACE_CURVE('',#25,#30,.PCURVE_S1.);", "#24 =",
         "the parameter-space curves must be a list"},
        {"#24 = SURFACE_CURVE('',#25,(#30,#42),.PCURVE_S1.);", "#24 = SURFACE_CURVE('',#25,(#30,'x'),.PCURVE_S1.);", "#24 =",
         "a parameter-space curve must be"},
        {"#24 = SURFACE_CURVE('',#25,(#30,#42),.PCURVE_S1.);", "#24 = SURFACE_CURVE('',$,(#30,#42),.PCURVE_S1.);", "#24 =",
         "the 3-D curve must be"},
        {"#31 = CONICAL_SURFACE('',#32,4.,0.404891786285);", "#31 = CONICAL_SURFACE('',#33,4.,0.404891786285);", "#33 =",
         "expected an AXIS2_PLACEMENT_3D"},
    };
    for (size_t k = 0; orig != NULL && k < sizeof pc / sizeof pc[0]; k++) {
        char what[32];
        (void)snprintf(what, sizeof what, "pcurve case %zu", k);
        char *text = edit(orig, (const char *const[]){pc[k].from, pc[k].to, NULL}, NULL);
        must_refuse(what, text, BS_ERR_PARSE, text != NULL ? line_of(text, pc[k].where) : 0, pc[k].names);
        free(text);
    }
    free(orig);
    cone_reads("a PCURVE that is no PCURVE, a 2-D placement without direction", "cone.step",
               E("#24 = SURFACE_CURVE('',#25,(#30,#42),.PCURVE_S1.);", "#24 = SURFACE_CURVE('',#25,(#26,#30,#42),.PCURVE_S1.);",
                 "#50 = AXIS2_PLACEMENT_2D('',#51,#52);", "#50 = AXIS2_PLACEMENT_2D('',#51,$);"));
}

/* Faces without edges: the sphere (data/cad) and a whole torus, bounded by vertex loops. */
static void test_vertex_loops(void)
{
    char *orig = read_text("sphere.step");
    char *text = orig != NULL ? edit(orig, E("#22 = SPHERICAL_SURFACE('',#23,5.);", "#22 = TOROIDAL_SURFACE('',#23,5.,1.);"), NULL)
                              : NULL;
    bs_model *m = must_read("torus of vertex loops", text);
    double a, v;
    properties(m, &a, &v);
    CHECKF(bs_model_face_count(m) == 1 && near(a, 4.0 * pi * pi * 5.0, 1e-9) && near(v, 2.0 * pi * pi * 5.0, 1e-9),
           "torus: area %.15g, volume %.15g", a, v);
    bs_model_destroy(m);
    free(text);
    /* the torus without PCURVEs as the revolution of its tube's circle about its axis: read (a swept
     * conic); the v of a revolution is not periodic in the model, so a whole turn of a closed
     * generatrix does not bound the face and its area is not checked */
    char *torus = read_text("torus-3d-edges.step");
    text = torus != NULL ? edit(torus, E("#38 = TOROIDAL_SURFACE('',#39,6.,1.5);", "#38 = SURFACE_OF_REVOLUTION('',#31,#993);\n"
                                                                               "#993 = AXIS1_PLACEMENT('',#40,#41);"), NULL)
                         : NULL;
    m = must_read("torus as a revolution", text);
    CHECK(bs_model_face_count(m) == 1);
    bs_model_destroy(m);
    free(torus);
    free(text);
    text = orig != NULL ? edit(orig, E("#22 = SPHERICAL_SURFACE('',#23,5.);", "#22 = CYLINDRICAL_SURFACE('',#23,5.);"), NULL)
                        : NULL;
    must_refuse("cylinder of vertex loops", text, BS_ERR_PARSE, text != NULL ? line_of(text, "#17 =") : 0, "unbounded surface");
    free(text);
    free(orig);
}

int main(void)
{
    test_parts();
    test_syntax();
    test_lexer_refusals();
    test_square_refusals();
    test_square_surfaces();
    test_cubes();
    test_cone();
    test_vertex_loops();
    return bs_test_exit("test_step");
}
