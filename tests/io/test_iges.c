/* The IGES reader: files written by OpenCASCADE against the points it computed (and a cylinder's
 * radius), entities built here against the same B-splines added directly, delimiters and Hollerith
 * strings, transformations, parameter ranges, every error with its record and column, mutated and
 * hostile files, a decimal-comma locale, and the file interface. */
#include "harness.h"
#include "surface_check.h"

#include <bezsurf.h>

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FIXTURES BS_TEST_SOURCE_DIR "/data/iges"

/* ---- IGES text built here: S, G, D, P, T records of 80 columns ---- */
typedef struct ent {
    int type;
    const char *params; /* with the delimiters in use, ended by the record delimiter */
    int transform;      /* directory pointer of a 124, or 0 */
    int form;
} ent;

typedef struct text {
    char *buf;
    size_t len, cap;
} text;

static void put_record(text *t, const char *data, size_t n, size_t width, const char *tail, char letter, size_t seq)
{
    if (t->len + 128 > t->cap) {
        t->cap = 2 * t->cap + 4096;
        t->buf = realloc(t->buf, t->cap);
    }
    char line[160];
    snprintf(line, sizeof line, "%-*.*s%s%c%07zu\n", (int)width, (int)n, data, tail, letter, seq);
    memcpy(t->buf + t->len, line, strlen(line) + 1);
    t->len += strlen(line);
}

/* Records of `width` columns holding s, counted in *seq; returns the number of records. */
static size_t put_lines(text *t, const char *s, size_t width, const char *tail, char letter, size_t *seq)
{
    size_t n = strlen(s), k = 0, count = 0;
    do {
        size_t m = n - k < width ? n - k : width;
        put_record(t, s + k, m, width, tail, letter, ++*seq);
        k += m;
        count++;
    } while (k < n);
    return count;
}

static char *make_iges(const char *global, const ent *e, size_t n)
{
    text t = {NULL, 0, 0};
    size_t seq_s = 0, seq_g = 0, seq_d = 0, seq_p = 0;
    put_lines(&t, "built by test_iges", 72, "", 'S', &seq_s);
    put_lines(&t, global, 72, "", 'G', &seq_g);
    size_t pstart[16], plines[16], pseq = 0;
    for (size_t k = 0; k < n; k++) { /* count the P records first */
        pstart[k] = pseq + 1;
        plines[k] = (strlen(e[k].params) + 63) / 64;
        pseq += plines[k];
    }
    for (size_t k = 0; k < n; k++) {
        char d[96];
        snprintf(d, sizeof d, "%8d%8zu%8d%8d%8d%8d%8d%8d%8s", e[k].type, pstart[k], 0, 0, 0, 0, e[k].transform, 0,
                 "00010000");
        put_lines(&t, d, 72, "", 'D', &seq_d);
        snprintf(d, sizeof d, "%8d%8d%8d%8zu%8d%8s%8s%8s%8d", e[k].type, 0, 0, plines[k], e[k].form, "", "", "", 0);
        put_lines(&t, d, 72, "", 'D', &seq_d);
    }
    for (size_t k = 0; k < n; k++) {
        char tail[24];
        snprintf(tail, sizeof tail, " %7zu", 2 * k + 1);
        put_lines(&t, e[k].params, 64, tail, 'P', &seq_p);
    }
    char term[80];
    snprintf(term, sizeof term, "S%07zuG%07zuD%07zuP%07zu", seq_s, seq_g, seq_d, seq_p);
    put_lines(&t, term, 72, "", 'T', &(size_t){0});
    return t.buf;
}

static const char *const GLOBAL = ",,4Htest,8Htest.igs,4Htest,4Htest,32,308,15,308,15,,1.,2,2HMM,1,0.01,"
                                  "15H20260101.000000,0.0001,,,,11,0,15H20260101.000000;";

