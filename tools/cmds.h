/* The bezsurf command-line tool: subcommands and the helpers they share. */
#ifndef BEZSURF_TOOL_CMDS_H
#define BEZSURF_TOOL_CMDS_H

#include "outfile.h"

#include <bezsurf.h>

/* Exit codes, the same for every subcommand (docs/cli.md). */
#define CLI_OK       0 /* success */
#define CLI_USAGE    1 /* bad command line */
#define CLI_INPUT    2 /* input cannot be read or is invalid (parse error, unknown patch id) */
#define CLI_OUTPUT   3 /* output cannot be written */
#define CLI_INTERNAL 4 /* the library failed (out of memory) */

/* A subcommand gets its own arguments: argv[0] is the subcommand's name. */
typedef int (*cli_run_fn)(int argc, char **argv);

typedef struct cli_command {
    const char *name;
    const char *summary; /* one line for `bezsurf --help` */
    cli_run_fn run;
} cli_command;

/* One declaration per subcommand; each has its own file tools/cmd_<name>.c. */
int cmd_info(int argc, char **argv);
int cmd_eval(int argc, char **argv);
int cmd_continuity(int argc, char **argv);
int cmd_tessellate(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_closest(int argc, char **argv);
int cmd_trims(int argc, char **argv);

/* ---- surface file formats (tools/formats.c) ---- */
typedef struct cli_format {
    const char *name; /* bpt, obj, iges, step */
    const char *exts; /* the file extensions that select it, space-separated */
    bs_status (*read)(const char *text, size_t len, bs_parse_error *err, bs_surface **out);
    bs_status (*read_file)(const char *path, bs_parse_error *err, bs_surface **out);
    bs_status (*write_file)(const bs_surface *s, const char *path); /* NULL: read only */
    /* the model readers (NULL for .bpt: its models are made by bs_model_from_surface) */
    bs_status (*read_model)(const char *text, size_t len, bs_parse_error *err, bs_model **out);
    bs_status (*read_model_file)(const char *path, bs_parse_error *err, bs_model **out);
} cli_format;

/* The format of this name (igs is iges); NULL if none. */
const cli_format *cli_format_named(const char *name);
/* The format a file's extension selects (case ignored); NULL if none. */
const cli_format *cli_format_of_path(const char *path);

/* ---- helpers (tools/cli.c) ---- */

/* Where the surface comes from: a file (.bpt, OBJ or IGES), "-" for standard input, or a built-in
 * name. */
typedef struct cli_input {
    const char *path;    /* NULL: built-in */
    const char *builtin; /* used when path is NULL; "teapot" by default */
    int given;           /* a FILE or --builtin was given (a second one is a usage error) */
    const char *format;  /* --from FORMAT; NULL: the file's extension (.bpt when none matches) */
    int end_of_options;  /* after "--": every argument is an operand */
} cli_input;

/* 1 if arg is -h or --help. */
int cli_is_help(const char *arg);
/* Print "bezsurf CMD: MSG: ARG (try 'bezsurf CMD --help')" (no ": ARG" when arg is NULL);
 * returns CLI_USAGE. */
int cli_usage_error(const char *cmd, const char *msg, const char *arg);

/* What cli_common_arg returns when the subcommand is to go on parsing (exit codes are >= 0). */
#define CLI_NEXT       (-1) /* argv[*i] (and its value) taken: go on with argv[*i + 1] */
#define CLI_NOT_COMMON (-2) /* argv[*i] is an option of the subcommand's own */
/* The arguments every subcommand takes: --builtin NAME (-b NAME), --from FORMAT, -h/--help
 * (prints usage to stdout), "--" (every later argument is an operand, even one starting with '-')
 * and the input FILE (an argument not starting with '-', or "-"; at most one). Returns
 * CLI_NEXT, CLI_NOT_COMMON, or else the exit code the subcommand must return at once. */
int cli_common_arg(const char *cmd, const char *usage, int argc, char **argv, int *i, cli_input *in);
/* Default output name: the input file's name without directory and extension, or the built-in's
 * name ("surface" for standard input), followed by ext. */
void cli_default_output(const cli_input *in, const char *ext, char *out, size_t cap);
/* Load the input; on failure print one line to stderr and return CLI_INPUT or CLI_INTERNAL. A
 * STEP or IGES file is read as a model and its faces' patches are the surface (untrimmed). */
int cli_load(const char *cmd, const cli_input *in, bs_surface **out);
/* Load the input as a model (a .bpt file or built-in: bs_model_from_surface); as cli_load. */
int cli_load_model(const char *cmd, const cli_input *in, bs_model **out);
/* 1 when the input is a STEP or IGES file, which the commands take as a model of trimmed faces
 * (an OBJ file stays its surfaces there, as in 1.1). */
int cli_input_is_model(const cli_input *in);
/* Human-readable name of the input, for reports. */
const char *cli_input_name(const cli_input *in);
/* Parse a finite number / a non-negative integer; 1 on success. */
int cli_parse_double(const char *text, double *out);
/* 1 if text is a whole number that is a finite double (into *out), -1 if it is a whole number
 * that is not (nan, inf, 1e400), 0 if it is not a number. */
int cli_parse_number(const char *text, double *out);
int cli_parse_size(const char *text, size_t *out);
/* Print "bezsurf CMD: message" to stderr; returns code. */
int cli_fail(const char *cmd, int code, const char *fmt, ...);
/* Flush stdout; CLI_OUTPUT (with a message) if anything failed to be written. */
int cli_finish(const char *cmd);
/* Copy the value of option opt into buf (cap bytes); 0 after a usage error if it does not fit. */
int cli_value(const char *cmd, const char *opt, const char *val, char *buf, size_t cap);
/* Before any work: open the output file path (tools/outfile.h: a temporary file beside its target,
 * removed on failure and on SIGINT, SIGTERM and SIGHUP); "-" (standard output) opens nothing.
 * CLI_OK, or CLI_OUTPUT after "cannot write PATH: reason" (an empty name, a directory, FIFO or
 * device, a file the user may not write, a missing directory, a link to a missing file). */
int cli_open_output(const char *cmd, const char *path, out_file *o);
/* Finish the output of cli_open_output: with rc CLI_OK put the file in place, otherwise remove the
 * temporary file. Returns rc, or CLI_OUTPUT after "cannot write PATH: reason". */
int cli_close_output(const char *cmd, out_file *o, int rc);
/* A w x h RGB picture as PNG into the output of cli_open_output, then cli_close_output. */
int cli_write_png(const char *cmd, out_file *o, const unsigned char *rgb, size_t w, size_t h);
/* "cannot write PATH: strerror(errno)"; returns CLI_OUTPUT. */
int cli_fail_write(const char *cmd, const char *path);
/* Print x with the fewest of 15, 16, 17 significant digits that read back exactly. */
void cli_print_double(double x);
/* ---- triangle budget of tessellate and render (tools/budget.c) ---- */
/* Default budgets: tessellate about 0.5 GB of memory at its peak, render about 0.5 GB (and at
 * least one patch at the largest rate, 2 x 1024^2 triangles). */
#define CLI_TESSELLATE_MAX_TRIANGLES ((size_t)10000000)
#define CLI_RENDER_MAX_TRIANGLES ((size_t)4000000)
/* Parse the value of --max-triangles (0: no budget); CLI_OK, or CLI_USAGE after the message. */
int cli_parse_budget(const char *cmd, const char *val, size_t *budget);
/* Parse the value of --method: "per-patch" or "subdivide" (BS_TESS_PER_PATCH, BS_TESS_SUBDIVIDE);
 * CLI_OK, or CLI_USAGE after the message. */
int cli_parse_method(const char *cmd, const char *val, int *method);
/* The mesh of o, or CLI_INPUT before any work when it would have more than budget triangles (0: no
 * budget), after one line naming the count (for subdivision, refused while its trees are built: the
 * line gives the budget); CLI_INPUT or CLI_INTERNAL when the library fails. */
int cli_tessellate(const char *cmd, const bs_surface *s, const bs_tess_options *o, size_t budget, bs_mesh **out);

/* Default budget of render --closest, in steps (tools/budget.c): 0.1 to 0.5 microseconds each
 * (docs/cli.md), so 10 to 50 s of work; 100000 points on bicubic patches take 13 million. */
#define CLI_RENDER_MAX_QUERY_WORK ((size_t)100000000)
/* Parse the value of --max-query-work (0: no budget); CLI_OK, or CLI_USAGE after the message. */
int cli_parse_query_budget(const char *cmd, const char *val, size_t *budget);
/* CLI_OK when n closest points on s fit the budget (0: no budget), else CLI_INPUT after one line
 * naming the estimated work, the patch degrees that price it and the flag that raises it. */
int cli_query_budget(const char *cmd, const bs_surface *s, size_t n, size_t budget);

/* "v0", "u1", "v1", "u0" for BS_SIDE_*. */
const char *cli_side_name(int side);

#endif
