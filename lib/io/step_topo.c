/*
 * STEP faces: ADVANCED_FACE (or FACE_SURFACE) with its bounds, each an EDGE_LOOP of ORIENTED_EDGEs
 * of EDGE_CURVEs. Each oriented edge becomes one trim of the face's loop:
 *   - its range on the edge's 3-D curve runs between its vertices' parameters (a closed edge on a
 *     conic: a whole turn), traversed backwards when the oriented edge or the edge's same_sense
 *     says so;
 *   - its curve is the edge's PCURVE on the face's surface, over the same range (a SURFACE_CURVE's
 *     parameter space curves share its parametrisation), scaled to the face's native parameters;
 *     a SEAM_CURVE has two on the same surface: each use takes the one that continues the loop;
 *   - an edge without a PCURVE (files with 3-D edges only) is projected onto the surface
 *     (bsi_pcurve_project_def, within the reader's tolerance: 1e-7 of the file's extent); on a
 *     plane the edge's own curve is its exact trim, whatever PCURVE the file gives.
 * Each EDGE_CURVE is one model edge; gaps in a loop (the poles, which the files leave out) are
 * closed by lines in parameter space.
 */
#include "io/step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One trim in the making: the chosen trim, and for a seam the other parameter-space curve. */
typedef struct trim_slot {
    bsi_trim trim;
    bsi_trim alt;   /* a seam's second candidate (alt.uv.axis.n == 0 otherwise) */
} trim_slot;

static void slot_free(trim_slot *t)
{
    bsi_curve_free(&t->trim.uv);
    bsi_curve_free(&t->alt.uv);
}

/* The start and end in the loop's direction of a trim's curve. */
static void trim_ends(const bsi_trim *t, double *start, double *end)
{
    const bsi_curve *c = &t->uv;
    double a[2], b[2];
    bsi_curve_point(c, 0, 0.0, a);
    bsi_curve_point(c, c->axis.n - 1, 1.0, b);
    memcpy(start, t->reversed ? b : a, sizeof a);
    memcpy(end, t->reversed ? a : b, sizeof b);
}

/* The vertex point of a VERTEX_POINT. */
static bs_status vertex(const stp *s, size_t i, size_t list, size_t k, double *p)
{
    size_t v, list2, r;
    bs_status st = bsi_stp_ref(s, i, list, k, "a vertex", &v);
    if (st != BS_OK)
        return st;
    if (!bsi_stp_part(s, v, "VERTEX_POINT", &list2))
        return bsi_stp_fail(s, v, "%s", "expected a VERTEX_POINT");
    if ((st = bsi_stp_ref(s, v, list2, 1, "the point", &r)) != BS_OK)
        return st;
    return bsi_stp_point(s, r, 3, p);
}

/* The 2-D curve of a PCURVE on surface `surf`, or 0 when the pcurve is on another surface. */
static bs_status pcurve_on(stp *s, size_t pc, size_t surf, int *on, stp_curve *out)
{
    size_t list, basis, rep, items, n, c;
    bs_status st;
    *on = 0;
    if (!bsi_stp_part(s, pc, "PCURVE", &list))
        return BS_OK; /* another kind of associated geometry: not a parameter-space curve */
    if ((st = bsi_stp_ref(s, pc, list, 1, "the basis surface", &basis)) != BS_OK || basis != surf)
        return st;
    if ((st = bsi_stp_ref(s, pc, list, 2, "the parameter-space curve", &rep)) != BS_OK)
        return st;
    if (!bsi_stp_part(s, rep, "DEFINITIONAL_REPRESENTATION", &list))
        return bsi_stp_fail(s, rep, "%s", "expected a DEFINITIONAL_REPRESENTATION");
    if ((st = bsi_stp_list(s, rep, list, 1, "the items", &items)) != BS_OK)
        return st;
    if (!bsi_stp_arg(s, items, 0, &n))
        return bsi_stp_fail(s, rep, "%s", "no curve in the representation");
    if ((st = bsi_stp_deref(s, rep, n, "the curve", &c)) != BS_OK || (st = bsi_stp_curve(s, c, 2, 0, out)) != BS_OK)
        return st;
    *on = 1;
    return BS_OK;
}

