/* The IGES 186 manifold solid B-rep: its 514 shells (the outer one, then the voids), their 510
 * faces with 508 loops (and shells and faces no solid holds: surface models); each entry of a 504 edge list is one model edge, shared by the loops
 * naming it. A loop's parameter-space curves are taken in the loop's direction (as OpenCASCADE
 * writes them); without them, or on planes, the edge's 3-D curve gives the trim (run backwards
 * when the loop's orientation flag is 0). Vertex entries of a loop (poles) give their parameter
 * curves, without an edge. */
#include "io/iges_model.h"

#include <stdlib.h>
#include <string.h>

static bs_status use(igm *m, size_t s, size_t t, long type)
{
    bs_status r = bsi_igm_typed(m, s, t, type);
    if (r == BS_OK && m->slot[t].used)
        return bsi_igm_fail(m, t, 1, "used twice (by DE %zu and another)", 2 * s + 1);
    m->slot[t].used = 1;
    return r;
}

/* The 504 at slot t: each edge's curve. */
static bs_status edge_list(igm *m, size_t t)
{
    igm_slot *e = &m->slot[t];
    if (e->state == IGM_DONE)
        return BS_OK;
    iges_stream st;
    long n;
    bs_status r = bsi_igm_open(m, t, &st);
    if (r == BS_OK)
        r = bsi_iges_int(&m->g, &st, "the number of edges", 1, (long)(st.nrec * st.width / 10), &n);
    if (r != BS_OK)
        return bsi_igm_name(m, t, r);
    /* five fields of two characters at least per edge: the count is bounded by the records */
    e->edge_curve = malloc((size_t)n * sizeof *e->edge_curve);
    e->edge_id = malloc((size_t)n * sizeof *e->edge_id);
    if (e->edge_curve == NULL || e->edge_id == NULL)
        return BS_ERR_NO_MEMORY;
    for (long k = 0; k < n && r == BS_OK; k++) {
        size_t c = 0, v;
        long x;
        if ((r = bsi_igm_ptr(m, t, &st, "the curve pointer", 0, &c, NULL)) == BS_OK &&
            (r = bsi_igm_ptr(m, t, &st, "the start vertex list pointer", 0, &v, NULL)) == BS_OK &&
            (r = bsi_iges_int(&m->g, &st, "the start vertex index", 1, 99999999L, &x)) == BS_OK &&
            (r = bsi_igm_ptr(m, t, &st, "the end vertex list pointer", 0, &v, NULL)) == BS_OK)
            r = bsi_iges_int(&m->g, &st, "the end vertex index", 1, 99999999L, &x);
        e->edge_curve[k] = (long)c;
        e->edge_id[k] = BSI_NO_EDGE;
    }
    if (r == BS_OK)
        r = bsi_igm_rest(m, &st);
    if (r != BS_OK)
        return bsi_igm_name(m, t, r);
    e->nedge = (size_t)n;
    e->state = IGM_DONE;
    return BS_OK;
}

/* The model edge of entry k (1-based) of the edge list at slot t, made on first use. */
static bs_status edge_id(igm *m, size_t s, size_t t, long k, uint32_t *id)
{
    bs_status r = edge_list(m, t);
    igm_slot *e = &m->slot[t];
    if (r != BS_OK)
        return r;
    if ((size_t)k > e->nedge)
        return bsi_igm_fail(m, s, 1, "edge %ld of a list of %zu (DE %zu)", k, e->nedge, 2 * t + 1);
    if (e->edge_id[k - 1] == BSI_NO_EDGE && (r = bsi_model_add_edge(m->model, &e->edge_id[k - 1])) != BS_OK)
        return r;
    *id = e->edge_id[k - 1];
    return BS_OK;
}

/* One 508 loop at slot t of the face of entity f on surface ss. */
static bs_status loop(igm *m, size_t f, size_t t, size_t ss, igm_acc *a)
{
    iges_stream st;
    long n;
    bs_status r = use(m, f, t, 508);
    if (r == BS_OK)
        r = bsi_igm_open(m, t, &st);
    if (r != BS_OK || (r = bsi_iges_int(&m->g, &st, "the number of edges", 1, 99999999L, &n)) != BS_OK)
        return bsi_igm_name(m, t, r);
    const igm_surface *sf = m->slot[ss].surf;
    for (long k = 0; k < n && r == BS_OK; k++) {
        long type, ndx, of, np, isop;
        size_t e, c;
        uint32_t id = BSI_NO_EDGE;
        if ((r = bsi_iges_int(&m->g, &st, "TYPE", 0, 1, &type)) != BS_OK ||
            (r = bsi_igm_ptr(m, t, &st, "the edge or vertex list pointer", 0, &e, NULL)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "NDX", 1, 99999999L, &ndx)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "OF", 0, 1, &of)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "K", 0, 99999999L, &np)) != BS_OK)
            return bsi_igm_name(m, t, r);
        if ((r = bsi_igm_typed(m, t, e, type == 0 ? 504 : 502)) != BS_OK ||
            (type == 0 && (r = edge_id(m, t, e, ndx, &id)) != BS_OK))
            return r;
        int param = np > 0 && sf->param && !sf->plane;
        for (long j = 0; j < np && r == BS_OK; j++) {
            if ((r = bsi_iges_int(&m->g, &st, "ISOP", 0, 1, &isop)) != BS_OK ||
                (r = bsi_igm_ptr(m, t, &st, "a parameter curve pointer", 0, &c, NULL)) != BS_OK)
                return bsi_igm_name(m, t, r);
            if (param)
                r = bsi_igm_trims(m, t, ss, c, 0, 0, j == 0 ? id : BSI_NO_EDGE, a);
        }
        if (r == BS_OK && !param && type == 0)
            r = bsi_igm_trims(m, t, ss, (size_t)m->slot[e].edge_curve[ndx - 1], 1, of == 0, id, a);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        return bsi_igm_name(m, t, r);
    return r == BS_OK ? bsi_igm_close_loop(a) : r;
}

