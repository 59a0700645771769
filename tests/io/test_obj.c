/* The OBJ free-form reader and writer: exact round trips (tea set, random rational patches of
 * many degrees), multi-segment Bezier surfaces with u varying fastest, relative indices,
 * continuation lines, rational surfaces, B-splines against the same B-spline added directly,
 * skipped statements, every error with its line and column, hostile and mutated texts, a
 * decimal-comma locale, and the file interface. */
#include "harness.h"
#include "surface_check.h"

#include <bezsurf.h>

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bs_status parse(const char *t, bs_parse_error *err, bs_surface **out)
{
    return bs_surface_read_obj(t, strlen(t), err, out);
}

/* The text of s (NUL-terminated), or NULL. */
static char *write_text(const bs_surface *s)
{
    size_t size = 0, size2 = 0;
    if (bs_surface_write_obj(s, NULL, 0, &size) != BS_OK)
        return NULL;
    char *buf = malloc(size);
    if (buf == NULL || bs_surface_write_obj(s, buf, size, &size2) != BS_OK || size2 != size ||
        strlen(buf) != size - 1) {
        free(buf);
        return NULL;
    }
    return buf;
}

static int round_trips(const bs_surface *s)
{
    char *t = write_text(s);
    bs_surface *back = NULL;
    bs_parse_error err = {0, 0, ""};
    /* as a user writes it: the size the writer reports (final NUL included) passed back (1.2) */
    size_t size = 0;
    int ok = t != NULL && bs_surface_write_obj(s, NULL, 0, &size) == BS_OK &&
             bs_surface_read_obj(t, size, &err, &back) == BS_OK && surface_same_bits(s, back);
    bs_surface_destroy(back);
    back = NULL;
    ok = ok && parse(t, &err, &back) == BS_OK && surface_same_bits(s, back);
    if (!ok)
        fprintf(stderr, "round trip: %zu:%zu %s\n", err.line, err.column, err.message);
    bs_surface_destroy(back);
    free(t);
    return ok;
}

