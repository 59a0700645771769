/* Helpers shared by the subcommands of the bezsurf tool. */
#include "cmds.h"
#include "outfile.h"
#include "png.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_is_help(const char *arg) { return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0; }

int cli_fail(const char *cmd, int code, const char *fmt, ...)
{
    fprintf(stderr, "bezsurf %s: ", cmd);
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

int cli_usage_error(const char *cmd, const char *msg, const char *arg)
{
    return cli_fail(cmd, CLI_USAGE, "%s%s%s (try 'bezsurf %s --help')", msg, arg ? ": " : "", arg ? arg : "", cmd);
}

/* --builtin NAME or -b NAME: 1 when taken (with *i on NAME), -1 after a usage error, 0 otherwise. */
static int take_builtin(const char *cmd, int argc, char **argv, int *i, cli_input *in)
{
    if (strcmp(argv[*i], "--builtin") != 0 && strcmp(argv[*i], "-b") != 0)
        return 0;
    if (*i + 1 >= argc) {
        cli_fail(cmd, CLI_USAGE, "%s needs a name (teapot, teacup or teaspoon)", argv[*i]);
        return -1;
    }
    if (in->given) {
        cli_usage_error(cmd, "more than one input (a FILE and --builtin, or two of them)", argv[*i + 1]);
        return -1;
    }
    in->builtin = argv[++*i];
    in->path = NULL;
    in->given = 1;
    return 1;
}

/* The options every command shares; CLI_NOT_COMMON for another option. */
static int common_option(const char *cmd, const char *usage, int argc, char **argv, int *i, cli_input *in)
{
    const char *a = argv[*i];
    if (strcmp(a, "--") == 0) { /* the usual end of the options */
        in->end_of_options = 1;
        return CLI_NEXT;
    }
    int b = take_builtin(cmd, argc, argv, i, in);
    if (b != 0)
        return b > 0 ? CLI_NEXT : CLI_USAGE;
    if (cli_is_help(a)) {
        fputs(usage, stdout);
        return cli_finish(cmd);
    }
    if (strcmp(a, "--from") == 0) {
        if (*i + 1 >= argc)
            return cli_usage_error(cmd, "--from needs a format (bpt, obj, iges, step)", NULL);
        if (cli_format_named(argv[*i + 1]) == NULL)
            return cli_usage_error(cmd, "unknown input format (bpt, obj, iges, step)", argv[*i + 1]);
        in->format = argv[++*i];
        return CLI_NEXT;
    }
    return CLI_NOT_COMMON;
}

int cli_common_arg(const char *cmd, const char *usage, int argc, char **argv, int *i, cli_input *in)
{
    const char *a = argv[*i];
    if (!in->end_of_options && a[0] == '-' && a[1] != '\0')
        return common_option(cmd, usage, argc, argv, i, in);
    if (in->given)
        return cli_usage_error(cmd, "more than one input (a FILE and --builtin, or two of them)", a);
    in->path = a; /* "-" included: standard input */
    in->given = 1;
    return CLI_NEXT;
}

void cli_default_output(const cli_input *in, const char *ext, char *out, size_t cap)
{
    const char *base = in->builtin ? in->builtin : "teapot";
    size_t len = strlen(base);
    if (in->path != NULL && strcmp(in->path, "-") == 0) {
        base = "surface";
        len = strlen(base);
    } else if (in->path != NULL) {
        const char *slash = strrchr(in->path, '/');
        base = slash ? slash + 1 : in->path;
        const char *dot = strrchr(base, '.');
        len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    }
    snprintf(out, cap, "%.*s%s", (int)len, base, ext);
}

const char *cli_input_name(const cli_input *in)
{
    if (in->path == NULL)
        return in->builtin ? in->builtin : "teapot";
    return strcmp(in->path, "-") == 0 ? "<stdin>" : in->path;
}

static int read_stdin(const char *cmd, const cli_format *fmt, bs_surface **out)
{
    size_t len = 0, cap = 0;
    char *buf = NULL;
    for (;;) {
        if (len == cap) {
            if (cap >= ((size_t)256 << 20)) { /* full: only the end of the input may follow */
                char extra;
                if (fread(&extra, 1, 1, stdin) == 0)
                    break;
                free(buf);
                return cli_fail(cmd, CLI_INPUT, "<stdin>: more than 256 MiB");
            }
            char *grown = realloc(buf, cap ? 2 * cap : 65536);
            if (grown == NULL) {
                free(buf);
                return cli_fail(cmd, CLI_INTERNAL, "out of memory");
            }
            buf = grown;
            cap = cap ? 2 * cap : 65536;
        }
        size_t got = fread(buf + len, 1, cap - len, stdin);
        len += got;
        if (got == 0)
            break;
    }
    if (ferror(stdin)) {
        free(buf);
        return cli_fail(cmd, CLI_INPUT, "<stdin>: cannot read: %s", strerror(errno));
    }
    bs_parse_error err;
    bs_status st = fmt->read(buf, len, &err, out);
    free(buf);
    if (st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED)
        return cli_fail(cmd, CLI_INPUT, "<stdin>:%zu:%zu: %s", err.line, err.column, err.message);
    if (st != BS_OK)
        return cli_fail(cmd, CLI_INTERNAL, "<stdin>: %s", bs_status_string(st));
    return CLI_OK;
}

int cli_load(const char *cmd, const cli_input *in, bs_surface **out)
{
    *out = NULL;
    if (in->path == NULL) {
        const char *name = in->builtin ? in->builtin : "teapot";
        bs_status st = bs_surface_create_builtin(name, out);
        if (st == BS_ERR_INVALID_ARG)
            return cli_fail(cmd, CLI_INPUT, "no built-in surface named '%s' (teapot, teacup, teaspoon)", name);
        return st == BS_OK ? CLI_OK : cli_fail(cmd, CLI_INTERNAL, "%s", bs_status_string(st));
    }
    /* --from, else the file's extension, else .bpt (the format of standard input too) */
    const cli_format *fmt = in->format ? cli_format_named(in->format) : NULL;
    if (fmt == NULL && strcmp(in->path, "-") != 0)
        fmt = cli_format_of_path(in->path);
    if (fmt == NULL)
        fmt = cli_format_named("bpt");
    if (strcmp(in->path, "-") == 0)
        return read_stdin(cmd, fmt, out);
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    errno = 0;
    bs_status st = fmt->read_file(in->path, &err, out);
    /* a size cap the reader names (B-spline spans past the points per byte) is the input's fault */
    if (st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED || (st == BS_ERR_SIZE && err.message[0] != '\0'))
        return cli_fail(cmd, CLI_INPUT, "%s:%zu:%zu: %s", in->path, err.line, err.column, err.message);
    if (st == BS_ERR_IO) /* the library's reason, and the system's where a system call failed */
        return cli_fail(cmd, CLI_INPUT, "%s: %s%s%s", in->path, err.message, errno ? ": " : "",
                        errno ? strerror(errno) : "");
    if (st != BS_OK)
        return cli_fail(cmd, CLI_INTERNAL, "%s: %s", in->path, bs_status_string(st));
    return CLI_OK;
}

int cli_parse_number(const char *text, double *out)
{
    char *end = NULL;
    double x = strtod(text, &end);
    if (end == text || *end != '\0')
        return 0;
    if (!isfinite(x))
        return -1;
    *out = x;
    return 1;
}

int cli_parse_double(const char *text, double *out)
{
    char *end = NULL;
    double x = strtod(text, &end);
    if (end == text || *end != '\0' || !isfinite(x))
        return 0;
    *out = x;
    return 1;
}

int cli_parse_size(const char *text, size_t *out)
{
    char *end = NULL;
    if (text[0] < '0' || text[0] > '9')
        return 0;
    errno = 0;
    unsigned long long v = strtoull(text, &end, 10);
    if (*end != '\0' || errno != 0 || v > (unsigned long long)(size_t)-1)
        return 0;
    *out = (size_t)v;
    return 1;
}

int cli_finish(const char *cmd)
{
    if (fflush(stdout) != 0 || ferror(stdout))
        return cli_fail(cmd, CLI_OUTPUT, "cannot write the output");
    return CLI_OK;
}

const char *cli_side_name(int side)
{
    static const char *const names[4] = {"v0", "u1", "v1", "u0"};
    return side >= 0 && side < 4 ? names[side] : "?";
}

void cli_print_double(double x)
{
    /* The tool never sets a locale, so printf and strtod use the C notation. */
    char buf[40];
    if (x == 0.0)
        x = 0.0; /* -0 prints as 0: a zero coordinate has no sign worth reading */
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, sizeof buf, "%.*g", prec, x);
        if (prec == 17 || strtod(buf, NULL) == x)
            break;
    }
    fputs(buf, stdout);
}

