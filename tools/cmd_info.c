/* bezsurf info: what a surface is made of, and for a model (STEP, IGES, OBJ) its faces, edges and
 * shells. */
#include "cmds.h"

#include <stdio.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf info [--builtin NAME] [--from FORMAT] [--tol T] [FILE]\n"
    "Print the number of patches, their degrees, the bounds of the control points (which\n"
    "contain the surface) and the numbers of shared and open edges (sides matched when their\n"
    "control points agree within T per coordinate, default 1e-9). For a model (a STEP or IGES\n"
    "file), also its faces by surface kind, its edges, its shells, open or closed, and its\n"
    "area and the volume its closed shells enclose (on the exact faces, to 1e-9 relative).\n";

static const char *const kind_names[] = {"bezier", "bspline", "plane", "cylinder", "cone",
                                         "sphere", "torus", "revolution", "extrusion"};

/* The model lines: faces by kind, trimmed faces, edges, shells open and closed, instances. */
static void print_model(const bs_model *m)
{
    size_t by_kind[sizeof kind_names / sizeof kind_names[0]] = {0}, trimmed = 0, instances = 0;
    size_t nf = bs_model_face_count(m), ns = bs_model_shell_count(m), closed = 0;
    for (size_t f = 0; f < nf; f++) {
        bs_face_info fi;
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK)
            continue;
        if (fi.kind >= 0 && (size_t)fi.kind < sizeof by_kind / sizeof by_kind[0])
            by_kind[fi.kind]++;
        trimmed += fi.loop_count > 0;
        instances = fi.instance + 1 > instances ? fi.instance + 1 : instances;
    }
    printf("faces: %zu (", nf);
    const char *sep = "";
    for (size_t k = 0; k < sizeof by_kind / sizeof by_kind[0]; k++)
        if (by_kind[k]) {
            printf("%s%s %zu", sep, kind_names[k], by_kind[k]);
            sep = ", ";
        }
    printf("), %zu trimmed\n", trimmed);
    for (size_t sh = 0; sh < ns; sh++)
        closed += bs_model_shell_closed(m, sh) == 1;
    printf("model edges: %zu\nshells: %zu (%zu closed, %zu open)\ninstances: %zu\n",
           bs_model_edge_count(m), ns, closed, ns - closed, instances);
    /* on the exact faces, to 1e-9 relative: more digits than the files' own */
    double area = 0.0, volume = 0.0;
    if (bs_model_properties(m, 1e-9, &area, &volume, NULL) != BS_OK)
        return;
    printf("area: %.12g\n", area);
    if (closed > 0)
        printf("volume: %.12g\n", volume);
    else
        printf("volume: none (no closed shell)\n");
}

int cmd_info(int argc, char **argv)
{
    const char *cmd = argv[0];
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    double tol = 1e-9;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON)
            return r;
        if (strcmp(argv[i], "--tol") == 0) {
            if (i + 1 >= argc || !cli_parse_double(argv[++i], &tol) || tol < 0)
                return cli_fail(cmd, CLI_USAGE, "--tol needs a finite number >= 0");
        } else {
            return cli_usage_error(cmd, "unknown option", argv[i]);
        }
    }
    bs_surface *s;
    bs_model *model = NULL;
    int is_model = cli_input_is_model(&in);
    int rc = is_model ? cli_load_model(cmd, &in, &model) : cli_load(cmd, &in, &s);
    if (rc != CLI_OK)
        return rc;
    if (model != NULL && bs_surface_clone(bs_model_surface(model), &s) != BS_OK) {
        bs_model_destroy(model);
        return cli_fail(cmd, CLI_INTERNAL, "out of memory");
    }
    size_t np = bs_surface_count(s), dim = bs_surface_dim(s), nrat = 0;
    static size_t hist[BS_MAX_DEGREE + 1][BS_MAX_DEGREE + 1];
    memset(hist, 0, sizeof hist);
    double lo[BS_MAX_DIM], hi[BS_MAX_DIM];
    for (size_t c = 0; c < BS_MAX_DIM; c++)
        lo[c] = 1.0 / 0.0, hi[c] = -1.0 / 0.0;
    for (size_t k = 0; k < np; k++) {
        const bs_patch *p = bs_surface_get(s, k);
        size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p), cnt = (m + 1) * (n + 1) * dim;
        hist[m][n]++;
        nrat += (size_t)bs_patch_is_rational(p);
        double ctrl[(BS_MAX_DEGREE + 1) * (BS_MAX_DEGREE + 1) * 3];
        if (dim <= 3 && bs_patch_get_ctrl(p, ctrl, cnt, NULL, 0) == BS_OK)
            for (size_t i = 0; i < cnt; i++) {
                lo[i % dim] = ctrl[i] < lo[i % dim] ? ctrl[i] : lo[i % dim];
                hi[i % dim] = ctrl[i] > hi[i % dim] ? ctrl[i] : hi[i % dim];
            }
    }
    printf("input: %s%s\n", cli_input_name(&in), in.path ? "" : " (built-in)");
    printf("patches: %zu\n", np);
    printf("dimension: %zu\n", dim);
    printf("degrees:");
    for (size_t m = 0; m <= BS_MAX_DEGREE; m++)
        for (size_t n = 0; n <= BS_MAX_DEGREE; n++)
            if (hist[m][n])
                printf(" %zux%zu (%zu)", m, n, hist[m][n]);
    printf("\nrational patches: %zu\n", nrat);
    printf("bounds:");
    static const char axis[3] = {'x', 'y', 'z'};
    for (size_t c = 0; np > 0 && c < dim && c < 3; c++)
    {
        printf("%s %c ", c ? "," : "", axis[c]);
        cli_print_double(lo[c]);
        printf(" .. ");
        cli_print_double(hi[c]);
    }
    printf("%s\n", np > 0 ? "" : " none");
    size_t ne = 0, no = 0;
    bs_status st = bs_surface_continuity(s, tol, 1, NULL, 0, &ne, NULL, 0, &no);
    if (st == BS_OK)
        printf("shared edges: %zu\nopen edges: %zu\n", ne, no);
    if (model != NULL)
        print_model(model);
    bs_model_destroy(model);
    bs_surface_destroy(s);
    if (st != BS_OK)
        return cli_fail(cmd, CLI_INTERNAL, "edges: %s", bs_status_string(st));
    return cli_finish(cmd);
}
