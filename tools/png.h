/* A dependency-free PNG writer: 8-bit RGB, a filter chosen per row, the rows compressed by
 * tools/deflate.c into one zlib stream, CRC-32 per chunk and Adler-32 over the filtered rows. */
#ifndef BEZSURF_TOOLS_PNG_H
#define BEZSURF_TOOLS_PNG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* CRC-32 (ISO 3309, as PNG uses it) of n bytes, continued from crc (start with 0). */
uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n);

/* Adler-32 of n bytes, continued from adler (start with 1). */
uint32_t png_adler32(uint32_t adler, const unsigned char *p, size_t n);

/* Write w x h pixels, 3 bytes (R, G, B) each, row by row from the top, replacing path atomically
 * (tools/outfile.h: the old file stays as it was unless the whole new one was written). 0 on
 * success, -1 with errno set if the file cannot be written (EINVAL: the size is out of range). */
int png_write_rgb(const char *path, const unsigned char *rgb, size_t w, size_t h); /* "-": stdout */

/* The same bytes written to f (not flushed): 0, or -1 with errno set. */
int png_write_rgb_file(FILE *f, const unsigned char *rgb, size_t w, size_t h);

#endif
