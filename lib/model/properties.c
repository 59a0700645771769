/*
 * Area, enclosed volume and centroid of a model, on the exact surfaces.
 *
 * Each quantity is an integral over a face's trimmed parameter domain D of a function f(u, v) of
 * the surface point S and w = S_u x S_v (outward): |w| for the area, S.w / 3 for the volume
 * (divergence theorem), S_x^2 w_x / 2 ... for the volume's moments, S_x |w| ... for the area's.
 * Green's theorem turns the integral over D into one along its boundary:
 *     integral over D of f du dv = sum over loops of the integral of F(u, v) dv,
 *     F(u, v) = integral of f(s, v) ds from the face's u0 to u,
 * with each loop counted counter-clockwise in (u, v) for the outer loop and clockwise for holes
 * (the file's orientation is not relied on: each loop's sign comes from the area it encloses).
 * Both integrals are adaptive Gauss-Kronrod (quadrature.c), the inner one cut at the face's
 * patch breaks, the outer one along each exact Bezier segment of the trims. A first pass at a
 * coarse tolerance gives each quantity's size; the second holds every error estimate below
 * rel_tol times that size. Points are taken relative to the centre of the model's box, so that
 * a part far from the origin loses no digits to the cancellation of its faces' volumes; its
 * coordinates still carry rounding of their magnitude, so the tolerance is never below
 * 16 eps times (the largest coordinate / the box's diagonal).
 */
#include "model/quadrature.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { AREA, VOLUME, VMOM, AMOM = VMOM + 3, NQ = AMOM + 3 };

#define INNER_MAX 400   /* Gauss-Kronrod rules per inner integral */
#define OUTER_MAX 4000  /* per trim segment */

typedef struct prop_ctx {
    const bs_model *m;
    size_t face;
    double sign;            /* -1 for a reversed face */
    double centre[3];
    const bsi_axis *ubreaks; /* the axis along native u */
    double u0, u1;
    double v;               /* the inner integral's fixed v */
    double inner_tol[NQ];
    const double *seg;      /* the outer segment's homogeneous points */
    size_t degree;
    int failed;
} prop_ctx;

/* f at native (u, v) of the face, for the inner integral along u. */
static int inner_fn(void *ctx_, size_t n, const double *x, double *f)
{
    const prop_ctx *ctx = ctx_;
    for (size_t i = 0; i < n; i++) {
        double p[3], pu[3], pv[3], w[3];
        if (!bsi_face_partials(ctx->m, ctx->face, x[i], ctx->v, p, pu, pv))
            return 0;
        bsi_cross3(pu, pv, w);
        for (int c = 0; c < 3; c++) {
            w[c] *= ctx->sign;
            p[c] -= ctx->centre[c];
        }
        double a = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        double *out = f + i * NQ;
        out[AREA] = a;
        out[VOLUME] = bsi_dot3(p, w) / 3.0;
        for (int c = 0; c < 3; c++) {
            out[VMOM + c] = 0.5 * p[c] * p[c] * w[c];
            out[AMOM + c] = p[c] * a;
        }
    }
    return 1;
}

/* F(u, v): the inner integral from the face's u0 to u, cut at the patch breaks between. */
static int inner_integral(prop_ctx *ctx, double u, double *F)
{
    double err[NQ], part[NQ];
    for (int c = 0; c < NQ; c++)
        F[c] = 0.0;
    u = u < ctx->u0 ? ctx->u0 : u > ctx->u1 ? ctx->u1 : u;
    const bsi_axis *a = ctx->ubreaks;
    for (size_t k = 0; k < a->n && a->breaks[k] < u; k++) {
        double hi = a->breaks[k + 1] < u ? a->breaks[k + 1] : u;
        if (!bsi_quad(inner_fn, ctx, NQ, a->breaks[k], hi, ctx->inner_tol, INNER_MAX, part, err))
            return 0;
        for (int c = 0; c < NQ; c++)
            F[c] += part[c];
    }
    return 1;
}

/* The point and derivative of a rational Bezier segment in 2-D at local t (de Casteljau). */
static void segment_at(const double *hom, size_t degree, double t, double *uv, double *duv)
{
    double q[(BS_MAX_DEGREE + 1) * 3];
    memcpy(q, hom, (degree + 1) * 3 * sizeof *q);
    for (size_t r = degree; r > 1; r--)
        for (size_t i = 0; i < r; i++)
            for (int c = 0; c < 3; c++)
                q[i * 3 + (size_t)c] = (1.0 - t) * q[i * 3 + (size_t)c] + t * q[(i + 1) * 3 + (size_t)c];
    double h[3], dh[3];
    for (int c = 0; c < 3; c++) {
        h[c] = (1.0 - t) * q[c] + t * q[3 + c];
        dh[c] = (double)degree * (q[3 + c] - q[c]);
    }
    uv[0] = h[0] / h[2];
    uv[1] = h[1] / h[2];
    duv[0] = (dh[0] - uv[0] * dh[2]) / h[2];
    duv[1] = (dh[1] - uv[1] * dh[2]) / h[2];
}

