/*
 * The tessellation entry points of 1.1: one options struct for every method, budgets refused before
 * any large allocation, and the counts of a mesh without building it.
 */
#include "mesh/subdiv.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void bs_tess_options_init(bs_tess_options *o)
{
    if (o == NULL)
        return;
    memset(o, 0, sizeof(*o));
    o->size = sizeof(*o);
    o->method = BS_TESS_UNIFORM;
    o->nu = 16;
    o->nv = 16;
    o->tolerance = 1e-3;
    o->threads = 1; /* single-threaded unless asked */
}

/* Check the options and start t with the rates of their method (subdivision needs no t). */
static bs_status start(tess *t, const bs_surface *s, const bs_tess_options *o)
{
    if (o == NULL || o->size < sizeof(bs_tess_options))
        return BS_ERR_INVALID_ARG;
    if (o->method != BS_TESS_UNIFORM && o->method != BS_TESS_PER_PATCH && o->method != BS_TESS_SUBDIVIDE)
        return BS_ERR_INVALID_ARG;
    bs_status st = bsi_tess_check(s, o->flags);
    if (st != BS_OK)
        return st;
    switch (o->method) {
    case BS_TESS_UNIFORM:
        return bsi_tess_start_uniform(t, s, o->flags, o->nu, o->nv);
    case BS_TESS_PER_PATCH:
        return bsi_tess_start_adaptive(t, s, o->flags, o->tolerance);
    case BS_TESS_SUBDIVIDE:
        return o->tolerance > 0.0 && isfinite(o->tolerance) ? BS_OK : BS_ERR_DOMAIN;
    default:
        return BS_ERR_INVALID_ARG;
    }
}

/* The power of two that brings a surface whose coordinates reach beyond 2^1000, or stay below
 * 2^-1000, near 1 (at most 2^1000, so that it is finite), else 1: there the evaluators'
 * derivatives overflow or underflow (normals (0, 0, 1) for a box at 1e308 or 1e-320). */
static double extreme_scale(const bs_surface *s)
{
    double big = bsi_tess_max_abs_coord(s);
    if (!(big > 0.0 && big <= DBL_MAX) || (big >= 0x1p-1000 && big <= 0x1p1000))
        return 1.0;
    int e = 0;
    (void)frexp(big, &e);
    return ldexp(1.0, -e < 1000 ? -e : 1000);
}

/* s with every control point times sig (exact but where it meets the subnormal range). */
static bs_status scaled_copy(const bs_surface *s, double sig, bs_surface **copy)
{
    bs_status st = bs_surface_create(copy);
    for (size_t i = 0; st == BS_OK && i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        double *ctrl = malloc(p->nctrl * p->dim * sizeof *ctrl);
        bs_patch *q = NULL;
        st = ctrl ? BS_OK : BS_ERR_NO_MEMORY;
        for (size_t k = 0; st == BS_OK && k < p->nctrl * p->dim; k++)
            ctrl[k] = p->ctrl[k] * sig;
        if (st == BS_OK)
            st = bs_patch_create(p->deg_u, p->deg_v, p->dim, ctrl, p->rational ? p->weights : NULL, &q);
        if (st == BS_OK)
            st = bs_surface_add(*copy, q, NULL);
        bs_patch_destroy(q);
        free(ctrl);
    }
    if (st != BS_OK) {
        bs_surface_destroy(*copy);
        *copy = NULL;
    }
    return st;
}

static bs_status tessellate_at(const bs_surface *s, const bs_tess_options *o, bs_mesh **out);

bs_status bs_surface_tessellate(const bs_surface *s, const bs_tess_options *o, bs_mesh **out)
{
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    *out = NULL;
    double sig = s != NULL && o != NULL && o->size >= sizeof(bs_tess_options) ? extreme_scale(s) : 1.0;
    if (sig == 1.0 || o == NULL)
        return tessellate_at(s, o, out);
    /* a copy scaled by sig, the positions scaled back: normals and parameters do not depend on
     * the scale, nor does the mesh's shape under a tolerance scaled with it */
    bs_surface *copy = NULL;
    bs_status st = scaled_copy(s, sig, &copy);
    if (st != BS_OK)
        return st;
    bs_tess_options so = *o;
    if (!(o->flags & BS_TESS_RELATIVE))
        so.tolerance = o->tolerance * sig;
    st = tessellate_at(copy, &so, out);
    for (size_t k = 0; st == BS_OK && k < 3 * (*out)->nvert; k++)
        (*out)->pos[k] /= sig;
    bs_surface_destroy(copy);
    return st;
}

static bs_status tessellate_at(const bs_surface *s, const bs_tess_options *o, bs_mesh **out)
{
    tess t;
    bs_status st = start(&t, s, o);
    if (st == BS_OK && o->method == BS_TESS_SUBDIVIDE)
        return bsi_tess_subdivide(s, bsi_tess_absolute_tolerance(s, o->tolerance, o->flags), o->flags,
                                  o->max_vertices, o->max_triangles, o->threads, out);
    if (st != BS_OK)
        return st;
    t.threads = o->threads;
    return bsi_tess_build(&t, o->max_vertices, o->max_triangles, out);
}

bs_status bs_surface_tessellate_count(const bs_surface *s, const bs_tess_options *o, size_t *vertices,
                                      size_t *triangles)
{
    tess t;
    bs_status st = start(&t, s, o);
    if (st != BS_OK)
        return st;
    if (o->method == BS_TESS_SUBDIVIDE)
        return bsi_tess_subdivide_count(s, bsi_tess_absolute_tolerance(s, o->tolerance, o->flags), o->max_vertices,
                                        o->max_triangles, vertices, triangles);
    tess_counts c;
    st = bsi_tess_measure(&t, &c);
    bsi_tess_free(&t);
    if (st != BS_OK)
        return st;
    if (vertices != NULL)
        *vertices = c.vertices;
    if (triangles != NULL)
        *triangles = c.triangles;
    return BS_OK;
}
