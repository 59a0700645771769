/* What the text readers and writers of lib/io/ share: parse errors with a position, decimal
 * integers, growing arrays, whole files read into memory and written from memory, a B-spline
 * restricted to a parameter range. */
#define _POSIX_C_SOURCE 200809L // NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp): POSIX feature-test macro

#include "io/internal.h"

#include <bezsurf/bspline.h>

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

bs_status bsi_vfail(bs_parse_error *err, size_t line, size_t column, const char *fmt, va_list ap)
{
    if (err != NULL) {
        err->line = line;
        err->column = column;
        /* a message cut to the buffer is fine */
        (void)vsnprintf(err->message, sizeof err->message, fmt, ap); // NOLINT(clang-analyzer-valist.Uninitialized)
    }
    return BS_ERR_PARSE;
}

bs_status bsi_fail(bs_parse_error *err, size_t line, size_t column, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    bs_status st = bsi_vfail(err, line, column, fmt, ap);
    va_end(ap);
    return st;
}

int bsi_parse_size(const char *t, size_t len, size_t max, size_t *value)
{
    if (len == 0)
        return 0;
    size_t v = 0;
    int over = 0;
    for (size_t k = 0; k < len; k++) {
        if (t[k] < '0' || t[k] > '9')
            return 0;
        size_t d = (size_t)(t[k] - '0');
        if (over || v > (max - d) / 10)
            over = 1; /* keep going only to validate the remaining digits */
        else
            v = v * 10 + d;
    }
    if (over)
        return -1;
    *value = v;
    return 1;
}

bs_status bsi_grow(bsi_growing *g, size_t elem, size_t more)
{
    if (more <= g->cap - g->n)
        return BS_OK;
    size_t cap = g->cap ? g->cap : 16;
    while (cap - g->n < more) {
        if (cap > SIZE_MAX / 2 / elem)
            return BS_ERR_NO_MEMORY;
        cap *= 2;
    }
    void *p = realloc(g->data, cap * elem);
    if (p == NULL)
        return BS_ERR_NO_MEMORY;
    g->data = p;
    g->cap = cap;
    return BS_OK;
}

void bsi_io_error(bs_parse_error *err, const char *what)
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
        bsi_io_error(err, "cannot open the file");
        errno = e;
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        (void)close(fd);
        bsi_io_error(err, "cannot open the file");
        errno = e;
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        (void)close(fd);
        bsi_io_error(err, S_ISDIR(st.st_mode)    ? "not a regular file (a directory)"
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
        bsi_io_error(err, "cannot open the file");
        errno = e;
    }
    return f;
}

bs_status bsi_read_file(const char *path, bs_parse_error *err, char **data, size_t *size)
{
    FILE *f = open_regular(path, err);
    if (f == NULL)
        return BS_ERR_IO;
    char *buf = NULL;
    size_t len = 0, cap = 0;
    bs_status st = BS_OK;
    for (;;) {
        if (len == cap) {
            if (cap >= BSI_FILE_MAX) { /* full: only the end of the file may follow */
                char extra;
                if (fread(&extra, 1, 1, f) == 0) {
                    if (ferror(f)) {
                        bsi_io_error(err, "cannot read the file");
                        st = BS_ERR_IO;
                    }
                    break;
                }
                bsi_io_error(err, "file larger than 256 MiB");
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
                bsi_io_error(err, "cannot read the file");
                st = BS_ERR_IO;
            }
            break;
        }
    }
    (void)fclose(f); /* a stream only read from has nothing left to report */
    if (st != BS_OK) {
        free(buf);
        return st;
    }
    *data = buf;
    *size = len;
    return BS_OK;
}

bs_status bsi_read_surface_file(const char *path, bs_parse_error *err, bs_surface **out, bsi_text_reader read)
{
    if (out != NULL)
        *out = NULL;
    if (path == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    char *buf = NULL;
    size_t len = 0;
    bs_status st = bsi_read_file(path, err, &buf, &len);
    if (st == BS_OK)
        st = read(buf, len, err, out);
    free(buf);
    return st;
}

bs_status bsi_write_file(const char *path, const char *data, size_t size)
{
    bsi_out_file out;
    bs_status st = bsi_out_open(path, &out); /* atomic: a temporary file renamed over path */
    if (st == BS_OK)
        st = bsi_out_close(&out, size == 0 || fwrite(data, 1, size, out.f) == size);
    return st;
}

bs_status bsi_check_surface3(const bs_surface *s)
{
    if (s == NULL)
        return BS_ERR_INVALID_ARG;
    if (bs_surface_count(s) > 0 && bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    return BS_OK;
}

bs_status bsi_write_surface_file(const bs_surface *s, const char *path, bsi_text_writer write)
{
    if (path == NULL)
        return BS_ERR_INVALID_ARG;
    size_t size = 0;
    bs_status st = write(s, NULL, 0, &size);
    if (st != BS_OK)
        return st;
    char *text = malloc(size);
    if (text == NULL)
        return BS_ERR_NO_MEMORY;
    st = write(s, text, size, &size);
    if (st == BS_OK)
        st = bsi_write_file(path, text, size - 1);
    free(text);
    return st;
}

bs_status bsi_add_bspline_range(bs_surface *out, const bs_bspline *b, const double *range)
{
    size_t nu, nv, count;
    bs_status st = bs_bspline_span_count(b, &nu, &nv);
    if (st != BS_OK)
        return st;
    bs_surface *t;
    double *spans = malloc(4 * nu * nv * sizeof(double));
    if (spans == NULL)
        return BS_ERR_NO_MEMORY;
    if ((st = bs_surface_create(&t)) != BS_OK) {
        free(spans);
        return st;
    }
    st = bs_surface_add_bspline(t, b, spans, 4 * nu * nv, &count);
    for (size_t k = 0; k < count && st == BS_OK; k++) {
        const double *sp = spans + 4 * k;
        double a0 = sp[0] > range[0] ? sp[0] : range[0], a1 = sp[1] < range[1] ? sp[1] : range[1];
        double b0 = sp[2] > range[2] ? sp[2] : range[2], b1 = sp[3] < range[3] ? sp[3] : range[3];
        if (!(a1 > a0 && b1 > b0))
            continue;
        const bs_patch *p = bs_surface_get(t, k);
        if (a0 == sp[0] && a1 == sp[1] && b0 == sp[2] && b1 == sp[3]) {
            st = bs_surface_add(out, p, NULL);
            continue;
        }
        bs_patch *q;
        double du = sp[1] - sp[0], dv = sp[3] - sp[2];
        st = bs_patch_subpatch(p, (a0 - sp[0]) / du, (a1 - sp[0]) / du, (b0 - sp[2]) / dv, (b1 - sp[2]) / dv, &q);
        if (st == BS_OK) {
            st = bs_surface_add(out, q, NULL);
            bs_patch_destroy(q);
        }
    }
    bs_surface_destroy(t);
    free(spans);
    return st;
}
