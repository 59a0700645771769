/* IGES records, sections and parameter fields (io/iges.h): fixed 80-column records, the section
 * letter in column 73, parameters separated by the delimiters of the global section, Hollerith
 * strings, integers and reals (with E or D exponents) read without the C locale. */
#include "io/iges.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define IGES_LETTER 72 /* 0-based column of the section letter */
#define IGES_WIDTH 80
#define IGES_BACK 64 /* 0-based column of a P record's back pointer to its directory entry */

static bs_status fail_rec(const iges *g, size_t rec, size_t col, const char *msg)
{
    (void)bsi_fail(g->err, rec + 1, col, "%s", msg);
    return BS_ERR_PARSE;
}

/* Blanks only (or a DOS end-of-file mark). */
static int blank(const char *t, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (t[k] != ' ' && t[k] != '\t' && t[k] != '\x1a')
            return 0;
    return 1;
}

bs_status bsi_iges_records(iges *g)
{
    static const char letters[IGES_SECTIONS + 1] = "SGDPT";
    size_t off = 0, skipped = 0;
    int sec = 0;
    while (off < g->len) {
        size_t end = off;
        while (end < g->len && g->text[end] != '\n')
            end++;
        size_t n = end - off;
        if (n > 0 && g->text[end - 1] == '\r')
            n--;
        size_t r = g->nrec + skipped; /* for errors: stored records all come before skipped lines */
        if (g->count[IGES_T] > 0 && blank(g->text + off, n)) { /* blank lines after the end */
            off = end + (end < g->len);
            skipped++;
            continue;
        }
        if (memchr(g->text + off, '\0', n) != NULL)
            return fail_rec(g, r, (size_t)((const char *)memchr(g->text + off, '\0', n) - (g->text + off)) + 1,
                            "NUL byte in a record");
        if (n <= IGES_LETTER)
            return fail_rec(g, r, n + 1, "record shorter than 73 columns (no section letter)");
        if (n > IGES_WIDTH)
            return fail_rec(g, r, IGES_WIDTH + 1, "record longer than 80 columns");
        char c = g->text[off + IGES_LETTER];
        const char *at = c != '\0' ? strchr(letters, c) : NULL;
        if (c == 'C' || c == 'B')
            return fail_rec(g, r, IGES_LETTER + 1, "compressed or binary IGES is not read");
        if (at == NULL)
            return fail_rec(g, r, IGES_LETTER + 1, "expected a section letter S, G, D, P or T in column 73");
        int k = (int)(at - letters);
        if (k < sec || (sec == IGES_T && g->count[IGES_T] > 0))
            return fail_rec(g, r, IGES_LETTER + 1, "section out of order (S, G, D, P, T) or after T");
        if (g->count[k] == 0)
            g->first[k] = r;
        g->count[k]++;
        sec = k;
        if (g->nrec == g->rec_cap) {
            size_t cap = g->rec_cap ? 2 * g->rec_cap : 256;
            size_t *grown = realloc(g->rec, cap * sizeof *grown);
            if (grown == NULL)
                return BS_ERR_NO_MEMORY;
            g->rec = grown;
            g->rec_cap = cap;
        }
        g->rec[g->nrec++] = off;
        off = end + (end < g->len);
    }
    static const char *const missing[IGES_SECTIONS] = {NULL, "no global (G) section", "no directory entry (D) section",
                                                       "no parameter data (P) section", "no terminate (T) section"};
    for (int k = IGES_G; k < IGES_SECTIONS; k++)
        if (g->count[k] == 0) {
            size_t at = g->nrec; /* where the section should begin */
            for (int j = IGES_SECTIONS - 1; j > k; j--)
                if (g->count[j] > 0)
                    at = g->first[j];
            return fail_rec(g, at, 1, missing[k]);
        }
    if (g->count[IGES_D] % 2 != 0)
        return fail_rec(g, g->first[IGES_D] + g->count[IGES_D] - 1, IGES_LETTER + 1,
                        "odd number of directory entry records (two per entity)");
    return BS_OK;
}

static char at_pos(const iges *g, const iges_stream *s, size_t pos)
{
    return g->text[g->rec[s->first + pos / s->width] + pos % s->width];
}

bs_status bsi_iges_fail_at(const iges *g, const iges_stream *s, size_t pos, const char *fmt, ...)
{
    size_t total = s->nrec * s->width;
    size_t p = pos < total ? pos : total - 1;
    va_list ap;
    va_start(ap, fmt);
    (void)bsi_vfail(g->err, s->first + p / s->width + 1, p % s->width + 1 + (pos >= total), fmt, ap);
    va_end(ap);
    return BS_ERR_PARSE;
}

static void skip_blanks(const iges *g, iges_stream *s)
{
    while (s->pos < s->nrec * s->width && at_pos(g, s, s->pos) == ' ')
        s->pos++;
}

