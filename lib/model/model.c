/*
 * The model: built face by face by a reader (bsi_model_add_face), then frozen by
 * bsi_model_finish (edges sewn, shells judged closed or open); afterwards only read.
 */
#include "model/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

bs_status bsi_model_create(bs_model **out)
{
    bs_model *m = calloc(1, sizeof *m);
    if (m == NULL)
        return BS_ERR_NO_MEMORY;
    if (bs_surface_create(&m->surface) != BS_OK) {
        free(m);
        return BS_ERR_NO_MEMORY;
    }
    *out = m;
    return BS_OK;
}

void bs_model_destroy(bs_model *m)
{
    if (m == NULL)
        return;
    for (size_t f = 0; f < m->nface; f++) {
        bsi_axis_free(&m->faces[f].au);
        bsi_axis_free(&m->faces[f].av);
    }
    for (size_t t = 0; t < m->ntrim; t++)
        bsi_curve_free(&m->trims[t].uv);
    free(m->faces);
    free(m->loops);
    free(m->trims);
    free(m->edges);
    free(m->shell_closed);
    bs_surface_destroy(m->surface);
    free(m);
}

/* Room for `more` elements in an array of *cap (doubling): BS_OK or BS_ERR_NO_MEMORY. */
static bs_status reserve(void **data, size_t *cap, size_t n, size_t more, size_t elem)
{
    if (more <= *cap - n)
        return BS_OK;
    size_t want = *cap ? *cap : 8;
    while (want - n < more) {
        if (want > SIZE_MAX / 2 / elem)
            return BS_ERR_NO_MEMORY;
        want *= 2;
    }
    void *grown = realloc(*data, want * elem);
    if (grown == NULL)
        return BS_ERR_NO_MEMORY;
    *data = grown;
    *cap = want;
    return BS_OK;
}

/* The native box of a face: given, the unit square of a Bezier face, or the loops' bounds (the
 * trims' lo and hi, set by bsi_model_add_face). */
static bs_status face_box(const bsi_face_spec *spec, double *box)
{
    if (spec->box != NULL) {
        memcpy(box, spec->box, 4 * sizeof *box);
    } else if (spec->def == NULL) {
        box[0] = box[2] = 0.0;
        box[1] = box[3] = 1.0;
    } else {
        if (spec->ntrim == 0)
            return BS_ERR_DOMAIN;
        box[0] = box[2] = INFINITY;
        box[1] = box[3] = -INFINITY;
        for (size_t t = 0; t < spec->ntrim; t++) {
            const double *lo = spec->trims[t].lo, *hi = spec->trims[t].hi;
            box[0] = fmin(box[0], lo[0]);
            box[1] = fmax(box[1], hi[0]);
            box[2] = fmin(box[2], lo[1]);
            box[3] = fmax(box[3], hi[1]);
        }
    }
    if (!(isfinite(box[0]) && isfinite(box[1]) && isfinite(box[2]) && isfinite(box[3]) &&
          box[0] < box[1] && box[2] < box[3]))
        return BS_ERR_DOMAIN;
    return BS_OK;
}

/* The face's patches appended to the model's surface, and its axes. */
static bs_status face_patches(bs_model *m, const bsi_face_spec *spec, const double *box, bsi_face *face)
{
    if (spec->def == NULL) {
        if (spec->patch == NULL || bs_patch_dim(spec->patch) != 3)
            return BS_ERR_INVALID_ARG;
        bs_patch *copy;
        bs_status st = bs_patch_clone(spec->patch, &copy);
        if (st != BS_OK)
            return st;
        if ((st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &face->au)) != BS_OK ||
            (st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &face->av)) != BS_OK ||
            (st = bsi_surface_adopt(m->surface, &copy, 1)) != BS_OK) {
            bs_patch_destroy(copy);
            bsi_axis_free(&face->au);
            bsi_axis_free(&face->av);
            return st;
        }
        return BS_OK;
    }
    double canon[4] = {box[0], box[1], box[2], box[3]};
    if (spec->swap) {
        canon[0] = box[2], canon[1] = box[3], canon[2] = box[0], canon[3] = box[1];
    }
    double period[2];
    bsi_surface_def_periods(spec->def, &period[0], &period[1]);
    face->period[0] = period[spec->swap ? 1 : 0];
    face->period[1] = period[spec->swap ? 0 : 1];
    return bsi_surface_def_patches(spec->def, canon, m->surface, &face->au, &face->av);
}

