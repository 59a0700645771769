/* Reading the free-form surfaces of Wavefront OBJ text (docs/formats.md): statements are read one
 * logical line at a time, vertices kept, and each `surf` ... `end` body turned into patches when
 * its `end` is read. Every array grows with the data seen, never with a declared count. */
#include "io/internal.h"

#include <bezsurf/bspline.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { BODY_NONE, BODY_SURF, BODY_OTHER };
enum { TYPE_NONE, TYPE_BEZIER, TYPE_BSPLINE, TYPE_OTHER };

typedef struct obj {
    const char *text;
    size_t len, pos;
    size_t line, line_start;  /* 1-based line of pos and the offset of its first byte */
    bs_parse_error *err;
    bsi_growing verts;        /* 4 doubles per vertex: x y z w */
    int rat, type;            /* from the last cstype */
    size_t type_line;
    char type_name[16];
    size_t deg[2], ndeg;      /* from the last deg */
    int body;                 /* inside surf ... end, or another element's body */
    size_t surf_line, surf_col, parm_line[2], parm_col[2];
    double range[4];          /* s0 s1 t0 t1 of the open surf */
    bsi_growing refs;         /* 0-based vertex of each control vertex of the open surf */
    bsi_growing parm[2];      /* parameter values along u and v */
    int have_parm[2];
    bs_surface *s;
    size_t surfs;             /* surf statements read */
    size_t points;            /* patch control points made so far (BSI_READ_POINTS caps them) */
    size_t skipped[4], skip_line, skip_col; /* f, l, p, curv/curv2 skipped; where the first was */
} obj;

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

static bs_status fail_at(obj *o, size_t at, const char *fmt, const char *arg)
{
    return bsi_fail(o->err, o->line, at - o->line_start + 1, fmt, arg);
}

/* Offset just past a backslash at `at` that continues the line, or 0 when it does not. */
static size_t continuation(const obj *o, size_t at)
{
    size_t k = at + 1;
    while (k < o->len && is_blank(o->text[k]))
        k++;
    if (k >= o->len)
        return k;
    return o->text[k] == '\n' ? k + 1 : 0;
}

/* The next token of the current statement; 0 at its end (a newline, a comment or the input's end).
 * A backslash ending a line joins the next line to the statement. */
static int next_token(obj *o, size_t *start, size_t *tlen)
{
    for (;;) {
        if (o->pos >= o->len || o->text[o->pos] == '\n')
            return 0;
        char c = o->text[o->pos];
        if (is_blank(c)) {
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
            if (next <= o->len && o->text[next - 1] == '\n') {
                o->line++;
                o->line_start = next;
            }
            o->pos = next;
            continue;
        }
        *start = o->pos;
        while (o->pos < o->len && o->text[o->pos] != '\n' && !is_blank(o->text[o->pos]) &&
               !(o->text[o->pos] == '\\' && o->pos > *start && continuation(o, o->pos) != 0))
            o->pos++;
        *tlen = o->pos - *start;
        return 1;
    }
}

/* Skip the rest of the statement and its newline. */
static void end_line(obj *o)
{
    size_t start, tlen;
    while (next_token(o, &start, &tlen))
        ;
    if (o->pos < o->len) {
        o->pos++;
        o->line++;
        o->line_start = o->pos;
    }
}

static int token_is(const obj *o, size_t start, size_t tlen, const char *word)
{
    return tlen == strlen(word) && memcmp(o->text + start, word, tlen) == 0;
}

static bs_status parse_number(obj *o, size_t start, size_t tlen, const char *what, double *x)
{
    int ok = bsi_parse_double(o->text + start, tlen, x);
    return ok <= 0 ? fail_at(o, start, bsi_parse_double_says(ok), what) : BS_OK;
}

static bs_status read_number(obj *o, const char *what, double *x)
{
    size_t start, tlen;
    if (!next_token(o, &start, &tlen))
        return fail_at(o, o->pos, "expected %s", what);
    return parse_number(o, start, tlen, what, x);
}

static bs_status no_more(obj *o, const char *statement)
{
    size_t start, tlen;
    if (next_token(o, &start, &tlen))
        return fail_at(o, start, "unexpected value after the %s statement", statement);
    return BS_OK;
}

