/* bezsurf convert: a surface or a model from one file format to another. */
#include "cmds.h"

#include <stdio.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf convert [--from FORMAT] [--to FORMAT] IN OUT\n"
    "       bezsurf convert --builtin NAME [--to FORMAT] OUT\n"
    "Read the surface in IN ('-': standard input) and write it to OUT. Formats: bpt and obj\n"
    "(read and written), iges and step (read only); each is taken from the file's extension\n"
    "(.bpt, .obj, .igs, .iges, .step or .stp) unless --from or --to names it. A STEP or IGES\n"
    "part written as obj keeps its trims (OBJ free-form with trim and hole loops); written as\n"
    "bpt it keeps only its faces' untrimmed patches. OUT is replaced only once it is written\n"
    "completely.\n"
    "  -b, --builtin NAME    teapot, teacup or teaspoon instead of IN\n"
    "      --from FORMAT     the input's format: bpt, obj, iges or step\n"
    "      --to FORMAT       the output's format: bpt or obj\n"
    "  -h, --help            this text\n";

/* Close the output after a library writer, which took its temporary file's name; st is what the
 * writer returned. CLI_OK or the exit code after a message. */
static int finish(const char *cmd, out_file *of, bs_status st)
{
    int rc = CLI_OK;
    if (st == BS_ERR_IO)
        rc = cli_fail_write(cmd, of->path);
    else if (st != BS_OK)
        rc = cli_fail(cmd, st == BS_ERR_NO_MEMORY ? CLI_INTERNAL : CLI_INPUT, "%s: %s", of->path,
                      bs_status_string(st));
    return cli_close_output(cmd, of, rc);
}

/* A trimmed model (STEP, IGES) to OBJ free-form with its trim loops. */
static int convert_model(const char *cmd, const cli_input *in, const char *out, out_file *of)
{
    bs_model *m;
    int rc = cli_load_model(cmd, in, &m);
    if (rc != CLI_OK)
        return rc;
    out_hold(of); /* the library writes through a temporary file of its own */
    bs_status st = bs_model_write_obj_file(m, of->tmp);
    out_release();
    size_t nf = bs_model_face_count(m);
    bs_model_destroy(m);
    if ((rc = finish(cmd, of, st)) != CLI_OK)
        return rc;
    printf("%s: %zu trimmed faces (obj)\n", out, nf);
    return cli_finish(cmd);
}

/* A surface to a .bpt or OBJ file. */
static int convert_surface(const char *cmd, const cli_input *in, const cli_format *fmt, const char *out,
                           out_file *of)
{
    bs_surface *s;
    int rc = cli_load(cmd, in, &s);
    if (rc != CLI_OK)
        return rc;
    out_hold(of);
    bs_status st = fmt->write_file(s, of->tmp);
    out_release();
    size_t np = bs_surface_count(s);
    bs_surface_destroy(s);
    if ((rc = finish(cmd, of, st)) != CLI_OK)
        return rc;
    printf("%s: %zu patches (%s)\n", out, np, fmt->name);
    return cli_finish(cmd);
}

int cmd_convert(int argc, char **argv)
{
    const char *cmd = argv[0], *pos[2] = {NULL, NULL}, *to = NULL;
    size_t npos = 0;
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    for (int i = 1; i < argc; i++) {
        /* operands: IN and OUT ("-" included), and everything after "--" */
        if (in.end_of_options || strcmp(argv[i], "--") == 0 || argv[i][0] != '-' || argv[i][1] == '\0') {
            if (!in.end_of_options && strcmp(argv[i], "--") == 0)
                in.end_of_options = 1;
            else if (npos == 2)
                return cli_usage_error(cmd, "more than IN and OUT", argv[i]);
            else
                pos[npos++] = argv[i];
            continue;
        }
        if (cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return cli_finish(cmd);
        }
        if (strcmp(argv[i], "--to") == 0) {
            if (i + 1 >= argc)
                return cli_usage_error(cmd, "--to needs a format", NULL);
            to = argv[++i];
        } else if (strcmp(argv[i], "--from") == 0 || strcmp(argv[i], "--builtin") == 0 ||
                   strcmp(argv[i], "-b") == 0) {
            int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
            if (r != CLI_NEXT)
                return r;
        } else {
            return cli_usage_error(cmd, "unknown option", argv[i]);
        }
    }
    size_t need = in.given ? 1 : 2; /* a built-in takes IN's place */
    if (npos != need)
        return cli_usage_error(cmd, need == 2 ? "needs IN and OUT" : "needs OUT (and no IN with --builtin)",
                               NULL);
    if (need == 2) {
        in.path = pos[0];
        in.given = 1;
    }
    const char *out = pos[need - 1];
    const cli_format *fmt = to ? cli_format_named(to) : cli_format_of_path(out);
    if (fmt == NULL)
        return to ? cli_usage_error(cmd, "unknown format (bpt, obj)", to)
                  : cli_usage_error(cmd, "no format for this extension: use --to (bpt, obj)", out);
    if (fmt->write_file == NULL)
        return cli_usage_error(cmd, "this format is read, not written", fmt->name);
    out_file of;
    int rc = cli_open_output(cmd, strcmp(out, "-") == 0 ? "./-" : out, &of); /* a file named "-" */
    if (rc != CLI_OK)
        return rc;
    const cli_format *from = NULL;
    if (in.path != NULL && strcmp(in.path, "-") != 0)
        from = in.format ? cli_format_named(in.format) : cli_format_of_path(in.path);
    if (from != NULL && (strcmp(from->name, "step") == 0 || strcmp(from->name, "iges") == 0) &&
        strcmp(fmt->name, "obj") == 0)
        rc = convert_model(cmd, &in, out, &of);
    else
        rc = convert_surface(cmd, &in, fmt, out, &of);
    return cli_close_output(cmd, &of, rc); /* removes the temporary file after a failure */
}
