/*
 * I/O layer, private to lib/io/: locale-independent numbers for the text formats and the built-in
 * tea set. Not installed.
 */
#ifndef BEZSURF_IO_INTERNAL_H
#define BEZSURF_IO_INTERNAL_H

#include "core/internal.h"

/* ---- .bpt numbers (lib/io/bpt_number.c): locale-independent decimal text ---- */
#define BSI_NUMBER_MAX 400 /* longest number token accepted, in bytes */

/* Parse the whole token tok[0..len) as a C-notation decimal number (no hex, no nan/inf). Returns 1
 * and sets *out when it is valid and finite, 0 when it is not a number, -1 when it is a number too
 * large for a double (the value underflows quietly to a subnormal or zero, correctly rounded). */
int bsi_parse_double(const char *tok, size_t len, double *out);

/* Write the shortest of "%.15g", "%.16g", "%.17g" that reads back to x exactly, with '.' as the
 * decimal point, into buf (room for 32 bytes); returns its length (NUL not counted). */
size_t bsi_format_double(double x, char *buf);

/* The built-in tea set's .bpt texts (teaset_data.c in the build tree, generated from data/ at build time). */
typedef struct bsi_builtin {
    const char *name;
    const char *text;
    size_t len;
} bsi_builtin;
extern const bsi_builtin bsi_builtins[];
extern const size_t bsi_builtin_count;

#endif