/* Parameters of an entity 128 from a B-spline (dim 3), numbers in %.17g, range as given. */
static char *params_128(const bs_bspline *b, const double *range, char pd, char rd)
{
    size_t cap = 64 + 32 * (b->count_u + b->deg_u + b->count_v + b->deg_v + 4 * b->count_u * b->count_v + 8);
    char *s = malloc(cap);
    size_t len = (size_t)snprintf(s, cap, "128%c%zu%c%zu%c%zu%c%zu%c0%c0%c%d%c0%c0", pd, b->count_u - 1, pd,
                                  b->count_v - 1, pd, b->deg_u, pd, b->deg_v, pd, pd, pd, b->weights == NULL, pd, pd);
#define NUM(x) (len += (size_t)snprintf(s + len, cap - len, "%c%.17g", pd, (x)))
    for (size_t k = 0; k < b->count_u + b->deg_u + 1; k++)
        NUM(b->knots_u[k]);
    for (size_t k = 0; k < b->count_v + b->deg_v + 1; k++)
        NUM(b->knots_v[k]);
    for (size_t j = 0; j < b->count_v; j++)
        for (size_t i = 0; i < b->count_u; i++)
            NUM(b->weights ? b->weights[i * b->count_v + j] : 1.0);
    for (size_t j = 0; j < b->count_v; j++)
        for (size_t i = 0; i < b->count_u; i++)
            for (size_t c = 0; c < 3; c++)
                NUM(b->ctrl[(i * b->count_v + j) * 3 + c]);
    for (size_t k = 0; k < 4; k++)
        NUM(range[k]);
#undef NUM
    s[len++] = rd;
    s[len] = '\0';
    return s;
}

static bs_status parse(const char *t, bs_parse_error *err, bs_surface **out)
{
    return bs_surface_read_iges(t, strlen(t), err, out);
}

/* The text fails with BS_ERR_PARSE at (line, column), no surface. */
static void expect_error(const char *t, size_t line, size_t column, const char *what)
{
    bs_parse_error err = {0, 0, ""};
    bs_surface *s = (bs_surface *)&err;
    bs_status st = parse(t, &err, &s);
    CHECKF(st == BS_ERR_PARSE && s == NULL && err.line == line && err.column == column,
           "%s: status %d, at %zu:%zu (expected %zu:%zu): %s", what, st, err.line, err.column, line, column,
           err.message);
}

/* ---- the B-splines used below ---- */
static const double KU[] = {0, 0, 0, 0, 1, 2.5, 2.5, 4, 4, 4, 4}, KV[] = {-1, -1, -1, 0.5, 2, 2, 2};
static double CTRL[7 * 4 * 3], W[7 * 4];

static void make_nets(void)
{
    unsigned long long rng = 42;
    for (size_t k = 0; k < 7 * 4 * 3; k++)
        CTRL[k] = bs_test_rand(&rng, -3.0, 3.0);
    for (size_t k = 0; k < 7 * 4; k++)
        W[k] = bs_test_rand(&rng, 0.3, 3.0);
}

/* A file built here against the same B-spline added directly: identical patches. */
static void test_against_direct(void)
{
    for (int rational = 0; rational < 2; rational++) {
        bs_bspline b = {3, 2, 7, 4, 3, KU, KV, CTRL, rational ? W : NULL};
        double range[4] = {0, 4, -1, 2};
        char *p = params_128(&b, range, ',', ';');
        ent e = {128, p, 0, 0};
        char *t = make_iges(GLOBAL, &e, 1);
        bs_surface *got = NULL, *want = NULL;
        bs_parse_error err;
        CHECK_STATUS(parse(t, &err, &got), BS_OK);
        CHECK_STATUS(bs_surface_create(&want), BS_OK);
        CHECK_STATUS(bs_surface_add_bspline(want, &b, NULL, 0, NULL), BS_OK);
        CHECKF(surface_same_bits(got, want), "rational %d", rational);
        CHECK(bs_surface_count(got) == 3 * 2);
        bs_surface_destroy(got);
        bs_surface_destroy(want);

        /* A sub-range: spans cut where the range ends inside them, the others whole. */
        double sub[4] = {0.5, 3.0, -0.5, 2};
        free(p);
        free(t);
        p = params_128(&b, sub, ',', ';');
        e.params = p;
        t = make_iges(GLOBAL, &e, 1);
        CHECK_STATUS(parse(t, &err, &got), BS_OK);
        CHECK(bs_surface_count(got) == 3 * 2);
        CHECK_STATUS(bs_surface_create(&want), BS_OK);
        double spans[4 * 6];
        CHECK_STATUS(bs_surface_add_bspline(want, &b, spans, 24, NULL), BS_OK);
        double worst = 0;
        for (size_t k = 0; got && k < bs_surface_count(got); k++)
            for (int a = 0; a <= 4; a++)
                for (int c = 0; c <= 4; c++) {
                    /* read patch k covers the span's part inside sub */
                    const double *sp = spans + 4 * k;
                    double u0 = fmax(sp[0], sub[0]), u1 = fmin(sp[1], sub[1]);
                    double v0 = fmax(sp[2], sub[2]), v1 = fmin(sp[3], sub[3]);
                    double u = u0 + (u1 - u0) * a / 4.0, v = v0 + (v1 - v0) * c / 4.0, x[3], y[3];
                    CHECK(patch_point(bs_surface_get(got, k), a / 4.0, c / 4.0, x));
                    CHECK(patch_point(bs_surface_get(want, k), (u - sp[0]) / (sp[1] - sp[0]),
                                      (v - sp[2]) / (sp[3] - sp[2]), y));
                    for (int d = 0; d < 3; d++)
                        worst = fmax(worst, fabs(x[d] - y[d]));
                }
        CHECKF(worst < 1e-12, "sub-range differs by %g", worst);
        CHECK(bs_patch_degree_u(bs_surface_get(got, 0)) == 3 && bs_patch_degree_v(bs_surface_get(got, 0)) == 2);
        bs_surface_destroy(got);
        bs_surface_destroy(want);
        free(p);
        free(t);
    }
}

