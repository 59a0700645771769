/* The tool's PNG writer (tools/png.c and its deflate, compiled in): known CRC-32 and Adler-32
 * values, and pictures of several kinds and sizes decoded back exactly by the tests' own strict
 * reader and inflater (tests/support/png_reader.h, inflate.h), the five row filters all met. */
#include "harness.h"
#include "png_reader.h"
#include "png.h"

/* Write w x h pixels, read them back; the set of filter types the rows use (0 after a failure). */
static unsigned round_trip(const char *dir, const char *what, const unsigned char *img, size_t w, size_t h)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/test_png.png", dir);
    CHECKF(png_write_rgb(path, img, w, h) == 0, "%s: not written", what);
    size_t n = 0, rw = 0, rh = 0;
    unsigned filters = 0;
    unsigned char *file = pngr_load(path, &n), *back = NULL;
    CHECKF(file != NULL, "%s: unreadable", what);
    const char *why = file ? png_read_rgb_filters(file, n, &rw, &rh, &back, &filters) : "unreadable";
    CHECKF(why == NULL, "%s: %s", what, why);
    CHECKF(rw == w && rh == h && back != NULL && memcmp(back, img, 3 * w * h) == 0, "%s: pixels differ", what);
    if (file != NULL && n > 40) {
        file[n / 2] ^= 1; /* the reader notices a flipped bit */
        unsigned char *bad = NULL;
        CHECKF(png_read_rgb(file, n, &rw, &rh, &bad) != NULL, "%s: flipped bit unnoticed", what);
        free(bad);
    }
    free(file);
    free(back);
    remove(path);
    return why == NULL ? filters : 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const unsigned char *digits = (const unsigned char *)"123456789";
    CHECK(png_crc32(0, digits, 9) == 0xCBF43926u);                             /* the CRC-32 check value */
    CHECK(png_crc32(png_crc32(0, digits, 4), digits + 4, 5) == 0xCBF43926u);  /* continued */
    CHECK(png_adler32(1, (const unsigned char *)"Wikipedia", 9) == 0x11E60398u);
    CHECK(png_adler32(1, NULL, 0) == 1u);

    /* Noise, flat colour (long runs), black rows between noise, and gradients, at several sizes
     * (the largest spanning several deflate blocks). */
    static const size_t sizes[][2] = {{1, 1}, {3, 2}, {17, 5}, {300, 200}, {640, 480}};
    unsigned long long seed = 7;
    for (size_t k = 0; k < 5; k++)
        for (int kind = 0; kind < 4; kind++) {
            size_t w = sizes[k][0], h = sizes[k][1];
            unsigned char *img = malloc(3 * w * h);
            for (size_t i = 0; i < 3 * w * h; i++) {
                size_t x = i % (3 * w) / 3, y = i / (3 * w);
                unsigned char noise = (unsigned char)(bs_test_rand_u64(&seed) >> 56);
                img[i] = kind == 0 ? noise : kind == 1 ? 90 : kind == 2 ? (y % 3 ? 0 : noise)
                                                                   : (unsigned char)(x * 3 + y * 2 + i % 3);
            }
            char what[64];
            snprintf(what, sizeof what, "%zux%zu kind %d", w, h, kind);
            unsigned filters = round_trip(dir, what, img, w, h);
            if (kind == 1) /* a flat picture: rows after the first equal the one above */
                CHECKF(h == 1 || (filters & 0x1c) != 0, "%s: filters %#x", what, filters);
            free(img);
        }

    /* Rows built so that one filter predicts each best: row 0 black (None: every filter ties at 0
     * and the first is taken), row 1 steps of 1 (Sub), row 2 a copy (Up), row 3 the mean of its
     * left and upper bytes (Average: all 0), row 4 flat 50 (Sub), row 5 flat 128 over it (Paeth
     * predicts the upper byte, then the left one: residuals 78, 78, 78 and 0, against 128 for Sub). */
    size_t w = 64, h = 6, n = 3 * w;
    unsigned char *img = calloc(3 * w * h, 1), *r1 = img + n, *r2 = img + 2 * n, *r3 = img + 3 * n;
    for (size_t i = 0; i < n; i++) {
        r1[i] = (unsigned char)(i < 3 ? 200 + 20 * i : r1[i - 3] + 1u);
        r2[i] = r1[i];
        r3[i] = (unsigned char)(((i >= 3 ? r3[i - 3] : 0) + r2[i]) >> 1);
    }
    memset(img + 4 * n, 50, n);
    memset(img + 5 * n, 128, n);
    unsigned filters = round_trip(dir, "five filters", img, w, h);
    CHECKF(filters == 0x1f, "five filters: filters %#x", filters);
    free(img);

    unsigned char px[3] = {0, 0, 0};
    CHECK(png_write_rgb("/nonexistent-dir/x.png", px, 1, 1) == -1);
    CHECK(png_write_rgb("unused.png", px, 0, 1) == -1);
    return bs_test_exit("test_png");
}
