/*
 * Trims computed from 3-D edges: the edge is projected onto the face's surface at its segment ends
 * (reached by continuation in small steps, so periodic parameters unwrap along the edge), and the
 * projected points with their parameter derivatives uv' = J+ C'(t) are joined by cubic Hermite
 * segments, bisected until the segment's image on the surface is within tol/2 (beyond the edge's
 * own distance to the surface) of the edge at a quarter, the middle and three quarters.
 */
#include "model/pcurve_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SEGMENTS 4096
#define ON_SURFACE 1000.0 /* how far, in tol, an edge may lie off its surface */
#define STACK 64     /* bisection depth: 2^-64 of a segment is far below any parameter step */
#define CHAIN 4      /* continuation steps from one segment end to the next */

typedef struct node {
    double t, uv[2], d[2], dl[2], dist; /* d: uv' onwards, dl: uv' before (they differ at corners) */
    int pole;
} node;

typedef struct fitter {
    const bsi_pc_surf *S;
    const bsi_curve *edge;
    double tol;
    node *nodes;
    size_t n, cap;
} fitter;

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* uv' = J+ C'(t) with C' from the edge's piece after t (left = 0) or before it (left = 1); at a
 * pole only the defined parameter moves. */
static void derivative(const fitter *F, node *a, int left)
{
    double c[3], dc[3], p[3], du[3], dv[3], *d = left ? a->dl : a->d;
    d[0] = d[1] = 0.0;
    if (!bsi_pc_edge(F->edge, a->t, left, c, dc) || !bsi_pc_eval(F->S, a->uv, p, du, dv))
        return; /* LCOV_EXCL_LINE: the foot was evaluated there */
    double a11 = dot3(du, du), a12 = dot3(du, dv), a22 = dot3(dv, dv);
    double b1 = dot3(du, dc), b2 = dot3(dv, dc), det = a11 * a22 - a12 * a12;
    if (a->pole & BSI_PC_POLE_U) {
        d[1] = a22 > 0.0 ? b2 / a22 : 0.0;
    } else if (a->pole & BSI_PC_POLE_V) {
        d[0] = a11 > 0.0 ? b1 / a11 : 0.0;
    } else if (det > 0.0) {
        d[0] = (a22 * b1 - a12 * b2) / det;
        d[1] = (a11 * b2 - a12 * b1) / det;
    }
}

static void derivatives(const fitter *F, node *a)
{
    derivative(F, a, 0);
    derivative(F, a, 1);
}

/* A foot found on the far side of a closed, non-periodic surface's seam (a lofted tube whose
 * first and last rows of control points agree), while the continuation comes from the near side:
 * the same point on the near side, when the surface is there within tol of it. */
static void across_seam(const bsi_pc_surf *S, const double *c, const double *start, node *out)
{
    for (size_t k = 0; k < 2; k++) {
        double lo = S->box[2 * k], hi = S->box[2 * k + 1], width = hi - lo;
        if (S->period[k] > 0.0 || !(width > 0.0) || !(fabs(out->uv[k] - start[k]) > 0.5 * width))
            continue;
        double uv[2] = {out->uv[0], out->uv[1]}, p[3], du[3], dv[3];
        uv[k] = out->uv[k] - lo < hi - out->uv[k] ? hi - (out->uv[k] - lo) : lo + (hi - out->uv[k]);
        if (!bsi_pc_eval(S, uv, p, du, dv))
            continue;
        double d = hypot(hypot(p[0] - c[0], p[1] - c[1]), p[2] - c[2]);
        if (d <= out->dist + 1e-9 * S->scale) {
            out->uv[k] = uv[k];
            out->dist = d;
        }
    }
}

/* The foot of the edge's point at t (start: a nearby uv, or NULL) with its derivative along t.
 * At a pole the undefined parameter is taken from start. */
