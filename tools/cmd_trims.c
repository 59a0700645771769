/* `bezsurf trims`: a picture of one face's trim loops in its native parameter space. Trims are not
 * read back from the model: the picture is what bs_model_classify makes of the face, a grid of
 * points shaded inside or outside and the boundary traced where the classification flips (found
 * by bisection on the grid's edges and joined cell by cell). */
#include "png.h"
#include "font.h"
#include "cmds.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BISECTIONS 10

static const char usage[] =
    "usage: bezsurf trims [options] [FILE]\n"
    "Draw one face of a model (STEP, IGES or OBJ by its extension, or --from) in its native\n"
    "parameters (u across, v up, the face's parameter box framed): the region inside its trim\n"
    "loops shaded, the loops drawn dark, as bs_model_classify finds them on a grid of points.\n"
    "  -o, --output FILE     output file (default: FILE's name + -trims.png); '-': standard output\n"
    "      --face N          the face to draw (default: the first face with the most loops)\n"
    "      --size N          picture size in pixels, N x N (default 600, 128..4096)\n"
    "      --from FORMAT     read FILE as step, iges or obj whatever its extension\n"
    "  -h, --help            this text\n"
    "Exit status: 0 success, 1 bad command line, 2 bad input, 3 output not written,\n"
    "4 library failure.\n";

typedef struct plot {
    const bs_model *m;
    uint32_t face;
    double box[4];         /* u0 u1 v0 v1 */
    size_t size, x0, y0, sx, sy; /* picture size; the plot's rectangle: top-left corner, sides */
    unsigned char *rgb;
} plot;

static void set_px(const plot *p, long x, long y, const unsigned char c[3])
{
    if (x >= 0 && y >= 0 && (size_t)x < p->size && (size_t)y < p->size)
        memcpy(p->rgb + 3 * ((size_t)y * p->size + (size_t)x), c, 3);
}

/* Pixel coordinates (fractional) of native (u, v). */
static void to_px(const plot *p, double u, double v, double *x, double *y)
{
    *x = (double)p->x0 + (u - p->box[0]) / (p->box[1] - p->box[0]) * (double)p->sx;
    *y = (double)(p->y0 + p->sy) - (v - p->box[2]) / (p->box[3] - p->box[2]) * (double)p->sy;
}

static void line(const plot *p, double xa, double ya, double xb, double yb, int width, const unsigned char c[3])
{
    double len = fmax(fabs(xb - xa), fabs(yb - ya));
    size_t steps = (size_t)ceil(len) + 1;
    for (size_t k = 0; k <= steps; k++) {
        double f = (double)k / (double)steps, x = xa + f * (xb - xa), y = ya + f * (yb - ya);
        for (int dy = 0; dy < width; dy++)
            for (int dx = 0; dx < width; dx++)
                set_px(p, (long)floor(x) + dx - width / 2, (long)floor(y) + dy - width / 2, c);
    }
}

static int classify(const plot *p, size_t n, const double *u, const double *v, unsigned char *in)
{
    uint32_t *faces = calloc(n + 1, sizeof(uint32_t)); /* zeroed: n may be 0 */
    if (faces == NULL)
        return -1;
    for (size_t k = 0; k < n; k++)
        faces[k] = p->face;
    bs_cview cu = {u, n, 0}, cv = {v, n, 0};
    bs_status st = bs_model_classify(p->m, n, faces, &cu, &cv, 0.0, in);
    free(faces);
    for (size_t k = 0; st == BS_OK && k < n; k++)
        in[k] = in[k] != BS_TRIM_OUTSIDE;
    return st == BS_OK ? 0 : -1;
}

