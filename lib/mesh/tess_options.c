/*
 * The tessellation entry points of 1.1: one options struct for every method, budgets refused before
 * any large allocation, and the counts of a mesh without building it.
 */
#include "mesh/subdiv.h"

#include <math.h>

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

bs_status bs_surface_tessellate(const bs_surface *s, const bs_tess_options *o, bs_mesh **out)
{
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    *out = NULL;
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
        return bsi_tess_subdivide_count(s, bsi_tess_absolute_tolerance(s, o->tolerance, o->flags), vertices,
                                        triangles);
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
