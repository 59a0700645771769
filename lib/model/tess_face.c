/*
 * Tessellation phase 2 (tess.h): one face triangulated in its native parameters.
 *
 * The metric: native (u, v) scaled by the face's mean |S_u| and |S_v|, so that lengths and angles
 * in the plane are close to those on the surface (exactly so on planes, cylinders and cones along
 * their rulings). The trim loops' samples (tess_edges.c) are the constrained edges of a Delaunay
 * triangulation in that metric (cdt.c), rounded onto an integer grid of 2^29 steps across the
 * face for exact orientation tests; the triangles inside the loops are kept.
 *
 * Refinement. A triangle whose corners have native parameters x_i and points P_i errs at
 * barycentric l by E(l) = S(sum l_i x_i) - sum l_i P_i. Where S is its second-order Taylor
 * polynomial, E(l) = sum_{i<j} l_i l_j q_ij with q_ij = -(1/2) H[x_i - x_j, x_i - x_j], so that
 * the error at the middle of side ij is q_ij / 4 and |E| <= max |q_ij| / 3 everywhere: the largest
 * side-middle error times 4/3 is the estimate, taken together with the error at the centroid. A
 * triangle above the tolerance gets a point at its circumcentre (or, where that is outside the
 * domain or across a constraint, at its centroid); a triangle with a corner angle below 20
 * degrees in the metric gets its circumcentre too, within a budget, where that lands inside.
 */
#include "model/cdt.h"
#include "model/tess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MIN_ANGLE_DEG 20.0
#define PI 3.14159265358979323846
#define MAX_PASSES 256

void bsi_tm_face_free(tm_face_mesh *fm)
{
    free(fm->tri);
    free(fm->tuv);
    free(fm->inner);
    memset(fm, 0, sizeof *fm);
}

/* A point of the triangulation: native (u, v), 3-D point, edge-phase vertex (TM_NONE: inner). */
typedef struct fpoint {
    double uv[2], p[3];
    uint32_t vid;
} fpoint;

typedef struct face_run {
    tm_job *j;
    size_t f;
    double su, sv;         /* the metric */
    double cx, cy, k;      /* metric -> grid: (x - cx) * k */
    bsi_cdt cdt;
    fpoint *pt;            /* per cdt point */
    size_t pt_cap;
} face_run;

static bs_status put_point(face_run *r, uint32_t id, const double *uv, const double *p, uint32_t vid)
{
    if (id >= r->pt_cap) {
        size_t n = r->pt_cap ? r->pt_cap : 256;
        while (n <= id)
            n *= 2;
        fpoint *q = realloc(r->pt, n * sizeof(fpoint));
        if (q == NULL)
            return BS_ERR_NO_MEMORY;
        r->pt = q;
        r->pt_cap = n;
    }
    fpoint *fp = &r->pt[id];
    fp->uv[0] = uv[0];
    fp->uv[1] = uv[1];
    memcpy(fp->p, p, sizeof fp->p);
    fp->vid = vid;
    return BS_OK;
}

static int64_t to_grid(double x, double c, double k)
{
    double g = (x - c) * k;
    if (!(fabs(g) <= (double)BSI_CDT_RANGE))
        return INT64_MAX;
    return (int64_t)llround(g);
}

/* ---- The loops ---- */

typedef struct loop_pt {
    double uv[2];
    uint32_t vid;
} loop_pt;

/* 1 when two loop points are one vertex less than 1e-6 of the face's box apart in the metric. */
static int same_place(const tm_job *j, size_t f, const loop_pt *a, const loop_pt *b)
{
    const bsi_face *face = &j->m->faces[f];
    const tm_face_scale *s = &j->scale[f];
    double size = hypot((face->box[1] - face->box[0]) * s->su, (face->box[3] - face->box[2]) * s->sv);
    return a->vid == b->vid && hypot((a->uv[0] - b->uv[0]) * s->su, (a->uv[1] - b->uv[1]) * s->sv) <= 1e-6 * size;
}

/* The points of face f's loops in order, each loop closed implicitly; loop l is
 * pts[start[l] .. start[l+1]). */