/* G(t) = F(c(t)) dv/dt along the outer segment. */
static int outer_fn(void *ctx_, size_t n, const double *x, double *f)
{
    prop_ctx *ctx = ctx_;
    for (size_t i = 0; i < n; i++) {
        double uv[2], duv[2], F[NQ];
        segment_at(ctx->seg, ctx->degree, x[i], uv, duv);
        if (duv[1] == 0.0) {
            memset(f + i * NQ, 0, NQ * sizeof *f);
            continue;
        }
        ctx->v = uv[1];
        if (!inner_integral(ctx, uv[0], F))
            return 0;
        for (int c = 0; c < NQ; c++)
            f[i * NQ + (size_t)c] = F[c] * duv[1];
    }
    return 1;
}

/* The signed area one loop encloses in (u, v), exact for its polygon of control points is not
 * enough near seams: integrated as u dv along the exact segments. */
static int area_fn(void *ctx_, size_t n, const double *x, double *f)
{
    const prop_ctx *ctx = ctx_;
    for (size_t i = 0; i < n; i++) {
        double uv[2], duv[2];
        segment_at(ctx->seg, ctx->degree, x[i], uv, duv);
        f[i] = (uv[0] - ctx->u0) * duv[1];
    }
    return 1;
}

/* One loop (trims[0..n)) of a face: its contribution, counted with the sign its enclosed area
 * gives (outer: positive, inner: negative). */
static int loop_integral(prop_ctx *ctx, const bsi_trim *trims, size_t n, int outer, const double *tol,
                         double *sum)
{
    double enclosed = 0.0, one = 0.0, err;
    const double area_tol = 1e-12 * (ctx->u1 - ctx->u0);
    double loop[NQ] = {0};
    for (size_t t = 0; t < n; t++) {
        const bsi_curve *c = &trims[t].uv;
        double dir = trims[t].reversed ? -1.0 : 1.0;
        ctx->degree = c->degree;
        for (size_t k = 0; k < c->axis.n; k++) {
            ctx->seg = c->hom + k * (c->degree + 1) * 3;
            double part[NQ], perr[NQ];
            if (!bsi_quad(area_fn, ctx, 1, 0.0, 1.0, &area_tol, OUTER_MAX, &one, &err) ||
                !bsi_quad(outer_fn, ctx, NQ, 0.0, 1.0, tol, OUTER_MAX, part, perr))
                return 0;
            enclosed += dir * one;
            for (int q = 0; q < NQ; q++)
                loop[q] += dir * part[q];
        }
    }
    double s = (enclosed >= 0.0) == (outer != 0) ? 1.0 : -1.0;
    for (int q = 0; q < NQ; q++)
        sum[q] += s * loop[q];
    return 1;
}

/* A face's integrals; an untrimmed face is bounded by its box. */
static int face_integral(prop_ctx *ctx, const double *tol, double *sum)
{
    const bs_model *m = ctx->m;
    const bsi_face *face = &m->faces[ctx->face];
    ctx->sign = face->reversed ? -1.0 : 1.0;
    ctx->ubreaks = face->swap ? &face->av : &face->au;
    ctx->u0 = face->box[0];
    ctx->u1 = face->box[1];
    if (face->loop_count == 0) {
        const double *b = face->box;
        double corner[4][2] = {{b[0], b[2]}, {b[1], b[2]}, {b[1], b[3]}, {b[0], b[3]}};
        bsi_trim box[4];
        int ok = 1, made = 0;
        memset(box, 0, sizeof box);
        for (int k = 0; k < 4 && ok; k++, made++) {
            double d[2] = {corner[(k + 1) % 4][0] - corner[k][0], corner[(k + 1) % 4][1] - corner[k][1]};
            ok = bsi_curve_line(2, corner[k], d, 0.0, 1.0, &box[k].uv) == BS_OK;
        }
        ok = ok && loop_integral(ctx, box, 4, 1, tol, sum);
        for (int k = 0; k < made; k++)
            bsi_curve_free(&box[k].uv);
        return ok;
    }
    for (size_t l = 0; l < face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[face->first_loop + l];
        if (!loop_integral(ctx, m->trims + loop->first_trim, loop->trim_count, l == 0, tol, sum))
            return 0;
    }
    return 1;
}

