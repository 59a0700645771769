/* STEP assemblies: which representation holds each shell, and where that representation is
 * placed. A part is placed in its assembly by a REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION
 * (the complex instance a CONTEXT_DEPENDENT_SHAPE_REPRESENTATION points to) or by a MAPPED_ITEM
 * among the assembly's items; relationships without a motion join two representations of one
 * shape into a class. A shell's placements are the paths from its class up to the roots (classes
 * placed nowhere), their motions composed; each placement is one instance. Counts are taken
 * before anything is placed, so that nesting cannot multiply work beyond the reader's cap. */
#include "io/step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ASM_DEPTH 32 /* deepest nesting of assemblies followed */

void bsi_stp_assembly_free(stp *s)
{
    free(s->as.cls);
    free(s->as.holder);
    free(s->as.count);
    free(s->as.base);
    free(s->as.busy);
    free(s->as.links.data);
    memset(&s->as, 0, sizeof s->as);
}

/* The class of instance i, halving the path to it on the way (joins in an adversarial order would
 * otherwise chain the classes and make each find linear). */
static size_t find(stp *s, size_t i)
{
    while (s->as.cls[i] != i) {
        s->as.cls[i] = s->as.cls[s->as.cls[i]];
        i = s->as.cls[i];
    }
    return i;
}

static void join(stp *s, size_t a, size_t b)
{
    a = find(s, a);
    b = find(s, b);
    if (a != b) /* the earlier instance stays the root: classes do not depend on the order of joins */
        s->as.cls[a > b ? a : b] = a < b ? a : b;
}

/* The items of representation instance i: 1 and their LIST node, or 0 when i is not one (a
 * REPRESENTATION, simple or a part of a complex instance, or any simple *_REPRESENTATION: name,
 * items, context). */
static int rep_items(const stp *s, size_t i, size_t *items)
{
    static const char tail[] = "_REPRESENTATION";
    const size_t tl = sizeof tail - 1;
    size_t list = stp_inst_at(s, i)->root + 1, n, ctx;
    if (!bsi_stp_part(s, i, "REPRESENTATION", &list)) {
        int len;
        const char *name = bsi_stp_name(s, i, &len);
        if (stp_at(s, list - 1)->kind != STP_TYPED || (size_t)len < tl || memcmp(name + (size_t)len - tl, tail, tl) != 0)
            return 0;
    }
    if (!bsi_stp_arg(s, list, 1, &n) || stp_at(s, n)->kind != STP_LIST || !bsi_stp_arg(s, list, 2, &ctx) ||
        stp_at(s, ctx)->kind != STP_REF)
        return 0;
    *items = n;
    return 1;
}

/* Metres per length unit u (0 when it is not understood). */
static double unit_metres(const stp *s, size_t u, int depth)
{
    static const struct {
        const char *name;
        double f;
    } prefix[] = {{"EXA", 1e18},  {"PETA", 1e15}, {"TERA", 1e12},  {"GIGA", 1e9},  {"MEGA", 1e6},  {"KILO", 1e3},
                  {"HECTO", 1e2}, {"DECA", 1e1},  {"DECI", 1e-1},  {"CENTI", 1e-2}, {"MILLI", 1e-3}, {"MICRO", 1e-6},
                  {"NANO", 1e-9}, {"PICO", 1e-12}, {"FEMTO", 1e-15}, {"ATTO", 1e-18}};
    size_t list, n, m;
    double f;
    if (depth > STP_DEPTH)
        return 0.0;
    if (bsi_stp_part(s, u, "SI_UNIT", &list)) {
        if (!bsi_stp_arg(s, list, 0, &n) || stp_at(s, n)->kind != STP_ENUM)
            return 1.0;
        for (size_t k = 0; k < sizeof prefix / sizeof prefix[0]; k++)
            if (bsi_stp_enum(s, n, prefix[k].name))
                return prefix[k].f;
        return 0.0;
    }
    if (!bsi_stp_part(s, u, "CONVERSION_BASED_UNIT", &list) || !bsi_stp_arg(s, list, 1, &n) ||
        stp_at(s, n)->kind != STP_REF || !bsi_stp_find(s, stp_at(s, n)->v.ref, &m) ||
        (!bsi_stp_part(s, m, "LENGTH_MEASURE_WITH_UNIT", &list) && !bsi_stp_part(s, m, "MEASURE_WITH_UNIT", &list)) ||
        !bsi_stp_arg(s, list, 0, &n) || !bsi_stp_number(s, n, &f) || !bsi_stp_arg(s, list, 1, &n) ||
        stp_at(s, n)->kind != STP_REF || !bsi_stp_find(s, stp_at(s, n)->v.ref, &u))
        return 0.0;
    return f * unit_metres(s, u, depth + 1);
}