/* v x y z [w]; "x y z r g b" (vertex colours) is read as x y z. */
static bs_status read_vertex(obj *o)
{
    double x[6] = {0, 0, 0, 1, 0, 0};
    size_t n = 0, start, tlen;
    while (next_token(o, &start, &tlen)) {
        if (n == 6)
            return fail_at(o, start, "%s", "too many values for a vertex");
        bs_status st = parse_number(o, start, tlen, "a coordinate", &x[n++]);
        if (st != BS_OK)
            return st;
    }
    if (n < 3 || n == 5)
        return fail_at(o, o->pos, "%s", "a vertex needs x y z and an optional weight");
    if (n == 6)
        x[3] = 1.0;
    bs_status st = bsi_grow(&o->verts, 4 * sizeof(double), 1);
    if (st != BS_OK)
        return st;
    memcpy((double *)o->verts.data + 4 * o->verts.n++, x, 4 * sizeof(double));
    return BS_OK;
}

static bs_status read_cstype(obj *o)
{
    size_t start, tlen;
    if (!next_token(o, &start, &tlen))
        return fail_at(o, o->pos, "%s", "expected a curve type");
    o->rat = token_is(o, start, tlen, "rat");
    if (o->rat && !next_token(o, &start, &tlen))
        return fail_at(o, o->pos, "%s", "expected a curve type after rat");
    static const char *const names[] = {"bezier", "bspline", "bmatrix", "cardinal", "taylor"};
    int type = -1;
    for (int k = 0; k < 5 && type < 0; k++)
        if (token_is(o, start, tlen, names[k]))
            type = k;
    if (type < 0)
        return fail_at(o, start, "%s", "unknown curve type (bezier, bspline, bmatrix, cardinal or taylor)");
    o->type = type == 0 ? TYPE_BEZIER : type == 1 ? TYPE_BSPLINE : TYPE_OTHER;
    o->type_line = o->line;
    (void)snprintf(o->type_name, sizeof o->type_name, "%s", names[type]);
    return no_more(o, "cstype");
}

static bs_status read_degree(obj *o)
{
    size_t start, tlen, n = 0;
    while (next_token(o, &start, &tlen)) {
        if (n == 2)
            return fail_at(o, start, "%s", "more than two degrees");
        int ok = bsi_parse_size(o->text + start, tlen, BS_MAX_DEGREE, &o->deg[n++]);
        if (ok <= 0)
            return fail_at(o, start, "%s", ok == 0 ? "expected a degree (a non-negative integer)"
                                                   : "degree too large (at most 64)");
    }
    if (n == 0)
        return fail_at(o, o->pos, "%s", "expected a degree");
    o->ndeg = n;
    return BS_OK;
}

/* One vertex reference v[/vt[/vn]] as a 0-based vertex, relative ones resolved now. */
static bs_status read_ref(obj *o, size_t start, size_t tlen)
{
    const char *t = o->text + start;
    size_t k = 0, idx = 0;
    while (k < tlen && t[k] != '/')
        k++;
    int neg = k > 0 && t[0] == '-';
    int ok = bsi_parse_size(t + neg, k - (size_t)neg, SIZE_MAX, &idx);
    if (ok == 0 || (ok > 0 && idx == 0))
        return fail_at(o, start, "%s", "expected a vertex index (a non-zero integer)");
    if (ok < 0 || idx > o->verts.n)
        return fail_at(o, start, "%s", neg ? "relative vertex index before the first vertex"
                                           : "vertex index beyond the vertices defined so far");
    idx = neg ? o->verts.n - idx : idx - 1;
    if (o->rat && !(((double *)o->verts.data)[4 * idx + 3] > 0.0))
        return fail_at(o, start, "%s", "weight of a rational surface's vertex must be positive");
    bs_status st = bsi_grow(&o->refs, sizeof(size_t), 1);
    if (st == BS_OK)
        ((size_t *)o->refs.data)[o->refs.n++] = idx;
    return st;
}

