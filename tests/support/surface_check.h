/* Helpers shared by the file-format tests: bit-for-bit comparison of two surfaces, the point of
 * one patch at one parameter, switching to a locale whose decimal point is a comma. */
#ifndef BS_TEST_SURFACE_CHECK_H
#define BS_TEST_SURFACE_CHECK_H

#include <bezsurf.h>

#include <locale.h>
#include <stdlib.h>
#include <string.h>

/* All degrees, dimensions, control points and weights of two surfaces are bitwise equal. */
static inline int surface_same_bits(const bs_surface *a, const bs_surface *b)
{
    if (a == NULL || b == NULL || bs_surface_count(a) != bs_surface_count(b))
        return 0;
    for (size_t k = 0; k < bs_surface_count(a); k++) {
        const bs_patch *p = bs_surface_get(a, k), *q = bs_surface_get(b, k);
        if (bs_patch_degree_u(p) != bs_patch_degree_u(q) || bs_patch_degree_v(p) != bs_patch_degree_v(q) ||
            bs_patch_dim(p) != bs_patch_dim(q) || bs_patch_is_rational(p) != bs_patch_is_rational(q))
            return 0;
        size_t n = (bs_patch_degree_u(p) + 1) * (bs_patch_degree_v(p) + 1), dim = bs_patch_dim(p);
        double *cp = malloc(2 * n * (dim + 1) * sizeof(double)), *cq = cp + n * dim;
        double *wp = cp + 2 * n * dim, *wq = wp + n;
        int same = cp != NULL && bs_patch_get_ctrl(p, cp, n * dim, wp, n) == BS_OK &&
                   bs_patch_get_ctrl(q, cq, n * dim, wq, n) == BS_OK &&
                   memcmp(cp, cq, n * dim * sizeof(double)) == 0 &&
                   (!bs_patch_is_rational(p) || memcmp(wp, wq, n * sizeof(double)) == 0);
        free(cp);
        if (!same)
            return 0;
    }
    return 1;
}

/* The point of 3-D patch p at (u,v) into xyz; 0 when evaluation fails. */
static inline int patch_point(const bs_patch *p, double u, double v, double *xyz)
{
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view pos[3] = {{&xyz[0], 1, 0}, {&xyz[1], 1, 0}, {&xyz[2], 1, 0}};
    return p != NULL && bs_patch_eval(p, 1, &cu, &cv, pos, NULL, NULL) == BS_OK;
}

/* Switch LC_ALL to an installed locale with a decimal comma (German, else French): its name, or
 * NULL when there is none. */
static inline const char *switch_to_comma_locale(void)
{
    static const char *const names[] = {"de_DE.UTF-8", "de_DE.utf8", "de_DE", "de_DE@euro", "fr_FR.UTF-8"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (setlocale(LC_ALL, names[k]) != NULL && strcmp(localeconv()->decimal_point, ",") == 0)
            return names[k];
    return NULL;
}

#endif
