/* `bezsurf render`: shaded picture of a surface as a PNG, with no dependency. */
#include "png.h"
#include "raster.h"
#include "curvature_shade.h"
#include "legend.h"
#include "raycast.h"
#include "closest_draw.h"
#include "line_draw.h"
#include "model_draw.h"
#include "cmds.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Samples of the raster (colour and depth, 16 bytes each): 1 GiB. */
#define RENDER_MAX_SAMPLES ((size_t)1 << 26)

static const char usage[] =
    "usage: bezsurf render [options] [FILE]\n"
    "Render a surface from FILE (.bpt, OBJ or IGES by its extension, or --from; '-': standard\n"
    "input; default: the built-in teapot) to a PNG picture.\n"
    "  -o, --output FILE     output file (default: FILE's name, or the built-in's, + .png);\n"
    "                        '-': standard output (the report goes to stderr)\n"
    "  -b, --builtin NAME    teapot, teacup or teaspoon instead of a file\n"
    "      --from FORMAT     read FILE as bpt, obj or iges whatever its extension\n"
    "      --size WxH        picture size in pixels (default 800x600, each 16..8192)\n"
    "  -a, --azimuth DEG     camera azimuth around the up axis (default -60)\n"
    "  -e, --elevation DEG   camera elevation above the horizon, -90..90 (default 25)\n"
    "      --up y|z          the model's up axis (default z; y for the built-in teacup and teaspoon)\n"
    "  -r, --relative F      tessellation tolerance as a fraction of the model's size (default 0.0002)\n"
    "  -m, --method M        tessellation: per-patch (default) or subdivide\n"
    "      --wire            draw the triangles' edges over the surface (a model file: its\n"
    "                        watertight mesh within -r, each triangle shaded flat)\n"
    "      --faces           colour each face of a model by its surface kind (legend on the right),\n"
    "                        the faces' boundaries dark. A model file (STEP, IGES, OBJ) is drawn\n"
    "                        with each face cut at its trim loops (except with --curvature,\n"
    "                        --patch or --split, which draw its patches whole)\n"
    "      --color R,G,B     base colour, each 0..1 (default 0.72,0.76,0.86)\n"
    "      --curvature mean|gauss\n"
    "                        colour by the mean or Gaussian curvature at the mesh vertices: blue\n"
    "                        negative, light grey 0, red positive, over -R..R, R the larger magnitude\n"
    "                        of the 5th and 95th percentiles by area (0 below 1e-7 of the model's\n"
    "                        scale); dark grey where undefined; a legend on the right (pictures of\n"
    "                        at least 240x100)\n"
    "      --nets            draw the patches' control nets over the surface\n"
    "      --closest N       draw N points around the surface, each joined to its closest point\n"
    "                        on the surface (red), 0..100000\n"
    "      --max-query-work N\n"
    "                        refuse, before any work, --closest points that would cost more than\n"
    "                        N steps: (m+1)(n+1)(m+n+2) a point for patches of degree m x n\n"
    "                        (default 100000000, 10 to 50 s; 0: no limit)\n"
    "      --patch ID        render only patch ID\n"
    "      --split           subdivide every patch at (0.5, 0.5) into four first (with --nets:\n"
    "                        the four sub-nets are drawn)\n"
    "      --ss N            supersampling per axis, 1..4 (default 3); W x H x N^2 samples at most\n"
    "                        67108864 (16 bytes each: 1 GiB), e.g. 8192x8192 with --ss 1\n"
    "      --max-triangles N refuse, before any work, a mesh of more than N triangles\n"
    "                        (default 4000000, about 0.5 GB of memory; 0: no limit)\n"
    "      --rays            cast one ray per sample at the patches (through a locator) instead of\n"
    "                        drawing a tessellation: the same camera, lights and colours; a\n"
    "                        model's rays hit its trimmed faces only\n"
    "  -h, --help            this text\n"
    "Exit status: 0 success, 1 bad command line, 2 bad input, 3 output not written,\n"
    "4 library failure.\n";

