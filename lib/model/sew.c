/*
 * Edges of files without topology (IGES 144 faces, OBJ): two trims without an edge whose 3-D
 * images (the trim's uv on its face) coincide within tol become one edge. They may belong to two
 * faces or to one face at its seam, and run the same way or opposite ways.
 *
 * Two trims match when their end points coincide within tol (start to start and end to end, or
 * crossed), the points of the first at a quarter, half and three quarters of its range lie within
 * tol of the second's image, and the second's middle point within tol of the first's image. Each
 * trim is joined at most once, first come first served in the order of the keys below; a trim
 * whose image is one point (a pole, a collapsed side) gets no edge. Closed trims (a hole's whole
 * loop in one trim) left over are matched again by their images alone, as the two sides may start
 * the loop at different points; closed trims still left over, once more within loose_tol (a
 * file may write a hole's two trims that far apart: block.igs, 6.3e-4 D; the tessellator moves
 * such an edge's vertices to where its faces meet). Not joined: trims split differently on the
 * two sides (one trim along two of the neighbour's: their ends differ), and a third trim along
 * an edge already joined (non-manifold); their faces' shells are then open.
 *
 * Cost: each trim gets a key that does not depend on its direction (the sum of the coordinates of
 * both end points), trims are sorted by key, and only trims whose keys differ by at most 6 tol
 * are compared: O(T log T) for T trims unless many share one key (as lib/surface/topology.c).
 */
#include "model/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define COARSE 16  /* samples of the second image in the search for the point nearest a point */
#define GOLDEN 60  /* golden-section steps: 0.618^60 of a sample interval */

typedef struct sew_key {
    double key;
    size_t trim;
} sew_key;

typedef struct sew_trim {
    uint32_t face;
    int skip;         /* has an edge, is degenerate, or cannot be evaluated */
    double a[3], b[3]; /* 3-D start and end */
    double lo[3], hi[3]; /* closed trims: the box of samples of the image */
} sew_trim;

static double dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* The trim's 3-D point at fraction x of its parameter range: 1, or 0 outside its face. */
static int trim_point(const bs_model *m, size_t f, const bsi_curve *c, double x, double *p)
{
    double t0 = c->axis.breaks[0], t1 = c->axis.breaks[c->axis.n], s;
    /* the end itself at x = 1 (t0 + (t1 - t0) may round past t1, off the axis) */
    double t = x >= 1.0 ? t1 : t0 + x * (t1 - t0);
    size_t k;
    if (c->dim != 2 || !bsi_axis_locate(&c->axis, t, &k, &s))
        return 0;
    double h[BS_MAX_DEGREE + 1][3];
    size_t n = c->degree;
    memcpy(h, c->hom + k * (n + 1) * 3, (n + 1) * 3 * sizeof(double));
    for (size_t r = 1; r <= n; r++)
        for (size_t i = 0; i + r <= n; i++)
            for (int j = 0; j < 3; j++)
                h[i][j] = (1.0 - s) * h[i][j] + s * h[i + 1][j];
    double uv[2] = {h[0][0] / h[0][2], h[0][1] / h[0][2]};
    /* ends a rounding outside the box (u = -2e-16 of [0, 1]) are on its side */
    const bsi_face *face = &m->faces[f];
    for (size_t d = 0; d < 2; d++) {
        double lo = face->box[2 * d], hi = face->box[2 * d + 1], eps = 1e-9 * (hi - lo);
        if (!(face->period[d] > 0.0) && uv[d] < lo && uv[d] >= lo - eps)
            uv[d] = lo;
        if (!(face->period[d] > 0.0) && uv[d] > hi && uv[d] <= hi + eps)
            uv[d] = hi;
    }
    return bsi_face_point(m, f, uv[0], uv[1], p);
}

/* Whether q is within tol of the image of trim t: at fraction guess (the two images alike
 * parametrized, the usual case), else at the nearest of COARSE + 1 samples refined by golden
 * sections on the two intervals beside it. */
