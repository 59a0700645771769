/* The IGES 128 B-spline surface of a model face: knots, weights and the net (listed with u varying
 * fastest) into the surface's own arrays, its parameter range cut to the knots' domain. */
#include "io/iges_model.h"

#include <stdlib.h>
#include <string.h>

/* The next n reals appended to m->vals (grown as read). */
static bs_status reals(igm *m, iges_stream *st, size_t n, const char *what)
{
    iges_field f;
    bs_status r = BS_OK;
    for (size_t k = 0; k < n && r == BS_OK; k++)
        if ((r = bsi_grow(&m->vals, sizeof(double), 1)) == BS_OK)
            r = bsi_iges_real(&m->g, st, what, (double *)m->vals.data + m->vals.n++, &f);
    return r;
}

static int knots_ok(const double *k, size_t n)
{
    for (size_t i = 1; i < n; i++)
        if (k[i] < k[i - 1])
            return 0;
    return 1;
}

bs_status bsi_igm_bspline_128(igm *m, size_t s, iges_stream *st, igm_surface *sf)
{
    long v[9];
    size_t room = st->nrec * st->width, at = st->pos;
    static const char *const names[9] = {"K1", "K2", "the degree M1", "the degree M2", "PROP1", "PROP2",
                                         "PROP3", "PROP4", "PROP5"};
    bs_status r = BS_OK;
    for (size_t k = 0; k < 9 && r == BS_OK; k++)
        r = bsi_iges_int(&m->g, st, names[k], k < 4 ? 1 : 0,
                         k < 2 ? (long)(room < 99999999 ? room : 99999999) : k < 4 ? BS_MAX_DEGREE : 1, &v[k]);
    if (r != BS_OK)
        return r;
    size_t cu = (size_t)v[0] + 1, cv = (size_t)v[1] + 1, pu = (size_t)v[2], pv = (size_t)v[3];
    if (cu < pu + 1 || cv < pv + 1)
        return bsi_iges_fail_at(&m->g, st, at, "K1 and K2 must be at least the degrees M1 and M2");
    if (cv > room / cu || cu * cv > room / 4)
        return bsi_iges_fail_at(&m->g, st, at, "more control points than the parameter data can hold");
    size_t n = cu * cv, nku = cu + pu + 1, nkv = cv + pv + 1;
    m->vals.n = 0;
    if ((r = reals(m, st, nku + nkv, "a knot")) != BS_OK || (r = reals(m, st, n, "a weight")) != BS_OK ||
        (r = reals(m, st, 3 * n, "a control point coordinate")) != BS_OK ||
        (r = reals(m, st, 4, "the parameter range")) != BS_OK || (r = bsi_igm_rest(m, st)) != BS_OK)
        return r;
    const double *val = m->vals.data, *w = val + nku + nkv, *pts = w + n, *range = pts + 3 * n;
    if (!knots_ok(val, nku) || !knots_ok(val + nku, nkv))
        return bsi_igm_fail(m, s, 1, "knots must not decrease");
    sf->data = malloc((nku + nkv + 4 * n) * sizeof(double));
    if (sf->data == NULL)
        return BS_ERR_NO_MEMORY;
    memcpy(sf->data, val, (nku + nkv) * sizeof(double));
    double *ctrl = sf->data + nku + nkv, *wt = ctrl + 3 * n;
    int rational = 0;
    for (size_t i = 0; i < cu; i++)
        for (size_t j = 0; j < cv; j++) {
            memcpy(ctrl + 3 * (i * cv + j), pts + 3 * (j * cu + i), 3 * sizeof(double));
            wt[i * cv + j] = w[j * cu + i];
            if (!(wt[i * cv + j] > 0.0))
                return bsi_igm_fail(m, s, 1, "weights must be positive");
            rational |= w[j * cu + i] != w[0];
        }
    bs_bspline b = {pu, pv, cu, cv, 3, sf->data, sf->data + nku, ctrl, rational ? wt : NULL};
    sf->b = b;
    /* its Bezier spans counted before any face converts them (each surface is parsed once) */
    size_t nu = 0, nv = 0;
    /* bad knots are refused where faces convert */
    if (bs_bspline_span_count(&b, &nu, &nv) == BS_OK &&
        !bsi_spend_span_points(&m->g.points, m->g.len, nu, nv, pu, pv)) {
        (void)bsi_igm_fail(m, s, 1, BSI_READ_POINTS_SAY);
        return BS_ERR_SIZE;
    }
    double dom[4] = {val[pu], val[cu], val[nku + pv], val[nku + cv]};
    for (size_t d = 0; d < 2; d++) {
        sf->box[2 * d] = range[2 * d] > dom[2 * d] ? range[2 * d] : dom[2 * d];
        sf->box[2 * d + 1] = range[2 * d + 1] < dom[2 * d + 1] ? range[2 * d + 1] : dom[2 * d + 1];
        if (!(sf->box[2 * d + 1] > sf->box[2 * d]))
            return bsi_igm_fail(m, s, 1, "parameter range empty or outside the knots' domain");
    }
    sf->def.kind = BS_FACE_BSPLINE;
    sf->has_box = sf->param = 1;
    return BS_OK;
}
