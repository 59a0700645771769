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

typedef struct edge_run {
    tm_job *j;
    size_t n;                   /* trims of the edge (master first) */
    size_t trim[MAX_USES];
    curve3 c[MAX_USES];
    double end[2][3];           /* the edge's ends */
    double grade[2];            /* the grading at its ends (INFINITY: none) */
    /* samples so far, in the master's order: (param on each trim, vertex) */
    double *par;                /* n per sample */
    uint32_t *vid;
    size_t ns, cap;
} edge_run;

static bs_status add_sample(edge_run *r, const double *par, uint32_t vid)
{
    if (!bsi_grow_array((void **)&r->par, &r->cap, r->ns + 1, MAX_USES * sizeof(double)))
        return BS_ERR_NO_MEMORY;
    size_t cap = r->cap;
    void *q = realloc(r->vid, cap * sizeof(uint32_t));
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    r->vid = q;
    memcpy(r->par + r->ns * MAX_USES, par, r->n * sizeof(double));
    r->vid[r->ns++] = vid;
    return BS_OK;
}

/* 1 when the interval between samples with parameters pa and pb (points Pa, Pb) is fine. */
static int interval_fine(const edge_run *r, const double *pa, const double *pb, const double *Pa,
                         const double *Pb)
{
    double half = 0.5 * r->j->tol, len = bsi_tm_dist3(Pa, Pb);
    /* graded from the ends (GRADE), so that a long straight edge meeting finely sampled curves
     * leaves no slivers there */
    if (len > GRADE * (r->grade[0] + bsi_tm_dist3(Pa, r->end[0])) ||
        len > GRADE * (r->grade[1] + bsi_tm_dist3(Pb, r->end[1])))
        return 0;
    for (int q = 1; q <= 3; q++) {
        double f = 0.25 * q, uv[2], p[3], chord[3];
        if (!bsi_tm_curve_at(&r->c[0], pa[0] + f * (pb[0] - pa[0]), uv, p))
            return 0;
        for (int k = 0; k < 3; k++)
            chord[k] = Pa[k] + f * (Pb[k] - Pa[k]);
        if (bsi_tm_dist3(p, chord) > half)
            return 0;
    }
    double mid[3];
    for (int k = 0; k < 3; k++)
        mid[k] = 0.5 * (Pa[k] + Pb[k]);
    for (size_t i = 0; i < r->n; i++) {
        double ua[2], ub[2], p[3];
        bsi_curve_eval(r->c[i].uv, pa[i], ua);
        bsi_curve_eval(r->c[i].uv, pb[i], ub);
        if (!bsi_face_point(r->j->m, r->c[i].face, 0.5 * (ua[0] + ub[0]), 0.5 * (ua[1] + ub[1]), p) ||
            bsi_tm_dist3(p, mid) > half)
            return 0;
    }
    return 1;
}

/* Sample (pa, pb] recursively; the sample at pa is already in. */
static bs_status refine(edge_run *r, const double *pa, const double *Pa, const double *pb,
                        const double *Pb, uint32_t vb, int depth, int forced)
{
    if (depth >= MAX_DEPTH || (forced <= 0 && interval_fine(r, pa, pb, Pa, Pb)))
        return add_sample(r, pb, vb);
    double pm[MAX_USES], uv[2], Pm[3];
    pm[0] = 0.5 * (pa[0] + pb[0]);
    if (!bsi_tm_curve_at(&r->c[0], pm[0], uv, Pm))
        return BS_ERR_DOMAIN;
    for (size_t i = 1; i < r->n; i++)
        pm[i] = bsi_tm_project(&r->c[i], Pm, pa[i], pb[i], 0.5 * (pa[i] + pb[i]));
    uint32_t vm;
    bs_status st = bsi_tm_new_vertex(&r->j->edges, Pm, (uint32_t)r->c[0].face, uv, &vm);
    if (st == BS_OK)
        st = refine(r, pa, Pa, pm, Pm, vm, depth + 1, forced - 1);
    if (st == BS_OK)
        st = refine(r, pm, Pm, pb, Pb, vb, depth + 1, forced - 1);
    return st;
}

/* The parameters on trim i of the master's ends: 1, or 0 when its ends are not the master's. */
static int match_ends(edge_run *r, size_t i, const double *P0, const double *P1, int closed,
                      double *s0, double *s1)
{
    const curve3 *c = &r->c[i];
    double uv[2], Q0[3], Q1[3];
    if (!bsi_tm_curve_at(c, c->t0, uv, Q0) || !bsi_tm_curve_at(c, c->t1, uv, Q1))
        return 0;
    double same = bsi_tm_dist3(Q0, P0) + bsi_tm_dist3(Q1, P1), other = bsi_tm_dist3(Q0, P1) + bsi_tm_dist3(Q1, P0);
    double slack = 10.0 * r->j->merge;
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
        if (!bsi_grow_array((void **)&e->param, &e->sample_cap, e->nsample + r->ns, sizeof(double)))
            return BS_ERR_NO_MEMORY;
        void *q = realloc(e->vid, e->sample_cap * sizeof(uint32_t));
        if (q == NULL)
            return BS_ERR_NO_MEMORY;
        e->vid = q;
        tm_trim *t = &e->trim[r->trim[i]];
        int descending = r->ns > 1 && r->par[(r->ns - 1) * MAX_USES + i] < r->par[i];
        t->first = e->nsample;
        t->count = r->ns;
        for (size_t k = 0; k < r->ns; k++) {
            size_t src = descending ? r->ns - 1 - k : k;
            e->param[e->nsample] = r->par[src * MAX_USES + i];
            e->vid[e->nsample++] = r->vid[src];
        }
    }
    return BS_OK;
}

