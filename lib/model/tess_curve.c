/*
 * Tessellation, edge phase: trims carried onto their faces as 3-D curves (tess_edge.h), and the
 * vertices the phase makes.
 */
#include "model/tess_edge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PROJECT_STEPS 12

double bsi_tm_dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* The trim's (u, v) at t, and its point on the face (0 when off the face). */
int bsi_tm_curve_at(const curve3 *c, double t, double *uv, double *p)
{
    bsi_curve_eval(c->uv, t, uv);
    return bsi_face_point(c->m, c->face, uv[0], uv[1], p);
}

void bsi_tm_curve_init(curve3 *c, const tm_job *j, size_t t)
{
    c->m = j->m;
    c->uv = &j->m->trims[t].uv;
    c->face = j->edges.trim_face[t];
    c->t0 = c->uv->axis.breaks[0];
    c->t1 = c->uv->axis.breaks[c->uv->axis.n];
}

/* The parameter in [lo, hi] (either order) of c's point nearest p, from guess. */
double bsi_tm_project(const curve3 *c, const double *p, double lo, double hi, double guess)
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
        double sa = s - h < c->t0 ? c->t0 : s - h, sb = s + h > c->t1 ? c->t1 : s + h;
        if (!bsi_tm_curve_at(c, s, uv, q) || !bsi_tm_curve_at(c, sa, uv, qa) || !bsi_tm_curve_at(c, sb, uv, qb) || sb <= sa)
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

/* A model vertex at p: an existing one within merge, else a new one. */
bs_status bsi_tm_model_vertex(tm_job *j, const double *p, uint32_t face, const double *uv, uint32_t *id,
                              double *grade)
{
    tm_edges *e = &j->edges;
    for (size_t k = 0; k < e->nmodel; k++)
        if (bsi_tm_dist3(e->vert[e->model[k]].p, p) <= j->merge) {
            *id = e->model[k];
            *grade = e->grade != NULL ? e->grade[k] : INFINITY;
            return BS_OK;
        }
    if (!bsi_grow_array((void **)&e->model, &e->model_cap, e->nmodel + 1, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    bs_status st = bsi_tm_new_vertex(e, p, face, uv, id);
    *grade = e->grade != NULL ? e->grade[e->nmodel] : INFINITY;
    if (st == BS_OK)
        e->model[e->nmodel++] = *id;
    return st;
}

bs_status bsi_tm_new_vertex(tm_edges *e, const double *p, uint32_t face, const double *uv, uint32_t *id)
{
    if (e->nvert >= TM_INNER - 1)
        return BS_ERR_SIZE;
    if (!bsi_grow_array((void **)&e->vert, &e->vert_cap, e->nvert + 1, sizeof(tm_vertex)))
        return BS_ERR_NO_MEMORY;
    tm_vertex *v = &e->vert[e->nvert];
    memcpy(v->p, p, sizeof v->p);
    v->face = face;
    v->uv[0] = uv[0];
    v->uv[1] = uv[1];
    *id = (uint32_t)e->nvert++;
    return BS_OK;
}
