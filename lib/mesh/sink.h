/*
 * A byte sink for the mesh writers (and the OBJ surface writer of lib/io/): a FILE, a caller
 * buffer of cap bytes, or neither (only counts). Writes past cap or failing writes set err (a
 * failing file write to its errno); len counts every byte asked for. Private to the library;
 * not installed.
 */
#ifndef BEZSURF_MESH_SINK_H
#define BEZSURF_MESH_SINK_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct bsi_sink {
    FILE *f;
    unsigned char *buf;
    size_t cap, len;
    int err;
} bsi_sink;

void bsi_sink_put(bsi_sink *s, const void *data, size_t n);
void bsi_sink_str(bsi_sink *s, const char *text);
/* A double in %.<digits>g form with '.' as decimal point whatever the C locale; digits 0: the
 * shortest exact form (the fewest of 15, 16 and 17 digits that read back to the same bits). */
void bsi_sink_double(bsi_sink *s, double x, int digits);
void bsi_sink_uint(bsi_sink *s, size_t x);
void bsi_sink_f32le(bsi_sink *s, double x);
void bsi_sink_u32le(bsi_sink *s, uint32_t x);

#endif
