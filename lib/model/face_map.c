/*
 * Native face parameters -> (patch, s, t) in closed form, and what is evaluated through that map:
 * bs_model_face_to_patch, bs_model_face_eval (outward normals) and bs_model_classify.
 */
#include "model/internal.h"

#include <math.h>
#include <string.h>

double bsi_wrap(double u, double lo, double period)
{
    if (!(period > 0.0) || !isfinite(u))
        return u;
    double k = floor((u - lo) / period);
    double w = u - k * period;
    return w < lo ? lo : w;
}

/* x brought into [lo, hi] by whole periods when it lies outside and a shift lands inside; a
 * parameter outside by a rounding (1e-9 of the box's width: trim ends computed by the file's
 * writer) is taken at the box's side. */
static double into_box(double x, double lo, double hi, double period)
{
    if ((x >= lo && x <= hi) || !isfinite(x))
        return x;
    if (period > 0.0) {
        double k = round((0.5 * (lo + hi) - x) / period);
        double shifted = x + k * period;
        if (shifted >= lo && shifted <= hi)
            return shifted;
    }
    double slack = 1e-9 * (hi - lo);
    return x < lo && x >= lo - slack ? lo : x > hi && x <= hi + slack ? hi : x;
}

/* x taken at the axis's end when it is outside by a rounding (the face's box comes from its
 * trims, and a sweep's patches stop at its curve's range). */
static double onto_axis(const bsi_axis *a, double x)
{
    if (a->n == 0)
        return x;
    double lo = a->breaks[0], hi = a->breaks[a->n], slack = 1e-9 * (hi - lo);
    return x < lo && x >= lo - slack ? lo : x > hi && x <= hi + slack ? hi : x;
}

int bsi_face_locate(const bs_model *m, size_t f, double u, double v, uint32_t *patch, double *st)
{
    const bsi_face *face = &m->faces[f];
    u = into_box(u, face->box[0], face->box[1], face->period[0]);
    v = into_box(v, face->box[2], face->box[3], face->period[1]);
    if (face->swap) {
        double t = u;
        u = v;
        v = t;
    }
    size_t i, j;
    double s, t;
    if (!bsi_axis_locate(&face->au, onto_axis(&face->au, u), &i, &s) ||
        !bsi_axis_locate(&face->av, onto_axis(&face->av, v), &j, &t))
        return 0;
    *patch = (uint32_t)(face->first_patch + i * face->av.n + j);
    st[0] = s;
    st[1] = t;
    return 1;
}

int bsi_face_point(const bs_model *m, size_t f, double u, double v, double *p)
{
    uint32_t patch;
    double st[2];
    if (!bsi_face_locate(m, f, u, v, &patch, st))
        return 0;
    bsi_eval_point(bs_surface_get(m->surface, patch), st[0], st[1], p); /* bs_patch_eval's bits */
    return 1;
}

int bsi_face_partials_cell(const bs_model *m, size_t f, double u, double v, double *p, double *pu,
                           double *pv, double *cell)
{
    const bsi_face *face = &m->faces[f];
    u = into_box(u, face->box[0], face->box[1], face->period[0]);
    v = into_box(v, face->box[2], face->box[3], face->period[1]);
    double cu = onto_axis(&face->au, face->swap ? v : u), cv = onto_axis(&face->av, face->swap ? u : v);
    size_t i, j;
    double s, t;
    if (!bsi_axis_locate(&face->au, cu, &i, &s) || !bsi_axis_locate(&face->av, cv, &j, &t))
        return 0;
    double ds = bsi_axis_rate(&face->au, i, cu), dt = bsi_axis_rate(&face->av, j, cv);
    const bs_patch *patch = bs_surface_get(m->surface, face->first_patch + i * face->av.n + j);
    /* one point: the derivative table directly (no block evaluator set up for it) */
    double scratch[5 * (BS_MAX_DEGREE + 1) + 4 * (BS_MAX_DIM + 1)], tab[4 * BS_MAX_DIM];
    bsi_deriv_table(patch, s, t, 1, 1, scratch, tab);
    for (int c = 0; c < 3; c++) {
        double along_cu = tab[6 + c] * ds, along_cv = tab[3 + c] * dt; /* S_s, S_t */
        p[c] = tab[c];
        pu[c] = face->swap ? along_cv : along_cu;
        pv[c] = face->swap ? along_cu : along_cv;
    }
    if (cell != NULL) { /* the patch's native ranges, in the frame of the wrapped (u, v) */
        double a0 = face->au.breaks[i], a1 = face->au.breaks[i + 1];
        double b0 = face->av.breaks[j], b1 = face->av.breaks[j + 1];
        cell[0] = face->swap ? b0 : a0, cell[1] = face->swap ? b1 : a1;
        cell[2] = face->swap ? a0 : b0, cell[3] = face->swap ? a1 : b1;
        cell[4] = u, cell[5] = v;
    }
    return 1;
}

int bsi_face_partials(const bs_model *m, size_t f, double u, double v, double *p, double *pu,
                      double *pv)
{
    return bsi_face_partials_cell(m, f, u, v, p, pu, pv, NULL);
}

