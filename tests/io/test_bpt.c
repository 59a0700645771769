/* The .bpt reader and writer: exact round trips, parse errors at known positions, hostile inputs
 * (truncated, garbage, absurd counts, random and mutated bytes), memory and file interfaces. */
#include "harness.h"
#include "bpt_oracle.h"
#include "surface_check.h"

#include <bezsurf.h>

#include <float.h>
#include <string.h>

static bs_status parse(const char *text, bs_parse_error *err, bs_surface **out)
{
    return bs_surface_read_bpt(text, strlen(text), err, out);
}

/* Write s to memory, read it back, compare bit for bit. */
static int round_trips(const bs_surface *s)
{
    size_t size = 0;
    if (bs_surface_write_bpt(s, NULL, 0, &size) != BS_OK || size == 0)
        return 0;
    char *buf = malloc(size);
    size_t size2 = 0;
    int ok = buf && bs_surface_write_bpt(s, buf, size, &size2) == BS_OK && size2 == size &&
             buf[size - 1] == '\0' && strlen(buf) == size - 1;
    /* the size the writer reports, final NUL included, is what a user passes back (1.2); the
     * text without its NUL reads the same */
    bs_surface *back = NULL, *back2 = NULL;
    ok = ok && bs_surface_read_bpt(buf, size, NULL, &back) == BS_OK && surface_same_bits(s, back);
    ok = ok && bs_surface_read_bpt(buf, size - 1, NULL, &back2) == BS_OK && surface_same_bits(s, back2);
    bs_surface_destroy(back);
    bs_surface_destroy(back2);
    free(buf);
    return ok;
}

static void test_data_files(void)
{
    static const char *const names[] = {"teapot", "teacup", "teaspoon"};
    for (size_t f = 0; f < 3; f++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.bpt", BS_DATA_DIR, names[f]);
        size_t len = 0;
        char *text = oracle_slurp(path, &len);
        CHECKF(text != NULL, "%s", path);
        if (text == NULL)
            continue;
        static oracle_bpt o;
        CHECK(oracle_parse(text, &o));
        bs_surface *s = NULL, *b = NULL, *fromfile = NULL;
        bs_parse_error err;
        CHECK_STATUS(bs_surface_read_bpt(text, len, &err, &s), BS_OK);
        CHECK_STATUS(bs_surface_read_bpt_file(path, &err, &fromfile), BS_OK);
        CHECK_STATUS(bs_surface_create_builtin(names[f], &b), BS_OK);
        CHECK(surface_same_bits(s, fromfile) && surface_same_bits(s, b));
        CHECK(bs_surface_count(s) == o.npatch && bs_surface_dim(s) == 3);
        /* Every coordinate as strtod reads it in the C locale. */
        int exact = 1;
        for (size_t k = 0; k < o.npatch && k < bs_surface_count(s); k++) {
            double c[48];
            const bs_patch *p = bs_surface_get(s, k);
            exact &= bs_patch_degree_u(p) == o.deg[k][0] && bs_patch_degree_v(p) == o.deg[k][1];
            exact &= bs_patch_get_ctrl(p, c, 48, NULL, 0) == BS_OK && memcmp(c, o.ctrl[k], sizeof c) == 0;
        }
        CHECKF(exact, "%s: control points differ from strtod's", names[f]);
        CHECKF(round_trips(s), "%s does not round-trip", names[f]);
        /* Through a file as well. */
        CHECK_STATUS(bs_surface_write_bpt_file(s, "test_bpt_out.bpt"), BS_OK);
        bs_surface *again = NULL;
        CHECK_STATUS(bs_surface_read_bpt_file("test_bpt_out.bpt", NULL, &again), BS_OK);
        CHECK(surface_same_bits(s, again));
        remove("test_bpt_out.bpt");
        bs_surface_destroy(again);
        bs_surface_destroy(s);
        bs_surface_destroy(b);
        bs_surface_destroy(fromfile);
        free(text);
    }
}

