/* bezsurf closest: the point of a surface, or of a model's trimmed faces, closest to a given
 * point, through a locator. */
#include "cmds.h"

#include <stdio.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf closest [--builtin NAME] X Y Z [FILE]\n"
    "Find the point of the surface closest to (X, Y, Z) over all its patches (a 3-D surface;\n"
    "bs_locator_closest_point: its distance is within 1e-9 (D + d) of the true one d, D the\n"
    "diagonal of the control points' box) and print one line:\n"
    "  PATCH U V x y z DISTANCE\n"
    "the patch id, the parameters on it, the point (what 'bezsurf eval --point PATCH U V' gives)\n"
    "and its distance to (X, Y, Z), numbers with the fewest digits (at most 17) that read back\n"
    "exactly. A STEP or IGES file is a model: the point is the closest of its trimmed faces (on a\n"
    "trim where the surface's own closest point lies outside the face), and the line is\n"
    "  FACE U V x y z DISTANCE\n"
    "with the face id and native face parameters. X, Y and Z are finite numbers and may be\n"
    "negative.\n"
    "Exit status: 0 success, 1 bad command line, 2 bad input, 3 output not written,\n"
    "4 library failure.\n";

int cmd_closest(int argc, char **argv)
{
    const char *cmd = argv[0];
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    double q[3];
    int nq = 0;
    for (int i = 1; i < argc; i++) {
        int num = nq < 3 ? cli_parse_number(argv[i], &q[nq]) : 0; /* "-1.5" is a coordinate, not an option */
        if (num < 0)
            return cli_fail(cmd, CLI_USAGE, "%c is not a finite number: %s (try 'bezsurf %s --help')", "XYZ"[nq],
                            argv[i], cmd);
        if (num > 0) {
            nq++;
            continue;
        }
        int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
        if (r == CLI_NOT_COMMON)
            return cli_usage_error(cmd, "unknown option", argv[i]);
        if (r != CLI_NEXT)
            return r;
    }
    if (nq < 3)
        return cli_usage_error(cmd, "three coordinates X Y Z are needed", NULL);
    bs_surface *s = NULL;
    bs_model *m = NULL;
    int rc = cli_input_is_model(&in) ? cli_load_model(cmd, &in, &m) : cli_load(cmd, &in, &s);
    if (rc != CLI_OK)
        return rc;
    if (s != NULL && bs_surface_dim(s) != 3) {
        bs_surface_destroy(s);
        return cli_fail(cmd, CLI_INPUT, "the surface is not 3-D");
    }
    bs_locator *L = NULL;
    uint32_t patch = UINT32_MAX;
    double uv[2], dist, pos[3];
    const bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    const bs_view uvv[2] = {{&uv[0], 1, 0}, {&uv[1], 1, 0}}, dv = {&dist, 1, 0};
    const bs_view pv[3] = {{&pos[0], 1, 0}, {&pos[1], 1, 0}, {&pos[2], 1, 0}};
    bs_status st = m != NULL ? bs_locator_create_model(m, &L) : bs_locator_create(s, &L);
    if (st == BS_OK)
        st = bs_locator_closest_point(L, 1, qv, &patch, uvv, &dv, pv);
    bs_locator_destroy(L);
    bs_surface_destroy(s);
    bs_model_destroy(m);
    if (st != BS_OK)
        return cli_fail(cmd, CLI_INTERNAL, "%s", bs_status_string(st));
    if (patch == UINT32_MAX)
        return cli_fail(cmd, CLI_INPUT, "the surface has no patches: no closest point");
    printf("%u", patch);
    const double out[6] = {uv[0], uv[1], pos[0], pos[1], pos[2], dist};
    for (int k = 0; k < 6; k++) {
        putchar(' ');
        cli_print_double(out[k]);
    }
    putchar('\n');
    return cli_finish(cmd);
}
