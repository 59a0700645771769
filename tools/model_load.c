/* Inputs as models: STEP, IGES and OBJ files through the model readers, anything else (a .bpt
 * file, a built-in, standard input) as the model of its surface. */
#include "cmds.h"

#include <errno.h>
#include <string.h>

static int from_surface(const char *cmd, const cli_input *in, bs_model **out)
{
    bs_surface *s;
    int rc = cli_load(cmd, in, &s);
    if (rc != CLI_OK)
        return rc;
    bs_status st = bs_model_from_surface(s, out);
    bs_surface_destroy(s);
    if (st == BS_ERR_SIZE)
        return cli_fail(cmd, CLI_INPUT, "%s: no patch", cli_input_name(in));
    if (st == BS_ERR_DIMENSION)
        return cli_fail(cmd, CLI_INPUT, "%s: the patches are not 3-D", cli_input_name(in));
    return st == BS_OK ? CLI_OK : cli_fail(cmd, CLI_INTERNAL, "%s", bs_status_string(st));
}

int cli_load_model(const char *cmd, const cli_input *in, bs_model **out)
{
    *out = NULL;
    const cli_format *fmt = NULL;
    if (in->path != NULL && strcmp(in->path, "-") != 0)
        fmt = in->format ? cli_format_named(in->format) : cli_format_of_path(in->path);
    if (fmt == NULL || fmt->read_model_file == NULL)
        return from_surface(cmd, in, out);
    bs_parse_error err;
    errno = 0;
    bs_status st = fmt->read_model_file(in->path, &err, out);
    if (st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED || st == BS_ERR_SIZE)
        return cli_fail(cmd, CLI_INPUT, "%s:%zu:%zu: %s", in->path, err.line, err.column, err.message);
    if (st == BS_ERR_IO)
        return cli_fail(cmd, CLI_INPUT, "%s: %s%s%s", in->path, err.message, errno ? ": " : "",
                        errno ? strerror(errno) : "");
    if (st != BS_OK)
        return cli_fail(cmd, CLI_INTERNAL, "%s: %s", in->path, bs_status_string(st));
    return CLI_OK;
}

int cli_input_is_model(const cli_input *in)
{
    const cli_format *fmt = NULL;
    if (in->path != NULL && strcmp(in->path, "-") != 0)
        fmt = in->format ? cli_format_named(in->format) : cli_format_of_path(in->path);
    return fmt != NULL && fmt->read_model_file != NULL && strcmp(fmt->name, "obj") != 0;
}