static bs_status project_node(const fitter *F, double t, const double *start, node *out)
{
    double c[3], dc[3];
    if (!bsi_pc_edge(F->edge, t, 0, c, dc))
        return BS_ERR_DOMAIN; /* LCOV_EXCL_LINE: t lies in the edge's range */
    bs_status st = bsi_pc_project(F->S, c, start, F->tol, out->uv, &out->dist, &out->pole);
    if (st != BS_OK)
        return st;
    if (start != NULL)
        across_seam(F->S, c, start, out);
    /* CAD edges lie on their faces only within the writer's tolerance (often 1e-5 of the part
     * or more): an edge within 1000 tol (1e-4 D for the readers) is on the surface, and the fit
     * follows its feet to tol beyond that distance */
    if (!(out->dist <= ON_SURFACE * F->tol))
        return BS_ERR_DOMAIN;
    out->t = t;
    if (start != NULL && (out->pole & BSI_PC_POLE_U))
        out->uv[0] = start[0];
    if (start != NULL && (out->pole & BSI_PC_POLE_V))
        out->uv[1] = start[1];
    derivatives(F, out);
    return BS_OK;
}

/* The Bezier points of the cubic Hermite segment from a to b. */
static void hermite(const node *a, const node *b, double P[4][2])
{
    double h = (b->t - a->t) / 3.0;
    for (int k = 0; k < 2; k++) {
        P[0][k] = a->uv[k];
        P[1][k] = a->uv[k] + h * a->d[k];
        P[2][k] = b->uv[k] - h * b->dl[k];
        P[3][k] = b->uv[k];
    }
}

static void cubic(double P[4][2], double s, double *uv)
{
    double r = 1.0 - s;
    for (int k = 0; k < 2; k++)
        uv[k] = r * r * r * P[0][k] + 3.0 * r * s * (r * P[1][k] + s * P[2][k]) + s * s * s * P[3][k];
}

/* b reached from a by CHAIN steps of continuation; the first node's parameter undefined at a pole
 * is the first step's. */
static bs_status chain(const fitter *F, node *a, double t1, node *b)
{
    node prev = *a;
    for (int k = 1; k <= CHAIN; k++) {
        double t = k == CHAIN ? t1 : a->t + (t1 - a->t) * (double)k / CHAIN;
        double start[2] = {prev.uv[0] + (t - prev.t) * prev.d[0], prev.uv[1] + (t - prev.t) * prev.d[1]};
        bs_status st = project_node(F, t, start, b);
        if (st != BS_OK)
            return st;
        if (k == 1 && F->n == 1 && (a->pole & BSI_PC_POLE_U))
            a->uv[0] = b->uv[0];
        if (k == 1 && F->n == 1 && (a->pole & BSI_PC_POLE_V))
            a->uv[1] = b->uv[1];
        if (k == 1 && F->n == 1 && a->pole)
            derivatives(F, a);
        prev = *b;
    }
    return BS_OK;
}

/* Whether the Hermite segment a..b fits (*ok); *mid receives the foot at the middle. */
static bs_status fits(const fitter *F, const node *a, const node *b, node *mid, int *ok)
{
    static const double at[3] = {0.5, 0.25, 0.75};
    double P[4][2];
    hermite(a, b, P);
    *ok = 0;
    for (int i = 0; i < 3; i++) {
        double uv[2], p[3], du[3], dv[3], c[3], dc[3];
        node foot;
        double t = a->t + at[i] * (b->t - a->t);
        cubic(P, at[i], uv);
        bs_status st = project_node(F, t, uv, &foot);
        if (st != BS_OK)
            return st;
        if (i == 0)
            *mid = foot;
        (void)bsi_pc_edge(F->edge, t, 0, c, dc);
        if (!bsi_pc_eval(F->S, uv, p, du, dv))
            return BS_OK;
        if (!(hypot(hypot(p[0] - c[0], p[1] - c[1]), p[2] - c[2]) <= 0.5 * F->tol + foot.dist))
            return BS_OK;
    }
    *ok = 1;
    return BS_OK;
}

