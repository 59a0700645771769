/* Reading OBJ free-form models (docs/formats.md): each `surf` ... `end` body a face, its `trim`
 * and `hole` statements its outer and inner loops of `curv2` curves. Statements are read one
 * logical line at a time; a body's geometry is built at its `end` (obj_model_curve.c,
 * obj_model_face.c); edges are sewn when the text is read. `scrv` (special curves) and the
 * statements of polygons, groups and display are skipped. */
#include "io/obj_model.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* v x y z [w]; "x y z r g b" (vertex colours) is read as x y z. vp u [v [w]]. */
static bs_status read_vertex(objm *o, int param)
{
    double x[6] = {0, 0, 0, 1, 0, 0};
    size_t n = 0, start, tlen, most = param ? 3 : 6;
    while (bsi_objm_token(o, &start, &tlen)) {
        if (n == most)
            return bsi_objm_fail(o, start, "too many values for a %s", param ? "parameter vertex" : "vertex");
        bs_status st = bsi_objm_number(o, start, tlen, "a coordinate", &x[n++]);
        if (st != BS_OK)
            return st;
    }
    bsi_growing *g = param ? &o->vp : &o->v;
    if (param) {
        if (n == 0)
            return bsi_objm_fail(o, o->pos, "%s", "a parameter vertex needs u [v [w]]");
        if (n < 3)
            x[2] = 1.0;
        x[3] = (double)n;
    } else {
        if (n < 3 || n == 5)
            return bsi_objm_fail(o, o->pos, "%s", "a vertex needs x y z and an optional weight");
        if (n == 6)
            x[3] = 1.0;
    }
    bs_status st = bsi_grow(g, 4 * sizeof(double), 1);
    if (st != BS_OK)
        return st;
    memcpy((double *)g->data + 4 * g->n++, x, 4 * sizeof(double));
    return BS_OK;
}

static bs_status read_cstype(objm *o)
{
    size_t start, tlen;
    if (!bsi_objm_token(o, &start, &tlen))
        return bsi_objm_fail(o, o->pos, "%s", "expected a curve type");
    o->rat = bsi_objm_is(o, start, tlen, "rat");
    if (o->rat && !bsi_objm_token(o, &start, &tlen))
        return bsi_objm_fail(o, o->pos, "%s", "expected a curve type after rat");
    static const char *const names[] = {"bezier", "bspline", "bmatrix", "cardinal", "taylor"};
    int type = -1;
    for (int k = 0; k < 5 && type < 0; k++)
        if (bsi_objm_is(o, start, tlen, names[k]))
            type = k;
    if (type < 0)
        return bsi_objm_fail(o, start, "%s", "unknown curve type (bezier, bspline, bmatrix, cardinal or taylor)");
    o->type = type == 0 ? OBJM_BEZIER : type == 1 ? OBJM_BSPLINE : OBJM_TOTHER;
    o->type_line = o->line;
    (void)snprintf(o->type_name, sizeof o->type_name, "%s", names[type]);
    return bsi_objm_no_more(o, "cstype");
}

static bs_status read_degree(objm *o)
{
    size_t start, tlen, n = 0;
    while (bsi_objm_token(o, &start, &tlen)) {
        if (n == 2)
            return bsi_objm_fail(o, start, "%s", "more than two degrees");
        int ok = bsi_parse_size(o->text + start, tlen, BS_MAX_DEGREE, &o->deg[n++]);
        if (ok <= 0)
            return bsi_objm_fail(o, start, "%s", ok == 0 ? "expected a degree (a non-negative integer)"
                                                         : "degree too large (at most 64)");
    }
    if (n == 0)
        return bsi_objm_fail(o, o->pos, "%s", "expected a degree");
    o->ndeg = n;
    return BS_OK;
}

/* One control point reference of the open body: a vertex of a surf, a parameter vertex of a curv2. */
static bs_status read_ref(objm *o, size_t start, size_t tlen)
{
    int curve = o->body == OBJM_CURV2;
    const bsi_growing *g = curve ? &o->vp : &o->v;
    size_t idx;
    bs_status st = bsi_objm_index(o, start, tlen, g->n, curve ? "parameter vertex" : "vertex", &idx);
    if (st != BS_OK)
        return st;
    const double *x = (const double *)g->data + 4 * idx;
    if (curve && x[3] < 2.0)
        return bsi_objm_fail(o, start, "%s", "a trimming curve's parameter vertex needs u and v");
    if (o->rat && !(x[curve ? 2 : 3] > 0.0))
        return bsi_objm_fail(o, start, "weight of a rational %s's vertex must be positive", curve ? "curve" : "surface");
    if ((st = bsi_grow(&o->refs, sizeof(size_t), 1)) == BS_OK)
        ((size_t *)o->refs.data)[o->refs.n++] = idx;
    return st;
}

