/*
 * One direction of a face or a curve: native parameter <-> (piece, local s), linear pieces or
 * quadratic rational arcs (the tangent-half-angle map derived in lib/model/internal.h).
 */
#include "model/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* tan(a / 2) of piece k of an ANGULAR axis, a its half angle: kept, or computed alike. */
static double quarter_tan(const bsi_axis *a, size_t k)
{
    if (a->quarter != NULL)
        return a->quarter[k];
    double half = 0.5 * a->radians * (a->breaks[k + 1] - a->breaks[k]);
    return tan(0.5 * half);
}

/* The tangents of an ANGULAR axis computed from its breaks into the room after them. */
static void keep_quarters(bsi_axis *a)
{
    double *kept = a->breaks + a->n + 1;
    a->quarter = NULL; /* quarter_tan computes them from the breaks as they are now */
    for (size_t k = 0; k < a->n; k++)
        kept[k] = quarter_tan(a, k);
    a->quarter = kept;
}

int bsi_axis_locate(const bsi_axis *a, double x, size_t *piece, double *s)
{
    if (a->n == 0 || !(x >= a->breaks[0] && x <= a->breaks[a->n]))
        return 0;
    /* the last break at or below x: binary search, the end of the range on the last piece */
    size_t lo = 0, hi = a->n;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (a->breaks[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    double b0 = a->breaks[lo], b1 = a->breaks[lo + 1];
    double local;
    if (a->kind == BSI_AXIS_ANGULAR) {
        double half = 0.5 * a->radians * (b1 - b0), phi = a->radians * (x - b0);
        local = 0.5 * (1.0 + tan(0.5 * (phi - half)) / quarter_tan(a, lo));
    } else {
        local = (x - b0) / (b1 - b0);
    }
    /* rounding must not leave the piece */
    *s = local < 0.0 ? 0.0 : local > 1.0 ? 1.0 : local;
    *piece = lo;
    return 1;
}

double bsi_axis_native(const bsi_axis *a, size_t k, double s)
{
    double b0 = a->breaks[k], b1 = a->breaks[k + 1];
    if (s <= 0.0)
        return b0;
    if (s >= 1.0)
        return b1;
    if (a->kind == BSI_AXIS_ANGULAR) {
        double half = 0.5 * a->radians * (b1 - b0);
        double phi = half + 2.0 * atan((2.0 * s - 1.0) * quarter_tan(a, k));
        return b0 + phi / a->radians;
    }
    return b0 + s * (b1 - b0);
}

double bsi_axis_rate(const bsi_axis *a, size_t k, double x)
{
    double b0 = a->breaks[k], b1 = a->breaks[k + 1];
    if (a->kind != BSI_AXIS_ANGULAR)
        return 1.0 / (b1 - b0);
    double half = 0.5 * a->radians * (b1 - b0), phi = a->radians * (x - b0);
    double c = cos(0.5 * (phi - half));
    return a->radians / (4.0 * quarter_tan(a, k) * c * c);
}

bs_status bsi_axis_make(int kind, double radians, double x0, double x1, const double *inner,
                        size_t ninner, bsi_axis *a)
{
    memset(a, 0, sizeof *a);
    if (!(isfinite(x0) && isfinite(x1) && x0 < x1))
        return BS_ERR_DOMAIN;
    size_t n = 1;
    if (kind == BSI_AXIS_ANGULAR) {
        if (!(isfinite(radians) && radians > 0.0))
            return BS_ERR_DOMAIN;
        double turns = radians * (x1 - x0) / BSI_QUARTER_TURN;
        if (!(turns < 1e6))
            return BS_ERR_DOMAIN;
        /* a piece of exactly a quarter turn is fine; rounding of the ratio must not add one */
        n = (size_t)ceil(turns * (1.0 - 1e-12));
        if (n == 0)
            n = 1;
    } else {
        for (size_t i = 0; i < ninner; i++)
            n += inner[i] > x0 && inner[i] < x1 && (i == 0 || inner[i] > inner[i - 1]);
    }
    a->breaks = malloc((kind == BSI_AXIS_ANGULAR ? 2 * n + 1 : n + 1) * sizeof *a->breaks);
    if (a->breaks == NULL)
        return BS_ERR_NO_MEMORY;
    a->kind = kind;
    a->radians = kind == BSI_AXIS_ANGULAR ? radians : 1.0;
    a->n = n;
    a->breaks[0] = x0;
    if (kind == BSI_AXIS_ANGULAR) {
        for (size_t k = 1; k < n; k++)
            a->breaks[k] = x0 + (x1 - x0) * (double)k / (double)n;
    } else {
        size_t k = 1;
        for (size_t i = 0; i < ninner; i++)
            if (inner[i] > x0 && inner[i] < x1 && (i == 0 || inner[i] > inner[i - 1]))
                a->breaks[k++] = inner[i];
    }
    a->breaks[n] = x1;
    if (kind == BSI_AXIS_ANGULAR)
        keep_quarters(a);
    return BS_OK;
}

void bsi_axis_refresh(bsi_axis *a)
{
    if (a->quarter != NULL)
        keep_quarters(a);
}

bs_status bsi_axis_copy(const bsi_axis *src, bsi_axis *dst)
{
    *dst = *src;
    dst->breaks = dst->quarter = NULL;
    if (src->n == 0)
        return BS_OK;
    size_t count = src->n + 1 + (src->quarter != NULL ? src->n : 0);
    dst->breaks = malloc(count * sizeof *dst->breaks);
    if (dst->breaks == NULL) {
        dst->n = 0;
        return BS_ERR_NO_MEMORY;
    }
    memcpy(dst->breaks, src->breaks, (src->n + 1) * sizeof *dst->breaks);
    if (src->quarter != NULL) {
        memcpy(dst->breaks + src->n + 1, src->quarter, src->n * sizeof *dst->breaks);
        dst->quarter = dst->breaks + src->n + 1;
    }
    return BS_OK;
}

void bsi_axis_free(bsi_axis *a)
{
    free(a->breaks);
    a->breaks = a->quarter = NULL;
    a->n = 0;
}