/* The argument rules shared by the entry points; on success every face id is valid. */
static bs_status check_args(const bs_model *m, size_t n, const uint32_t *faces, const bs_cview *u,
                            const bs_cview *v, const bs_view *a, size_t ka, const bs_view *b, size_t kb)
{
    if (n == 0)
        return m == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    if (m == NULL || faces == NULL || u == NULL || v == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st;
    if ((st = bsi_check_cview(u, n)) != BS_OK || (st = bsi_check_cview(v, n)) != BS_OK)
        return st;
    if ((a && (st = bsi_check_views(a, ka, n)) != BS_OK) || (b && (st = bsi_check_views(b, kb, n)) != BS_OK))
        return st;
    for (size_t k = 0; k < n; k++)
        if (faces[k] >= m->nface)
            return BS_ERR_INVALID_ARG;
    return BS_OK;
}

bs_status bs_model_face_to_patch(const bs_model *m, size_t n, const uint32_t *faces,
                                 const bs_cview *u, const bs_cview *v, uint32_t *patch,
                                 const bs_view *st)
{
    bs_status status = check_args(m, n, faces, u, v, st, 2, NULL, 0);
    if (status != BS_OK)
        return status;
    for (size_t k = 0; k < n; k++) {
        uint32_t id = UINT32_MAX;
        double local[2] = {NAN, NAN};
        if (!bsi_face_locate(m, faces[k], bsi_cget(u, k), bsi_cget(v, k), &id, local)) {
            id = UINT32_MAX;
            local[0] = local[1] = NAN;
        }
        if (patch != NULL)
            patch[k] = id;
        if (st != NULL) {
            *bsi_at(&st[0], k) = local[0];
            *bsi_at(&st[1], k) = local[1];
        }
    }
    return BS_OK;
}

bs_status bs_model_face_eval(const bs_model *m, size_t n, const uint32_t *faces, const bs_cview *u,
                             const bs_cview *v, const bs_view *pos, const bs_view *nrm,
                             unsigned char *kind)
{
    bs_status status = check_args(m, n, faces, u, v, pos, 3, nrm, 3);
    if (status != BS_OK)
        return status;
    for (size_t k = 0; k < n; k++) {
        uint32_t id;
        double st[2], p[3] = {NAN, NAN, NAN}, q[3] = {NAN, NAN, NAN};
        unsigned char nk = BS_NORMAL_UNDEFINED;
        if (bsi_face_locate(m, faces[k], bsi_cget(u, k), bsi_cget(v, k), &id, st)) {
            bs_cview cu = {&st[0], 1, 0}, cv = {&st[1], 1, 0};
            bs_view pv[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
            bs_view nv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
            (void)bs_patch_eval_normal(bs_surface_get(m->surface, id), 1, &cu, &cv, pv, nv, &nk);
            if (m->faces[faces[k]].reversed != m->faces[faces[k]].swap)
                for (int c = 0; c < 3; c++)
                    q[c] = -q[c];
        }
        for (int c = 0; c < 3; c++) {
            if (pos != NULL)
                *bsi_at(&pos[c], k) = p[c];
            if (nrm != NULL)
                *bsi_at(&nrm[c], k) = q[c] == 0.0 ? 0.0 : q[c];
        }
        if (kind != NULL)
            kind[k] = nk;
    }
    return BS_OK;
}

bs_status bs_model_classify(const bs_model *m, size_t n, const uint32_t *faces, const bs_cview *u,
                            const bs_cview *v, double tol, unsigned char *where)
{
    bs_status status = check_args(m, n, faces, u, v, NULL, 0, NULL, 0);
    if (status != BS_OK)
        return status;
    if (n > 0 && where == NULL)
        return BS_ERR_INVALID_ARG;
    if (!(isfinite(tol) && tol >= 0.0))
        return BS_ERR_DOMAIN;
    for (size_t k = 0; k < n; k++) {
        double uk = bsi_cget(u, k), vk = bsi_cget(v, k);
        where[k] = (unsigned char)(isnan(uk) || isnan(vk) ? BS_TRIM_OUTSIDE
                                                          : bsi_face_classify(m, faces[k], uk, vk, tol));
    }
    return BS_OK;
}

/* The face holding patch p: faces' patches are appended in face order, so a binary search over
 * their first patches finds it. */
size_t bsi_face_of_patch(const bs_model *m, uint32_t p)
{
    size_t lo = 0, hi = m->nface;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (m->faces[mid].first_patch <= p)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

size_t bsi_patch_native(const bs_model *m, uint32_t p, double s, double t, double native[2])
{
    size_t f = bsi_face_of_patch(m, p);
    const bsi_face *fc = &m->faces[f];
    size_t local = p - fc->first_patch;
    double cu = bsi_axis_native(&fc->au, local / fc->av.n, s);
    double cv = bsi_axis_native(&fc->av, local % fc->av.n, t);
    native[0] = fc->swap ? cv : cu;
    native[1] = fc->swap ? cu : cv;
    return f;
}

bs_status bs_model_patch_to_face(const bs_model *m, size_t n, const uint32_t *patch,
                                 const bs_cview *s, const bs_cview *t, uint32_t *face,
                                 const bs_view *uv)
{
    if (n == 0)
        return m == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    if (m == NULL || patch == NULL || s == NULL || t == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status status;
    if ((status = bsi_check_cview(s, n)) != BS_OK || (status = bsi_check_cview(t, n)) != BS_OK ||
        (uv && (status = bsi_check_views(uv, 2, n)) != BS_OK))
        return status;
    size_t npatch = bs_surface_count(m->surface);
    for (size_t k = 0; k < n; k++)
        if (patch[k] >= npatch)
            return BS_ERR_INVALID_ARG;
    for (size_t k = 0; k < n; k++) {
        double sk = bsi_cget(s, k), tk = bsi_cget(t, k), native[2] = {NAN, NAN};
        uint32_t id = UINT32_MAX;
        if (sk >= 0.0 && sk <= 1.0 && tk >= 0.0 && tk <= 1.0)
            id = (uint32_t)bsi_patch_native(m, patch[k], sk, tk, native);
        if (face != NULL)
            face[k] = id;
        if (uv != NULL) {
            *bsi_at(&uv[0], k) = native[0];
            *bsi_at(&uv[1], k) = native[1];
        }
    }
    return BS_OK;
}