/* surf s0 s1 t0 t1 v1 v2 ... or curv2 vp1 vp2 ...: a body opened. */
static bs_status open_body(objm *o, size_t kw, int body)
{
    const char *name = body == OBJM_SURF ? "surf" : "curv2";
    if (o->body == OBJM_SURF || o->body == OBJM_CURV2)
        return bsi_objm_fail(o, kw, "%s before the end of the previous surface or curve", name);
    if (o->type == OBJM_TNONE)
        return bsi_objm_fail(o, kw, "%s before any cstype", name);
    if (o->type == OBJM_TOTHER) {
        (void)bsi_fail(o->err, o->line, kw - o->line_start + 1, "%s of type %s (cstype on line %zu) is not read",
                       name, o->type_name, o->type_line);
        return BS_ERR_UNSUPPORTED;
    }
    if (body == OBJM_SURF && o->ndeg != 2)
        return bsi_objm_fail(o, kw, "%s", "surf needs a deg statement with two degrees before it");
    if (body == OBJM_CURV2 && o->ndeg != 1)
        return bsi_objm_fail(o, kw, "%s", "curv2 needs a deg statement with one degree before it");
    o->body = body;
    o->body_line = o->line;
    o->body_col = kw - o->line_start + 1;
    o->refs.n = o->parm[0].n = o->parm[1].n = 0;
    o->have_parm[0] = o->have_parm[1] = 0;
    static const char *const range[4] = {"s0", "s1", "t0", "t1"};
    bs_status st = BS_OK;
    for (size_t k = 0; k < 4 && st == BS_OK && body == OBJM_SURF; k++)
        st = bsi_objm_read_number(o, range[k], &o->range[k]);
    size_t start, tlen;
    while (st == BS_OK && bsi_objm_token(o, &start, &tlen))
        st = read_ref(o, start, tlen);
    return st;
}

static bs_status read_parm(objm *o, size_t kw)
{
    size_t start, tlen;
    if (o->body == OBJM_NONE)
        return bsi_objm_fail(o, kw, "%s", "parm outside a surface or curve");
    if (!bsi_objm_token(o, &start, &tlen) || !(bsi_objm_is(o, start, tlen, "u") || bsi_objm_is(o, start, tlen, "v")))
        return bsi_objm_fail(o, o->pos, "%s", "expected u or v after parm");
    if (o->body == OBJM_OTHER)
        return BS_OK;
    int d = o->text[start] == 'v';
    if (d && o->body == OBJM_CURV2)
        return bsi_objm_fail(o, start, "%s", "a curve has no parameter v");
    if (o->have_parm[d])
        return bsi_objm_fail(o, start, "%s", "second parm statement for this direction");
    o->have_parm[d] = 1;
    o->parm_line[d] = o->line;
    o->parm_col[d] = start - o->line_start + 1;
    double x;
    bs_status st = BS_OK;
    while (st == BS_OK && bsi_objm_token(o, &start, &tlen)) {
        st = bsi_objm_number(o, start, tlen, "a parameter value", &x);
        if (st == BS_OK)
            st = bsi_grow(&o->parm[d], sizeof(double), 1);
        if (st == BS_OK)
            ((double *)o->parm[d].data)[o->parm[d].n++] = x;
    }
    return st;
}

static bs_status read_end(objm *o, size_t kw)
{
    if (o->body == OBJM_NONE)
        return bsi_objm_fail(o, kw, "%s", "end without surf or curve");
    int body = o->body;
    o->body = OBJM_NONE;
    if (body == OBJM_CURV2)
        return bsi_objm_end_curve(o);
    if (body == OBJM_SURF)
        return bsi_objm_end_surf(o);
    return BS_OK;
}