static void test_round_trips(void)
{
    for (size_t k = 0; bs_builtin_name(k) != NULL; k++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create_builtin(bs_builtin_name(k), &s), BS_OK);
        CHECKF(round_trips(s), "%s", bs_builtin_name(k));
        bs_surface_destroy(s);
    }
    /* random patches, rational and not, degrees 0 to 7 and 64, awkward numbers */
    unsigned long long rng = 11;
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    static const size_t degs[][2] = {{0, 0}, {1, 0}, {0, 3}, {2, 5}, {7, 1}, {3, 3}, {64, 2}, {1, 64}};
    for (size_t k = 0; k < 16; k++) {
        size_t m = degs[k % 8][0], n = degs[k % 8][1], np = (m + 1) * (n + 1);
        double *c = malloc(np * 4 * sizeof(double)), *w = c + 3 * np;
        for (size_t i = 0; i < 3 * np; i++)
            c[i] = bs_test_rand(&rng, -1, 1) * pow(10.0, bs_test_rand(&rng, -300, 300));
        for (size_t i = 0; i < np; i++)
            w[i] = bs_test_rand(&rng, 0.01, 100);
        c[0] = 5e-324; /* a subnormal */
        c[1] = -0.0;
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, c, k >= 8 ? w : NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        bs_patch_destroy(p);
        free(c);
    }
    CHECK(round_trips(s));
    char *t = write_text(s);
    CHECK(t != NULL && strchr(t, ',') == NULL && strstr(t, "cstype rat bezier\n") != NULL &&
          strstr(t, " \\\n ") != NULL);
    free(t);
    /* the file interface writes the same text */
    const char *path = "test_obj_roundtrip.obj";
    bs_surface *back = NULL;
    CHECK_STATUS(bs_surface_write_obj_file(s, path), BS_OK);
    CHECK_STATUS(bs_surface_read_obj_file(path, NULL, &back), BS_OK);
    CHECK(surface_same_bits(s, back));
    bs_surface_destroy(back);
    remove(path);
    /* an empty surface writes a comment that reads back as an empty surface */
    bs_surface *empty = NULL;
    CHECK_STATUS(bs_surface_create(&empty), BS_OK);
    t = write_text(empty);
    CHECK(t != NULL && t[0] == '#' && parse(t, NULL, &back) == BS_OK && bs_surface_count(back) == 0);
    free(t);
    bs_surface_destroy(back);
    bs_surface_destroy(empty);
    size_t size;
    char small[8];
    CHECK_STATUS(bs_surface_write_obj(s, small, sizeof small, &size), BS_ERR_SIZE);
    CHECK_STATUS(bs_surface_write_obj(s, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_obj(NULL, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_obj_file(s, "/nonexistent-directory/x.obj"), BS_ERR_IO);
    CHECK_STATUS(bs_surface_write_obj_file(s, NULL), BS_ERR_INVALID_ARG);
    bs_surface_destroy(s);
}

/* Control point (i,j) of patch k, coordinate c. */
static double ctrl_at(const bs_surface *s, size_t k, size_t i, size_t j, size_t c)
{
    const bs_patch *p = bs_surface_get(s, k);
    double buf[64 * 3], w[64];
    if (p == NULL || bs_patch_get_ctrl(p, buf, 64 * 3, w, 64) != BS_OK)
        return NAN;
    return c == 3 ? w[i * (bs_patch_degree_v(p) + 1) + j] : buf[(i * (bs_patch_degree_v(p) + 1) + j) * 3 + c];
}

/* A quadratic x linear Bezier surface of two segments along u: 5 x 2 vertices, u fastest, listed
 * with relative indices across continuation lines, among statements that are skipped. */
static void test_bezier_segments(void)
{
    const char *t = "# two segments\r\n"
                    "mtllib x.mtl\no thing\ng a b\nusemtl red\ns 1\n"
                    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\n"
                    "v 0 1 0 2\nv 1 1 1\nv 2 1 0\nv 3 1 1\nv 4 1 0 0.5\n"
                    "vt 0 0\nvn 0 0 1\nf 1 2 3\nl 1 2\n"
                    "cstype rat bezier\ndeg 2 1\n"
                    "surf 0 2 0 1 -10/1 -9/1/1 -8//1 \\\n  -7 -6 \\\n"
                    "\\\n"
                    " -5 -4 -3 -2 -1 # comment\n"
                    "parm u 0 1 2\nparm v 0 1\ntrim 0 1 1\nhole 0 1 2\nscrv 0 1 3\nsp 4\nend\n"
                    "curv 0 1 1 2\nparm u 0 1\nend\n"
                    "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 6 7\nend\n";
    bs_surface *s = NULL;
    bs_parse_error err = {0, 0, ""};
    CHECKF(parse(t, &err, &s) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
    CHECK(bs_surface_count(s) == 3);
    if (bs_surface_count(s) != 3) {
        bs_surface_destroy(s);
        return;
    }
    /* patch 0: vertices 1-3 (v=0) and 6-8 (v=1); patch 1: 3-5 and 8-10 */
    CHECK(bs_patch_is_rational(bs_surface_get(s, 0)) && bs_patch_degree_u(bs_surface_get(s, 0)) == 2);
    for (size_t k = 0; k < 2; k++)
        for (size_t i = 0; i <= 2; i++) {
            CHECK(ctrl_at(s, k, i, 0, 0) == (double)(2 * k + i) && ctrl_at(s, k, i, 0, 1) == 0.0);
            CHECK(ctrl_at(s, k, i, 1, 0) == (double)(2 * k + i) && ctrl_at(s, k, i, 1, 1) == 1.0);
        }
    CHECK(ctrl_at(s, 0, 0, 1, 3) == 2.0 && ctrl_at(s, 1, 2, 1, 3) == 0.5 && ctrl_at(s, 0, 1, 0, 3) == 1.0);
    CHECK(!bs_patch_is_rational(bs_surface_get(s, 2)) && ctrl_at(s, 2, 1, 1, 1) == 1.0);
    bs_surface_destroy(s);
    /* without parm statements: one segment per direction; vertex colours ignored */
    CHECK_STATUS(parse("v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0\nv 1 1 0\ncstype bezier\ndeg 1 1\n"
                       "surf 0 1 0 1 1 2 3 4\nend\n", NULL, &s), BS_OK);
    CHECK(bs_surface_count(s) == 1 && ctrl_at(s, 0, 1, 0, 0) == 1.0 && ctrl_at(s, 0, 0, 1, 1) == 1.0);
    bs_surface_destroy(s);
}

/* OBJ text for a B-spline (dim 3): its vertices, then the surface over range s0 s1 t0 t1. */
static char *bspline_text(const bs_bspline *b, const double *range)
{
    size_t cap = 256 + 128 * b->count_u * b->count_v + 32 * (b->count_u + b->count_v + 2 * BS_MAX_DEGREE);
    char *s = malloc(cap);
    size_t len = 0;
    for (size_t j = 0; j < b->count_v; j++)
        for (size_t i = 0; i < b->count_u; i++) {
            const double *c = b->ctrl + 3 * (i * b->count_v + j);
            len += (size_t)snprintf(s + len, cap - len, "v %.17g %.17g %.17g %.17g\n", c[0], c[1], c[2],
                                    b->weights ? b->weights[i * b->count_v + j] : 1.0);
        }
    len += (size_t)snprintf(s + len, cap - len, "cstype %sbspline\ndeg %zu %zu\nsurf %.17g %.17g %.17g %.17g",
                            b->weights ? "rat " : "", b->deg_u, b->deg_v, range[0], range[1], range[2], range[3]);
    for (size_t k = 0; k < b->count_u * b->count_v; k++)
        len += (size_t)snprintf(s + len, cap - len, " %zu", k + 1);
    len += (size_t)snprintf(s + len, cap - len, "\nparm u");
    for (size_t k = 0; k < b->count_u + b->deg_u + 1; k++)
        len += (size_t)snprintf(s + len, cap - len, " %.17g", b->knots_u[k]);
    len += (size_t)snprintf(s + len, cap - len, "\nparm v");
    for (size_t k = 0; k < b->count_v + b->deg_v + 1; k++)
        len += (size_t)snprintf(s + len, cap - len, " %.17g", b->knots_v[k]);
    snprintf(s + len, cap - len, "\nend\n");
    return s;
}

static void test_bspline(void)
{
    static const double ku[] = {0, 0, 0, 0, 1, 2.5, 2.5, 4, 4, 4, 4}, kv[] = {-1, -0.5, 0, 0.5, 2, 2.5, 3};
    double c[7 * 4 * 3], w[7 * 4];
    unsigned long long rng = 5;
    for (size_t k = 0; k < 7 * 4 * 3; k++)
        c[k] = bs_test_rand(&rng, -2, 2);
    for (size_t k = 0; k < 7 * 4; k++)
        w[k] = bs_test_rand(&rng, 0.25, 4);
    for (int rational = 0; rational < 2; rational++) {
        bs_bspline b = {3, 2, 7, 4, 3, ku, kv, c, rational ? w : NULL}; /* v unclamped: domain [0, 2] */
        double whole[4] = {-1, 5, 0, 2}; /* beyond the domain in u: cut at it */
        char *t = bspline_text(&b, whole);
        bs_surface *got = NULL, *want = NULL;
        bs_parse_error err = {0, 0, ""};
        CHECKF(parse(t, &err, &got) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
        CHECK_STATUS(bs_surface_create(&want), BS_OK);
        CHECK_STATUS(bs_surface_add_bspline(want, &b, NULL, 0, NULL), BS_OK);
        CHECKF(surface_same_bits(got, want) && bs_surface_count(got) == 3 * 2, "rational %d", rational);
        bs_surface_destroy(got);
        free(t);

        /* over a sub-range: the spans it cuts are cut, evaluated against the whole B-spline */
        double sub[4] = {0.5, 3.0, 0.25, 2};
        t = bspline_text(&b, sub);
        CHECKF(parse(t, &err, &got) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
        CHECK(bs_surface_count(got) == 3 * 2);
        double worst = 0;
        size_t nu = 3, nv = 2;
        const double bu[4] = {0.5, 1, 2.5, 3}, bv[3] = {0.25, 0.5, 2};
        for (size_t k = 0; got && k < nu * nv; k++)
            for (int a = 0; a <= 4; a++)
                for (int e = 0; e <= 4; e++) {
                    size_t i = k / nv, j = k % nv, index;
                    double u = bu[i] + (bu[i + 1] - bu[i]) * a / 4.0, v = bv[j] + (bv[j + 1] - bv[j]) * e / 4.0;
                    double lu, lv, x[3], y[3];
                    CHECK(patch_point(bs_surface_get(got, k), a / 4.0, e / 4.0, x));
                    CHECK(bs_bspline_locate(&b, u, v, &index, &lu, &lv) == BS_OK &&
                          patch_point(bs_surface_get(want, index), lu, lv, y));
                    for (int d = 0; d < 3; d++)
                        worst = fmax(worst, fabs(x[d] - y[d]));
                }
        CHECKF(worst < 1e-12, "sub-range differs by %g", worst);
        bs_surface_destroy(got);
        bs_surface_destroy(want);
        free(t);
        t = bspline_text(&b, (double[4]){5, 6, 0, 2}); /* outside the domain */
        CHECK(parse(t, &err, &got) == BS_ERR_PARSE && got == NULL && err.line == 7 * 4 + 3);
        free(t);
    }
}

static void expect(const char *t, bs_status status, size_t line, size_t column, const char *what)
{
    bs_parse_error err = {0, 0, ""};
    bs_surface *s = (bs_surface *)&err;
    bs_status st = parse(t, &err, &s);
    CHECKF(st == status && s == NULL && err.line == line && err.column == column,
           "%s: status %d, at %zu:%zu (expected %zu:%zu): %s", what, st, err.line, err.column, line, column,
           err.message);
}

#define V4 "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
static void test_errors(void)
{
    expect("v 0 0\n", BS_ERR_PARSE, 1, 6, "two coordinates");
    expect("v 0 0 0 1 2\n", BS_ERR_PARSE, 1, 12, "five values");
    expect("v 0 0 0 1 2 3 4\n", BS_ERR_PARSE, 1, 15, "seven values");
    expect("\n\nv 0 x 0\n", BS_ERR_PARSE, 3, 5, "not a number");
    expect("v 0 1e999 0\n", BS_ERR_PARSE, 1, 5, "overflow");
    expect("v 0 nan 0\n", BS_ERR_PARSE, 1, 5, "nan");
    expect("v 0 0,5 0\n", BS_ERR_PARSE, 1, 5, "decimal comma");
    expect("12 3\n", BS_ERR_PARSE, 1, 1, "no keyword");
    expect("cstype\n", BS_ERR_PARSE, 1, 7, "no type");
    expect("cstype rat\n", BS_ERR_PARSE, 1, 11, "no type after rat");
    expect("cstype nurbs\n", BS_ERR_PARSE, 1, 8, "unknown type");
    expect("cstype bezier x\n", BS_ERR_PARSE, 1, 15, "extra value");
    expect("deg\n", BS_ERR_PARSE, 1, 4, "no degree");
    expect("deg 1 2 3\n", BS_ERR_PARSE, 1, 9, "three degrees");
    expect("deg 65 1\n", BS_ERR_PARSE, 1, 5, "degree over 64");
    expect("deg 99999999999999999999999 1\n", BS_ERR_PARSE, 1, 5, "huge degree");
    expect("deg -1 1\n", BS_ERR_PARSE, 1, 5, "negative degree");
    expect(V4 "deg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", BS_ERR_PARSE, 6, 1, "surf before cstype");
    expect(V4 "cstype bezier\ndeg 1\nsurf 0 1 0 1 1 2 3 4\nend\n", BS_ERR_PARSE, 7, 1, "one degree");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0\n", BS_ERR_PARSE, 7, 11, "no t1");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 5\nend\n", BS_ERR_PARSE, 7, 20, "index beyond");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 -5\nend\n", BS_ERR_PARSE, 7, 20, "relative before");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 0 3 4\nend\n", BS_ERR_PARSE, 7, 16, "index 0");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 x 4\nend\n", BS_ERR_PARSE, 7, 18, "index not a number");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3\nend\n", BS_ERR_PARSE, 7, 1, "three of four");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1 2\nend\n", BS_ERR_PARSE, 7, 1,
           "parm u asks for more");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 0\nend\n", BS_ERR_PARSE, 8, 6,
           "parm u not increasing");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm v 0\nend\n", BS_ERR_PARSE, 8, 6, "one value");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm w 0 1\nend\n", BS_ERR_PARSE, 8, 6, "parm w");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1\nparm u 0 1\nend\n", BS_ERR_PARSE, 9, 6,
           "two parm u");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 x\nend\n", BS_ERR_PARSE, 8, 10, "parm x");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\n", BS_ERR_PARSE, 7, 1, "no end");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nsurf 0 1 0 1 1 2 3 4\n", BS_ERR_PARSE, 8, 1, "two surf");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\ncurv 0 1 1 2\n", BS_ERR_PARSE, 8, 1, "curv in surf");
    expect("end\n", BS_ERR_PARSE, 1, 1, "end alone");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\ndeg 2 2\nend\n", BS_ERR_PARSE, 8, 1, "deg in a body");
    expect(V4 "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\n  cstype rat bezier\nend\n", BS_ERR_PARSE, 8, 3,
           "cstype in a body");
    expect("parm u 0 1\n", BS_ERR_PARSE, 1, 1, "parm alone");
    expect(V4 "cstype rat bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\nv 0 0 0 0\nsurf 0 1 0 1 1 2 3 5\nend\n",
           BS_ERR_PARSE, 10, 20, "zero weight");
    expect("v 1e300 0 0 1e300\nv 1 0 0\nv 0 1 0\nv 1 1 0\ncstype rat bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n",
           BS_ERR_PARSE, 7, 1, "w times x overflows");
    expect(V4 "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nend\n", BS_ERR_PARSE, 7, 1,
           "bspline without parm v");
    expect(V4 "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 1 1\nend\n", BS_ERR_PARSE, 9,
           6, "too few knots");
    expect(V4 "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 1 0 1\nend\n", BS_ERR_PARSE,
           9, 6, "decreasing knots");
    expect(V4 "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1 1\nparm v 0 0 1 1\nend\n",
           BS_ERR_PARSE, 7, 1, "knots for more vertices");
    expect(V4 "cstype bspline\ndeg 0 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1 2\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 7,
           1, "bspline degree 0");
    expect(V4 "cstype bezier\ndeg 0 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1 2\nend\n", BS_ERR_PARSE, 8, 6,
           "bezier degree 0 with two segments");
    expect(V4 "cstype taylor\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", BS_ERR_UNSUPPORTED, 7, 1, "taylor");
    expect(V4 "cstype rat bmatrix\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", BS_ERR_UNSUPPORTED, 7, 1, "bmatrix");
    expect("v 0 0 0\nv 1 0\0 0\n", BS_ERR_PARSE, 2, 6, "NUL byte");
    bs_parse_error err;
    bs_surface *s = (bs_surface *)&err;
    /* polygons or curves without any surface: what the text holds, not an empty surface (1.2) */
    CHECK_STATUS(parse("# mesh\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nl 1 2\np 1\n", &err, &s), BS_ERR_UNSUPPORTED);
    CHECKF(s == NULL && err.line == 5 && err.column == 1 &&
               strcmp(err.message, "no surface (surf) to read, only 2 faces (f), 1 lines (l), 1 points (p)") == 0,
           "%zu:%zu %s", err.line, err.column, err.message);
    CHECK_STATUS(parse("v 0 0 0\n  curv 0 1 1 1\nend\n", &err, &s), BS_ERR_UNSUPPORTED);
    CHECKF(s == NULL && err.line == 2 && err.column == 3 && strstr(err.message, "only 1 curves") != NULL, "%s",
           err.message);
    /* vertices and comments only, or polygons beside a surface: read as before */
    CHECK_STATUS(parse("# nothing\nv 0 0 0\nvn 0 0 1\n", &err, &s), BS_OK);
    CHECK(s != NULL && bs_surface_count(s) == 0);
    bs_surface_destroy(s);
    CHECK_STATUS(parse(V4 "f 1 2 3\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", &err, &s), BS_OK);
    CHECK(s != NULL && bs_surface_count(s) == 1);
    bs_surface_destroy(s);
    /* one final NUL is the end of the text (the writer's size counts it); two are an error */
    CHECK_STATUS(bs_surface_read_obj("v 0 0 0\n\0", 9, &err, &s), BS_OK);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_surface_read_obj("v 0 0 0\n\0\0", 10, &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && err.line == 2 && err.column == 1);
    CHECK_STATUS(bs_surface_read_obj("v 0 0 0\nv 1 0\0 0\n", 17, &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && err.line == 2 && err.column == 6);
    CHECK_STATUS(bs_surface_read_obj(V4 "cstype cardinal\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", 64, &err, &s),
                 BS_ERR_UNSUPPORTED);
    CHECK(strstr(err.message, "cardinal") != NULL && strstr(err.message, "line 5") != NULL);
    CHECK_STATUS(bs_surface_read_obj(NULL, 0, &err, &s), BS_OK); /* nothing: no surfaces */
    CHECK(s != NULL && bs_surface_count(s) == 0);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_surface_read_obj(NULL, 1, &err, &s), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_obj("v 0 0 0", 7, &err, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_obj_file("/nonexistent-directory/x.obj", &err, &s), BS_ERR_IO);
    CHECK(s == NULL && err.line == 0);
    CHECK_STATUS(bs_surface_read_obj_file(NULL, &err, &s), BS_ERR_INVALID_ARG);
}