/* Other delimiters, a Hollerith string holding them, D and d exponents, blanks, defaulted fields, a
 * number split over two records, and two chained transformations. */
static void test_syntax_and_transforms(void)
{
    static const double ku[] = {0, 0, 1, 1}, kv[] = {0, 0, 1, 1}, c[] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    bs_bspline b = {1, 1, 2, 2, 3, ku, kv, c, NULL};
    double range[4] = {0, 1, 0, 1};
    char *p = params_128(&b, range, '/', '!');
    p[strlen(p) - 1] = '\0';
    char p2[512];
    snprintf(p2, sizeof p2, "%s/ /  !", p); /* trailing optional pointer fields, one blank */
    /* the knots 0 0 1 1, 0 0 1 1 and the first weight: blanks and exponents D and d */
    char *d = strstr(p2, "/0/0/1/1/0/0/1/1/1");
    CHECK(d != NULL);
    if (d != NULL)
        memmove(d + 29, d + 18, strlen(d + 18) + 1), memcpy(d, "/ /0d0/1.D0/1/.0/0./0.1d1/1/1", 29);
    ent e[3] = {{128, p2, 3, 0},
                {124, "124/2.0D0/0/0/1/0/2/0/0/0/0/2/0!", 5, 0},
                {124, "124/0/-1/0/0/1/0/0/0/0/0/1/10!", 0, 0}};
    char *t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    bs_surface *s = NULL;
    bs_parse_error err = {0, 0, ""};
    CHECKF(parse(t, &err, &s) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
    CHECK(bs_surface_count(s) == 1);
    double x[3];
    /* (1,1,1) -> first matrix (2x+1, 2y, 2z) -> (3,2,2) -> second (-y, x, z+10) -> (-2,3,12) */
    CHECK(patch_point(bs_surface_get(s, 0), 1.0, 1.0, x) && x[0] == -2.0 && x[1] == 3.0 && x[2] == 12.0);
    CHECK(patch_point(bs_surface_get(s, 0), 0.0, 0.0, x) && x[0] == 0.0 && x[1] == 1.0 && x[2] == 10.0);
    bs_surface_destroy(s);
    free(t);

    /* A circular chain of transformations, and a pointer to an entity that is not a 124. */
    e[2].transform = 3;
    t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    expect_error(t, 7, 49, "circular transformations");
    free(t);
    e[0].transform = 1;
    t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    expect_error(t, 3, 49, "transformation pointer to a 128");
    free(t);
    e[0].transform = 4;
    t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    expect_error(t, 3, 49, "even transformation pointer");
    free(t);
    /* a 124 that maps space onto a point (an all-zero rotation), then onto a plane */
    e[0].transform = 3;
    e[1].transform = 0;
    e[1].params = "124/0/0/0/1/0/0/0/0/0/0/0/0!";
    t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    expect_error(t, 5, 1, "singular"); /* the 124's own directory entry */
    free(t);
    e[1].params = "124/1/2/0/0/2/4/0/0/0/0/1/0!";
    t = make_iges("1H//1H!/9Hx/y!z;,!!/4Htest/1.5D0!", e, 3);
    expect_error(t, 5, 1, "singular"); /* the 124's own directory entry */
    free(t);
    free(p);
}

/* One good file, then each record or field spoiled in turn. */
static void test_errors(void)
{
    static const double ku[] = {0, 0, 1, 1}, kv[] = {0, 0, 0, 1, 1, 1};
    static const double c[] = {0, 0, 0, 0, 1, 0, 0, 2, 1, 1, 0, 0, 1, 1, 0, 1, 2, 1};
    bs_bspline b = {1, 2, 2, 3, 3, ku, kv, c, NULL};
    double range[4] = {0, 1, 0, 1};
    char *p = params_128(&b, range, ',', ';');
    ent e = {128, p, 0, 0};
    char *good = make_iges(GLOBAL, &e, 1);
    /* S on line 1, G on 2-3, D on 4-5, P on 6-7, T on 8 */
    bs_surface *s = NULL;
    CHECK_STATUS(parse(good, NULL, &s), BS_OK);
    CHECK(bs_surface_count(s) == 1);
    bs_surface_destroy(s);
    size_t glen = strlen(good);
    char *t = malloc(glen + 200);
    const size_t L = 81; /* bytes per record */

#define SPOIL(code, line, col, what)       \
    do {                                   \
        memcpy(t, good, glen + 1);         \
        code;                              \
        expect_error(t, line, col, what);  \
    } while (0)
    SPOIL(memmove(t + 60, t + 80, glen - 79), 1, 61, "short record");
    SPOIL((memmove(t + L + 81, t + L + 80, glen - L - 79), t[L + 80] = ' '), 2, 81, "long record");
    SPOIL(t[L + 72] = 'C', 2, 73, "compressed form");
    SPOIL(t[L + 72] = 'X', 2, 73, "unknown section letter");
    SPOIL(t[3 * L + 72] = 'G', 5, 73, "section out of order");
    SPOIL(t[7 * L] = '\0', 8, 1, "missing T");
    SPOIL(memmove(t + L, t + 3 * L, glen - 3 * L + 1), 2, 1, "missing G");
    SPOIL(memmove(t + 4 * L, t + 5 * L, glen - 5 * L + 1), 4, 73, "odd D records");
    SPOIL(memmove(t + 5 * L, t + 7 * L, glen - 7 * L + 1), 6, 1, "missing P");
    SPOIL(t[3 * L + 15] = '9', 4, 9, "P pointer outside");
    SPOIL(t[4 * L + 31] = '7', 5, 25, "P line count outside");
    SPOIL(t[5 * L + 71] = '3', 6, 65, "P record pointing back at DE 3");
    SPOIL(t[6 * L + 71] = ' ', 7, 65, "P record without a back pointer");
    SPOIL(memcpy(t + 4 * L + 38, "12", 2), 5, 33, "form 12");
    SPOIL(t[3 * L + 6] = 'x', 4, 6, "letter in a directory field");
    {
        size_t at = (size_t)(strstr(good + 2 * L, "15H2026") - good);
        SPOIL(t[at] = '9', 3, at - 2 * L + 1, "Hollerith past the section");
    }
    SPOIL(memcpy(t + 5 * L, "126", 3), 6, 1, "type of the parameter data");
    SPOIL(t[5 * L + 4] = '0', 6, 5, "K1 = 0");
    SPOIL(t[5 * L + 8] = '0', 6, 9, "M1 = 0");
    SPOIL(memcpy(t + 5 * L + 10, "70", 2), 6, 11, "M2 = 70");
    SPOIL(t[5 * L + 12] = '2', 6, 13, "PROP1 = 2");
    SPOIL(t[5 * L + 22] = 'z', 6, 23, "knot not a number");
    SPOIL(t[5 * L + 28] = '0', 6, 29, "decreasing knots");
    SPOIL(t[5 * L + 36] = '0', 6, 23, "a knot repeated more than degree + 1 times");
    {
        char *w = strstr(good + 5 * L, ",1,1,1,1,1,1,");
        size_t at = w ? (size_t)(w - good) : 0;
        SPOIL(t[at + 3] = '0', 6, at - 5 * L + 4, "zero weight");
    }
    SPOIL(memcpy(t + 6 * L + strcspn(good + 6 * L, ";"), ",", 1), 7, 65, "no record delimiter");
    SPOIL(memcpy(t + 6 * L + strcspn(good + 6 * L, ";") - 3, "3,1", 3), 7, strcspn(good + 6 * L, ";") - 6,
          "range outside");
    SPOIL(memcpy(t + 5 * L + 2, "8,9999999,9999999", 17), 6, 5, "huge declared counts");
    SPOIL(memcpy(t + 6 * L + strcspn(good + 6 * L, ";") - 4, ";   ", 4), 7, strcspn(good + 6 * L, ";") - 3,
          "parameters end early");
#undef SPOIL
    expect_error("", 1, 1, "empty input");
    bs_parse_error err;
    memcpy(t, good, glen + 1);
    memcpy(t + glen, "\n  \n\x1a", 6); /* blank lines after the T section are fine */
    CHECK_STATUS(bs_surface_read_iges(t, glen + 5, NULL, &s), BS_OK);
    bs_surface_destroy(s);
    memcpy(t + glen, "\nx\n", 4); /* anything else is not */
    CHECK_STATUS(bs_surface_read_iges(t, glen + 3, &err, &s), BS_ERR_PARSE);
    CHECKF(err.line == 10 && err.column == 2, "at %zu:%zu", err.line, err.column);
    memcpy(t, good, glen + 1);
    t[100] = '\0';
    CHECK_STATUS(bs_surface_read_iges(t, glen, &err, &s), BS_ERR_PARSE);
    CHECK(err.line == 2 && err.column == 20 && s == NULL);
    CHECK_STATUS(bs_surface_read_iges(NULL, 0, &err, &s), BS_ERR_PARSE);
    CHECK_STATUS(bs_surface_read_iges(NULL, 1, &err, &s), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_iges(good, glen, &err, NULL), BS_ERR_INVALID_ARG);

    /* Mutated files: any status is a clean BS_OK or BS_ERR_PARSE with a position. */
    unsigned long long rng = 7;
    for (int k = 0; k < 3000; k++) {
        memcpy(t, good, glen + 1);
        size_t n = 1 + bs_test_rand_u64(&rng) % 4, len = glen;
        for (size_t m = 0; m < n; m++)
            t[bs_test_rand_u64(&rng) % glen] = " ,;0123456789.-HDE\nPx"[bs_test_rand_u64(&rng) % 21];
        if (k % 3 == 0)
            len = bs_test_rand_u64(&rng) % glen;
        bs_status st = bs_surface_read_iges(t, len, &err, &s);
        CHECKF(st == BS_OK ? s != NULL : (st == BS_ERR_PARSE && s == NULL && err.line > 0 && err.column > 0),
               "mutation %d: status %d", k, st);
        bs_surface_destroy(s);
    }
    free(t);
    free(good);
    free(p);
}

/* The B-spline of a fixture at full precision, as OpenCASCADE holds it. */
typedef struct occt_bspline {
    bs_bspline b;
    double knots[2][64], ctrl[3 * 64], w[64], scale; /* scale: max|P| wmax/wmin */
    bs_surface *direct;                              /* b added directly */
} occt_bspline;

static int read_bspline(FILE *f, occt_bspline *o)
{
    size_t d[4];
    if (fscanf(f, "%zu %zu %zu %zu", &d[0], &d[1], &d[2], &d[3]) != 4 || d[2] * d[3] > 64 ||
        d[2] + d[0] + 1 > 64 || d[3] + d[1] + 1 > 64)
        return 0;
    for (int k = 0; k < 2; k++)
        for (size_t j = 0; j < d[2 + k] + d[k] + 1; j++)
            if (fscanf(f, "%lf", &o->knots[k][j]) != 1)
                return 0;
    double pmax = 0, wmin = INFINITY, wmax = 0;
    char word[16];
    for (size_t j = 0; j < d[2] * d[3]; j++) {
        double *c = o->ctrl + 3 * j;
        if (fscanf(f, "%15s %lf %lf %lf %lf", word, &c[0], &c[1], &c[2], &o->w[j]) != 5 || strcmp(word, "pole") != 0)
            return 0;
        pmax = fmax(pmax, fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2]))));
        wmin = fmin(wmin, o->w[j]);
        wmax = fmax(wmax, o->w[j]);
    }
    o->b = (bs_bspline){d[0], d[1], d[2], d[3], 3, o->knots[0], o->knots[1], o->ctrl, o->w};
    o->scale = pmax * wmax / wmin;
    bs_surface_destroy(o->direct);
    o->direct = NULL;
    return bs_surface_create(&o->direct) == BS_OK && bs_surface_add_bspline(o->direct, &o->b, NULL, 0, NULL) == BS_OK;
}