typedef struct render_opts {
    cli_input in;
    const char *output;
    size_t w, h, ss, budget;
    double azimuth, elevation, rel, color[3];
    int up_y, up_given, nets, split, wire, method;
    size_t patch;  /* (size_t)-1: all */
    size_t closest; /* --closest N: points of the cloud */
    int curvature; /* 0 none, 1 mean, 2 Gaussian */
    int rays;      /* ray-cast instead of tessellated */
    double unit;   /* the factor unit_scale() applied to the model */
    int faces;     /* --faces */
    model_draw *md; /* a model's trimmed faces (NULL, or md->model NULL: patches drawn whole) */
    out_file *of;   /* the output opened (nothing open: standard output) */
    size_t query_budget; /* --max-query-work */
} render_opts;

static int parse_args(int argc, char **argv, render_opts *o)
{
    for (int i = 1; i < argc; i++) {
        int r = cli_common_arg("render", usage, argc, argv, &i, &o->in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON)
            return r;
        const char *a = argv[i];
        if (strcmp(a, "--faces") == 0) {
            o->faces = 1;
            continue;
        }
        if (strcmp(a, "--nets") == 0 || strcmp(a, "--split") == 0 || strcmp(a, "--rays") == 0 ||
            strcmp(a, "--wire") == 0) {
            if (a[2] == 'n')
                o->nets = 1;
            else if (a[2] == 's')
                o->split = 1;
            else if (a[2] == 'r')
                o->rays = 1;
            else
                o->wire = 1;
            continue;
        }
        if (i + 1 >= argc)
            return cli_usage_error("render", "missing value for", a);
        const char *val = argv[++i];
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            o->output = val;
        } else if (strcmp(a, "--size") == 0) {
            char buf[64];
            if (!cli_value("render", a, val, buf, sizeof buf))
                return CLI_USAGE;
            char *x = strchr(buf, 'x');
            if (x == NULL)
                return cli_usage_error("render", "bad size", val);
            *x = '\0';
            if (!cli_parse_size(buf, &o->w) || !cli_parse_size(x + 1, &o->h) || o->w < 16 ||
                o->h < 16 || o->w > 8192 || o->h > 8192)
                return cli_usage_error("render", "bad size", val);
        } else if (strcmp(a, "-a") == 0 || strcmp(a, "--azimuth") == 0) {
            if (!cli_parse_double(val, &o->azimuth))
                return cli_usage_error("render", "bad azimuth", val);
        } else if (strcmp(a, "-e") == 0 || strcmp(a, "--elevation") == 0) {
            if (!cli_parse_double(val, &o->elevation) || fabs(o->elevation) > 90.0)
                return cli_usage_error("render", "bad elevation", val);
        } else if (strcmp(a, "--up") == 0) {
            if (strcmp(val, "y") != 0 && strcmp(val, "z") != 0)
                return cli_usage_error("render", "bad up axis", val);
            o->up_y = val[0] == 'y';
            o->up_given = 1;
        } else if (strcmp(a, "-r") == 0 || strcmp(a, "--relative") == 0) {
            if (!cli_parse_double(val, &o->rel) || !(o->rel > 0.0))
                return cli_usage_error("render", "bad tolerance", val);
        } else if (strcmp(a, "--color") == 0) {
            char buf[128], *p = buf;
            if (!cli_value("render", a, val, buf, sizeof buf))
                return CLI_USAGE;
            for (int k = 0; k < 3; k++) {
                char *comma = strchr(p, ',');
                if ((comma == NULL) != (k == 2))
                    return cli_usage_error("render", "bad colour", val);
                if (comma)
                    *comma = '\0';
                if (!cli_parse_double(p, &o->color[k]) || o->color[k] < 0.0 || o->color[k] > 1.0)
                    return cli_usage_error("render", "bad colour", val);
                p = comma ? comma + 1 : p;
            }
        } else if (strcmp(a, "--curvature") == 0) {
            if (strcmp(val, "mean") != 0 && strcmp(val, "gauss") != 0)
                return cli_usage_error("render", "bad curvature (mean or gauss)", val);
            o->curvature = val[0] == 'm' ? 1 : 2;
        } else if (strcmp(a, "--closest") == 0) {
            if (!cli_parse_size(val, &o->closest) || o->closest > 100000)
                return cli_usage_error("render", "bad point count for --closest (0..100000)", val);
        } else if (strcmp(a, "--patch") == 0) {
            if (!cli_parse_size(val, &o->patch) || o->patch == (size_t)-1)
                return cli_usage_error("render", "bad patch id", val);
        } else if (strcmp(a, "--max-triangles") == 0) {
            if (cli_parse_budget("render", val, &o->budget) != CLI_OK)
                return CLI_USAGE;
        } else if (strcmp(a, "--max-query-work") == 0) {
            if (cli_parse_query_budget("render", val, &o->query_budget) != CLI_OK)
                return CLI_USAGE;
        } else if (strcmp(a, "-m") == 0 || strcmp(a, "--method") == 0) {
            if (cli_parse_method("render", val, &o->method) != CLI_OK)
                return CLI_USAGE;
        } else if (strcmp(a, "--ss") == 0) {
            if (!cli_parse_size(val, &o->ss) || o->ss < 1 || o->ss > 4)
                return cli_usage_error("render", "bad supersampling", val);
        } else {
            return cli_usage_error("render", "unknown option", a);
        }
    }
    return CLI_NEXT; /* go on */
}

