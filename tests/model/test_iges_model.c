/* The IGES model reader: the CAD parts of data/cad/ (144 trimmed surfaces and 186 B-reps written by
 * OpenCASCADE 7.6) against the face counts of their .ref files, closed shells from the B-rep
 * topology, points of the faces on the closed-form surfaces of the parts (sphere, torus, cone,
 * wedge); small files written here, one per entity read and one per refusal. */
#include "harness.h"
#include "iges_text.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The reader refuses with status want and a message holding `words`, at a line. */
static void refused(const ent *e, size_t n, long back_fix, bs_status want, const char *words)
{
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_model *m = (bs_model *)&err;
    bs_status st = read_ents(e, n, back_fix, &err, &m);
    CHECKF(st == want && m == NULL && err.line > 0 && strstr(err.message, words) != NULL,
           "status %d (want %d), line %zu: \"%s\" (want \"%s\")", (int)st, (int)want, err.line, err.message, words);
    if (st == BS_OK)
        bs_model_destroy(m);
}

/* Points of face f over its box (a grid of g x g inside it) through bs_model_face_eval. */
static size_t face_points(const bs_model *m, size_t f, size_t g, double *pts)
{
    bs_face_info fi;
    memset(&fi, 0, sizeof fi);
    fi.size = sizeof fi;
    if (bs_model_face_info(m, f, &fi) != BS_OK)
        return 0;
    size_t n = 0;
    for (size_t i = 0; i < g; i++)
        for (size_t j = 0; j < g; j++) {
            double u = fi.u0 + (fi.u1 - fi.u0) * ((double)i + 0.5) / (double)g;
            double v = fi.v0 + (fi.v1 - fi.v0) * ((double)j + 0.5) / (double)g;
            uint32_t face = (uint32_t)f;
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view pos[3] = {{&pts[3 * n], 1, 0}, {&pts[3 * n + 1], 1, 0}, {&pts[3 * n + 2], 1, 0}};
            if (bs_model_face_eval(m, 1, &face, &cu, &cv, pos, NULL, NULL) == BS_OK && !isnan(pts[3 * n]))
                n++;
        }
    return n;
}

/* Distance of p from the part's closed-form surface of a face of that kind (NAN: not judged). */
static double off_surface(const char *part, int kind, const double *p)
{
    if (strcmp(part, "sphere") == 0) /* centre and radius of sphere.ref's box */
        return fabs(sqrt((p[0] - 1) * (p[0] - 1) + (p[1] - 2) * (p[1] - 2) + (p[2] - 3) * (p[2] - 3)) - 5);
    if (strcmp(part, "torus") == 0) { /* R 6, r 1.5 (torus.ref's box and volume), axis (0,1,1)/sqrt 2 */
        double h = (p[1] + p[2]) / sqrt(2.0), q[3] = {p[0], p[1] - h / sqrt(2.0), p[2] - h / sqrt(2.0)};
        double rho = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        return fabs(hypot(rho - 6, h) - 1.5);
    }
    if (strcmp(part, "cone") == 0) /* radius 4 at z = 0, 1 at z = 7 (cone.ref's box and volume) */
        return kind == BS_FACE_PLANE ? fmin(fabs(p[2]), fabs(p[2] - 7)) : fabs(hypot(p[0], p[1]) - (4 - 3 * p[2] / 7));
    if (strcmp(part, "wedge") == 0 && kind != BS_FACE_PLANE) /* radius 2.5 about the x axis */
        return fabs(hypot(p[1], p[2]) - 2.5);
    return NAN;
}

