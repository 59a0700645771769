/* Tokens of the OBJ model reader: a statement is a logical line (a backslash ending a line joins
 * the next), `#` starts a comment; numbers and indices with the position of every error. The
 * rules are those of the surface reader (obj_read.c). */
#include "io/obj_model.h"

#include <string.h>

int bsi_objm_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bs_status bsi_objm_fail(objm *o, size_t at, const char *fmt, const char *arg)
{
    return bsi_fail(o->err, o->line, at - o->line_start + 1, fmt, arg);
}

/* Offset just past a backslash at `at` that continues the line, or 0 when it does not. */
static size_t continuation(const objm *o, size_t at)
{
    size_t k = at + 1;
    while (k < o->len && bsi_objm_blank(o->text[k]))
        k++;
    if (k >= o->len)
        return k;
    return o->text[k] == '\n' ? k + 1 : 0;
}

int bsi_objm_token(objm *o, size_t *start, size_t *tlen)
{
    for (;;) {
        if (o->pos >= o->len || o->text[o->pos] == '\n')
            return 0;
        char c = o->text[o->pos];
        if (bsi_objm_blank(c)) {
            o->pos++;
            continue;
        }
        if (c == '#') {
            while (o->pos < o->len && o->text[o->pos] != '\n')
                o->pos++;
            return 0;
        }
        size_t next = c == '\\' ? continuation(o, o->pos) : 0;
        if (next != 0) {
            if (o->text[next - 1] == '\n') {
                o->line++;
                o->line_start = next;
            }
            o->pos = next;
            continue;
        }
        *start = o->pos;
        while (o->pos < o->len && o->text[o->pos] != '\n' && !bsi_objm_blank(o->text[o->pos]) &&
               !(o->text[o->pos] == '\\' && o->pos > *start && continuation(o, o->pos) != 0))
            o->pos++;
        *tlen = o->pos - *start;
        return 1;
    }
}

void bsi_objm_end_line(objm *o)
{
    size_t start, tlen;
    while (bsi_objm_token(o, &start, &tlen))
        ;
    if (o->pos < o->len) {
        o->pos++;
        o->line++;
        o->line_start = o->pos;
    }
}

int bsi_objm_is(const objm *o, size_t start, size_t tlen, const char *word)
{
    return tlen == strlen(word) && memcmp(o->text + start, word, tlen) == 0;
}

bs_status bsi_objm_number(objm *o, size_t start, size_t tlen, const char *what, double *x)
{
    int ok = bsi_parse_double(o->text + start, tlen, x);
    if (ok <= 0)
        return bsi_objm_fail(o, start, bsi_parse_double_says(ok), what);
    return BS_OK;
}

bs_status bsi_objm_read_number(objm *o, const char *what, double *x)
{
    size_t start, tlen;
    if (!bsi_objm_token(o, &start, &tlen))
        return bsi_objm_fail(o, o->pos, "expected %s", what);
    return bsi_objm_number(o, start, tlen, what, x);
}

bs_status bsi_objm_no_more(objm *o, const char *statement)
{
    size_t start, tlen;
    if (bsi_objm_token(o, &start, &tlen))
        return bsi_objm_fail(o, start, "unexpected value after the %s statement", statement);
    return BS_OK;
}

bs_status bsi_objm_index(objm *o, size_t start, size_t tlen, size_t n, const char *what, size_t *idx)
{
    const char *t = o->text + start;
    size_t k = 0, i = 0;
    while (k < tlen && t[k] != '/')
        k++;
    int neg = k > 0 && t[0] == '-';
    int ok = bsi_parse_size(t + neg, k - (size_t)neg, SIZE_MAX, &i);
    if (ok == 0 || (ok > 0 && i == 0))
        return bsi_objm_fail(o, start, "expected a %s index (a non-zero integer)", what);
    if (ok < 0 || i > n)
        return bsi_objm_fail(o, start, neg ? "relative %s index before the first one"
                                           : "%s index beyond those defined so far", what);
    *idx = neg ? n - i : i - 1;
    return BS_OK;
}

bs_status bsi_objm_spend(objm *o, size_t points, size_t line, size_t col)
{
    if (points > o->points_left) {
        (void)bsi_fail(o->err, line, col, "more geometry than %zu control points (16 per input byte)",
                       OBJM_POINTS(o->len));
        return BS_ERR_SIZE;
    }
    o->points_left -= points;
    return BS_OK;
}