static bs_status gather_loops(const tm_job *j, size_t f, loop_pt **pts_out, size_t **start_out)
{
    const bs_model *m = j->m;
    const bsi_face *face = &m->faces[f];
    size_t n = 0;
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++)
        for (size_t k = 0; k < m->loops[l].trim_count; k++)
            n += j->edges.trim[m->loops[l].first_trim + k].count;
    loop_pt *pts = malloc((n ? n : 1) * sizeof(loop_pt));
    size_t *start = malloc((face->loop_count + 1) * sizeof(size_t));
    if (pts == NULL || start == NULL) {
        free(pts);
        free(start);
        return BS_ERR_NO_MEMORY;
    }
    size_t np = 0;
    for (size_t l = 0; l < face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[face->first_loop + l];
        start[l] = np;
        for (size_t k = 0; k < loop->trim_count; k++) {
            size_t t = loop->first_trim + k;
            const tm_trim *tt = &j->edges.trim[t];
            int rev = m->trims[t].reversed;
            for (size_t s = 0; s + 1 < tt->count; s++) {
                size_t at = tt->first + (rev ? tt->count - 1 - s : s);
                pts[np].uv[0] = j->edges.uv[2 * at];
                pts[np].uv[1] = j->edges.uv[2 * at + 1];
                pts[np].vid = j->edges.vid[at];
                /* one vertex met again at (nearly) the same place, as across a trim of no length
                 * or the small gap a file leaves between a trim's end and the next one's start:
                 * once is enough, and twice would fold the loop on itself */
                if (np > start[l] && same_place(j, f, &pts[np - 1], &pts[np]))
                    continue;
                np++;
            }
        }
        while (np > start[l] + 1 && same_place(j, f, &pts[start[l]], &pts[np - 1]))
            np--;
    }
    start[face->loop_count] = np;
    *pts_out = pts;
    *start_out = start;
    return BS_OK;
}

/* ---- Assessment ---- */

/* The error estimate of the triangle (module comment); INFINITY where the surface cannot be
 * evaluated. */
static double triangle_error(const face_run *r, const fpoint *const *c)
{
    double worst_side = 0.0;
    for (int i = 0; i < 3; i++) {
        const fpoint *a = c[i], *b = c[(i + 1) % 3];
        double p[3], mid[3];
        if (!bsi_face_point(r->j->m, r->f, 0.5 * (a->uv[0] + b->uv[0]), 0.5 * (a->uv[1] + b->uv[1]), p))
            return INFINITY;
        for (int k = 0; k < 3; k++)
            mid[k] = 0.5 * (a->p[k] + b->p[k]);
        double e = bsi_tm_dist3(p, mid);
        worst_side = e > worst_side ? e : worst_side;
    }
    double p[3], cen[3];
    if (!bsi_face_point(r->j->m, r->f, (c[0]->uv[0] + c[1]->uv[0] + c[2]->uv[0]) / 3.0,
                        (c[0]->uv[1] + c[1]->uv[1] + c[2]->uv[1]) / 3.0, p))
        return INFINITY;
    for (int k = 0; k < 3; k++)
        cen[k] = (c[0]->p[k] + c[1]->p[k] + c[2]->p[k]) / 3.0;
    double e = bsi_tm_dist3(p, cen), est = worst_side * (4.0 / 3.0);
    return e > est ? e : est;
}

/* Smallest corner angle of the triangle in the metric (radians). */
static double triangle_min_angle(const face_run *r, const fpoint *const *c)
{
    double best = PI;
    for (int i = 0; i < 3; i++) {
        const fpoint *a = c[i], *b = c[(i + 1) % 3], *d = c[(i + 2) % 3];
        double ux = (b->uv[0] - a->uv[0]) * r->su, uy = (b->uv[1] - a->uv[1]) * r->sv;
        double vx = (d->uv[0] - a->uv[0]) * r->su, vy = (d->uv[1] - a->uv[1]) * r->sv;
        double ang = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
        best = ang < best ? ang : best;
    }
    return best;
}

/* ---- Refinement ---- */

typedef struct cand {
    uint32_t t, v[3];
    int kind; /* 1: error, 2: shape */
} cand;

