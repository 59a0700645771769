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
#include "model/tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 24
/* Segments near an edge's end: at most GRADE times (the shortest segment there + the distance
 * from the end); 4 halves the slivers' count at a quarter more triangles than none (the bottle). */
#define GRADE 4.0
#define PROJECT_STEPS 12
#define COARSE 64          /* samples of a trim when telling the direction of a closed edge */
#define MAX_POLE_SAMPLES 4096
#define MAX_BREAKS 1024 /* a master's segment breaks that start intervals (more are left to refine) */

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 1;
    size_t n = *cap ? *cap : 64;
    while (n < need)
        n *= 2;
    void *q = realloc(*p, n * size);
    if (q == NULL)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

double bsi_tm_dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

typedef struct curve3 {
    const bs_model *m;
    size_t face;
    const bsi_curve *uv;
    double t0, t1;     /* the trim's range */
    double lo, hi;     /* the range of the parameters used: [t0, t1], or a turn from another start */
    int wrap;          /* parameters past t1 (before t0) are a turn later (earlier): a closed trim
                          walked from another point than its own start */
} curve3;

/* The trim's own parameter of t. */
static double actual(const curve3 *c, double t)
{
    if (c->wrap && t > c->t1)
        return t - (c->t1 - c->t0);
    if (c->wrap && t < c->t0)
        return t + (c->t1 - c->t0);
    return t;
}

/* The trim's own parameter of an end of the interval from a to b (end 0: a, 1: b): at the seam
 * of a wrapped trim, the interval's side of it (its (u, v) may differ there by a period). */
static double interval_end(const curve3 *c, double a, double b, int end)
{
    double t = end ? b : a;
    if (!c->wrap)
        return t;
    int up = a < b;
    if (t == (up ? c->t1 : c->t0))
        return end ? t : (up ? c->t0 : c->t1); /* the start of an interval leaving the seam */
    return actual(c, t);
}

/* The trim's (u, v) at t, and its point on the face (0 when off the face). */
static int curve_at(const curve3 *c, double t, double *uv, double *p)
{
    bsi_curve_eval(c->uv, actual(c, t), uv);
    return bsi_face_point(c->m, c->face, uv[0], uv[1], p);
}

static void curve_init(curve3 *c, const tm_job *j, size_t t)
{
    c->m = j->m;
    c->uv = &j->m->trims[t].uv;
    c->face = j->edges.trim_face[t];
    c->t0 = c->uv->axis.breaks[0];
    c->t1 = c->uv->axis.breaks[c->uv->axis.n];
    c->lo = c->t0;
    c->hi = c->t1;
    c->wrap = 0;
}

/* The parameter in [lo, hi] (either order) of c's point nearest p, from guess. */
static double project(const curve3 *c, const double *p, double lo, double hi, double guess)
{
    if (lo > hi) {
        double s = lo;
        lo = hi;
        hi = s;
    }
    double s = guess < lo ? lo : guess > hi ? hi : guess;
    double h = 1e-7 * (c->t1 - c->t0);
    for (int it = 0; it < PROJECT_STEPS; it++) {
        double uv[2], q[3], qa[3], qb[3];
        double sa = s - h < c->lo ? c->lo : s - h, sb = s + h > c->hi ? c->hi : s + h;
        if (!curve_at(c, s, uv, q) || !curve_at(c, sa, uv, qa) || !curve_at(c, sb, uv, qb) || sb <= sa)
            break;
        double d[3], num = 0.0, den = 0.0;
        for (int k = 0; k < 3; k++) {
            d[k] = (qb[k] - qa[k]) / (sb - sa);
            num += (q[k] - p[k]) * d[k];
            den += d[k] * d[k];
        }
        if (!(den > 0.0))
            break;
        double step = num / den, next = s - step;
        next = next < lo ? lo : next > hi ? hi : next;
        if (fabs(next - s) <= 1e-15 * (c->t1 - c->t0 + fabs(s))) {
            s = next;
            break;
        }
        s = next;
    }
    return s;
}

static bs_status new_vertex(tm_edges *e, const double *p, uint32_t face, const double *uv, uint32_t *id);