/* The files OpenCASCADE wrote, against the points it computed (tests/io/occt_iges_gen.cpp): the
 * patches read from the file (9 digits) within tol, and the same B-spline at full precision
 * added directly within 1e-13 of its size (the contract of bs_surface_add_bspline). */
static void test_fixture(const char *name, double tol)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.igs", FIXTURES, name);
    bs_surface *s = NULL;
    bs_parse_error err = {0, 0, ""};
    CHECKF(bs_surface_read_iges_file(path, &err, &s) == BS_OK, "%s: %zu:%zu %s", name, err.line, err.column,
           err.message);
    snprintf(path, sizeof path, "%s/%s.txt", FIXTURES, name);
    FILE *f = fopen(path, "r");
    CHECKF(f != NULL && s != NULL, "%s", path);
    if (f == NULL || s == NULL) {
        bs_surface_destroy(s);
        if (f)
            fclose(f);
        return;
    }
    char word[16];
    size_t first = 0, nb[2] = {0, 0}, points = 0;
    double br[2][32], worst = 0, worst_direct = 0;
    occt_bspline o = {.direct = NULL};
    while (fscanf(f, "%15s", word) == 1) {
        if (strcmp(word, "surface") == 0) {
            first += (nb[0] ? nb[0] - 1 : 0) * (nb[1] ? nb[1] - 1 : 0);
            CHECK(fscanf(f, "%zu %zu", &nb[0], &nb[1]) == 2 && nb[0] <= 32 && nb[1] <= 32);
            for (int d = 0; d < 2; d++)
                for (size_t k = 0; k < nb[d]; k++)
                    CHECK(fscanf(f, "%lf", &br[d][k]) == 1);
            continue;
        }
        if (strcmp(word, "bspline") == 0) {
            CHECKF(read_bspline(f, &o), "%s: the B-spline", name);
            continue;
        }
        double u, v, ref[3], x[3], lu, lv;
        CHECK(fscanf(f, "%lf %lf %lf %lf %lf", &u, &v, &ref[0], &ref[1], &ref[2]) == 5);
        size_t a = 0, b = 0, index = 0;
        while (a + 2 < nb[0] && u >= br[0][a + 1])
            a++;
        while (b + 2 < nb[1] && v >= br[1][b + 1])
            b++;
        lu = (u - br[0][a]) / (br[0][a + 1] - br[0][a]);
        lv = (v - br[1][b]) / (br[1][b + 1] - br[1][b]);
        CHECK(patch_point(bs_surface_get(s, first + a * (nb[1] - 1) + b), lu, lv, x));
        for (int d = 0; d < 3; d++)
            worst = fmax(worst, fabs(x[d] - ref[d]));
        CHECK(o.direct && bs_bspline_locate(&o.b, u, v, &index, &lu, &lv) == BS_OK &&
              patch_point(bs_surface_get(o.direct, index), lu, lv, x));
        for (int d = 0; d < 3; d++)
            worst_direct = fmax(worst_direct, fabs(x[d] - ref[d]) / o.scale);
        points++;
    }
    fclose(f);
    bs_surface_destroy(o.direct);
    first += (nb[0] - 1) * (nb[1] - 1);
    CHECKF(bs_surface_count(s) == first, "%s: %zu patches, %zu expected", name, bs_surface_count(s), first);
    CHECKF(points >= 49 && worst <= tol, "%s: %zu points, worst deviation %g", name, points, worst);
    CHECKF(worst_direct <= 1e-13, "%s: the B-spline added directly deviates by %g of its size", name, worst_direct);
    printf("%s: %zu patches, %zu points; from the file: worst deviation from OpenCASCADE %.3g; the B-spline "
           "added directly: %.3g of its size\n",
           name, first, points, worst, worst_direct);
    bs_surface_destroy(s);
}