/* The boundary between native a (inside) and b (outside), by bisection. */
static void crossing(const plot *p, const double *a, const double *b, double *out)
{
    double lo[2] = {a[0], a[1]}, hi[2] = {b[0], b[1]};
    for (int k = 0; k < BISECTIONS; k++) {
        double mid[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
        unsigned char in = 0;
        if (classify(p, 1, &mid[0], &mid[1], &in) != 0)
            break;
        memcpy(in ? lo : hi, mid, sizeof mid);
    }
    out[0] = 0.5 * (lo[0] + hi[0]);
    out[1] = 0.5 * (lo[1] + hi[1]);
}

/* Shade the grid's cells inside and trace the boundary through the cells whose corners differ. */
static int draw_face(const plot *p, size_t cells)
{
    static const unsigned char shade[3] = {196, 214, 240}, ink[3] = {20, 40, 110};
    size_t n1 = cells + 1, ns = n1 * n1;
    double *u = malloc(ns * sizeof(double) + 1), *v = malloc(ns * sizeof(double) + 1);
    unsigned char *in = malloc(ns + 1);
    int rc = u && v && in ? 0 : -1;
    for (size_t i = 0; rc == 0 && i < n1; i++)
        for (size_t j = 0; j < n1; j++) {
            u[i * n1 + j] = p->box[0] + (p->box[1] - p->box[0]) * (double)i / (double)cells;
            v[i * n1 + j] = p->box[2] + (p->box[3] - p->box[2]) * (double)j / (double)cells;
        }
    if (rc == 0)
        rc = classify(p, ns, u, v, in);
    double cx = (double)p->sx / (double)cells, cy = (double)p->sy / (double)cells;
    /* shading: a cell's quarter around each corner takes that corner's side */
    for (size_t y = 0; rc == 0 && y < p->sy; y++)
        for (size_t x = 0; x < p->sx; x++) {
            size_t i = (size_t)floor(((double)x + 0.5) / cx + 0.5), j = (size_t)floor(((double)(p->sy - y) - 0.5) / cy + 0.5);
            if (i > cells)
                i = cells;
            if (j > cells)
                j = cells;
            if (in[i * n1 + j])
                set_px(p, (long)(p->x0 + x), (long)(p->y0 + y), shade);
        }
    for (size_t i = 0; rc == 0 && i < cells; i++)
        for (size_t j = 0; j < cells; j++) {
            size_t c[4] = {i * n1 + j, (i + 1) * n1 + j, (i + 1) * n1 + j + 1, i * n1 + j + 1};
            double pts[4][2];
            int np = 0;
            for (int e = 0; e < 4; e++) {
                size_t a = c[e], b = c[(e + 1) % 4];
                if (in[a] == in[b])
                    continue;
                double pa[2] = {u[a], v[a]}, pb[2] = {u[b], v[b]};
                crossing(p, in[a] ? pa : pb, in[a] ? pb : pa, pts[np++]);
            }
            for (int k = 0; k + 1 < np; k += 2) {
                double xa, ya, xb, yb;
                to_px(p, pts[k][0], pts[k][1], &xa, &ya);
                to_px(p, pts[k + 1][0], pts[k + 1][1], &xb, &yb);
                line(p, xa, ya, xb, yb, 2, ink);
            }
        }
    /* where the inside reaches the box's sides, the boundary runs along them */
    for (size_t k = 0; rc == 0 && k < cells; k++) {
        size_t side[4][2] = {{k, k + 1}, {cells * n1 + k, cells * n1 + k + 1}, {k * n1, (k + 1) * n1},
                             {k * n1 + cells, (k + 1) * n1 + cells}};
        for (int sd = 0; sd < 4; sd++) {
            size_t a = side[sd][0], b = side[sd][1];
            if (!in[a] && !in[b])
                continue;
            double pa[2] = {u[a], v[a]}, pb[2] = {u[b], v[b]}, xa, ya, xb, yb;
            if (in[a] != in[b])
                crossing(p, in[a] ? pa : pb, in[a] ? pb : pa, in[a] ? pb : pa);
            to_px(p, pa[0], pa[1], &xa, &ya);
            to_px(p, pb[0], pb[1], &xb, &yb);
            line(p, xa, ya, xb, yb, 2, ink);
        }
    }
    free(u);
    free(v);
    free(in);
    return rc;
}

static void label(const plot *p, double value, size_t x, size_t y, size_t s, int right)
{
    static const unsigned char ink[3] = {20, 20, 20};
    char text[32];
    (void)snprintf(text, sizeof text, "%.6g", value);
    size_t w = font_width(text, s);
    font_draw(p->rgb, p->size, p->size, right ? (x > w ? x - w : 0) : x, y, text, s, ink);
}

/* The box's frame, its values at the corners and the axes' names. */
static void draw_axes(const plot *p, const char *title)
{
    static const unsigned char frame[3] = {90, 90, 90}, ink[3] = {20, 20, 20};
    size_t s = p->size >= 450 ? 2 : 1, x1 = p->x0 + p->sx, y1 = p->y0 + p->sy;
    line(p, (double)p->x0, (double)p->y0, (double)x1, (double)p->y0, 1, frame);
    line(p, (double)p->x0, (double)y1, (double)x1, (double)y1, 1, frame);
    line(p, (double)p->x0, (double)p->y0, (double)p->x0, (double)y1, 1, frame);
    line(p, (double)x1, (double)p->y0, (double)x1, (double)y1, 1, frame);
    label(p, p->box[0], p->x0, y1 + 6 * s, s, 0);
    label(p, p->box[1], x1, y1 + 6 * s, s, 1);
    label(p, p->box[2], p->x0 - 6 * s, y1 - 7 * s, s, 1);
    label(p, p->box[3], p->x0 - 6 * s, p->y0, s, 1);
    font_draw(p->rgb, p->size, p->size, (p->x0 + x1) / 2, y1 + 8 * s, "u", 2 * s, ink);
    font_draw(p->rgb, p->size, p->size, p->x0 - 20 * s, (p->y0 + y1) / 2, "v", 2 * s, ink);
    font_draw(p->rgb, p->size, p->size, p->x0, p->y0 - 16 * s, title, s, ink);
}

static const char *const kind_names[9] = {"bezier", "bspline", "plane", "cylinder", "cone",
                                          "sphere", "torus", "revolution", "extrusion"};

static int trims_picture(const char *cmd, const cli_input *in, size_t face, size_t size, out_file *of);

int cmd_trims(int argc, char **argv)
{
    static const char *cmd = "trims";
    cli_input in = {NULL, "teapot", 0, NULL, 0};
    const char *output = NULL;
    size_t face = (size_t)-1, size = 600;
    for (int i = 1; i < argc; i++) {
        int r = cli_common_arg(cmd, usage, argc, argv, &i, &in);
        if (r == CLI_NEXT)
            continue;
        if (r != CLI_NOT_COMMON)
            return r;
        const char *a = argv[i];
        if (i + 1 >= argc)
            return cli_usage_error(cmd, "missing value for", a);
        const char *val = argv[++i];
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            output = val;
        } else if (strcmp(a, "--face") == 0) {
            if (!cli_parse_size(val, &face) || face == (size_t)-1)
                return cli_usage_error(cmd, "bad face id", val);
        } else if (strcmp(a, "--size") == 0) {
            if (!cli_parse_size(val, &size) || size < 128 || size > 4096)
                return cli_usage_error(cmd, "bad size (128..4096)", val);
        } else {
            return cli_usage_error(cmd, "unknown option", a);
        }
    }
    char outbuf[1024];
    if (output == NULL) {
        cli_default_output(&in, "-trims.png", outbuf, sizeof outbuf);
        output = outbuf;
    }
    out_file of;
    int rc = cli_open_output(cmd, output, &of); /* before the work */
    if (rc == CLI_OK)
        rc = trims_picture(cmd, &in, face, size, &of);
    return cli_close_output(cmd, &of, rc);
}

