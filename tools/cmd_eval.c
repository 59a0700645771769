/* bezsurf eval: points (and normals) of a surface at given patch ids and parameters. */
#include "cmds.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf eval [--builtin NAME] [--normals] --point ID U V [--point ID U V ...] [FILE]\n"
    "Evaluate the surface on patch ID at (U,V) and print one line per point:\n"
    "  ID U V x y z                     (--normals adds: nx ny nz kind)\n"
    "kind is 0 (regular), 1 (limit normal at a degenerate point) or 2 (undefined).\n"
    "Numbers are printed with the fewest digits (at most 17) that read back exactly. U and V may lie outside [0,1];\n"
    "a point where the surface overflows (not a finite number) is an error, exit status 2.\n";

int cmd_eval(int argc, char **argv)
{
    const char *cmd = argv[0];
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    int normals = 0;
    size_t n = 0, maxn = (size_t)argc / 4 + 1;
    uint32_t *ids = malloc(maxn * sizeof(uint32_t));
    double *uv = malloc(2 * maxn * sizeof(double));
    double *out = malloc(6 * maxn * sizeof(double));
    unsigned char *kind = malloc(maxn);
    int rc = (ids && uv && out && kind) ? CLI_OK : cli_fail(cmd, CLI_INTERNAL, "out of memory");
    for (int i = 1; rc == CLI_OK && i < argc; i++) {
        int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON) {
            rc = r; /* after --help too: nothing more to do */
            goto done;
        }
        if (strcmp(argv[i], "--normals") == 0) {
            normals = 1;
        } else if (strcmp(argv[i], "--point") == 0) {
            size_t id;
            if (i + 3 >= argc || !cli_parse_size(argv[i + 1], &id) || id > UINT32_MAX ||
                !cli_parse_double(argv[i + 2], &uv[2 * n]) || !cli_parse_double(argv[i + 3], &uv[2 * n + 1]))
                rc = cli_fail(cmd, CLI_USAGE, "--point needs a patch id and two finite numbers U V");
            else
                ids[n++] = (uint32_t)id;
            i += 3;
        } else {
            rc = cli_usage_error(cmd, "unknown option", argv[i]);
        }
    }
    if (rc == CLI_OK && n == 0)
        rc = cli_fail(cmd, CLI_USAGE, "no point given (--point ID U V)");
    bs_surface *s = NULL;
    if (rc == CLI_OK)
        rc = cli_load(cmd, &in, &s);
    for (size_t k = 0; rc == CLI_OK && k < n; k++)
        if (ids[k] >= bs_surface_count(s))
            rc = cli_fail(cmd, CLI_INPUT, "patch id %u is not below the number of patches, %zu", ids[k],
                          bs_surface_count(s));
    if (rc == CLI_OK && normals && bs_surface_dim(s) != 3)
        rc = cli_fail(cmd, CLI_INPUT, "normals need a 3-D surface");
    if (rc == CLI_OK) {
        size_t dim = bs_surface_dim(s);
        bs_cview u = {uv, n, 2 * sizeof(double)}, v = {uv + 1, n, 2 * sizeof(double)};
        bs_view pos[BS_MAX_DIM], nrm[3];
        for (size_t c = 0; c < 3; c++) {
            pos[c].data = out + c * n;
            pos[c].count = n;
            pos[c].stride = 0;
            nrm[c].data = out + (3 + c) * n;
            nrm[c].count = n;
            nrm[c].stride = 0;
        }
        bs_status st = dim > 3 ? BS_ERR_DIMENSION
                       : normals ? bs_surface_eval_normal(s, n, ids, &u, &v, pos, nrm, kind)
                                 : bs_surface_eval(s, n, ids, &u, &v, pos, NULL, NULL);
        if (st != BS_OK)
            rc = cli_fail(cmd, st == BS_ERR_DIMENSION ? CLI_INPUT : CLI_INTERNAL, "%s", bs_status_string(st));
        /* Far outside [0,1] the polynomial overflows: say so instead of printing nan (before any
         * line is printed). */
        for (size_t k = 0; rc == CLI_OK && k < n; k++)
            for (size_t c = 0; rc == CLI_OK && c < dim; c++)
                if (!isfinite(out[c * n + k]))
                    rc = cli_fail(cmd, CLI_INPUT, "--point %u %.17g %.17g: the surface overflows there", ids[k],
                                  uv[2 * k], uv[2 * k + 1]);
        for (size_t k = 0; rc == CLI_OK && k < n; k++) {
            printf("%u", ids[k]);
            for (size_t c = 0; c < 2; c++) {
                putchar(' ');
                cli_print_double(uv[2 * k + c]);
            }
            for (size_t c = 0; c < dim + (normals ? 3u : 0u); c++) {
                putchar(' ');
                cli_print_double(out[c * n + k]);
            }
            if (normals)
                printf(" %d", kind[k]);
            printf("\n");
        }
        if (rc == CLI_OK)
            rc = cli_finish(cmd);
    }
    bs_surface_destroy(s);
done:
    free(ids);
    free(uv);
    free(out);
    free(kind);
    return rc;
}
