/* IGES curves for models: 124 transformation chains (each 124 parsed once, iges_matrix.c), 100
 * circular arcs, 104 elliptic arcs, 110 lines, 126 B-spline curves and 102 composites, each built
 * once into 3-D pieces (a composite's pieces are its curves' pieces in order) with the
 * transformations of its directory entry. */
#include "io/iges_model.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586

bs_status bsi_igm_matrix(igm *m, size_t s, double *mat)
{
    static const double id[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    memcpy(mat, id, sizeof id);
    long t;
    size_t cur = s;
    bs_status r = bsi_iges_de_field(&m->g, 2 * cur, 7, &t);
    for (int depth = 0; r == BS_OK && t != 0; depth++) {
        if (depth == IGM_DEPTH)
            return bsi_igm_fail(m, s, 7, "chain of transformations longer than 16 or circular");
        if (t < 0 || t % 2 == 0 || (size_t)t >= m->g.count[IGES_D])
            return bsi_igm_fail(m, cur, 7, "transformation pointer to no directory entry");
        size_t ts = (size_t)(t - 1) / 2;
        if (m->slot[ts].type != 124)
            return bsi_igm_fail(m, cur, 7, "transformation pointer to entity %ld, not 124", m->slot[ts].type);
        const double *a;
        if ((r = bsi_iges_124(&m->g, 2 * ts, &a)) != BS_OK)
            return bsi_igm_name(m, ts, r);
        double out[12];
        for (size_t i = 0; i < 3; i++)
            for (size_t j = 0; j < 4; j++)
                out[4 * i + j] = a[4 * i] * mat[j] + a[4 * i + 1] * mat[4 + j] + a[4 * i + 2] * mat[8 + j] +
                                 (j == 3 ? a[4 * i + 3] : 0.0);
        memcpy(mat, out, sizeof out);
        cur = ts;
        r = bsi_iges_de_field(&m->g, 2 * cur, 7, &t);
    }
    return r;
}

void bsi_igm_move(bsi_curve *c, const double *mat)
{
    double a[12]; /* bsi_curve_transform's order: the 3x3 part row by row, then the shift */
    for (size_t i = 0; i < 3; i++) {
        for (size_t j = 0; j < 3; j++)
            a[3 * i + j] = mat[4 * i + j];
        a[9 + i] = mat[4 * i + 3];
    }
    bsi_curve_transform(c, a);
}

bs_status bsi_igm_curve2(const bsi_curve *c, const double *a, bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    size_t n = c->axis.n * (c->degree + 1);
    out->dim = 2;
    out->degree = c->degree;
    out->hom = malloc((n ? n : 1) * 3 * sizeof *out->hom);
    if (out->hom == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status r = bsi_axis_copy(&c->axis, &out->axis);
    if (r != BS_OK) {
        free(out->hom);
        out->hom = NULL;
        return r;
    }
    for (size_t k = 0; k < n; k++) {
        const double *h = c->hom + 4 * k;
        for (size_t i = 0; i < 2; i++)
            out->hom[3 * k + i] = a[4 * i] * h[0] + a[4 * i + 1] * h[1] + a[4 * i + 2] * h[2] + a[4 * i + 3] * h[3];
        out->hom[3 * k + 2] = h[3];
    }
    return BS_OK;
}

/* Room for one more piece in slot e. */
static bs_status more_pieces(igm_slot *e)
{
    size_t n = e->npieces;
    if (n != 0 && (n & (n - 1)) != 0)
        return BS_OK; /* capacity is the next power of two */
    bsi_curve *grown = realloc(e->pieces, (n ? 2 * n : 1) * sizeof *grown);
    if (grown == NULL)
        return BS_ERR_NO_MEMORY;
    e->pieces = grown;
    return BS_OK;
}

static bs_status reals(igm *m, iges_stream *st, size_t n, double *x, const char *what)
{
    iges_field f;
    bs_status r = BS_OK;
    for (size_t k = 0; k < n && r == BS_OK; k++)
        r = bsi_iges_real(&m->g, st, what, &x[k], &f);
    return r;
}

/* The end angle of an arc from a0 to a1 counter-clockwise: a full turn when the ends coincide. */
static double end_angle(double a0, double a1, int closed)
{
    if (closed)
        return a0 + TWO_PI;
    while (a1 <= a0)
        a1 += TWO_PI;
    return a1;
}

static bs_status arc_100(igm *m, size_t s, iges_stream *st, bsi_curve *out)
{
    double v[7];
    bs_status r = reals(m, st, 7, v, "an arc's coordinate");
    if (r != BS_OK)
        return r;
    double rad = hypot(v[3] - v[1], v[4] - v[2]);
    if (!(rad > 0.0) || !isfinite(rad))
        return bsi_igm_fail(m, s, 1, "arc of radius 0");
    int closed = hypot(v[5] - v[3], v[6] - v[4]) <= 1e-12 * rad;
    double a0 = atan2(v[4] - v[2], v[3] - v[1]);
    double a1 = end_angle(a0, atan2(v[6] - v[2], v[5] - v[1]), closed);
    double c[3] = {v[1], v[2], v[0]}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    return bsi_curve_conic(3, c, x, y, rad, rad, 1.0, a0, a1, out);
}

static bs_status conic_104(igm *m, size_t s, iges_stream *st, bsi_curve *out)
{
    double v[11];
    bs_status r = reals(m, st, 11, v, "a conic's coefficient or coordinate");
    if (r != BS_OK)
        return r;
    double scale = fmax(fmax(fabs(v[0]), fabs(v[2])), fabs(v[5]));
    if (m->slot[s].form > 1 || !(v[0] * v[2] > 0.0) || !(v[0] * v[5] < 0.0) ||
        fabs(v[1]) + fabs(v[3]) + fabs(v[4]) > 1e-12 * scale) {
        (void)bsi_igm_fail(m, s, 15, "only elliptic arcs in standard position are read");
        return BS_ERR_UNSUPPORTED;
    }
    double rx = sqrt(-v[5] / v[0]), ry = sqrt(-v[5] / v[2]);
    int closed = hypot(v[9] - v[7], v[10] - v[8]) <= 1e-12 * fmax(rx, ry);
    double a0 = atan2(v[8] / ry, v[7] / rx);
    double a1 = end_angle(a0, atan2(v[10] / ry, v[9] / rx), closed);
    double c[3] = {0, 0, v[6]}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    return bsi_curve_conic(3, c, x, y, rx, ry, 1.0, a0, a1, out);
}

static bs_status line_110(igm *m, iges_stream *st, bsi_curve *out)
{
    double v[6];
    bs_status r = reals(m, st, 6, v, "a line's coordinate");
    if (r != BS_OK)
        return r;
    double d[3] = {v[3] - v[0], v[4] - v[1], v[5] - v[2]};
    return bsi_curve_line(3, v, d, 0.0, 1.0, out);
}

static bs_status bspline_126(igm *m, size_t s, iges_stream *st, bsi_curve *out)
{
    long v[6];
    size_t room = st->nrec * st->width, at = st->pos;
    static const char *const names[6] = {"the upper index K", "the degree M", "PROP1 (planar)", "PROP2 (closed)",
                                         "PROP3 (polynomial)", "PROP4 (periodic)"};
    bs_status r = BS_OK;
    for (size_t k = 0; k < 6 && r == BS_OK; k++)
        r = bsi_iges_int(&m->g, st, names[k], k == 0 ? 1 : k == 1 ? 1 : 0,
                         k == 0 ? (long)(room < 99999999 ? room : 99999999) : k == 1 ? BS_MAX_DEGREE : 1, &v[k]);
    if (r != BS_OK)
        return r;
    size_t n = (size_t)v[0] + 1, deg = (size_t)v[1];
    if (n < deg + 1)
        return bsi_iges_fail_at(&m->g, st, at, "K must be at least the degree M");
    if (n > room / 4)
        return bsi_iges_fail_at(&m->g, st, at, "more control points than the parameter data can hold");
    size_t nk = n + deg + 1, total = nk + 4 * n + 2;
    m->vals.n = 0;
    for (size_t k = 0; k < total && r == BS_OK; k++) { /* grown as read */
        if ((r = bsi_grow(&m->vals, sizeof(double), 1)) != BS_OK)
            return r;
        r = reals(m, st, 1, (double *)m->vals.data + m->vals.n++, "a knot, weight, point or range");
    }
    if (r != BS_OK || (r = bsi_igm_rest(m, st)) != BS_OK)
        return r;
    const double *knots = m->vals.data, *w = knots + nk, *pts = w + n, *range = pts + 3 * n;
    int rational = 0;
    for (size_t k = 0; k < n; k++) {
        if (!(w[k] > 0.0))
            return bsi_igm_fail(m, s, 1, "weights must be positive");
        rational |= w[k] != w[0];
    }
    r = bsi_curve_bspline(3, deg, n, knots, pts, rational ? w : NULL, range[0], range[1], out);
    if (r == BS_ERR_DOMAIN || r == BS_ERR_SIZE || r == BS_ERR_DEGREE || r == BS_ERR_NONFINITE)
        return bsi_igm_fail(m, s, 1, "knots or parameter range V0, V1 refused");
    return r;
}

bs_status bsi_igm_spend(igm *m, size_t s, size_t c)
{
    size_t cost = 1, cap = m->g.len < SIZE_MAX / 8 ? 8 * m->g.len : SIZE_MAX;
    for (size_t k = 0; k < m->slot[c].npieces; k++)
        cost += m->slot[c].pieces[k].axis.n * (m->slot[c].pieces[k].degree + 1);
    if (cost > cap - m->copies)
        return bsi_igm_fail(m, s, 1, "curves reused more often than the file's size allows");
    m->copies += cost;
    return BS_OK;
}

static bs_status composite_102(igm *m, size_t s, iges_stream *st, int depth)
{
    long n;
    igm_slot *e = &m->slot[s];
    bs_status r = bsi_iges_int(&m->g, st, "the number of curves", 1, 99999999L, &n);
    for (long k = 0; k < n && r == BS_OK; k++) {
        size_t c;
        if ((r = bsi_igm_ptr(m, s, st, "a curve pointer", 0, &c, NULL)) != BS_OK ||
            (r = bsi_igm_curve(m, c, depth + 1)) != BS_OK)
            return r;
        if ((r = bsi_igm_spend(m, s, c)) != BS_OK)
            return r;
        for (size_t i = 0; i < m->slot[c].npieces && r == BS_OK; i++)
            if ((r = more_pieces(e)) == BS_OK && (r = bsi_curve_copy(&m->slot[c].pieces[i], &e->pieces[e->npieces])) == BS_OK)
                e->npieces++;
    }
    return r;
}

static bs_status build(igm *m, size_t s, int depth)
{
    igm_slot *e = &m->slot[s];
    iges_stream st;
    bs_status r = bsi_igm_open(m, s, &st);
    if (r != BS_OK)
        return r;
    if (e->type == 102)
        r = composite_102(m, s, &st, depth);
    else if ((r = more_pieces(e)) == BS_OK) {
        bsi_curve *c = &e->pieces[0];
        r = e->type == 100 ? arc_100(m, s, &st, c)
          : e->type == 104 ? conic_104(m, s, &st, c)
          : e->type == 110 ? line_110(m, &st, c) : bspline_126(m, s, &st, c);
        e->npieces = r == BS_OK;
    }
    if (r == BS_OK && e->type != 126)
        r = bsi_igm_rest(m, &st);
    double mat[12];
    if (r == BS_OK && (r = bsi_igm_matrix(m, s, mat)) == BS_OK)
        for (size_t k = 0; k < e->npieces; k++)
            bsi_igm_move(&e->pieces[k], mat);
    return bsi_igm_name(m, s, r);
}

bs_status bsi_igm_curve(igm *m, size_t s, int depth)
{
    igm_slot *e = &m->slot[s];
    if (e->type != 100 && e->type != 102 && e->type != 104 && e->type != 110 && e->type != 126) {
        (void)bsi_igm_fail(m, s, 1, "curve type not read");
        return BS_ERR_UNSUPPORTED;
    }
    if (e->state == IGM_DONE)
        return BS_OK;
    if (e->state == IGM_BUSY || depth > IGM_DEPTH)
        return bsi_igm_fail(m, s, 1, "curves nested deeper than %d or circular", IGM_DEPTH);
    e->state = IGM_BUSY;
    bs_status r = build(m, s, depth);
    if (r != BS_OK) {
        for (size_t k = 0; k < e->npieces; k++)
            bsi_curve_free(&e->pieces[k]);
        e->npieces = 0;
        return r;
    }
    e->state = IGM_DONE;
    return BS_OK;
}