static void test_part(const char *part, int brep)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s.ref", BS_CAD_DIR, part);
    FILE *f = fopen(path, "r");
    size_t want = 0;
    double ref_area = 0.0, ref_volume = 0.0;
    CHECK(f != NULL && fscanf(f, "%*[^\n]\nfaces %zu area %lf volume %lf", &want, &ref_area, &ref_volume) == 3);
    if (f != NULL)
        fclose(f);
    (void)snprintf(path, sizeof path, "%s/%s%s.igs", BS_CAD_DIR, part, brep ? "-brep" : "");
    bs_model *m = NULL;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_status st = bs_model_read_iges_file(path, &err, &m);
    CHECKF(st == BS_OK, "%s: status %d, line %zu column %zu: %s", path, (int)st, err.line, err.column, err.message);
    if (st != BS_OK)
        return;
    size_t faces = bs_model_face_count(m), closed = 0, points = 0;
    CHECKF(faces == want, "%s: %zu faces, %zu in the .ref", path, faces, want);
    for (size_t s = 0; s < bs_model_shell_count(m); s++)
        closed += (size_t)bs_model_shell_closed(m, s);
    if (brep)
        CHECKF(closed == bs_model_shell_count(m) && closed == 1, "%s: %zu of %zu shells closed", path, closed,
               bs_model_shell_count(m));
    double worst = 0.0, pts[3 * 64];
    for (size_t k = 0; k < faces; k++) {
        bs_face_info fi;
        memset(&fi, 0, sizeof fi);
        fi.size = sizeof fi;
        CHECK(bs_model_face_info(m, k, &fi) == BS_OK && fi.loop_count >= 1);
        size_t n = face_points(m, k, 8, pts);
        for (size_t i = 0; i < n; i++) {
            double d = off_surface(part, fi.kind, &pts[3 * i]);
            if (!isnan(d)) {
                worst = fmax(worst, d);
                points++;
            }
        }
    }
    CHECKF(worst <= 1e-7, "%s: points %g off the part's surface", path, worst);
    double area = NAN, volume = NAN;
    st = bs_model_properties(m, 1e-9, &area, &volume, NULL);
    CHECKF(st == BS_OK && fabs(area - ref_area) <= 1e-6 * ref_area, "%s: area %.10g, %.10g in the .ref", path, area,
           ref_area);
    if (closed == bs_model_shell_count(m)) /* the B-reps, and the 144 files the model sews closed */
        CHECKF(fabs(volume - ref_volume) <= 1e-6 * ref_volume, "%s: volume %.10g, %.10g in the .ref", path, volume,
               ref_volume);
    printf("%s%s: %zu faces (%zu in the .ref), %zu edges, %zu of %zu shells closed; %zu points on the closed "
           "form, worst %.3g; area %.10g (.ref %.10g), volume %.10g (.ref %.10g)\n",
           part, brep ? "-brep" : "", faces, want, bs_model_edge_count(m), closed, bs_model_shell_count(m), points,
           worst, area, ref_area, volume, ref_volume);
    bs_model_destroy(m);
}

/* A CAD file with `from` replaced by `to` (of the same length) is refused with those words. */
static void spoiled(const char *part, const char *from, const char *to, bs_status want, const char *words)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s.igs", BS_CAD_DIR, part);
    FILE *f = fopen(path, "rb");
    char *t = malloc(1 << 20);
    size_t len = f != NULL && t != NULL ? fread(t, 1, (1 << 20) - 1, f) : 0;
    if (f != NULL)
        fclose(f);
    CHECK(len > 0 && strlen(from) == strlen(to));
    t[len] = '\0';
    char *at = strstr(t, from);
    CHECKF(at != NULL, "%s: no %s", part, from);
    if (at != NULL) {
        memcpy(at, to, strlen(to));
        bs_parse_error err;
        memset(&err, 0, sizeof err);
        bs_model *m = NULL;
        bs_status st = bs_model_read_iges(t, len, &err, &m);
        CHECKF(st == want && m == NULL && err.line > 0 && strstr(err.message, words) != NULL,
               "%s: status %d, line %zu: \"%s\" (want \"%s\")", part, (int)st, err.line, err.message, words);
        bs_model_destroy(m);
    }
    free(t);
}

/* The cone's B-rep with its cone (194) of form 0, unparametrised: the trims projected from the
 * edges' 3-D curves give the same area and volume. */