/* Hostile texts: deep continuations, long statements, mutations of a good file. */
static void test_hostile(void)
{
    size_t n = 200000;
    char *t = malloc(3 * n + 64);
    size_t len = (size_t)snprintf(t, 64, "v 0 0 0");
    for (size_t k = 0; k < n; k++)
        memcpy(t + len, " \\\n", 3), len += 3;
    memcpy(t + len, " 1\nx", 4);
    bs_surface *s = NULL;
    bs_parse_error err;
    CHECK_STATUS(bs_surface_read_obj(t, len + 4, &err, &s), BS_OK); /* a vertex with a weight */
    CHECK(s != NULL && bs_surface_count(s) == 0);
    bs_surface_destroy(s);
    memcpy(t + len, " 1 2 3 4\n", 9);
    CHECK_STATUS(bs_surface_read_obj(t, len + 9, &err, &s), BS_ERR_PARSE); /* seven values */
    CHECK(err.line == n + 1 && err.column == 8);
    /* a surf statement of 200000 references to one vertex: too many for degree 1 x 1 */
    len = (size_t)snprintf(t, 64, "v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1");
    for (size_t k = 0; k < n; k++)
        memcpy(t + len, " 1", 2), len += 2;
    memcpy(t + len, "\nend\n", 5);
    CHECK_STATUS(bs_surface_read_obj(t, len + 5, &err, &s), BS_ERR_PARSE);
    CHECK(err.line == 4 && err.column == 1);
    free(t);

    const char *good = V4 "cstype rat bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 -2 -1\nparm u 0 0 1 1\n"
                          "parm v 0 0 1 1\nend\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 \\\n 3 4\nend\n";
    CHECK_STATUS(parse(good, NULL, &s), BS_OK);
    CHECK(bs_surface_count(s) == 2);
    bs_surface_destroy(s);
    size_t glen = strlen(good);
    char *m = malloc(glen + 1);
    unsigned long long rng = 3;
    for (int k = 0; k < 4000; k++) {
        memcpy(m, good, glen + 1);
        for (size_t j = 0; j < 1 + bs_test_rand_u64(&rng) % 3; j++)
            m[bs_test_rand_u64(&rng) % glen] = " \n\\#-019.e/vxu"[bs_test_rand_u64(&rng) % 14];
        bs_status st = bs_surface_read_obj(m, bs_test_rand_u64(&rng) % (glen + 1), &err, &s);
        CHECKF(st == BS_OK ? s != NULL : ((st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED) && s == NULL &&
                                          err.line > 0 && err.column > 0),
               "mutation %d: status %d", k, st);
        bs_surface_destroy(s);
    }
    free(m);
}

