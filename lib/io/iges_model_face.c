/* IGES faces: the trims of a face from parameter-space curves, from 3-D curves on planes (exact
 * affine map) or projected onto the surface, and the faces of 144 trimmed surfaces (142 curves on
 * the surface), 143 bounded surfaces (141 boundaries) and untrimmed surfaces. */
#include "io/iges_model.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>


void bsi_igm_acc_free(igm_acc *a)
{
    bsi_trim *t = a->trims.data;
    for (size_t k = 0; k < a->trims.n; k++)
        bsi_curve_free(&t[k].uv);
    free(a->trims.data);
    free(a->lens.data);
    memset(a, 0, sizeof *a);
}

static bs_status push_trim(igm_acc *a, bsi_trim *t)
{
    bs_status r = bsi_grow(&a->trims, sizeof *t, 1);
    if (r != BS_OK) {
        bsi_curve_free(&t->uv);
        return r;
    }
    ((bsi_trim *)a->trims.data)[a->trims.n++] = *t;
    a->open++;
    return BS_OK;
}

/* The start (end 0) or end (end 1) of trim t in its loop's direction. */
static void trim_end(const bsi_trim *t, int end, double *p)
{
    int last = end != t->reversed;
    bsi_curve_point(&t->uv, last ? t->uv.axis.n - 1 : 0, last ? 1.0 : 0.0, p);
}

/* Lines across the gaps between the trims of the open loop (poles a 144's loop leaves out). */
static bs_status fill_gaps(igm_acc *a)
{
    size_t first = a->trims.n - a->open;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = first; k < a->trims.n; k++) {
        double l[2], h[2];
        bsi_curve_bounds(&((bsi_trim *)a->trims.data)[k].uv, l, h);
        for (size_t d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], l[d]);
            hi[d] = fmax(hi[d], h[d]);
        }
    }
    double eps = 1e-7 * hypot(hi[0] - lo[0], hi[1] - lo[1]);
    for (size_t k = first; k < a->trims.n; k++) {
        size_t next = k + 1 < a->trims.n ? k + 1 : first;
        double p[2], q[2];
        trim_end(&((bsi_trim *)a->trims.data)[k], 1, p);
        trim_end(&((bsi_trim *)a->trims.data)[next], 0, q);
        if (!(hypot(q[0] - p[0], q[1] - p[1]) > eps))
            continue;
        bsi_trim gap;
        memset(&gap, 0, sizeof gap);
        gap.edge = BSI_NO_EDGE;
        double d[2] = {q[0] - p[0], q[1] - p[1]};
        bs_status r = bsi_curve_line(2, p, d, 0.0, 1.0, &gap.uv);
        if (r == BS_OK)
            r = bsi_grow(&a->trims, sizeof gap, 1);
        if (r != BS_OK) {
            bsi_curve_free(&gap.uv);
            return r;
        }
        bsi_trim *t = a->trims.data;
        memmove(t + k + 2, t + k + 1, (a->trims.n - k - 1) * sizeof *t);
        t[k + 1] = gap;
        a->trims.n++;
        a->open++;
        k++;
    }
    return BS_OK;
}

bs_status bsi_igm_close_loop(igm_acc *a)
{
    if (a->open == 0)
        return BS_OK;
    bsi_trim *t = (bsi_trim *)a->trims.data + (a->trims.n - a->open);
    int computed = 0;
    for (size_t k = 0; k < a->open; k++)
        computed |= t[k].computed;
    if (computed) {
        const igm_surface *sf = a->sf;
        double tol = 1e-7;
        if (sf->def.kind == BS_FACE_BSPLINE) { /* its size from its control points */
            double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
            for (size_t k = 0; k < sf->b.count_u * sf->b.count_v; k++)
                for (size_t c = 0; c < 3; c++) {
                    lo[c] = fmin(lo[c], sf->b.ctrl[3 * k + c]);
                    hi[c] = fmax(hi[c], sf->b.ctrl[3 * k + c]);
                }
            tol *= hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
        }
        bsi_pcurve_close_loop_def(&sf->def, sf->swap, sf->has_box ? sf->box : NULL, tol, t, a->open);
    }
    bs_status r = fill_gaps(a);
    if (r == BS_OK)
        r = bsi_grow(&a->lens, sizeof(size_t), 1);
    if (r != BS_OK)
        return r;
    ((size_t *)a->lens.data)[a->lens.n++] = a->open;
    a->open = 0;
    return BS_OK;
}

