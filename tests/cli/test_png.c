/* The tool's PNG writer (tools/png.c, compiled in): known CRC-32 and Adler-32 values, and images of
 * several sizes (one spanning several stored blocks) decoded back by an independent strict reader. */
#include "harness.h"
#include "png_reader.h"
#include "png.h"

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const unsigned char *digits = (const unsigned char *)"123456789";
    CHECK(png_crc32(0, digits, 9) == 0xCBF43926u);                             /* the CRC-32 check value */
    CHECK(png_crc32(png_crc32(0, digits, 4), digits + 4, 5) == 0xCBF43926u);  /* continued */
    CHECK(png_adler32(1, (const unsigned char *)"Wikipedia", 9) == 0x11E60398u);
    CHECK(png_adler32(1, NULL, 0) == 1u);

    static const size_t sizes[][2] = {{1, 1}, {3, 2}, {17, 5}, {300, 200}};
    unsigned long long seed = 7;
    for (size_t k = 0; k < 4; k++) {
        size_t w = sizes[k][0], h = sizes[k][1];
        unsigned char *img = malloc(3 * w * h);
        for (size_t i = 0; i < 3 * w * h; i++)
            img[i] = (unsigned char)(bs_test_rand_u64(&seed) >> 56);
        char path[1024];
        snprintf(path, sizeof path, "%s/test_png_%zu.png", dir, k);
        CHECK(png_write_rgb(path, img, w, h) == 0);
        size_t n = 0, rw = 0, rh = 0;
        unsigned char *file = pngr_load(path, &n), *back = NULL;
        CHECK(file != NULL);
        const char *why = file ? png_read_rgb(file, n, &rw, &rh, &back) : "unreadable";
        CHECKF(why == NULL, "%zux%zu: %s", w, h, why);
        CHECK(rw == w && rh == h && back != NULL && memcmp(back, img, 3 * w * h) == 0);
        if (file != NULL && n > 40) {
            file[n / 2] ^= 1; /* the reader notices a flipped bit */
            unsigned char *bad = NULL;
            CHECK(png_read_rgb(file, n, &rw, &rh, &bad) != NULL);
            free(bad);
        }
        free(file);
        free(back);
        free(img);
        remove(path);
    }
    unsigned char px[3] = {0, 0, 0};
    CHECK(png_write_rgb("/nonexistent-dir/x.png", px, 1, 1) == -1);
    CHECK(png_write_rgb("unused.png", px, 0, 1) == -1);
    return bs_test_exit("test_png");
}