/* Under a decimal-comma locale: the same text and the same bits. */
static void test_locale(void)
{
    bs_surface *a = NULL, *b = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teacup", &a), BS_OK);
    char *ta = write_text(a);
    const char *found = switch_to_comma_locale();
    if (found == NULL) {
        printf("test_obj: locale part skipped, no locale with a decimal comma\n");
    } else {
        char *tb = write_text(a);
        CHECKF(ta && tb && strcmp(ta, tb) == 0, "text under %s", found);
        CHECK(ta && parse(ta, NULL, &b) == BS_OK && surface_same_bits(a, b));
        free(tb);
        setlocale(LC_ALL, "C");
    }
    free(ta);
    bs_surface_destroy(a);
    bs_surface_destroy(b);
}

/* tests/hostile/obj_deg64_amp_40.obj: 22 KB of degree-64 B-spline spans that would become 1,600
 * patches of 4,225 points (624 MB): refused before any is converted, and a degree-64 surface of
 * one span in a file of its size read. */
static void test_amplified(void)
{
    bs_surface *s = (bs_surface *)&s;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    CHECK_STATUS(bs_surface_read_obj_file(BS_TEST_SOURCE_DIR "/../hostile/obj_deg64_amp_40.obj", &err, &s), BS_ERR_SIZE);
    CHECKF(s == NULL && err.line == 4 && strstr(err.message, "4 per byte") != NULL, "%zu: %s", err.line, err.message);
    size_t n = 65 * 65, cap = 64 * n + 4096, len = 0;
    char *t = malloc(cap);
    if (t == NULL)
        return;
    len += (size_t)snprintf(t + len, cap - len, "v 0 0 0\nv 1 0 0\ncstype bspline\ndeg 64 64\nsurf 0 1 0 1");
    for (size_t k = 0; k < n; k++)
        len += (size_t)snprintf(t + len, cap - len, " %d", k % 2 ? 2 : 1);
    for (int d = 0; d < 2; d++) {
        len += (size_t)snprintf(t + len, cap - len, "\nparm %c", d ? 'v' : 'u');
        for (int k = 0; k < 130; k++)
            len += (size_t)snprintf(t + len, cap - len, " %d", k < 65 ? 0 : 1);
    }
    len += (size_t)snprintf(t + len, cap - len, "\nend\n");
    CHECK_STATUS(bs_surface_read_obj(t, len, &err, &s), BS_OK);
    CHECK(s != NULL && bs_surface_count(s) == 1);
    bs_surface_destroy(s);
    free(t);
}

int main(void)
{
    test_round_trips();
    test_bezier_segments();
    test_bspline();
    test_errors();
    test_hostile();
    test_amplified();
    test_locale();
    return bs_test_exit("test_obj");
}
