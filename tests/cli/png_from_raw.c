/* png_from_raw W H IN OUT: write the W x H RGB pixels of the raw file IN (3 bytes a pixel, rows from
 * the top) as the PNG OUT with the tool's writer, for the test that decodes it with Python's zlib. */
#include "png.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: png_from_raw W H IN OUT\n");
        return 2;
    }
    size_t w = strtoul(argv[1], NULL, 10), h = strtoul(argv[2], NULL, 10), n = 3 * w * h;
    unsigned char *rgb = malloc(n + 1);
    FILE *f = fopen(argv[3], "rb");
    size_t got = f && rgb ? fread(rgb, 1, n + 1, f) : 0;
    if (f)
        fclose(f);
    if (got != n || png_write_rgb(argv[4], rgb, w, h) != 0) {
        fprintf(stderr, "png_from_raw: %s: %zu bytes, %zu expected, or not written\n", argv[3], got, n);
        free(rgb);
        return 1;
    }
    free(rgb);
    return 0;
}
