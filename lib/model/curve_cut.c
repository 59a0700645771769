/*
 * A curve restricted to a sub-range of its native parameter, still exact and still on its own
 * map: linear segments are cut by de Casteljau; a cut quadratic arc of an angular axis is put
 * back into the standard form of weights (1, w, 1) (the Moebius reparametrisation that keeps its
 * control points), where w is the cosine of its half-angle again, so that the tangent-half-angle
 * map of the shorter piece holds.
 */
#include "model/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The classic split of a homogeneous Bezier segment at s: left into lo, right into hi. */
static void split_at(const double *h, size_t n, size_t k, double s, double *lo, double *hi)
{
    double tri[(BS_MAX_DEGREE + 1) * 4];
    memcpy(tri, h, (n + 1) * k * sizeof *tri);
    for (size_t c = 0; c < k; c++) {
        lo[c] = tri[c];
        hi[n * k + c] = tri[n * k + c];
    }
    for (size_t r = 1; r <= n; r++) {
        for (size_t i = 0; i + r <= n; i++)
            for (size_t c = 0; c < k; c++)
                tri[i * k + c] = (1.0 - s) * tri[i * k + c] + s * tri[(i + 1) * k + c];
        for (size_t c = 0; c < k; c++) {
            lo[r * k + c] = tri[c];
            hi[(n - r) * k + c] = tri[(n - r) * k + c];
        }
    }
}

bs_status bsi_curve_cut(const bsi_curve *src, double t0, double t1, bsi_curve *out)
{
    memset(out, 0, sizeof *out);
    const bsi_axis *a = &src->axis;
    if (a->n == 0 || !(t0 < t1) || t0 < a->breaks[0] || t1 > a->breaks[a->n])
        return BS_ERR_DOMAIN;
    size_t k0, k1;
    double s0, s1;
    (void)bsi_axis_locate(a, t0, &k0, &s0);
    (void)bsi_axis_locate(a, t1, &k1, &s1);
    if (k1 > k0 && s1 == 0.0) { /* t1 on a break: the piece before ends there */
        k1--;
        s1 = 1.0;
    }
    size_t n = k1 - k0 + 1, k = src->dim + 1, np = src->degree + 1;
    out->axis = *a;
    out->axis.n = n;
    out->axis.quarter = NULL; /* computed when asked: the breaks are new */
    out->axis.breaks = malloc((n + 1) * sizeof *out->axis.breaks);
    out->hom = malloc(n * np * k * sizeof *out->hom);
    if (out->axis.breaks == NULL || out->hom == NULL) {
        free(out->axis.breaks);
        free(out->hom);
        memset(out, 0, sizeof *out);
        return BS_ERR_NO_MEMORY;
    }
    out->dim = src->dim;
    out->degree = src->degree;
    for (size_t i = 0; i <= n; i++)
        out->axis.breaks[i] = i == 0 ? t0 : i == n ? t1 : a->breaks[k0 + i];
    for (size_t i = 0; i < n; i++) {
        const double *seg = src->hom + (k0 + i) * np * k;
        double *dst = out->hom + i * np * k;
        double lo = i == 0 ? s0 : 0.0, hi = i == n - 1 ? s1 : 1.0;
        double left[(BS_MAX_DEGREE + 1) * 4], right[(BS_MAX_DEGREE + 1) * 4];
        memcpy(dst, seg, np * k * sizeof *dst);
        if (hi < 1.0) {
            split_at(dst, src->degree, k, hi, left, right);
            memcpy(dst, left, np * k * sizeof *dst);
            lo = lo / hi;
        }
        if (lo > 0.0) {
            split_at(dst, src->degree, k, lo, left, right);
            memcpy(dst, right, np * k * sizeof *dst);
        }
        if (a->kind == BSI_AXIS_ANGULAR && src->degree == 2) {
            /* back to weights (1, w1 / sqrt(w0 w2), 1): point j scaled by f^j / w0 */
            double w0 = dst[src->dim], w2 = dst[2 * k + src->dim], f = sqrt(w0 / w2);
            for (size_t j = 0; j < 3; j++) {
                double scale = (j == 0 ? 1.0 : j == 1 ? f : f * f) / w0;
                for (size_t c = 0; c < k; c++)
                    dst[j * k + c] *= scale;
            }
        }
    }
    return BS_OK;
}