/* A model vertex at p: an existing one within merge, else a new one. */
static bs_status model_vertex(tm_job *j, const double *p, uint32_t face, const double *uv, uint32_t *id,
                              double *grade)
{
    tm_edges *e = &j->edges;
    for (size_t k = 0; k < e->nmodel; k++)
        if (bsi_tm_dist3(e->vert[e->model[k]].p, p) <= j->merge) {
            *id = e->model[k];
            *grade = e->grade != NULL ? e->grade[k] : INFINITY;
            return BS_OK;
        }
    if (!grow((void **)&e->model, &e->model_cap, e->nmodel + 1, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    bs_status st = new_vertex(e, p, face, uv, id);
    *grade = e->grade != NULL ? e->grade[e->nmodel] : INFINITY;
    if (st == BS_OK)
        e->model[e->nmodel++] = *id;
    return st;
}

static bs_status new_vertex(tm_edges *e, const double *p, uint32_t face, const double *uv, uint32_t *id)
{
    if (e->nvert >= TM_INNER - 1)
        return BS_ERR_SIZE;
    if (!grow((void **)&e->vert, &e->vert_cap, e->nvert + 1, sizeof(tm_vertex)))
        return BS_ERR_NO_MEMORY;
    tm_vertex *v = &e->vert[e->nvert];
    memcpy(v->p, p, sizeof v->p);
    v->face = face;
    v->uv[0] = uv[0];
    v->uv[1] = uv[1];
    *id = (uint32_t)e->nvert++;
    return BS_OK;
}

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
    if (!grow((void **)&r->par, &r->cap, r->ns + 1, MAX_USES * sizeof(double)))
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
        if (!curve_at(&r->c[0], pa[0] + f * (pb[0] - pa[0]), uv, p))
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
        bsi_curve_eval(r->c[i].uv, interval_end(&r->c[i], pa[i], pb[i], 0), ua);
        bsi_curve_eval(r->c[i].uv, interval_end(&r->c[i], pa[i], pb[i], 1), ub);
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
    if (!curve_at(&r->c[0], pm[0], uv, Pm))
        return BS_ERR_DOMAIN;
    for (size_t i = 1; i < r->n; i++)
        pm[i] = project(&r->c[i], Pm, pa[i], pb[i], 0.5 * (pa[i] + pb[i]));
    uint32_t vm;
    bs_status st = new_vertex(&r->j->edges, Pm, (uint32_t)r->c[0].face, uv, &vm);
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
    if (!curve_at(c, c->t0, uv, Q0) || !curve_at(c, c->t1, uv, Q1))
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
        if (!curve_at(m, m->t0 + 0.25 * (m->t1 - m->t0), uv, P))
            return 0;
        for (int k = 0; k <= COARSE; k++) {
            double t = c->t0 + (c->t1 - c->t0) * k / COARSE, Q[3];
            if (curve_at(c, t, uv, Q) && bsi_tm_dist3(Q, P) < best) {
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

/* The parameter in [lo, hi] of c's point nearest p: the nearest of COARSE samples, polished. */
static double nearest(const curve3 *c, const double *p, double lo, double hi)
{
    double best = INFINITY, at = lo, step = (hi - lo) / COARSE, uv[2], q[3];
    for (int k = 0; k <= COARSE; k++) {
        double t = lo + step * k;
        if (curve_at(c, t, uv, q) && bsi_tm_dist3(q, p) < best) {
            best = bsi_tm_dist3(q, p);
            at = t;
        }
    }
    double t = project(c, p, at - step < lo ? lo : at - step, at + step > hi ? hi : at + step, at);
    if (at == lo || at == hi) {
        /* the ends of a closed curve are one point: the nearest may lie just inside the other */
        double other = at == lo ? hi : lo;
        double u = project(c, p, other == lo ? lo : hi - step, other == lo ? lo + step : hi, other);
        double qt[3], qu[3];
        if (curve_at(c, u, uv, qu) && (!curve_at(c, t, uv, qt) || bsi_tm_dist3(qu, p) < bsi_tm_dist3(qt, p)))
            t = u;
    }
    return t;
}

/* A closed trim i that starts elsewhere on the closed master edge (files put a circle's seam
 * where they like): walked a whole turn from the master's start, *s0 .. *s1, its parameters past
 * its own end wrapping around. Its own start must be a sample too: *seam_master is the master's
 * parameter there, *seam the trim's. 1, or 0 when the trim does not lie along the master. */
static int match_rotated(edge_run *r, size_t i, const double *P0, double *s0, double *s1,
                         double *seam_master, double *seam)
{
    curve3 *c = &r->c[i];
    const curve3 *mc = &r->c[0];
    double len = c->t1 - c->t0, slack = 10.0 * r->j->merge, uv[2], Q[3], P[3], Qs[3], Pq[3];
    double star = nearest(c, P0, c->t0, c->t1);
    if (!curve_at(c, star, uv, Q) || bsi_tm_dist3(Q, P0) > slack ||
        !curve_at(mc, mc->t0 + 0.25 * (mc->t1 - mc->t0), uv, P) || !curve_at(c, c->t0, uv, Qs))
        return 0;
    double d = nearest(c, P, c->t0, c->t1) - star;
    int forward = (d < 0.0 ? d + len : d) < 0.5 * len;
    double tq = nearest(mc, Qs, mc->t0, mc->t1);
    if (!curve_at(mc, tq, uv, Pq) || bsi_tm_dist3(Pq, Qs) > slack || tq <= mc->t0 || tq >= mc->t1)
        return 0;
    c->wrap = 1;
    *s0 = star;
    *s1 = forward ? star + len : star - len;
    c->lo = fmin(*s0, *s1);
    c->hi = fmax(*s0, *s1);
    *seam_master = tq;
    *seam = forward ? c->t1 : c->t0;
    return 1;
}

typedef struct param_vid {
    double t;
    uint32_t vid;
} param_vid;

static int cmp_param(const void *a, const void *b)
{
    double x = ((const param_vid *)a)->t, y = ((const param_vid *)b)->t;
    return (x > y) - (x < y);
}

/* A wrapped trim's samples in its own parameters, ascending, its seam sample at both ends. */
static bs_status store_wrapped(tm_edges *e, const edge_run *r, size_t i, tm_trim *t)
{
    size_t n = r->ns - 1; /* the master's last sample is its first again */
    param_vid *pv = malloc((n + 1) * sizeof(param_vid));
    if (pv == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < n; k++) {
        pv[k].t = actual(&r->c[i], r->par[k * MAX_USES + i]);
        pv[k].vid = r->vid[k];
    }
    qsort(pv, n, sizeof(param_vid), cmp_param);
    t->first = e->nsample;
    t->count = n + 1;
    const curve3 *c = &r->c[i];
    int seam_last = pv[n - 1].t >= c->t1; /* else the seam is first, at t0 */
    if (!seam_last) {
        e->param[e->nsample] = c->t0;
        e->vid[e->nsample++] = pv[0].vid;
    } else {
        e->param[e->nsample] = c->t0;
        e->vid[e->nsample++] = pv[n - 1].vid;
    }
    for (size_t k = seam_last ? 0 : 1; k < (seam_last ? n - 1 : n); k++) {
        e->param[e->nsample] = pv[k].t;
        e->vid[e->nsample++] = pv[k].vid;
    }
    e->param[e->nsample] = c->t1;
    e->vid[e->nsample++] = seam_last ? pv[n - 1].vid : pv[0].vid;
    free(pv);
    return BS_OK;
}

/* Store the run's samples into each of its trims, ascending in the trim's own parameter. */
static bs_status store(tm_job *j, edge_run *r)
{
    tm_edges *e = &j->edges;
    for (size_t i = 0; i < r->n; i++) {
        if (!grow((void **)&e->param, &e->sample_cap, e->nsample + r->ns, sizeof(double)))
            return BS_ERR_NO_MEMORY;
        void *q = realloc(e->vid, e->sample_cap * sizeof(uint32_t));
        if (q == NULL)
            return BS_ERR_NO_MEMORY;
        e->vid = q;
        tm_trim *t = &e->trim[r->trim[i]];
        if (r->c[i].wrap) {
            bs_status st = store_wrapped(e, r, i, t);
            if (st != BS_OK)
                return st;
            continue;
        }
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

/* A trim whose image is one point: uniform samples in its parameter, all that point. */
static bs_status sample_pole(tm_job *j, size_t t, const double *P)
{
    const bs_model *m = j->m;
    curve3 c;
    curve_init(&c, j, t);
    double a[2], b[2];
    bsi_curve_eval(c.uv, c.t0, a);
    bsi_curve_eval(c.uv, c.t1, b);
    const tm_face_scale *s = &j->scale[c.face];
    double len = hypot((b[0] - a[0]) * s->su, (b[1] - a[1]) * s->sv);
    /* as fine as the face's other boundary samples, measured in its metric: the mean spacing
     * of the samples made so far on the same face */
    double spacing = 0.0;
    size_t count = 0;
    const bsi_face *f = &m->faces[c.face];
    for (size_t l = f->first_loop; l < f->first_loop + f->loop_count; l++)
        for (size_t k = m->loops[l].first_trim; k < m->loops[l].first_trim + m->loops[l].trim_count; k++) {
            const tm_trim *o = &j->edges.trim[k];
            if (o->pole || o->count < 2)
                continue;
            for (size_t q = 0; q + 1 < o->count; q++) {
                double u0[2], u1[2];
                bsi_curve_eval(&m->trims[k].uv, j->edges.param[o->first + q], u0);
                bsi_curve_eval(&m->trims[k].uv, j->edges.param[o->first + q + 1], u1);
                spacing += hypot((u1[0] - u0[0]) * s->su, (u1[1] - u0[1]) * s->sv);
                count++;
            }
        }
    size_t n = 4;
    if (count > 0 && spacing > 0.0) {
        double want = ceil(len / (spacing / (double)count));
        n = want > MAX_POLE_SAMPLES ? MAX_POLE_SAMPLES : want < 4.0 ? 4 : (size_t)want;
    }
    uint32_t vid;
    double grade;
    bs_status st = model_vertex(j, P, (uint32_t)c.face, a, &vid, &grade);
    if (st != BS_OK)
        return st;
    tm_edges *e = &j->edges;
    if (!grow((void **)&e->param, &e->sample_cap, e->nsample + n + 1, sizeof(double)))
        return BS_ERR_NO_MEMORY;
    void *q = realloc(e->vid, e->sample_cap * sizeof(uint32_t));
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    e->vid = q;
    e->trim[t].first = e->nsample;
    e->trim[t].count = n + 1;
    e->trim[t].pole = 1;
    for (size_t k = 0; k <= n; k++) {
        e->param[e->nsample] = k == n ? c.t1 : c.t0 + (c.t1 - c.t0) * (double)k / (double)n;
        e->vid[e->nsample++] = vid;
    }
    return BS_OK;
}

/* 1 when trim t's image is within merge of one point P. */
static int is_pole(const tm_job *j, size_t t, double *P)
{
    curve3 c;
    curve_init(&c, j, t);
    double uv[2], Q[3];
    if (!curve_at(&c, c.t0, uv, P))
        return 0;
    for (int k = 1; k <= 16; k++)
        if (!curve_at(&c, c.t0 + (c.t1 - c.t0) * k / 16.0, uv, Q) || bsi_tm_dist3(Q, P) > j->merge)
            return 0;
    return 1;
}

/* A master parameter where a sample must be: a break of its segments (trim 0), or where closed
 * trim `trim` that starts elsewhere starts (its parameter there: seam). */
typedef struct edge_stop {
    double t, seam;
    size_t trim;
} edge_stop;

/* Sample the edge whose trims are trims[0 .. n) (the first the master). */
static bs_status sample_edge(tm_job *j, const size_t *trims, size_t n)
{
    edge_run r;
    memset(&r, 0, sizeof r);
    r.j = j;
    bs_status st = BS_OK;
    r.n = 0;
    r.trim[r.n] = trims[0];
    curve_init(&r.c[r.n++], j, trims[0]);
    const curve3 *mc = &r.c[0];
    double uv0[2], uv1[2], P0[3], P1[3];
    if (!curve_at(mc, mc->t0, uv0, P0) || !curve_at(mc, mc->t1, uv1, P1))
        return BS_ERR_DOMAIN;
    int closed = bsi_tm_dist3(P0, P1) <= j->merge;
    double par0[MAX_USES], par1[MAX_USES];
    par0[0] = mc->t0;
    par1[0] = mc->t1;
    /* the other trims whose ends match; those that do not are sampled on their own. stop[]: the
     * master's parameters where a sample must be (its segments' breaks, and the starts of closed
     * trims that start elsewhere: on those, the trim's parameter there is `seam`) */
    edge_stop stop[MAX_USES + MAX_BREAKS];
    size_t nstop = 0;
    size_t alone[MAX_USES * 4];
    size_t nalone = 0;
    for (size_t k = 1; k < n; k++) {
        if (r.n == MAX_USES) {
            if (nalone < sizeof alone / sizeof alone[0])
                alone[nalone++] = trims[k];
            continue;
        }
        curve_init(&r.c[r.n], j, trims[k]);
        double s0, s1;
        if (match_ends(&r, r.n, P0, P1, closed, &s0, &s1) ||
            (closed && match_rotated(&r, r.n, P0, &s0, &s1, &stop[nstop].t, &stop[nstop].seam))) {
            if (r.c[r.n].wrap)
                stop[nstop++].trim = r.n;
            r.trim[r.n] = trims[k];
            par0[r.n] = s0;
            par1[r.n] = s1;
            r.n++;
        } else if (nalone < sizeof alone / sizeof alone[0]) {
            alone[nalone++] = trims[k];
        }
    }
    uint32_t v0, v1;
    st = model_vertex(j, P0, (uint32_t)mc->face, uv0, &v0, &r.grade[0]);
    if (st == BS_OK)
        st = model_vertex(j, P1, (uint32_t)mc->face, uv1, &v1, &r.grade[1]);
    memcpy(r.end[0], P0, sizeof r.end[0]);
    memcpy(r.end[1], P1, sizeof r.end[1]);
    if (st == BS_OK)
        st = add_sample(&r, par0, v0);
    /* start from the master's Bezier segments, each halved at least once (twice for a closed
     * edge of one segment, so that it is never a two-gon) */
    const bsi_axis *ax = &mc->uv->axis;
    int forced = closed && ax->n < 2 ? 2 : 1;
    for (size_t b = 1; b < ax->n && nstop < sizeof stop / sizeof stop[0]; b++) {
        stop[nstop].t = ax->breaks[b];
        stop[nstop++].trim = 0;
    }
    for (size_t a = 1; a < nstop; a++) /* ascending (insertion: a few stops) */
        for (size_t b = a; b > 0 && stop[b].t < stop[b - 1].t; b--) {
            edge_stop x = stop[b];
            stop[b] = stop[b - 1];
            stop[b - 1] = x;
        }
    double pa[MAX_USES], Pa[3];
    memcpy(pa, par0, sizeof pa);
    memcpy(Pa, P0, sizeof Pa);
    for (size_t s = 0; s <= nstop && st == BS_OK; s++) {
        double pb[MAX_USES], Pb[3], uv[2];
        uint32_t vb = v1;
        if (s == nstop) {
            memcpy(pb, par1, sizeof pb);
            memcpy(Pb, P1, sizeof Pb);
        } else {
            pb[0] = stop[s].t;
            if (!curve_at(mc, pb[0], uv, Pb)) {
                st = BS_ERR_DOMAIN;
                break;
            }
            for (size_t i = 1; i < r.n; i++)
                pb[i] = i == stop[s].trim ? stop[s].seam
                                          : project(&r.c[i], Pb, pa[i], par1[i],
                                                    pa[i] + (par1[i] - pa[i]) * (pb[0] - pa[0]) / (par1[0] - pa[0]));
            st = new_vertex(&j->edges, Pb, (uint32_t)mc->face, uv, &vb);
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
        pole[t] = (unsigned char)is_pole(j, t, pole_at + 3 * t);
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
            st = sample_pole(j, t, pole_at + 3 * t);
done:
    free(next);
    free(head);
    free(group);
    free(pole);
    free(pole_at);
    return st;
}

/* The grading of each model vertex from the first pass: its shortest segment. */
static bs_status grading(tm_edges *e)
{
    uint32_t *ordinal = malloc((e->nvert ? e->nvert : 1) * sizeof(uint32_t));
    double *grade = malloc((e->nmodel ? e->nmodel : 1) * sizeof(double));
    if (ordinal == NULL || grade == NULL) {
        free(ordinal);
        free(grade);
        return BS_ERR_NO_MEMORY;
    }
    for (size_t v = 0; v < e->nvert; v++)
        ordinal[v] = TM_NONE;
    for (size_t k = 0; k < e->nmodel; k++) {
        ordinal[e->model[k]] = (uint32_t)k;
        grade[k] = INFINITY;
    }
    for (size_t s = 0; s + 1 < e->nsample; s++) {
        uint32_t a = e->vid[s], b = e->vid[s + 1];
        double len = bsi_tm_dist3(e->vert[a].p, e->vert[b].p);
        if (!(len > 0.0))
            continue; /* across two trims' lists, or along a pole */
        if (ordinal[a] != TM_NONE && len < grade[ordinal[a]])
            grade[ordinal[a]] = len;
        if (ordinal[b] != TM_NONE && len < grade[ordinal[b]])
            grade[ordinal[b]] = len;
    }
    free(ordinal);
    e->grade = grade;
    return BS_OK;
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
        st = grading(e);
    if (st != BS_OK)
        return st;
    e->nvert = e->nsample = e->nmodel = 0;
    memset(e->trim, 0, m->ntrim * sizeof(tm_trim));
    return sample_all(j);
}