/* The cylinder file: every point at radius 2 (to the 9 digits OpenCASCADE writes). */
static void test_cylinder(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_read_iges_file(FIXTURES "/nurbs_cylinder.igs", NULL, &s), BS_OK);
    double worst = 0;
    for (int a = 0; s && a <= 20; a++)
        for (int b = 0; b <= 4; b++) {
            double x[3];
            CHECK(patch_point(bs_surface_get(s, 0), a / 20.0, b / 4.0, x));
            worst = fmax(worst, fabs(hypot(x[0], x[1]) - 2.0));
        }
    CHECKF(s && bs_patch_is_rational(bs_surface_get(s, 0)) && worst < 1e-9, "radius off by %g", worst);
    printf("nurbs_cylinder: radius 2 within %.3g\n", worst);
    bs_surface_destroy(s);
}

/* Under a decimal-comma locale the same file gives the same bits. */
static void test_locale(void)
{
    bs_surface *a = NULL, *b = NULL;
    CHECK_STATUS(bs_surface_read_iges_file(FIXTURES "/bicubic_knots.igs", NULL, &a), BS_OK);
    const char *found = switch_to_comma_locale();
    if (found == NULL) {
        printf("test_iges: locale part skipped, no locale with a decimal comma\n");
    } else {
        CHECK_STATUS(bs_surface_read_iges_file(FIXTURES "/bicubic_knots.igs", NULL, &b), BS_OK);
        CHECKF(surface_same_bits(a, b), "under %s", found);
        setlocale(LC_ALL, "C");
    }
    bs_surface_destroy(a);
    bs_surface_destroy(b);
}