/* Metres per length unit of the context of representation rep (0 when it names none). */
static double rep_metres(const stp *s, size_t rep)
{
    size_t items, ctx, list, units, n, u;
    if (!rep_items(s, rep, &items) || !bsi_stp_find(s, stp_at(s, items + stp_at(s, items)->span)->v.ref, &ctx) ||
        !bsi_stp_part(s, ctx, "GLOBAL_UNIT_ASSIGNED_CONTEXT", &list) || !bsi_stp_arg(s, list, 0, &units))
        return 0.0;
    for (size_t k = 0; bsi_stp_arg(s, units, k, &n); k++)
        if (stp_at(s, n)->kind == STP_REF && bsi_stp_find(s, stp_at(s, n)->v.ref, &u) && bsi_stp_is(s, u, "LENGTH_UNIT"))
            return unit_metres(s, u, 0);
    return 0.0;
}

/* The motion taking placement a (in the part) onto placement b (in the assembly): F_b F_a^-1,
 * F the map from a frame's coordinates to its representation's. */
static bs_status motion(const stp *s, size_t a, size_t b, stp_xf *m)
{
    bsi_frame fa, fb;
    bs_status st;
    for (int k = 0; k < 2; k++)
        if (!bsi_stp_is(s, k ? b : a, "AXIS2_PLACEMENT_3D")) {
            (void)bsi_stp_fail(s, k ? b : a, "%s", "assembly placements other than AXIS2_PLACEMENT_3D are not supported");
            return BS_ERR_UNSUPPORTED;
        }
    if ((st = bsi_stp_placement(s, a, 3, &fa)) != BS_OK || (st = bsi_stp_placement(s, b, 3, &fb)) != BS_OK)
        return st;
    for (size_t r = 0; r < 3; r++) {
        for (size_t c = 0; c < 3; c++)
            m->r[3 * r + c] = fb.x[r] * fa.x[c] + fb.y[r] * fa.y[c] + fb.z[r] * fa.z[c];
        m->t[r] = fb.o[r] - (m->r[3 * r] * fa.o[0] + m->r[3 * r + 1] * fa.o[1] + m->r[3 * r + 2] * fa.o[2]);
    }
    return BS_OK;
}

/* Representation child placed in representation parent by m (link instance i). */
static bs_status add_link(stp *s, size_t i, size_t child, size_t parent, const stp_xf *m)
{
    double uc = rep_metres(s, child), up = rep_metres(s, parent);
    if (uc > 0.0 && up > 0.0 && fabs(uc - up) > 1e-9 * up) {
        (void)bsi_stp_fail(s, i, "mixed length units are not supported: a part in %g m placed in %g m", uc, up);
        return BS_ERR_UNSUPPORTED;
    }
    if (bsi_grow(&s->as.links, sizeof(stp_link), 1) != BS_OK)
        return BS_ERR_NO_MEMORY;
    stp_link *l = (stp_link *)s->as.links.data + s->as.links.n;
    l->child = child;
    l->parent = parent;
    l->seq = s->as.links.n++;
    l->xf = *m;
    return BS_OK;
}

/* Relationship instance i: a link when it carries an ITEM_DEFINED_TRANSFORMATION, else its two
 * representations joined. Other instances: nothing. */
static bs_status relationship(stp *s, size_t i)
{
    size_t list, child, parent, items, t, tl, a, b;
    bs_status st;
    if ((!bsi_stp_part(s, i, "REPRESENTATION_RELATIONSHIP", &list) || stp_at(s, list)->count < 4) &&
        (!bsi_stp_part(s, i, "SHAPE_REPRESENTATION_RELATIONSHIP", &list) || stp_at(s, list)->count < 4))
        return BS_OK;
    if ((st = bsi_stp_ref(s, i, list, 2, "the first representation", &child)) != BS_OK ||
        (st = bsi_stp_ref(s, i, list, 3, "the second representation", &parent)) != BS_OK)
        return st;
    if (!rep_items(s, child, &items) || !rep_items(s, parent, &items))
        return bsi_stp_fail(s, i, "%s", "relates something that is not a representation");
    if (!bsi_stp_part(s, i, "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION", &list)) {
        join(s, child, parent);
        return BS_OK;
    }
    if ((st = bsi_stp_ref(s, i, list, 0, "the transformation", &t)) != BS_OK)
        return st;
    if (!bsi_stp_part(s, t, "ITEM_DEFINED_TRANSFORMATION", &tl)) {
        (void)bsi_stp_fail(s, t, "%s", "transformations other than ITEM_DEFINED_TRANSFORMATION are not supported");
        return BS_ERR_UNSUPPORTED;
    }
    stp_xf m;
    if ((st = bsi_stp_ref(s, t, tl, 2, "the first item", &a)) != BS_OK ||
        (st = bsi_stp_ref(s, t, tl, 3, "the second item", &b)) != BS_OK || (st = motion(s, a, b, &m)) != BS_OK)
        return st;
    return add_link(s, i, child, parent, &m);
}

