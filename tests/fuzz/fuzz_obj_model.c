/* libFuzzer target for the OBJ model reader: any byte string must read or fail cleanly (a position
 * with every parse, unsupported and size error); a model read must write (every face of an OBJ
 * model has straight directions), read back with as many faces, and from then on write and read
 * to the same text (the second text equals the third). */
#include <bezsurf.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The text of m, NUL-terminated, in a new buffer; abort() when it cannot be written. */
static char *write_text(const bs_model *m, size_t *n)
{
    if (bs_model_write_obj(m, NULL, 0, n) != BS_OK)
        abort();
    char *text = malloc(*n + 1);
    if (text == NULL || bs_model_write_obj(m, text, *n + 1, n) != BS_OK)
        abort();
    return text;
}

static bs_model *read_back(const char *text, size_t n, size_t faces)
{
    bs_model *m = NULL;
    if (bs_model_read_obj(text, n, NULL, &m) != BS_OK || bs_model_face_count(m) != faces)
        abort();
    return m;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bs_model *m = NULL;
    bs_parse_error err;
    bs_status st = bs_model_read_obj((const char *)data, size, &err, &m);
    if (st != BS_OK) {
        if (m != NULL ||
            ((st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED || st == BS_ERR_SIZE) && (err.line == 0 || err.column == 0)))
            abort();
        return 0;
    }
    size_t faces = bs_model_face_count(m), n1, n2, n3;
    char *t1 = write_text(m, &n1);
    bs_model *m2 = read_back(t1, n1, faces);
    char *t2 = write_text(m2, &n2);
    bs_model *m3 = read_back(t2, n2, faces);
    char *t3 = write_text(m3, &n3);
    if (n2 != n3 || memcmp(t2, t3, n2) != 0)
        abort();
    free(t1);
    free(t2);
    free(t3);
    bs_model_destroy(m);
    bs_model_destroy(m2);
    bs_model_destroy(m3);
    return 0;
}
