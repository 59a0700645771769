/* A minimal .bpt reader for tests only (polynomial patches, whitespace separated). The library's
 * own reader is tested elsewhere; this one keeps the tessellation tests independent of it. */
#ifndef BS_TEST_BPT_READER_H
#define BS_TEST_BPT_READER_H

#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>

#ifndef BS_DATA_DIR
#define BS_DATA_DIR "data"
#endif

/* Load BS_DATA_DIR/name into a new surface; NULL on any error. */
static bs_surface *test_load_bpt(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", BS_DATA_DIR, name);
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return NULL;
    bs_surface *s = NULL;
    size_t np = 0;
    int ok = fscanf(f, "%zu", &np) == 1 && bs_surface_create(&s) == BS_OK;
    for (size_t k = 0; ok && k < np; k++) {
        size_t m = 0, n = 0;
        ok = fscanf(f, "%zu %zu", &m, &n) == 2 && m <= 64 && n <= 64;
        if (!ok)
            break;
        size_t cnt = (m + 1) * (n + 1) * 3;
        double *net = malloc(cnt * sizeof(double));
        ok = net != NULL;
        for (size_t i = 0; ok && i < cnt; i++)
            ok = fscanf(f, "%lf", &net[i]) == 1;
        bs_patch *p = NULL;
        ok = ok && bs_patch_create(m, n, 3, net, NULL, &p) == BS_OK && bs_surface_add(s, p, NULL) == BS_OK;
        bs_patch_destroy(p);
        free(net);
    }
    fclose(f);
    if (!ok) {
        bs_surface_destroy(s);
        return NULL;
    }
    return s;
}

#endif