/* The edge's range on its curve: [t0, t1] in the curve's direction, from the vertices. */
static void edge_range(const stp *s, const stp_curve *c, const double *p0, const double *p1, int same_sense,
                       double *t0, double *t1)
{
    double a = bsi_stp_curve_param(s, c, same_sense ? p0 : p1), b = bsi_stp_curve_param(s, c, same_sense ? p1 : p0);
    double lo, hi, period = bsi_stp_curve_period(s, c, &lo, &hi);
    double gap = hypot(hypot(p0[0] - p1[0], p0[1] - p1[1]), p0[2] - p1[2]);
    if (period > 0.0) {
        if (gap <= s->tol)     /* a closed edge: the whole turn */
            b = a + period;
        else if (b <= a)
            b += period;
    } else if (gap <= s->tol && isfinite(lo) && isfinite(hi)) {
        a = lo;                /* a closed B-spline edge: its whole domain */
        b = hi;
    }
    *t0 = a;
    *t1 = b;
}

/* The range of a straight PCURVE c2 between the surface points of the edge's ends q0 (at t0) and
 * q1 (at t1), where the surface's closed form inverts them: a PCURVE need not share the 3-D
 * curve's parametrisation (a cone's seam runs along the slant in 3-D, along the axis in (u, v)).
 * Each end's angles are taken nearest the PCURVE's point at the 3-D parameter. */
static void line_range(const stp *s, const stp_surf *sf, const stp_curve *c2, const double *q0, const double *q1,
                       double *t0, double *t1)
{
    const double *q[2] = {q0, q1};
    double *t[2] = {t0, t1}, r[2];
    for (int k = 0; k < 2; k++) {
        double hint[2] = {(c2->p[0] + *t[k] * c2->d[0]) * sf->scale[0], (c2->p[1] + *t[k] * c2->d[1]) * sf->scale[1]};
        double uv[2];
        if (c2->kind != STP_LINE || !bsi_surface_def_inverse(&sf->def, q[k], hint, uv))
            return;
        uv[0] /= sf->scale[0];
        uv[1] /= sf->scale[1];
        r[k] = bsi_stp_curve_param(s, c2, uv);
    }
    if (isfinite(r[0]) && isfinite(r[1]) && r[0] != r[1]) {
        *t0 = r[0];
        *t1 = r[1];
    }
}

