/* The bezsurf command-line tool: subcommands and the helpers they share. */
#ifndef BEZSURF_TOOL_CMDS_H
#define BEZSURF_TOOL_CMDS_H

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

/* ---- helpers (tools/cli.c) ---- */

/* Where the surface comes from: a .bpt file, "-" for standard input, or a built-in name. */
typedef struct cli_input {
    const char *path;    /* NULL: built-in */
    const char *builtin; /* used when path is NULL; "teapot" by default */
} cli_input;

/* 1 if arg is -h or --help. */
int cli_is_help(const char *arg);
/* If argv[*i] is --builtin NAME (or -b NAME), take it into in and advance *i; returns 1 when taken,
 * -1 (after printing a usage error) when NAME is missing, else 0. */
int cli_take_builtin(int argc, char **argv, int *i, cli_input *in);
/* Load the input; on failure print one line to stderr and return CLI_INPUT or CLI_INTERNAL. */
int cli_load(const char *cmd, const cli_input *in, bs_surface **out);
/* Human-readable name of the input, for reports. */
const char *cli_input_name(const cli_input *in);
/* Parse a finite number / a non-negative integer; 1 on success. */
int cli_parse_double(const char *text, double *out);
int cli_parse_size(const char *text, size_t *out);
/* Print "bezsurf CMD: message" to stderr; returns code. */
int cli_fail(const char *cmd, int code, const char *fmt, ...);
/* Flush stdout; CLI_OUTPUT (with a message) if anything failed to be written. */
int cli_finish(const char *cmd);
/* Print x with the fewest of 15, 16, 17 significant digits that read back exactly. */
void cli_print_double(double x);
/* "v0", "u1", "v1", "u0" for BS_SIDE_*. */
const char *cli_side_name(int side);

#endif