static void test_files(void)
{
    bs_surface *s = (bs_surface *)&s;
    bs_parse_error err;
    CHECK_STATUS(bs_surface_read_iges_file("/nonexistent-directory/x.igs", &err, &s), BS_ERR_IO);
    CHECK(s == NULL && err.line == 0);
    CHECK_STATUS(bs_surface_read_iges_file(NULL, &err, &s), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_iges_file(FIXTURES "/transformed.igs", &err, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_iges_file(FIXTURES "/transformed.txt", &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && err.line == 1);
}

/* A file without a 128 is an error naming what it holds: trimmed surfaces go to bs_model_read_iges. */
static void test_no_bspline(void)
{
    static const ent trimmed[] = {{144, "144,3,1,0,5;", 0, 0}, {108, "108,0.,0.,1.,0.,0,0.,0.,0.,0.;", 0, 0},
                                  {110, "110,0.,0.,0.,1.,0.,0.;", 0, 0}};
    bs_surface *s = (bs_surface *)&s;
    bs_parse_error err;
    char *t = make_iges(GLOBAL, trimmed, 3);
    CHECK_STATUS(bs_surface_read_iges(t, strlen(t), &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && err.line == 4 && err.column == 1 &&
          strcmp(err.message, "no 128 surface: the file holds 1 trimmed surfaces (144); read it with "
                              "bs_model_read_iges") == 0);
    free(t);
    t = make_iges(GLOBAL, trimmed + 2, 1);
    CHECK_STATUS(bs_surface_read_iges(t, strlen(t), &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && strcmp(err.message, "no untrimmed B-spline surface (128) among the 1 entities") == 0);
    free(t);
}

/* tests/hostile/iges_deg64_amp_10.igs: 36 KB of degree-64 B-spline spans, 100 patches of 4,225
 * points: refused by both IGES readers before any span is converted. */
static void test_amplified(void)
{
    const char *path = BS_TEST_SOURCE_DIR "/../hostile/iges_deg64_amp_10.igs";
    bs_surface *s = (bs_surface *)&s;
    bs_model *m = (bs_model *)&m;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    CHECK_STATUS(bs_surface_read_iges_file(path, &err, &s), BS_ERR_SIZE);
    CHECKF(s == NULL && strstr(err.message, "4 per byte") != NULL, "%s", err.message);
    memset(&err, 0, sizeof err);
    CHECK_STATUS(bs_model_read_iges_file(path, &err, &m), BS_ERR_SIZE);
    CHECKF(m == NULL && strstr(err.message, "4 per byte") != NULL, "%s", err.message);
}

/* `entries` directory entries of entity 128 that all point at one entity's P records, whose back
 * pointers name DE 1. */
static char *shared_iges(const char *params, size_t entries)
{
    text t = {NULL, 0, 0};
    size_t seq_s = 0, seq_g = 0, seq_d = 0, seq_p = 0, lines = (strlen(params) + 63) / 64;
    put_lines(&t, "built by test_iges", 72, "", 'S', &seq_s);
    put_lines(&t, GLOBAL, 72, "", 'G', &seq_g);
    for (size_t k = 0; k < entries; k++) {
        char d[96];
        (void)snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", 128, 1, 0, 0, 0, 0, 0, 0, "00000000");
        put_lines(&t, d, 72, "", 'D', &seq_d);
        (void)snprintf(d, sizeof d, "%8d%8d%8d%8zu%8d%8s%8s%8s%8d", 128, 0, 0, lines, 0, "", "", "", 0);
        put_lines(&t, d, 72, "", 'D', &seq_d);
    }
    put_lines(&t, params, 64, "       1", 'P', &seq_p);
    char term[80];
    (void)snprintf(term, sizeof term, "S%07zuG%07zuD%07zuP%07zu", seq_s, seq_g, seq_d, seq_p);
    put_lines(&t, term, 72, "", 'T', &(size_t){0});
    return t.buf;
}

/* Both readers refuse the text at the back pointer of DE 3's first P record (line). */
static void expect_shared_refused(const char *t, size_t line, const char *what)
{
    bs_parse_error err = {0, 0, ""};
    bs_surface *s = (bs_surface *)&err;
    bs_model *m = (bs_model *)&err;
    bs_status st = parse(t, &err, &s);
    CHECKF(st == BS_ERR_PARSE && s == NULL && err.line == line && err.column == 65 &&
               strcmp(err.message, "P record's back pointer is not DE 3") == 0,
           "%s: status %d at %zu:%zu: %s", what, st, err.line, err.column, err.message);
    bs_surface_destroy(st == BS_OK ? s : NULL);
    st = bs_model_read_iges(t, strlen(t), &err, &m);
    CHECKF(st == BS_ERR_PARSE && m == NULL && err.line == line && err.column == 65 &&
               strcmp(err.message, "entity 128 (DE 3): P record's back pointer is not DE 3") == 0,
           "%s (model): status %d at %zu:%zu: %s", what, st, err.line, err.column, err.message);
}

/* Parameter data shared by many directory entries would be parsed once per entry: an entity
 * padded with 500,000 blanks under 100 entries (650 KB, 50 MB of blanks to scan; 5.6 MB of these
 * took 66 s) and a 100 x 100 linear B-spline under 200 entries (157 KB once made 1.9 million
 * patches) are refused at the second entry. The padded entity alone reads. */
static void test_shared_parameters(void)
{
    static const char head[] = "128,1,1,1,1,0,0,1,0,0,",
                      tail[] = "0,0,1,1,0,0,1,1,1,1,1,1,0,0,0,1,0,0,0,1,0,1,1,1,0,1,0,1;";
    size_t pad = 500000, n = 100;
    char *params = malloc(sizeof head + pad + sizeof tail);
    memcpy(params, head, sizeof head - 1);
    memset(params + sizeof head - 1, ' ', pad);
    memcpy(params + sizeof head - 1 + pad, tail, sizeof tail);
    char *t = shared_iges(params, 1);
    bs_surface *s = NULL;
    CHECK_STATUS(parse(t, NULL, &s), BS_OK);
    CHECK(s != NULL && bs_surface_count(s) == 1);
    bs_surface_destroy(s);
    free(t);
    t = shared_iges(params, n);
    expect_shared_refused(t, 1 + 2 + 2 * n + 1, "blank-padded entity under 100 entries");
    free(t);
    free(params);
    enum { C = 100 };
    double knots[C + 2], *ctrl = malloc(3 * C * C * sizeof *ctrl), range[4] = {0, C - 1, 0, C - 1};
    for (size_t k = 0; k < C + 2; k++)
        knots[k] = k == 0 ? 0.0 : k > C ? (double)(C - 1) : (double)(k - 1);
    for (size_t i = 0; i < C * C; i++) {
        ctrl[3 * i] = (double)(i / C);
        ctrl[3 * i + 1] = (double)(i % C);
        ctrl[3 * i + 2] = (double)(i / C * (i % C) % 3);
    }
    bs_bspline b = {1, 1, C, C, 3, knots, knots, ctrl, NULL};
    params = params_128(&b, range, ',', ';');
    t = shared_iges(params, 200);
    expect_shared_refused(t, 1 + 2 + 2 * 200 + 1, "100 x 100 B-spline under 200 entries");
    free(t);
    free(params);
    free(ctrl);
}

int main(void)
{
    make_nets();
    test_against_direct();
    test_syntax_and_transforms();
    test_errors();
    test_fixture("nurbs_cylinder", 1e-8);
    test_fixture("bicubic_knots", 1e-8);
    test_fixture("transformed", 1e-8);
    test_fixture("subrange", 1e-8);
    test_fixture("trimmed_face", 1e-8);
    test_cylinder();
    test_locale();
    test_files();
    test_no_bspline();
    test_amplified();
    test_shared_parameters();
    return bs_test_exit("test_iges");
}
