/*
 * Constrained Delaunay triangulation (cdt.h).
 *
 * Points go in by Bowyer-Watson: the triangles whose circumcircle holds the new point, grown from
 * the one that contains it and never across a constraint, are replaced by a fan around it. The
 * cavity is checked to be star-shaped around the point with the exact orientation test (triangles
 * that break it leave the cavity), so a rounded in-circle test costs at most a less Delaunay
 * triangle, never an invalid one. Segments are recovered as in Anglada (1997): the triangles the
 * segment crosses are removed, and the two polygons on its sides are triangulated again by
 * choosing, for a base edge, the vertex whose circle holds no other.
 */
#include "model/cdt_internal.h"

#include <stdlib.h>
#include <string.h>

static int64_t orient_q(const int64_t *a, const int64_t *b, const int64_t *p)
{
    /* |differences| < 2^31: each product below 2^62, their difference below 2^63 */
    int64_t d = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    return d;
}

int bsi_cdt_orient(const bsi_cdt *c, uint32_t a, uint32_t b, const int64_t *p)
{
    int64_t d = orient_q(c->q + 2 * (size_t)a, c->q + 2 * (size_t)b, p);
    return (d > 0) - (d < 0);
}

int bsi_cdt_orient3(const bsi_cdt *c, uint32_t a, uint32_t b, uint32_t p)
{
    return bsi_cdt_orient(c, a, b, c->q + 2 * (size_t)p);
}

/* > 0 when p is inside the circle through the counter-clockwise a, b, c. */
long double bsi_cdt_incircle(const bsi_cdt *c, uint32_t a, uint32_t b, uint32_t d, const int64_t *p)
{
    const int64_t *pa = c->q + 2 * (size_t)a, *pb = c->q + 2 * (size_t)b, *pd = c->q + 2 * (size_t)d;
    long double ax = (long double)(pa[0] - p[0]), ay = (long double)(pa[1] - p[1]);
    long double bx = (long double)(pb[0] - p[0]), by = (long double)(pb[1] - p[1]);
    long double dx = (long double)(pd[0] - p[0]), dy = (long double)(pd[1] - p[1]);
    long double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, d2 = dx * dx + dy * dy;
    return a2 * (bx * dy - by * dx) - b2 * (ax * dy - ay * dx) + d2 * (ax * by - ay * bx);
}