static void test_unparametrised(void)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/cone-brep.igs", BS_CAD_DIR);
    FILE *f = fopen(path, "rb");
    char *t = malloc(1 << 16);
    size_t len = f != NULL && t != NULL ? fread(t, 1, (1 << 16) - 1, f) : 0;
    if (f != NULL)
        fclose(f);
    t[len] = '\0';
    char *at = strstr(t, "     194       0       0       1       1");
    CHECK(at != NULL);
    if (at != NULL) {
        at[39] = '0';
        bs_parse_error err;
        bs_model *m = NULL;
        bs_status st = bs_model_read_iges(t, len, &err, &m);
        double area = NAN, volume = NAN;
        CHECKF(st == BS_OK && bs_model_properties(m, 1e-9, &area, &volume, NULL) == BS_OK &&
                   fabs(area - 173.03535931497038) < 1e-6 && fabs(volume - 153.93804002589985) < 1e-6,
               "cone of form 0: status %d (%s), area %.12g, volume %.12g", (int)st, err.message, area, volume);
        bs_model_destroy(m);
    }
    free(t);
}

static void test_spoiled_parts(void)
{
    spoiled("cone-brep", "508,4,0,17,1,0,1", "508,4,0,17,9,0,1", BS_ERR_PARSE, "edge 9 of a list of 3");
    spoiled("cone-brep", "514,3,5,1,37,1,49,0", "514,3,5,1,5 ,1,49,0", BS_ERR_PARSE, "used twice");
    spoiled("cone-brep", "194,9,11,4.", "194,9,9 ,4.", BS_ERR_PARSE, "where 123 is needed");
    spoiled("cone-brep", "508,1,0,17,1,1,0;", "508,1,1,17,1,1,0;", BS_ERR_PARSE, "where 502 is needed");
    spoiled("sphere-brep", "186,3,1,0;", "186,5,1,0;", BS_ERR_PARSE, "where 514 is needed");
    spoiled("sphere-brep", "504,1,23,17,2,17,1;", "504,9,23,17,2,17,1;", BS_ERR_PARSE, "the number of edges");
    spoiled("sphere", "142,0,3,15,21,3;", "142,0,5,15,21,3;", BS_ERR_PARSE, "not DE 3 of its face");
    spoiled("sphere", "120,7,9,0.,6.283185307;", "120,7,9,0.,6.283185307,", BS_ERR_PARSE, "");
    spoiled("torus", "0000001P0000001", "0000003P0000001", BS_ERR_PARSE, "back pointer is not DE 1");
    spoiled("torus", "     124       3", "     124      99", BS_ERR_PARSE, "parameter data pointer outside");
}

/* Every field of the P section spoiled in turn (its first character made a letter, a 1 or a minus,
 * the record delimiter made a parameter delimiter): a model or a clean failure, at a line. */
static void sweep(const char *name, const char *text, size_t len)
{
    char *t = malloc(len + 1);
    size_t tried = 0, failed = 0;
    for (size_t at = 0; at < len; at++) {
        size_t col = 0;
        while (col < at && text[at - col - 1] != '\n')
            col++;
        if (col >= 72 || at + 80 - col > len)
            continue;
        char sec = text[at - col + 72];
        int first = col == 0 || text[at - 1] == ',' || text[at - 1] == ';';
        if (sec == 'D' ? col % 8 != 7 : sec != 'P' || col >= 64 || (!first && text[at] != ';'))
            continue; /* directory entries: the last column of each field */
        static const char subs[3] = {'X', '1', '-'};
        for (int k = 0; k < 3; k++) {
            char c = text[at] == ';' ? ',' : subs[k];
            if (text[at] == ';' && k > 0)
                break;
            memcpy(t, text, len);
            t[at] = c;
            bs_parse_error err;
            memset(&err, 0, sizeof err);
            bs_model *m = NULL;
            bs_status st = bs_model_read_iges(t, len, &err, &m);
            tried++;
            if (st != BS_OK) {
                failed++;
                CHECKF(m == NULL && err.line > 0 && err.column > 0, "%s: byte %zu made '%c': status %d, line %zu",
                       name, at, c, (int)st, err.line);
            }
            bs_model_destroy(m);
        }
    }
    printf("%s: %zu spoiled fields, %zu refused\n", name, tried, failed);
    free(t);
}

