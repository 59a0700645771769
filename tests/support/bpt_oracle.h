/* Test-side reading of .bpt files, independent of lib/: the whole file through strtod() in the C
 * locale, for comparing the library's reader with. Plain (non-rational) bicubic files only. */
#ifndef BS_TEST_BPT_ORACLE_H
#define BS_TEST_BPT_ORACLE_H

#include <stdio.h>
#include <stdlib.h>

typedef struct oracle_bpt {
    size_t npatch;
    size_t deg[64][2];
    double ctrl[64][16 * 3]; /* bicubic or smaller only */
} oracle_bpt;

/* Reads the whole file into a NUL-terminated buffer; *len receives its size. NULL on failure. */
static inline char *oracle_slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    char *buf = malloc(1 << 20);
    size_t n = buf ? fread(buf, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    if (buf)
        buf[n] = '\0';
    *len = n;
    return buf;
}

/* 1 on success. */
static inline int oracle_parse(const char *text, oracle_bpt *o)
{
    char *end;
    const char *p = text;
    o->npatch = (size_t)strtoul(p, &end, 10);
    if (end == p || o->npatch > 64)
        return 0;
    for (size_t k = 0; k < o->npatch; k++) {
        p = end;
        o->deg[k][0] = (size_t)strtoul(p, &end, 10);
        p = end;
        o->deg[k][1] = (size_t)strtoul(p, &end, 10);
        size_t npts = (o->deg[k][0] + 1) * (o->deg[k][1] + 1);
        if (end == p || npts > 16)
            return 0;
        for (size_t i = 0; i < 3 * npts; i++) {
            p = end;
            o->ctrl[k][i] = strtod(p, &end);
            if (end == p)
                return 0;
        }
    }
    return 1;
}

#endif
