/* The built-in tea set: patch counts, the centre of every teapot patch in one batched call, the
 * seams of the teapot, and the teacup written as .bpt text into a caller buffer. */
#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    for (size_t i = 0; bs_builtin_name(i) != NULL; i++) {
        bs_surface *s;
        if (bs_surface_create_builtin(bs_builtin_name(i), &s) != BS_OK)
            return 1;
        printf("%-9s %zu patches\n", bs_builtin_name(i), bs_surface_count(s));
        bs_surface_destroy(s);
    }

    bs_surface *pot;
    if (bs_surface_create_builtin("teapot", &pot) != BS_OK)
        return 1;
    enum { N = 32 };
    uint32_t ids[N];
    double half[N], x[N], y[N], z[N];
    for (uint32_t k = 0; k < N; k++)
        ids[k] = k, half[k] = 0.5;
    bs_cview uv = {half, N, 0};
    bs_view pos[3] = {{x, N, 0}, {y, N, 0}, {z, N, 0}};
    if (bs_surface_eval(pot, N, ids, &uv, &uv, pos, NULL, NULL) != BS_OK)
        return 1;
    size_t top = 0;
    for (size_t k = 1; k < N; k++)
        top = z[k] > z[top] ? k : top;
    printf("highest patch centre: patch %zu at (%g, %g, %g)\n", top, x[top], y[top], z[top]);

    size_t shared = 0, open = 0;
    if (bs_surface_continuity(pot, 1e-9, 16, NULL, 0, &shared, NULL, 0, &open) != BS_OK)
        return 1;
    printf("teapot: %zu shared edges, %zu open edges\n", shared, open);
    bs_surface_destroy(pot);

    bs_surface *cup;
    size_t size = 0;
    if (bs_surface_create_builtin("teacup", &cup) != BS_OK || bs_surface_write_bpt(cup, NULL, 0, &size) != BS_OK)
        return 1;
    char *text = malloc(size);
    int ok = text != NULL && bs_surface_write_bpt(cup, text, size, &size) == BS_OK;
    if (ok)
        printf("teacup as .bpt: %zu bytes of text\n", size - 1);
    free(text);
    bs_surface_destroy(cup);
    return ok ? 0 : 1;
}
