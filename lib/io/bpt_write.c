/* Writing the .bpt text format: shortest exact decimals, '.' as decimal point in every locale. */
#include "io/internal.h"

#include <stdio.h>
#include <string.h>

/* Appends to buf while there is room and counts every byte, so one routine both measures and writes. */
typedef struct sink {
    char *buf;
    size_t cap, len;
} sink;

static void put(sink *o, const char *text, size_t n)
{
    if (o->buf != NULL && o->len + n <= o->cap)
        memcpy(o->buf + o->len, text, n);
    o->len += n;
}

static void put_size(sink *o, size_t v)
{
    char tmp[32];
    int n = snprintf(tmp, sizeof tmp, "%zu", v);
    put(o, tmp, (size_t)n);
}

static void put_double(sink *o, double x)
{
    char tmp[32];
    put(o, tmp, bsi_format_double(x, tmp));
}

/* The text without a final NUL; o->len is its length even when it did not fit. */
static void emit(const bs_surface *s, sink *o)
{
    size_t count = bs_surface_count(s);
    put_size(o, count);
    put(o, "\n", 1);
    for (size_t k = 0; k < count; k++) {
        const bs_patch *p = bs_surface_get(s, k);
        put_size(o, p->deg_u);
        put(o, " ", 1);
        put_size(o, p->deg_v);
        put(o, p->rational ? " w\n" : "\n", p->rational ? 3 : 1);
        for (size_t i = 0; i < p->nctrl; i++) {
            for (size_t c = 0; c < 3; c++) {
                if (c > 0)
                    put(o, " ", 1);
                put_double(o, p->ctrl[3 * i + c]);
            }
            if (p->rational) {
                put(o, " ", 1);
                put_double(o, p->weights[i]);
            }
            put(o, "\n", 1);
        }
    }
}

bs_status bs_surface_write_bpt(const bs_surface *s, char *buf, size_t cap, size_t *size)
{
    if (size == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st = bsi_check_surface3(s);
    if (st != BS_OK)
        return st;
    sink measure = {NULL, 0, 0};
    emit(s, &measure);
    size_t need = measure.len + 1;
    if (buf != NULL) {
        if (cap < need)
            return BS_ERR_SIZE;
        sink o = {buf, cap, 0};
        emit(s, &o);
        buf[o.len] = '\0';
    }
    *size = need;
    return BS_OK;
}

bs_status bs_surface_write_bpt_file(const bs_surface *s, const char *path)
{
    return bsi_write_surface_file(s, path, bs_surface_write_bpt); /* atomic, as every writer */
}
