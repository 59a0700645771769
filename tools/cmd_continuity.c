/* bezsurf continuity: how the patches meet along each shared edge, and the open edges. */
#include "cmds.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf continuity [--builtin NAME] [--tol T] [--samples N] [FILE]\n"
    "One line per shared edge (sides whose control points agree within T per coordinate,\n"
    "default 1e-9):\n"
    "  patch_a side_a patch_b side_b reversed c0_gap g1_degrees c1 c1_defect flipped samples\n"
    "sides are v0 (v=0), u1 (u=1), v1 (v=1), u0 (u=0); g1_degrees is the largest angle between\n"
    "the tangent planes over N samples along the edge (default 32); c1 is 1 when the\n"
    "cross-boundary derivatives are opposite within T. Then a summary and the open edges.\n";

int cmd_continuity(int argc, char **argv)
{
    const char *cmd = argv[0];
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    double tol = 1e-9;
    size_t samples = 32;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON)
            return r;
        if (strcmp(argv[i], "--tol") == 0) {
            if (i + 1 >= argc || !cli_parse_double(argv[++i], &tol) || tol < 0)
                return cli_fail(cmd, CLI_USAGE, "--tol needs a finite number >= 0");
        } else if (strcmp(argv[i], "--samples") == 0) {
            if (i + 1 >= argc || !cli_parse_size(argv[++i], &samples) || samples < 1 || samples > 4096)
                return cli_fail(cmd, CLI_USAGE, "--samples needs an integer from 1 to 4096");
        } else {
            return cli_usage_error(cmd, "unknown option", argv[i]);
        }
    }
    bs_surface *s;
    int rc = cli_load(cmd, &in, &s);
    if (rc != CLI_OK)
        return rc;
    size_t ne = 0, no = 0;
    bs_edge_continuity *e = NULL;
    bs_open_edge *o = NULL;
    bs_status st = bs_surface_continuity(s, tol, samples, NULL, 0, &ne, NULL, 0, &no);
    if (st == BS_OK) {
        e = malloc((ne ? ne : 1) * sizeof(*e));
        o = malloc((no ? no : 1) * sizeof(*o));
        st = (e && o) ? bs_surface_continuity(s, tol, samples, e, ne, &ne, o, no, &no) : BS_ERR_NO_MEMORY;
    }
    if (st != BS_OK) {
        rc = cli_fail(cmd, st == BS_ERR_DIMENSION ? CLI_INPUT : CLI_INTERNAL, "%s", bs_status_string(st));
    } else {
        const double deg = 180.0 / acos(-1.0);
        double max_gap = 0.0, max_g1 = 0.0;
        size_t nc1 = 0, nflip = 0, worst = 0;
        printf("# %s: patch_a side_a patch_b side_b reversed c0_gap g1_degrees c1 c1_defect flipped samples\n",
               cli_input_name(&in));
        for (size_t k = 0; k < ne; k++) {
            printf("%u %s %u %s %d %.3g %.6g %d %.3g %d %d\n", e[k].patch_a, cli_side_name(e[k].side_a),
                   e[k].patch_b, cli_side_name(e[k].side_b), e[k].reversed, e[k].c0_gap, e[k].g1_angle * deg,
                   e[k].c1, e[k].c1_defect, e[k].flipped, e[k].samples);
            max_gap = fmax(max_gap, e[k].c0_gap);
            if (e[k].g1_angle > max_g1)
                max_g1 = e[k].g1_angle, worst = k;
            nc1 += (size_t)e[k].c1;
            nflip += (size_t)e[k].flipped;
        }
        printf("shared edges: %zu, C1: %zu, orientation flips: %zu\n", ne, nc1, nflip);
        printf("max C0 gap: %.3g\n", max_gap);
        if (ne > 0)
            printf("max G1 angle: %.6g degrees (patch %u %s / patch %u %s)\n", max_g1 * deg, e[worst].patch_a,
                   cli_side_name(e[worst].side_a), e[worst].patch_b, cli_side_name(e[worst].side_b));
        printf("open edges: %zu", no);
        for (size_t k = 0; k < no; k++)
            printf(" %u:%s", o[k].patch, cli_side_name(o[k].side));
        printf("\n");
        rc = cli_finish(cmd);
    }
    free(e);
    free(o);
    bs_surface_destroy(s);
    return rc;
}