static bs_status append(fitter *F, const node *a)
{
    if (F->n > MAX_SEGMENTS)
        return BS_ERR_DOMAIN;
    if (F->n == F->cap) {
        size_t cap = F->cap ? 2 * F->cap : 16;
        node *grown = realloc(F->nodes, cap * sizeof *grown);
        if (grown == NULL)
            return BS_ERR_NO_MEMORY;
        F->nodes = grown;
        F->cap = cap;
    }
    F->nodes[F->n++] = *a;
    return BS_OK;
}

/* The nodes of the fit over edge segment [t0, t1], the node at t0 being the last one. */
static bs_status fit_span(fitter *F, double t1, double min_step)
{
    node stack[STACK];
    size_t top = 0;
    bs_status st = chain(F, &F->nodes[F->n - 1], t1, &stack[top++]);
    while (st == BS_OK && top > 0) {
        const node *a = &F->nodes[F->n - 1];
        node mid;
        int ok;
        if ((st = fits(F, a, &stack[top - 1], &mid, &ok)) != BS_OK)
            break;
        if (ok) {
            st = append(F, &stack[--top]);
        } else if (top == STACK || stack[top - 1].t - a->t <= min_step) {
            st = BS_ERR_DOMAIN;
        } else {
            stack[top++] = mid;
        }
    }
    return st;
}

/* A first foot on the seam of a surface closed in a direction that is not periodic (a closed
 * B-spline's first and last rows are the same points) is put on the side the edge goes on: the
 * side nearer the foot a step further along. */
static bs_status seam_side(const fitter *F, node *first, double t1)
{
    const bsi_pc_surf *S = F->S;
    for (size_t k = 0; k < 2 && S->def == NULL; k++) {
        double lo = S->box[2 * k], hi = S->box[2 * k + 1], eps = 1e-9 * (hi - lo);
        int at_lo = fabs(first->uv[k] - lo) <= eps, at_hi = fabs(first->uv[k] - hi) <= eps;
        if (S->period[k] > 0.0 || !(at_lo || at_hi))
            continue;
        double other[2] = {first->uv[0], first->uv[1]}, p[3], q[3], du[3], dv[3];
        other[k] = at_lo ? hi : lo;
        if (!bsi_pc_eval(S, first->uv, p, du, dv) || !bsi_pc_eval(S, other, q, du, dv) ||
            !(hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]) <= F->tol))
            continue;
        node probe;
        bs_status st = project_node(F, first->t + (t1 - first->t) / CHAIN, NULL, &probe);
        if (st != BS_OK)
            return st;
        if (fabs(probe.uv[k] - other[k]) < fabs(probe.uv[k] - first->uv[k])) {
            first->uv[k] = other[k];
            derivatives(F, first);
        }
    }
    return BS_OK;
}

/* Whole periods added to a periodic direction of every node: the trim inside [lo, hi] when its
 * range fits there, else its start in [lo, lo + period). */
static void place(fitter *F, int k, double lo, double hi, double period)
{
    if (!(period > 0.0))
        return;
    double a = INFINITY, b = -INFINITY, eps = 1e-9 * period;
    for (size_t i = 0; i < F->n; i++) {
        a = fmin(a, F->nodes[i].uv[k]);
        b = fmax(b, F->nodes[i].uv[k]);
    }
    double shift = period * ceil((lo - eps - a) / period);
    if (!(b + shift <= hi + eps))
        shift = period * -floor((F->nodes[0].uv[k] - lo + eps) / period);
    for (size_t i = 0; i < F->n; i++)
        F->nodes[i].uv[k] += shift;
}