static bs_status read_surf(obj *o, size_t kw)
{
    o->surfs++;
    if (o->body == BODY_SURF)
        return fail_at(o, kw, "%s", "surf before the end of the previous surface");
    if (o->type == TYPE_NONE)
        return fail_at(o, kw, "%s", "surf before any cstype");
    if (o->type == TYPE_OTHER) {
        (void)bsi_fail(o->err, o->line, kw - o->line_start + 1,
                       "surface of type %s (cstype on line %zu) is not read", o->type_name, o->type_line);
        return BS_ERR_UNSUPPORTED;
    }
    if (o->ndeg != 2)
        return fail_at(o, kw, "%s", "surf needs a deg statement with two degrees before it");
    o->body = BODY_SURF;
    o->surf_line = o->line;
    o->surf_col = kw - o->line_start + 1;
    o->refs.n = o->parm[0].n = o->parm[1].n = 0;
    o->have_parm[0] = o->have_parm[1] = 0;
    static const char *const range[4] = {"s0", "s1", "t0", "t1"};
    bs_status st = BS_OK;
    for (size_t k = 0; k < 4 && st == BS_OK; k++)
        st = read_number(o, range[k], &o->range[k]);
    size_t start, tlen;
    while (st == BS_OK && next_token(o, &start, &tlen))
        st = read_ref(o, start, tlen);
    return st;
}

static bs_status read_parm(obj *o, size_t kw)
{
    size_t start, tlen;
    if (o->body == BODY_NONE)
        return fail_at(o, kw, "%s", "parm outside a surface or curve");
    if (!next_token(o, &start, &tlen))
        return fail_at(o, o->pos, "%s", "expected u or v after parm");
    if (!(token_is(o, start, tlen, "u") || token_is(o, start, tlen, "v")))
        return fail_at(o, start, "%s", "expected u or v after parm");
    if (o->body == BODY_OTHER)
        return BS_OK;
    int d = o->text[start] == 'v';
    if (o->have_parm[d])
        return fail_at(o, start, "%s", "second parm statement for this direction");
    o->have_parm[d] = 1;
    o->parm_line[d] = o->line;
    o->parm_col[d] = start - o->line_start + 1;
    double x;
    bs_status st = BS_OK;
    while (st == BS_OK && next_token(o, &start, &tlen)) {
        st = parse_number(o, start, tlen, "a parameter value", &x);
        if (st == BS_OK)
            st = bsi_grow(&o->parm[d], sizeof(double), 1);
        if (st == BS_OK)
            ((double *)o->parm[d].data)[o->parm[d].n++] = x;
    }
    return st;
}

/* Report at the surface's surf statement (or its parm statement of direction d when d >= 0). */
static bs_status fail_surf(obj *o, int d, const char *msg)
{
    if (d >= 0 && o->have_parm[d])
        return bsi_fail(o->err, o->parm_line[d], o->parm_col[d], "%s", msg);
    return bsi_fail(o->err, o->surf_line, o->surf_col, "%s", msg);
}

/* Control vertex (i, j) of the open surface, cu along u: its vertex's x y z w. */
static const double *cv(const obj *o, size_t i, size_t j, size_t cu)
{
    return (const double *)o->verts.data + 4 * ((const size_t *)o->refs.data)[j * cu + i];
}

