/* PNG writer: signature, IHDR, one IDAT holding a zlib stream of stored deflate blocks, IEND. */
#include "png.h"
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

int png_write_rgb(const char *path, const unsigned char *rgb, size_t w, size_t h)
{
    errno = EINVAL;
    if (w == 0 || h == 0 || w > 0x7fffffffu / 3 || h > 0x7fffffffu)
        return -1;
    size_t row = 3 * w + 1;
    if (h > (SIZE_MAX / 2) / row)
        return -1;
    size_t raw_n = row * h;                      /* filter byte + pixels per row */
    size_t blocks = (raw_n + 65534) / 65535;
    size_t z_n = 2 + raw_n + 5 * blocks + 4;     /* zlib header, stored blocks, Adler-32 */
    if (z_n > 0x7fffffffu)
        return -1;
    unsigned char *raw = malloc(raw_n), *z = malloc(z_n);
    if (raw == NULL || z == NULL) {
        free(raw);
        free(z);
        errno = ENOMEM;
        return -1;
    }
    for (size_t y = 0; y < h; y++) {
        raw[y * row] = 0; /* filter: none */
        memcpy(raw + y * row + 1, rgb + y * 3 * w, 3 * w);
    }
    size_t k = 0;
    z[k++] = 0x78; /* deflate, 32K window */
    z[k++] = 0x01; /* no preset dictionary; (0x78 * 256 + 0x01) % 31 == 0 */
    for (size_t off = 0; off < raw_n; off += 65535) {
        size_t len = raw_n - off < 65535 ? raw_n - off : 65535;
        z[k++] = off + len == raw_n ? 1 : 0; /* BFINAL, BTYPE 00 (stored) */
        z[k++] = (unsigned char)(len & 0xff);
        z[k++] = (unsigned char)(len >> 8);
        z[k++] = (unsigned char)(~len & 0xff);
        z[k++] = (unsigned char)((~len >> 8) & 0xff);
        memcpy(z + k, raw + off, len);
        k += len;
    }
    be32(z + k, png_adler32(1, raw, raw_n));
    k += 4;
    unsigned char ihdr[13];
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* compression: deflate */
    ihdr[11] = 0; /* filter method */
    ihdr[12] = 0; /* no interlace */
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    out_file o;
    int rc = out_open(path, &o);
    if (rc == 0) {
        errno = 0;
        int ok = fwrite(sig, 1, 8, o.f) == 8 && chunk(o.f, "IHDR", ihdr, 13) && chunk(o.f, "IDAT", z, k) &&
                 chunk(o.f, "IEND", NULL, 0);
        rc = out_close(&o, ok);
    }
    int e = errno;
    free(raw);
    free(z);
    errno = e;
    return rc;
}
