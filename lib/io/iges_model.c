/* Reading an IGES 5.3 file as a model (docs/formats.md): the faces of its 186 B-reps (one shell
 * per 514), of its 144 trimmed surfaces (one shell for the file, edges sewn by the model) and its
 * untrimmed independent 128 surfaces. Every directory entry is parsed at most once (slots). */
#include "io/iges_model.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bs_status bsi_igm_fail(igm *m, size_t s, int f, const char *fmt, ...)
{
    char msg[96];
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(msg, sizeof msg, fmt, ap); // NOLINT(clang-analyzer-valist.Uninitialized)
    va_end(ap);
    size_t rec = m->g.first[IGES_D] + 2 * s + (size_t)(f - 1) / 10;
    m->named = 1;
    return bsi_fail(m->g.err, rec + 1, (size_t)((f - 1) % 10) * 8 + 1, "entity %ld (DE %zu): %s",
                    m->slot[s].type, 2 * s + 1, msg);
}

bs_status bsi_igm_name(igm *m, size_t s, bs_status st)
{
    bs_parse_error *e = m->g.err;
    if (st == BS_ERR_NO_MEMORY || st == BS_OK || m->named)
        return st;
    if (st != BS_ERR_PARSE) { /* the model layer refused the geometry */
        (void)bsi_igm_fail(m, s, 1, "geometry refused by the model (status %d)", (int)st);
        return st == BS_ERR_UNSUPPORTED ? st : BS_ERR_PARSE;
    }
    m->named = 1;
    if (e != NULL) {
        char msg[sizeof e->message];
        memcpy(msg, e->message, sizeof msg);
        msg[sizeof msg - 1] = '\0';
        char head[48];
        int n = snprintf(head, sizeof head, "entity %ld (DE %zu): ", m->slot[s].type, 2 * s + 1);
        size_t hl = n > 0 ? (size_t)n : 0, ml = strlen(msg); /* the head fits: two numbers of 8 digits */
        if (ml > sizeof e->message - 1 - hl)
            ml = sizeof e->message - 1 - hl; /* a message cut to the buffer is fine */
        memcpy(e->message, head, hl);
        memcpy(e->message + hl, msg, ml);
        e->message[hl + ml] = '\0';
    }
    return st;
}

bs_status bsi_igm_open(igm *m, size_t s, iges_stream *st)
{
    long type;
    bs_status r = bsi_iges_open(&m->g, 2 * s, st);
    if (r == BS_OK)
        r = bsi_iges_int(&m->g, st, "the entity type of the directory entry", m->slot[s].type, m->slot[s].type, &type);
    return bsi_igm_name(m, s, r);
}

bs_status bsi_igm_ref(igm *m, size_t s, const iges_stream *st, size_t pos, long ptr, size_t *out)
{
    if (ptr < 1 || ptr % 2 == 0 || (size_t)ptr >= m->g.count[IGES_D])
        return bsi_igm_name(m, s, bsi_iges_fail_at(&m->g, st, pos, "pointer %ld to no directory entry", ptr));
    *out = (size_t)(ptr - 1) / 2;
    return BS_OK;
}

bs_status bsi_igm_ptr(igm *m, size_t s, iges_stream *st, const char *what, int zero_ok, size_t *out,
                      int *none)
{
    long ptr;
    size_t pos = st->pos;
    bs_status r = bsi_iges_int(&m->g, st, what, zero_ok ? 0 : 1, 99999999L, &ptr);
    if (r != BS_OK)
        return bsi_igm_name(m, s, r);
    if (none != NULL)
        *none = ptr == 0;
    if (ptr == 0 && zero_ok) {
        *out = 0;
        return BS_OK;
    }
    return bsi_igm_ref(m, s, st, pos, ptr, out);
}

bs_status bsi_igm_typed(igm *m, size_t s, size_t t, long type)
{
    if (m->slot[t].type == type)
        return BS_OK;
    return bsi_igm_fail(m, s, 1, "pointer to entity %ld (DE %zu) where %ld is needed", m->slot[t].type, 2 * t + 1,
                        type);
}

bs_status bsi_igm_rest(igm *m, iges_stream *st)
{
    return bsi_iges_rest(&m->g, st);
}

