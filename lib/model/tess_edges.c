/*
 * Tessellation phase 1 (tess.h): each model edge sampled once.
 *
 * The edge's first trim is its master: the edge is the master's trim curve carried onto its face.
 * An interval of the master's parameter is halved until, at its midpoint and quarter points, the
 * edge lies within tol / 2 of the chord, and, on every face using the edge, the surface at the
 * middle of the trim's chord in (u, v) lies within tol / 2 of the chord's middle: a triangle
 * standing on the chord then errs by no more than the interior allows. Each sample's 3-D point is
 * projected onto the edge's other trims (Gauss-Newton on the trim's curve carried onto its face,
 * between the neighbouring samples' parameters), so that they share the vertex.
 * Edge ends, and trims whose image is a single point (the poles of spheres and cones), are model
 * vertices: points closer than j->merge are one.
 */
#include "model/tess_edge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 24
#define COARSE 64 /* samples of a trim when telling the direction of a closed edge */
/* Segments near an edge's end: at most GRADE times (the shortest segment there + the distance
 * from the end); 4 halves the slivers' count at a quarter more triangles than none (the bottle). */
#define GRADE 4.0

/* ---- One edge: its trims, the samples' parameters on each ---- */
#define MAX_USES 8
/* Trims of one edge whose ends a file wrote up to BSI_LOOSE_GAP apart share its vertices, moved
 * to where the faces meet. */

/* One sample of an edge: its parameter and (u, v) on each trim, its point and vertex. */
typedef struct edge_sample {
    double par[MAX_USES];
    double uv[MAX_USES][2];
    double P[3];
    uint32_t vid;
} edge_sample;

typedef struct edge_run {
    tm_job *j;
    size_t n;                   /* trims of the edge (master first) */
    size_t trim[MAX_USES];
    curve3 c[MAX_USES];
    int loose;                  /* the second trim is apart from the master (BSI_LOOSE_GAP) */
    double end[2][3];           /* the edge's ends */
    double grade[2];            /* the grading at its ends (INFINITY: none) */
    edge_sample *s;             /* samples so far, in the master's order */
    size_t ns, cap;
} edge_run;

static bs_status add_sample(edge_run *r, const edge_sample *s)
{
    if (!bsi_grow_array((void **)&r->s, &r->cap, r->ns + 1, sizeof(edge_sample)))
        return BS_ERR_NO_MEMORY;
    r->s[r->ns++] = *s;
    return BS_OK;
}

/* s's point and (u, v) moved to where the master's face and the loose trim's meet; left as they
 * are where they do not meet near it (nearly tangent faces, where the gap matters least). */
static void meet(const edge_run *r, edge_sample *s)
{
    double ua[2] = {s->uv[0][0], s->uv[0][1]}, ub[2] = {s->uv[1][0], s->uv[1][1]}, X[3];
    const tm_job *j = r->j;
    if (bsi_tm_meet(j->m, r->c[0].face, ua, r->c[1].face, ub, 1e-6 * j->tol, X) &&
        bsi_tm_dist3(X, s->P) <= BSI_LOOSE_GAP * j->diag) {
        memcpy(s->P, X, sizeof s->P);
        memcpy(s->uv[0], ua, sizeof ua);
        memcpy(s->uv[1], ub, sizeof ub);
    }
}

/* The loose trim's (u, v) at an end of the edge: where the faces meet next to the master's end. */
static void meet_at_end(const edge_run *r, edge_sample *s)
{
    edge_sample moved = *s;
    meet(r, &moved);
    memcpy(s->uv[1], moved.uv[1], sizeof moved.uv[1]);
}

/* The point at master parameter t between a and the parameters hi (the next known sample or
 * the edge's end): on the master, projected onto the other trims. 0 when off the face. */