static int near_image(const bs_model *m, const sew_trim *st, const bsi_trim *t, const double *q,
                      double guess, double tol)
{
    double best = INFINITY, p[3];
    if (trim_point(m, st->face, &t->uv, guess, p) && dist3(p, q) <= tol)
        return 1;
    int at = 0;
    for (int i = 0; i <= COARSE; i++) {
        if (!trim_point(m, st->face, &t->uv, (double)i / COARSE, p))
            return 0;
        double d = dist3(p, q);
        if (d < best) {
            best = d;
            at = i;
        }
    }
    const double g = 0.6180339887498949;
    double lo = (double)(at > 0 ? at - 1 : 0) / COARSE, hi = (double)(at < COARSE ? at + 1 : COARSE) / COARSE;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), d1, d2;
    if (!trim_point(m, st->face, &t->uv, x1, p))
        return 0; /* LCOV_EXCL_LINE: inside the range sampled above */
    d1 = dist3(p, q);
    if (!trim_point(m, st->face, &t->uv, x2, p))
        return 0; /* LCOV_EXCL_LINE */
    d2 = dist3(p, q);
    for (int i = 0; i < GOLDEN; i++) {
        if (d1 < d2) {
            hi = x2;
            x2 = x1;
            d2 = d1;
            x1 = hi - g * (hi - lo);
            if (!trim_point(m, st->face, &t->uv, x1, p))
                return 0; /* LCOV_EXCL_LINE */
            d1 = dist3(p, q);
        } else {
            lo = x1;
            x1 = x2;
            d1 = d2;
            x2 = lo + g * (hi - lo);
            if (!trim_point(m, st->face, &t->uv, x2, p))
                return 0; /* LCOV_EXCL_LINE */
            d2 = dist3(p, q);
        }
    }
    return fmin(best, fmin(d1, d2)) <= tol;
}

/* Whether trims i and j (their ends already known) have the same image. */
static int same_image(const bs_model *m, const sew_trim *st, size_t i, size_t j, double tol)
{
    const sew_trim *a = &st[i], *b = &st[j];
    int crossed;
    if (dist3(a->a, b->a) <= tol && dist3(a->b, b->b) <= tol)
        crossed = 0;
    else if (dist3(a->a, b->b) <= tol && dist3(a->b, b->a) <= tol)
        crossed = 1;
    else
        return 0;
    static const double at[3] = {0.5, 0.25, 0.75};
    double p[3];
    for (int k = 0; k < 3; k++)
        if (!trim_point(m, a->face, &m->trims[i].uv, at[k], p) ||
            !near_image(m, b, &m->trims[j], p, crossed ? 1.0 - at[k] : at[k], tol))
            return 0;
    return trim_point(m, b->face, &m->trims[j].uv, 0.5, p) && near_image(m, a, &m->trims[i], p, 0.5, tol);
}

static int by_key(const void *x, const void *y)
{
    const sew_key *a = x, *b = y;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return a->trim < b->trim ? -1 : a->trim > b->trim;
}

/* A closed trim's box of COARSE samples (1), or 0 when a sample is off its face. */
static int sample_box(const bs_model *m, size_t t, sew_trim *st)
{
    double p[3];
    for (int i = 0; i < COARSE; i++) {
        if (!trim_point(m, st->face, &m->trims[t].uv, (double)i / COARSE, p))
            return 0; /* LCOV_EXCL_LINE: the ends were evaluated; a middle off the face */
        for (int c = 0; c < 3; c++) {
            st->lo[c] = i ? fmin(st->lo[c], p[c]) : p[c];
            st->hi[c] = i ? fmax(st->hi[c], p[c]) : p[c];
        }
    }
    return 1;
}

/* Whether closed trims i and j are one loop, started at different points: the boxes of their
 * samples overlap, each start lies on the other's image, the quarter points of i and the middle
 * of j on the other's image. */
static int same_loop(const bs_model *m, const sew_trim *st, size_t i, size_t j, double tol)
{
    const sew_trim *a = &st[i], *b = &st[j];
    for (int c = 0; c < 3; c++)
        if (a->lo[c] > b->hi[c] + tol || b->lo[c] > a->hi[c] + tol)
            return 0;
    static const double at[3] = {0.25, 0.5, 0.75};
    double p[3];
    if (!near_image(m, b, &m->trims[j], a->a, 0.0, tol) || !near_image(m, a, &m->trims[i], b->a, 0.0, tol))
        return 0;
    for (int k = 0; k < 3; k++)
        if (!trim_point(m, a->face, &m->trims[i].uv, at[k], p) || !near_image(m, b, &m->trims[j], p, at[k], tol))
            return 0;
    return trim_point(m, b->face, &m->trims[j].uv, 0.5, p) && near_image(m, a, &m->trims[i], p, 0.5, tol);
}

/* Trims left unpaired that are closed within closed_tol (a hole's loop and the neighbour's,
 * started at different points), matched within tol: sorted by the low x of their sample boxes,
 * compared while the boxes can overlap. */
