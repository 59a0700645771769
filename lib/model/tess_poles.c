/*
 * Tessellation, edge phase: trims whose image is a point (the poles of spheres and cones), and
 * the grading of the second pass (tess_edge.h).
 */
#include "model/tess_edge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_POLE_SAMPLES 4096

/* A trim whose image is one point: uniform samples in its parameter, all that point. */
bs_status bsi_tm_sample_pole(tm_job *j, size_t t, const double *P)
{
    const bs_model *m = j->m;
    curve3 c;
    bsi_tm_curve_init(&c, j, t);
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
                const double *u0 = j->edges.uv + 2 * (o->first + q), *u1 = u0 + 2;
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
    bs_status st = bsi_tm_model_vertex(j, P, (uint32_t)c.face, a, &vid, &grade);
    if (st != BS_OK)
        return st;
    tm_edges *e = &j->edges;
    if (!bsi_grow_array((void **)&e->uv, &e->sample_cap, e->nsample + n + 1, 2 * sizeof(double)))
        return BS_ERR_NO_MEMORY;
    void *q = realloc(e->vid, e->sample_cap * sizeof(uint32_t));
    if (q == NULL)
        return BS_ERR_NO_MEMORY;
    e->vid = q;
    e->trim[t].first = e->nsample;
    e->trim[t].count = n + 1;
    e->trim[t].pole = 1;
    for (size_t k = 0; k <= n; k++) {
        bsi_curve_eval(c.uv, k == n ? c.t1 : c.t0 + (c.t1 - c.t0) * (double)k / (double)n, e->uv + 2 * e->nsample);
        e->vid[e->nsample++] = vid;
    }
    return BS_OK;
}

/* 1 when trim t's image is within merge of one point P. */
int bsi_tm_is_pole(const tm_job *j, size_t t, double *P)
{
    curve3 c;
    bsi_tm_curve_init(&c, j, t);
    double uv[2], Q[3];
    if (!bsi_tm_curve_at(&c, c.t0, uv, P))
        return 0;
    for (int k = 1; k <= 16; k++)
        if (!bsi_tm_curve_at(&c, c.t0 + (c.t1 - c.t0) * k / 16.0, uv, Q) || bsi_tm_dist3(Q, P) > j->merge)
            return 0;
    return 1;
}

/* The grading of each model vertex from the first pass: its shortest segment. */
bs_status bsi_tm_grading(tm_edges *e)
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
