/*
 * Subdivision phase 3: each leaf as a polygon (its corners and every point lying inside its sides,
 * counter-clockwise in (u,v)) cut into triangles that use all those points, so a leaf beside
 * finer leaves, or beside a finer neighbour patch, shares their vertices and no T-junction
 * appears. The cuts, fewest triangles first:
 *   - no side point: two triangles (a b d, d b c as in the grid tessellator);
 *   - a corner whose two sides have none: a fan from that corner (n - 2 triangles);
 *   - points on two opposite sides only: the two rows zipped by parameter (n - 2);
 *   - otherwise a fan from a new vertex at the leaf's centre (n triangles).
 * Every triangle lies in its leaf, so the leaf's bound (subdiv_tree.c) holds for it. Triangles with
 * a repeated vertex (at poles) are dropped.
 */
#include "mesh/subdiv.h"

#include <stdlib.h>

enum { K_QUAD, K_FAN_A, K_FAN_B, K_FAN_C, K_FAN_D, K_ZIP_U, K_ZIP_V, K_CENTRE };
/* Kind flag: the leaf may lose triangles to repeated vertices (it touches a pole, spans its patch,
 * or has two corners welded), so its triangles are counted by emitting them. */
#define K_COUNT_BY_EMITTING 0x80

/* Side points of a leaf, exclusive of its corners: ranges in s->vu (bottom, top) or s->uv. */
typedef struct leaf_sides { size_t f[4], l[4]; } leaf_sides;

/* Side points of leaf k between its corners: bottom and top are ranges of s->vu (the points
 * after one corner by (v,u) up to the next), right and left ranges of s->uv. */
static void sides_of(const subdiv *s, size_t p, size_t k, leaf_sides *ls)
{
    const uint32_t *c = s->corner + 4 * k, *vp = s->vupos + s->pt0[p];
    ls->f[0] = vp[c[0]] + 1, ls->l[0] = vp[c[1]];
    ls->f[1] = c[1] + 1, ls->l[1] = c[2];
    ls->f[2] = vp[c[3]] + 1, ls->l[2] = vp[c[2]];
    ls->f[3] = c[0] + 1, ls->l[3] = c[3];
}

static unsigned char classify(const leaf_sides *ls)
{
    int has[4];
    for (int k = 0; k < 4; k++)
        has[k] = ls->l[k] > ls->f[k];
    if (!has[0] && !has[1] && !has[2] && !has[3])
        return K_QUAD;
    /* corner a touches sides 3 and 0, b sides 0 and 1, c 1 and 2, d 2 and 3 */
    for (int c = 0; c < 4; c++)
        if (!has[c] && !has[(c + 3) % 4])
            return (unsigned char)(K_FAN_A + c);
    if (!has[1] && !has[3])
        return K_ZIP_U;
    if (!has[0] && !has[2])
        return K_ZIP_V;
    return K_CENTRE;
}

/* 1 if every triangle of leaf k of patch p has three distinct vertices: it touches no pole, does
 * not span the patch (whose opposite sides may be one curve) and its corners are four vertices. */
static int plain_leaf(const subdiv *s, size_t p, size_t k)
{
    const sd_leaf *lf = &s->leaf[k];
    const bsi_side_link *lk = &s->topo.links[4 * p];
    if ((lk[BSI_SIDE_V0].collapsed && lf->v0 == 0) || (lk[BSI_SIDE_U1].collapsed && lf->u1 == SD_N) ||
        (lk[BSI_SIDE_V1].collapsed && lf->v1 == SD_N) || (lk[BSI_SIDE_U0].collapsed && lf->u0 == 0) ||
        (lf->u0 == 0 && lf->u1 == SD_N) || (lf->v0 == 0 && lf->v1 == SD_N))
        return 0;
    uint32_t id[4];
    for (int c = 0; c < 4; c++)
        id[c] = s->vid[s->pt0[p] + s->corner[4 * k + (size_t)c]];
    return id[0] != id[1] && id[0] != id[2] && id[0] != id[3] && id[1] != id[2] && id[1] != id[3] && id[2] != id[3];
}

