/* Writing models as OBJ free-form text that bs_model_read_obj reads back to the same faces. Each
 * face is one surf: a BEZIER face whose patches share their sides bit for bit as a `bezier` surf
 * over its breaks (parm values), any other as a `bspline` surf whose every break is a knot of
 * multiplicity degree + 1, so that its spans are the face's patches exactly. Its loops are
 * `trim` (outer) and `hole` statements of curv2 curves written just before it, each a B-spline of
 * full-multiplicity knots at the trim's breaks (a reversed trim as its range backwards).
 * Numbers are shortest exact decimals. A rational trim's points are written as h / w: the reader's
 * w * (h / w) gives h back whenever h is itself w times a double (every curve read from OBJ); a
 * computed one (a conic, a B-spline cut inside a span) may come back an ulp away, and from then on
 * exactly.
 * OBJ has no face orientation: a reversed face is written with u and v exchanged (its native
 * parameters come back exchanged, its outward normal the same). Edges, shells and instances are
 * not written (the reader sews edges again). Faces with angular directions (cylinders, cones,
 * spheres, tori, revolutions) are written in the piecewise linear parameters of their patches
 * (obj_model_remap.c): read back, such a face has the same patches but other native parameters;
 * one with a trim those parameters cannot carry exactly is refused with BS_ERR_UNSUPPORTED. */
#include "io/obj_model.h"
#include "mesh/sink.h"

#include <stdlib.h>
#include <string.h>

#define REFS_PER_LINE 16 /* indices per line of a surf or curv2 statement, then a continuation */

typedef struct writer {
    bsi_sink *o;
    size_t nv, nvp, ncurve; /* vertices, parameter vertices and curv2 written so far */
} writer;

static void put_double(bsi_sink *o, double x)
{
    char tmp[32];
    bsi_sink_str(o, " ");
    bsi_sink_put(o, tmp, bsi_format_double(x, tmp));
}

static void put_refs(bsi_sink *o, size_t first, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        bsi_sink_str(o, k > 0 && k % REFS_PER_LINE == 0 ? " \\\n " : " ");
        bsi_sink_uint(o, first + k + 1);
    }
}

/* Breaks b[0..n] as knots, each repeated mult times. */
static void put_knots(bsi_sink *o, const char *dir, const double *b, size_t n, size_t mult)
{
    bsi_sink_str(o, "parm ");
    bsi_sink_str(o, dir);
    for (size_t k = 0; k <= n; k++)
        for (size_t r = 0; r < mult; r++)
            put_double(o, b[k]);
    bsi_sink_str(o, "\n");
}

static void put_point(bsi_sink *o, const bsi_face *f, const double *xy, int swap)
{
    double p[2];
    for (int d = 0; d < 2; d++)
        (void)bsi_objm_map(f, d, xy[d], &p[d]); /* mappable: checked by check_model */
    bsi_sink_str(o, "vp");
    put_double(o, p[swap ? 1 : 0]);
    put_double(o, p[swap ? 0 : 1]);
}

/* Trim curve c of face f as the next curv2, in the written parameters (exchanged when swap). */
static void put_curve(writer *wr, const bsi_face *f, const bsi_curve *c, int swap)
{
    bsi_sink *o = wr->o;
    int segment = bsi_objm_trim_form(f, c) == OBJM_SEGMENT;
    size_t n = segment ? 2 : c->axis.n * (c->degree + 1), degree = segment ? 1 : c->degree;
    int rat = 0;
    for (size_t k = 0; !segment && k < n; k++)
        rat |= c->hom[3 * k + 2] != 1.0;
    for (size_t k = 0; k < n; k++) {
        double xy[2];
        if (segment) {
            bsi_curve_point(c, k ? c->axis.n - 1 : 0, k ? 1.0 : 0.0, xy);
        } else {
            xy[0] = c->hom[3 * k] / c->hom[3 * k + 2];
            xy[1] = c->hom[3 * k + 1] / c->hom[3 * k + 2];
        }
        put_point(o, f, xy, swap);
        if (rat)
            put_double(o, c->hom[3 * k + 2]);
        bsi_sink_str(o, "\n");
    }
    bsi_sink_str(o, rat ? "cstype rat bspline\ndeg " : "cstype bspline\ndeg ");
    bsi_sink_uint(o, degree);
    bsi_sink_str(o, "\ncurv2");
    put_refs(o, wr->nvp, n);
    bsi_sink_str(o, "\n");
    if (segment) {
        double ends[2] = {c->axis.breaks[0], c->axis.breaks[c->axis.n]};
        put_knots(o, "u", ends, 1, 2);
    } else {
        put_knots(o, "u", c->axis.breaks, c->axis.n, c->degree + 1);
    }
    bsi_sink_str(o, "end\n");
    wr->nvp += n;
    wr->ncurve++;
}