/* Numbers: the compiler's own conversions of the same literals are the reference. */
static void test_numbers(void)
{
    static const struct { const char *text; double value; } cases[] = {
        {"0.1", 0.1}, {"2.4", 2.4}, {"-0.784", -0.784}, {"1e23", 1e23}, {"8.5E-3", 8.5e-3},
        {"+7", 7.0}, {".5", .5}, {"5.", 5.}, {"4.9e-324", 4.9e-324}, {"2.2250738585072011e-308", 2.2250738585072011e-308},
        {"1.7976931348623157e308", DBL_MAX}, {"9007199254740993", 9007199254740993.0},
        {"123456789012345678901234567890", 123456789012345678901234567890.0},
        {"0.30000000000000004", 0.30000000000000004}, {"-0", -0.0}, {"1e-400", 0.0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[160];
        snprintf(text, sizeof text, "1\n0 0\n%s 0 0\n", cases[k].text);
        bs_surface *s = NULL;
        CHECK_STATUS(parse(text, NULL, &s), BS_OK);
        double c[3] = {1, 1, 1};
        if (s)
            bs_patch_get_ctrl(bs_surface_get(s, 0), c, 3, NULL, 0);
        CHECKF(memcmp(&c[0], &cases[k].value, sizeof(double)) == 0, "%s read as %.17g", cases[k].text, c[0]);
        bs_surface_destroy(s);
    }
    /* A number is at most 400 characters (docs/bpt-format.md): "000...0.25" of exactly 400 reads
     * as 0.25, one of 401 is a parse error at its first character that says why. */
    for (size_t len = 400; len <= 401; len++) {
        char text[512] = "1\n0 0\n";
        size_t at = strlen(text);
        memset(text + at, '0', len);
        memcpy(text + at + len - 3, ".25", 3);
        strcpy(text + at + len, " 0 0\n");
        bs_surface *s = NULL;
        bs_parse_error err;
        memset(&err, 0, sizeof err);
        bs_status st = parse(text, &err, &s);
        double c[3] = {1, 1, 1};
        if (s)
            bs_patch_get_ctrl(bs_surface_get(s, 0), c, 3, NULL, 0);
        if (len == 400)
            CHECKF(st == BS_OK && c[0] == 0.25, "400 characters: status %d, %g", st, c[0]);
        else
            CHECKF(st == BS_ERR_PARSE && err.line == 3 && err.column == 1 &&
                       strstr(err.message, "longer than 400 characters") != NULL,
                   "401 characters: status %d at %zu:%zu: %s", st, err.line, err.column, err.message);
        bs_surface_destroy(s);
    }
    /* Random finite doubles of every magnitude (random bit patterns) survive write + read. */
    unsigned long long seed = 12345;
    int all = 1;
    for (int t = 0; t < 20000; t++) {
        unsigned long long bits = bs_test_rand_u64(&seed);
        double x;
        memcpy(&x, &bits, sizeof x);
        if (x != x || x - x != 0.0)
            continue;
        double ctrl[3] = {x, -x, x / 3};
        bs_patch *p;
        bs_surface *s;
        if (bs_patch_create(0, 0, 3, ctrl, NULL, &p) != BS_OK || bs_surface_create(&s) != BS_OK)
            continue;
        bs_surface_add(s, p, NULL);
        all &= round_trips(s);
        bs_patch_destroy(p);
        bs_surface_destroy(s);
    }
    CHECK(all);
}

/* Inputs that must fail with BS_ERR_PARSE at a known line and column. */
static void test_errors(void)
{
    static const struct { const char *text; size_t line, column; const char *word; } cases[] = {
        {"", 1, 1, "end of input"},
        {"   \n  ", 2, 3, "end of input"},
        {"-1\n", 1, 1, "negative"},
        {"x\n", 1, 1, "integer"},
        {"1.0\n0 0\n1 2 3\n", 1, 1, "integer"},
        {"99999999999999999999999\n", 1, 1, "too large"},
        {"5\n0 0\n1 2 3\n", 1, 1, "more than the input"},
        {"\n\n  4000000000 0 0 1 2 3", 3, 3, "more than the input"},
        {"1\n3 3\n", 3, 1, "end of input"},
        {"1\n3 3\n1 2 3\n", 4, 1, "end of input"},
        {"1\n65 1\n", 2, 1, "too large"},
        {"1\n1 -2\n", 2, 3, "negative"},
        {"1\n-0 1\n", 2, 1, "negative degree in u"},
        {"-09\n", 1, 1, "negative the patch count"},
        {"1\n0 0\n1 2 x\n", 3, 5, "number"},
        {"1\n0 0\n1 nan 3\n", 3, 3, "number"},
        {"1\n0 0\n1 inf 3\n", 3, 3, "number"},
        {"1\n0 0\n1 1e999 3\n", 3, 3, "out of range"},
        {"1\n0 0\n1,5 2 3\n", 3, 1, "number"},
        {"1\n0 0\n0x1p3 2 3\n", 3, 1, "number"},
        {"1\n0 0\n1e 2 3\n", 3, 1, "number"},
        {"1\n0 0\n1 2 3\nfoo\n", 4, 1, "after the last patch"},
        {"1\n0 0\n1 2 3 4\n", 3, 7, "after the last patch"},
        {"1\n0 0 w\n1 2 3 0\n", 3, 7, "positive"},
        {"1\n0 0 w\n1 2 3 -1\n", 3, 7, "positive"},
        {"1\n0 0 w\n1 2 3\n", 4, 1, "end of input"},
        {"1\r\n0 0\r\n\t1 2 3 @\r\n", 3, 8, "after the last patch"},
        {"1\n0 0 w\n1e300 2 3 1e300\n", 2, 1, "overflows"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        bs_parse_error err = {0, 0, ""};
        bs_surface *s = (bs_surface *)&err;
        bs_status st = parse(cases[k].text, &err, &s);
        CHECKF(st == BS_ERR_PARSE && s == NULL, "case %zu: status %d", k, st);
        CHECKF(err.line == cases[k].line && err.column == cases[k].column,
               "case %zu: at %zu:%zu, expected %zu:%zu (%s)", k, err.line, err.column, cases[k].line,
               cases[k].column, err.message);
        CHECKF(strstr(err.message, cases[k].word) != NULL, "case %zu: message '%s'", k, err.message);
    }
    /* A NUL byte inside the text is an error, not an end. */
    bs_parse_error err;
    bs_surface *s;
    CHECK_STATUS(bs_surface_read_bpt("1\n0 0\n1 2\0 3\n", 13, &err, &s), BS_ERR_PARSE);
    CHECK(err.line == 3 && err.column == 3);
    /* The length is honoured: the same bytes cut short are truncated. */
    const char *ok = "1\n0 0\n1 2 3\n";
    CHECK_STATUS(bs_surface_read_bpt(ok, 10, &err, &s), BS_ERR_PARSE);
    CHECK_STATUS(bs_surface_read_bpt(ok, strlen(ok), &err, &s), BS_OK);
    bs_surface_destroy(s);
    /* One final NUL (the writer's size counts it) is the end of the text; two are an error. */
    CHECK_STATUS(bs_surface_read_bpt(ok, strlen(ok) + 1, &err, &s), BS_OK);
    CHECK(s != NULL && bs_surface_count(s) == 1);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_surface_read_bpt("0\n\0", 3, &err, &s), BS_OK);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_surface_read_bpt("\0", 1, &err, &s), BS_ERR_PARSE); /* nothing before it: no count */
    CHECK_STATUS(bs_surface_read_bpt("1\n0 0\n1 2 3\n\0\0", 14, &err, &s), BS_ERR_PARSE);
    CHECK(s == NULL && err.line == 4 && err.column == 1);
    /* Whitespace of every kind, a rational patch, an empty surface. */
    CHECK_STATUS(parse("\t1\r\n0\v1\fw 1 2 3 0.5\n4 5 6 2", NULL, &s), BS_OK);
    CHECK(s && bs_surface_count(s) == 1 && bs_patch_is_rational(bs_surface_get(s, 0)));
    CHECK(s && round_trips(s));
    bs_surface_destroy(s);
    CHECK_STATUS(parse("0", NULL, &s), BS_OK);
    CHECK(s && bs_surface_count(s) == 0 && round_trips(s));
    bs_surface_destroy(s);
    /* Arguments. */
    CHECK_STATUS(bs_surface_read_bpt(ok, 5, NULL, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_read_bpt(NULL, 5, NULL, &s), BS_ERR_INVALID_ARG);
    CHECK(s == NULL);
    CHECK_STATUS(bs_surface_read_bpt(NULL, 0, NULL, &s), BS_ERR_PARSE);
    CHECK_STATUS(bs_surface_read_bpt_file(NULL, NULL, &s), BS_ERR_INVALID_ARG);
    err.line = 7;
    CHECK_STATUS(bs_surface_read_bpt_file("no/such/dir/file.bpt", &err, &s), BS_ERR_IO);
    CHECK(s == NULL && err.line == 0 && err.column == 0);
}

static void test_writer_args(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teacup", &s), BS_OK);
    size_t size = 0;
    CHECK_STATUS(bs_surface_write_bpt(s, NULL, 0, &size), BS_OK);
    char *buf = malloc(size);
    memset(buf, 'Q', size);
    size_t got = 12345;
    CHECK_STATUS(bs_surface_write_bpt(s, buf, size - 1, &got), BS_ERR_SIZE);
    CHECK(got == 12345 && buf[0] == 'Q' && buf[size - 2] == 'Q');
    CHECK_STATUS(bs_surface_write_bpt(s, buf, size, &got), BS_OK);
    CHECK(got == size && buf[size - 1] == '\0' && strncmp(buf, "26\n3 3\n", 7) == 0);
    free(buf);
    CHECK_STATUS(bs_surface_write_bpt(NULL, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_bpt(s, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_bpt_file(s, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_bpt_file(NULL, "x.bpt"), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_write_bpt_file(s, "no/such/dir/out.bpt"), BS_ERR_IO);
    bs_surface_destroy(s);
    /* Only 3-D patches have a .bpt form. */
    double net2[2] = {1, 2};
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(0, 0, 2, net2, NULL, &p), BS_OK);
    bs_surface_create(&s);
    bs_surface_add(s, p, NULL);
    CHECK_STATUS(bs_surface_write_bpt(s, NULL, 0, &size), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_write_bpt_file(s, "x.bpt"), BS_ERR_DIMENSION);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
    /* Built-in names. */
    CHECK(strcmp(bs_builtin_name(0), "teapot") == 0 && strcmp(bs_builtin_name(1), "teacup") == 0 &&
          strcmp(bs_builtin_name(2), "teaspoon") == 0 && bs_builtin_name(3) == NULL);
    s = (bs_surface *)&p;
    CHECK_STATUS(bs_surface_create_builtin("Teapot", &s), BS_ERR_INVALID_ARG);
    CHECK(s == NULL);
    CHECK_STATUS(bs_surface_create_builtin(NULL, &s), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_create_builtin("teapot", NULL), BS_ERR_INVALID_ARG);
}

/* Random and mutated inputs: never a crash (the sanitizer build checks memory), and whatever is
 * accepted must round-trip. */
static void test_hostile(void)
{
    unsigned long long seed = 777;
    bs_surface *tea;
    bs_surface_create_builtin("teaspoon", &tea);
    size_t size;
    bs_surface_write_bpt(tea, NULL, 0, &size);
    char *orig = malloc(size), *buf = malloc(size + 64);
    bs_surface_write_bpt(tea, orig, size, &size);
    bs_surface_destroy(tea);
    size_t len0 = size - 1, accepted = 0, rejected = 0;
    int consistent = 1;
    for (int t = 0; t < 3000; t++) {
        memcpy(buf, orig, len0);
        size_t len = len0;
        int nmut = 1 + (int)(bs_test_rand_u64(&seed) % 4);
        for (int m = 0; m < nmut; m++) {
            size_t at = (size_t)(bs_test_rand_u64(&seed) % len);
            static const char alphabet[] = "0123456789 \n.-+eEw\0x";
            char c = alphabet[bs_test_rand_u64(&seed) % (sizeof alphabet - 1)];
            switch (bs_test_rand_u64(&seed) % 4) {
            case 0: buf[at] = c; break;                                          /* replace */
            case 1: len = at; break;                                             /* truncate */
            case 2: memmove(buf + at, buf + at + 1, len - at - 1); len--; break; /* delete */
            default: memmove(buf + at + 1, buf + at, len - at); buf[at] = c; len++; break;
            }
            if (len == 0)
                break;
        }
        bs_surface *s = NULL;
        bs_parse_error err;
        bs_status st = bs_surface_read_bpt(buf, len, &err, &s);
        if (st == BS_OK) {
            accepted++;
            consistent &= round_trips(s);
        } else {
            rejected++;
            consistent &= st == BS_ERR_PARSE && s == NULL && err.line >= 1 && err.column >= 1;
        }
        bs_surface_destroy(s);
    }
    CHECK(consistent);
    CHECKF(accepted > 0 && rejected > 0, "accepted %zu rejected %zu", accepted, rejected);
    /* Pure random bytes from a small alphabet, short enough to sometimes parse. */
    for (int t = 0; t < 3000; t++) {
        size_t len = (size_t)(bs_test_rand_u64(&seed) % 40);
        for (size_t k = 0; k < len; k++)
            buf[k] = "0123 \n.-e9w"[bs_test_rand_u64(&seed) % 11];
        bs_surface *s = NULL;
        bs_status st = bs_surface_read_bpt(buf, len, NULL, &s);
        CHECK(st == BS_OK || (st == BS_ERR_PARSE && s == NULL));
        if (st == BS_OK)
            CHECK(round_trips(s));
        bs_surface_destroy(s);
    }
    free(orig);
    free(buf);
}

int main(void)
{
    test_data_files();
    test_numbers();
    test_errors();
    test_writer_args();
    test_hostile();
    return bs_test_exit("test_bpt");
}
