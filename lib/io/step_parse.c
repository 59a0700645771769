/* STEP instances by number, typed access to their parameters (every failure names the instance,
 * its line and column), and the plane angle unit of the file. */
#include "io/step.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void bsi_stp_free(stp *s)
{
    free(s->nodes.data);
    free(s->inst.data);
    free(s->order);
    free(s->edge_id);
    free(s->busy);
    free(s->flip);
    bsi_stp_assembly_free(s);
    memset(s, 0, sizeof *s);
}

/* Sorting by id without global state: the ids are gathered next to the indices. */
typedef struct idpair {
    size_t id, index;
} idpair;

static int by_id(const void *a, const void *b)
{
    const idpair *x = a, *y = b;
    return x->id < y->id ? -1 : x->id > y->id;
}

bs_status bsi_stp_index(stp *s)
{
    size_t n = s->inst.n;
    idpair *p = malloc((n ? n : 1) * sizeof *p);
    s->order = malloc((n ? n : 1) * sizeof *s->order);
    s->edge_id = malloc((n ? n : 1) * sizeof *s->edge_id);
    s->busy = calloc(n ? n : 1, 1);
    s->flip = calloc(n ? n : 1, 1);
    if (p == NULL || s->order == NULL || s->edge_id == NULL || s->busy == NULL || s->flip == NULL) {
        free(p);
        return BS_ERR_NO_MEMORY;
    }
    for (size_t k = 0; k < n; k++) {
        p[k].id = stp_inst_at(s, k)->id;
        p[k].index = k;
        s->edge_id[k] = BSI_NO_EDGE;
    }
    qsort(p, n, sizeof *p, by_id);
    for (size_t k = 0; k < n; k++) {
        if (k > 0 && p[k].id == p[k - 1].id) {
            size_t later = p[k].index > p[k - 1].index ? p[k].index : p[k - 1].index;
            free(p);
            return bsi_stp_fail(s, later, "entity number defined twice");
        }
        s->order[k] = p[k].index;
    }
    free(p);
    return BS_OK;
}