/* Box of all control points (it contains the surface). */
static void surface_box(const bs_surface *s, double lo[3], double hi[3])
{
    for (int c = 0; c < 3; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        size_t n = (bs_patch_degree_u(p) + 1) * (bs_patch_degree_v(p) + 1);
        double *net = malloc(3 * n * sizeof(double));
        if (net == NULL || bs_patch_get_ctrl(p, net, 3 * n, NULL, 0) != BS_OK) {
            free(net);
            continue;
        }
        for (size_t k = 0; k < n; k++)
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], net[3 * k + (size_t)c]);
                hi[c] = fmax(hi[c], net[3 * k + (size_t)c]);
            }
        free(net);
    }
}

/* Vertex colours by the curvature --curvature names; the summary of the values in *cr, in the
 * model's units. The colours are worked out on the surface drawn, the model scaled by o->unit to
 * a size near 1, where every curvature is a finite number; only the reported values are brought
 * back (curvatures scale by 1/unit, Gaussian ones by 1/unit^2), and may overflow there.
 * NULL after an error, with its exit code in *rc. */
static double *curvature_vertex_colors(const render_opts *o, const bs_surface *s, const bs_mesh *m,
                                       const double *pos, const uint32_t *tri, curvature_range *cr, int *rc)
{
    /* Below 1e-7 of the model's scale (1/D, 1/D^2: D the diagonal of its box) a curvature is
     * rounding: a cylinder's Gaussian curvature would be coloured by noise. */
    double lo[3], hi[3];
    surface_box(s, lo, hi);
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double noise = o->curvature == 2 ? 1e-7 / (diag * diag) : 1e-7 / diag;
    size_t nv = bs_mesh_vertex_count(m);
    double *val = malloc(nv * sizeof(double) + 1), *area = malloc(nv * sizeof(double) + 1);
    double *rgb = malloc(3 * nv * sizeof(double) + 1);
    bs_status st = val && area && rgb ? curvature_at_vertices(s, m, o->curvature == 2, val) : BS_ERR_NO_MEMORY;
    if (st == BS_OK) {
        vertex_areas(pos, nv, tri, bs_mesh_triangle_count(m), area);
        if (curvature_summary(val, area, nv, cr) != 0)
            st = BS_ERR_NO_MEMORY;
        else if (!(cr->range >= noise)) /* NaN included: nothing to colour by */
            cr->range = 0.0;
    }
    if (st == BS_OK) {
        curvature_colors(val, nv, cr->range, rgb);
        double back = o->curvature == 2 ? o->unit * o->unit : o->unit;
        cr->range *= back;
        cr->min *= back;
        cr->max *= back;
    }
    free(val);
    free(area);
    if (st != BS_OK) {
        free(rgb);
        *rc = cli_fail("render", CLI_INTERNAL, "%s", bs_status_string(st));
        return NULL;
    }
    return rgb;
}

/* Face the mesh outwards where it encloses a negative signed volume (the teapot's patches face
 * into the pot): the triangles reversed and the normals negated, as BS_TESS_REVERSE would (the
 * curvatures keep the sign of the patches' normals, as bs_patch_eval_curvature gives them).
 * Returns 1 when it did. */
