/* OBJ reader (to be written). */
#include "io/internal.h"
#include "model/internal.h"

bs_status bs_model_read_obj(const char *text, size_t len, bs_parse_error *err, bs_model **out)
{
    (void)text; (void)len;
    if (out != NULL)
        *out = NULL;
    (void)bsi_fail(err, 0, 0, "OBJ files are not read yet");
    return BS_ERR_UNSUPPORTED;
}

bs_status bs_model_read_obj_file(const char *path, bs_parse_error *err, bs_model **out)
{
    (void)path;
    return bs_model_read_obj(NULL, 0, err, out);
}

bs_status bs_model_write_obj(const bs_model *m, char *buf, size_t cap, size_t *size)
{
    (void)m; (void)buf; (void)cap; (void)size;
    return BS_ERR_UNSUPPORTED;
}

bs_status bs_model_write_obj_file(const bs_model *m, const char *path)
{
    (void)m; (void)path;
    return BS_ERR_UNSUPPORTED;
}
