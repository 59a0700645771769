/* Reading the .bpt text format (docs/bpt-format.md) from memory or from a file. */
#define _POSIX_C_SOURCE 200809L // NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp): POSIX feature-test macro

#include "io/internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Each patch needs at least "0 0 x y z" and a separator before it: 10 bytes. */
#define MIN_PATCH_BYTES 10
/* Largest file read (a power of two times the first buffer): about 5 million bicubic patches. */
#define BPT_FILE_MAX ((size_t)256 << 20)

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
    if (r->err != NULL) {
        r->err->line = r->line;
        r->err->column = at - r->line_start + 1;
        va_list ap;
        va_start(ap, fmt);
        /* a message cut to the buffer is fine; ap is started just above (the analyzer misses it) */
        (void)vsnprintf(r->err->message, sizeof r->err->message, fmt, ap); // NOLINT(clang-analyzer-valist.Uninitialized)
        va_end(ap);
    }
    return BS_ERR_PARSE;
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
    size_t v = 0;
    int over = 0;
    for (size_t k = 0; k < tlen; k++) {
        if (t[k] < '0' || t[k] > '9')
            return fail(r, start, "expected %s (a non-negative integer)", what);
        size_t d = (size_t)(t[k] - '0');
        if (over || v > (max - d) / 10)
            over = 1; /* keep going only to validate the remaining digits */
        else
            v = v * 10 + d;
    }
    if (over)
        return fail(r, start, "%s too large (at most %zu here)", what, max);
    *value = v;
    return BS_OK;
}

static bs_status read_number(reader *r, const char *what, double *x)
{
    size_t start, tlen;
    if (!next_token(r, &start, &tlen))
        return fail(r, r->pos, "unexpected end of input: expected %s", what);
    int ok = bsi_parse_double(r->text + start, tlen, x);
    if (ok == 0)
        return fail(r, start, "expected %s (a finite decimal number)", what);
    if (ok < 0)
        return fail(r, start, "%s out of range for a double", what);
    return BS_OK;
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

static void io_error(bs_parse_error *err, const char *what)
{
    if (err != NULL) {
        err->line = 0;
        err->column = 0;
        (void)snprintf(err->message, sizeof err->message, "%s", what);
    }
}

/* Open path for reading if it is a regular file. Opening does not wait (a FIFO without a writer
 * would block a plain open), and anything else is refused before a byte is read: a FIFO, a device
 * or a socket could block the reads or never end. NULL with err and errno set on failure. */
static FILE *open_regular(const char *path, bs_parse_error *err)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        io_error(err, "cannot open the file");
        errno = e;
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        (void)close(fd);
        io_error(err, "cannot open the file");
        errno = e;
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        (void)close(fd);
        io_error(err, S_ISDIR(st.st_mode)    ? "not a regular file (a directory)"
                      : S_ISFIFO(st.st_mode) ? "not a regular file (a FIFO)"
                      : S_ISSOCK(st.st_mode) ? "not a regular file (a socket)"
                                             : "not a regular file (a device)");
        errno = S_ISDIR(st.st_mode) ? EISDIR : 0;
        return NULL;
    }
    /* regular files never block: the flag changes nothing for them and may stay set */
    FILE *f = fdopen(fd, "rb");
    if (f == NULL) {
        int e = errno;
        (void)close(fd);
        io_error(err, "cannot open the file");
        errno = e;
    }
    return f;
}

bs_status bs_surface_read_bpt_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (path == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    FILE *f = open_regular(path, err);
    if (f == NULL)
        return BS_ERR_IO;
    char *buf = NULL;
    size_t len = 0, cap = 0;
    bs_status st = BS_OK;
    for (;;) {
        if (len == cap) {
            if (cap >= BPT_FILE_MAX) { /* full: only the end of the file may follow */
                char extra;
                if (fread(&extra, 1, 1, f) == 0) {
                    if (ferror(f)) {
                        io_error(err, "cannot read the file");
                        st = BS_ERR_IO;
                    }
                    break;
                }
                io_error(err, "file larger than 256 MiB");
                errno = EFBIG;
                st = BS_ERR_IO;
                break;
            }
            size_t ncap = cap ? 2 * cap : 65536;
            char *grown = realloc(buf, ncap);
            if (grown == NULL) {
                st = BS_ERR_NO_MEMORY;
                break;
            }
            buf = grown;
            cap = ncap;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            if (ferror(f)) {
                io_error(err, "cannot read the file");
                st = BS_ERR_IO;
            }
            break;
        }
    }
    (void)fclose(f); /* a stream only read from has nothing left to report */
    if (st == BS_OK)
        st = bs_surface_read_bpt(buf, len, err, out);
    free(buf);
    return st;
}
