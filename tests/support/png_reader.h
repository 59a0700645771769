/* A strict reader for the PNG files the bezsurf tool writes (8-bit RGB, no interlace, filter 0,
 * stored deflate blocks): every chunk's CRC-32, the zlib header, each block's LEN/NLEN and the
 * Adler-32 are verified with code written independently of tools/png.c. */
#ifndef BS_TEST_PNG_READER_H
#define BS_TEST_PNG_READER_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Decode file bytes into *rgb (malloc'd, w*h*3). Returns NULL on success or the reason. */
static const char *png_read_rgb(const unsigned char *f, size_t n, size_t *w, size_t *h, unsigned char **rgb)
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
    if (zn < 6 || (z[0] & 0x0F) != 8 || ((unsigned)z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20))
        return free(z), "bad zlib header";
    size_t row = 3 * *w + 1, raw_n = row * *h, got = 0, zp = 2;
    unsigned char *raw = malloc(raw_n);
    int final = 0;
    while (!final) {
        if (zp + 5 > zn)
            return free(z), free(raw), "truncated deflate block";
        if ((z[zp] & 0x06) != 0)
            return free(z), free(raw), "not a stored block";
        final = z[zp] & 1;
        size_t len = (size_t)z[zp + 1] | (size_t)z[zp + 2] << 8, nlen = (size_t)z[zp + 3] | (size_t)z[zp + 4] << 8;
        if ((len ^ 0xFFFF) != nlen)
            return free(z), free(raw), "LEN and NLEN disagree";
        zp += 5;
        if (len > zn - zp || len > raw_n - got)
            return free(z), free(raw), "block too long";
        memcpy(raw + got, z + zp, len);
        got += len;
        zp += len;
    }
    if (got != raw_n || zn - zp != 4 || pngr_be32(z + zp) != pngr_adler(raw, raw_n))
        return free(z), free(raw), "bad length or Adler-32";
    *rgb = malloc(3 * *w * *h);
    for (size_t y = 0; y < *h; y++) {
        if (raw[y * row] != 0)
            return free(z), free(raw), free(*rgb), *rgb = NULL, "unexpected filter";
        memcpy(*rgb + 3 * *w * y, raw + y * row + 1, 3 * *w);
    }
    free(z);
    free(raw);
    return NULL;
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

#endif