/* Insert the point at metric (x, y) from triangle hint: 1 added, 0 not. */
static bs_status try_point(face_run *r, double x, double y, uint32_t hint, int *added)
{
    *added = 0;
    int64_t gx = to_grid(x, r->cx, r->k), gy = to_grid(y, r->cy, r->k);
    if (gx == INT64_MAX || gy == INT64_MAX)
        return BS_OK;
    double uv[2] = {((double)gx / r->k + r->cx) / r->su, ((double)gy / r->k + r->cy) / r->sv}, p[3];
    if (!bsi_face_point(r->j->m, r->f, uv[0], uv[1], p))
        return BS_OK;
    uint32_t id;
    int outcome;
    bs_status st = bsi_cdt_insert(&r->cdt, gx, gy, BSI_CDT_GUARDED, hint, &id, &outcome);
    if (st != BS_OK || outcome != BSI_CDT_ADDED)
        return st;
    *added = 1;
    return put_point(r, id, uv, p, TM_NONE);
}

static void circumcentre(const double *a, const double *b, const double *c, double *o)
{
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double d = 2.0 * (bx * cy - by * cx);
    double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    o[0] = a[0] + (cy * b2 - by * c2) / d;
    o[1] = a[1] + (bx * c2 - cx * b2) / d;
}

static bs_status refine(face_run *r, size_t boundary_points)
{
    bsi_cdt *c = &r->cdt;
    cand *list = NULL;
    size_t cap = 0;
    size_t shape_budget = 2 * boundary_points + 64;
    const double min_angle = MIN_ANGLE_DEG * PI / 180.0;
    bs_status st = BS_OK;
    for (int pass = 0; pass < MAX_PASSES && st == BS_OK; pass++) {
        size_t n = 0;
        for (size_t t = 0; t < c->nt; t++) {
            bsi_cdt_tri *T = &c->t[t];
            if (T->dead || !T->inside || T->done)
                continue;
            const fpoint *corner[3] = {&r->pt[T->v[0]], &r->pt[T->v[1]], &r->pt[T->v[2]]};
            int kind = 0;
            if (triangle_error(r, corner) > r->j->tol)
                kind = 1;
            else if (shape_budget > 0 && triangle_min_angle(r, corner) < min_angle)
                kind = 2;
            if (kind == 0) {
                T->done = 1;
                continue;
            }
            if (n == cap) {
                size_t nc = cap ? 2 * cap : 256;
                cand *q = realloc(list, nc * sizeof(cand));
                if (q == NULL) {
                    st = BS_ERR_NO_MEMORY;
                    break;
                }
                list = q;
                cap = nc;
            }
            cand *cd = &list[n++];
            cd->t = (uint32_t)t;
            memcpy(cd->v, T->v, sizeof cd->v);
            cd->kind = kind;
        }
        if (n == 0 || st != BS_OK)
            break;
        for (size_t i = 0; i < n && st == BS_OK; i++) {
            const cand *cd = &list[i];
            bsi_cdt_tri *T = &c->t[cd->t];
            if (T->dead || memcmp(T->v, cd->v, sizeof cd->v) != 0)
                continue; /* changed by an earlier insertion: assessed again next pass */
            double xy[3][2], o[2];
            for (int k = 0; k < 3; k++) {
                xy[k][0] = r->pt[cd->v[k]].uv[0] * r->su;
                xy[k][1] = r->pt[cd->v[k]].uv[1] * r->sv;
            }
            circumcentre(xy[0], xy[1], xy[2], o);
            int added = 0;
            if (isfinite(o[0]) && isfinite(o[1]))
                st = try_point(r, o[0], o[1], cd->t, &added);
            if (st == BS_OK && !added && cd->kind == 1)
                st = try_point(r, (xy[0][0] + xy[1][0] + xy[2][0]) / 3.0, (xy[0][1] + xy[1][1] + xy[2][1]) / 3.0,
                               cd->t, &added);
            if (!added) {
                T = &c->t[cd->t];
                if (!T->dead && memcmp(T->v, cd->v, sizeof cd->v) == 0)
                    T->done = 1;
            } else if (cd->kind == 2) {
                shape_budget--;
            }
            if (r->j->max_points && c->np > r->j->max_points)
                st = BS_ERR_SIZE;
        }
    }
    free(list);
    return st;
}

/* ---- The face ---- */

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* rep[i]: the first loop point of the same vertex at the same place as point i (the two sides of
 * a slit, an edge a loop runs along there and back, are one), found among the points sorted by
 * vertex. */
