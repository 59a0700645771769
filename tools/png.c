/* PNG writer: signature, IHDR, one IDAT holding the zlib stream of the filtered rows, IEND. */
#include "png.h"
#include "deflate.h"
#include "outfile.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    crc = ~crc;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

uint32_t png_adler32(uint32_t adler, const unsigned char *p, size_t n)
{
    uint32_t a = adler & 0xffffu, b = adler >> 16;
    for (size_t i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (b << 16) | a;
}

static void be32(unsigned char *out, uint32_t x)
{
    out[0] = (unsigned char)(x >> 24);
    out[1] = (unsigned char)(x >> 16);
    out[2] = (unsigned char)(x >> 8);
    out[3] = (unsigned char)x;
}

/* One chunk: length, type, data, CRC over type and data. */
static int chunk(FILE *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], tail[4];
    be32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    uint32_t crc = png_crc32(png_crc32(0, head + 4, 4), data, n);
    be32(tail, crc);
    return fwrite(head, 1, 8, f) == 8 && (n == 0 || fwrite(data, 1, n, f) == n) && fwrite(tail, 1, 4, f) == 4;
}

/* Paeth predictor (PNG specification, filter type 4). */
static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Row x filtered by type t against the row above (NULL for the first row) into out. */
static void filter_row(int t, const unsigned char *x, const unsigned char *up, size_t n, unsigned char *out)
{
    for (size_t i = 0; i < n; i++) {
        int a = i >= 3 ? x[i - 3] : 0, b = up ? up[i] : 0, c = up && i >= 3 ? up[i - 3] : 0;
        int pred = t == 1 ? a : t == 2 ? b : t == 3 ? (a + b) / 2 : t == 4 ? paeth(a, b, c) : 0;
        out[i] = (unsigned char)(x[i] - pred);
    }
}

/* Each row gets the filter whose output has the smallest sum of magnitudes (bytes read as signed),
 * the heuristic of the PNG specification: small residuals make long matches and short codes. */
static void filter_image(const unsigned char *rgb, size_t w, size_t h, unsigned char *raw, unsigned char *trial)
{
    size_t n = 3 * w, row = n + 1;
    for (size_t y = 0; y < h; y++) {
        const unsigned char *x = rgb + y * n, *up = y ? rgb + (y - 1) * n : NULL;
        unsigned long best_sum = (unsigned long)-1;
        for (int t = 0; t < 5; t++) {
            filter_row(t, x, up, n, trial);
            unsigned long sum = 0;
            for (size_t i = 0; i < n; i++)
                sum += trial[i] < 128 ? trial[i] : 256u - trial[i];
            if (sum < best_sum) {
                best_sum = sum;
                raw[y * row] = (unsigned char)t;
                memcpy(raw + y * row + 1, trial, n);
            }
        }
    }
}

/* The zlib stream (RFC 1950) of n bytes: header, deflate data, Adler-32. */
static unsigned char *zlib_stream(const unsigned char *raw, size_t n, size_t *z_n)
{
    size_t d_n = 0;
    unsigned char *d = deflate_compress(raw, n, &d_n);
    unsigned char *z = d && d_n <= SIZE_MAX - 6 ? malloc(d_n + 6) : NULL;
    if (z != NULL) {
        z[0] = 0x78; /* deflate, 32K window */
        z[1] = 0x01; /* no preset dictionary; (0x78 * 256 + 0x01) % 31 == 0 */
        memcpy(z + 2, d, d_n);
        be32(z + 2 + d_n, png_adler32(1, raw, n));
        *z_n = d_n + 6;
    }
    free(d);
    return z;
}

int png_write_rgb_file(FILE *f, const unsigned char *rgb, size_t w, size_t h)
{
    errno = EINVAL;
    if (w == 0 || h == 0 || w > 0x7fffffffu / 3 || h > 0x7fffffffu)
        return -1;
    size_t row = 3 * w + 1;
    if (h > (SIZE_MAX / 2) / row)
        return -1;
    size_t raw_n = row * h, k = 0; /* filter byte + pixels per row */
    unsigned char *raw = malloc(raw_n), *trial = malloc(row), *z = NULL;
    if (raw != NULL && trial != NULL) {
        filter_image(rgb, w, h, raw, trial);
        z = zlib_stream(raw, raw_n, &k);
    }
    free(trial);
    free(raw);
    if (z == NULL || k > 0x7fffffffu) { /* a chunk holds less than 2^31 bytes */
        errno = z == NULL ? ENOMEM : EINVAL;
        free(z);
        return -1;
    }
    unsigned char ihdr[13];
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* compression: deflate */
    ihdr[11] = 0; /* filter method */
    ihdr[12] = 0; /* no interlace */
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    errno = 0;
    int ok = fwrite(sig, 1, 8, f) == 8 && chunk(f, "IHDR", ihdr, 13) && chunk(f, "IDAT", z, k) &&
             chunk(f, "IEND", NULL, 0);
    if (!ok && errno == 0)
        errno = EIO;
    int e = errno;
    free(z);
    errno = e;
    return ok ? 0 : -1;
}

int png_write_rgb(const char *path, const unsigned char *rgb, size_t w, size_t h)
{
    if (strcmp(path, "-") == 0) { /* standard output */
        if (png_write_rgb_file(stdout, rgb, w, h) != 0)
            return -1;
        errno = 0;
        if (fflush(stdout) == 0)
            return 0;
        errno = errno ? errno : EIO;
        return -1;
    }
    out_file o;
    if (out_open(path, &o) != 0)
        return -1;
    return out_close(&o, png_write_rgb_file(o.f, rgb, w, h) == 0);
}
