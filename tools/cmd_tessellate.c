/* `bezsurf tessellate`: surface to triangle mesh file (OBJ, PLY, STL). */
#include "cmds.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: bezsurf tessellate [options] [FILE]\n"
    "Tessellate a surface from FILE (.bpt, OBJ or IGES by its extension, or --from; '-':\n"
    "standard input; default: the built-in teapot) into a triangle mesh file. A STEP or IGES\n"
    "file is a model: its trimmed faces become one watertight mesh (every edge sampled once and\n"
    "shared by the faces on both sides), and the report says whether it is closed.\n"
    "  -o, --output FILE     output file (default: FILE's name, or the built-in's, + .obj);\n"
    "                        '-': standard output (OBJ unless -f; the counts go to stderr)\n"
    "  -f, --format FMT      obj, ply (binary), ply-ascii or stl (default: from the output's\n"
    "                        extension .obj, .ply or .stl; else obj)\n"
    "  -u, --uniform N[xM]   N x M segments per patch (1..1024)\n"
    "  -t, --tolerance D     adaptive: chordal tolerance D in model units\n"
    "  -r, --relative F      adaptive: tolerance F times the control-net box diagonal\n"
    "                        (default when no rate is given: -r 0.001)\n"
    "  -m, --method M        adaptive: per-patch (one rate per patch, default) or subdivide\n"
    "                        (a quadtree of sub-patches in each patch, fewer triangles)\n"
    "  -b, --builtin NAME    teapot, teacup or teaspoon instead of a file\n"
    "      --from FORMAT     read FILE as bpt, obj or iges whatever its extension\n"
    "  -s, --strips          also build triangle strips (reported, not written)\n"
    "      --reverse         reverse the triangles' winding and the normals (the built-in\n"
    "                        teapot's patches face into the pot: --reverse faces it outwards)\n"
    "      --max-triangles N refuse, before any work, a mesh of more than N triangles\n"
    "                        (default 10000000, about 0.5 GB of memory; 0: no limit)\n"
    "  -h, --help            this text\n"
    "Exit status: 0 success, 1 bad command line, 2 bad input, 3 output not written,\n"
    "4 library failure.\n";

static int format_of(const char *name, int *format)
{
    static const struct { const char *name; int format; } table[] = {
        {"obj", BS_MESH_OBJ}, {"ply", BS_MESH_PLY}, {"ply-ascii", BS_MESH_PLY_ASCII}, {"stl", BS_MESH_STL}};
    for (size_t k = 0; k < sizeof table / sizeof table[0]; k++)
        if (strcmp(name, table[k].name) == 0) {
            *format = table[k].format;
            return 1;
        }
    return 0;
}

static int format_of_path(const char *path)
{
    const char *dot = strrchr(path, '.');
    int format = BS_MESH_OBJ;
    if (dot != NULL && (strcmp(dot, ".ply") == 0 || strcmp(dot, ".PLY") == 0))
        format = BS_MESH_PLY;
    else if (dot != NULL && (strcmp(dot, ".stl") == 0 || strcmp(dot, ".STL") == 0))
        format = BS_MESH_STL;
    return format;
}

