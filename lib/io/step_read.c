/* Reading STEP (ISO 10303-21) B-rep models: the text parsed into instances (step_lex.c), then each
 * shell of the file (CLOSED_SHELL, OPEN_SHELL: those of MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS and
 * SHELL_BASED_SURFACE_MODEL alike) one shell of the model per placement of its part in the file's
 * assemblies (step_assembly.c), each of its faces read by step_topo.c.
 * Instances the model does not need (product data, presentation, colours) are never looked at. */
#include "io/step.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The extent of the file's 3-D points, and from it the tolerance of computed trims. */
static void extent(stp *s)
{
    for (int c = 0; c < 3; c++) {
        s->lo[c] = INFINITY;
        s->hi[c] = -INFINITY;
    }
    for (size_t i = 0; i < s->inst.n; i++) {
        double p[3];
        size_t list, n;
        if (!bsi_stp_part(s, i, "CARTESIAN_POINT", &list) || !bsi_stp_arg(s, list, 1, &n) ||
            stp_at(s, n)->kind != STP_LIST || stp_at(s, n)->count != 3 || bsi_stp_point(s, i, 3, p) != BS_OK)
            continue;
        for (int c = 0; c < 3; c++) {
            s->lo[c] = fmin(s->lo[c], p[c]);
            s->hi[c] = fmax(s->hi[c], p[c]);
        }
    }
    double d = 0.0;
    for (int c = 0; c < 3; c++)
        if (s->hi[c] >= s->lo[c])
            d = hypot(d, s->hi[c] - s->lo[c]);
    s->tol = 1e-7 * (d > 0.0 ? d : 1.0);
}

/* The shells used reversed: the voids of BREP_WITH_VOIDS, ORIENTED_CLOSED_SHELL(.., #shell, .F.),
 * whose faces point out of the void (into the solid) as written. */
static bs_status reversed_shells(stp *s)
{
    for (size_t i = 0; i < s->inst.n; i++) {
        size_t list, r;
        int orient;
        bs_status st;
        if (!bsi_stp_part(s, i, "ORIENTED_CLOSED_SHELL", &list))
            continue;
        if ((st = bsi_stp_ref(s, i, list, 2, "the shell", &r)) != BS_OK ||
            (st = bsi_stp_bool(s, i, list, 3, "the orientation", &orient)) != BS_OK)
            return st;
        s->flip[r] = (unsigned char)!orient;
    }
    return BS_OK;
}

/* The faces of shell instance i as model shell `shell`. */
static bs_status shell_faces(stp *s, size_t i, size_t shell, size_t *nface)
{
    size_t list, faces, n;
    bs_status st;
    if (!bsi_stp_part(s, i, "CLOSED_SHELL", &list) && !bsi_stp_part(s, i, "OPEN_SHELL", &list))
        return BS_OK;
    if ((st = bsi_stp_list(s, i, list, 1, "the faces", &faces)) != BS_OK)
        return st;
    for (size_t k = 0; bsi_stp_arg(s, faces, k, &n); k++) {
        size_t f;
        if ((st = bsi_stp_deref(s, i, n, "a face", &f)) != BS_OK)
            return st;
        if (bsi_stp_is(s, f, "ORIENTED_FACE"))
            return bsi_stp_fail(s, f, "%s", "oriented faces are not supported");
        if (!bsi_stp_is(s, f, "ADVANCED_FACE") && !bsi_stp_is(s, f, "FACE_SURFACE"))
            return bsi_stp_fail(s, i, "#%zu is not a face", stp_inst_at(s, f)->id);
        if ((st = bsi_stp_face(s, f, shell, s->flip[i])) != BS_OK)
            return st;
        (*nface)++;
    }
    return BS_OK;
}

/* The faces of shell instance i (0 for other instances). */
static size_t shell_size(const stp *s, size_t i)
{
    size_t list, faces;
    if ((!bsi_stp_part(s, i, "CLOSED_SHELL", &list) && !bsi_stp_part(s, i, "OPEN_SHELL", &list)) ||
        !bsi_stp_arg(s, list, 1, &faces))
        return 0;
    return stp_at(s, faces)->kind == STP_LIST ? stp_at(s, faces)->count : 0;
}

