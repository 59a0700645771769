/* bezsurf: inspect and evaluate Bezier surfaces (.bpt, OBJ or IGES files, or the built-in tea set).
 * Usage: bezsurf COMMAND [OPTIONS] [FILE]; see docs/cli.md. */
#include "cmds.h"

#include <stdio.h>
#include <string.h>

/* The subcommands, one line each; add a line (and a declaration in cmds.h) to add one. */
static const cli_command commands[] = {
    {"info",       "patches, degrees, bounds, shared and open edges", cmd_info},
    {"eval",       "points (and normals) at given patch ids and (u,v)", cmd_eval},
    {"continuity", "C0 gap, G1 angle and C1 test across each shared edge", cmd_continuity},
    {"tessellate", "triangle mesh of the surface to an OBJ, PLY or STL file", cmd_tessellate},
    {"render",     "shaded picture of the surface to a PNG file", cmd_render},
    {"convert",    "the surface to another file format (.bpt, OBJ)", cmd_convert},
    {"closest",    "the point of the surface closest to a given point", cmd_closest},
    {"trims",      "one face of a model and its trim loops in its parameters, to a PNG file", cmd_trims},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: bezsurf COMMAND [OPTIONS] [FILE]\n"
               "Inspect Bezier surfaces read from a FILE ('-' for standard input): .bpt, OBJ\n"
               "free-form (.obj) or IGES (.igs, .iges), by its extension or --from bpt|obj|iges;\n"
               "without FILE the built-in teapot is used (--builtin NAME picks another).\n\n"
               "commands:\n");
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
        fprintf(f, "  %-12s %s\n", commands[k].name, commands[k].summary);
    fprintf(f, "\n'bezsurf COMMAND --help' describes a command. --version prints the library version.\n"
               "exit status: 0 ok, 1 bad command line, 2 bad input, 3 output error, 4 library failure\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return CLI_USAGE;
    }
    if (cli_is_help(argv[1])) {
        usage(stdout);
        return cli_finish("--help");
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("bezsurf %s\n", bs_version_string());
        return cli_finish("--version");
    }
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
        if (strcmp(argv[1], commands[k].name) == 0)
            return commands[k].run(argc - 1, argv + 1);
    fprintf(stderr, "bezsurf: unknown command '%s' (try 'bezsurf --help')\n", argv[1]);
    return CLI_USAGE;
}