/* Face f's patch holding OBJ segment (a, b), and the index of OBJ point (i, j) in it; tr: the
 * OBJ u direction is the patches' t direction. */
static const bs_patch *face_patch(const bs_model *m, const bsi_face *f, int tr, size_t a, size_t b,
                                  size_t i, size_t j, size_t *at)
{
    size_t cu = tr ? b : a, cv = tr ? a : b, ci = tr ? j : i, cj = tr ? i : j;
    const bs_patch *p = bs_surface_get(m->surface, f->first_patch + cu * f->av.n + cv);
    *at = ci * (p->deg_v + 1) + cj;
    return p;
}

/* 1 when the face's patches meet with identical control points along their shared sides, so that
 * OBJ's Bezier surface (shared points) holds them. */
static int sides_shared(const bs_model *m, const bsi_face *f)
{
    const bs_patch *p0 = bs_surface_get(m->surface, f->first_patch);
    size_t p = p0->deg_u, q = p0->deg_v;
    for (size_t a = 0; a < f->au.n; a++)
        for (size_t b = 0; b < f->av.n; b++)
            for (size_t i = 0; i <= p; i++)
                for (size_t j = 0; j <= q; j++) {
                    size_t x, y;
                    const bs_patch *pa = face_patch(m, f, 0, a, b, i, j, &x);
                    const bs_patch *pb = NULL;
                    if (i == p && a + 1 < f->au.n)
                        pb = face_patch(m, f, 0, a + 1, b, 0, j, &y);
                    else if (j == q && b + 1 < f->av.n)
                        pb = face_patch(m, f, 0, a, b + 1, i, 0, &y);
                    if (pb != NULL && (pa->ctrl[3 * x] != pb->ctrl[3 * y] || pa->ctrl[3 * x + 1] != pb->ctrl[3 * y + 1] ||
                                       pa->ctrl[3 * x + 2] != pb->ctrl[3 * y + 2] ||
                                       (pa->rational && pa->weights[x] != pb->weights[y])))
                        return 0;
                }
    return 1;
}

static void put_face(writer *wr, const bs_model *m, const bsi_face *f)
{
    bsi_sink *o = wr->o;
    int tr = f->swap != f->reversed;
    const bsi_axis *ax[2] = {tr ? &f->av : &f->au, tr ? &f->au : &f->av};
    const bs_patch *p0 = bs_surface_get(m->surface, f->first_patch);
    size_t deg[2] = {tr ? p0->deg_v : p0->deg_u, tr ? p0->deg_u : p0->deg_v};
    int rat = 0, bezier = f->kind == BS_FACE_BEZIER && sides_shared(m, f);
    for (size_t k = 0; k < f->patch_count; k++)
        rat |= bs_surface_get(m->surface, f->first_patch + k)->rational;
    size_t first_curve = wr->ncurve, loops = f->untrimmed ? 0 : f->loop_count; /* its box goes without saying */
    for (size_t l = f->first_loop; l < f->first_loop + loops; l++)
        for (size_t t = m->loops[l].first_trim; t < m->loops[l].first_trim + m->loops[l].trim_count; t++)
            put_curve(wr, f, &m->trims[t].uv, f->reversed);
    /* the OBJ net, u fastest: Bezier segments share their sides, B-spline spans do not */
    size_t step[2], cnt[2];
    for (int d = 0; d < 2; d++) {
        step[d] = bezier ? deg[d] : deg[d] + 1;
        cnt[d] = bezier ? ax[d]->n * deg[d] + 1 : ax[d]->n * (deg[d] + 1);
    }
    for (size_t jj = 0; jj < cnt[1]; jj++)
        for (size_t ii = 0; ii < cnt[0]; ii++) {
            size_t a = step[0] ? ii / step[0] : 0, b = step[1] ? jj / step[1] : 0, at;
            a = a < ax[0]->n ? a : ax[0]->n - 1;
            b = b < ax[1]->n ? b : ax[1]->n - 1;
            const bs_patch *p = face_patch(m, f, tr, a, b, ii - a * step[0], jj - b * step[1], &at);
            bsi_sink_str(o, "v");
            for (int c = 0; c < 3; c++)
                put_double(o, p->ctrl[3 * at + (size_t)c]);
            if (rat)
                put_double(o, p->rational ? p->weights[at] : 1.0);
            bsi_sink_str(o, "\n");
        }
    bsi_sink_str(o, rat ? "cstype rat " : "cstype ");
    bsi_sink_str(o, bezier ? "bezier\ndeg " : "bspline\ndeg ");
    bsi_sink_uint(o, deg[0]);
    bsi_sink_str(o, " ");
    bsi_sink_uint(o, deg[1]);
    bsi_sink_str(o, "\nsurf");
    const double *box = f->box;
    double obox[4] = {box[f->reversed ? 2 : 0], box[f->reversed ? 3 : 1], box[f->reversed ? 0 : 2],
                      box[f->reversed ? 1 : 3]};
    for (int k = 0; k < 4; k++)
        put_double(o, obox[k]);
    put_refs(o, wr->nv, cnt[0] * cnt[1]);
    bsi_sink_str(o, "\n");
    wr->nv += cnt[0] * cnt[1];
    put_knots(o, "u", ax[0]->breaks, ax[0]->n, bezier ? 1 : deg[0] + 1);
    put_knots(o, "v", ax[1]->breaks, ax[1]->n, bezier ? 1 : deg[1] + 1);
    for (size_t l = 0, k = first_curve; l < loops; l++) {
        const bsi_loop *loop = &m->loops[f->first_loop + l];
        bsi_sink_str(o, l == 0 ? "trim" : "hole");
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++, k++) {
            const bsi_curve *c = &m->trims[t].uv;
            int rev = m->trims[t].reversed;
            bsi_sink_str(o, t > loop->first_trim && (t - loop->first_trim) % 8 == 0 ? " \\\n" : "");
            put_double(o, c->axis.breaks[rev ? c->axis.n : 0]);
            put_double(o, c->axis.breaks[rev ? 0 : c->axis.n]);
            bsi_sink_str(o, " ");
            bsi_sink_uint(o, k + 1);
        }
        bsi_sink_str(o, "\n");
    }
    bsi_sink_str(o, "end\n");
}