static bs_status same_points(const face_run *r, const loop_pt *pts, size_t n, size_t *rep)
{
    uint64_t *key = malloc((n ? n : 1) * sizeof(uint64_t));
    if (key == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 0; i < n; i++) {
        key[i] = (uint64_t)pts[i].vid << 32 | (uint64_t)i;
        rep[i] = i;
    }
    qsort(key, n, sizeof(uint64_t), cmp_u64);
    for (size_t g = 0; g < n;) {
        size_t e = g + 1;
        while (e < n && key[e] >> 32 == key[g] >> 32)
            e++;
        for (size_t a = g + 1; a < e; a++)
            for (size_t b = g; b < a; b++) {
                size_t ia = (size_t)(key[a] & 0xffffffffu), ib = (size_t)(key[b] & 0xffffffffu);
                if (rep[ib] == ib && same_place(r->j, r->f, &pts[ia], &pts[ib])) {
                    rep[ia] = ib;
                    break;
                }
            }
        g = e;
    }
    free(key);
    return BS_OK;
}

/* The loops' segments as constraints. A segment the loops run along an even number of times (a
 * slit: an edge used twice by the face, there and back at the same place) bounds nothing and is
 * left free. */
static bs_status constrain(face_run *r, const uint32_t *ids, const size_t *start, size_t nloop)
{
    size_t n = start[nloop], ns = 0;
    uint64_t *seg = malloc((n ? n : 1) * sizeof(uint64_t));
    if (seg == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t l = 0; l < nloop; l++)
        for (size_t i = start[l]; i < start[l + 1]; i++) {
            size_t next = i + 1 < start[l + 1] ? i + 1 : start[l];
            uint32_t a = ids[i], b = ids[next];
            if (a != b)
                seg[ns++] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
        }
    qsort(seg, ns, sizeof(uint64_t), cmp_u64);
    bs_status st = BS_OK;
    for (size_t g = 0; g < ns && st == BS_OK;) {
        size_t e = g + 1;
        while (e < ns && seg[e] == seg[g])
            e++;
        if ((e - g) % 2 == 1)
            st = bsi_cdt_force(&r->cdt, (uint32_t)(seg[g] >> 32), (uint32_t)(seg[g] & 0xffffffffu));
        g = e;
    }
    free(seg);
    return st;
}

static bs_status triangulate(face_run *r, const loop_pt *pts, const size_t *start, size_t nloop)
{
    size_t n = start[nloop];
    uint32_t *ids = malloc((n ? n : 1) * sizeof(uint32_t));
    size_t *rep = malloc((n ? n : 1) * sizeof(size_t));
    bs_status st = ids != NULL && rep != NULL ? same_points(r, pts, n, rep) : BS_ERR_NO_MEMORY;
    const tm_vertex *vert = r->j->edges.vert;
    for (size_t i = 0; i < n && st == BS_OK; i++) {
        if (rep[i] != i) {
            ids[i] = ids[rep[i]];
            continue;
        }
        int64_t gx = to_grid(pts[i].uv[0] * r->su, r->cx, r->k), gy = to_grid(pts[i].uv[1] * r->sv, r->cy, r->k);
        int outcome;
        if (gx == INT64_MAX || gy == INT64_MAX)
            st = BS_ERR_DOMAIN;
        if (st == BS_OK)
            st = bsi_cdt_insert(&r->cdt, gx, gy, BSI_CDT_FREE, 0, &ids[i], &outcome);
        if (st == BS_OK && outcome == BSI_CDT_ADDED)
            st = put_point(r, ids[i], pts[i].uv, vert[pts[i].vid].p, pts[i].vid);
    }
    if (st == BS_OK)
        st = constrain(r, ids, start, nloop);
    free(ids);
    free(rep);
    if (st == BS_OK)
        st = bsi_cdt_mark_inside(&r->cdt);
    return st;
}