/* Assemblies copy a part once per placement: refuse to place more faces than the file holds or
 * one per STP_BYTES_PER_PLACED_FACE bytes of it, whichever is more, before anything is placed. */
static bs_status placed_cap(stp *s)
{
    size_t own = 0, placed = 0;
    for (size_t i = 0; i < s->inst.n; i++) {
        size_t nf = shell_size(s, i), times;
        bs_status st = nf > 0 ? bsi_stp_placement_count(s, i, &times) : BS_OK;
        if (st != BS_OK)
            return st;
        if (nf == 0)
            continue;
        own += nf;
        placed = times > (SIZE_MAX / 2 - placed) / nf ? SIZE_MAX / 2 : placed + nf * times;
    }
    size_t cap = s->len / STP_BYTES_PER_PLACED_FACE;
    if (placed > own && placed > cap) {
        (void)bsi_fail(s->err, 1, 1, "assemblies place %zu faces, more than one per %d bytes of the file", placed,
                       STP_BYTES_PER_PLACED_FACE);
        return BS_ERR_SIZE;
    }
    return BS_OK;
}

/* Shell instance i once per placement, each a model shell. */
static bs_status placed_shell(stp *s, size_t i, bsi_growing *xf, size_t *shells, size_t *nface)
{
    size_t first;
    bs_status st = bsi_stp_placements(s, i, xf, &first);
    for (size_t k = 0; k < xf->n && st == BS_OK; k++) {
        s->moved = s->as.links.n > 0;
        s->xf = ((const stp_xf *)xf->data)[k];
        s->instance = first + k;
        s->edge_base = s->moved ? (uint32_t)bs_model_edge_count(s->model) : 0;
        st = shell_faces(s, i, (*shells)++, nface);
    }
    s->moved = 0;
    s->instance = 0;
    return st;
}

static bs_status read_model(stp *s)
{
    bs_status st = bsi_stp_lex(s);
    if (st != BS_OK || (st = bsi_stp_index(s)) != BS_OK || (st = bsi_stp_units(s)) != BS_OK ||
        (st = reversed_shells(s)) != BS_OK || (st = bsi_stp_assembly(s)) != BS_OK || (st = placed_cap(s)) != BS_OK)
        return st;
    extent(s);
    if ((st = bsi_model_create(&s->model)) != BS_OK)
        return st;
    size_t shells = 0, nface = 0, advanced = 0;
    bsi_growing xf = {NULL, 0, 0};
    for (size_t i = 0; i < s->inst.n && st == BS_OK; i++) {
        advanced += (size_t)bsi_stp_is(s, i, "ADVANCED_FACE");
        if (bsi_stp_is(s, i, "CLOSED_SHELL") || bsi_stp_is(s, i, "OPEN_SHELL"))
            st = placed_shell(s, i, &xf, &shells, &nface);
    }
    free(xf.data);
    if (st != BS_OK)
        return st;
    if (nface == 0)
        return bsi_fail(s->err, 1, 1, "no B-rep faces: %zu ADVANCED_FACE in %zu shells among %zu entities", advanced,
                        shells, s->inst.n);
    return bsi_model_finish(s->model);
}

bs_status bs_model_read_step(const char *text, size_t len, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    if (len > BSI_FILE_MAX) {
        (void)bsi_fail(err, 1, 1, "%s", "text longer than 256 MiB");
        return BS_ERR_SIZE;
    }
    stp s;
    memset(&s, 0, sizeof s);
    s.text = text != NULL ? text : "";
    s.len = len;
    s.err = err;
    bs_status st = read_model(&s);
    if (st == BS_OK)
        *out = s.model;
    else
        bs_model_destroy(s.model);
    s.model = NULL;
    bsi_stp_free(&s);
    return st;
}

bs_status bs_model_read_step_file(const char *path, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (path == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    char *buf = NULL;
    size_t len = 0;
    bs_status st = bsi_read_file(path, err, &buf, &len);
    if (st == BS_OK)
        st = bs_model_read_step(buf, len, err, out);
    free(buf);
    return st;
}