bs_status bsi_model_add_face(bs_model *m, const bsi_face_spec *spec, size_t *face_id)
{
    bs_status st;
    bsi_face face;
    memset(&face, 0, sizeof face);
    size_t first_patch = bs_surface_count(m->surface);
    size_t looped = 0;
    for (size_t l = 0; l < spec->nloop; l++)
        looped += spec->loop_len[l];
    if (looped != spec->ntrim || m->nface >= UINT32_MAX) {
        st = looped != spec->ntrim ? BS_ERR_INVALID_ARG : BS_ERR_SIZE;
        goto fail;
    }
    for (size_t t = 0; t < spec->ntrim; t++) /* once: the box below and every later point test */
        bsi_curve_bounds(&spec->trims[t].uv, spec->trims[t].lo, spec->trims[t].hi);
    if ((st = face_box(spec, face.box)) != BS_OK ||
        (st = reserve((void **)&m->faces, &m->face_cap, m->nface, 1, sizeof *m->faces)) != BS_OK ||
        (st = reserve((void **)&m->loops, &m->loop_cap, m->nloop, spec->nloop, sizeof *m->loops)) != BS_OK ||
        (st = reserve((void **)&m->trims, &m->trim_cap, m->ntrim, spec->ntrim, sizeof *m->trims)) != BS_OK ||
        (st = face_patches(m, spec, face.box, &face)) != BS_OK)
        goto fail;
    face.kind = spec->def ? spec->def->kind : BS_FACE_BEZIER;
    face.reversed = spec->reversed != 0;
    face.swap = spec->swap != 0;
    face.shell = spec->shell;
    face.instance = spec->instance;
    face.first_patch = first_patch;
    face.patch_count = bs_surface_count(m->surface) - first_patch;
    face.first_loop = m->nloop;
    face.loop_count = spec->nloop;
    face.untrimmed = spec->untrimmed != 0 && spec->nloop == 1;
    for (size_t l = 0, t = m->ntrim; l < spec->nloop; l++) {
        m->loops[m->nloop].first_trim = t;
        m->loops[m->nloop].trim_count = spec->loop_len[l];
        m->nloop++;
        t += spec->loop_len[l];
    }
    for (size_t t = 0; t < spec->ntrim; t++) {
        m->trims[m->ntrim++] = spec->trims[t];
        memset(&spec->trims[t].uv, 0, sizeof spec->trims[t].uv);
    }
    if (spec->shell >= m->nshell)
        m->nshell = spec->shell + 1;
    bsi_face_speed(m, &face, face.lip); /* once: every later test for nearness to its trims */
    m->faces[m->nface++] = face;
    if (face_id != NULL)
        *face_id = m->nface - 1;
    return BS_OK;
fail:
    for (size_t t = 0; t < spec->ntrim; t++)
        bsi_curve_free(&spec->trims[t].uv);
    return st;
}

bs_status bsi_model_add_edge(bs_model *m, uint32_t *edge)
{
    if (m->nedge >= UINT32_MAX - 1)
        return BS_ERR_SIZE;
    bs_status st = reserve((void **)&m->edges, &m->edge_cap, m->nedge, 1, sizeof *m->edges);
    if (st != BS_OK)
        return st;
    m->edges[m->nedge].uses = 0;
    m->edges[m->nedge].face[0] = m->edges[m->nedge].face[1] = UINT32_MAX;
    *edge = (uint32_t)m->nedge++;
    return BS_OK;
}

double bsi_model_diagonal(const bs_model *m)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p < bs_surface_count(m->surface); p++) {
        double plo[3], phi[3];
        if (bs_patch_bounds(bs_surface_get(m->surface, p), plo, phi) != BS_OK)
            continue;
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], plo[c]);
            hi[c] = fmax(hi[c], phi[c]);
        }
    }
    double d = 0.0;
    for (int c = 0; c < 3; c++)
        if (hi[c] >= lo[c])
            d = hypot(d, hi[c] - lo[c]);
    return d;
}