static int face_outwards(const double *pos, double *nrm, size_t nv, uint32_t *tri, size_t nt)
{
    double vol = 0.0;
    for (size_t t = 0; t < nt; t++) {
        const double *p = pos + 3 * (size_t)tri[3 * t], *q = pos + 3 * (size_t)tri[3 * t + 1],
                     *w = pos + 3 * (size_t)tri[3 * t + 2];
        vol += p[0] * (q[1] * w[2] - q[2] * w[1]) - p[1] * (q[0] * w[2] - q[2] * w[0]) +
               p[2] * (q[0] * w[1] - q[1] * w[0]);
    }
    if (!(vol < 0.0))
        return 0;
    for (size_t t = 0; t < nt; t++) {
        uint32_t b = tri[3 * t + 1];
        tri[3 * t + 1] = tri[3 * t + 2];
        tri[3 * t + 2] = b;
    }
    for (size_t k = 0; k < 3 * nv; k++)
        nrm[k] = -nrm[k];
    return 1;
}

/* The tessellated surface into r (framed already), coloured by o->color or by curvature (then *cr
 * holds the range); *ntri receives the triangle count. CLI_OK or the exit code after a message. */
static int draw_mesh(const render_opts *o, const bs_surface *s, raster *r, size_t *ntri, curvature_range *cr)
{
    if (o->md != NULL && o->md->model != NULL)
        return model_draw_faces(o->md, r, o->unit, o->color, o->wire, o->rel, o->budget, ntri);
    bs_tess_options to;
    bs_tess_options_init(&to);
    to.method = o->method;
    to.flags = BS_TESS_RELATIVE;
    to.tolerance = o->rel;
    bs_mesh *m = NULL;
    int rc = cli_tessellate("render", s, &to, o->budget, &m);
    if (rc != CLI_OK)
        return rc;
    size_t nv = bs_mesh_vertex_count(m), nt = bs_mesh_triangle_count(m);
    double *pos = malloc(3 * nv * sizeof(double) + 1), *nrm = malloc(3 * nv * sizeof(double) + 1), *vcol = NULL;
    uint32_t *tri = malloc(3 * nt * sizeof(uint32_t) + 1);
    ptrdiff_t s3 = 3 * sizeof(double);
    bs_view pv[3] = {{pos, nv, s3}, {pos + 1, nv, s3}, {pos + 2, nv, s3}};
    bs_view nvw[3] = {{nrm, nv, s3}, {nrm + 1, nv, s3}, {nrm + 2, nv, s3}};
    rc = CLI_INTERNAL;
    if (!(pos && nrm && tri && bs_mesh_copy_positions(m, pv) == BS_OK && bs_mesh_copy_normals(m, nvw) == BS_OK &&
          bs_mesh_copy_triangles(m, tri, 3 * nt) == BS_OK))
        cli_fail("render", CLI_INTERNAL, "out of memory");
    else if (face_outwards(pos, nrm, nv, tri, nt) >= 0 &&
             (!o->curvature || (vcol = curvature_vertex_colors(o, s, m, pos, tri, cr, &rc)) != NULL))
        rc = CLI_OK;
    if (rc == CLI_OK) {
        raster_mesh(r, pos, nrm, vcol, tri, nt, o->color);
        if (o->wire)
            draw_wire(r, pos, tri, nt);
        *ntri = nt;
    }
    free(vcol);
    free(pos);
    free(nrm);
    free(tri);
    bs_mesh_destroy(m);
    return rc;
}

/* The surface into r (framed already) by one ray per sample; *hits receives the samples that hit.
 * CLI_OK or the exit code after a message. */
static int draw_rays(const render_opts *o, const bs_surface *s, raster *r, size_t *hits)
{
    bs_locator *L = NULL;
    /* a model's trimmed faces through its own locator, in the model's own coordinates */
    int trimmed = o->md != NULL && o->md->model != NULL;
    bs_status st = trimmed ? bs_locator_create_model(o->md->model, &L) : bs_locator_create(s, &L);
    if (st == BS_OK)
        st = raycast_draw(r, L, trimmed ? o->unit : 1.0, o->color, hits);
    bs_locator_destroy(L);
    return st == BS_OK ? CLI_OK : cli_fail("render", CLI_INTERNAL, "%s", bs_status_string(st));
}

