/* Small IGES files written for the model reader's tests: fixed-column records of entities given
 * by their parameters, read as a model. */
#ifndef BS_TEST_IGES_TEXT_H
#define BS_TEST_IGES_TEXT_H

#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct ent {
    long type, form, xform; /* xform: DE number of a 124, or 0 */
    const char *par;        /* the parameters, from the type on, ended by ';' */
} ent;

/* Fixed-column records: S, G, two D records per entity, P records (64 columns, back pointer to
 * the entity's DE), T. back_fix: the DE number written as back pointer of entity 0 (0: right). */
static inline char *iges_text(const ent *e, size_t n, long back_fix, size_t *len)
{
    size_t cap = 4096 + n * 400;
    for (size_t k = 0; k < n; k++)
        cap += strlen(e[k].par) / 64 * 81 + 81;
    char *t = malloc(cap);
    size_t at = 0, p = 1;
    at += (size_t)sprintf(t + at, "%-72sS%7d\n", "", 1);
    at += (size_t)sprintf(t + at, "%-72sG%7d\n", ",,;", 1);
    for (size_t k = 0; k < n; k++) {
        size_t lines = (strlen(e[k].par) + 63) / 64;
        at += (size_t)sprintf(t + at, "%8ld%8zu%8d%8d%8d%8d%8ld%8d%8s", e[k].type, p, 0, 0, 0, 0, e[k].xform, 0,
                              "00000000");
        at += (size_t)sprintf(t + at, "D%7zu\n", 2 * k + 1);
        at += (size_t)sprintf(t + at, "%8ld%8d%8d%8zu%8ld%8s%8s%8s%8s", e[k].type, 0, 0, lines, e[k].form, "", "",
                              "", "0");
        at += (size_t)sprintf(t + at, "D%7zu\n", 2 * k + 2);
        p += lines;
    }
    size_t seq = 1;
    for (size_t k = 0; k < n; k++) {
        size_t len0 = strlen(e[k].par);
        long back = k == 0 && back_fix ? back_fix : (long)(2 * k + 1);
        for (size_t o = 0; o < len0; o += 64)
            at += (size_t)sprintf(t + at, "%-64.64s %07ldP%7zu\n", e[k].par + o, back, seq++);
    }
    at += (size_t)sprintf(t + at, "S%7dG%7dD%7zuP%7zu%40sT%7d\n", 1, 1, 2 * n, seq - 1, "", 1);
    *len = at;
    return t;
}

static inline bs_status read_ents(const ent *e, size_t n, long back_fix, bs_parse_error *err, bs_model **m)
{
    size_t len;
    char *t = iges_text(e, n, back_fix, &len);
    bs_status st = bs_model_read_iges(t, len, err, m);
    free(t);
    return st;
}

#endif