static bs_status build_bezier(obj *o, double *ctrl, double *w)
{
    size_t seg[2], cnt[2];
    for (int d = 0; d < 2; d++) {
        const double *pv = o->parm[d].data;
        seg[d] = o->have_parm[d] ? o->parm[d].n - (o->parm[d].n > 0) : 1;
        if (seg[d] == 0)
            return fail_surf(o, d, "a parm statement needs at least two values");
        if (seg[d] > 1 && o->deg[d] == 0)
            return fail_surf(o, d, "a surface of degree 0 has one segment");
        for (size_t k = 1; o->have_parm[d] && k <= seg[d]; k++)
            if (!(pv[k] > pv[k - 1]))
                return fail_surf(o, d, "parameter values must increase");
        if (o->refs.n == 0 || (o->deg[d] > 0 && seg[d] > (o->refs.n - 1) / o->deg[d]))
            return fail_surf(o, -1, "fewer control vertices than the degrees and parameter values need");
        cnt[d] = seg[d] * o->deg[d] + 1;
    }
    if (o->refs.n % cnt[0] != 0 || o->refs.n / cnt[0] != cnt[1])
        return fail_surf(o, -1, "number of control vertices does not match the degrees and parameter values");
    size_t p = o->deg[0], q = o->deg[1];
    for (size_t a = 0; a < seg[0]; a++)
        for (size_t b = 0; b < seg[1]; b++) {
            for (size_t i = 0; i <= p; i++)
                for (size_t j = 0; j <= q; j++) {
                    const double *x = cv(o, a * p + i, b * q + j, cnt[0]);
                    memcpy(ctrl + 3 * (i * (q + 1) + j), x, 3 * sizeof(double));
                    w[i * (q + 1) + j] = x[3];
                }
            bs_patch *patch;
            bs_status st = bs_patch_create(p, q, 3, ctrl, o->rat ? w : NULL, &patch);
            if (st == BS_ERR_NONFINITE)
                return fail_surf(o, -1, "weight times coordinate overflows");
            if (st != BS_OK)
                return st;
            st = bs_surface_add(o->s, patch, NULL);
            bs_patch_destroy(patch);
            if (st != BS_OK)
                return st;
        }
    return BS_OK;
}

static bs_status build_bspline(obj *o, double *ctrl, double *w)
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
    for (size_t i = 0; i < cnt[0]; i++)
        for (size_t j = 0; j < cnt[1]; j++) {
            const double *x = cv(o, i, j, cnt[0]);
            memcpy(ctrl + 3 * (i * cnt[1] + j), x, 3 * sizeof(double));
            w[i * cnt[1] + j] = x[3];
        }
    bs_bspline b = {o->deg[0], o->deg[1], cnt[0], cnt[1], 3, o->parm[0].data, o->parm[1].data, ctrl,
                    o->rat ? w : NULL};
    size_t nu, nv;
    if (bs_bspline_span_count(&b, &nu, &nv) != BS_OK) {
        bs_bspline bu = b; /* the direction at fault: u checked alone (as both directions) */
        bu.knots_v = b.knots_u;
        bu.deg_v = b.deg_u;
        bu.count_v = b.count_u;
        int d = bs_bspline_span_count(&bu, &nu, &nv) == BS_OK ? 1 : 0;
        return fail_surf(o, d, "knots decrease, repeat over degree + 1 times, leave an empty domain or span over DBL_MAX");
    }
    /* the surf statement's range s0 s1 t0 t1, within the knots' domain */
    const double *ku = b.knots_u, *kv = b.knots_v;
    double dom[4] = {ku[b.deg_u], ku[b.count_u], kv[b.deg_v], kv[b.count_v]}, cut[4];
    for (size_t d = 0; d < 4; d += 2) {
        cut[d] = o->range[d] > dom[d] ? o->range[d] : dom[d];
        cut[d + 1] = o->range[d + 1] < dom[d + 1] ? o->range[d + 1] : dom[d + 1];
        if (!(cut[d + 1] > cut[d]))
            return fail_surf(o, -1, "the surf range is empty or outside the knots' domain");
    }
    if (!bsi_spend_span_points(&o->points, o->len, nu, nv, b.deg_u, b.deg_v)) {
        (void)fail_surf(o, -1, BSI_READ_POINTS_SAY);
        return BS_ERR_SIZE;
    }
    bs_status st = bsi_add_bspline_range(o->s, &b, cut);
    if (st == BS_ERR_NONFINITE)
        return fail_surf(o, -1, "weight times coordinate overflows");
    if (st == BS_ERR_SIZE)
        return fail_surf(o, -1, "more patches than a surface can hold");
    return st;
}