static void test_parts(void)
{
    static const char *const parts[] = {"sphere", "torus", "cone", "wedge", "bell", "duct", "block", "bottle"};
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++)
        for (int brep = 0; brep < 2; brep++)
            test_part(parts[k], brep);
}

/* A square of side 2 on the plane z = 1 (108), its boundary a composite of four lines (3-D only). */
static const ent square[] = {
    {144, 0, 0, "144,3,1,0,5;"},
    {108, 0, 0, "108,0.,0.,1.,1.,0,0.,0.,0.,0.;"},
    {142, 0, 0, "142,0,3,0,7,2;"},
    {102, 0, 0, "102,4,9,11,13,15;"},
    {110, 0, 0, "110,0.,0.,1.,2.,0.,1.;"},
    {110, 0, 0, "110,2.,0.,1.,2.,2.,1.;"},
    {110, 0, 0, "110,2.,2.,1.,0.,2.,1.;"},
    {110, 0, 0, "110,0.,2.,1.,0.,0.,1.;"},
};

static void test_small(void)
{
    bs_model *m = NULL;
    bs_parse_error err;
    bs_status st = read_ents(square, 8, 0, &err, &m);
    CHECKF(st == BS_OK, "square: %d %s", (int)st, err.message);
    if (st == BS_OK) {
        double pts[3 * 16];
        bs_face_info fi;
        memset(&fi, 0, sizeof fi);
        fi.size = sizeof fi;
        CHECK(bs_model_face_count(m) == 1 && bs_model_face_info(m, 0, &fi) == BS_OK && fi.kind == BS_FACE_PLANE);
        CHECK(fi.loop_count == 1 && fabs((fi.u1 - fi.u0) * (fi.v1 - fi.v0) - 4.0) < 1e-12);
        size_t n = face_points(m, 0, 4, pts);
        CHECK(n == 16);
        for (size_t k = 0; k < n; k++)
            CHECK(fabs(pts[3 * k + 2] - 1.0) < 1e-14 && pts[3 * k] > 0 && pts[3 * k] < 2);
        bs_model_destroy(m);
    }
    /* an untrimmed bilinear 128 moved by a 124: one face without loops */
    static const ent patch[] = {
        {128, 0, 3, "128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,1.,"
                    "0.,1.,0.,1.;"},
        {124, 0, 0, "124,1.,0.,0.,5.,0.,1.,0.,0.,0.,0.,1.,0.;"},
    };
    st = read_ents(patch, 2, 0, &err, &m);
    CHECKF(st == BS_OK, "patch: %d %s", (int)st, err.message);
    if (st == BS_OK) {
        double pts[3 * 4];
        CHECK(bs_model_face_count(m) == 1 && face_points(m, 0, 2, pts) == 4);
        CHECK(fabs(pts[0] - 5.25) < 1e-14 && fabs(pts[2] - 0.25 * 0.25) < 1e-14);
        bs_model_destroy(m);
    }
}

/* A face read from ents: its info, and its points over its box (z of each checked against z). */
static void one_face(const char *what, const ent *e, size_t n, int kind, double area, double z)
{
    bs_model *m = NULL;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_status st = read_ents(e, n, 0, &err, &m);
    CHECKF(st == BS_OK, "%s: %d %s", what, (int)st, err.message);
    if (st != BS_OK)
        return;
    bs_face_info fi;
    memset(&fi, 0, sizeof fi);
    fi.size = sizeof fi;
    CHECK(bs_model_face_count(m) == 1 && bs_model_face_info(m, 0, &fi) == BS_OK && fi.kind == kind);
    CHECKF(fabs((fi.u1 - fi.u0) * (fi.v1 - fi.v0) - area) < 1e-12, "%s: box %g %g %g %g", what, fi.u0, fi.u1, fi.v0,
           fi.v1);
    double pts[3 * 16];
    size_t got = face_points(m, 0, 4, pts);
    CHECK(got == 16);
    for (size_t k = 0; k < got; k++)
        CHECKF(isnan(z) || fabs(pts[3 * k + 2] - z) < 1e-14, "%s: z %.17g", what, pts[3 * k + 2]);
    bs_model_destroy(m);
}