static int edge_point(const edge_run *r, double t, const edge_sample *a, const double *hi, edge_sample *out)
{
    out->par[0] = t;
    if (!bsi_tm_curve_at(&r->c[0], t, out->uv[0], out->P))
        return 0;
    double frac = (t - a->par[0]) / (hi[0] - a->par[0]);
    for (size_t i = 1; i < r->n; i++) {
        out->par[i] = bsi_tm_project(&r->c[i], out->P, a->par[i], hi[i], a->par[i] + (hi[i] - a->par[i]) * frac);
        bsi_curve_eval(r->c[i].uv, out->par[i], out->uv[i]);
    }
    if (r->loose)
        meet(r, out);
    return 1;
}

/* edge_point, a new vertex there. */
static bs_status new_sample(edge_run *r, double t, const edge_sample *a, const double *hi, edge_sample *out)
{
    if (!edge_point(r, t, a, hi, out))
        return BS_ERR_DOMAIN;
    return bsi_tm_new_vertex(&r->j->edges, out->P, (uint32_t)r->c[0].face, out->uv[0], &out->vid);
}

/* 1 when the interval between samples a and b is fine. */
static int interval_fine(const edge_run *r, const edge_sample *a, const edge_sample *b)
{
    double half = 0.5 * r->j->tol, len = bsi_tm_dist3(a->P, b->P);
    /* graded from the ends (GRADE), so that a long straight edge meeting finely sampled curves
     * leaves no slivers there */
    if (len > GRADE * (r->grade[0] + bsi_tm_dist3(a->P, r->end[0])) ||
        len > GRADE * (r->grade[1] + bsi_tm_dist3(b->P, r->end[1])))
        return 0;
    for (int q = 1; q <= 3; q++) {
        double f = 0.25 * q, t = a->par[0] + f * (b->par[0] - a->par[0]), chord[3];
        /* the edge is the master's curve, or where the faces meet when the trims are apart */
        edge_sample at;
        if (!(r->loose ? edge_point(r, t, a, b->par, &at) : bsi_tm_curve_at(&r->c[0], t, at.uv[0], at.P)))
            return 0;
        for (int k = 0; k < 3; k++)
            chord[k] = a->P[k] + f * (b->P[k] - a->P[k]);
        if (bsi_tm_dist3(at.P, chord) > half)
            return 0;
    }
    double mid[3];
    for (int k = 0; k < 3; k++)
        mid[k] = 0.5 * (a->P[k] + b->P[k]);
    for (size_t i = 0; i < r->n; i++) {
        double p[3], u = 0.5 * (a->uv[i][0] + b->uv[i][0]), v = 0.5 * (a->uv[i][1] + b->uv[i][1]);
        if (!bsi_face_point(r->j->m, r->c[i].face, u, v, p) || bsi_tm_dist3(p, mid) > half)
            return 0;
    }
    return 1;
}

/* Sample (a, b] recursively; a is already in. */
static bs_status refine(edge_run *r, const edge_sample *a, const edge_sample *b, int depth, int forced)
{
    if (depth >= MAX_DEPTH || (forced <= 0 && interval_fine(r, a, b)))
        return add_sample(r, b);
    edge_sample mid;
    bs_status st = new_sample(r, 0.5 * (a->par[0] + b->par[0]), a, b->par, &mid);
    if (st == BS_OK)
        st = refine(r, a, &mid, depth + 1, forced - 1);
    if (st == BS_OK)
        st = refine(r, &mid, b, depth + 1, forced - 1);
    return st;
}