/* The trim from the nodes: LINEAR over their parameters, one cubic per pair. */
static bs_status to_trim(const fitter *F, bsi_trim *out)
{
    bsi_curve c;
    memset(&c, 0, sizeof c);
    size_t nseg = F->n - 1;
    double *inner = malloc(F->n * sizeof *inner);
    if (inner == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 1; i < nseg; i++)
        inner[i - 1] = F->nodes[i].t;
    bs_status st = bsi_axis_make(BSI_AXIS_LINEAR, 1.0, F->nodes[0].t, F->nodes[nseg].t, inner,
                                 nseg - 1, &c.axis);
    free(inner);
    if (st != BS_OK)
        return st;
    /* the breaks strictly increase: the axis has nseg >= 1 pieces (a node per span end) */
    /* NOLINTNEXTLINE(clang-analyzer-optin.portability.UnixAPI): nseg >= 1, see above */
    if ((c.hom = malloc(nseg * 4 * 3 * sizeof *c.hom)) == NULL) {
        bsi_axis_free(&c.axis);
        return BS_ERR_NO_MEMORY;
    }
    c.dim = 2;
    c.degree = 3;
    for (size_t k = 0; k < nseg; k++) {
        double P[4][2];
        hermite(&F->nodes[k], &F->nodes[k + 1], P);
        for (int i = 0; i < 4; i++) {
            double *h = c.hom + (k * 4 + (size_t)i) * 3;
            h[0] = P[i][0];
            h[1] = P[i][1];
            h[2] = 1.0;
        }
    }
    memset(out, 0, sizeof *out);
    out->uv = c;
    out->edge = BSI_NO_EDGE;
    out->computed = 1;
    return BS_OK;
}

/* The size of the edge's control points (relative thresholds). */
static double edge_scale(const bsi_curve *e)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < e->axis.n * (e->degree + 1); i++)
        for (int c = 0; c < 3; c++) {
            double x = e->hom[i * 4 + (size_t)c] / e->hom[i * 4 + 3];
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
    return fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), fmax(hi[2] - lo[2], fabs(lo[0]) + fabs(lo[1]) + fabs(lo[2])));
}

bs_status bsi_pc_fit(const bsi_pc_surf *S, const bsi_curve *edge, const double *hint,
                     const double *place_box, double tol, bsi_trim *out)
{
    if (edge->dim != 3 || edge->axis.n == 0 || edge->hom == NULL || !(tol > 0.0))
        return BS_ERR_INVALID_ARG;
    bsi_pc_surf sized = *S;
    if (!(sized.scale > 0.0))
        sized.scale = edge_scale(edge);
    fitter F = {&sized, edge, tol, NULL, 0, 0};
    const double *br = edge->axis.breaks;
    double min_step = 1e-12 * (br[edge->axis.n] - br[0]);
    node first;
    bs_status st = project_node(&F, br[0], hint, &first);
    if (st == BS_OK && hint == NULL)
        st = seam_side(&F, &first, br[1]);
    if (st == BS_OK)
        st = append(&F, &first);
    for (size_t k = 0; st == BS_OK && k < edge->axis.n; k++)
        st = fit_span(&F, br[k + 1], min_step);
    if (st == BS_OK && hint == NULL && place_box != NULL) {
        place(&F, 0, place_box[0], place_box[1], sized.period[0]);
        place(&F, 1, place_box[2], place_box[3], sized.period[1]);
    }
    if (st == BS_OK)
        st = to_trim(&F, out);
    free(F.nodes);
    return st;
}

bs_status bsi_pcurve_project(const bs_model *m, size_t f, const bsi_curve *edge, double tol,
                             bsi_trim *out)
{
    memset(out, 0, sizeof *out);
    out->edge = BSI_NO_EDGE;
    if (m == NULL || f >= m->nface || edge == NULL)
        return BS_ERR_INVALID_ARG;
    const bsi_face *face = &m->faces[f];
    bsi_pc_surf S;
    memset(&S, 0, sizeof S);
    S.s = m->surface;
    S.first = face->first_patch;
    S.au = &face->au;
    S.av = &face->av;
    S.swap = face->swap;
    memcpy(S.box, face->box, sizeof S.box);
    memcpy(S.period, face->period, sizeof S.period);
    return bsi_pc_fit(&S, edge, NULL, face->box, tol, out);
}