/* 1 when the trim's image on its face is one point within tol (a pole, a collapsed side):
 * judged at the ends and middle of each segment. */
static int trim_degenerate(const bs_model *m, size_t f, const bsi_trim *t, double tol)
{
    double first[3] = {0, 0, 0}, p[3] = {0, 0, 0}, uv[2];
    int have = 0;
    for (size_t k = 0; k < t->uv.axis.n; k++)
        for (int i = 0; i <= 2; i++) {
            bsi_curve_point(&t->uv, k, 0.5 * (double)i, uv);
            if (!bsi_face_point(m, f, uv[0], uv[1], have ? p : first))
                return 0;
            if (have && hypot(hypot(p[0] - first[0], p[1] - first[1]), p[2] - first[2]) > tol)
                return 0;
            have = 1;
        }
    return have;
}

bs_status bsi_model_finish(bs_model *m)
{
    /* trims within 1e-7 D are one edge; closed ones (holes) left over within BSI_LOOSE_GAP too */
    double diag = bsi_model_diagonal(m), tol = 1e-7 * diag;
    bs_status st = bsi_model_sew(m, tol, BSI_LOOSE_GAP * diag);
    if (st != BS_OK)
        return st;
    unsigned char *closed = malloc(m->nshell ? m->nshell : 1);
    if (closed == NULL)
        return BS_ERR_NO_MEMORY;
    memset(closed, 1, m->nshell ? m->nshell : 1);
    for (size_t e = 0; e < m->nedge; e++)
        m->edges[e].uses = 0;
    for (size_t f = 0; f < m->nface; f++) {
        const bsi_face *face = &m->faces[f];
        if (face->loop_count == 0 && face->kind != BS_FACE_BEZIER)
            closed[face->shell] = 0;
        for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++)
            for (size_t t = m->loops[l].first_trim; t < m->loops[l].first_trim + m->loops[l].trim_count; t++) {
                uint32_t e = m->trims[t].edge;
                if (e == BSI_NO_EDGE || e >= m->nedge) {
                    if (!trim_degenerate(m, f, &m->trims[t], tol))
                        closed[face->shell] = 0;
                    continue;
                }
                bsi_edge *edge = &m->edges[e];
                if (edge->uses < 2)
                    edge->face[edge->uses] = (uint32_t)f;
                edge->uses++;
            }
    }
    for (size_t e = 0; e < m->nedge; e++) {
        const bsi_edge *edge = &m->edges[e];
        if (edge->uses != 2 && edge->face[0] != UINT32_MAX)
            closed[m->faces[edge->face[0]].shell] = 0;
    }
    /* a shell of untrimmed Bezier faces (bs_model_from_surface) is judged by its sewn sides */
    free(m->shell_closed);
    m->shell_closed = closed;
    return BS_OK;
}

size_t bs_model_face_count(const bs_model *m) { return m ? m->nface : 0; }
size_t bs_model_edge_count(const bs_model *m) { return m ? m->nedge : 0; }
size_t bs_model_shell_count(const bs_model *m) { return m ? m->nshell : 0; }
const bs_surface *bs_model_surface(const bs_model *m) { return m ? m->surface : NULL; }

int bs_model_shell_closed(const bs_model *m, size_t shell)
{
    if (m == NULL || shell >= m->nshell || m->shell_closed == NULL)
        return -1;
    return m->shell_closed[shell];
}

bs_status bs_model_face_info(const bs_model *m, size_t face, bs_face_info *info)
{
    if (m == NULL || info == NULL || info->size < sizeof(bs_face_info))
        return BS_ERR_INVALID_ARG;
    if (face >= m->nface)
        return BS_ERR_DOMAIN;
    const bsi_face *f = &m->faces[face];
    bs_face_info out;
    memset(&out, 0, sizeof out);
    out.size = sizeof out;
    out.kind = f->kind;
    out.reversed = f->reversed;
    out.shell = f->shell;
    out.instance = f->instance;
    out.first_patch = f->first_patch;
    out.patch_count = f->patch_count;
    out.loop_count = f->untrimmed ? 0 : f->loop_count;
    out.u0 = f->box[0];
    out.u1 = f->box[1];
    out.v0 = f->box[2];
    out.v1 = f->box[3];
    memcpy(info, &out, sizeof out);
    return BS_OK;
}