/* The trim(s) of one ORIENTED_EDGE on the face's surface. */
static bs_status edge_trim(stp *s, size_t oe, size_t surf, const stp_surf *sf, trim_slot *slot)
{
    size_t list, e, elist, geom, glist, c3, pcs, n, pc;
    int orient, same, on;
    double p0[3] = {0, 0, 0}, p1[3] = {0, 0, 0}, t0, t1;
    bs_status st;
    memset(slot, 0, sizeof *slot);
    if (!bsi_stp_part(s, oe, "ORIENTED_EDGE", &list))
        return bsi_stp_fail(s, oe, "%s", "expected an ORIENTED_EDGE");
    if ((st = bsi_stp_ref(s, oe, list, 3, "the edge", &e)) != BS_OK ||
        (st = bsi_stp_bool(s, oe, list, 4, "the orientation", &orient)) != BS_OK)
        return st;
    if (!bsi_stp_part(s, e, "EDGE_CURVE", &elist))
        return bsi_stp_fail(s, e, "%s", "expected an EDGE_CURVE");
    if ((st = vertex(s, e, elist, 1, p0)) != BS_OK || (st = vertex(s, e, elist, 2, p1)) != BS_OK ||
        (st = bsi_stp_ref(s, e, elist, 3, "the edge geometry", &geom)) != BS_OK ||
        (st = bsi_stp_bool(s, e, elist, 4, "the sense", &same)) != BS_OK)
        return st;
    int surface_curve = bsi_stp_part(s, geom, "SURFACE_CURVE", &glist) || bsi_stp_part(s, geom, "SEAM_CURVE", &glist);
    c3 = geom;
    if (surface_curve && (st = bsi_stp_ref(s, geom, glist, 1, "the 3-D curve", &c3)) != BS_OK)
        return st;
    stp_curve curve;
    if ((st = bsi_stp_curve(s, c3, 3, 0, &curve)) != BS_OK)
        return st;
    edge_range(s, &curve, p0, p1, same, &t0, &t1);
    if ((s->edge_id[e] == BSI_NO_EDGE || s->edge_id[e] < s->edge_base) &&
        (st = bsi_model_add_edge(s->model, &s->edge_id[e])) != BS_OK) {
        bsi_stp_curve_free(&curve);
        return st;
    }
    int backwards = (orient == 0) != (same == 0);
    const double scale[6] = {sf->scale[0], 0.0, 0.0, 0.0, sf->scale[1], 0.0};
    int found = 0;
    /* on a plane the edge's own curve in the plane's (u, v) is exact: no PCURVE needed */
    if (sf->def.kind != BS_FACE_PLANE && surface_curve &&
        (st = bsi_stp_list(s, geom, glist, 2, "the parameter-space curves", &pcs)) == BS_OK) {
        for (size_t k = 0; found < 2 && bsi_stp_arg(s, pcs, k, &n) && st == BS_OK; k++) {
            stp_curve c2;
            if ((st = bsi_stp_deref(s, geom, n, "a parameter-space curve", &pc)) != BS_OK ||
                (st = pcurve_on(s, pc, surf, &on, &c2)) != BS_OK || !on)
                continue;
            bsi_trim *t = found == 0 ? &slot->trim : &slot->alt;
            double s0 = t0, s1 = t1;
            line_range(s, sf, &c2, same ? p0 : p1, same ? p1 : p0, &s0, &s1);
            st = bsi_stp_curve_make(s, &c2, s0, s1, &t->uv);
            bsi_stp_curve_free(&c2);
            if (st == BS_OK) {
                bsi_curve_transform(&t->uv, scale);
                t->reversed = backwards;
                t->edge = s->edge_id[e];
                found++;
            }
        }
    }
    if (st == BS_OK && found == 0) { /* 3-D edges only: project the edge onto the surface */
        bsi_curve edge3;
        if ((st = bsi_stp_curve_make(s, &curve, t0, t1, &edge3)) == BS_OK) {
            st = bsi_pcurve_project_def(&sf->def, 0, NULL, NULL, &edge3, s->tol, &slot->trim);
            bsi_curve_free(&edge3);
            slot->trim.reversed = backwards;
            slot->trim.edge = s->edge_id[e];
            if (st != BS_OK && st != BS_ERR_NO_MEMORY)
                st = bsi_stp_fail(s, e, "%s", "the edge is not on the face's surface");
        }
    }
    bsi_stp_curve_free(&curve);
    if (st != BS_OK)
        slot_free(slot);
    return st;
}

/* Each seam use takes the candidate whose start is nearer the loop's previous end (the next
 * start for the first trim). */
static void choose_seams(trim_slot *slots, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        if (slots[k].alt.uv.axis.n == 0)
            continue;
        double s0[2], e0[2], s1[2], e1[2], other[2], scratch[2];
        trim_ends(&slots[k].trim, s0, e0);
        trim_ends(&slots[k].alt, s1, e1);
        double d0, d1;
        if (k > 0 || n == 1) {
            trim_ends(&slots[(k + n - 1) % n].trim, scratch, other);
            d0 = hypot(s0[0] - other[0], s0[1] - other[1]);
            d1 = hypot(s1[0] - other[0], s1[1] - other[1]);
        } else {
            trim_ends(&slots[1].trim, other, scratch);
            d0 = hypot(e0[0] - other[0], e0[1] - other[1]);
            d1 = hypot(e1[0] - other[0], e1[1] - other[1]);
        }
        if (d1 < d0) {
            bsi_trim t = slots[k].trim;
            slots[k].trim = slots[k].alt;
            slots[k].alt = t;
        }
        bsi_curve_free(&slots[k].alt.uv);
    }
}

