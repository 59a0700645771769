/*
 * BS_TESS_REVERSE: a finished tessellation faced the other way (phase 6 of lib/mesh/tess.h).
 * Normals are negated; each triangle (a, b, c) becomes (a, c, b), its corners' own (u,v) following
 * their corners; a strip of odd length is read backwards, which reverses every triangle of it,
 * and one of even length (where reading backwards keeps the winding) starts with its first index
 * twice, which shifts every triangle to the other parity (one degenerate triangle more).
 */
#include "mesh/tess.h"

#include <stdlib.h>

/* Swap corners 1 and 2 of every triangle, with the corner list kept ascending. */
static void reverse_triangles(tess *t)
{
    for (size_t k = 0; k + 2 < t->tri.n; k += 3) {
        uint32_t b = t->tri.v[k + 1];
        t->tri.v[k + 1] = t->tri.v[k + 2];
        t->tri.v[k + 2] = b;
    }
    xbuf *x = &t->xc;
    for (size_t i = 0; i < x->n; i++) {
        size_t c = x->corner[i] % 3;
        if (c == 1)
            x->corner[i]++;
        else if (c == 2)
            x->corner[i]--;
    }
    for (size_t i = 0; i + 1 < x->n; i++)
        if (x->corner[i] > x->corner[i + 1]) { /* corners 2 and 1 of one triangle */
            size_t c = x->corner[i];
            x->corner[i] = x->corner[i + 1];
            x->corner[i + 1] = c;
            for (size_t d = 0; d < 2; d++) {
                double w = x->uv[2 * i + d];
                x->uv[2 * i + d] = x->uv[2 * i + 2 + d];
                x->uv[2 * i + 2 + d] = w;
            }
        }
}

/* Strips with sstart already closed (t->sstart.n = strips + 1). */
static bs_status reverse_strips(tess *t)
{
    size_t ns = t->sstart.n - 1, even = 0;
    for (size_t k = 0; k < ns; k++)
        even += t->sstart.v[k + 1] > t->sstart.v[k] && (t->sstart.v[k + 1] - t->sstart.v[k]) % 2 == 0;
    if (t->sidx.n + even > UINT32_MAX)
        return BS_ERR_SIZE;
    uint32_t *idx = malloc((t->sidx.n + even ? t->sidx.n + even : 1) * sizeof(uint32_t));
    if (idx == NULL)
        return BS_ERR_NO_MEMORY;
    size_t n = 0;
    for (size_t k = 0; k < ns; k++) {
        size_t a = t->sstart.v[k], b = t->sstart.v[k + 1];
        t->sstart.v[k] = (uint32_t)n;
        if (b > a && (b - a) % 2 == 0) {
            idx[n++] = t->sidx.v[a];
            for (size_t i = a; i < b; i++)
                idx[n++] = t->sidx.v[i];
        } else {
            for (size_t i = b; i > a; i--)
                idx[n++] = t->sidx.v[i - 1];
        }
    }
    t->sstart.v[ns] = (uint32_t)n;
    free(t->sidx.v);
    t->sidx.v = idx;
    t->sidx.n = t->sidx.cap = n;
    return BS_OK;
}

bs_status bsi_tess_reverse(tess *t)
{
    bs_status st = t->strips ? reverse_strips(t) : BS_OK;
    if (st != BS_OK)
        return st;
    for (size_t k = 0; k < 3 * t->nvert; k++)
        t->nrm[k] = -t->nrm[k];
    reverse_triangles(t);
    return BS_OK;
}