/* The trim of 3-D curve c on surface sf by certified projection, within 1e-7 of the curve's size. */
static bs_status project(const igm_surface *sf, const bsi_curve *c, bsi_trim *out)
{
    double lo[3], hi[3];
    bsi_curve_bounds(c, lo, hi);
    double size = hypot(hypot(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    return bsi_pcurve_project_def(&sf->def, sf->swap, sf->has_box ? sf->box : NULL, NULL, c,
                                  1e-7 * (size > 0.0 ? size : 1.0), out);
}

bs_status bsi_igm_trims(igm *m, size_t s, size_t ss, size_t c, int space, int reversed, uint32_t edge,
                        igm_acc *a)
{
    bs_status r = bsi_igm_curve(m, c, 0);
    if (r == BS_OK)
        r = bsi_igm_spend(m, s, c);
    if (r != BS_OK)
        return r;
    const igm_slot *ce = &m->slot[c];
    const igm_surface *sf = m->slot[ss].surf;
    const bsi_frame *f = &sf->def.f;
    const double *x = sf->aff;
    double pu, pv;
    bsi_surface_def_periods(&sf->def, &pu, &pv);
    a->period[0] = sf->swap ? pv : pu;
    a->period[1] = sf->swap ? pu : pv;
    a->sf = sf;
    double pa[8] = {x[0], x[1], 0, x[2], x[3], x[4], 0, x[5]};
    double pl[8] = {f->x[0], f->x[1], f->x[2], -(f->o[0] * f->x[0] + f->o[1] * f->x[1] + f->o[2] * f->x[2]),
                    f->y[0], f->y[1], f->y[2], -(f->o[0] * f->y[0] + f->o[1] * f->y[1] + f->o[2] * f->y[2])};
    for (size_t i = 0; i < ce->npieces && r == BS_OK; i++) {
        const bsi_curve *piece = &ce->pieces[space && reversed ? ce->npieces - 1 - i : i];
        bsi_trim t;
        memset(&t, 0, sizeof t);
        if (!space)
            r = bsi_igm_curve2(piece, pa, &t.uv);
        else if (sf->plane)
            r = bsi_igm_curve2(piece, pl, &t.uv);
        else
            r = project(sf, piece, &t);
        t.edge = i == 0 ? edge : BSI_NO_EDGE;
        t.reversed = space && reversed;
        if (r == BS_OK)
            r = push_trim(a, &t);
    }
    if (r == BS_ERR_DOMAIN && space && !sf->plane)
        return bsi_igm_fail(m, c, 1, "curve not on the surface of DE %zu (projection failed)", 2 * ss + 1);
    return bsi_igm_name(m, s, r);
}

/* The face's native box: its loops' bounds, cut to the surface's own box along the directions
 * where it is bounded (the file's trims may pass its ends by their rounding). A revolution's
 * generatrix arc first turned by whole turns to where the trims use it (its parameter in the file
 * may differ from the angle of its start point by turns). */
static bs_status face_box(igm *m, size_t s, igm_surface *sf, const igm_acc *a, double *box)
{
    const bsi_trim *t = a->trims.data;
    box[0] = box[2] = INFINITY;
    box[1] = box[3] = -INFINITY;
    for (size_t k = 0; k < a->trims.n; k++) {
        double lo[2], hi[2];
        bsi_curve_bounds(&t[k].uv, lo, hi);
        for (size_t d = 0; d < 2; d++) {
            box[2 * d] = fmin(box[2 * d], lo[d]);
            box[2 * d + 1] = fmax(box[2 * d + 1], hi[d]);
        }
    }
    bsi_axis *ax = &sf->curve.axis;
    if (sf->def.kind == BS_FACE_REVOLUTION && ax->kind == BSI_AXIS_ANGULAR) {
        double turn = 2.0 * 3.141592653589793 / ax->radians;
        double mid = 0.5 * (box[0] + box[1]), c = 0.5 * (ax->breaks[0] + ax->breaks[ax->n]);
        double k = floor((mid - c) / turn + 0.5);
        for (size_t i = 0; k != 0.0 && i <= ax->n; i++)
            ax->breaks[i] += k * turn;
        bsi_axis_refresh(ax); /* the widths moved with the breaks by rounding */
        sf->box[0] = ax->breaks[0];
        sf->box[1] = ax->breaks[ax->n];
    }
    if (sf->has_box)
        for (size_t d = 0; d < 2; d++) {
            if (d == 1 && sf->def.kind != BS_FACE_BSPLINE)
                continue; /* angles and sweeps are not bounded */
            double lo = sf->box[2 * d], hi = sf->box[2 * d + 1], eps = 1e-9 * (hi - lo);
            box[2 * d] = fmax(box[2 * d], lo);
            box[2 * d + 1] = fmin(box[2 * d + 1], hi);
            for (size_t k = 0; k < a->trims.n; k++) { /* points past the ends by rounding: onto them */
                const bsi_curve *c = &t[k].uv;
                for (size_t i = 0; i < c->axis.n * (c->degree + 1); i++) {
                    double *h = c->hom + 3 * i, x = h[d] / h[2];
                    if (x < lo && x >= lo - eps)
                        h[d] = lo * h[2];
                    if (x > hi && x <= hi + eps)
                        h[d] = hi * h[2];
                }
            }
        }
    if (!(box[0] < box[1] && box[2] < box[3]))
        return bsi_igm_fail(m, s, 1, "trims outside the parameter range of its surface");
    return BS_OK;
}

/* The patches a face added since `before` counted against the copies the file allows, each as its
 * control points and at least 16 (a patch's own record weighs as much): a large surface trimmed by
 * many faces cannot outgrow the input either. */
static bs_status spend_patches(igm *m, size_t s, size_t before)
{
    const bs_surface *all = bs_model_surface(m->model);
    size_t points = 0, cap = m->g.len < SIZE_MAX / 8 ? 8 * m->g.len : SIZE_MAX;
    for (size_t p = before; p < bs_surface_count(all); p++) {
        const bs_patch *q = bs_surface_get(all, p);
        size_t own = (q->deg_u + 1) * (q->deg_v + 1); /* degrees at most BS_MAX_DEGREE: no overflow */
        points += own > 16 ? own : 16;
    }
    if (points > cap - m->copies)
        return bsi_igm_fail(m, s, 1, "surfaces reused more often than the file's size allows");
    m->copies += points;
    return BS_OK;
}

bs_status bsi_igm_add_face(igm *m, size_t s, size_t ss, igm_acc *a, int reversed, size_t shell)
{
    igm_surface *sf = m->slot[ss].surf;
    bs_status r = bsi_igm_close_loop(a);
    if (r != BS_OK)
        return r;
    if (a->trims.n == 0)
        return bsi_igm_fail(m, s, 1, "face without a trim curve");
    double box[4];
    if ((r = face_box(m, s, sf, a, box)) != BS_OK)
        return r;
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.def = &sf->def;
    /* the file's flags are against its own parameters' normal: a mirrored map turns it round */
    spec.reversed = reversed != (sf->aff[0] * sf->aff[4] - sf->aff[1] * sf->aff[3] < 0.0);
    spec.swap = sf->swap;
    spec.shell = shell;
    spec.trims = a->trims.data;
    spec.ntrim = a->trims.n;
    spec.loop_len = a->lens.data;
    spec.nloop = a->lens.n;
    spec.box = box;
    spec.untrimmed = a->untrimmed;
    size_t before = bs_surface_count(bs_model_surface(m->model));
    r = bsi_model_add_face(m->model, &spec, NULL);
    a->trims.n = 0; /* moved or freed */
    return r == BS_OK ? spend_patches(m, s, before) : bsi_igm_name(m, s, r);
}

/* The loop of the surface's own boundary: its native box's four sides. */
static bs_status box_loop(igm *m, size_t s, const igm_surface *sf, igm_acc *a)
{
    if (!sf->has_box)
        return bsi_igm_fail(m, s, 1, "outer boundary of an unbounded surface");
    const double *b = sf->box;
    double p[4][2] = {{b[0], b[2]}, {b[1], b[2]}, {b[1], b[3]}, {b[0], b[3]}};
    bs_status r = BS_OK;
    for (int k = 0; k < 4 && r == BS_OK; k++) {
        bsi_trim t;
        memset(&t, 0, sizeof t);
        double d[2] = {p[(k + 1) % 4][0] - p[k][0], p[(k + 1) % 4][1] - p[k][1]};
        t.edge = BSI_NO_EDGE;
        if ((r = bsi_curve_line(2, p[k], d, 0.0, 1.0, &t.uv)) == BS_OK)
            r = push_trim(a, &t);
    }
    return r == BS_OK ? bsi_igm_close_loop(a) : r;
}

/* Mark slot t used by entity s: each curve on a surface, face and loop serves one face. */
static bs_status use(igm *m, size_t s, size_t t, long type)
{
    bs_status r = bsi_igm_typed(m, s, t, type);
    if (r == BS_OK && m->slot[t].used)
        return bsi_igm_fail(m, t, 1, "used twice (by DE %zu and another)", 2 * s + 1);
    m->slot[t].used = 1;
    return r;
}

/* One 142 curve on the surface ss of entity s: its loop. */
static bs_status curve_on_surface(igm *m, size_t s, size_t t, size_t ss, igm_acc *a)
{
    iges_stream st;
    long crtn, pref;
    size_t sp, bp, cp;
    int nob, noc;
    bs_status r = use(m, s, t, 142);
    if (r == BS_OK)
        r = bsi_igm_open(m, t, &st);
    if (r != BS_OK || (r = bsi_iges_int(&m->g, &st, "CRTN", 0, 3, &crtn)) != BS_OK ||
        (r = bsi_igm_ptr(m, t, &st, "the surface pointer", 0, &sp, NULL)) != BS_OK ||
        (r = bsi_igm_ptr(m, t, &st, "the parameter curve pointer", 1, &bp, &nob)) != BS_OK ||
        (r = bsi_igm_ptr(m, t, &st, "the model curve pointer", 1, &cp, &noc)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "PREF", 0, 3, &pref)) != BS_OK || (r = bsi_igm_rest(m, &st)) != BS_OK)
        return bsi_igm_name(m, t, r);
    if (sp != ss)
        return bsi_igm_fail(m, t, 1, "on the surface DE %zu, not DE %zu of its face", 2 * sp + 1, 2 * ss + 1);
    const igm_surface *sf = m->slot[ss].surf;
    int space = !noc && (sf->plane || nob || !sf->param);
    if (!space && (nob || !sf->param))
        return bsi_igm_fail(m, t, 1, "no curve the surface's parameters can use");
    r = bsi_igm_trims(m, t, ss, space ? cp : bp, space, 0, BSI_NO_EDGE, a);
    return r == BS_OK ? bsi_igm_close_loop(a) : r;
}

/* One 141 boundary on the surface ss of the 143 s. */
static bs_status boundary(igm *m, size_t s, size_t t, size_t ss, igm_acc *a)
{
    iges_stream st;
    long type, pref, n;
    size_t sp;
    bs_status r = use(m, s, t, 141);
    if (r == BS_OK)
        r = bsi_igm_open(m, t, &st);
    if (r != BS_OK || (r = bsi_iges_int(&m->g, &st, "TYPE", 0, 1, &type)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "PREF", 0, 3, &pref)) != BS_OK ||
        (r = bsi_igm_ptr(m, t, &st, "the surface pointer", 0, &sp, NULL)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "the number of curves", 1, 99999999L, &n)) != BS_OK)
        return bsi_igm_name(m, t, r);
    if (sp != ss)
        return bsi_igm_fail(m, t, 1, "on the surface DE %zu, not DE %zu of its face", 2 * sp + 1, 2 * ss + 1);
    const igm_surface *sf = m->slot[ss].surf;
    for (long k = 0; k < n && r == BS_OK; k++) {
        long sense, np;
        size_t cp, pp = 0, more;
        if ((r = bsi_igm_ptr(m, t, &st, "a model curve pointer", 0, &cp, NULL)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "SENSE", 1, 2, &sense)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "the number of parameter curves", 0, 99999999L, &np)) != BS_OK)
            return bsi_igm_name(m, t, r);
        for (long j = 0; j < np && r == BS_OK; j++) /* the first one is used */
            r = bsi_igm_ptr(m, t, &st, "a parameter curve pointer", 0, j == 0 ? &pp : &more, NULL);
        if (r != BS_OK)
            return r;
        int space = np == 0 || sf->plane || !sf->param || type == 0;
        r = bsi_igm_trims(m, t, ss, space ? cp : pp, space, sense == 2, BSI_NO_EDGE, a);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        return bsi_igm_name(m, t, r);
    return r == BS_OK ? bsi_igm_close_loop(a) : r;
}