/* Shell instance sh held by representation rep (an ORIENTED_CLOSED_SHELL stands for its shell). */
static bs_status hold(stp *s, size_t at, size_t sh, size_t rep)
{
    size_t list;
    bs_status st;
    if (bsi_stp_part(s, sh, "ORIENTED_CLOSED_SHELL", &list) && (st = bsi_stp_ref(s, sh, list, 2, "the shell", &sh)) != BS_OK)
        return st;
    if (!bsi_stp_is(s, sh, "CLOSED_SHELL") && !bsi_stp_is(s, sh, "OPEN_SHELL"))
        return bsi_stp_fail(s, at, "#%zu is not a shell", stp_inst_at(s, sh)->id);
    if (s->as.holder[sh] == SIZE_MAX)
        s->as.holder[sh] = rep;
    else
        join(s, s->as.holder[sh], rep);
    return BS_OK;
}

/* Item it of representation rep: the shells of a solid or surface model, or a MAPPED_ITEM's link. */
static bs_status item(stp *s, size_t it, size_t rep)
{
    size_t list, n, sh, map, ml, origin, mapped, target;
    bs_status st = BS_OK;
    if (bsi_stp_part(s, it, "MANIFOLD_SOLID_BREP", &list) || bsi_stp_part(s, it, "BREP_WITH_VOIDS", &list)) {
        if ((st = bsi_stp_ref(s, it, list, 1, "the outer shell", &sh)) != BS_OK || (st = hold(s, it, sh, rep)) != BS_OK)
            return st;
    }
    if (bsi_stp_part(s, it, "BREP_WITH_VOIDS", &list) || bsi_stp_part(s, it, "SHELL_BASED_SURFACE_MODEL", &list)) {
        size_t shells, k0 = bsi_stp_is(s, it, "BREP_WITH_VOIDS") ? 2 : 1;
        if ((st = bsi_stp_list(s, it, list, k0, "the shells", &shells)) != BS_OK)
            return st;
        for (size_t k = 0; bsi_stp_arg(s, shells, k, &n) && st == BS_OK; k++)
            if ((st = bsi_stp_deref(s, it, n, "a shell", &sh)) == BS_OK)
                st = hold(s, it, sh, rep);
        return st;
    }
    if (!bsi_stp_part(s, it, "MAPPED_ITEM", &list))
        return st;
    stp_xf m;
    if ((st = bsi_stp_ref(s, it, list, 1, "the mapping source", &map)) != BS_OK ||
        (st = bsi_stp_ref(s, it, list, 2, "the mapping target", &target)) != BS_OK)
        return st;
    if (!bsi_stp_part(s, map, "REPRESENTATION_MAP", &ml))
        return bsi_stp_fail(s, map, "%s", "expected a REPRESENTATION_MAP");
    if ((st = bsi_stp_ref(s, map, ml, 0, "the mapping origin", &origin)) != BS_OK ||
        (st = bsi_stp_ref(s, map, ml, 1, "the mapped representation", &mapped)) != BS_OK)
        return st;
    if (!rep_items(s, mapped, &n))
        return bsi_stp_fail(s, map, "%s", "maps something that is not a representation");
    if ((st = motion(s, origin, target, &m)) != BS_OK)
        return st;
    return add_link(s, it, mapped, rep, &m);
}

static int by_child(const void *a, const void *b)
{
    const stp_link *x = a, *y = b;
    if (x->child != y->child)
        return x->child < y->child ? -1 : 1;
    return x->seq < y->seq ? -1 : x->seq > y->seq;
}

bs_status bsi_stp_assembly(stp *s)
{
    size_t n = s->inst.n, items, node, it;
    bs_status st = BS_OK;
    s->as.cls = malloc((n ? n : 1) * sizeof *s->as.cls);
    s->as.holder = malloc((n ? n : 1) * sizeof *s->as.holder);
    if (s->as.cls == NULL || s->as.holder == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 0; i < n; i++) {
        s->as.cls[i] = i;
        s->as.holder[i] = SIZE_MAX;
    }
    for (size_t i = 0; i < n && st == BS_OK; i++) {
        if ((st = relationship(s, i)) != BS_OK || !rep_items(s, i, &items))
            continue;
        /* items that are not references to defined instances belong to nothing read here */
        node = items + 1;
        for (size_t k = 0; k < stp_at(s, items)->count && st == BS_OK; k++, node += stp_at(s, node)->span)
            if (stp_at(s, node)->kind == STP_REF && bsi_stp_find(s, stp_at(s, node)->v.ref, &it))
                st = item(s, it, i);
    }
    if (st != BS_OK || s->as.links.n == 0)
        return st;
    stp_link *l = s->as.links.data;
    for (size_t k = 0; k < s->as.links.n; k++) {
        l[k].child = find(s, l[k].child);
        l[k].parent = find(s, l[k].parent);
    }
    qsort(l, s->as.links.n, sizeof *l, by_child);
    s->as.count = calloc(n ? n : 1, sizeof *s->as.count);
    s->as.base = calloc(n ? n : 1, sizeof *s->as.base);
    s->as.busy = calloc(n ? n : 1, 1);
    return s->as.count == NULL || s->as.base == NULL || s->as.busy == NULL ? BS_ERR_NO_MEMORY : BS_OK;
}