int bsi_stp_find(const stp *s, size_t id, size_t *i)
{
    size_t lo = 0, hi = s->inst.n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2, at = stp_inst_at(s, s->order[mid])->id;
        if (at == id) {
            *i = s->order[mid];
            return 1;
        }
        if (at < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return 0;
}

static int named(const stp *s, size_t n, const char *name)
{
    const stp_node *t = stp_at(s, n);
    size_t w = strlen(name);
    return t->kind == STP_TYPED && t->len == w && memcmp(s->text + t->v.off, name, w) == 0;
}

int bsi_stp_part(const stp *s, size_t i, const char *name, size_t *list)
{
    size_t root = stp_inst_at(s, i)->root;
    const stp_node *r = stp_at(s, root);
    if (r->kind == STP_TYPED) {
        if (!named(s, root, name))
            return 0;
        *list = root + 1;
        return 1;
    }
    for (size_t k = 0, n = root + 1; k < r->count; k++, n += stp_at(s, n)->span)
        if (named(s, n, name)) {
            *list = n + 1;
            return 1;
        }
    return 0;
}

int bsi_stp_is(const stp *s, size_t i, const char *name)
{
    size_t list;
    return bsi_stp_part(s, i, name, &list);
}

const char *bsi_stp_name(const stp *s, size_t i, int *len)
{
    size_t root = stp_inst_at(s, i)->root;
    const stp_node *r = stp_at(s, root);
    if (r->kind != STP_TYPED) {
        if (r->count == 0) {
            *len = 2;
            return "()";
        }
        r = stp_at(s, root + 1);
    }
    *len = (int)r->len;
    return s->text + r->v.off;
}

int bsi_stp_arg(const stp *s, size_t list, size_t k, size_t *node)
{
    const stp_node *l = stp_at(s, list);
    if (l->kind != STP_LIST || k >= l->count)
        return 0;
    size_t n = list + 1;
    for (size_t j = 0; j < k; j++)
        n += stp_at(s, n)->span;
    *node = n;
    return 1;
}

bs_status bsi_stp_fail(const stp *s, size_t i, const char *fmt, ...)
{
    const stp_inst *in = stp_inst_at(s, i);
    char msg[200];
    int len;
    const char *name = bsi_stp_name(s, i, &len);
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(msg, sizeof msg, fmt, ap); /* NOLINT(clang-analyzer-valist.Uninitialized): va_start is above */
    va_end(ap);
    return bsi_fail(s->err, in->line, in->col, "#%zu %.*s: %s", in->id, len > 60 ? 60 : len, name, msg);
}

int bsi_stp_number(const stp *s, size_t n, double *x)
{
    if (stp_at(s, n)->kind == STP_TYPED && stp_at(s, n + 1)->count == 1) /* LENGTH_MEASURE(1.) and the like */
        n += 2;
    if (stp_at(s, n)->kind != STP_INT && stp_at(s, n)->kind != STP_REAL)
        return 0;
    *x = stp_at(s, n)->v.num;
    return 1;
}

bs_status bsi_stp_num(const stp *s, size_t i, size_t list, size_t k, const char *what, double *x)
{
    size_t n;
    if (!bsi_stp_arg(s, list, k, &n))
        return bsi_stp_fail(s, i, "%s missing", what);
    if (!bsi_stp_number(s, n, x))
        return bsi_stp_fail(s, i, "%s must be a number", what);
    return BS_OK;
}

bs_status bsi_stp_deref(const stp *s, size_t i, size_t n, const char *what, size_t *ref)
{
    const stp_node *v = stp_at(s, n);
    if (v->kind != STP_REF)
        return bsi_stp_fail(s, i, "%s must be a reference #N", what);
    if (!bsi_stp_find(s, v->v.ref, ref))
        return bsi_stp_fail(s, i, "%s refers to #%zu, which is not defined", what, v->v.ref);
    return BS_OK;
}

bs_status bsi_stp_ref(const stp *s, size_t i, size_t list, size_t k, const char *what, size_t *ref)
{
    size_t n;
    if (!bsi_stp_arg(s, list, k, &n))
        return bsi_stp_fail(s, i, "%s missing", what);
    return bsi_stp_deref(s, i, n, what, ref);
}

bs_status bsi_stp_list(const stp *s, size_t i, size_t list, size_t k, const char *what, size_t *node)
{
    if (!bsi_stp_arg(s, list, k, node))
        return bsi_stp_fail(s, i, "%s missing", what);
    if (stp_at(s, *node)->kind != STP_LIST)
        return bsi_stp_fail(s, i, "%s must be a list", what);
    return BS_OK;
}

bs_status bsi_stp_bool(const stp *s, size_t i, size_t list, size_t k, const char *what, int *b)
{
    size_t n;
    if (!bsi_stp_arg(s, list, k, &n))
        return bsi_stp_fail(s, i, "%s missing", what);
    const stp_node *v = stp_at(s, n);
    if (v->kind == STP_ENUM && v->len == 1 && (s->text[v->v.off] == 'T' || s->text[v->v.off] == 'F')) {
        *b = s->text[v->v.off] == 'T';
        return BS_OK;
    }
    return bsi_stp_fail(s, i, "%s must be .T. or .F.", what);
}

int bsi_stp_enum(const stp *s, size_t n, const char *word)
{
    const stp_node *v = stp_at(s, n);
    size_t w = strlen(word);
    return v->kind == STP_ENUM && v->len == w && memcmp(s->text + v->v.off, word, w) == 0;
}

/* Radians per unit of the plane angle unit at instance u (SI radian, or converted). */
static bs_status angle_unit(const stp *s, size_t u, int depth, double *out)
{
    size_t list = 0, n = 0, m = 0;
    if (depth > STP_DEPTH)
        return bsi_stp_fail(s, u, "units defined in a cycle");
    if (bsi_stp_part(s, u, "SI_UNIT", &list)) {
        if (!bsi_stp_arg(s, list, 1, &n) || !bsi_stp_enum(s, n, "RADIAN"))
            return bsi_stp_fail(s, u, "a plane angle unit of the SI must be the radian");
        *out = 1.0;
        return BS_OK;
    }
    if (!bsi_stp_part(s, u, "CONVERSION_BASED_UNIT", &list))
        return bsi_stp_fail(s, u, "plane angle unit not understood");
    double f = 0.0, base = 0.0;
    bs_status st;
    if ((st = bsi_stp_ref(s, u, list, 1, "the conversion factor", &m)) != BS_OK)
        return st;
    if (!bsi_stp_part(s, m, "PLANE_ANGLE_MEASURE_WITH_UNIT", &list) &&
        !bsi_stp_part(s, m, "MEASURE_WITH_UNIT", &list))
        return bsi_stp_fail(s, m, "expected a PLANE_ANGLE_MEASURE_WITH_UNIT");
    if ((st = bsi_stp_num(s, m, list, 0, "the factor", &f)) != BS_OK ||
        (st = bsi_stp_ref(s, m, list, 1, "the unit", &n)) != BS_OK || (st = angle_unit(s, n, depth + 1, &base)) != BS_OK)
        return st;
    if (!(f * base > 0.0) || !(f * base < 1e3))
        return bsi_stp_fail(s, m, "plane angle conversion factor out of range");
    *out = f * base;
    return BS_OK;
}

bs_status bsi_stp_units(stp *s)
{
    s->angle = 1.0;
    for (size_t i = 0; i < s->inst.n; i++)
        if (bsi_stp_is(s, i, "PLANE_ANGLE_UNIT"))
            return angle_unit(s, i, 0, &s->angle);
    return BS_OK;
}