/* The oriented edges of an EDGE_LOOP as trims appended to *trims (grown), gaps closed by lines. */
static bs_status loop_trims(stp *s, size_t lp, size_t surf, const stp_surf *sf, int flip, bsi_growing *g)
{
    size_t list, edges, n, oe;
    bs_status st;
    if (!bsi_stp_part(s, lp, "EDGE_LOOP", &list))
        return bsi_stp_fail(s, lp, "%s", "expected an EDGE_LOOP");
    if ((st = bsi_stp_list(s, lp, list, 1, "the edges", &edges)) != BS_OK)
        return st;
    size_t count = stp_at(s, edges)->count, first = g->n;
    if (count == 0)
        return bsi_stp_fail(s, lp, "%s", "an empty loop");
    trim_slot *slots = calloc(count, sizeof *slots);
    if (slots == NULL)
        return BS_ERR_NO_MEMORY;
    size_t made = 0;
    for (size_t k = 0; k < count && st == BS_OK; k++) {
        if (!bsi_stp_arg(s, edges, k, &n) || (st = bsi_stp_deref(s, lp, n, "an oriented edge", &oe)) != BS_OK)
            break;
        if ((st = edge_trim(s, oe, surf, sf, &slots[k])) == BS_OK)
            made++;
    }
    if (st == BS_OK && flip) { /* a bound used backwards: the loop in the other order and sense */
        for (size_t k = 0; k < count; k++) {
            slots[k].trim.reversed ^= 1;
            slots[k].alt.reversed ^= 1;
        }
        for (size_t a = 0, b = count - 1; a < b; a++, b--) {
            trim_slot t = slots[a];
            slots[a] = slots[b];
            slots[b] = t;
        }
    }
    if (st == BS_OK) {
        choose_seams(slots, count);
        /* room for each trim and a closing line after it */
        st = bsi_grow(g, sizeof(bsi_trim), 2 * count);
    }
    if (st == BS_OK && sf->def.kind != BS_FACE_PLANE) {
        /* projected trims: across seams by whole periods, before the gaps are judged */
        int computed = 0;
        for (size_t k = 0; k < count; k++)
            computed |= slots[k].trim.computed;
        bsi_trim *loop = (bsi_trim *)g->data + g->n + count; /* the second half of the room */
        for (size_t k = 0; computed && k < count; k++)
            loop[k] = slots[k].trim;
        if (computed)
            bsi_pcurve_close_loop_def(&sf->def, 0, NULL, s->tol, loop, count);
        for (size_t k = 0; computed && k < count; k++)
            slots[k].trim = loop[k];
    }
    for (size_t k = 0; k < count && st == BS_OK; k++) {
        bsi_trim *out = (bsi_trim *)g->data;
        out[g->n++] = slots[k].trim;
        memset(&slots[k].trim, 0, sizeof slots[k].trim);
        double end[2], start[2], unused[2];
        trim_ends(&out[g->n - 1], unused, end);
        const bsi_trim *next = slots[(k + 1) % count].trim.uv.axis.n ? &slots[(k + 1) % count].trim : &out[first];
        trim_ends(next, start, unused);
        double gap = hypot(end[0] - start[0], end[1] - start[1]);
        if (gap > 1e-9 * (1.0 + fabs(end[0]) + fabs(end[1]))) {
            const double d[2] = {start[0] - end[0], start[1] - end[1]};
            bsi_trim line;
            memset(&line, 0, sizeof line);
            line.edge = BSI_NO_EDGE;
            if ((st = bsi_curve_line(2, end, d, 0.0, 1.0, &line.uv)) == BS_OK)
                out[g->n++] = line;
        }
    }
    for (size_t k = 0; k < made; k++)
        slot_free(&slots[k]);
    free(slots);
    return st;
}

