/* A surf body made a face: its Bezier patches (a bezier surf's segments with the shared control
 * points of OBJ; a bspline surf's spans within its s0 s1 t0 t1 range), native parameters the parm
 * values (knots), and its loops, outer first. The patches are built here rather than from a
 * bsi_surface_def so that control points are kept bit for bit where the file gives them (a B-spline
 * whose every knot has multiplicity degree + 1 is its patches exactly, as bs_model_write_obj
 * writes faces). A bezier surf's box is that of its parm values (its s0 s1 t0 t1 are not used, as
 * in bs_surface_read_obj); a bspline surf's is s0 s1 t0 t1 within its knots' domain. Holes without
 * a trim statement get the parameter box as their outer loop. */
#include "io/obj_model.h"

#include <bezsurf/bspline.h>

#include <stdlib.h>
#include <string.h>

/* The face being made: patches in a scratch surface, native breaks, box, kind. */
typedef struct face_build {
    bs_surface *s;
    bsi_axis au, av;
    double box[4];
    int kind;
} face_build;

static bs_status fail_surf(objm *o, int d, const char *msg)
{
    if (d >= 0 && o->have_parm[d])
        return bsi_fail(o->err, o->parm_line[d], o->parm_col[d], "%s", msg);
    return bsi_fail(o->err, o->body_line, o->body_col, "%s", msg);
}

/* Control vertex (i, j) of the open surface, cu along u (OBJ lists u fastest): x y z w. */
static const double *cv(const objm *o, size_t i, size_t j, size_t cu)
{
    return (const double *)o->v.data + 4 * ((const size_t *)o->refs.data)[j * cu + i];
}

/* Patch (a, b) of degrees p q whose control point (i, j) is cv(a p + i, b q + j) (stride p, q
 * between patches: shared sides for Bezier segments, none when stride is degree + 1). */
static bs_status add_patch(objm *o, face_build *fb, size_t a, size_t b, const size_t *stride,
                           size_t cu, double *ctrl, double *w)
{
    size_t p = o->deg[0], q = o->deg[1];
    for (size_t i = 0; i <= p; i++)
        for (size_t j = 0; j <= q; j++) {
            const double *x = cv(o, a * stride[0] + i, b * stride[1] + j, cu);
            memcpy(ctrl + 3 * (i * (q + 1) + j), x, 3 * sizeof(double));
            w[i * (q + 1) + j] = x[3];
        }
    bs_patch *patch;
    bs_status st = bs_patch_create(p, q, 3, ctrl, o->rat ? w : NULL, &patch);
    if (st == BS_ERR_NONFINITE)
        return fail_surf(o, -1, "weight times coordinate overflows");
    if (st == BS_OK) {
        st = bs_surface_add(fb->s, patch, NULL);
        bs_patch_destroy(patch);
    }
    return st;
}

/* seg[0] x seg[1] patches taken straight from the control points, stride apart. */
static bs_status direct_patches(objm *o, face_build *fb, const size_t *seg, const size_t *stride, size_t cu)
{
    size_t p = o->deg[0], q = o->deg[1], n = (p + 1) * (q + 1);
    bs_status st = bsi_objm_spend(o, seg[0] * seg[1] * n, o->body_line, o->body_col);
    double *ctrl = st == BS_OK ? malloc(4 * n * sizeof(double)) : NULL;
    if (st == BS_OK && ctrl == NULL)
        st = BS_ERR_NO_MEMORY;
    for (size_t a = 0; st == BS_OK && a < seg[0]; a++)
        for (size_t b = 0; st == BS_OK && b < seg[1]; b++)
            st = add_patch(o, fb, a, b, stride, cu, ctrl, ctrl + 3 * n);
    free(ctrl);
    return st;
}

static bs_status bezier_face(objm *o, face_build *fb)
{
    size_t seg[2], cnt[2];
    static const double unit[2] = {0.0, 1.0};
    for (size_t d = 0; d < 2; d++) {
        const double *pv = o->have_parm[d] ? o->parm[d].data : unit;
        size_t np = o->have_parm[d] ? o->parm[d].n : 2;
        if (np < 2)
            return fail_surf(o, (int)d, "a parm statement needs at least two values");
        seg[d] = np - 1;
        if (seg[d] > 1 && o->deg[d] == 0)
            return fail_surf(o, (int)d, "a surface of degree 0 has one segment");
        for (size_t k = 1; k < np; k++)
            if (!(pv[k] > pv[k - 1]))
                return fail_surf(o, (int)d, "parameter values must increase");
        if (o->refs.n == 0 || (o->deg[d] > 0 && seg[d] > (o->refs.n - 1) / o->deg[d]))
            return fail_surf(o, -1, "fewer control vertices than the degrees and parameter values need");
        cnt[d] = seg[d] * o->deg[d] + 1;
        fb->box[2 * d] = pv[0];
        fb->box[2 * d + 1] = pv[np - 1];
        bs_status st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, pv[0], pv[np - 1], pv, np, d ? &fb->av : &fb->au);
        if (st != BS_OK)
            return st;
    }
    if (o->refs.n % cnt[0] != 0 || o->refs.n / cnt[0] != cnt[1])
        return fail_surf(o, -1, "number of control vertices does not match the degrees and parameter values");
    fb->kind = BS_FACE_BEZIER;
    return direct_patches(o, fb, seg, o->deg, cnt[0]);
}

