/* STEP files written by OpenCASCADE, spoiled one token at a time: every entity reference pointed
 * at a missing entity, every number replaced by a bad one, every enumeration by an unknown one,
 * every entity name by an unknown one, and the text cut short at many places. Each variant must
 * give a model whose faces evaluate to finite points, or a clean error with a position and a
 * message (never a crash, never an error without a place). */
#include "harness.h"

#include <bezsurf.h>
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    char *buf = malloc(1 << 20);
    *len = buf ? fread(buf, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    return buf;
}

static size_t variants, models, errors;

/* Read one variant: a model whose faces' box centres evaluate finite, or an error with a place. */
static void judge(const char *text, size_t len, const char *what, size_t at)
{
    bs_parse_error err;
    bs_model *m = NULL;
    memset(&err, 0, sizeof err);
    bs_status st = bs_model_read_step(text, len, &err, &m);
    variants++;
    if (st == BS_OK) {
        models++;
        for (size_t f = 0; f < bs_model_face_count(m); f++) {
            bs_face_info fi;
            fi.size = sizeof fi;
            CHECK_STATUS(bs_model_face_info(m, f, &fi), BS_OK);
            double u = 0.5 * (fi.u0 + fi.u1), v = 0.5 * (fi.v0 + fi.v1), p[3];
            uint32_t id = (uint32_t)f;
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
            CHECK_STATUS(bs_model_face_eval(m, 1, &id, &cu, &cv, pos, NULL, NULL), BS_OK);
            CHECKF(isfinite(fi.u0) && isfinite(fi.v1), "%s at %zu: a face box not finite", what, at);
        }
        bs_model_destroy(m);
        return;
    }
    errors++;
    CHECKF(m == NULL, "%s at %zu: a model with status %d", what, at, st);
    CHECKF(st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED || st == BS_ERR_NO_MEMORY || st == BS_ERR_SIZE,
           "%s at %zu: status %d", what, at, st);
    CHECKF(err.message[0] != '\0', "%s at %zu: status %d without a message", what, at, st);
    CHECKF(st != BS_ERR_PARSE || err.line > 0, "%s at %zu: a parse error without a line (%s)", what, at, err.message);
}

/* text with [at, at + n) replaced by rep. */
static void replaced(const char *text, size_t len, size_t at, size_t n, const char *rep, const char *what)
{
    size_t r = strlen(rep), out_len = len - n + r;
    char *out = malloc(out_len + 1);
    if (out == NULL)
        return;
    memcpy(out, text, at);
    memcpy(out + at, rep, r);
    memcpy(out + at + r, text + at + n, len - at - n);
    judge(out, out_len, what, at);
    free(out);
}

static void spoil(const char *name, size_t stride)
{
    char path[512];
    size_t len = 0;
    (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, name);
    char *text = slurp(path, &len);
    CHECKF(text != NULL, "cannot read %s", path);
    if (text == NULL)
        return;
    char *data = strstr(text, "DATA;");
    size_t start = data ? (size_t)(data - text) : 0, k = 0;
    for (size_t i = start; i < len; i++) {
        char c = text[i];
        size_t n = 1;
        if (c == '#' && i > 0 && text[i - 1] != '\n') { /* a reference, not an instance's own number */
            while (i + n < len && isdigit((unsigned char)text[i + n]))
                n++;
            if (k++ % stride == 0)
                replaced(text, len, i, n, "#0", "reference");
        } else if ((c == '-' || isdigit((unsigned char)c)) && i > 0 && (text[i - 1] == '(' || text[i - 1] == ',')) {
            while (i + n < len && (isdigit((unsigned char)text[i + n]) || strchr(".E-+", text[i + n])))
                n++;
            if (k++ % stride == 0)
                replaced(text, len, i, n, (k / stride) % 3 == 0 ? "-1." : (k / stride) % 3 == 1 ? "0." : "1.E400", "number");
        } else if (c == '.' && i + 2 < len && isupper((unsigned char)text[i + 1])) {
            while (i + n < len && text[i + n] != '.')
                n++;
            n++;
            if (k++ % stride == 0)
                replaced(text, len, i, n, ".X.", "enumeration");
        } else if (c == '=' && i + 2 < len && text[i + 1] == ' ' && isupper((unsigned char)text[i + 2])) {
            size_t j = i + 2;
            while (j < len && (isupper((unsigned char)text[j]) || text[j] == '_' || isdigit((unsigned char)text[j])))
                j++;
            if (k++ % stride == 0)
                replaced(text, len, i + 2, j - i - 2, "UNKNOWN_THING", "name");
        }
        i += n - 1;
    }
    for (size_t cut = 1; cut < 64; cut += stride > 1 ? 7 : 1) /* the text cut short */
        judge(text, start + (len - start) * cut / 64, "cut", cut);
    free(text);
}

int main(void)
{
    int quick = bs_test_quick();
    spoil("cone.step", quick ? 9 : 1);
    if (!quick) {
        spoil("sphere.step", 1);
        spoil("torus-3d-edges.step", 2);
        spoil("bell.step", 17);
        spoil("duct.step", 37);
        spoil("wedge.step", 3);
    }
    printf("spoiled STEP files: %zu variants, %zu models, %zu clean errors\n", variants, models, errors);
    CHECK(variants > (quick ? 20u : 1000u) && errors > (quick ? 10u : 500u));
    return bs_test_exit("test_step_spoil");
}