static int render(const render_opts *o, const bs_surface *s)
{
    unsigned char *rgb = malloc(o->w * o->h * 3);
    raster r;
    memset(&r, 0, sizeof r);
    double lo[3], hi[3];
    surface_box(s, lo, hi);
    int framed = rgb ? raster_init(&r, o->w, o->h, o->ss, o->azimuth, o->elevation, o->up_y, lo, hi) : -1;
    int rc = framed == 0    ? CLI_OK
             : framed == -2 ? cli_fail("render", CLI_INPUT, "the surface cannot be framed (its size is not a finite number)")
                            : cli_fail("render", CLI_INTERNAL, "out of memory");
    curvature_range cr;
    size_t nt = 0, hits = 0;
    if (rc == CLI_OK) {
        if (o->curvature)
            raster_reserve_right(&r, legend_strip(o->w, o->h));
        else if (o->md != NULL)
            raster_reserve_right(&r, model_draw_legend_strip(o->md, o->w, o->h));
        rc = o->rays ? draw_rays(o, s, &r, &hits) : draw_mesh(o, s, &r, &nt, &cr);
    }
    if (rc == CLI_OK) {
        if (o->nets)
            draw_nets(&r, s);
        if (o->closest > 0) {
            bs_status st = closest_draw(&r, s, o->closest, lo, hi);
            if (st != BS_OK)
                rc = cli_fail("render", CLI_INTERNAL, "%s", bs_status_string(st));
        }
    }
    if (rc == CLI_OK) {
        raster_finish(&r, rgb);
        if (o->curvature)
            legend_draw(rgb, o->w, o->h, o->curvature == 2 ? "K (Gauss)" : "H (mean)", cr.range);
        else if (o->md != NULL && o->md->model != NULL)
            model_draw_legend(o->md, rgb, o->w, o->h);
        rc = cli_write_png("render", o->of, rgb, o->w, o->h); /* in place before the report */
    }
    if (rc == CLI_OK) {
        FILE *report = strcmp(o->output, "-") == 0 ? stderr : stdout; /* not into the picture */
        const char *name = report == stderr ? "<stdout>" : o->output;
        if (o->rays)
            fprintf(report, "%s: %zux%zu, %zu rays, %zu hits\n", name, o->w, o->h, r.W * r.H, hits);
        else
            fprintf(report, "%s: %zux%zu, %zu triangles\n", name, o->w, o->h, nt);
        if (o->curvature)
            fprintf(report, "%s curvature: colours over -%.6g..%.6g; at the vertices from %.6g to %.6g, %zu undefined\n",
                   o->curvature == 2 ? "Gaussian" : "mean", cr.range, cr.range, cr.min, cr.max, cr.undefined);
        rc = cli_finish("render");
    }
    raster_free(&r);
    free(rgb);
    return rc;
}

/* A power of two that brings the largest control coordinate of the patches drawn near 1, so that
 * tiny (down to subnormal) and huge (up to DBL_MAX) models are tessellated, shaded and framed in
 * finite numbers. Scaling by a power of two is exact (the picture does not change), and the
 * exponent is kept well inside the range of a double. */
static double unit_scale(const render_opts *o, const bs_surface *s)
{
    double big = 0.0;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        if (o->patch != (size_t)-1 && i != o->patch)
            continue;
        double lo[3], hi[3];
        if (bs_patch_bounds(bs_surface_get(s, i), lo, hi) == BS_OK)
            for (int c = 0; c < 3; c++)
                big = fmax(big, fmax(fabs(lo[c]), fabs(hi[c])));
    }
    if (!(big > 0.0) || !isfinite(big))
        return 1.0;
    int e = ilogb(big);
    return ldexp(1.0, e < -1000 ? 1000 : e > 1000 ? -1000 : -e);
}