static bs_status new_point(bsi_cdt *c, int64_t x, int64_t y, uint32_t *id)
{
    if (c->np >= UINT32_MAX - 1)
        return BS_ERR_SIZE;
    if (!bsi_grow_array((void **)&c->q, &c->pcap, c->np + 1, 2 * sizeof(int64_t)) ||
        !bsi_grow_array((void **)&c->vtri, &c->vcap, c->np + 1, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    c->q[2 * c->np] = x;
    c->q[2 * c->np + 1] = y;
    c->vtri[c->np] = BSI_CDT_NONE;
    *id = (uint32_t)c->np++;
    return BS_OK;
}

bs_status bsi_cdt_new_tri(bsi_cdt *c, uint32_t *id)
{
    if (c->nspare > 0) {
        *id = c->spare[--c->nspare];
    } else {
        if (c->nt >= UINT32_MAX - 1)
            return BS_ERR_SIZE;
        if (!bsi_grow_array((void **)&c->t, &c->tcap, c->nt + 1, sizeof(bsi_cdt_tri)))
            return BS_ERR_NO_MEMORY;
        *id = (uint32_t)c->nt++;
    }
    memset(&c->t[*id], 0, sizeof(bsi_cdt_tri));
    return BS_OK;
}

bs_status bsi_cdt_retire(bsi_cdt *c, uint32_t t)
{
    if (!bsi_grow_array((void **)&c->spare, &c->spare_cap, c->nspare + 1, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    c->t[t].dead = 1;
    c->spare[c->nspare++] = t;
    return BS_OK;
}

bs_status bsi_cdt_init(bsi_cdt *c)
{
    memset(c, 0, sizeof *c);
    const int64_t big = (int64_t)1 << 30;
    const int64_t corner[3][2] = {{-(big / 10) * 9, -big / 2}, {(big / 10) * 9, -big / 2}, {0, (big / 10) * 9}};
    uint32_t id, t;
    for (int k = 0; k < 3; k++)
        if (new_point(c, corner[k][0], corner[k][1], &id) != BS_OK)
            return BS_ERR_NO_MEMORY;
    if (bsi_cdt_new_tri(c, &t) != BS_OK)
        return BS_ERR_NO_MEMORY;
    for (int k = 0; k < 3; k++) {
        c->t[t].v[k] = (uint32_t)k;
        c->t[t].nb[k] = BSI_CDT_NONE;
        c->vtri[k] = t;
    }
    c->last = t;
    return BS_OK;
}

void bsi_cdt_free(bsi_cdt *c)
{
    free(c->q);
    free(c->vtri);
    free(c->t);
    free(c->spare);
    free(c->cav);
    free(c->edge);
    free(c->fresh);
    free(c->chain);
    memset(c, 0, sizeof *c);
}

/* Index of vertex v in triangle t, or 3. */
int bsi_cdt_slot_of(const bsi_cdt_tri *t, uint32_t v)
{
    for (int i = 0; i < 3; i++)
        if (t->v[i] == v)
            return i;
    return 3;
}

/* Walk from triangle t towards p: the triangle holding p (inside or on its sides). guarded: stop
 * (BSI_CDT_NONE) rather than cross a constraint. */
static uint32_t locate(const bsi_cdt *c, uint32_t t, const int64_t *p, int guarded)
{
    size_t limit = 4 * c->nt + 64;
    for (size_t step = 0; step < limit; step++) {
        const bsi_cdt_tri *T = &c->t[t];
        int moved = 0;
        for (int j = 0; j < 3 && !moved; j++) {
            int i = (int)((step + (size_t)j) % 3);
            if (bsi_cdt_orient(c, T->v[NEXT(i)], T->v[PREV(i)], p) < 0) {
                if (T->nb[i] == BSI_CDT_NONE || (guarded && T->fixed[i]))
                    return BSI_CDT_NONE;
                t = T->nb[i];
                moved = 1;
            }
        }
        if (!moved)
            return t;
    }
    return BSI_CDT_NONE;
}

static int add_edge(bsi_cdt *c, uint32_t from, uint32_t to, uint32_t outer, uint32_t fixed)
{
    if (!bsi_grow_array((void **)&c->edge, &c->edge_cap, 4 * (c->nedge + 1), sizeof(uint32_t)))
        return 0;
    uint32_t *e = c->edge + 4 * c->nedge++;
    e[0] = from;
    e[1] = to;
    e[2] = outer;
    e[3] = fixed;
    return 1;
}

/* The boundary of the marked triangles c->cav: their edges whose other side is unmarked. */
int bsi_cdt_collect_boundary(bsi_cdt *c)
{
    c->nedge = 0;
    for (size_t k = 0; k < c->ncav; k++) {
        const bsi_cdt_tri *T = &c->t[c->cav[k]];
        for (int i = 0; i < 3; i++) {
            uint32_t n = T->nb[i];
            if (n != BSI_CDT_NONE && c->t[n].mark == c->stamp)
                continue;
            if (!add_edge(c, T->v[NEXT(i)], T->v[PREV(i)], n, T->fixed[i]))
                return 0;
        }
    }
    return 1;
}

/* Side i = (x, y) of the fresh triangle tk against the boundary edge (x, y) of the cavity: the
 * triangle behind it becomes its neighbour, and its own link is turned to tk. 0 when no boundary
 * edge is (x, y). */
static int link_behind(bsi_cdt *c, uint32_t tk, int i, uint32_t x, uint32_t y)
{
    bsi_cdt_tri *T = &c->t[tk];
    for (size_t e = 0; e < c->nedge; e++) {
        const uint32_t *E = c->edge + 4 * e;
        if (E[0] != x || E[1] != y)
            continue;
        T->nb[i] = E[2];
        T->fixed[i] = (unsigned char)E[3];
        if (E[2] != BSI_CDT_NONE) {
            bsi_cdt_tri *O = &c->t[E[2]];
            int b = bsi_cdt_slot_of(O, y);
            if (b < 3 && O->v[NEXT(b)] == x)
                O->nb[PREV(b)] = tk;
        }
        return 1;
    }
    return 0;
}

/* Neighbours of the triangles c->fresh: among themselves where they share an edge, else the
 * outer triangle of the boundary edge they stand on (whose own link is turned to them). */
void bsi_cdt_link_fresh(bsi_cdt *c)
{
    for (size_t k = 0; k < c->nfresh; k++) {
        uint32_t tk = c->fresh[k];
        bsi_cdt_tri *T = &c->t[tk];
        for (int i = 0; i < 3; i++) {
            uint32_t x = T->v[NEXT(i)], y = T->v[PREV(i)];
            T->nb[i] = BSI_CDT_NONE;
            int found = 0;
            for (size_t j = 0; j < c->nfresh && !found; j++) {
                if (j == k)
                    continue;
                const bsi_cdt_tri *U = &c->t[c->fresh[j]];
                int a = bsi_cdt_slot_of(U, y);
                if (a < 3 && U->v[NEXT(a)] == x) {
                    T->nb[i] = c->fresh[j];
                    T->fixed[i] = U->fixed[PREV(a)];
                    found = 1;
                }
            }
            if (!found)
                link_behind(c, tk, i, x, y);
        }
        for (int i = 0; i < 3; i++)
            c->vtri[T->v[i]] = tk;
    }
}

/* bsi_cdt_link_fresh for the fan of an insertion: fresh[k] = (from, to, p) stands on boundary
 * edge k, so its neighbour across (to, p) is the fan's triangle starting at to, across (p, from)
 * the one ending at from, and across (from, to) the triangle behind that edge: the same links,
 * found by comparing one vertex rather than searching each triangle for the edge's ends. */
static void link_fan(bsi_cdt *c)
{
    for (size_t k = 0; k < c->nfresh; k++) {
        uint32_t tk = c->fresh[k];
        bsi_cdt_tri *T = &c->t[tk];
        uint32_t from = T->v[0], to = T->v[1];
        T->nb[0] = T->nb[1] = T->nb[2] = BSI_CDT_NONE;
        int found[3] = {0, 0, 0};
        for (size_t j = 0; j < c->nfresh; j++) {
            const bsi_cdt_tri *U = &c->t[c->fresh[j]];
            if (j == k)
                continue;
            if (!found[0] && U->v[0] == to) /* (to, next, p) */
                T->nb[0] = c->fresh[j], T->fixed[0] = U->fixed[1], found[0] = 1;
            if (!found[1] && U->v[1] == from) /* (before, from, p) */
                T->nb[1] = c->fresh[j], T->fixed[1] = U->fixed[0], found[1] = 1;
            if (!found[2] && U->v[0] == to && U->v[1] == from) /* the edge run back: a spike */
                T->nb[2] = c->fresh[j], T->fixed[2] = U->fixed[2], found[2] = 1;
        }
        if (!found[2])
            link_behind(c, tk, 2, from, to);
        for (int i = 0; i < 3; i++)
            c->vtri[T->v[i]] = tk;
    }
}

int bsi_cdt_push_cav(bsi_cdt *c, uint32_t t)
{
    if (!bsi_grow_array((void **)&c->cav, &c->cav_cap, c->ncav + 1, sizeof(uint32_t)))
        return 0;
    c->cav[c->ncav++] = t;
    c->t[t].mark = c->stamp;
    return 1;
}

void bsi_cdt_next_stamp(bsi_cdt *c)
{
    if (++c->stamp == 0) {
        for (size_t k = 0; k < c->nt; k++)
            c->t[k].mark = 0;
        c->stamp = 1;
    }
}

/* The Bowyer-Watson cavity of p from t0 (c->cav, marked), made star-shaped around p. 0 when the
 * point cannot go in there (a constraint would be lost, or p lies on one). */
static int cavity(bsi_cdt *c, uint32_t t0, const int64_t *p, int *nomem)
{
    bsi_cdt_next_stamp(c);
    c->ncav = 0;
    if (!bsi_cdt_push_cav(c, t0))
        return *nomem = 1, 0;
    for (size_t k = 0; k < c->ncav; k++) {
        uint32_t tk = c->cav[k];
        for (int i = 0; i < 3; i++) {
            const bsi_cdt_tri *T = &c->t[tk];
            uint32_t n = T->nb[i];
            if (n == BSI_CDT_NONE || c->t[n].mark == c->stamp)
                continue;
            int on_side = tk == t0 && bsi_cdt_orient(c, T->v[NEXT(i)], T->v[PREV(i)], p) == 0;
            if (T->fixed[i]) {
                if (on_side)
                    return 0;
                continue;
            }
            const bsi_cdt_tri *N = &c->t[n];
            if (on_side || bsi_cdt_incircle(c, N->v[0], N->v[1], N->v[2], p) > 0.0L)
                if (!bsi_cdt_push_cav(c, n))
                    return *nomem = 1, 0;
        }
    }
    for (;;) {
        if (!bsi_cdt_collect_boundary(c))
            return *nomem = 1, 0;
        size_t bad = c->ncav;
        for (size_t e = 0; e < c->nedge && bad == c->ncav; e++) {
            const uint32_t *E = c->edge + 4 * e;
            if (bsi_cdt_orient(c, E[0], E[1], p) > 0)
                continue;
            for (size_t k = 0; k < c->ncav; k++) {
                const bsi_cdt_tri *T = &c->t[c->cav[k]];
                int a = bsi_cdt_slot_of(T, E[0]);
                if (a < 3 && T->v[NEXT(a)] == E[1])
                    bad = k;
            }
        }
        if (bad == c->ncav)
            break;
        if (c->cav[bad] == t0)
            return 0;
        c->t[c->cav[bad]].mark = 0;
        c->cav[bad] = c->cav[--c->ncav];
    }
    /* a cavity that is a disk has two more boundary edges than triangles; a constraint inside it
     * (both sides in the cavity) would be lost */
    if (c->nedge != c->ncav + 2)
        return 0;
    for (size_t k = 0; k < c->ncav; k++) {
        const bsi_cdt_tri *T = &c->t[c->cav[k]];
        for (int i = 0; i < 3; i++)
            if (T->fixed[i] && T->nb[i] != BSI_CDT_NONE && c->t[T->nb[i]].mark == c->stamp)
                return 0;
    }
    return 1;
}

bs_status bsi_cdt_insert(bsi_cdt *c, int64_t x, int64_t y, int mode, uint32_t hint, uint32_t *id,
                         int *outcome)
{
    const int64_t p[2] = {x, y};
    int guarded = mode == BSI_CDT_GUARDED;
    uint32_t start = guarded ? hint : c->last;
    if (start >= c->nt || c->t[start].dead)
        start = c->last;
    uint32_t t0 = locate(c, start, p, guarded);
    if (t0 == BSI_CDT_NONE) {
        if (guarded)
            return *outcome = BSI_CDT_BLOCKED, BS_OK;
        return BS_ERR_DOMAIN;
    }
    const bsi_cdt_tri *T0 = &c->t[t0];
    for (int i = 0; i < 3; i++)
        if (c->q[2 * (size_t)T0->v[i]] == x && c->q[2 * (size_t)T0->v[i] + 1] == y) {
            *id = T0->v[i];
            return *outcome = BSI_CDT_EXISTS, BS_OK;
        }
    if (guarded && !T0->inside)
        return *outcome = BSI_CDT_BLOCKED, BS_OK;
    int nomem = 0;
    if (!cavity(c, t0, p, &nomem)) {
        if (nomem)
            return BS_ERR_NO_MEMORY;
        if (guarded)
            return *outcome = BSI_CDT_BLOCKED, BS_OK;
        return BS_ERR_DOMAIN;
    }
    unsigned char inside = T0->inside;
    uint32_t pid;
    bs_status st = new_point(c, x, y, &pid);
    if (st != BS_OK)
        return st;
    if (!bsi_grow_array((void **)&c->fresh, &c->fresh_cap, c->nedge, sizeof(uint32_t)))
        return BS_ERR_NO_MEMORY;
    c->nfresh = 0;
    for (size_t e = 0; e < c->nedge; e++) {
        uint32_t t;
        if (e < c->ncav)
            t = c->cav[e];
        else if ((st = bsi_cdt_new_tri(c, &t)) != BS_OK)
            return st;
        bsi_cdt_tri *T = &c->t[t];
        memset(T, 0, sizeof *T);
        T->v[0] = c->edge[4 * e];
        T->v[1] = c->edge[4 * e + 1];
        T->v[2] = pid;
        T->inside = inside;
        c->fresh[c->nfresh++] = t;
    }
    link_fan(c);
    c->last = c->fresh[0];
    *id = pid;
    return *outcome = BSI_CDT_ADDED, BS_OK;
}

bs_status bsi_cdt_mark_inside(bsi_cdt *c)
{
    /* BFS by parity from the triangle at the enclosing triangle's first corner */
    bsi_cdt_next_stamp(c);
    c->ncav = 0;
    uint32_t t0 = c->vtri[0];
    c->t[t0].inside = 0;
    if (!bsi_cdt_push_cav(c, t0))
        return BS_ERR_NO_MEMORY;
    for (size_t k = 0; k < c->ncav; k++) {
        const bsi_cdt_tri *T = &c->t[c->cav[k]];
        for (int i = 0; i < 3; i++) {
            uint32_t n = T->nb[i];
            if (n == BSI_CDT_NONE)
                continue;
            unsigned char want = (unsigned char)(T->inside ^ T->fixed[i]);
            if (c->t[n].mark == c->stamp) {
                if (c->t[n].inside != want)
                    return BS_ERR_DOMAIN;
                continue;
            }
            c->t[n].inside = want;
            if (!bsi_cdt_push_cav(c, n))
                return BS_ERR_NO_MEMORY;
            T = &c->t[c->cav[k]];
        }
    }
    return BS_OK;
}