/* 1 when every knot value appears degree + 1 times: the B-spline is its patches, side by side. */
static int separate_spans(const double *k, size_t n, size_t deg)
{
    for (size_t i = 0; i < n;) {
        size_t r = 1;
        while (i + r < n && k[i + r] == k[i])
            r++;
        if (r != deg + 1)
            return 0;
        i += r;
    }
    return 1;
}

static bs_status bspline_face(objm *o, face_build *fb)
{
    size_t cnt[2];
    for (int d = 0; d < 2; d++) {
        if (!o->have_parm[d])
            return fail_surf(o, -1, "a B-spline surface needs parm u and parm v (its knots)");
        if (o->deg[d] == 0)
            return fail_surf(o, -1, "a B-spline surface's degrees must be 1 or more");
        if (o->parm[d].n < 2 * o->deg[d] + 2)
            return fail_surf(o, d, "too few knots for the degree");
        cnt[d] = o->parm[d].n - o->deg[d] - 1;
    }
    if (o->refs.n % cnt[0] != 0 || o->refs.n / cnt[0] != cnt[1])
        return fail_surf(o, -1, "number of control vertices does not match the knots and degrees");
    double *ctrl = malloc(4 * o->refs.n * sizeof(double));
    if (ctrl == NULL)
        return BS_ERR_NO_MEMORY;
    double *w = ctrl + 3 * o->refs.n;
    for (size_t i = 0; i < cnt[0]; i++)
        for (size_t j = 0; j < cnt[1]; j++) {
            const double *x = cv(o, i, j, cnt[0]);
            memcpy(ctrl + 3 * (i * cnt[1] + j), x, 3 * sizeof(double));
            w[i * cnt[1] + j] = x[3];
        }
    bs_bspline b = {o->deg[0], o->deg[1], cnt[0], cnt[1], 3, o->parm[0].data, o->parm[1].data, ctrl,
                    o->rat ? w : NULL};
    size_t nu, nv;
    bs_status st = bs_bspline_span_count(&b, &nu, &nv);
    if (st != BS_OK) {
        bs_bspline bu = b; /* the direction at fault: u checked alone (as both directions) */
        bu.knots_v = b.knots_u;
        bu.deg_v = b.deg_u;
        bu.count_v = b.count_u;
        int d = bs_bspline_span_count(&bu, &nu, &nv) == BS_OK ? 1 : 0;
        st = fail_surf(o, d, "knots decrease, repeat over degree + 1 times, leave an empty domain or span over DBL_MAX");
    }
    const double *ku = b.knots_u, *kv = b.knots_v;
    double dom[4] = {ku[b.deg_u], ku[b.count_u], kv[b.deg_v], kv[b.count_v]};
    for (size_t d = 0; d < 4 && st == BS_OK; d += 2) {
        fb->box[d] = o->range[d] > dom[d] ? o->range[d] : dom[d];
        fb->box[d + 1] = o->range[d + 1] < dom[d + 1] ? o->range[d + 1] : dom[d + 1];
        if (!(fb->box[d + 1] > fb->box[d]))
            st = fail_surf(o, -1, "the surf range is empty or outside the knots' domain");
    }
    if (st == BS_OK && (st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, fb->box[0], fb->box[1], ku, o->parm[0].n, &fb->au)) == BS_OK)
        st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, fb->box[2], fb->box[3], kv, o->parm[1].n, &fb->av);
    fb->kind = BS_FACE_BSPLINE;
    int whole = st == BS_OK && dom[0] == fb->box[0] && dom[1] == fb->box[1] && dom[2] == fb->box[2] &&
                dom[3] == fb->box[3];
    if (whole && separate_spans(ku, o->parm[0].n, b.deg_u) && separate_spans(kv, o->parm[1].n, b.deg_v)) {
        size_t seg[2] = {nu, nv}, stride[2] = {b.deg_u + 1, b.deg_v + 1};
        free(ctrl);
        return direct_patches(o, fb, seg, stride, cnt[0]);
    }
    if (st == BS_OK)
        st = bsi_objm_spend(o, nu * nv * (b.deg_u + 1) * (b.deg_v + 1), o->body_line, o->body_col);
    if (st == BS_OK)
        st = bsi_add_bspline_range(fb->s, &b, fb->box);
    free(ctrl);
    if (st == BS_ERR_NONFINITE)
        return fail_surf(o, -1, "weight times coordinate overflows");
    return st;
}