/* The parameters on trim i of the master's ends when they lie within slack of them: 1, or 0. */
static int match_ends(edge_run *r, size_t i, const double *P0, const double *P1, int closed, double slack,
                      double *s0, double *s1)
{
    const curve3 *c = &r->c[i];
    double uv[2], Q0[3], Q1[3];
    if (!bsi_tm_curve_at(c, c->t0, uv, Q0) || !bsi_tm_curve_at(c, c->t1, uv, Q1))
        return 0;
    double same = bsi_tm_dist3(Q0, P0) + bsi_tm_dist3(Q1, P1), other = bsi_tm_dist3(Q0, P1) + bsi_tm_dist3(Q1, P0);
    if ((same < other ? same : other) > slack)
        return 0;
    int forward = same <= other;
    if (closed) {
        /* both ends are one point: the direction from a point a quarter along the master */
        const curve3 *m = &r->c[0];
        double P[3], best = INFINITY, at = c->t0;
        if (!bsi_tm_curve_at(m, m->t0 + 0.25 * (m->t1 - m->t0), uv, P))
            return 0;
        for (int k = 0; k <= COARSE; k++) {
            double t = c->t0 + (c->t1 - c->t0) * k / COARSE, Q[3];
            if (bsi_tm_curve_at(c, t, uv, Q) && bsi_tm_dist3(Q, P) < best) {
                best = bsi_tm_dist3(Q, P);
                at = t;
            }
        }
        forward = at < 0.5 * (c->t0 + c->t1);
    }
    *s0 = forward ? c->t0 : c->t1;
    *s1 = forward ? c->t1 : c->t0;
    return 1;
}

/* Store the run's samples into each of its trims, ascending in the trim's own parameter. */
static bs_status store(tm_job *j, edge_run *r)
{
    tm_edges *e = &j->edges;
    for (size_t i = 0; i < r->n; i++) {
        if (!bsi_grow_array((void **)&e->uv, &e->sample_cap, e->nsample + r->ns, 2 * sizeof(double)))
            return BS_ERR_NO_MEMORY;
        void *q = realloc(e->vid, e->sample_cap * sizeof(uint32_t));
        if (q == NULL)
            return BS_ERR_NO_MEMORY;
        e->vid = q;
        tm_trim *t = &e->trim[r->trim[i]];
        int descending = r->ns > 1 && r->s[r->ns - 1].par[i] < r->s[0].par[i];
        t->first = e->nsample;
        t->count = r->ns;
        for (size_t k = 0; k < r->ns; k++) {
            const edge_sample *src = &r->s[descending ? r->ns - 1 - k : k];
            memcpy(e->uv + 2 * e->nsample, src->uv[i], 2 * sizeof(double));
            e->vid[e->nsample++] = src->vid;
        }
    }
    return BS_OK;
}

/* The trims of the edge after the master that share its samples: those whose ends are the
 * master's, or failing any, one within BSI_LOOSE_GAP of them; the rest into alone[]. */
static void gather_trims(edge_run *r, const size_t *trims, size_t n, edge_sample *first, edge_sample *last,
                         int closed, size_t *alone, size_t *nalone, size_t alone_cap)
{
    const tm_job *j = r->j;
    for (size_t k = 1; k < n; k++) {
        if (r->n < MAX_USES) {
            bsi_tm_curve_init(&r->c[r->n], j, trims[k]);
            if (match_ends(r, r->n, first->P, last->P, closed, 10.0 * j->merge, &first->par[r->n],
                           &last->par[r->n])) {
                r->trim[r->n++] = trims[k];
                continue;
            }
        }
        if (*nalone < alone_cap)
            alone[(*nalone)++] = trims[k];
    }
    /* an edge of two trims written apart: the second shares the master's samples, moved to
     * where the faces meet */
    if (r->n == 1 && n == 2 && *nalone == 1) {
        bsi_tm_curve_init(&r->c[1], j, trims[1]);
        if (match_ends(r, 1, first->P, last->P, closed, BSI_LOOSE_GAP * j->diag, &first->par[1],
                       &last->par[1])) {
            r->trim[r->n++] = trims[1];
            r->loose = 1;
            *nalone = 0;
        }
    }
}

/* How far the master's points stand from where the faces meet, less the second trim's: > 0 when
 * the second trim is the better master (the sum at the master's quarter points). */