static size_t pair_loops(const bs_model *m, sew_trim *st, sew_key *keys, size_t *pair, double closed_tol,
                         double tol)
{
    size_t T = m->ntrim, nk = 0, npair = 0;
    for (size_t t = 0; t < T; t++)
        if (!st[t].skip && pair[t] == T && dist3(st[t].a, st[t].b) <= closed_tol && sample_box(m, t, &st[t])) {
            keys[nk].key = st[t].lo[0];
            keys[nk++].trim = t;
        }
    qsort(keys, nk, sizeof *keys, by_key);
    for (size_t i = 0; i < nk; i++) {
        size_t a = keys[i].trim;
        for (size_t j = i + 1; pair[a] == T && j < nk && keys[j].key <= st[a].hi[0] + tol; j++) {
            size_t b = keys[j].trim;
            if (pair[b] == T && same_loop(m, st, a, b, tol)) {
                pair[a] = b;
                pair[b] = a;
                npair++;
            }
        }
    }
    return npair;
}

/* The trim's face, ends, and whether it is left out (an edge already, degenerate, unevaluable). */
static void describe(const bs_model *m, size_t f, size_t t, double tol, sew_trim *out)
{
    const bsi_trim *tr = &m->trims[t];
    double p[3];
    out->face = (uint32_t)f;
    out->skip = 1;
    if (tr->edge != BSI_NO_EDGE || tr->uv.axis.n == 0 || tr->uv.hom == NULL ||
        !trim_point(m, f, &tr->uv, 0.0, out->a) || !trim_point(m, f, &tr->uv, 1.0, out->b))
        return;
    int point = dist3(out->a, out->b) <= tol;
    for (int k = 1; k < 4 && point; k++)
        point = trim_point(m, f, &tr->uv, 0.25 * k, p) && dist3(p, out->a) <= tol;
    out->skip = point;
}


bs_status bsi_model_sew(bs_model *m, double tol, double loose_tol)
{
    size_t T = m->ntrim;
    if (T < 2)
        return BS_OK;
    sew_trim *st = malloc(T * sizeof *st);
    sew_key *keys = malloc(T * sizeof *keys);
    size_t *pair = malloc(T * sizeof *pair); /* the matched partner, T: none */
    if (st == NULL || keys == NULL || pair == NULL) {
        free(st);
        free(keys);
        free(pair);
        return BS_ERR_NO_MEMORY;
    }
    for (size_t t = 0; t < T; t++)
        st[t].skip = 1; /* trims of no loop */
    for (size_t f = 0; f < m->nface; f++)
        for (size_t l = m->faces[f].first_loop; l < m->faces[f].first_loop + m->faces[f].loop_count; l++)
            for (size_t t = m->loops[l].first_trim; t < m->loops[l].first_trim + m->loops[l].trim_count; t++)
                describe(m, f, t, tol, &st[t]);
    size_t nk = 0;
    for (size_t t = 0; t < T; t++) {
        pair[t] = T;
        if (!st[t].skip) {
            keys[nk].key = st[t].a[0] + st[t].a[1] + st[t].a[2] + st[t].b[0] + st[t].b[1] + st[t].b[2];
            keys[nk++].trim = t;
        }
    }
    qsort(keys, nk, sizeof *keys, by_key);
    size_t npair = 0;
    for (size_t i = 0; i < nk; i++) {
        size_t a = keys[i].trim;
        for (size_t j = i + 1; pair[a] == T && j < nk && keys[j].key - keys[i].key <= 6.0 * tol; j++) {
            size_t b = keys[j].trim;
            if (pair[b] == T && same_image(m, st, a, b, tol)) {
                pair[a] = b;
                pair[b] = a;
                npair++;
            }
        }
    }
    npair += pair_loops(m, st, keys, pair, tol, tol);
    npair += pair_loops(m, st, keys, pair, tol, loose_tol);
    /* the edges first, then the trims: on failure the model is as before */
    size_t before = m->nedge;
    bs_status status = BS_OK;
    for (size_t k = 0; k < npair && status == BS_OK; k++) {
        uint32_t e;
        status = bsi_model_add_edge(m, &e);
    }
    if (status != BS_OK) {
        m->nedge = before;
    } else {
        uint32_t next = (uint32_t)before;
        for (size_t t = 0; t < T; t++)
            if (pair[t] < t) {
                m->trims[t].edge = m->trims[pair[t]].edge = next++;
            }
    }
    free(st);
    free(keys);
    free(pair);
    return status;
}