/* Every face's integrals at the given absolute tolerances; the volume's over closed shells. */
static int model_integrals(prop_ctx *ctx, const double *tol, double *area_sum, double *closed_sum)
{
    const bs_model *m = ctx->m;
    size_t nseg = 0;
    for (size_t t = 0; t < m->ntrim; t++)
        nseg += m->trims[t].uv.axis.n;
    nseg += 4 * m->nface;
    double seg_tol[NQ];
    for (int q = 0; q < NQ; q++) {
        seg_tol[q] = tol[q] / (double)nseg;
        /* the inner error is multiplied by at most the segment's v-extent, bounded by the box's */
        ctx->inner_tol[q] = seg_tol[q];
    }
    for (size_t f = 0; f < m->nface; f++) {
        double sum[NQ] = {0};
        ctx->face = f;
        const double *b = m->faces[f].box;
        double extent = b[3] - b[2] > 0.0 ? b[3] - b[2] : 1.0;
        for (int q = 0; q < NQ; q++)
            ctx->inner_tol[q] = seg_tol[q] / (2.0 * extent);
        if (!face_integral(ctx, seg_tol, sum))
            return 0;
        int closed = m->shell_closed != NULL && m->shell_closed[m->faces[f].shell];
        for (int q = 0; q < NQ; q++) {
            area_sum[q] += sum[q];
            if (closed)
                closed_sum[q] += sum[q];
        }
    }
    return 1;
}

bs_status bs_model_properties(const bs_model *m, double rel_tol, double *area, double *volume,
                              double *centroid)
{
    if (m == NULL)
        return BS_ERR_INVALID_ARG;
    if (!(rel_tol >= 1e-12 && rel_tol <= 0.1))
        return BS_ERR_DOMAIN;
    prop_ctx ctx;
    memset(&ctx, 0, sizeof ctx);
    ctx.m = m;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p < bs_surface_count(m->surface); p++) {
        double plo[3], phi[3];
        if (bs_patch_bounds(bs_surface_get(m->surface, p), plo, phi) == BS_OK)
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], plo[c]);
                hi[c] = fmax(hi[c], phi[c]);
            }
    }
    double diag = 0.0, far = 0.0;
    for (int c = 0; c < 3; c++) {
        ctx.centre[c] = m->nface ? 0.5 * (lo[c] + hi[c]) : 0.0;
        diag = m->nface ? hypot(diag, hi[c] - lo[c]) : 0.0;
        far = m->nface ? fmax(far, fmax(fabs(lo[c]), fabs(hi[c]))) : 0.0;
    }
    /* coordinates far from the origin carry rounding of their magnitude: no quantity is known
     * better than that relative to the model's size */
    double floor_rel = diag > 0.0 ? 16.0 * DBL_EPSILON * far / diag : 0.0;
    rel_tol = fmax(rel_tol, floor_rel);
    /* pass 1: each quantity's size, at a coarse tolerance relative to the model's size */
    double size_of[NQ], tol[NQ], coarse_a[NQ] = {0}, coarse_v[NQ] = {0};
    double d2 = diag * diag, scale[NQ] = {d2, d2 * diag, 0, 0, 0, 0, 0, 0};
    for (int c = 0; c < 3; c++) {
        scale[VMOM + c] = d2 * d2;
        scale[AMOM + c] = d2 * diag;
    }
    for (int q = 0; q < NQ; q++)
        tol[q] = 1e-5 * scale[q];
    if (m->nface > 0 && !model_integrals(&ctx, tol, coarse_a, coarse_v))
        return BS_ERR_UNSUPPORTED;
    /* pass 2: within rel_tol of each size (the volume's of the closed shells) */
    double sum_a[NQ] = {0}, sum_v[NQ] = {0};
    for (int q = 0; q < NQ; q++) {
        double big = q == AREA || q >= AMOM ? fabs(coarse_a[q]) : fabs(coarse_v[q]);
        /* a moment is held to the model's scale (the centroid to rel_tol of the diagonal); a
         * small area or volume to a thousandth of it */
        size_of[q] = q >= VMOM ? fmax(big, scale[q]) : fmax(big, 1e-3 * scale[q]);
        tol[q] = 0.25 * rel_tol * size_of[q];
    }
    if (m->nface > 0 && !model_integrals(&ctx, tol, sum_a, sum_v))
        return BS_ERR_UNSUPPORTED;
    int any_closed = 0;
    for (size_t s = 0; s < m->nshell; s++)
        any_closed |= m->shell_closed != NULL && m->shell_closed[s];
    if (area != NULL)
        *area = sum_a[AREA];
    if (volume != NULL)
        *volume = any_closed ? sum_v[VOLUME] : NAN;
    if (centroid != NULL)
        for (int c = 0; c < 3; c++) {
            if (m->nface == 0)
                centroid[c] = NAN;
            else if (any_closed && sum_v[VOLUME] != 0.0)
                centroid[c] = ctx.centre[c] + sum_v[VMOM + c] / sum_v[VOLUME];
            else
                centroid[c] = ctx.centre[c] + sum_a[AMOM + c] / sum_a[AREA];
        }
    return BS_OK;
}
