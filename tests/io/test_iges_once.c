/* Each directory entry's parameter data is parsed at most once per read, by both IGES readers:
 * bsi_iges_open, which every parse of an entity starts with, is wrapped (-Wl,--wrap) to count the
 * openings of each entry and the P records they span. A 124 padded with blanks (and chained to a
 * second) under 300 128s was parsed once per 128 by bs_surface_read_iges (1.1 to 1.2): 300 x its
 * 1,563 records. The CAD parts of data/cad/ are read the same way by the model reader. */
#include "harness.h"
#include "surface_check.h"

#include "io/iges.h"

#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bs_status __real_bsi_iges_open(const iges *g, size_t de, iges_stream *s);
bs_status __wrap_bsi_iges_open(const iges *g, size_t de, iges_stream *s);

enum { MAX_DE = 4096 };
static unsigned opens[MAX_DE]; /* openings of the entry at each D record */
static size_t scanned;         /* P records of all openings */

bs_status __wrap_bsi_iges_open(const iges *g, size_t de, iges_stream *s)
{
    bs_status st = __real_bsi_iges_open(g, de, s);
    if (de < MAX_DE)
        opens[de]++;
    if (st == BS_OK)
        scanned += s->nrec;
    return st;
}

static void reset(void)
{
    memset(opens, 0, sizeof opens);
    scanned = 0;
}

/* No entry opened twice, and no more P records scanned than the file has (p). */
static void expect_once(size_t p, const char *what)
{
    size_t worst = 0, at = 0;
    for (size_t k = 0; k < MAX_DE; k++)
        if (opens[k] > worst)
            worst = opens[k], at = k + 1;
    CHECKF(worst <= 1 && scanned <= p, "%s: DE %zu opened %zu times, %zu P records scanned of %zu", what, at, worst,
           scanned, p);
}

static void put(char *buf, size_t *len, const char *data, char letter, size_t seq, size_t width, size_t back)
{
    char line[96];
    if (back != 0)
        (void)snprintf(line, sizeof line, "%-64.64s %7zu%c%07zu\n", data, back, letter, seq);
    else
        (void)snprintf(line, sizeof line, "%-*.*s%c%07zu\n", (int)width, (int)width, data, letter, seq);
    memcpy(buf + *len, line, 82); /* 80 columns, the newline, the terminating NUL */
    *len += 81;
}

/* A file of n 128s (independent: status 0) pointing at a 124 padded with `pad` blanks, which
 * points at a second 124; *p: its number of P records. */
static char *padded_file(size_t pad, size_t n, size_t *p)
{
    static const char g[] = "1H,,1H;,4Htest,8Htest.igs,4Htest,4Htest,32,308,15,308,15,,1.,2,2HMM;";
    static const char b[] = "128,1,1,1,1,0,0,1,0,0,0,0,1,1,0,0,1,1,1,1,1,1,0,0,0,1,0,0,0,1,0,1,1,1,0,1,0,1;";
    char *m1 = malloc(pad + 64);
    const char *m2 = "124,1,0,0,10,0,1,0,0,0,0,1,0;";
    (void)snprintf(m1, 8, "124,");
    memset(m1 + 4, ' ', pad);
    strcpy(m1 + 4 + pad, "2,0,0,0,0,2,0,0,0,0,2,1;");
    const char *params[3] = {m1, m2, b};
    size_t lines[3], ent = n + 2;
    for (size_t k = 0; k < 3; k++)
        lines[k] = (strlen(params[k]) + 63) / 64;
    *p = lines[0] + lines[1] + n * lines[2];
    char *buf = malloc(81 * (3 + 2 * ent + *p) + 1), d[96];
    size_t len = 0, seq = 0, first = 1;
    put(buf, &len, "built by test_iges_once", 'S', 1, 72, 0);
    put(buf, &len, g, 'G', 1, 72, 0);
    for (size_t e = 0; e < ent; e++) {
        size_t k = e < 2 ? e : 2;
        int type = k < 2 ? 124 : 128, tr = k == 0 ? 3 : k == 1 ? 0 : 1;
        (void)snprintf(d, sizeof d, "%8d%8zu%8d%8d%8d%8d%8d%8d%8s", type, first, 0, 0, 0, 0, tr, 0, "00000000");
        put(buf, &len, d, 'D', 2 * e + 1, 72, 0);
        (void)snprintf(d, sizeof d, "%8d%8d%8d%8zu%8d%8s%8s%8s%8d", type, 0, 0, lines[k], 0, "", "", "", 0);
        put(buf, &len, d, 'D', 2 * e + 2, 72, 0);
        first += lines[k];
    }
    for (size_t e = 0; e < ent; e++) {
        const char *s = params[e < 2 ? e : 2];
        for (size_t r = 0; r < lines[e < 2 ? e : 2]; r++) {
            put(buf, &len, s + 64 * r, 'P', ++seq, 64, 2 * e + 1);
        }
    }
    (void)snprintf(d, sizeof d, "S%07dG%07dD%07zuP%07zu", 1, 1, 2 * ent, *p);
    put(buf, &len, d, 'T', 1, 72, 0);
    free(m1);
    return buf;
}

static void test_shared_124(void)
{
    size_t p, n = 300;
    char *t = padded_file(100000, n, &p);
    bs_parse_error err = {0, 0, ""};
    bs_surface *s = NULL;
    reset();
    CHECKF(bs_surface_read_iges(t, strlen(t), &err, &s) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
    CHECK(bs_surface_count(s) == n);
    expect_once(p, "bs_surface_read_iges");
    /* corner (1, 1, 1): the 128's 124 (2x, 2y, 2z + 1), then the one it points at (x + 10) */
    double x[3] = {0, 0, 0};
    for (size_t k = 0; k < n; k += n - 1)
        CHECK(patch_point(bs_surface_get(s, k), 1.0, 1.0, x) && x[0] == 12.0 && x[1] == 2.0 &&
              x[2] == 3.0);
    bs_surface_destroy(s);
    bs_model *m = NULL;
    reset();
    CHECKF(bs_model_read_iges(t, strlen(t), &err, &m) == BS_OK, "%zu:%zu %s", err.line, err.column, err.message);
    CHECK(bs_model_face_count(m) == n);
    expect_once(p, "bs_model_read_iges");
    bs_model_destroy(m);
    free(t);
}

/* The CAD parts: curves shared by 142s and 504 edge lists, surfaces by faces, each parsed once. */
static void test_cad(void)
{
    static const char *const names[] = {"bell", "block", "bottle", "cone", "duct", "sphere", "torus", "wedge"};
    for (size_t k = 0; k < 2 * sizeof names / sizeof names[0]; k++) {
        char path[256];
        (void)snprintf(path, sizeof path, "%s/%s%s.igs", BS_CAD_DIR, names[k / 2], k % 2 ? "-brep" : "");
        bs_model *m = NULL;
        bs_parse_error err = {0, 0, ""};
        reset();
        CHECKF(bs_model_read_iges_file(path, &err, &m) == BS_OK, "%s: %s", path, err.message);
        expect_once((size_t)-1, path);
        bs_model_destroy(m);
    }
}

int main(void)
{
    test_shared_124();
    test_cad();
    return bs_test_exit("test_iges_once");
}
