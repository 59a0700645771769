/* A strict reader for the PNG files the bezsurf tool writes (8-bit RGB, no interlace, any of the
 * five row filters, a zlib stream of any deflate blocks): every chunk's CRC-32, the zlib header,
 * the deflate data (tests/support/inflate.h), its exact length and the Adler-32 are verified with
 * code written independently of tools/png.c and tools/deflate.c. */
#ifndef BS_TEST_PNG_READER_H
#define BS_TEST_PNG_READER_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inflate.h"

static uint32_t pngr_be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

/* Table-driven CRC-32 (the tool computes it bit by bit). */
static uint32_t pngr_crc(const unsigned char *p, size_t n)
{
    uint32_t table[256];
    for (uint32_t i = 0; i < 256; i++) {
        uint32_t c = i;
        for (int k = 0; k < 8; k++)
            c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[i] = c;
    }
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++)
        c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

static uint32_t pngr_adler(const unsigned char *p, size_t n)
{
    unsigned long long a = 1, b = 0;
    for (size_t i = 0; i < n; i++) {
        a = (a + p[i]) % 65521;
        b = (b + a) % 65521;
    }
    return (uint32_t)(b << 16 | a);
}

static int pngr_paeth(int a, int b, int c)
{
    int p = a + b - c, pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p, pc = p > c ? p - c : c - p;
    if (pa <= pb && pa <= pc)
        return a;
    return pb <= pc ? b : c;
}

/* Undo the row filters of raw (h rows of 1 + 3w bytes) into rgb; bit t of *seen set for each filter
 * type t met. 0 on success, -1 for an unknown filter type. */
static int pngr_unfilter(const unsigned char *raw, size_t w, size_t h, unsigned char *rgb, unsigned *seen)
{
    size_t n = 3 * w;
    for (size_t y = 0; y < h; y++) {
        int t = raw[y * (n + 1)];
        if (t > 4)
            return -1;
        *seen |= 1u << t;
        const unsigned char *f = raw + y * (n + 1) + 1;
        unsigned char *x = rgb + y * n, *up = y ? rgb + (y - 1) * n : NULL;
        for (size_t i = 0; i < n; i++) {
            int a = i >= 3 ? x[i - 3] : 0, b = up ? up[i] : 0, c = up && i >= 3 ? up[i - 3] : 0;
            int pred = t == 0 ? 0 : t == 1 ? a : t == 2 ? b : t == 3 ? (a + b) >> 1 : pngr_paeth(a, b, c);
            x[i] = (unsigned char)(f[i] + pred);
        }
    }
    return 0;
}

/* Decode file bytes into *rgb (malloc'd, w*h*3); bit t of *filters (if not NULL) is set when a row
 * uses filter type t. Returns NULL on success or the reason. */
static const char *png_read_rgb_filters(const unsigned char *f, size_t n, size_t *w, size_t *h, unsigned char **rgb,
                                        unsigned *filters)
{
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    *rgb = NULL;
    if (n < 8 || memcmp(f, sig, 8) != 0)
        return "bad signature";
    size_t pos = 8, zn = 0, zcap = 0;
    unsigned char *z = NULL;
    int ihdr = 0, iend = 0;
    while (!iend) {
        if (n - pos < 12)
            return free(z), "truncated chunk";
        size_t len = pngr_be32(f + pos);
        if (len > n - pos - 12)
            return free(z), "chunk longer than the file";
        const unsigned char *type = f + pos + 4, *data = f + pos + 8;
        if (pngr_crc(type, len + 4) != pngr_be32(data + len))
            return free(z), "bad CRC";
        if (memcmp(type, "IHDR", 4) == 0) {
            if (ihdr || pos != 8 || len != 13)
                return free(z), "bad IHDR";
            *w = pngr_be32(data);
            *h = pngr_be32(data + 4);
            if (*w == 0 || *h == 0 || data[8] != 8 || data[9] != 2 || data[10] || data[11] || data[12])
                return free(z), "unsupported IHDR";
            ihdr = 1;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            if (!ihdr)
                return free(z), "IDAT before IHDR";
            if (zn + len > zcap) {
                zcap = 2 * (zn + len);
                unsigned char *g = realloc(z, zcap);
                if (g == NULL)
                    return free(z), "out of memory";
                z = g;
            }
            memcpy(z + zn, data, len);
            zn += len;
        } else if (memcmp(type, "IEND", 4) == 0) {
            if (len != 0)
                return free(z), "bad IEND";
            iend = 1;
        } else if (!(type[0] & 0x20)) {
            return free(z), "unknown critical chunk";
        }
        pos += 12 + len;
    }
    if (pos != n)
        return free(z), "bytes after IEND";
    if (zn < 6 || (z[0] & 0x0F) != 8 || (z[0] >> 4) > 7 || ((unsigned)z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20))
        return free(z), "bad zlib header";
    size_t row = 3 * *w + 1, raw_n = row * *h, got = 0, used = 0;
    unsigned char *raw = malloc(raw_n + 1); /* one spare byte: a longer stream is caught */
    const char *why = raw ? bs_inflate(z + 2, zn - 2, raw, raw_n + 1, &got, &used) : "out of memory";
    if (why == NULL && (got != raw_n || zn - 2 - used != 4 || pngr_be32(z + 2 + used) != pngr_adler(raw, raw_n)))
        why = "bad length or Adler-32";
    unsigned seen = 0;
    if (why == NULL && (*rgb = malloc(3 * *w * *h)) == NULL)
        why = "out of memory";
    if (why == NULL && pngr_unfilter(raw, *w, *h, *rgb, &seen) != 0)
        why = "unknown filter type";
    if (why != NULL) {
        free(*rgb);
        *rgb = NULL;
    }
    if (filters != NULL)
        *filters = seen;
    free(z);
    free(raw);
    return why;
}

/* Decode file bytes into *rgb (malloc'd, w*h*3). Returns NULL on success or the reason. */
static const char *png_read_rgb(const unsigned char *f, size_t n, size_t *w, size_t *h, unsigned char **rgb)
{
    return png_read_rgb_filters(f, n, w, h, rgb, NULL);
}

/* Load a whole file; NULL if it cannot be read. */
static unsigned char *pngr_load(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    size_t cap = 1 << 16;
    unsigned char *b = malloc(cap);
    *n = 0;
    size_t got;
    while (b && (got = fread(b + *n, 1, cap - *n, f)) > 0) {
        *n += got;
        if (*n == cap) {
            unsigned char *g = realloc(b, cap *= 2);
            if (g == NULL) {
                free(b);
                b = NULL;
            }
            b = g;
        }
    }
    fclose(f);
    return b;
}

/* Load and decode the PNG file at path into *rgb (malloc'd); NULL on success or the reason. */
static inline const char *png_read_file(const char *path, size_t *w, size_t *h, unsigned char **rgb)
{
    size_t n = 0;
    unsigned char *file = pngr_load(path, &n);
    *rgb = NULL;
    if (file == NULL)
        return "cannot read";
    const char *why = png_read_rgb(file, n, w, h, rgb);
    free(file);
    return why;
}

#endif
