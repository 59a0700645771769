/* Reading the rational B-spline surfaces (entity 128) of an IGES file, with the transformations
 * (entity 124, each parsed once: iges_matrix.c) their directory entries point to, into Bezier
 * patches (docs/formats.md). */
#include "io/iges.h"

#include <bezsurf/bspline.h>

#include <stdlib.h>
#include <string.h>

#define CHAIN_MAX 16 /* longest chain of transformations followed */

/* Fail at field f (1..20) of the directory entry starting at D record de. */
static bs_status fail_de(const iges *g, size_t de, int f, const char *msg)
{
    size_t rec = g->first[IGES_D] + de + (size_t)(f - 1) / 10;
    (void)bsi_fail(g->err, rec + 1, (size_t)((f - 1) % 10) * 8 + 1, "%s", msg);
    return BS_ERR_PARSE;
}

/* The parameter data of the entity at D record de, its first field (the type) checked. */
static bs_status entity_stream(const iges *g, size_t de, long type, iges_stream *s)
{
    long t;
    bs_status st = bsi_iges_open(g, de, s);
    return st != BS_OK ? st : bsi_iges_int(g, s, "the entity type of the directory entry", type, type, &t);
}

/* Apply the chain of 124 matrices starting at the transformation pointer of entity de. */
static bs_status transform(iges *g, size_t de, double *ctrl, size_t n)
{
    long t;
    bs_status st = bsi_iges_de_field(g, de, 7, &t);
    for (int depth = 0; st == BS_OK && t != 0; depth++) {
        if (depth == CHAIN_MAX)
            return fail_de(g, de, 7, "chain of transformations longer than 16 or circular");
        if (t < 0 || t % 2 == 0 || (size_t)t > g->count[IGES_D])
            return fail_de(g, de, 7, "transformation pointer to no directory entry");
        long type;
        if ((st = bsi_iges_de_field(g, (size_t)t - 1, 1, &type)) != BS_OK)
            return st;
        if (type != 124)
            return fail_de(g, de, 7, "transformation pointer to an entity other than 124");
        de = (size_t)t - 1;
        const double *m;
        if ((st = bsi_iges_124(g, de, &m)) != BS_OK)
            return st;
        for (size_t i = 0; i < n; i++) {
            const double x[3] = {ctrl[3 * i], ctrl[3 * i + 1], ctrl[3 * i + 2]};
            for (size_t r = 0; r < 3; r++)
                ctrl[3 * i + r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
        }
        st = bsi_iges_de_field(g, de, 7, &t);
    }
    return st;
}

/* The next n reals of the entity into vals; knots (kind 1) must not decrease, weights (kind 2)
 * must be positive. */
static bs_status read_reals(const iges *g, iges_stream *s, bsi_growing *vals, size_t n, int kind, const char *what)
{
    iges_field f;
    for (size_t k = 0; k < n; k++) {
        bs_status st = bsi_grow(vals, sizeof(double), 1);
        if (st != BS_OK)
            return st;
        double *x = (double *)vals->data + vals->n;
        if ((st = bsi_iges_real(g, s, what, x, &f)) != BS_OK)
            return st;
        if (kind == 1 && k > 0 && x[0] < x[-1])
            return bsi_iges_fail_at(g, s, f.start, "knots must not decrease");
        if (kind == 2 && !(x[0] > 0.0))
            return bsi_iges_fail_at(g, s, f.start, "weights must be positive");
        vals->n++;
    }
    return BS_OK;
}

static bs_status read_128(iges *g, size_t de, bsi_growing *vals, bs_surface *out)
{
    iges_stream s;
    long form, v[9];
    bs_status st = bsi_iges_de_field(g, de, 15, &form);
    if (st != BS_OK)
        return st;
    if (form < 0 || form > 9)
        return fail_de(g, de, 15, "form number of entity 128 must be 0 to 9");
    if ((st = entity_stream(g, de, 128, &s)) != BS_OK)
        return st;
    size_t room = s.nrec * s.width; /* every field takes at least one character */
    static const char *const names[9] = {"K1", "K2", "the degree M1", "the degree M2", "PROP1 (closed in u)",
                                         "PROP2 (closed in v)", "PROP3 (polynomial)", "PROP4 (periodic in u)",
                                         "PROP5 (periodic in v)"};
    size_t at = s.pos;
    for (size_t k = 0; k < 9 && st == BS_OK; k++)
        st = bsi_iges_int(g, &s, names[k], k < 2 ? 1 : k < 4 ? 1 : 0,
                          k < 2 ? (long)(room < 99999999 ? room : 99999999) : k < 4 ? BS_MAX_DEGREE : 1, &v[k]);
    if (st != BS_OK)
        return st;
    size_t cu = (size_t)v[0] + 1, cv = (size_t)v[1] + 1, pu = (size_t)v[2], pv = (size_t)v[3];
    if (cu < pu + 1 || cv < pv + 1)
        return bsi_iges_fail_at(g, &s, at, "K1 and K2 must be at least the degrees M1 and M2");
    if (cv > room / cu)
        return bsi_iges_fail_at(g, &s, at, "more control points than the parameter data can hold");
    size_t n = cu * cv, nku = cu + pu + 1, nkv = cv + pv + 1;
    vals->n = 0;
    size_t knots_at = s.pos; /* just after the delimiter before the first knot */
    if ((st = read_reals(g, &s, vals, nku, 1, "a knot of u")) != BS_OK ||
        (st = read_reals(g, &s, vals, nkv, 1, "a knot of v")) != BS_OK ||
        (st = read_reals(g, &s, vals, n, 2, "a weight")) != BS_OK ||
        (st = read_reals(g, &s, vals, 3 * n, 0, "a control point coordinate")) != BS_OK)
        return st;
    size_t range_at = s.pos;
    if ((st = read_reals(g, &s, vals, 4, 0, "the parameter range")) != BS_OK || (st = bsi_iges_rest(g, &s)) != BS_OK)
        return st;
    const double *val = vals->data, *w = val + nku + nkv, *pts = w + n, *range = pts + 3 * n;
    double *ctrl = malloc(4 * n * sizeof(double));
    if (ctrl == NULL)
        return BS_ERR_NO_MEMORY;
    double *wt = ctrl + 3 * n;
    int rational = 0;
    for (size_t i = 0; i < cu; i++) /* the file lists the net with u varying fastest */
        for (size_t j = 0; j < cv; j++) {
            memcpy(ctrl + 3 * (i * cv + j), pts + 3 * (j * cu + i), 3 * sizeof(double));
            wt[i * cv + j] = w[j * cu + i];
            rational |= w[j * cu + i] != w[0];
        }
    st = transform(g, de, ctrl, n);
    bs_bspline b = {pu, pv, cu, cv, 3, val, val + nku, ctrl, rational ? wt : NULL};
    size_t nu, nv;
    if (st == BS_OK && bs_bspline_span_count(&b, &nu, &nv) != BS_OK)
        st = BS_ERR_DOMAIN; /* knots repeated too often or an empty domain, before the range */
    double dom[4] = {val[pu], val[cu], val[nku + pv], val[nku + cv]}, cut[4];
    for (size_t d = 0; d < 2; d++) { /* the range within the knots' domain */
        cut[2 * d] = range[2 * d] > dom[2 * d] ? range[2 * d] : dom[2 * d];
        cut[2 * d + 1] = range[2 * d + 1] < dom[2 * d + 1] ? range[2 * d + 1] : dom[2 * d + 1];
        if (st == BS_OK && !(cut[2 * d + 1] > cut[2 * d]))
            st = bsi_iges_fail_at(g, &s, range_at, "parameter range empty or outside the knots' domain");
    }
    if (st == BS_OK && !bsi_spend_span_points(&g->points, g->len, nu, nv, pu, pv)) {
        free(ctrl);
        (void)fail_de(g, de, 1, BSI_READ_POINTS_SAY);
        return BS_ERR_SIZE;
    }
    if (st == BS_OK)
        st = bsi_add_bspline_range(out, &b, cut);
    free(ctrl);
    if (st == BS_ERR_DOMAIN)
        return bsi_iges_fail_at(g, &s, knots_at, "knots repeated over degree + 1 times, an empty domain or knots spanning over DBL_MAX");
    if (st == BS_ERR_NONFINITE)
        return fail_de(g, de, 7, "a control point (transformed, times its weight) is not finite");
    if (st == BS_ERR_SIZE)
        return fail_de(g, de, 1, "more patches than a surface can hold");
    return st;
}

/* A file without a 128: what it holds instead, and the reader of models for trimmed ones. */
static bs_status no_bspline(const iges *g)
{
    size_t n = g->count[IGES_D] / 2, trimmed = 0, brep = 0;
    for (size_t de = 0; de < g->count[IGES_D]; de += 2) {
        long type;
        if (bsi_iges_de_field(g, de, 1, &type) != BS_OK)
            return BS_ERR_PARSE;
        trimmed += type == 144 || type == 143;
        brep += type == 186;
    }
    size_t line = g->first[IGES_D] + 1;
    if (trimmed > 0 || brep > 0)
        return bsi_fail(g->err, line, 1, "no 128 surface: the file holds %zu %s; read it with bs_model_read_iges",
                        trimmed ? trimmed : brep, trimmed ? "trimmed surfaces (144)" : "B-reps (186)");
    return bsi_fail(g->err, line, 1, "no untrimmed B-spline surface (128) among the %zu entities", n);
}

bs_status bs_surface_read_iges(const char *text, size_t len, bs_parse_error *err, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    iges g;
    memset(&g, 0, sizeof g);
    g.text = text;
    g.len = len;
    g.err = err;
    g.pdelim = ',';
    g.rdelim = ';';
    bs_surface *s = NULL;
    bsi_growing vals = {NULL, 0, 0};
    bs_status st = bsi_iges_records(&g);
    if (st == BS_OK)
        st = bsi_iges_global(&g);
    if (st == BS_OK)
        st = bs_surface_create(&s);
    for (size_t de = 0; st == BS_OK && de < g.count[IGES_D]; de += 2) {
        long type;
        st = bsi_iges_de_field(&g, de, 1, &type);
        if (st == BS_OK && type == 128)
            st = read_128(&g, de, &vals, s);
    }
    if (st == BS_OK && bs_surface_count(s) == 0)
        st = no_bspline(&g);
    free(vals.data);
    bsi_iges_free(&g);
    if (st != BS_OK) {
        bs_surface_destroy(s);
        return st;
    }
    *out = s;
    return BS_OK;
}

bs_status bs_surface_read_iges_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    return bsi_read_surface_file(path, err, out, bs_surface_read_iges);
}