/* The picture of face (the first with the most loops when (size_t)-1) into the output opened.
 * CLI_OK or the exit code after a message. */
static int trims_picture(const char *cmd, const cli_input *in, size_t face, size_t size, out_file *of)
{
    const char *output = of->path;
    bs_model *m = NULL;
    int rc = cli_load_model(cmd, in, &m);
    if (rc != CLI_OK)
        return rc;
    size_t nf = bs_model_face_count(m);
    bs_face_info fi;
    fi.size = sizeof fi;
    if (face == (size_t)-1) {
        size_t best = 0;
        for (size_t f = 0; f < nf; f++)
            if (bs_model_face_info(m, f, &fi) == BS_OK && (face == (size_t)-1 || fi.loop_count > best)) {
                face = f;
                best = fi.loop_count;
            }
    }
    if (face >= nf || bs_model_face_info(m, face, &fi) != BS_OK) {
        rc = cli_fail(cmd, CLI_INPUT, "no face %zu (the model has %zu)", face, nf);
        bs_model_destroy(m);
        return rc;
    }
    plot p;
    memset(&p, 0, sizeof p);
    p.m = m;
    p.face = (uint32_t)face;
    p.box[0] = fi.u0, p.box[1] = fi.u1, p.box[2] = fi.v0, p.box[3] = fi.v1;
    p.size = size;
    size_t margin = size / 7;
    p.x0 = margin + margin / 3;
    p.y0 = margin;
    size_t span = size - p.x0 - margin / 2;
    if (size - p.y0 - margin < span)
        span = size - p.y0 - margin;
    p.sx = p.sy = span;
    /* a plane's u and v are lengths: drawn to the same scale */
    double wu = fi.u1 - fi.u0, wv = fi.v1 - fi.v0;
    if (fi.kind == BS_FACE_PLANE && wu > 0.0 && wv > 0.0) {
        if (wu > wv)
            p.sy = (size_t)fmax(8.0, round((double)span * wv / wu));
        else
            p.sx = (size_t)fmax(8.0, round((double)span * wu / wv));
        p.y0 += span - p.sy;
    }
    p.rgb = malloc(3 * size * size);
    if (p.rgb == NULL) {
        bs_model_destroy(m);
        return cli_fail(cmd, CLI_INTERNAL, "out of memory");
    }
    memset(p.rgb, 255, 3 * size * size);
    char title[96];
    (void)snprintf(title, sizeof title, "face %zu, %s, %zu loops", face,
             fi.kind >= 0 && fi.kind < 9 ? kind_names[fi.kind] : "", fi.loop_count);
    rc = draw_face(&p, span / 3) == 0 ? CLI_OK : cli_fail(cmd, CLI_INTERNAL, "out of memory");
    if (rc == CLI_OK) {
        draw_axes(&p, title);
        rc = cli_write_png(cmd, of, p.rgb, size, size); /* in place before the report */
    }
    if (rc == CLI_OK) {
        FILE *report = strcmp(output, "-") == 0 ? stderr : stdout;
        (void)fprintf(report, "%s: %zux%zu, face %zu of %zu (%s), %zu loops, u %.17g..%.17g, v %.17g..%.17g\n",
                strcmp(output, "-") == 0 ? "<stdout>" : output, size, size, face, nf,
                fi.kind >= 0 && fi.kind < 9 ? kind_names[fi.kind] : "?", fi.loop_count, fi.u0, fi.u1,
                fi.v0, fi.v1);
        rc = cli_finish(cmd);
    }
    free(p.rgb);
    bs_model_destroy(m);
    return rc;
}