static bs_status read_end(obj *o, size_t kw)
{
    if (o->body == BODY_NONE)
        return fail_at(o, kw, "%s", "end without surf");
    int body = o->body;
    o->body = BODY_NONE;
    if (body == BODY_OTHER)
        return BS_OK;
    double *ctrl = malloc(4 * o->refs.n * sizeof(double) + 1);
    if (ctrl == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status st = o->type == TYPE_BEZIER ? build_bezier(o, ctrl, ctrl + 3 * o->refs.n)
                                          : build_bspline(o, ctrl, ctrl + 3 * o->refs.n);
    free(ctrl);
    return st;
}

static bs_status statement(obj *o)
{
    size_t kw, klen;
    if (!next_token(o, &kw, &klen))
        return BS_OK;
    char c = o->text[kw];
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')))
        return fail_at(o, kw, "%s", "expected a statement keyword");
    if (token_is(o, kw, klen, "v"))
        return read_vertex(o);
    int cstype = token_is(o, kw, klen, "cstype"), deg = token_is(o, kw, klen, "deg");
    if ((cstype || deg) && o->body == BODY_SURF) /* the open surface keeps its type and degrees */
        return fail_at(o, kw, "%s before the end of the surface", cstype ? "cstype" : "deg");
    if (cstype)
        return read_cstype(o);
    if (deg)
        return read_degree(o);
    if (token_is(o, kw, klen, "surf"))
        return read_surf(o, kw);
    if (token_is(o, kw, klen, "parm"))
        return read_parm(o, kw);
    if (token_is(o, kw, klen, "end"))
        return read_end(o, kw);
    static const char *const elements[4] = {"f", "l", "p", "curv"};
    int curve = token_is(o, kw, klen, "curv") || token_is(o, kw, klen, "curv2");
    for (size_t e = 0; e < 4; e++)
        if (e == 3 ? curve : token_is(o, kw, klen, elements[e])) {
            if (o->skipped[0] + o->skipped[1] + o->skipped[2] + o->skipped[3] == 0)
                o->skip_line = o->line, o->skip_col = kw - o->line_start + 1;
            o->skipped[e]++;
        }
    if (curve) {
        if (o->body == BODY_SURF)
            return fail_at(o, kw, "%s", "curve before the end of the surface");
        o->body = BODY_OTHER;
    }
    return BS_OK; /* every other statement is skipped */
}

/* A text with polygons or curves but no surf: say what it holds instead of reading nothing. */
static bs_status only_skipped(const obj *o)
{
    static const char *const what[4] = {"faces (f)", "lines (l)", "points (p)", "curves"};
    char msg[96] = "no surface (surf) to read, only ";
    for (size_t e = 0, n = 0; e < 4; e++)
        if (o->skipped[e] > 0) {
            size_t at = strlen(msg);
            (void)snprintf(msg + at, sizeof msg - at, "%s%zu %s", n++ ? ", " : "", o->skipped[e], what[e]);
        }
    (void)bsi_fail(o->err, o->skip_line, o->skip_col, "%s", msg);
    return BS_ERR_UNSUPPORTED;
}

bs_status bs_surface_read_obj(const char *text, size_t len, bs_parse_error *err, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    len = bsi_text_len(text, len);
    obj o;
    memset(&o, 0, sizeof o);
    o.text = text;
    o.len = len;
    o.line = 1;
    o.err = err;
    const char *nul = len ? memchr(text, '\0', len) : NULL;
    if (nul != NULL) {
        for (size_t k = 0; text + k < nul; k++)
            if (text[k] == '\n')
                o.line++, o.line_start = k + 1;
        return fail_at(&o, (size_t)(nul - text), "%s", "NUL byte in the text");
    }
    bs_status st = bs_surface_create(&o.s);
    while (st == BS_OK && o.pos < o.len) {
        st = statement(&o);
        if (st == BS_OK)
            end_line(&o);
    }
    if (st == BS_OK && o.body == BODY_SURF)
        st = bsi_fail(err, o.surf_line, o.surf_col, "%s", "surface without end");
    if (st == BS_OK && o.surfs == 0 && o.skipped[0] + o.skipped[1] + o.skipped[2] + o.skipped[3] > 0)
        st = only_skipped(&o);
    free(o.verts.data);
    free(o.refs.data);
    free(o.parm[0].data);
    free(o.parm[1].data);
    if (st != BS_OK) {
        bs_surface_destroy(o.s);
        return st;
    }
    *out = o.s;
    return BS_OK;
}

bs_status bs_surface_read_obj_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    return bsi_read_surface_file(path, err, out, bs_surface_read_obj);
}