/* The links placing class c: l[*lo .. *hi - 1]. */
static void links_of(const stp *s, size_t c, size_t *lo, size_t *hi)
{
    const stp_link *l = s->as.links.data;
    size_t a = 0, b = s->as.links.n;
    while (a < b) {
        size_t mid = a + (b - a) / 2;
        if (l[mid].child < c)
            a = mid + 1;
        else
            b = mid;
    }
    *lo = a;
    for (b = a; b < s->as.links.n && l[b].child == c; b++) {
    }
    *hi = b;
}

/* The placements of class c (saturating at SIZE_MAX / 2), each class counted once. */
static bs_status count(stp *s, size_t c, int depth, size_t *out)
{
    size_t lo, hi, total = 0;
    if (s->as.count[c] != 0) {
        *out = s->as.count[c];
        return BS_OK;
    }
    if (s->as.busy[c] || depth > ASM_DEPTH)
        return bsi_stp_fail(s, c, "assemblies placed in a cycle or nested deeper than %d levels", ASM_DEPTH);
    s->as.busy[c] = 1;
    links_of(s, c, &lo, &hi);
    for (size_t k = lo; k < hi; k++) {
        size_t up;
        bs_status st = count(s, ((const stp_link *)s->as.links.data)[k].parent, depth + 1, &up);
        if (st != BS_OK)
            return st;
        total = up > SIZE_MAX / 2 - total ? SIZE_MAX / 2 : total + up;
    }
    s->as.busy[c] = 0;
    *out = s->as.count[c] = lo == hi ? 1 : total;
    return BS_OK;
}

bs_status bsi_stp_placement_count(stp *s, size_t i, size_t *n)
{
    *n = 1;
    if (s->as.links.n == 0 || s->as.holder[i] == SIZE_MAX)
        return BS_OK;
    return count(s, find(s, s->as.holder[i]), 0, n);
}

/* a after b. */
static stp_xf compose(const stp_xf *a, const stp_xf *b)
{
    stp_xf m;
    for (size_t r = 0; r < 3; r++) {
        for (size_t c = 0; c < 3; c++)
            m.r[3 * r + c] = a->r[3 * r] * b->r[c] + a->r[3 * r + 1] * b->r[3 + c] + a->r[3 * r + 2] * b->r[6 + c];
        m.t[r] = a->r[3 * r] * b->t[0] + a->r[3 * r + 1] * b->t[1] + a->r[3 * r + 2] * b->t[2] + a->t[r];
    }
    return m;
}

static bs_status push(bsi_growing *out, const stp_xf *m)
{
    if (bsi_grow(out, sizeof(stp_xf), 1) != BS_OK)
        return BS_ERR_NO_MEMORY;
    ((stp_xf *)out->data)[out->n++] = *m;
    return BS_OK;
}

/* The world motions of class c's placements, `inner` (the motion into c's coordinates) first. */
static bs_status place(stp *s, size_t c, const stp_xf *inner, bsi_growing *out)
{
    size_t lo, hi;
    links_of(s, c, &lo, &hi);
    if (lo == hi)
        return push(out, inner);
    for (size_t k = lo; k < hi; k++) {
        const stp_link *l = (const stp_link *)s->as.links.data + k;
        stp_xf m = compose(&l->xf, inner);
        bs_status st = place(s, l->parent, &m, out);
        if (st != BS_OK)
            return st;
    }
    return BS_OK;
}

bs_status bsi_stp_placements(stp *s, size_t i, bsi_growing *out, size_t *first)
{
    static const stp_xf identity = {{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}};
    size_t n;
    bs_status st = bsi_stp_placement_count(s, i, &n);
    out->n = 0;
    *first = 0;
    if (st != BS_OK)
        return st;
    if (s->as.links.n == 0 || s->as.holder[i] == SIZE_MAX)
        return push(out, &identity);
    size_t c = find(s, s->as.holder[i]);
    if (s->as.base[c] == 0) { /* each class its own ids, in the order shells are read */
        s->as.base[c] = s->as.next + 1;
        s->as.next += n;
    }
    *first = s->as.base[c] - 1;
    return place(s, c, &identity, out);
}