static double master_excess(const edge_run *r)
{
    double excess = 0.0;
    for (int q = 1; q <= 3; q++) {
        double t = r->c[0].t0 + 0.25 * q * (r->c[0].t1 - r->c[0].t0), P[3], Q[3], X[3], ua[2], ub[2];
        if (!bsi_tm_curve_at(&r->c[0], t, ua, P))
            return 0.0;
        double s = bsi_tm_project(&r->c[1], P, r->c[1].t0, r->c[1].t1, 0.5 * (r->c[1].t0 + r->c[1].t1));
        if (!bsi_tm_curve_at(&r->c[1], s, ub, Q) ||
            !bsi_tm_meet(r->j->m, r->c[0].face, ua, r->c[1].face, ub, 1e-6 * r->j->tol, X))
            return 0.0;
        excess += bsi_tm_dist3(X, P) - bsi_tm_dist3(X, Q);
    }
    return excess;
}

/* Sample the edge whose trims are trims[0 .. n) (the first the master; of an edge of two trims
 * written apart, the one nearer where the faces meet unless keep_master). */
static bs_status sample_edge(tm_job *j, const size_t *trims, size_t n, int keep_master)
{
    edge_run r;
    memset(&r, 0, sizeof r);
    r.j = j;
    r.trim[0] = trims[0];
    bsi_tm_curve_init(&r.c[0], j, trims[0]);
    r.n = 1;
    const curve3 *mc = &r.c[0];
    edge_sample first, last;
    memset(&first, 0, sizeof first);
    memset(&last, 0, sizeof last);
    first.par[0] = mc->t0;
    last.par[0] = mc->t1;
    if (!bsi_tm_curve_at(mc, mc->t0, first.uv[0], first.P) || !bsi_tm_curve_at(mc, mc->t1, last.uv[0], last.P))
        return BS_ERR_DOMAIN;
    int closed = bsi_tm_dist3(first.P, last.P) <= j->merge;
    size_t alone[MAX_USES * 4];
    size_t nalone = 0;
    gather_trims(&r, trims, n, &first, &last, closed, alone, &nalone, sizeof alone / sizeof alone[0]);
    if (r.loose && !keep_master && master_excess(&r) > 0.0) {
        size_t swapped[2] = {trims[1], trims[0]};
        return sample_edge(j, swapped, 2, 1);
    }
    for (size_t i = 1; i < r.n; i++) {
        bsi_curve_eval(r.c[i].uv, first.par[i], first.uv[i]);
        bsi_curve_eval(r.c[i].uv, last.par[i], last.uv[i]);
    }
    /* the ends are the neighbouring edges' too and stay where the master has them; the loose
     * trim's (u, v) there are where the faces meet, next to them */
    if (r.loose) {
        meet_at_end(&r, &first);
        meet_at_end(&r, &last);
    }
    bs_status st = bsi_tm_model_vertex(j, first.P, (uint32_t)mc->face, first.uv[0], &first.vid, &r.grade[0]);
    if (st == BS_OK)
        st = bsi_tm_model_vertex(j, last.P, (uint32_t)mc->face, last.uv[0], &last.vid, &r.grade[1]);
    memcpy(r.end[0], first.P, sizeof r.end[0]);
    memcpy(r.end[1], last.P, sizeof r.end[1]);
    if (st == BS_OK)
        st = add_sample(&r, &first);
    /* start from the master's Bezier segments, each halved at least once (twice for a closed
     * edge of one segment, so that it is never a two-gon) */
    const bsi_axis *ax = &mc->uv->axis;
    int forced = closed && ax->n < 2 ? 2 : 1;
    edge_sample a = first;
    for (size_t s = 1; s <= ax->n && st == BS_OK; s++) {
        edge_sample b = last;
        if (s < ax->n)
            st = new_sample(&r, ax->breaks[s], &a, last.par, &b);
        if (st == BS_OK)
            st = refine(&r, &a, &b, 0, forced);
        a = b;
    }
    if (st == BS_OK)
        st = store(j, &r);
    free(r.s);
    for (size_t k = 0; k < nalone && st == BS_OK; k++)
        st = sample_edge(j, &alone[k], 1, 1);
    return st;
}

