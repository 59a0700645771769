/* STEP reader (to be written). */
#include "io/internal.h"
#include "model/internal.h"

bs_status bs_model_read_step(const char *text, size_t len, bs_parse_error *err, bs_model **out)
{
    (void)text; (void)len;
    if (out != NULL)
        *out = NULL;
    (void)bsi_fail(err, 0, 0, "STEP files are not read yet");
    return BS_ERR_UNSUPPORTED;
}

bs_status bs_model_read_step_file(const char *path, bs_parse_error *err, bs_model **out)
{
    (void)path;
    return bs_model_read_step(NULL, 0, err, out);
}