/* The kept triangles and inner points into fm. */
static bs_status harvest(face_run *r, tm_face_mesh *fm)
{
    const bsi_cdt *c = &r->cdt;
    uint32_t *local = malloc((c->np ? c->np : 1) * sizeof(uint32_t));
    size_t ninner = 0, ntri = 0;
    if (local == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t i = 3; i < c->np; i++)
        local[i] = r->pt[i].vid == TM_NONE ? (uint32_t)ninner++ : TM_NONE;
    for (size_t t = 0; t < c->nt; t++)
        ntri += !c->t[t].dead && c->t[t].inside;
    fm->inner = malloc((ninner ? ninner : 1) * 5 * sizeof(double));
    fm->tri = malloc((ntri ? ntri : 1) * 3 * sizeof(uint32_t));
    fm->tuv = malloc((ntri ? ntri : 1) * 6 * sizeof(double));
    if (fm->inner == NULL || fm->tri == NULL || fm->tuv == NULL) {
        free(local);
        return BS_ERR_NO_MEMORY;
    }
    for (size_t i = 3; i < c->np; i++)
        if (local[i] != TM_NONE) {
            double *o = fm->inner + 5 * (size_t)local[i];
            o[0] = r->pt[i].uv[0];
            o[1] = r->pt[i].uv[1];
            memcpy(o + 2, r->pt[i].p, 3 * sizeof(double));
        }
    fm->ninner = ninner;
    fm->min_angle = PI;
    for (size_t t = 0; t < c->nt; t++) {
        const bsi_cdt_tri *T = &c->t[t];
        if (T->dead || !T->inside || T->v[0] < 3 || T->v[1] < 3 || T->v[2] < 3)
            continue;
        uint32_t id[3];
        for (int k = 0; k < 3; k++) {
            uint32_t v = T->v[k];
            id[k] = r->pt[v].vid == TM_NONE ? TM_INNER | local[v] : r->pt[v].vid;
        }
        if (id[0] == id[1] || id[1] == id[2] || id[0] == id[2])
            continue; /* at a pole: its image is a segment */
        const fpoint *corner[3] = {&r->pt[T->v[0]], &r->pt[T->v[1]], &r->pt[T->v[2]]};
        double a = triangle_min_angle(r, corner);
        fm->min_angle = a < fm->min_angle ? a : fm->min_angle;
        for (int k = 0; k < 3; k++) {
            fm->tri[3 * fm->ntri + (size_t)k] = id[k];
            fm->tuv[6 * fm->ntri + 2 * (size_t)k] = corner[k]->uv[0];
            fm->tuv[6 * fm->ntri + 2 * (size_t)k + 1] = corner[k]->uv[1];
        }
        fm->ntri++;
    }
    free(local);
    return BS_OK;
}

bs_status bsi_tm_face(tm_job *j, size_t f)
{
    tm_face_mesh *fm = &j->face[f];
    memset(fm, 0, sizeof *fm);
    const bsi_face *face = &j->m->faces[f];
    if (face->loop_count == 0)
        return BS_ERR_UNSUPPORTED;
    face_run r;
    memset(&r, 0, sizeof r);
    r.j = j;
    r.f = f;
    r.su = j->scale[f].su;
    r.sv = j->scale[f].sv;
    loop_pt *pts = NULL;
    size_t *start = NULL;
    bs_status st = gather_loops(j, f, &pts, &start);
    if (st != BS_OK)
        return st;
    size_t n = start[face->loop_count];
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < n; i++) {
        double xy[2] = {pts[i].uv[0] * r.su, pts[i].uv[1] * r.sv};
        for (int k = 0; k < 2; k++) {
            lo[k] = xy[k] < lo[k] ? xy[k] : lo[k];
            hi[k] = xy[k] > hi[k] ? xy[k] : hi[k];
        }
    }
    double half = 0.5 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (n < 3 || !(half > 0.0) || !isfinite(half)) {
        free(pts);
        free(start);
        return n == 0 ? BS_OK : BS_ERR_DOMAIN;
    }
    r.cx = 0.5 * (lo[0] + hi[0]);
    r.cy = 0.5 * (lo[1] + hi[1]);
    r.k = 0.999 * (double)BSI_CDT_RANGE / half;
    st = bsi_cdt_init(&r.cdt);
    double zero[3] = {0.0, 0.0, 0.0};
    for (uint32_t k = 0; k < 3 && st == BS_OK; k++)
        st = put_point(&r, k, zero, zero, TM_NONE);
    if (st == BS_OK)
        st = triangulate(&r, pts, start, face->loop_count);
    if (st == BS_OK)
        st = refine(&r, n);
    if (st == BS_OK)
        st = harvest(&r, fm);
    if (st != BS_OK)
        bsi_tm_face_free(fm);
    bsi_cdt_free(&r.cdt);
    free(r.pt);
    free(pts);
    free(start);
    return st;
}