/* One 510 face at slot t of the shell s. */
static bs_status face(igm *m, size_t s, size_t t, int reversed, size_t shell)
{
    iges_stream st;
    size_t ss;
    long n, of;
    igm_acc a;
    memset(&a, 0, sizeof a);
    bs_status r = use(m, s, t, 510);
    if (r == BS_OK)
        r = bsi_igm_open(m, t, &st);
    if (r != BS_OK || (r = bsi_igm_ptr(m, t, &st, "the surface pointer", 0, &ss, NULL)) != BS_OK ||
        (r = bsi_igm_surface(m, ss, 0)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "the number of loops", 1, 99999999L, &n)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "OF", 0, 1, &of)) != BS_OK)
        return bsi_igm_name(m, t, r);
    m->slot[ss].used = 1;
    for (long k = 0; k < n && r == BS_OK; k++) {
        size_t l;
        if ((r = bsi_igm_ptr(m, t, &st, "a loop pointer", 0, &l, NULL)) == BS_OK)
            r = loop(m, t, l, ss, &a);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        r = bsi_igm_name(m, t, r);
    if (r == BS_OK)
        r = bsi_igm_add_face(m, t, ss, &a, reversed, shell);
    bsi_igm_acc_free(&a);
    return r;
}

/* One 514 shell at slot t of the B-rep s; flip: the shell is used against its orientation. */
static bs_status shell_514(igm *m, size_t s, size_t t, int flip, size_t shell)
{
    iges_stream st;
    long n;
    bs_status r = use(m, s, t, 514);
    if (r == BS_OK)
        r = bsi_igm_open(m, t, &st);
    if (r != BS_OK || (r = bsi_iges_int(&m->g, &st, "the number of faces", 1, 99999999L, &n)) != BS_OK)
        return bsi_igm_name(m, t, r);
    for (long k = 0; k < n && r == BS_OK; k++) {
        size_t f;
        long of;
        if ((r = bsi_igm_ptr(m, t, &st, "a face pointer", 0, &f, NULL)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "a face's orientation flag", 0, 1, &of)) != BS_OK)
            return bsi_igm_name(m, t, r);
        r = face(m, t, f, (of == 0) != flip, shell);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        return bsi_igm_name(m, t, r);
    return r;
}

bs_status bsi_igm_brep(igm *m, size_t s, size_t *shell)
{
    iges_stream st;
    size_t t;
    long of, n;
    bs_status r = bsi_igm_open(m, s, &st);
    if (r != BS_OK || (r = bsi_igm_ptr(m, s, &st, "the shell pointer", 0, &t, NULL)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "SOF", 0, 1, &of)) != BS_OK ||
        (r = shell_514(m, s, t, of == 0, (*shell)++)) != BS_OK ||
        (r = bsi_iges_int(&m->g, &st, "the number of voids", 0, 99999999L, &n)) != BS_OK)
        return bsi_igm_name(m, s, r);
    for (long k = 0; k < n && r == BS_OK; k++) {
        if ((r = bsi_igm_ptr(m, s, &st, "a void shell pointer", 0, &t, NULL)) != BS_OK ||
            (r = bsi_iges_int(&m->g, &st, "VOF", 0, 1, &of)) != BS_OK)
            return bsi_igm_name(m, s, r);
        r = shell_514(m, s, t, of == 0, (*shell)++);
    }
    if (r == BS_OK && (r = bsi_igm_rest(m, &st)) != BS_OK)
        return bsi_igm_name(m, s, r);
    return r;
}

bs_status bsi_igm_loose_brep(igm *m, size_t *shell)
{
    bs_status r = BS_OK;
    for (size_t t = 0; r == BS_OK && t < m->nslot; t++)
        if (m->slot[t].type == 514 && !m->slot[t].used)
            r = shell_514(m, t, t, 0, (*shell)++);
    int any = 0;
    for (size_t t = 0; r == BS_OK && t < m->nslot; t++)
        if (m->slot[t].type == 510 && !m->slot[t].used) {
            r = face(m, t, t, 0, *shell);
            any = 1;
        }
    *shell += (size_t)any;
    return r;
}