bs_status bsi_subdiv_classify(subdiv *s)
{
    s->kind = malloc(s->nleaf ? s->nleaf : 1);
    s->cen0 = malloc((s->np + 1) * sizeof(size_t));
    if (s->kind == NULL || s->cen0 == NULL)
        return BS_ERR_NO_MEMORY;
    size_t nv = s->nvert, nt = 0;
    for (size_t p = 0; p < s->np; p++) {
        s->cen0[p] = nv;
        for (size_t k = s->leaf0[p]; k < s->leaf0[p + 1]; k++) {
            leaf_sides ls;
            sides_of(s, p, k, &ls);
            unsigned char kind = classify(&ls);
            size_t n = 4;
            for (int q = 0; q < 4; q++)
                n += ls.l[q] - ls.f[q];
            nv += kind == K_CENTRE;
            if (plain_leaf(s, p, k))
                nt += kind == K_CENTRE ? n : n - 2; /* a fan of n points, or a cut into n - 2 */
            else
                kind |= K_COUNT_BY_EMITTING;
            s->kind[k] = kind;
        }
    }
    s->cen0[s->np] = nv;
    if (nv > UINT32_MAX - 1)
        return BS_ERR_SIZE;
    s->nvert = nv;
    s->ntri = nt;
    return BS_OK;
}

typedef struct emitter {
    subdiv *s;
    tess *t;        /* NULL: only count */
    uint32_t patch;
    bsi_corner *poly;
    size_t cap;
} emitter;

static void tri(emitter *x, bsi_corner a, bsi_corner b, bsi_corner c)
{
    if (x->t != NULL)
        bsi_tess_emit(x->t, x->patch, a, b, c, 1);
    else if (a.id != b.id && b.id != c.id && a.id != c.id)
        x->s->ntri++;
}

static bsi_corner point_corner(const subdiv *s, size_t g)
{
    uint64_t key = s->uv[g];
    bsi_corner c = {s->vid[g], (double)(key >> SD_BITS) / (double)SD_N,
                    (double)(key & ((UINT64_C(1) << SD_BITS) - 1)) / (double)SD_N};
    return c;
}

/* Append the side points of range k (reversed for the top and left sides). */
static size_t put_side(emitter *x, size_t p, const leaf_sides *ls, int k, size_t n)
{
    const subdiv *s = x->s;
    size_t first = ls->f[k], last = ls->l[k], cnt = last - first;
    int reversed = k >= 2; /* top and left */
    for (size_t i = 0; i < cnt; i++) {
        size_t r = reversed ? last - 1 - i : first + i;
        size_t g = s->pt0[p] + (k % 2 == 0 ? (size_t)(s->vu[s->pt0[p] + r] & ((UINT64_C(1) << 24) - 1)) : r);
        x->poly[n++] = point_corner(s, g);
    }
    return n;
}

/* The rows of two opposite sides zipped by parameter: lo[0..nl) and hi[0..nh), same direction. */
static void zip(emitter *x, const bsi_corner *lo, size_t nl, const bsi_corner *hi, size_t nh, int along_u)
{
    size_t i = 0, j = 0;
    while (i + 1 < nl || j + 1 < nh) {
        int advance_lo;
        if (j + 1 >= nh)
            advance_lo = 1;
        else if (i + 1 >= nl)
            advance_lo = 0;
        else
            advance_lo = along_u ? lo[i].u + lo[i + 1].u <= hi[j].u + hi[j + 1].u
                                 : lo[i].v + lo[i + 1].v <= hi[j].v + hi[j + 1].v;
        if (advance_lo) {
            tri(x, lo[i], lo[i + 1], hi[j]);
            i++;
        } else {
            tri(x, lo[i], hi[j + 1], hi[j]);
            j++;
        }
    }
}

static int grow(emitter *x, size_t need)
{
    if (need <= x->cap)
        return 1;
    size_t cap = 2 * need;
    bsi_corner *np = realloc(x->poly, cap * sizeof(bsi_corner));
    if (np == NULL)
        return 0;
    x->poly = np;
    x->cap = cap;
    return 1;
}