/* The mesh file's bytes to standard output: BS_OK, BS_ERR_IO (errno set) or a library status. */
static bs_status write_stdout(const bs_mesh *m, int format)
{
    size_t size = 0;
    bs_status st = bs_mesh_write_memory(m, format, NULL, 0, &size);
    char *buf = st == BS_OK ? malloc(size + 1) : NULL;
    if (st == BS_OK && buf == NULL)
        st = BS_ERR_NO_MEMORY;
    if (st == BS_OK)
        st = bs_mesh_write_memory(m, format, buf, size + 1, &size);
    errno = 0;
    if (st == BS_OK && (fwrite(buf, 1, size, stdout) != size || fflush(stdout) != 0))
        st = BS_ERR_IO;
    free(buf);
    return st;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* 1 when every edge of the mesh is used by two triangles, once in each direction; -1 when that
 * cannot be told (out of memory). */
static int mesh_closed(const bs_mesh *m)
{
    size_t nt = bs_mesh_triangle_count(m);
    uint32_t *tri = malloc((3 * nt + 1) * sizeof(uint32_t));
    uint64_t *e = malloc((3 * nt + 1) * sizeof(uint64_t));
    int closed = tri != NULL && e != NULL && bs_mesh_copy_triangles(m, tri, 3 * nt) == BS_OK ? 1 : -1;
    for (size_t k = 0; closed == 1 && k < 3 * nt; k++)
        e[k] = (uint64_t)tri[k] << 32 | tri[k % 3 == 2 ? k - 2 : k + 1];
    if (closed == 1)
        qsort(e, 3 * nt, sizeof(uint64_t), cmp_u64);
    for (size_t k = 0; closed == 1 && k < 3 * nt; k++) {
        uint64_t back = (e[k] & 0xffffffffu) << 32 | e[k] >> 32;
        if ((k > 0 && e[k] == e[k - 1]) || bsearch(&back, e, 3 * nt, sizeof(uint64_t), cmp_u64) == NULL)
            closed = 0;
    }
    free(tri);
    free(e);
    return closed;
}

/* A STEP or IGES file's model tessellated (uniform rates do not apply to trimmed faces). */
static int tessellate_model(const cli_input *in, const bs_tess_options *o, size_t budget, bs_mesh **out)
{
    bs_model *model = NULL;
    int rc = cli_load_model("tessellate", in, &model);
    if (rc != CLI_OK)
        return rc;
    int trimmed = 0;
    for (size_t f = 0; f < bs_model_face_count(model); f++) {
        bs_face_info info;
        info.size = sizeof info;
        trimmed |= bs_model_face_info(model, f, &info) == BS_OK && info.loop_count > 0;
    }
    if (o->method == BS_TESS_UNIFORM && trimmed) {
        bs_model_destroy(model);
        return cli_fail("tessellate", CLI_USAGE, "a model's trimmed faces take a tolerance (-t or -r), not -u");
    }
    if (o->method == BS_TESS_UNIFORM) {
        /* an IGES file of lone surfaces: their patches, as in 1.1 */
        rc = cli_tessellate("tessellate", bs_model_surface(model), o, budget, out);
        bs_model_destroy(model);
        return rc;
    }
    bs_tess_options b = *o;
    b.method = BS_TESS_SUBDIVIDE;
    b.max_triangles = budget;
    bs_status st = bs_model_tessellate(model, &b, out);
    bs_model_destroy(model);
    if (st == BS_ERR_SIZE && budget != 0)
        return cli_fail("tessellate", CLI_INPUT,
                        "the mesh would have more triangles than the budget of %zu (--max-triangles N raises it, "
                        "0 removes it)",
                        budget);
    if (st == BS_ERR_UNSUPPORTED && (o->flags & BS_TESS_STRIPS))
        return cli_fail("tessellate", CLI_USAGE, "--strips is not available for models");
    if (st != BS_OK)
        return cli_fail("tessellate", st == BS_ERR_DOMAIN ? CLI_INPUT : CLI_INTERNAL, "%s: %s", in->path,
                        bs_status_string(st));
    return CLI_OK;
}

/* The input's mesh: a model's (STEP, IGES) or a surface's. CLI_OK or the exit code after a message. */
static int make_mesh(const cli_input *in, const bs_tess_options *o, size_t budget, bs_mesh **m)
{
    if (cli_input_is_model(in))
        return tessellate_model(in, o, budget, m);
    bs_surface *s = NULL;
    int rc = cli_load("tessellate", in, &s);
    if (rc == CLI_OK)
        rc = cli_tessellate("tessellate", s, o, budget, m);
    bs_surface_destroy(s);
    return rc;
}

/* The mesh file into the output opened (standard output when nothing is). CLI_OK or the exit code
 * after a message. */
static int write_mesh(const bs_mesh *m, int format, out_file *of)
{
    bs_status st = BS_OK;
    if (of->tmp == NULL) {
        st = write_stdout(m, format);
    } else {
        out_hold(of); /* the library writes of->tmp through a temporary file of its own */
        st = bs_mesh_write(m, format, of->tmp);
        out_release();
    }
    if (st == BS_OK)
        return CLI_OK;
    const char *name = of->tmp == NULL ? "standard output" : of->path;
    return st == BS_ERR_IO ? cli_fail_write("tessellate", name)
                           : cli_fail("tessellate", CLI_OUTPUT, "cannot write %s: %s", name, bs_status_string(st));
}

int cmd_tessellate(int argc, char **argv)
{
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    const char *output = NULL;
    int format = -1, mode = 0 /* 0 relative, 1 absolute, 2 uniform */, flags = 0;
    double tol = 1e-3;
    int method = BS_TESS_PER_PATCH;
    size_t nu = 0, nv = 0, budget = CLI_TESSELLATE_MAX_TRIANGLES;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_arg("tessellate", usage, argc, argv, &i, &in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON)
            return r;
        const char *a = argv[i];
        if (strcmp(a, "-s") == 0 || strcmp(a, "--strips") == 0) {
            flags |= BS_TESS_STRIPS;
            continue;
        }
        if (strcmp(a, "--reverse") == 0) {
            flags |= BS_TESS_REVERSE;
            continue;
        }
        if (i + 1 >= argc)
            return cli_usage_error("tessellate", "missing value for", a);
        const char *val = argv[++i];
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            output = val;
        } else if (strcmp(a, "-f") == 0 || strcmp(a, "--format") == 0) {
            if (!format_of(val, &format))
                return cli_usage_error("tessellate", "unknown format", val);
        } else if (strcmp(a, "--max-triangles") == 0) {
            if (cli_parse_budget("tessellate", val, &budget) != CLI_OK)
                return CLI_USAGE;
        } else if (strcmp(a, "-m") == 0 || strcmp(a, "--method") == 0) {
            if (cli_parse_method("tessellate", val, &method) != CLI_OK)
                return CLI_USAGE;
        } else if (strcmp(a, "-u") == 0 || strcmp(a, "--uniform") == 0) {
            char buf[64];
            if (!cli_value("tessellate", a, val, buf, sizeof buf))
                return CLI_USAGE;
            char *x = strchr(buf, 'x');
            if (x != NULL)
                *x = '\0';
            if (!cli_parse_size(buf, &nu) || (x && !cli_parse_size(x + 1, &nv)))
                return cli_usage_error("tessellate", "bad rate", val);
            if (x == NULL)
                nv = nu;
            if (nu < 1 || nv < 1 || nu > BS_TESS_MAX_RATE || nv > BS_TESS_MAX_RATE)
                return cli_fail("tessellate", CLI_USAGE,
                                "%s %s: segments out of range (1..%d) (try 'bezsurf tessellate --help')", a, val,
                                BS_TESS_MAX_RATE);
            mode = 2;
        } else if (strcmp(a, "-t") == 0 || strcmp(a, "--tolerance") == 0 || strcmp(a, "-r") == 0 ||
                   strcmp(a, "--relative") == 0) {
            if (!cli_parse_double(val, &tol) || !(tol > 0.0))
                return cli_usage_error("tessellate", "bad tolerance", val);
            mode = (a[1] == 't' || a[2] == 't') ? 1 : 0;
        } else {
            return cli_usage_error("tessellate", "unknown option", a);
        }
    }
    char outbuf[1024];
    if (output == NULL) {
        cli_default_output(&in,
                           format == BS_MESH_PLY || format == BS_MESH_PLY_ASCII ? ".ply"
                           : format == BS_MESH_STL                              ? ".stl"
                                                                                : ".obj",
                           outbuf, sizeof outbuf);
        output = outbuf;
    }
    if (format < 0)
        format = format_of_path(output);
    int to_stdout = strcmp(output, "-") == 0;
    out_file of;
    int rc = cli_open_output("tessellate", output, &of); /* before the work */
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = mode == 2 ? BS_TESS_UNIFORM : method;
    o.flags = flags | (mode == 0 ? BS_TESS_RELATIVE : 0);
    o.nu = nu;
    o.nv = nv;
    o.tolerance = tol;
    bs_mesh *m = NULL;
    if (rc == CLI_OK)
        rc = make_mesh(&in, &o, budget, &m);
    if (rc == CLI_OK)
        rc = write_mesh(m, format, &of);
    rc = cli_close_output("tessellate", &of, rc);
    if (rc != CLI_OK) {
        bs_mesh_destroy(m);
        return rc;
    }
    FILE *report = to_stdout ? stderr : stdout; /* not into the mesh */
    fprintf(report, "%s: %zu vertices, %zu triangles", to_stdout ? "<stdout>" : output, bs_mesh_vertex_count(m),
            bs_mesh_triangle_count(m));
    if (flags & BS_TESS_STRIPS)
        fprintf(report, ", %zu strips", bs_mesh_strip_count(m));
    if (cli_input_is_model(&in)) {
        int closed = mesh_closed(m);
        fprintf(report, closed == 1 ? ", closed" : closed == 0 ? ", not closed" : "");
    }
    fprintf(report, "\n");
    bs_mesh_destroy(m);
    return cli_finish("tessellate");
}
