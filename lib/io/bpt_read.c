/* Reading the .bpt text format (docs/bpt-format.md) from memory or from a file. */
#include "io/internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Each patch needs at least "0 0 x y z" and a separator before it: 10 bytes. */
#define MIN_PATCH_BYTES 10

typedef struct reader {
    const char *text;
    size_t len, pos;
    size_t line, line_start; /* 1-based line number of pos, offset of that line's first byte */
    bs_parse_error *err;
} reader;

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

static void skip_space(reader *r)
{
    while (r->pos < r->len && is_space(r->text[r->pos])) {
        if (r->text[r->pos] == '\n') {
            r->line++;
            r->line_start = r->pos + 1;
        }
        r->pos++;
    }
}

/* The next whitespace-delimited token; 0 at the end of the input. Tokens never span lines, so the
 * current line and line_start describe the token's start. */
static int next_token(reader *r, size_t *start, size_t *tlen)
{
    skip_space(r);
    if (r->pos >= r->len)
        return 0;
    *start = r->pos;
    while (r->pos < r->len && !is_space(r->text[r->pos]))
        r->pos++;
    *tlen = r->pos - *start;
    return 1;
}

/* Record the first error at byte offset `at` (on the current line) and return BS_ERR_PARSE. */
static bs_status fail(reader *r, size_t at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    bs_status st = bsi_vfail(r->err, r->line, at - r->line_start + 1, fmt, ap);
    va_end(ap);
    return st;
}

/* A non-negative decimal integer no larger than max. */
static bs_status read_count(reader *r, const char *what, size_t max, size_t *value)
{
    size_t start, tlen;
    if (!next_token(r, &start, &tlen))
        return fail(r, r->pos, "unexpected end of input: expected %s", what);
    const char *t = r->text + start;
    if (tlen > 1 && t[0] == '-' && t[1] >= '0' && t[1] <= '9')
        return fail(r, start, "negative %s", what);
    int ok = bsi_parse_size(t, tlen, max, value);
    if (ok == 0)
        return fail(r, start, "expected %s (a non-negative integer)", what);
    if (ok < 0)
        return fail(r, start, "%s too large (at most %zu here)", what, max);
    return BS_OK;
}

static bs_status read_number(reader *r, const char *what, double *x)
{
    size_t start, tlen;
    if (!next_token(r, &start, &tlen))
        return fail(r, r->pos, "unexpected end of input: expected %s", what);
    int ok = bsi_parse_double(r->text + start, tlen, x);
    return ok <= 0 ? fail(r, start, bsi_parse_double_says(ok), what) : BS_OK;
}

/* One patch: degrees, optional rational marker "w", then the net. */
static bs_status read_patch(reader *r, double **scratch, size_t *scratch_cap, bs_surface *s)
{
    size_t start = r->pos, tlen, deg[2] = {0, 0};
    skip_space(r);
    size_t patch_line = r->line, patch_col = r->pos - r->line_start + 1;
    bs_status st = read_count(r, "degree in u", BS_MAX_DEGREE, &deg[0]);
    if (st == BS_OK)
        st = read_count(r, "degree in v", BS_MAX_DEGREE, &deg[1]);
    if (st != BS_OK)
        return st;
    int rational = 0;
    size_t save_pos = r->pos, save_line = r->line, save_ls = r->line_start;
    if (next_token(r, &start, &tlen) && tlen == 1 && r->text[start] == 'w')
        rational = 1;
    else
        r->pos = save_pos, r->line = save_line, r->line_start = save_ls;

    size_t npts = (deg[0] + 1) * (deg[1] + 1);
    size_t need = npts * 4;
    if (need > *scratch_cap) {
        double *grown = realloc(*scratch, need * sizeof(double));
        if (grown == NULL)
            return BS_ERR_NO_MEMORY;
        *scratch = grown;
        *scratch_cap = need;
    }
    double *ctrl = *scratch, *w = *scratch + 3 * npts;
    static const char *const coord_name[3] = {"x coordinate", "y coordinate", "z coordinate"};
    for (size_t k = 0; k < npts; k++) {
        for (size_t c = 0; c < 3; c++)
            if ((st = read_number(r, coord_name[c], &ctrl[3 * k + c])) != BS_OK)
                return st;
        if (rational) {
            size_t at = r->pos;
            if ((st = read_number(r, "weight", &w[k])) != BS_OK)
                return st;
            if (!(w[k] > 0.0)) { // NOLINT(clang-analyzer-core.NullDereference,clang-analyzer-core.UndefinedBinaryOperatorResult): w[k] was just read
                while (at < r->len && is_space(r->text[at]))
                    at++;
                return fail(r, at, "weight must be positive");
            }
        }
    }
    bs_patch *p;
    st = bs_patch_create(deg[0], deg[1], 3, ctrl, rational ? w : NULL, &p);
    if (st == BS_ERR_NONFINITE) {
        if (r->err != NULL) {
            r->err->line = patch_line;
            r->err->column = patch_col;
            (void)snprintf(r->err->message, sizeof r->err->message, "weight times coordinate overflows");
        }
        return BS_ERR_PARSE;
    }
    if (st != BS_OK)
        return st;
    st = bs_surface_add(s, p, NULL);
    bs_patch_destroy(p);
    return st;
}

bs_status bs_surface_read_bpt(const char *text, size_t len, bs_parse_error *err, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    len = bsi_text_len(text, len);
    reader r = {text, len, 0, 1, 0, err};
    size_t count = 0;
    bs_status st = read_count(&r, "the patch count", UINT32_MAX, &count);
    if (st != BS_OK)
        return st;
    /* Reject absurd counts before reading on; one patch of slack lets a short truncated file
     * report where it ends instead. */
    if (count > (len - r.pos) / MIN_PATCH_BYTES + 1) {
        size_t at = r.pos;
        while (at > 0 && !is_space(text[at - 1]))
            at--;
        return fail(&r, at, "patch count %zu is more than the input can hold", count);
    }
    bs_surface *s;
    if ((st = bs_surface_create(&s)) != BS_OK)
        return st;
    double *scratch = NULL;
    size_t scratch_cap = 0;
    for (size_t k = 0; k < count && st == BS_OK; k++)
        st = read_patch(&r, &scratch, &scratch_cap, s);
    free(scratch);
    size_t start, tlen;
    if (st == BS_OK && next_token(&r, &start, &tlen))
        st = fail(&r, start, "unexpected text after the last patch");
    if (st != BS_OK) {
        bs_surface_destroy(s);
        return st;
    }
    *out = s;
    return BS_OK;
}

bs_status bs_surface_read_bpt_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    return bsi_read_surface_file(path, err, out, bs_surface_read_bpt);
}