/* 143: TYPE, SPTR, N, the boundaries (the outer first). */
static bs_status bounded(igm *m, size_t s, iges_stream *st, igm_acc *a, size_t *ss)
{
    long type, n = 0;
    bs_status r = bsi_iges_int(&m->g, st, "TYPE", 0, 1, &type);
    if (r == BS_OK && (r = bsi_igm_ptr(m, s, st, "the surface pointer", 0, ss, NULL)) == BS_OK &&
        (r = bsi_igm_surface(m, *ss, 0)) == BS_OK)
        r = bsi_iges_int(&m->g, st, "the number of boundaries", 1, 99999999L, &n);
    if (r == BS_OK)
        m->slot[*ss].used = 1;
    for (long k = 0; k < n && r == BS_OK; k++) {
        size_t t;
        if ((r = bsi_igm_ptr(m, s, st, "a boundary pointer", 0, &t, NULL)) == BS_OK)
            r = boundary(m, s, t, *ss, a);
    }
    return r;
}

bs_status bsi_igm_trimmed(igm *m, size_t s, size_t shell)
{
    iges_stream st;
    igm_acc a;
    memset(&a, 0, sizeof a);
    size_t ss = 0, to;
    long n1 = 0, n2 = 0;
    bs_status r = bsi_igm_open(m, s, &st);
    if (r == BS_OK && m->slot[s].type == 143)
        r = bounded(m, s, &st, &a, &ss);
    else if (r == BS_OK) {
        if ((r = bsi_igm_ptr(m, s, &st, "the surface pointer", 0, &ss, NULL)) == BS_OK &&
            (r = bsi_igm_surface(m, ss, 0)) == BS_OK && (r = bsi_iges_int(&m->g, &st, "N1", 0, 1, &n1)) == BS_OK &&
            (r = bsi_iges_int(&m->g, &st, "N2", 0, 99999999L, &n2)) == BS_OK)
            r = bsi_igm_ptr(m, s, &st, "the outer boundary pointer", n1 == 0, &to, NULL);
        if (r == BS_OK) {
            m->slot[ss].used = 1;
            r = n1 == 0 ? box_loop(m, s, m->slot[ss].surf, &a) : curve_on_surface(m, s, to, ss, &a);
        }
        for (long k = 0; k < n2 && r == BS_OK; k++)
            if ((r = bsi_igm_ptr(m, s, &st, "an inner boundary pointer", 0, &to, NULL)) == BS_OK)
                r = curve_on_surface(m, s, to, ss, &a);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        r = bsi_igm_name(m, s, r);
    if (r == BS_OK)
        r = bsi_igm_add_face(m, s, ss, &a, 0, shell);
    bsi_igm_acc_free(&a);
    return r;
}

bs_status bsi_igm_untrimmed(igm *m, size_t s, size_t shell)
{
    bs_status r = bsi_igm_surface(m, s, 0);
    if (r != BS_OK)
        return r;
    /* its own box as its loop, as a 144 without an outer boundary has (its sides become edges,
     * the tessellator meshes it), reported as untrimmed (no loop) */
    igm_acc a;
    memset(&a, 0, sizeof a);
    m->slot[s].used = 1;
    a.untrimmed = 1;
    r = box_loop(m, s, m->slot[s].surf, &a);
    if (r == BS_OK)
        r = bsi_igm_add_face(m, s, s, &a, 0, shell);
    bsi_igm_acc_free(&a);
    return r;
}