int cli_value(const char *cmd, const char *opt, const char *val, char *buf, size_t cap)
{
    size_t len = strlen(val);
    if (len >= cap) {
        cli_fail(cmd, CLI_USAGE, "value of %s too long (%zu bytes, at most %zu) (try 'bezsurf %s --help')", opt, len,
                 cap - 1, cmd);
        return 0;
    }
    memcpy(buf, val, len + 1);
    return 1;
}

int cli_open_output(const char *cmd, const char *path, out_file *o)
{
    if (strcmp(path, "-") == 0) { /* standard output: nothing to open */
        memset(o, 0, sizeof *o);
        o->path = path;
        return CLI_OK;
    }
    if (out_open(path, o) == 0)
        return CLI_OK;
    return o->why ? cli_fail(cmd, CLI_OUTPUT, "cannot write %s: %s", path[0] ? path : "''", o->why)
                  : cli_fail_write(cmd, path);
}

int cli_close_output(const char *cmd, out_file *o, int rc)
{
    if (out_close(o, rc == CLI_OK) != 0 && rc == CLI_OK)
        return cli_fail_write(cmd, o->path);
    return rc;
}

int cli_write_png(const char *cmd, out_file *o, const unsigned char *rgb, size_t w, size_t h)
{
    int to_file = o->tmp != NULL, rc = CLI_OK;
    if ((to_file ? png_write_rgb_file(o->f, rgb, w, h) : png_write_rgb("-", rgb, w, h)) != 0)
        rc = cli_fail_write(cmd, to_file ? o->path : "standard output");
    return cli_close_output(cmd, o, rc);
}

int cli_fail_write(const char *cmd, const char *path)
{
    return cli_fail(cmd, CLI_OUTPUT, "cannot write %s: %s", path,
                    errno == EINVAL ? "not a regular file" : strerror(errno ? errno : EIO));
}