void bsi_tm_edges_free(tm_edges *e)
{
    free(e->vert);
    free(e->uv);
    free(e->vid);
    free(e->trim);
    free(e->trim_face);
    free(e->model);
    free(e->grade);
    memset(e, 0, sizeof *e);
}

/* One pass over the edges and poles. */
static bs_status sample_all(tm_job *j)
{
    const bs_model *m = j->m;
    size_t *next = malloc((m->ntrim ? m->ntrim : 1) * sizeof(size_t));
    size_t *head = malloc((m->nedge ? m->nedge : 1) * sizeof(size_t));
    size_t *group = malloc((m->ntrim ? m->ntrim : 1) * sizeof(size_t));
    unsigned char *pole = calloc(m->ntrim ? m->ntrim : 1, 1);
    double *pole_at = malloc((m->ntrim ? m->ntrim : 1) * 3 * sizeof(double));
    bs_status st = BS_OK;
    if (next == NULL || head == NULL || group == NULL || pole == NULL || pole_at == NULL) {
        st = BS_ERR_NO_MEMORY;
        goto done;
    }
    for (size_t k = 0; k < m->nedge; k++)
        head[k] = SIZE_MAX;
    for (size_t t = m->ntrim; t-- > 0;) {
        pole[t] = (unsigned char)bsi_tm_is_pole(j, t, pole_at + 3 * t);
        uint32_t ed = m->trims[t].edge;
        if (ed != BSI_NO_EDGE && ed < m->nedge && !pole[t]) {
            next[t] = head[ed];
            head[ed] = t;
        }
    }
    /* edges in the order of their first trim, then lone trims, so that the result does not
     * depend on how edges were numbered */
    for (size_t t = 0; t < m->ntrim && st == BS_OK; t++) {
        if (pole[t])
            continue;
        uint32_t ed = m->trims[t].edge;
        size_t n = 0;
        if (ed != BSI_NO_EDGE && ed < m->nedge) {
            if (head[ed] != t)
                continue; /* sampled with its edge's first trim */
            for (size_t k = t; k != SIZE_MAX; k = next[k])
                group[n++] = k;
        } else {
            group[n++] = t;
        }
        st = sample_edge(j, group, n, 0);
    }
    /* poles last: their spacing follows the samples of their faces' other trims */
    for (size_t t = 0; t < m->ntrim && st == BS_OK; t++)
        if (pole[t])
            st = bsi_tm_sample_pole(j, t, pole_at + 3 * t);
done:
    free(next);
    free(head);
    free(group);
    free(pole);
    free(pole_at);
    return st;
}

bs_status bsi_tm_edges(tm_job *j)
{
    const bs_model *m = j->m;
    tm_edges *e = &j->edges;
    e->trim = calloc(m->ntrim ? m->ntrim : 1, sizeof(tm_trim));
    e->trim_face = malloc((m->ntrim ? m->ntrim : 1) * sizeof(uint32_t));
    if (e->trim == NULL || e->trim_face == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t f = 0; f < m->nface; f++)
        for (size_t l = m->faces[f].first_loop; l < m->faces[f].first_loop + m->faces[f].loop_count; l++)
            for (size_t k = 0; k < m->loops[l].trim_count; k++)
                e->trim_face[m->loops[l].first_trim + k] = (uint32_t)f;
    /* twice: the second pass grades each edge from the shortest segment the first found at its
     * ends (the model vertices are met in the same order both times) */
    bs_status st = sample_all(j);
    if (st == BS_OK)
        st = bsi_tm_grading(e);
    if (st != BS_OK)
        return st;
    e->nvert = e->nsample = e->nmodel = 0;
    memset(e->trim, 0, m->ntrim * sizeof(tm_trim));
    return sample_all(j);
}