/* The area of a loop's box in parameter space (to find the outer loop when none is marked). */
static double loop_box_area(const bsi_trim *t, size_t n)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = 0; k < n; k++) {
        double a[2], b[2];
        bsi_curve_bounds(&t[k].uv, a, b);
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], a[c]);
            hi[c] = fmax(hi[c], b[c]);
        }
    }
    return (hi[0] - lo[0]) * (hi[1] - lo[1]);
}

/* A face bounded by vertex loops only (a whole sphere or torus): the loop of its natural
 * domain's four sides, the two sides of a periodic direction one seam edge, the others (a
 * sphere's poles) without an edge. BS_ERR_PARSE when the surface's domain is not bounded. */
static bs_status domain_loop(stp *s, size_t i, const stp_surf *sf, bsi_growing *g, size_t *len)
{
    double pu, pv, box[4];
    bsi_surface_def_periods(&sf->def, &pu, &pv);
    box[0] = pu > 0.0 ? 0.0 : sf->dom[0];
    box[1] = pu > 0.0 ? pu : sf->dom[1];
    box[2] = pv > 0.0 ? 0.0 : sf->dom[2];
    box[3] = pv > 0.0 ? pv : sf->dom[3];
    if (!(isfinite(box[0]) && isfinite(box[1]) && isfinite(box[2]) && isfinite(box[3])))
        return bsi_stp_fail(s, i, "%s", "a face without edges on an unbounded surface");
    uint32_t seam_u = BSI_NO_EDGE, seam_v = BSI_NO_EDGE;
    bs_status st = BS_OK;
    if (pu > 0.0)
        st = bsi_model_add_edge(s->model, &seam_u);
    if (st == BS_OK && pv > 0.0)
        st = bsi_model_add_edge(s->model, &seam_v);
    if (st != BS_OK || (st = bsi_grow(g, sizeof(bsi_trim), 4)) != BS_OK)
        return st;
    const double start[4][2] = {{box[0], box[2]}, {box[1], box[2]}, {box[1], box[3]}, {box[0], box[3]}};
    const uint32_t edge[4] = {seam_v, seam_u, seam_v, seam_u};
    for (int k = 0; k < 4; k++) {
        const double *a = start[k], *b = start[(k + 1) % 4];
        const double d[2] = {b[0] - a[0], b[1] - a[1]};
        bsi_trim t;
        memset(&t, 0, sizeof t);
        t.edge = edge[k];
        if ((st = bsi_curve_line(2, a, d, 0.0, 1.0, &t.uv)) != BS_OK)
            return st;
        ((bsi_trim *)g->data)[g->n++] = t;
    }
    *len = 4;
    return BS_OK;
}

static void free_trims(bsi_growing *g)
{
    for (size_t k = 0; k < g->n; k++)
        bsi_curve_free(&((bsi_trim *)g->data)[k].uv);
    free(g->data);
}