bs_status bsi_iges_field(const iges *g, iges_stream *s, iges_field *f)
{
    size_t total = s->nrec * s->width;
    if (s->ended)
        return bsi_iges_fail_at(g, s, s->pos - 1, "fewer parameters than the entity needs");
    skip_blanks(g, s);
    f->start = s->pos;
    f->hollerith = 0;
    size_t count = 0, k = s->pos;
    while (k < total && at_pos(g, s, k) >= '0' && at_pos(g, s, k) <= '9' && count <= total)
        count = count * 10 + (size_t)(at_pos(g, s, k++) - '0');
    if (k > s->pos && k < total && at_pos(g, s, k) == 'H') {
        if (count > total - k - 1)
            return bsi_iges_fail_at(g, s, s->pos, "Hollerith string longer than the section");
        f->hollerith = 1;
        f->start = k + 1;
        f->len = count;
        s->pos = k + 1 + count;
        skip_blanks(g, s);
    } else {
        while (s->pos < total && at_pos(g, s, s->pos) != g->pdelim && at_pos(g, s, s->pos) != g->rdelim)
            s->pos++;
        f->len = s->pos - f->start;
        while (f->len > 0 && at_pos(g, s, f->start + f->len - 1) == ' ')
            f->len--;
    }
    if (s->pos >= total)
        return bsi_iges_fail_at(g, s, s->pos, "parameters not ended by the record delimiter");
    char d = at_pos(g, s, s->pos);
    if (d != g->pdelim && d != g->rdelim)
        return bsi_iges_fail_at(g, s, s->pos, "expected a delimiter after the Hollerith string");
    f->last = s->ended = d == g->rdelim;
    s->pos++;
    return BS_OK;
}

/* The field's characters into buf (NUL-terminated), D exponents as E; 0 when longer than cap - 1. */
static int copy_field(const iges *g, const iges_stream *s, const iges_field *f, char *buf, size_t cap)
{
    if (f->len >= cap)
        return 0;
    for (size_t k = 0; k < f->len; k++) {
        char c = at_pos(g, s, f->start + k);
        if (c == 'D' || c == 'd')
            c = 'E'; /* FORTRAN's double-precision exponent */
        buf[k] = c;
    }
    buf[f->len] = '\0';
    return 1;
}

/* The next field's text into buf, for a number: BS_ERR_PARSE for a Hollerith string or a field
 * longer than BSI_NUMBER_MAX. */
static bs_status number_field(const iges *g, iges_stream *s, const char *what, iges_field *f, char *buf)
{
    bs_status st = bsi_iges_field(g, s, f);
    if (st != BS_OK)
        return st;
    if (!f->hollerith && f->len > BSI_NUMBER_MAX) {
        (void)bsi_iges_fail_at(g, s, f->start, "%s longer than 400 characters", what);
        return BS_ERR_PARSE;
    }
    if (f->hollerith || !copy_field(g, s, f, buf, BSI_NUMBER_MAX + 1)) {
        (void)bsi_iges_fail_at(g, s, f->start, "expected %s (a number)", what);
        return BS_ERR_PARSE; /* as bsi_iges_fail_at, said here for the analyzer */
    }
    return BS_OK;
}

bs_status bsi_iges_real(const iges *g, iges_stream *s, const char *what, double *x, iges_field *f)
{
    char buf[BSI_NUMBER_MAX + 1];
    bs_status st = number_field(g, s, what, f, buf);
    if (st != BS_OK)
        return st;
    if (f->len == 0) {
        *x = 0.0;
        return BS_OK;
    }
    int ok = bsi_parse_double(buf, f->len, x);
    if (ok <= 0)
        return bsi_iges_fail_at(g, s, f->start,
                                ok == 0 ? "expected %s (a finite number)" : "%s out of range for a double",
                                what);
    return BS_OK;
}

/* Text t[0..len) as an integer in [lo, hi]; 0 when it is not one. */
static int parse_long(const char *t, size_t len, long lo, long hi, long *x)
{
    int neg = len > 0 && (t[0] == '-' || t[0] == '+');
    size_t v;
    if (len == 0) {
        *x = 0;
        return lo <= 0 && 0 <= hi;
    }
    size_t max = (size_t)(hi > -lo ? hi : -lo); /* lo and hi are far from LONG_MIN */
    if (bsi_parse_size(t + neg, len - (size_t)neg, max, &v) <= 0)
        return 0;
    long value = t[0] == '-' ? -(long)v : (long)v;
    if (value < lo || value > hi)
        return 0;
    *x = value;
    return 1;
}

bs_status bsi_iges_int(const iges *g, iges_stream *s, const char *what, long lo, long hi, long *x)
{
    char buf[BSI_NUMBER_MAX + 1];
    iges_field f;
    bs_status st = number_field(g, s, what, &f, buf);
    if (st != BS_OK)
        return st;
    if (!parse_long(buf, f.len, lo, hi, x))
        return bsi_iges_fail_at(g, s, f.start, "expected %s (an integer from %ld to %ld)", what, lo, hi);
    return BS_OK;
}