static bs_status statement(objm *o)
{
    size_t kw, klen;
    if (!bsi_objm_token(o, &kw, &klen))
        return BS_OK;
    char c = o->text[kw];
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')))
        return bsi_objm_fail(o, kw, "%s", "expected a statement keyword");
    if (bsi_objm_is(o, kw, klen, "v") || bsi_objm_is(o, kw, klen, "vp"))
        return read_vertex(o, klen == 2);
    int cstype = bsi_objm_is(o, kw, klen, "cstype"), deg = bsi_objm_is(o, kw, klen, "deg");
    if ((cstype || deg) && (o->body == OBJM_SURF || o->body == OBJM_CURV2))
        return bsi_objm_fail(o, kw, "%s before the end of the surface or curve", cstype ? "cstype" : "deg");
    if (cstype)
        return read_cstype(o);
    if (deg)
        return read_degree(o);
    if (bsi_objm_is(o, kw, klen, "surf"))
        return open_body(o, kw, OBJM_SURF);
    if (bsi_objm_is(o, kw, klen, "curv2"))
        return open_body(o, kw, OBJM_CURV2);
    if (bsi_objm_is(o, kw, klen, "parm"))
        return read_parm(o, kw);
    if (bsi_objm_is(o, kw, klen, "end"))
        return read_end(o, kw);
    int outer = bsi_objm_is(o, kw, klen, "trim");
    if (outer || bsi_objm_is(o, kw, klen, "hole")) {
        if (o->body != OBJM_SURF)
            return bsi_objm_fail(o, kw, "%s outside a surface", outer ? "trim" : "hole");
        return bsi_objm_loop(o, kw, outer);
    }
    static const char *const others[4] = {"f", "l", "p", "curv"};
    for (size_t k = 0; k < 4; k++)
        if (bsi_objm_is(o, kw, klen, others[k]))
            o->found[k]++;
    if (bsi_objm_is(o, kw, klen, "curv")) {
        if (o->body != OBJM_NONE)
            return bsi_objm_fail(o, kw, "%s", "curve before the end of the surface or curve");
        o->body = OBJM_OTHER;
    }
    return BS_OK; /* scrv, sp, con, polygons, groups, materials: skipped */
}

/* The parse error of a text without a surface, saying what it holds instead. */
static bs_status no_surface(objm *o)
{
    static const char *const what[4][2] = {{"polygon face", "polygon faces"}, {"line", "lines"},
                                           {"point", "points"}, {"3-D curve", "3-D curves"}};
    char msg[160] = "no free-form surface";
    size_t used = strlen(msg);
    int any = 0;
    for (size_t k = 0; k < 4; k++)
        if (o->found[k] > 0 && used < sizeof msg) {
            int n = snprintf(msg + used, sizeof msg - used, "%s %zu %s", any ? "," : ":", o->found[k],
                             what[k][o->found[k] > 1]);
            used += n > 0 ? (size_t)n : 0;
            any = 1;
        }
    if (!any)
        (void)snprintf(msg + used, sizeof msg - used, ": %zu vertices and no surf statement", o->v.n);
    return bsi_fail(o->err, o->line, 1, "%s", msg);
}

static void release(objm *o)
{
    bsi_objm_drop_loops(o);
    free(o->v.data);
    free(o->vp.data);
    free(o->refs.data);
    free(o->parm[0].data);
    free(o->parm[1].data);
    free(o->curves.data);
    free(o->cdata.data);
    free(o->trims.data);
    free(o->loops.data);
}

bs_status bs_model_read_obj(const char *text, size_t len, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    objm o;
    memset(&o, 0, sizeof o);
    o.text = text;
    o.len = len;
    o.line = 1;
    o.err = err;
    o.points_left = OBJM_POINTS(len);
    if (len > BSI_FILE_MAX) {
        (void)bsi_fail(err, 1, 1, "%s", "text longer than 256 MiB");
        return BS_ERR_SIZE;
    }
    const char *nul = len ? memchr(text, '\0', len) : NULL;
    if (nul != NULL) {
        for (size_t k = 0; text + k < nul; k++)
            if (text[k] == '\n')
                o.line++, o.line_start = k + 1;
        return bsi_objm_fail(&o, (size_t)(nul - text), "%s", "NUL byte in the text");
    }
    bs_status st = bsi_model_create(&o.m);
    while (st == BS_OK && o.pos < o.len) {
        st = statement(&o);
        if (st == BS_OK)
            bsi_objm_end_line(&o);
    }
    if (st == BS_OK && (o.body == OBJM_SURF || o.body == OBJM_CURV2))
        st = bsi_fail(err, o.body_line, o.body_col, "%s without end", o.body == OBJM_SURF ? "surface" : "curve");
    if (st == BS_OK && bs_model_face_count(o.m) == 0)
        st = no_surface(&o);
    if (st == BS_OK)
        st = bsi_model_finish(o.m);
    release(&o);
    if (st != BS_OK) {
        bs_model_destroy(o.m);
        return st;
    }
    *out = o.m;
    return BS_OK;
}

bs_status bs_model_read_obj_file(const char *path, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (path == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    char *buf = NULL;
    size_t len = 0;
    bs_status st = bsi_read_file(path, err, &buf, &len);
    if (st == BS_OK)
        st = bs_model_read_obj(buf, len, err, out);
    free(buf);
    return st;
}
