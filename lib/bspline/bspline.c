/*
 * B-spline and NURBS surfaces to Bezier patches (bezsurf/bspline.h). The net is taken to
 * homogeneous coordinates (w P, w), each u-span's Bezier rows are found for every column of the
 * net, then each v-span's points from those rows; the patches are made first and appended all at
 * once, so a failure leaves the surface as it was.
 */
#include "bspline/internal.h"

#include <math.h>
#include <stdlib.h>

/* The rules of bezsurf/bspline.h up to the knots (what the knot-only functions check). */
static bs_status check_knots(const bs_bspline *b, bsi_knots *ku, bsi_knots *kv)
{
    if (b->knots_u == NULL || b->knots_v == NULL)
        return BS_ERR_INVALID_ARG;
    if (b->deg_u == 0 || b->deg_u > BS_MAX_DEGREE || b->deg_v == 0 || b->deg_v > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (b->count_u < b->deg_u + 1 || b->count_v < b->deg_v + 1)
        return BS_ERR_SIZE;
    bs_status st = bsi_knots_check(b->deg_u, b->count_u, b->knots_u, ku);
    if (st == BS_OK)
        st = bsi_knots_check(b->deg_v, b->count_v, b->knots_v, kv);
    return st;
}

/* Every rule of bezsurf/bspline.h, in its order. */
static bs_status check_all(const bs_bspline *b, bsi_knots *ku, bsi_knots *kv)
{
    if (b->knots_u == NULL || b->knots_v == NULL || b->ctrl == NULL)
        return BS_ERR_INVALID_ARG;
    if (b->deg_u == 0 || b->deg_u > BS_MAX_DEGREE || b->deg_v == 0 || b->deg_v > BS_MAX_DEGREE)
        return BS_ERR_DEGREE;
    if (b->dim == 0 || b->dim > BS_MAX_DIM)
        return BS_ERR_DIMENSION;
    if (b->count_u < b->deg_u + 1 || b->count_v < b->deg_v + 1 ||
        b->count_u > SIZE_MAX / sizeof(double) / b->count_v / (b->dim + 1))
        return BS_ERR_SIZE;
    bs_status st = check_knots(b, ku, kv);
    if (st != BS_OK)
        return st;
    size_t n = b->count_u * b->count_v;
    for (size_t k = 0; k < n; k++) {
        double w = b->weights ? b->weights[k] : 1.0;
        if (!(w > 0.0) || !isfinite(w))
            return BS_ERR_NONFINITE;
        for (size_t c = 0; c < b->dim; c++)
            if (!isfinite(b->ctrl[k * b->dim + c]) || !isfinite(w * b->ctrl[k * b->dim + c]))
                return BS_ERR_NONFINITE;
    }
    return BS_OK;
}

bs_status bs_bspline_span_count(const bs_bspline *b, size_t *spans_u, size_t *spans_v)
{
    if (b == NULL || spans_u == NULL || spans_v == NULL)
        return BS_ERR_INVALID_ARG;
    bsi_knots ku, kv;
    bs_status st = check_knots(b, &ku, &kv);
    if (st != BS_OK)
        return st;
    *spans_u = ku.nspan;
    *spans_v = kv.nspan;
    return BS_OK;
}

/* Span number of x along one direction (half-open spans, the last one closed) and the knot
 * index of its start; -1 when x is NaN or outside the domain. */
static int locate_1d(const bsi_knots *k, double x, size_t *span, size_t *first)
{
    const double *t = k->t;
    if (!(x >= t[k->deg] && x <= t[k->count]))
        return -1;
    size_t a = 0, last = 0;
    for (size_t i = k->deg; i < k->count; i++) {
        if (!(t[i] < t[i + 1]))
            continue;
        last = i;
        if (x < t[i + 1]) {
            *span = a;
            *first = i;
            return 0;
        }
        a++;
    }
    *span = a - 1; /* x is the domain's end: the last span */
    *first = last;
    return 0;
}

bs_status bs_bspline_locate(const bs_bspline *b, double u, double v, size_t *index, double *local_u,
                            double *local_v)
{
    if (b == NULL || index == NULL)
        return BS_ERR_INVALID_ARG;
    bsi_knots ku, kv;
    bs_status st = check_knots(b, &ku, &kv);
    if (st != BS_OK)
        return st;
    size_t a, bv, iu, iv;
    if (locate_1d(&ku, u, &a, &iu) != 0 || locate_1d(&kv, v, &bv, &iv) != 0)
        return BS_ERR_DOMAIN;
    *index = a * kv.nspan + bv;
    if (local_u != NULL)
        *local_u = (u - ku.t[iu]) / (ku.t[iu + 1] - ku.t[iu]);
    if (local_v != NULL)
        *local_v = (v - kv.t[iv]) / (kv.t[iv + 1] - kv.t[iv]);
    return BS_OK;
}

/* The homogeneous net: ncoord doubles per control point, w P then w for a NURBS. */
static double *homogeneous_net(const bs_bspline *b, size_t ncoord)
{
    size_t n = b->count_u * b->count_v;
    double *h = malloc(n * ncoord * sizeof(double));
    if (h == NULL)
        return NULL;
    for (size_t k = 0; k < n; k++) {
        double w = b->weights ? b->weights[k] : 1.0;
        for (size_t c = 0; c < b->dim; c++)
            h[k * ncoord + c] = b->weights ? w * b->ctrl[k * b->dim + c] : b->ctrl[k * b->dim + c];
        if (b->weights)
            h[k * ncoord + b->dim] = w;
    }
    return h;
}

/* The patch of u-span starting at knot iu and v-span starting at iv. rows holds the u-span's
 * Bezier rows: (deg_u + 1) x count_v points of ncoord coordinates. */
static bs_status span_patch(const bs_bspline *b, const double *rows, size_t ncoord, size_t iv,
                            double *net, double *ctrl, double *weights, bs_patch **out)
{
    size_t pu = b->deg_u, pv = b->deg_v, dim = b->dim;
    for (size_t k = 0; k <= pu; k++)
        bsi_span_bezier(b->knots_v, pv, iv, rows + k * b->count_v * ncoord, ncoord, ncoord,
                        net + k * (pv + 1) * ncoord, ncoord);
    for (size_t k = 0; k < (pu + 1) * (pv + 1); k++) {
        const double *h = net + k * ncoord;
        for (size_t c = 0; c < dim; c++)
            ctrl[k * dim + c] = b->weights ? h[c] / h[dim] : h[c];
        if (b->weights)
            weights[k] = h[dim];
    }
    return bs_patch_create(pu, pv, dim, ctrl, b->weights ? weights : NULL, out);
}

/* Every patch of b, in order, into patches[0 .. nu * nv); su and sv: the spans' first knots. */
static bs_status make_patches(const bs_bspline *b, const bsi_knots *ku, const bsi_knots *kv,
                              const size_t *su, const size_t *sv, bs_patch **patches)
{
    size_t ncoord = b->dim + (b->weights != NULL), pu = b->deg_u, pv = b->deg_v;
    size_t nnet = (pu + 1) * (pv + 1);
    double *h = homogeneous_net(b, ncoord);
    double *rows = malloc((pu + 1) * b->count_v * ncoord * sizeof(double));
    double *net = malloc(nnet * ncoord * sizeof(double));
    double *ctrl = malloc(nnet * b->dim * sizeof(double));
    double *weights = malloc(nnet * sizeof(double));
    bs_status st = h && rows && net && ctrl && weights ? BS_OK : BS_ERR_NO_MEMORY;
    size_t made = 0;
    for (size_t a = 0; st == BS_OK && a < ku->nspan; a++) {
        /* the Bezier rows of u-span a, column by column of the net */
        for (size_t j = 0; j < b->count_v; j++)
            bsi_span_bezier(b->knots_u, pu, su[a], h + j * ncoord, b->count_v * ncoord, ncoord,
                            rows + j * ncoord, b->count_v * ncoord);
        for (size_t bv = 0; st == BS_OK && bv < kv->nspan; bv++) {
            st = span_patch(b, rows, ncoord, sv[bv], net, ctrl, weights, &patches[made]);
            made += st == BS_OK;
        }
    }
    if (st != BS_OK)
        for (size_t k = 0; k < made; k++)
            bs_patch_destroy(patches[k]);
    free(h);
    free(rows);
    free(net);
    free(ctrl);
    free(weights);
    return st;
}

bs_status bs_surface_add_bspline(bs_surface *s, const bs_bspline *b, double *spans, size_t spans_cap,
                                 size_t *count)
{
    if (s == NULL || b == NULL)
        return BS_ERR_INVALID_ARG;
    bsi_knots ku, kv;
    bs_status st = check_all(b, &ku, &kv);
    if (st != BS_OK)
        return st;
    if (bs_surface_count(s) > 0 && bs_surface_dim(s) != b->dim)
        return BS_ERR_INCOMPATIBLE;
    if (ku.nspan > UINT32_MAX / kv.nspan)
        return BS_ERR_SIZE;
    size_t np = ku.nspan * kv.nspan;
    if ((spans != NULL && spans_cap / 4 < np) || np > UINT32_MAX - bs_surface_count(s))
        return BS_ERR_SIZE;
    bs_patch **patches = malloc(np * sizeof(*patches)); // NOLINT(bugprone-sizeof-expression): an array of pointers
    size_t *su = malloc(ku.nspan * sizeof(size_t)), *sv = malloc(kv.nspan * sizeof(size_t));
    st = patches && su && sv ? BS_OK : BS_ERR_NO_MEMORY;
    if (st == BS_OK) {
        bsi_knots_spans(&ku, su);
        bsi_knots_spans(&kv, sv);
        st = make_patches(b, &ku, &kv, su, sv, patches);
        if (st == BS_OK && (st = bsi_surface_adopt(s, patches, np)) != BS_OK)
            for (size_t k = 0; k < np; k++)
                bs_patch_destroy(patches[k]);
    }
    for (size_t a = 0; st == BS_OK && spans != NULL && a < ku.nspan; a++)
        for (size_t bv = 0; bv < kv.nspan; bv++) {
            double *sp = spans + 4 * (a * kv.nspan + bv);
            sp[0] = ku.t[su[a]];
            sp[1] = ku.t[su[a] + 1];
            sp[2] = kv.t[sv[bv]];
            sp[3] = kv.t[sv[bv] + 1];
        }
    if (st == BS_OK && count != NULL)
        *count = np;
    free(patches);
    free(su);
    free(sv);
    return st;
}