bs_status bsi_iges_de_field(const iges *g, size_t de, int f, long *x)
{
    size_t rec = g->first[IGES_D] + de + (size_t)(f - 1) / 10, col = (size_t)((f - 1) % 10) * 8;
    const char *t = g->text + g->rec[rec] + col;
    size_t a = 0, b = 8;
    while (a < b && t[a] == ' ')
        a++;
    while (b > a && t[b - 1] == ' ')
        b--;
    if (!parse_long(t + a, b - a, -99999999L, 99999999L, x))
        return fail_rec(g, rec, col + a + 1, "expected an integer in a directory entry field");
    return BS_OK;
}

bs_status bsi_iges_rest(const iges *g, iges_stream *s)
{
    iges_field f;
    bs_status st = BS_OK;
    while (st == BS_OK && !s->ended)
        st = bsi_iges_field(g, s, &f);
    return st;
}

bs_status bsi_iges_open(const iges *g, size_t de, iges_stream *s)
{
    long ptr, lines;
    bs_status st = bsi_iges_de_field(g, de, 2, &ptr);
    if (st == BS_OK)
        st = bsi_iges_de_field(g, de, 14, &lines);
    if (st != BS_OK)
        return st;
    size_t np = g->count[IGES_P], rec = g->first[IGES_D] + de;
    if (ptr < 1 || (size_t)ptr > np)
        return fail_rec(g, rec, 9, "parameter data pointer outside the P section");
    if (lines < 1 || (size_t)lines > np - (size_t)ptr + 1)
        return fail_rec(g, rec + 1, 25, "parameter line count outside the P section");
    s->first = g->first[IGES_P] + (size_t)ptr - 1;
    s->nrec = (size_t)lines;
    s->width = 64;
    s->pos = 0;
    s->ended = 0;
    /* Records that name another entry are refused, so entries cannot share parameter data: the
     * 1.1 reader would parse it once per entry (padded with blanks, size x entries). */
    for (size_t k = 0; k < s->nrec; k++) {
        const char *t = g->text + g->rec[s->first + k] + IGES_BACK;
        size_t a = 0, back;
        while (a < 8 && t[a] == ' ')
            a++;
        if (bsi_parse_size(t + a, 8 - a, 99999999, &back) <= 0 || back != de + 1) {
            (void)bsi_fail(g->err, s->first + k + 1, IGES_BACK + 1, "P record's back pointer is not DE %zu", de + 1);
            return BS_ERR_PARSE;
        }
    }
    return BS_OK;
}

/* One delimiter of the global section: "1Hc" or nothing (the default). */
static bs_status read_delimiter(iges *g, iges_stream *s, char *delim, char fallback)
{
    size_t total = s->nrec * s->width;
    skip_blanks(g, s);
    *delim = fallback;
    if (s->pos + 2 < total && at_pos(g, s, s->pos) == '1' && at_pos(g, s, s->pos + 1) == 'H') {
        *delim = at_pos(g, s, s->pos + 2);
        if (strchr(" 0123456789+-.DEH", *delim) != NULL)
            return bsi_iges_fail_at(g, s, s->pos + 2, "delimiter may not be a blank, digit, sign, point, D, E or H");
        s->pos += 3;
        skip_blanks(g, s);
    }
    return BS_OK;
}

bs_status bsi_iges_global(iges *g)
{
    iges_stream s = {g->first[IGES_G], g->count[IGES_G], 72, 0, 0};
    size_t total = s.nrec * s.width;
    bs_status st = read_delimiter(g, &s, &g->pdelim, ',');
    if (st != BS_OK)
        return st;
    if (s.pos >= total || at_pos(g, &s, s.pos) != g->pdelim)
        return bsi_iges_fail_at(g, &s, s.pos, "expected the parameter delimiter after the first global field");
    s.pos++;
    if ((st = read_delimiter(g, &s, &g->rdelim, ';')) != BS_OK)
        return st;
    if (g->rdelim == g->pdelim)
        return bsi_iges_fail_at(g, &s, s.pos - 1, "the record delimiter equals the parameter delimiter");
    if (s.pos < total && at_pos(g, &s, s.pos) == g->rdelim)
        return BS_OK; /* the other global fields are defaulted */
    if (s.pos >= total || at_pos(g, &s, s.pos) != g->pdelim)
        return bsi_iges_fail_at(g, &s, s.pos, "expected a delimiter after the second global field");
    s.pos++;
    iges_field f = {0, 0, 0, 0};
    while (st == BS_OK && !f.last)
        st = bsi_iges_field(g, &s, &f);
    return st;
}