/* What OBJ can hold exactly: patches of one degree, 2-D trims that obj_model_remap.c writes. */
static bs_status check_model(const bs_model *m)
{
    for (size_t k = 0; k < m->nface; k++) {
        const bsi_face *f = &m->faces[k];
        if (f->patch_count == 0 || f->patch_count != f->au.n * f->av.n)
            return BS_ERR_UNSUPPORTED;
        const bs_patch *p0 = bs_surface_get(m->surface, f->first_patch);
        for (size_t p = 1; p < f->patch_count; p++) {
            const bs_patch *q = bs_surface_get(m->surface, f->first_patch + p);
            if (q->deg_u != p0->deg_u || q->deg_v != p0->deg_v)
                return BS_ERR_UNSUPPORTED;
        }
        if (f->kind != BS_FACE_BEZIER && (p0->deg_u == 0 || p0->deg_v == 0))
            return BS_ERR_UNSUPPORTED;
        for (size_t l = f->first_loop; l < f->first_loop + f->loop_count; l++)
            for (size_t t = m->loops[l].first_trim; t < m->loops[l].first_trim + m->loops[l].trim_count; t++)
                if (m->trims[t].uv.dim != 2 || m->trims[t].uv.axis.n == 0 ||
                    bsi_objm_trim_form(f, &m->trims[t].uv) < 0)
                    return BS_ERR_UNSUPPORTED;
    }
    return BS_OK;
}

static void emit(const bs_model *m, bsi_sink *o)
{
    writer wr = {o, 0, 0, 0};
    bsi_sink_str(o, "# libbezsurf model: ");
    bsi_sink_uint(o, m->nface);
    bsi_sink_str(o, m->nface == 1 ? " face\n" : " faces\n");
    for (size_t k = 0; k < m->nface; k++)
        put_face(&wr, m, &m->faces[k]);
}

bs_status bs_model_write_obj(const bs_model *m, char *buf, size_t cap, size_t *size)
{
    if (m == NULL || size == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st = check_model(m);
    if (st != BS_OK)
        return st;
    bsi_sink measure = {NULL, NULL, 0, 0, 0};
    emit(m, &measure);
    *size = measure.len;
    if (buf != NULL) {
        if (cap < measure.len + 1)
            return BS_ERR_SIZE;
        bsi_sink out = {NULL, (unsigned char *)buf, cap, 0, 0};
        emit(m, &out);
        buf[out.len] = '\0';
    }
    return BS_OK;
}

bs_status bs_model_write_obj_file(const bs_model *m, const char *path)
{
    if (m == NULL || path == NULL)
        return BS_ERR_INVALID_ARG;
    size_t size = 0;
    bs_status st = bs_model_write_obj(m, NULL, 0, &size);
    if (st != BS_OK)
        return st;
    char *text = size < SIZE_MAX ? malloc(size + 1) : NULL;
    if (text == NULL)
        return BS_ERR_NO_MEMORY;
    st = bs_model_write_obj(m, text, size + 1, &size);
    if (st == BS_OK)
        st = bsi_write_file(path, text, size);
    free(text);
    return st;
}
