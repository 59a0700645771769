/* The tool tests' look at PNG files, read by the strict reader tests/support/png_reader.h (every
 * CRC, the deflate data and the Adler-32 verified):
 *   png_check FILE W H
 *       exit 0 if FILE is a valid PNG of W x H pixels whose picture is not one flat colour; else
 *       print why and exit 1.
 *   png_check --colors FILE X0 Y0 X1 Y1
 *       print how many pixels of the rectangle X0..X1 x Y0..Y1 (inclusive) are
 *         red      R > 2 max(G, B) and R >= 30
 *         blue     B > 1.8 R and B > G + 20
 *         neutral  max - min <= 12 and min >= 40 (greys, not too dark)
 *         dark     max < 60 (text)
 *       as "red N blue N neutral N dark N total N"; exit 1 if the rectangle is not inside.
 *   png_check --compare FILE OTHER TOL
 *       two pictures of the same size: print "differ N silhouette N total N", N the pixels where
 *       a channel differs by more than TOL, and those that are surface in one picture and
 *       background in the other, a surface pixel being one whose green and blue differ by at
 *       most 1 (true of a surface drawn in the base colour 1,0,0 without supersampling: lights
 *       scale the 0 of green and blue alike and the highlight adds the same to both, while the
 *       background's blue exceeds its green by at least 7). */
#include "png_reader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_picture(const unsigned char *rgb, size_t w, size_t h, char **argv)
{
    int ok = w == strtoul(argv[2], NULL, 10) && h == strtoul(argv[3], NULL, 10);
    size_t differ = 0;
    for (size_t k = 3; k < 3 * w * h; k++)
        differ += rgb[k] != rgb[k % 3];
    if (!ok || differ < w * h / 20) {
        fprintf(stderr, "%s: %zux%zu, %zu bytes differ from the first pixel\n", argv[1], w, h, differ);
        return 1;
    }
    return 0;
}

static int count_colors(const unsigned char *rgb, size_t w, size_t h, char **argv)
{
    size_t x0 = strtoul(argv[2], NULL, 10), y0 = strtoul(argv[3], NULL, 10);
    size_t x1 = strtoul(argv[4], NULL, 10), y1 = strtoul(argv[5], NULL, 10);
    if (x0 > x1 || y0 > y1 || x1 >= w || y1 >= h) {
        fprintf(stderr, "%s: rectangle outside the %zux%zu picture\n", argv[1], w, h);
        return 1;
    }
    size_t red = 0, blue = 0, neutral = 0, dark = 0;
    for (size_t y = y0; y <= y1; y++)
        for (size_t x = x0; x <= x1; x++) {
            int r = rgb[3 * (y * w + x)], g = rgb[3 * (y * w + x) + 1], b = rgb[3 * (y * w + x) + 2];
            int hi = r > g ? (r > b ? r : b) : (g > b ? g : b), lo = r < g ? (r < b ? r : b) : (g < b ? g : b);
            red += r > 2 * (g > b ? g : b) && r >= 30;
            blue += 10 * b > 18 * r && b > g + 20;
            neutral += hi - lo <= 12 && lo >= 40;
            dark += hi < 60;
        }
    printf("red %zu blue %zu neutral %zu dark %zu total %zu\n", red, blue, neutral, dark,
           (x1 - x0 + 1) * (y1 - y0 + 1));
    return 0;
}

static int is_surface(const unsigned char *px) { return px[1] - px[2] <= 1 && px[2] - px[1] <= 1; }

static int compare(const unsigned char *rgb, size_t w, size_t h, char **argv)
{
    size_t w2 = 0, h2 = 0, differ = 0, silhouette = 0;
    unsigned char *other = NULL;
    const char *why = png_read_file(argv[2], &w2, &h2, &other);
    if (why != NULL || w2 != w || h2 != h) {
        fprintf(stderr, "%s: %s\n", argv[2], why ? why : "not the same size");
        free(other);
        return 1;
    }
    int tol = atoi(argv[3]);
    for (size_t i = 0; i < w * h; i++) {
        const unsigned char *a = rgb + 3 * i, *b = other + 3 * i;
        int far = 0;
        for (int k = 0; k < 3; k++)
            far |= a[k] - b[k] > tol || b[k] - a[k] > tol;
        differ += (size_t)far;
        silhouette += (size_t)(is_surface(a) != is_surface(b));
    }
    printf("differ %zu silhouette %zu total %zu\n", differ, silhouette, w * h);
    free(other);
    return 0;
}

int main(int argc, char **argv)
{
    int colors = argc > 1 && strcmp(argv[1], "--colors") == 0;
    int cmp = argc > 1 && strcmp(argv[1], "--compare") == 0;
    if (argc != (colors ? 7 : cmp ? 5 : 4)) {
        fprintf(stderr, "usage: png_check FILE W H | png_check --colors FILE X0 Y0 X1 Y1 |\n"
                        "       png_check --compare FILE OTHER TOL\n");
        return 2;
    }
    char **args = argv + (colors || cmp); /* args[1] is the file */
    size_t w = 0, h = 0;
    unsigned char *rgb = NULL;
    const char *why = png_read_file(args[1], &w, &h, &rgb);
    if (why != NULL) {
        fprintf(stderr, "%s: %s\n", args[1], why);
        return 1;
    }
    int rc = colors ? count_colors(rgb, w, h, args) : cmp ? compare(rgb, w, h, args) : check_picture(rgb, w, h, args);
    free(rgb);
    return rc;
}
