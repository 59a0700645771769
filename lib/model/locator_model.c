/*
 * The locator of a model (bs_locator_create_model): the locator of the model's patches
 * (lib/query/), told through its trim record (query/locator.h) which hits count and how to report
 * them. A hit counts where its patch point, in its face's native parameters, is inside the face's
 * trims or on them within a small 3-D distance (so that a ray through the edge between two faces,
 * whose trims may stand a little apart in a file, hits one of them); it is reported as the face,
 * its native (u, v) and the outward normal.
 */
#include "model/internal.h"
#include "query/locator.h"

#include <math.h>
#include <stdlib.h>

/* Distance from a trim, relative to the diagonal of the model's control points, within which a
 * point counts as on the trim (and so inside the face): the closeness of the edges of the CAD
 * files read (their own tolerance is about 1e-7 of the part's size). */
#define ON_TRIM 1e-7
/* The same for a closest point: a point of the surface counts as on its face only that near to
 * it, a small part of the 1e-9 (D + d) a closest point is certified within. */
#define ON_TRIM_CLOSEST 1e-10

typedef struct model_trim {
    bsi_loc_trim base; /* first: the locator holds a pointer to it */
    const bs_model *m;
    double tol;        /* ON_TRIM times the diagonal */
    double tight;      /* ON_TRIM_CLOSEST times the diagonal */
    bsi_trim_search *ts; /* the faces' boundaries, for closest points */
} model_trim;

static int inside(const bsi_loc_trim *t, uint32_t patch, double u, double v)
{
    const model_trim *mt = (const model_trim *)t;
    double native[2];
    size_t f = bsi_patch_native(mt->m, patch, u, v, native);
    return bsi_face_covers(mt->m, f, native[0], native[1], mt->tol);
}

static void to_face(const bsi_loc_trim *t, uint32_t patch, double u, double v, uint32_t *face,
                    double uv[2], double nrm[3])
{
    const model_trim *mt = (const model_trim *)t;
    size_t f = bsi_patch_native(mt->m, patch, u, v, uv);
    *face = (uint32_t)f;
    if (mt->m->faces[f].reversed != mt->m->faces[f].swap) /* as bs_model_face_eval */
        for (int c = 0; c < 3; c++)
            nrm[c] = nrm[c] == 0.0 ? 0.0 : -nrm[c];
}

static void release(bsi_loc_trim *t)
{
    bsi_trim_search_free(((model_trim *)t)->ts);
    free(t);
}

/* Where the box st of a patch's domain lies in its face (native box: the axes' maps are
 * increasing, so the corners' images bound it). */
static int box_place(const void *t, uint32_t patch, const double st[4])
{
    const model_trim *mt = t;
    double a[2], b[2];
    size_t f = bsi_patch_native(mt->m, patch, st[0], st[2], a);
    (void)bsi_patch_native(mt->m, patch, st[1], st[3], b);
    double nb[4] = {fmin(a[0], b[0]), fmax(a[0], b[0]), fmin(a[1], b[1]), fmax(a[1], b[1])};
    return bsi_face_box_place(mt->m, f, nb);
}

static int on_face(const void *t, uint32_t patch, double s, double u)
{
    const model_trim *mt = t;
    double native[2];
    size_t f = bsi_patch_native(mt->m, patch, s, u, native);
    return bsi_face_covers(mt->m, f, native[0], native[1], mt->tight);
}

static int boundary(const bsi_loc_trim *t, const double *q, double *best_d, uint32_t *patch,
                    double st[2])
{
    return bsi_trim_search_closest(((const model_trim *)t)->ts, q, best_d, patch, st);
}

bs_status bs_locator_create_model(const bs_model *m, bs_locator **out)
{
    if (out)
        *out = NULL;
    if (m == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    model_trim *mt = malloc(sizeof *mt);
    if (mt == NULL)
        return BS_ERR_NO_MEMORY;
    bs_locator *L = NULL;
    bs_status st = bs_locator_create(m->surface, &L);
    if (st != BS_OK) {
        free(mt);
        return st;
    }
    mt->base.inside = inside;
    mt->base.to_face = to_face;
    mt->base.release = release;
    mt->base.box = box_place;
    mt->base.point = on_face;
    mt->base.boundary = boundary;
    mt->m = m;
    mt->tol = ON_TRIM * L->diag;
    mt->tight = ON_TRIM_CLOSEST * L->diag;
    if ((st = bsi_trim_search_create(m, L->diag, &mt->ts)) != BS_OK) {
        free(mt);
        bs_locator_destroy(L);
        return st;
    }
    L->trim = &mt->base;
    *out = L;
    return BS_OK;
}
