/*
 * I/O layer, private to lib/io/: locale-independent numbers for the text formats and the built-in
 * tea set. Not installed.
 */
#ifndef BEZSURF_IO_INTERNAL_H
#define BEZSURF_IO_INTERNAL_H

#include "core/internal.h"

#include <stdarg.h>

/* ---- .bpt numbers (lib/io/bpt_number.c): locale-independent decimal text ---- */
#define BSI_NUMBER_MAX 400 /* longest number token accepted, in bytes */

/* Parse the whole token tok[0..len) as a C-notation decimal number (no hex, no nan/inf). Returns 1
 * and sets *out when it is valid and finite, 0 when it is not a number, -1 when it is a number too
 * large for a double (the value underflows quietly to a subnormal or zero, correctly rounded), -2
 * when it is longer than BSI_NUMBER_MAX (whatever it holds). */
int bsi_parse_double(const char *tok, size_t len, double *out);
/* The readers' message for bsi_parse_double's answer ok <= 0 (-2, -1, 0): a format of one %s,
 * the name of what was expected. */
const char *bsi_parse_double_says(int ok);

/* Write the shortest of "%.15g", "%.16g", "%.17g" that reads back to x exactly, with '.' as the
 * decimal point, into buf (room for 32 bytes); returns its length (NUL not counted). */
size_t bsi_format_double(double x, char *buf);

/* ---- shared by the readers and writers (lib/io/io_common.c) ---- */
#define BSI_FILE_MAX ((size_t)256 << 20) /* largest file read into memory */

/* The length of a text without its one final NUL, if it ends with one: the sizes the writers
 * report count it, and a reader given such a size reads the text (1.2). */
static inline size_t bsi_text_len(const char *text, size_t len)
{
    return len > 0 && text != NULL && text[len - 1] == '\0' ? len - 1 : len;
}

/* Fill err (when not NULL) with line, column and the formatted message; return BS_ERR_PARSE. */
bs_status bsi_fail(bs_parse_error *err, size_t line, size_t column, const char *fmt, ...);
bs_status bsi_vfail(bs_parse_error *err, size_t line, size_t column, const char *fmt, va_list ap);
/* Fill err with line 0, column 0 and the message (for BS_ERR_IO). */
void bsi_io_error(bs_parse_error *err, const char *what);
/* The whole token t[0..len) as a decimal integer of digits only: 1 and *value set when it is at
 * most max, -1 when it is larger, 0 when it is not such an integer (empty, sign, other bytes). */
int bsi_parse_size(const char *t, size_t len, size_t max, size_t *value);
/* The bytes of a file (at most BSI_FILE_MAX), in a new buffer the caller frees. BS_ERR_IO (err
 * filled) or BS_ERR_NO_MEMORY, nothing to free then. */
bs_status bsi_read_file(const char *path, bs_parse_error *err, char **data, size_t *size);
/* A reader of text in memory, and the same reader on a file's bytes: out set to NULL first, then
 * BS_ERR_INVALID_ARG if path or out is NULL, bsi_read_file's statuses, or the reader's. */
typedef bs_status (*bsi_text_reader)(const char *text, size_t len, bs_parse_error *err, bs_surface **out);
bs_status bsi_read_surface_file(const char *path, bs_parse_error *err, bs_surface **out, bsi_text_reader read);
/* Patch control points the surface readers (OBJ, IGES 128) make from a text of len bytes at most:
 * 4 per byte and 2^16 more. A B-spline's spans each become (p + 1) (q + 1) points, so a small
 * file of degree-64 surfaces would otherwise ask for gigabytes: the count is taken from the spans
 * before anything is converted, and past the cap the reader fails with BS_ERR_SIZE. Files of
 * ordinary B-splines make well under one point per byte (a bicubic span per control point of
 * some 35 bytes: 0.5). */
#define BSI_READ_POINTS(len) ((len) < (SIZE_MAX - 65536) / 4 ? 4 * (len) + 65536 : SIZE_MAX)
#define BSI_READ_POINTS_SAY "B-spline spans of more patch control points than 4 per byte of the file"
/* The control points of nu x nv patches of degrees du x dv charged to *spent, the points a text of
 * len bytes has made so far: 1, or 0 (nothing charged) when they pass BSI_READ_POINTS(len). */
static inline int bsi_spend_span_points(size_t *spent, size_t len, size_t nu, size_t nv, size_t du, size_t dv)
{
    size_t per = (du + 1) * (dv + 1), made = SIZE_MAX; /* degrees are at most BS_MAX_DEGREE */
    if (nu == 0 || nv == 0)
        made = 0;
    else if (nv <= SIZE_MAX / nu && nu * nv <= SIZE_MAX / per)
        made = nu * nv * per;
    if (made > BSI_READ_POINTS(len) - *spent)
        return 0;
    *spent += made;
    return 1;
}

/* An array appended to as the data is read (never sized from a declared count). */
typedef struct bsi_growing {
    void *data;
    size_t n, cap; /* elements held, elements of room */
} bsi_growing;
/* Room for `more` further elements of elem bytes: BS_OK or BS_ERR_NO_MEMORY (g unchanged). */
bs_status bsi_grow(bsi_growing *g, size_t elem, size_t more);
/* Create or truncate path and write size bytes: BS_OK or BS_ERR_IO. */
bs_status bsi_write_file(const char *path, const char *data, size_t size);
/* Append the Bezier patches of B-spline b (3-D) restricted to range u0 u1 v0 v1, which must lie in
 * its knot domain with u0 < u1 and v0 < v1: the spans inside it whole, the spans it cuts cut by
 * bs_patch_subpatch, the others left out. The statuses of bs_surface_add_bspline and
 * bs_patch_subpatch; out may hold some of the patches on failure. */
bs_status bsi_add_bspline_range(bs_surface *out, const bs_bspline *b, const double *range);
/* What the text writers accept: BS_ERR_INVALID_ARG for NULL, BS_ERR_DIMENSION for a surface of
 * patches that are not 3-D (an empty one is fine), else BS_OK. */
bs_status bsi_check_surface3(const bs_surface *s);
/* A writer of text into a caller buffer (a bs_surface_write_* function), and the same text written
 * to a file: BS_ERR_INVALID_ARG if path is NULL, then the writer's statuses on the size query,
 * BS_ERR_NO_MEMORY, or bsi_write_file's. The whole text is built in memory before the file is
 * opened, so a surface the writer refuses leaves no file. */
typedef bs_status (*bsi_text_writer)(const bs_surface *s, char *buf, size_t cap, size_t *size);
bs_status bsi_write_surface_file(const bs_surface *s, const char *path, bsi_text_writer write);

/* The built-in tea set's .bpt texts (teaset_data.c in the build tree, generated from data/ at build time). */
typedef struct bsi_builtin {
    const char *name;
    const char *text;
    size_t len;
} bsi_builtin;
extern const bsi_builtin bsi_builtins[];
extern const size_t bsi_builtin_count;

#endif
