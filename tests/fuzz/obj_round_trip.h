/* The OBJ round trip both free-form fuzz targets check: a surface that was read writes, reads
 * back and writes again to the same text; abort() otherwise. */
#ifndef BS_FUZZ_OBJ_ROUND_TRIP_H
#define BS_FUZZ_OBJ_ROUND_TRIP_H

#include <bezsurf.h>

#include <stdlib.h>
#include <string.h>

static void obj_round_trip(const bs_surface *s)
{
    size_t n1 = 0, n2 = 0;
    if (bs_surface_write_obj(s, NULL, 0, &n1) != BS_OK)
        abort();
    char *a = malloc(n1), *b = malloc(n1);
    bs_surface *t = NULL;
    if (a == NULL || b == NULL || bs_surface_write_obj(s, a, n1, &n1) != BS_OK ||
        bs_surface_read_obj(a, n1 - 1, NULL, &t) != BS_OK || bs_surface_write_obj(t, b, n1, &n2) != BS_OK ||
        n1 != n2 || memcmp(a, b, n1) != 0)
        abort();
    free(a);
    free(b);
    bs_surface_destroy(t);
}

#endif