/* The leaf's triangles; its centre vertex, when it has one, is *centre (then advanced). */
static int leaf_emit(emitter *x, size_t p, size_t k, uint32_t *centre)
{
    const subdiv *s = x->s;
    leaf_sides ls;
    sides_of(s, p, k, &ls);
    size_t cnt = 4;
    for (int q = 0; q < 4; q++)
        cnt += ls.l[q] - ls.f[q];
    if (!grow(x, 2 * cnt))
        return 0;
    bsi_corner *P = x->poly;
    size_t n = 0, at[4];
    for (int q = 0; q < 4; q++) { /* corner q, then the points inside side q (q = 0: bottom) */
        at[q] = n;
        P[n++] = point_corner(s, s->pt0[p] + s->corner[4 * k + (size_t)q]);
        n = put_side(x, p, &ls, q, n);
    }
    unsigned char kind = (unsigned char)(s->kind[k] & ~K_COUNT_BY_EMITTING);
    if (kind == K_QUAD) {
        tri(x, P[0], P[1], P[3]);
        tri(x, P[3], P[1], P[2]);
    } else if (kind >= K_FAN_A && kind <= K_FAN_D) {
        size_t c = at[kind - K_FAN_A];
        for (size_t i = 1; i + 1 < n; i++)
            tri(x, P[c], P[(c + i) % n], P[(c + i + 1) % n]);
    } else if (kind == K_ZIP_U) {
        /* bottom a..b as it is; top d..c is the polygon's c..d reversed */
        bsi_corner *top = P + n;
        size_t nt = at[3] - at[2] + 1;
        for (size_t i = 0; i < nt; i++)
            top[i] = P[at[3] - i];
        zip(x, P, at[1] + 1, top, nt, 1);
    } else if (kind == K_ZIP_V) {
        /* left a..d is the polygon's d..a reversed (wrapping to a); right b..c as it is */
        bsi_corner *left = P + n;
        size_t nl = n - at[3] + 1;
        left[0] = P[0];
        for (size_t i = 1; i < nl; i++)
            left[i] = P[n - i];
        zip(x, left, nl, P + at[1], at[2] - at[1] + 1, 0);
    } else {
        bsi_corner c = {(*centre)++, 0.5 * (P[0].u + P[at[2]].u), 0.5 * (P[0].v + P[at[2]].v)};
        for (size_t i = 0; i < n; i++)
            tri(x, c, P[i], P[(i + 1) % n]);
    }
    return 1;
}

void bsi_subdiv_centres(const subdiv *s, double *uv)
{
    for (size_t p = 0; p < s->np; p++) {
        size_t id = s->cen0[p];
        for (size_t k = s->leaf0[p]; k < s->leaf0[p + 1]; k++) {
            const sd_leaf *lf = &s->leaf[k];
            if ((s->kind[k] & ~K_COUNT_BY_EMITTING) != K_CENTRE)
                continue;
            uv[2 * id] = 0.5 * ((double)lf->u0 / (double)SD_N + (double)lf->u1 / (double)SD_N);
            uv[2 * id + 1] = 0.5 * ((double)lf->v0 / (double)SD_N + (double)lf->v1 / (double)SD_N);
            id++;
        }
    }
}

bs_status bsi_subdiv_emit(subdiv *s, tess *t)
{
    emitter x = {s, t, 0, NULL, 0};
    for (size_t p = 0; p < s->np; p++) {
        uint32_t centre = (uint32_t)s->cen0[p]; /* counting: any id no point has will do */
        x.patch = (uint32_t)p;
        for (size_t k = s->leaf0[p]; k < s->leaf0[p + 1]; k++)
            if ((t != NULL || (s->kind[k] & K_COUNT_BY_EMITTING)) && !leaf_emit(&x, p, k, &centre)) {
                free(x.poly);
                return BS_ERR_NO_MEMORY;
            }
    }
    free(x.poly);
    return BS_OK;
}