static void test_entities(void)
{
    /* 143 bounded by a 141 of the square's composite (3-D only): as the 144 */
    ent b[9];
    memcpy(b, square, sizeof square);
    b[0] = (ent){143, 0, 0, "143,1,3,1,17;"};
    b[2] = (ent){110, 0, 0, "110,0.,0.,0.,0.,0.,0.;"};
    b[8] = (ent){141, 0, 0, "141,1,2,3,1,7,1,0;"};
    one_face("143", b, 9, BS_FACE_PLANE, 4.0, 1.0);
    /* a full ellipse (104) at z = 1 (its ZT) bounding the plane: box 4 by 2 */
    static const ent ellipse[] = {
        {144, 0, 0, "144,3,1,0,5;"},
        {108, 0, 0, "108,0.,0.,1.,1.,0,0.,0.,0.,0.;"},
        {142, 0, 0, "142,0,3,0,7,2;"},
        {104, 1, 0, "104,1.,0.,4.,0.,0.,-4.,1.,2.,0.,2.,0.;"},
    };
    one_face("104", ellipse, 4, BS_FACE_PLANE, 8.0, 1.0);
    /* a circle (100, full turn, ZT 1) of radius 2 turned upright by a 124: box 4 by 4 on the plane x = 3 */
    static const ent circle[] = {
        {144, 0, 0, "144,3,1,0,5;"},
        {108, 0, 0, "108,1.,0.,0.,3.,0,0.,0.,0.,0.;"},
        {142, 0, 0, "142,0,3,0,7,2;"},
        {100, 0, 9, "100,3.,0.,0.,2.,0.,2.,0.;"},
        {124, 0, 0, "124,0.,0.,1.,0.,1.,0.,0.,0.,0.,-1.,0.,0.;"},
    };
    one_face("100", circle, 5, BS_FACE_PLANE, 16.0, NAN);
    /* a 143 on a 128 bounded by one 141 of a model curve and its parameter curve (run backwards) */
    static const ent b128[] = {
        {143, 0, 0, "143,0,3,1,5;"},
        {128, 0, 0, "128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,2.,2.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,"
                    "0.,1.,0.,2.;"},
        {141, 0, 0, "141,1,1,3,1,7,2,2,9,9;"},
        {102, 0, 0, "102,4,11,13,15,17;"},
        {102, 0, 0, "102,4,11,13,15,17;"},
        {110, 0, 0, "110,0.,0.,0.,1.,0.,0.;"},
        {110, 0, 0, "110,1.,0.,0.,1.,2.,0.;"},
        {110, 0, 0, "110,1.,2.,0.,0.,2.,0.;"},
        {110, 0, 0, "110,0.,2.,0.,0.,0.,0.;"},
    };
    one_face("143 with parameter curves", b128, 9, BS_FACE_BSPLINE, 2.0, NAN);
    /* a 128 trimmed by its own boundary (N1 = 0): its range */
    static const ent own[] = {
        {144, 0, 0, "144,3,0,0,0;"},
        {128, 0, 0, "128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,2.,2.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,"
                    "0.,1.,0.,2.;"},
    };
    one_face("128 untrimmed by 144", own, 2, BS_FACE_BSPLINE, 2.0, 0.0);
    /* a tabulated cylinder (122) of a line swept along z, bounded by its own [0,1]^2 */
    static const ent tab[] = {
        {144, 0, 0, "144,3,0,0,0;"},
        {122, 0, 0, "122,5,0.,0.,3.;"},
        {110, 0, 0, "110,0.,0.,0.,2.,0.,0.;"},
    };
    one_face("122", tab, 3, BS_FACE_EXTRUSION, 1.0, NAN);
    /* the sphere's 142 without its parameter curve: the trims projected from the 3-D curves */
    bs_model *m = NULL;
    char path[512];
    (void)snprintf(path, sizeof path, "%s/sphere.igs", BS_CAD_DIR);
    FILE *f = fopen(path, "rb");
    char *t = malloc(1 << 16);
    size_t len = f != NULL && t != NULL ? fread(t, 1, (1 << 16) - 1, f) : 0;
    if (f != NULL)
        fclose(f);
    t[len] = '\0';
    char *at = strstr(t, "142,0,3,15,21,3;");
    CHECK(at != NULL);
    if (at != NULL) {
        memcpy(at, "142,0,3,0 ,21,3;", 16);
        bs_parse_error err;
        bs_status st = bs_model_read_iges(t, len, &err, &m);
        /* read, on the sphere; where its two meridians land (both on one side of the seam) is
         * the projection's choice at the poles, so its area is not judged here */
        double pts[3 * 64], worst = 0.0;
        CHECKF(st == BS_OK && bs_model_face_count(m) == 1, "projected sphere: status %d (%s)", (int)st, err.message);
        size_t n = st == BS_OK ? face_points(m, 0, 8, pts) : 0;
        for (size_t k = 0; k < n; k++)
            worst = fmax(worst, off_surface("sphere", BS_FACE_REVOLUTION, &pts[3 * k]));
        CHECKF(n == 64 && worst < 1e-12, "projected sphere: %zu points, %g off", n, worst);
        bs_model_destroy(m);
    }
    free(t);
}