/* Sample the edge whose trims are trims[0 .. n) (the first the master). */
static bs_status sample_edge(tm_job *j, const size_t *trims, size_t n)
{
    edge_run r;
    memset(&r, 0, sizeof r);
    r.j = j;
    bs_status st = BS_OK;
    r.n = 0;
    r.trim[r.n] = trims[0];
    bsi_tm_curve_init(&r.c[r.n++], j, trims[0]);
    const curve3 *mc = &r.c[0];
    double uv0[2], uv1[2], P0[3], P1[3];
    if (!bsi_tm_curve_at(mc, mc->t0, uv0, P0) || !bsi_tm_curve_at(mc, mc->t1, uv1, P1))
        return BS_ERR_DOMAIN;
    int closed = bsi_tm_dist3(P0, P1) <= j->merge;
    double par0[MAX_USES] = {0.0}, par1[MAX_USES] = {0.0};
    par0[0] = mc->t0;
    par1[0] = mc->t1;
    /* the other trims whose ends match; those that do not are sampled on their own */
    size_t alone[MAX_USES * 4];
    size_t nalone = 0;
    for (size_t k = 1; k < n; k++) {
        if (r.n == MAX_USES) {
            if (nalone < sizeof alone / sizeof alone[0])
                alone[nalone++] = trims[k];
            continue;
        }
        bsi_tm_curve_init(&r.c[r.n], j, trims[k]);
        double s0, s1;
        if (match_ends(&r, r.n, P0, P1, closed, &s0, &s1)) {
            r.trim[r.n] = trims[k];
            par0[r.n] = s0;
            par1[r.n] = s1;
            r.n++;
        } else if (nalone < sizeof alone / sizeof alone[0]) {
            alone[nalone++] = trims[k];
        }
    }
    uint32_t v0 = TM_NONE, v1 = TM_NONE;
    st = bsi_tm_model_vertex(j, P0, (uint32_t)mc->face, uv0, &v0, &r.grade[0]);
    if (st == BS_OK)
        st = bsi_tm_model_vertex(j, P1, (uint32_t)mc->face, uv1, &v1, &r.grade[1]);
    memcpy(r.end[0], P0, sizeof r.end[0]);
    memcpy(r.end[1], P1, sizeof r.end[1]);
    if (st == BS_OK)
        st = add_sample(&r, par0, v0);
    /* start from the master's Bezier segments, each halved at least once (twice for a closed
     * edge of one segment, so that it is never a two-gon) */
    const bsi_axis *ax = &mc->uv->axis;
    int forced = closed && ax->n < 2 ? 2 : 1;
    double pa[MAX_USES], Pa[3];
    memcpy(pa, par0, sizeof pa);
    memcpy(Pa, P0, sizeof Pa);
    for (size_t s = 1; s <= ax->n && st == BS_OK; s++) {
        double pb[MAX_USES], Pb[3], uv[2];
        uint32_t vb = v1;
        if (s == ax->n) {
            memcpy(pb, par1, sizeof pb);
            memcpy(Pb, P1, sizeof Pb);
        } else {
            pb[0] = ax->breaks[s];
            if (!bsi_tm_curve_at(mc, pb[0], uv, Pb)) {
                st = BS_ERR_DOMAIN;
                break;
            }
            for (size_t i = 1; i < r.n; i++)
                pb[i] = bsi_tm_project(&r.c[i], Pb, pa[i], par1[i],
                                       pa[i] + (par1[i] - pa[i]) * (pb[0] - pa[0]) / (par1[0] - pa[0]));
            st = bsi_tm_new_vertex(&j->edges, Pb, (uint32_t)mc->face, uv, &vb);
        }
        if (st == BS_OK)
            st = refine(&r, pa, Pa, pb, Pb, vb, 0, forced);
        memcpy(pa, pb, sizeof pa);
        memcpy(Pa, Pb, sizeof Pa);
    }
    if (st == BS_OK)
        st = store(j, &r);
    free(r.par);
    free(r.vid);
    for (size_t k = 0; k < nalone && st == BS_OK; k++)
        st = sample_edge(j, &alone[k], 1);
    return st;
}

void bsi_tm_edges_free(tm_edges *e)
{
    free(e->vert);
    free(e->param);
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
        st = sample_edge(j, group, n);
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