/* The patches to draw: all or --patch ID, scaled by unit_scale(), each split in four with --split. */
static int select_patches(render_opts *o, const bs_surface *s, bs_surface **out)
{
    if (o->patch != (size_t)-1 && o->patch >= bs_surface_count(s))
        return cli_fail("render", CLI_INPUT, "no patch %zu (the surface has %zu)", o->patch, bs_surface_count(s));
    double k = unit_scale(o, s);
    o->unit = k;
    const double affine[12] = {k, 0, 0, 0, 0, k, 0, 0, 0, 0, k, 0};
    bs_status st = bs_surface_create(out);
    for (size_t i = 0; st == BS_OK && i < bs_surface_count(s); i++) {
        if (o->patch != (size_t)-1 && i != o->patch)
            continue;
        bs_patch *p = NULL;
        st = bs_patch_transform(bs_surface_get(s, i), affine, &p);
        if (st == BS_OK && !o->split)
            st = bs_surface_add(*out, p, NULL);
        if (st == BS_OK && o->split) {
            bs_patch *quarter[4] = {NULL, NULL, NULL, NULL};
            st = bs_patch_split4(p, 0.5, 0.5, quarter);
            for (int q = 0; q < 4; q++) {
                if (st == BS_OK)
                    st = bs_surface_add(*out, quarter[q], NULL);
                bs_patch_destroy(quarter[q]);
            }
        }
        bs_patch_destroy(p);
    }
    return st == BS_OK ? CLI_OK : cli_fail("render", CLI_INTERNAL, "%s", bs_status_string(st));
}

/* Load the input, check it and the cost of its queries, and render it. CLI_OK or the exit code
 * after a message. */
static int render_input(render_opts *o)
{
    bs_surface *s = NULL;
    int rc = cli_load("render", &o->in, &s);
    if (rc != CLI_OK)
        return rc;
    if (bs_surface_count(s) == 0)
        rc = cli_fail("render", CLI_INPUT, "the surface has no patches: nothing to render");
    else if (bs_surface_dim(s) != 3)
        rc = cli_fail("render", CLI_INPUT, "the surface is not 3-D");
    bs_surface *picked = NULL;
    if (rc == CLI_OK)
        rc = select_patches(o, s, &picked);
    if (rc == CLI_OK)
        rc = cli_query_budget("render", picked, o->closest, o->query_budget);
    model_draw md = {NULL, 0, 0};
    if (rc == CLI_OK && !o->curvature && !o->split && o->patch == (size_t)-1)
        rc = model_draw_open("render", &o->in, o->faces, &md);
    o->md = &md;
    if (rc == CLI_OK)
        rc = render(o, picked);
    bs_surface_destroy(picked);
    bs_surface_destroy(s);
    model_draw_close(&md);
    return rc;
}

int cmd_render(int argc, char **argv)
{
    render_opts o = {{NULL, "teapot", 0, NULL, 0}, NULL, 800, 600, 3, CLI_RENDER_MAX_TRIANGLES, -60.0, 25.0, 2e-4,
                     {0.72, 0.76, 0.86}, 0, 0, 0, 0, 0, BS_TESS_PER_PATCH, (size_t)-1, 0, 0, 0, 1.0, 0, NULL,
                     NULL, CLI_RENDER_MAX_QUERY_WORK};
    int rc = parse_args(argc, argv, &o);
    if (rc >= 0)
        return rc;
    if (!o.up_given && o.in.path == NULL && strcmp(o.in.builtin, "teapot") != 0)
        o.up_y = 1; /* the teacup and the teaspoon of the tea set are modelled with y up */
    char outbuf[1024];
    if (o.output == NULL) {
        cli_default_output(&o.in, ".png", outbuf, sizeof outbuf);
        o.output = outbuf;
    }
    if (o.rays && o.curvature)
        return cli_usage_error("render", "--rays and --curvature do not go together", NULL);
    if (o.faces && (o.rays || o.curvature || o.split || o.patch != (size_t)-1))
        return cli_usage_error("render", "--faces does not go with --rays, --curvature, --patch or --split", NULL);
    if (o.w * o.h * o.ss * o.ss > RENDER_MAX_SAMPLES) /* each at most 8192 and 4: no overflow */
        return cli_usage_error("render", "--size W x H times --ss N squared exceeds 67108864 samples (1 GiB)",
                               NULL);
    out_file of;
    rc = cli_open_output("render", o.output, &of); /* before the work */
    o.of = &of;
    if (rc == CLI_OK)
        rc = render_input(&o);
    return cli_close_output("render", &of, rc);
}