static void test_refusals(void)
{
    static const ent lines[] = {{110, 0, 0, "110,0.,0.,0.,1.,0.,0.;"}, {116, 0, 0, "116,0.,0.,0.;"}};
    refused(lines, 2, 0, BS_ERR_PARSE, "no surface read: 2 entities of types 110, 116");
    static const ent three[] = {lines[0], lines[1], lines[0]};
    refused(three, 3, 0, BS_ERR_PARSE, "no surface read: 3 entities of types 110, 116");
    ent e[8];
    memcpy(e, square, sizeof e);
    refused(e, 8, 5, BS_ERR_PARSE, "back pointer");
    e[1] = (ent){140, 0, 0, "140,1.,3,0.,0.,0.;"}; /* an offset surface (of itself) */
    refused(e, 8, 0, BS_ERR_UNSUPPORTED, "entity 140 (DE 3): surface type not read");
    memcpy(e, square, sizeof e);
    e[3] = (ent){102, 0, 0, "102,2,9,7;"}; /* a composite holding itself */
    refused(e, 8, 0, BS_ERR_PARSE, "circular");
    memcpy(e, square, sizeof e);
    e[4].xform = 9; /* a line whose transformation is the line */
    refused(e, 8, 0, BS_ERR_PARSE, "not 124");
    ent chain[9]; /* a line moved by a 124 moved by itself */
    memcpy(chain, square, sizeof e);
    chain[8] = (ent){124, 0, 17, "124,1.,0.,0.,0.,0.,1.,0.,0.,0.,0.,1.,0.;"}, chain[5].xform = 17;
    refused(chain, 9, 0, BS_ERR_PARSE, "longer than 16 or circular");
    chain[8] = (ent){124, 0, 0, "124,0.,0.,0.,1.,0.,0.,0.,0.,0.,0.,0.,0.;"}; /* all points onto (1,0,0) */
    refused(chain, 9, 0, BS_ERR_PARSE, "singular");
    chain[8] = (ent){124, 0, 0, "124,1.,2.,0.,0.,2.,4.,0.,0.,0.,0.,1.,0.;"}; /* onto a plane */
    refused(chain, 9, 0, BS_ERR_PARSE, "singular");
    memcpy(e, square, sizeof e);
    e[2] = (ent){142, 0, 0, "142,0,3,0,8,2;"}; /* an even pointer */
    refused(e, 8, 0, BS_ERR_PARSE, "pointer 8 to no directory entry");
    memcpy(e, square, sizeof e);
    e[7] = (ent){126, 0, 0, "126,60,3,0,0,1,0,0.,1.;"};
    refused(e, 8, 0, BS_ERR_PARSE, "more control points than the parameter data can hold");
    memcpy(e, square, sizeof e);
    e[7] = (ent){112, 0, 0, "112,1,1,2,0.,1.;"};
    refused(e, 8, 0, BS_ERR_UNSUPPORTED, "entity 112 (DE 15): curve type not read");
    memcpy(e, square, sizeof e);
    e[2] = (ent){142, 0, 0, "142,0,3,0,0,2;"};
    refused(e, 8, 0, BS_ERR_PARSE, "no curve the surface's parameters can use");
    static const struct {
        size_t at;
        ent e;
        bs_status st;
        const char *words;
    } one[] = {
        {4, {100, 0, 0, "100,0.,0.,0.,0.,0.,0.,0.;"}, BS_ERR_PARSE, "arc of radius 0"},
        {4, {104, 2, 0, "104,1.,0.,-1.,0.,0.,-1.,0.,1.,0.,1.,0.;"}, BS_ERR_UNSUPPORTED, "only elliptic arcs"},
        {4, {126, 0, 0, "126,1,1,0,0,1,0,1.,0.,1.,1.,1.,1.,0.,0.,1.,1.,1.,1.,0.,1.;"}, BS_ERR_PARSE, "refused"},
        {4, {126, 0, 0, "126,1,1,0,0,1,0,0.,0.,1.,1.,1.,-1.,0.,0.,1.,1.,1.,1.,0.,1.;"}, BS_ERR_PARSE,
         "weights must be positive"},
        {4, {126, 0, 0, "126,1,2,0,0,1,0,0.,0.,1.,1.;"}, BS_ERR_PARSE, "K must be at least the degree M"},
        {3, {102, 0, 0, "102,0;"}, BS_ERR_PARSE, "the number of curves"},
        {1, {108, 0, 17, "108,0.,0.,1.,1.,0,0.,0.,0.,0.;"}, BS_ERR_UNSUPPORTED, "scales or shears"},
        {1, {108, 0, 0, "108,0.,0.,0.,1.,0,0.,0.,0.,0.;"}, BS_ERR_PARSE, "plane of normal 0"},
        {1, {192, 0, 0, "192,9,9,1.;"}, BS_ERR_PARSE, "(DE 9) where 116 is needed"},
        {1, {120, 0, 0, "120,7,9,0.,1.;"}, BS_ERR_PARSE, "axis of entity 102"},
        {1, {120, 0, 0, "120,9,11,1.,1.;"}, BS_ERR_PARSE, "terminate angle"},
        {1, {120, 0, 0, "120,9,7,0.,1.;"}, BS_ERR_UNSUPPORTED, "several pieces"},
        {0, {144, 0, 0, "144,3,1,1,5,5;"}, BS_ERR_PARSE, "used twice"},
        {0, {144, 0, 0, "144,3,0,0,0;"}, BS_ERR_PARSE, "outer boundary of an unbounded surface"},
        {0, {144, 0, 0, "144,9,1,0,5;"}, BS_ERR_UNSUPPORTED, "surface type not read"},
        {2, {142, 0, 0, "142,0,9,0,7,2;"}, BS_ERR_PARSE, "not DE 3 of its face"},
    };
    for (size_t k = 0; k < sizeof one / sizeof one[0]; k++) {
        ent f[9];
        memcpy(f, square, sizeof square);
        f[8] = (ent){124, 0, 0, "124,2.,0.,0.,0.,0.,1.,0.,0.,0.,0.,1.,0.;"}; /* a scaling */
        f[one[k].at] = one[k].e;
        refused(f, 9, 0, one[k].st, one[k].words);
    }
    /* composites of composites, each holding the one before twice: 32768 lines from 19 entities */
    ent nest[19] = {square[0], square[1], {142, 0, 0, "142,0,3,0,37,2;"}, {110, 0, 0, "110,0.,0.,0.,1.,0.,0.;"}};
    char pars[15][32];
    for (int k = 1; k <= 15; k++) {
        (void)snprintf(pars[k - 1], sizeof pars[k - 1], "102,2,%d,%d;", 5 + 2 * k, 5 + 2 * k);
        nest[3 + k] = (ent){102, 0, 0, pars[k - 1]};
    }
    refused(nest, 19, 0, BS_ERR_PARSE, "curves reused more often than the file's size allows");
    /* the 128 bounded by its own range, spoiled */
    static const char *const bad128[][2] = {
        {"128,1,1,2,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,0.,1.,0.,1.;",
         "at least the degrees"},
        {"128,30,30,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.;", "more control points"},
        {"128,1,1,1,1,0,0,1,0,0,0.,1.,0.,1.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,0.,1.,0.,1.;",
         "knots must not decrease"},
        {"128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,0.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,0.,1.,0.,1.;",
         "weights must be positive"},
        {"128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,2.,3.,0.,1.;",
         "parameter range empty"},
    };
    for (size_t k = 0; k < sizeof bad128 / sizeof bad128[0]; k++) {
        ent b[2] = {{144, 0, 0, "144,3,0,0,0;"}, {128, 0, 0, bad128[k][0]}};
        refused(b, 2, 0, BS_ERR_PARSE, bad128[k][1]);
    }
    /* a 143 whose 141 boundary lies on another surface */
    ent b143[9];
    memcpy(b143, square, sizeof square);
    b143[0] = (ent){143, 0, 0, "143,1,3,1,17;"};
    b143[8] = (ent){141, 0, 0, "141,1,2,5,1,7,1,0;"};
    refused(b143, 9, 0, BS_ERR_PARSE, "not DE 3 of its face");
    /* a 128 of 1000 spans bounded by its own range in 40 faces: copies past 8 points per byte */
    char *wide = malloc(64 * 1024);
    size_t w = (size_t)sprintf(wide, "128,1000,1,1,1,0,0,1,0,0,0.,0.");
    for (int k = 1; k < 1000; k++)
        w += (size_t)sprintf(wide + w, ",%d.", k);
    w += (size_t)sprintf(wide + w, ",1000.,1000.,0.,0.,1.,1.");
    for (int k = 0; k < 2002; k++)
        w += (size_t)sprintf(wide + w, ",1.");
    for (int j = 0; j < 2; j++)
        for (int k = 0; k <= 1000; k++)
            w += (size_t)sprintf(wide + w, ",%d.,%d.,0.", k, j);
    (void)sprintf(wide + w, ",0.,1000.,0.,1.;");
    ent many[41];
    many[0] = (ent){128, 0, 0, wide};
    for (size_t k = 1; k < 41; k++)
        many[k] = (ent){144, 0, 0, "144,1,0,0,0;"};
    refused(many, 41, 0, BS_ERR_PARSE, "surfaces reused more often than the file's size allows");
    free(wide);
    /* the 1.1 reader sends files of trimmed surfaces here */
    size_t len;
    char *t = iges_text(square, 8, 0, &len);
    bs_surface *s = NULL;
    bs_parse_error err;
    CHECK(bs_surface_read_iges(t, len, &err, &s) == BS_ERR_PARSE && s == NULL &&
          strstr(err.message, "1 trimmed surfaces (144); read it with bs_model_read_iges") != NULL);
    free(t);
    bs_model *m = (bs_model *)&err;
    CHECK(bs_model_read_iges(NULL, 1, &err, &m) == BS_ERR_INVALID_ARG && m == NULL);
    CHECK(bs_model_read_iges_file(NULL, &err, &m) == BS_ERR_INVALID_ARG);
    CHECK(bs_model_read_iges_file(BS_CAD_DIR "/missing.igs", &err, &m) == BS_ERR_IO && m == NULL);
}

static void test_sweeps(void)
{
    static const char *const parts[] = {"cone-brep", "sphere-brep", "sphere", "cone", "wedge-brep"};
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        char path[512];
        (void)snprintf(path, sizeof path, "%s/%s.igs", BS_CAD_DIR, parts[k]);
        FILE *f = fopen(path, "rb");
        char *t = malloc(1 << 16);
        size_t len = f != NULL && t != NULL ? fread(t, 1, 1 << 16, f) : 0;
        if (f != NULL)
            fclose(f);
        CHECK(len > 0);
        sweep(parts[k], t, len);
        free(t);
    }
    size_t len;
    char *t = iges_text(square, 8, 0, &len);
    sweep("square", t, len);
    free(t);
}

int main(void)
{
    test_small();
    test_entities();
    test_refusals();
    test_spoiled_parts();
    test_unparametrised();
    if (!bs_test_quick())
        test_sweeps();
    test_parts();
    return bs_test_exit("test_iges_model");
}