static void free_slots(igm *m)
{
    for (size_t s = 0; s < m->nslot; s++) {
        igm_slot *e = &m->slot[s];
        for (size_t k = 0; k < e->npieces; k++)
            bsi_curve_free(&e->pieces[k]);
        free(e->pieces);
        if (e->surf != NULL) {
            bsi_curve_free(&e->surf->curve);
            free(e->surf->data);
            free(e->surf);
        }
        free(e->mat);
        free(e->edge_curve);
        free(e->edge_id);
    }
    free(m->slot);
}

/* The types of the file's entities for the message of a file without a surface. */
static bs_status no_surface(igm *m)
{
    char list[64] = "";
    size_t used = 0, listed = 0;
    long types[6];
    for (size_t s = 0; s < m->nslot && listed < 6; s++) {
        int seen = 0;
        for (size_t t = 0; t < listed && !seen; t++)
            seen = types[t] == m->slot[s].type;
        if (seen)
            continue;
        types[listed] = m->slot[s].type;
        int n = snprintf(list + used, sizeof list - used, "%s%ld", listed ? ", " : "", m->slot[s].type);
        if (n < 0 || (size_t)n >= sizeof list - used)
            break;
        used += (size_t)n;
        listed++;
    }
    return bsi_fail(m->g.err, m->g.first[IGES_D] + 1, 1, "no surface read: %zu entities of types %s",
                    m->nslot, list);
}

static bs_status read_faces(igm *m)
{
    bs_status st = BS_OK;
    size_t shell = 0;
    for (size_t s = 0; st == BS_OK && s < m->nslot; s++)
        if (m->slot[s].type == 186)
            st = bsi_igm_brep(m, s, &shell);
    if (st == BS_OK)
        st = bsi_igm_loose_brep(m, &shell);
    for (size_t s = 0; st == BS_OK && s < m->nslot; s++)
        if (m->slot[s].type == 144 || m->slot[s].type == 143)
            st = bsi_igm_trimmed(m, s, shell);
    for (size_t s = 0; st == BS_OK && s < m->nslot; s++) {
        long status;
        if (m->slot[s].type != 128 || m->slot[s].used)
            continue;
        if ((st = bsi_iges_de_field(&m->g, 2 * s, 9, &status)) == BS_OK && status / 10000 % 100 == 0)
            st = bsi_igm_untrimmed(m, s, shell); /* an independent surface no face trims */
    }
    if (st == BS_OK && bs_model_face_count(m->model) == 0)
        return no_surface(m);
    return st == BS_OK ? bsi_model_finish(m->model) : st;
}

bs_status bs_model_read_iges(const char *text, size_t len, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (out == NULL || (text == NULL && len > 0))
        return BS_ERR_INVALID_ARG;
    if (len > BSI_FILE_MAX)
        return BS_ERR_SIZE;
    igm m;
    memset(&m, 0, sizeof m);
    m.g.text = text;
    m.g.len = len;
    m.g.err = err;
    m.g.pdelim = ',';
    m.g.rdelim = ';';
    bs_status st = bsi_iges_records(&m.g);
    if (st == BS_OK)
        st = bsi_iges_global(&m.g);
    if (st == BS_OK) {
        m.nslot = m.g.count[IGES_D] / 2; /* records present, two per entry */
        m.slot = calloc(m.nslot ? m.nslot : 1, sizeof *m.slot);
        st = m.slot == NULL ? BS_ERR_NO_MEMORY : BS_OK;
    }
    for (size_t s = 0; st == BS_OK && s < m.nslot; s++)
        if ((st = bsi_iges_de_field(&m.g, 2 * s, 1, &m.slot[s].type)) == BS_OK)
            st = bsi_iges_de_field(&m.g, 2 * s, 15, &m.slot[s].form);
    if (st == BS_OK)
        st = bsi_model_create(&m.model);
    if (st == BS_OK)
        st = read_faces(&m);
    free_slots(&m);
    free(m.vals.data);
    bsi_iges_free(&m.g);
    if (st != BS_OK) {
        bs_model_destroy(m.model);
        return st;
    }
    *out = m.model;
    return BS_OK;
}

bs_status bs_model_read_iges_file(const char *path, bs_parse_error *err, bs_model **out)
{
    if (out != NULL)
        *out = NULL;
    if (path == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    char *data;
    size_t size;
    bs_status st = bsi_read_file(path, err, &data, &size);
    if (st != BS_OK)
        return st;
    st = bs_model_read_iges(data, size, err, out);
    free(data);
    return st;
}