bs_status bsi_stp_face(stp *s, size_t i, size_t shell, int flip)
{
    size_t list, bounds, n, b, blist, lp, surf;
    int same = 1, orient;
    bs_status st;
    int advanced = bsi_stp_part(s, i, "ADVANCED_FACE", &list) || bsi_stp_part(s, i, "FACE_SURFACE", &list);
    if (!advanced)
        return bsi_stp_fail(s, i, "%s", "expected a face");
    if ((st = bsi_stp_list(s, i, list, 1, "the bounds", &bounds)) != BS_OK ||
        (st = bsi_stp_ref(s, i, list, 2, "the surface", &surf)) != BS_OK ||
        (st = bsi_stp_bool(s, i, list, 3, "the sense", &same)) != BS_OK)
        return st;
    stp_surf sf;
    if ((st = bsi_stp_surface(s, surf, &sf)) != BS_OK)
        return st;
    bsi_growing trims = {NULL, 0, 0};
    size_t nb = stp_at(s, bounds)->count, outer = SIZE_MAX;
    size_t *len = calloc(nb ? nb : 1, sizeof *len);
    size_t nloop = 0;
    if (len == NULL)
        st = BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < nb && st == BS_OK; k++) {
        if (!bsi_stp_arg(s, bounds, k, &n) || (st = bsi_stp_deref(s, i, n, "a bound", &b)) != BS_OK)
            break;
        int is_outer = bsi_stp_part(s, b, "FACE_OUTER_BOUND", &blist);
        if (!is_outer && !bsi_stp_part(s, b, "FACE_BOUND", &blist)) {
            st = bsi_stp_fail(s, b, "%s", "expected a FACE_BOUND");
            break;
        }
        if ((st = bsi_stp_ref(s, b, blist, 1, "the loop", &lp)) != BS_OK ||
            (st = bsi_stp_bool(s, b, blist, 2, "the orientation", &orient)) != BS_OK)
            break;
        if (bsi_stp_is(s, lp, "VERTEX_LOOP")) /* a pole: no trim */
            continue;
        size_t before = trims.n;
        if ((st = loop_trims(s, lp, surf, &sf, !orient, &trims)) != BS_OK)
            break;
        if (is_outer)
            outer = nloop;
        len[nloop++] = trims.n - before;
    }
    if (st == BS_OK && nloop == 0 && (st = domain_loop(s, i, &sf, &trims, &len[0])) == BS_OK)
        nloop = 1;
    if (st == BS_OK && nloop > 0) {
        /* the outer loop first: the marked one, else the one of the widest box */
        size_t *first = malloc(nloop * sizeof *first);
        bsi_trim *sorted = malloc((trims.n ? trims.n : 1) * sizeof *sorted);
        size_t *len2 = malloc(nloop * sizeof *len2);
        if (first == NULL || sorted == NULL || len2 == NULL) {
            st = BS_ERR_NO_MEMORY;
        } else {
            double widest = -1.0;
            size_t wide = 0;
            for (size_t l = 0, at = 0; l < nloop; at += len[l], l++) {
                first[l] = at;
                double a = loop_box_area((bsi_trim *)trims.data + at, len[l]);
                if (a > widest)
                    widest = a, wide = l;
            }
            if (outer == SIZE_MAX)
                outer = wide;
            size_t at = 0;
            for (size_t l = 0; l < nloop; l++) {
                size_t from = l == 0 ? outer : (l <= outer ? l - 1 : l);
                if (len[from] > 0)
                    memcpy(sorted + at, (bsi_trim *)trims.data + first[from], len[from] * sizeof *sorted);
                len2[l] = len[from];
                at += len[from];
            }
            if (trims.n > 0)
                memcpy(trims.data, sorted, trims.n * sizeof *sorted);
            bsi_face_spec spec;
            memset(&spec, 0, sizeof spec);
            spec.def = &sf.def;
            spec.reversed = !same != (flip != 0);
            spec.shell = shell;
            spec.instance = s->instance;
            spec.trims = (bsi_trim *)trims.data;
            spec.ntrim = trims.n;
            spec.loop_len = len2;
            spec.nloop = nloop;
            st = bsi_model_add_face(s->model, &spec, NULL);
            trims.n = 0; /* the builder took (or freed) the curves */
            if (st == BS_ERR_DOMAIN)
                st = bsi_stp_fail(s, i, "%s", "the face's trims lie outside its surface");
        }
        free(first);
        free(sorted);
        free(len2);
    }
    free(len);
    free_trims(&trims);
    bsi_stp_surf_free(&sf);
    /* a value the model's builders refuse (a zero radius, a degenerate range, a knot vector)
     * is the file's error: say where */
    if (st != BS_OK && st != BS_ERR_NO_MEMORY && st != BS_ERR_PARSE && st != BS_ERR_UNSUPPORTED && st != BS_ERR_SIZE)
        st = bsi_stp_fail(s, i, "a curve or surface of the face is out of range (status %d)", st);
    return st;
}