/* The box's four sides counter-clockwise: the outer loop of a surface with holes only. */
static bs_status box_loop(const double *box, bsi_trim *t)
{
    const double start[4][2] = {{box[0], box[2]}, {box[1], box[2]}, {box[1], box[3]}, {box[0], box[3]}};
    const double dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const double len[4] = {box[1] - box[0], box[3] - box[2], box[1] - box[0], box[3] - box[2]};
    bs_status st = BS_OK;
    for (int k = 0; k < 4; k++) {
        memset(&t[k], 0, sizeof t[k]);
        t[k].edge = BSI_NO_EDGE;
        if (st == BS_OK)
            st = bsi_curve_line(2, start[k], dir[k], 0.0, len[k], &t[k].uv);
    }
    return st;
}

/* The loops in the builder's order (outer first) with their trims moved out of o->trims. */
static bs_status order_loops(objm *o, const face_build *fb, bsi_trim **trims, size_t *ntrim, size_t **lens,
                             size_t *nloop)
{
    const objm_loop *l = o->loops.data;
    size_t outer = 0, second = 0;
    for (size_t k = 0; k < o->loops.n; k++)
        if (l[k].outer && outer++ == 1)
            second = k;
    if (outer > 1) {
        (void)bsi_fail(o->err, l[second].line, l[second].col, "%s",
                       "a second trim loop: a face of a model has one outer loop");
        return BS_ERR_UNSUPPORTED;
    }
    /* holes without an outer loop, or no loop at all (an untrimmed surf): the box is the outer */
    size_t extra = outer == 0 ? 4 : 0, n = o->trims.n + extra;
    *ntrim = n;
    *nloop = o->loops.n + (extra > 0);
    *trims = malloc((n ? n : 1) * sizeof **trims);
    *lens = malloc((*nloop ? *nloop : 1) * sizeof **lens);
    if (*trims == NULL || *lens == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status st = extra ? box_loop(fb->box, *trims) : BS_OK;
    size_t at = extra, nl = 0;
    if (extra)
        (*lens)[nl++] = 4;
    for (int pass = 1; pass >= 0; pass--) /* the outer loop, then the holes */
        for (size_t k = 0; k < o->loops.n; k++)
            if (l[k].outer == pass) {
                memcpy(*trims + at, (const bsi_trim *)o->trims.data + l[k].first, l[k].count * sizeof **trims);
                at += l[k].count;
                (*lens)[nl++] = l[k].count;
            }
    o->trims.n = 0; /* moved */
    o->loops.n = 0;
    if (st != BS_OK)
        for (size_t k = 0; k < n; k++)
            bsi_curve_free(&(*trims)[k].uv);
    return st;
}

/* The face added with its first patch, then given its other patches, its axes, box and kind. */
static bs_status add_face(objm *o, face_build *fb)
{
    bsi_trim *trims = NULL;
    size_t *lens = NULL, nloop = 0, ntrim = 0, id;
    int untrimmed = o->loops.n == 0; /* given its box as its loop, reported as untrimmed */
    bs_status st = order_loops(o, fb, &trims, &ntrim, &lens, &nloop);
    if (st == BS_OK) {
        bsi_face_spec spec;
        memset(&spec, 0, sizeof spec);
        spec.patch = bs_surface_get(fb->s, 0);
        spec.trims = trims;
        spec.loop_len = lens;
        spec.nloop = nloop;
        spec.ntrim = ntrim;
        spec.untrimmed = untrimmed;
        st = bsi_model_add_face(o->m, &spec, &id);
    }
    free(trims);
    free(lens);
    size_t np = bs_surface_count(fb->s);
    for (size_t k = 1; k < np && st == BS_OK; k++)
        st = bs_surface_add(o->m->surface, bs_surface_get(fb->s, k), NULL);
    if (st != BS_OK)
        return st; /* the reader fails: the model is destroyed whole */
    bsi_face *f = &o->m->faces[id];
    bsi_axis_free(&f->au);
    bsi_axis_free(&f->av);
    f->au = fb->au;
    f->av = fb->av;
    memset(&fb->au, 0, sizeof fb->au);
    memset(&fb->av, 0, sizeof fb->av);
    memcpy(f->box, fb->box, sizeof f->box);
    f->kind = fb->kind;
    f->patch_count = np;
    return BS_OK;
}

bs_status bsi_objm_end_surf(objm *o)
{
    face_build fb;
    memset(&fb, 0, sizeof fb);
    bs_status st = bs_surface_create(&fb.s);
    if (st == BS_OK)
        st = o->type == OBJM_BEZIER ? bezier_face(o, &fb) : bspline_face(o, &fb);
    if (st == BS_OK)
        st = add_face(o, &fb);
    bsi_axis_free(&fb.au);
    bsi_axis_free(&fb.av);
    bs_surface_destroy(fb.s);
    bsi_objm_drop_loops(o);
    return st;
}
