/* png_check FILE W H: exit 0 if FILE is a valid PNG of W x H pixels (every CRC, the stored deflate
 * blocks and the Adler-32 verified by tests/png_reader.h) whose picture is not one flat colour;
 * else print why and exit 1. Used by the CLI test. */
#include "png_reader.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: png_check FILE W H\n");
        return 2;
    }
    size_t n = 0, w = 0, h = 0;
    unsigned char *file = pngr_load(argv[1], &n), *rgb = NULL;
    if (file == NULL) {
        fprintf(stderr, "%s: cannot read\n", argv[1]);
        return 1;
    }
    const char *why = png_read_rgb(file, n, &w, &h, &rgb);
    free(file);
    if (why != NULL) {
        fprintf(stderr, "%s: %s\n", argv[1], why);
        return 1;
    }
    int ok = w == strtoul(argv[2], NULL, 10) && h == strtoul(argv[3], NULL, 10);
    size_t differ = 0;
    for (size_t k = 3; k < 3 * w * h; k++)
        differ += rgb[k] != rgb[k % 3];
    free(rgb);
    if (!ok || differ < w * h / 20) {
        fprintf(stderr, "%s: %zux%zu, %zu bytes differ from the first pixel\n", argv[1], w, h, differ);
        return 1;
    }
    return 0;
}
