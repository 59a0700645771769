/* Trimmed faces of a model drawn for display: see model_draw.h. Each patch is sampled on a grid
 * whose spacing follows the lengths of its control polygons; the samples are classified against
 * their face's trims, triangles wholly inside are drawn, those crossing the boundary are clipped
 * where the classification flips (found by bisection in the patch's (s,t)). */
#include "model_draw.h"
#include "font.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_TRIANGLES ((size_t)300000) /* at most, whatever the picture's size */
#define MIN_TRIANGLES ((size_t)20000)
#define MAX_RATE 400
#define BISECTIONS 6

void model_draw_kind_color(int kind, double rgb[3])
{
    static const double palette[9][3] = {
        {0.70, 0.70, 0.70}, /* Bezier */
        {0.85, 0.55, 0.80}, /* B-spline */
        {0.55, 0.72, 0.90}, /* plane */
        {0.95, 0.65, 0.35}, /* cylinder */
        {0.55, 0.82, 0.50}, /* cone */
        {0.92, 0.45, 0.45}, /* sphere */
        {0.95, 0.85, 0.40}, /* torus */
        {0.50, 0.80, 0.80}, /* revolution */
        {0.70, 0.60, 0.90}, /* extrusion */
    };
    int k = kind >= 0 && kind < 9 ? kind : 0;
    memcpy(rgb, palette[k], sizeof palette[k]);
}

static const char *const kind_names[9] = {"bezier", "bspline", "plane", "cylinder", "cone",
                                          "sphere", "torus", "revolution", "extrusion"};

int model_draw_open(const char *cmd, const cli_input *in, int faces, model_draw *md)
{
    md->model = NULL;
    md->faces = faces;
    md->kinds = 0;
    const cli_format *fmt = NULL;
    if (in->path != NULL && strcmp(in->path, "-") != 0)
        fmt = in->format ? cli_format_named(in->format) : cli_format_of_path(in->path);
    if (!faces && (fmt == NULL || fmt->read_model_file == NULL))
        return CLI_OK; /* a surface drawn as before; with --faces: the model of the surface */
    int rc = cli_load_model(cmd, in, &md->model);
    if (rc != CLI_OK || faces)
        return rc;
    /* without trims (an OBJ file of Bezier patches) the patches are drawn as before */
    for (size_t f = 0; f < bs_model_face_count(md->model); f++) {
        bs_face_info fi;
        fi.size = sizeof fi;
        if (bs_model_face_info(md->model, f, &fi) == BS_OK && fi.loop_count > 0)
            return CLI_OK;
    }
    model_draw_close(md);
    return CLI_OK;
}

void model_draw_close(model_draw *md)
{
    bs_model_destroy(md->model);
    md->model = NULL;
}

/* One patch being drawn: its grid's samples (s, t, class, position, normal) and where the
 * triangles and boundary segments go. */
typedef struct patch_grid {
    const bs_model *m;
    const bs_patch *p;
    uint32_t id;
    size_t nu, nv;
    double tol, unit;
    double *s, *t, *pos, *nrm; /* (nu+1)(nv+1) samples; pos, nrm 3 each, scaled */
    unsigned char *in;         /* 1 inside or on the boundary */
    double *cross;             /* 3 x 2 per sample: the boundary's (s,t) on the grid edges from it
                                  along s, along t and diagonally (NaN: not found yet) */
    double color[3];
    int box_side[4];           /* s = 0, s = 1, t = 0, t = 1 lie on the face's box */
} patch_grid;

typedef struct draw_out {
    raster *r;
    double *tri_pos, *tri_nrm; /* a batch of triangles, 9 doubles each */
    size_t ntri, cap;
    double *seg;               /* boundary segments, 6 doubles each (scaled positions) */
    size_t nseg, seg_cap;
    size_t drawn;
    int wire;
    const double *color;
} draw_out;

static int inside_at(const patch_grid *g, double s, double t)
{
    uint32_t face;
    double u, v;
    bs_cview cs = {&s, 1, 0}, ct = {&t, 1, 0};
    bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}};
    unsigned char where = BS_TRIM_OUTSIDE;
    if (bs_model_patch_to_face(g->m, 1, &g->id, &cs, &ct, &face, uv) != BS_OK || face == UINT32_MAX)
        return 0;
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    if (bs_model_classify(g->m, 1, &face, &cu, &cv, g->tol, &where) != BS_OK)
        return 0;
    return where != BS_TRIM_OUTSIDE;
}

static void eval_point(const patch_grid *g, double s, double t, double *p, double *n)
{
    bs_cview cs = {&s, 1, 0}, ct = {&t, 1, 0};
    bs_view pv[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
    bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
    if (bs_patch_eval_normal(g->p, 1, &cs, &ct, pv, nv, NULL) != BS_OK)
        p[0] = p[1] = p[2] = n[0] = n[1] = NAN;
    for (int c = 0; c < 3; c++)
        p[c] *= g->unit;
    if (!(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2])))
        n[0] = n[1] = 0.0, n[2] = 1.0;
}

/* The boundary between an inside sample a and an outside one b, by bisection in (s,t). */
static void crossing(const patch_grid *g, const double *a, const double *b, double *st)
{
    double lo[2] = {a[0], a[1]}, hi[2] = {b[0], b[1]};
    for (int k = 0; k < BISECTIONS; k++) {
        double mid[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
        if (inside_at(g, mid[0], mid[1]))
            memcpy(lo, mid, sizeof mid);
        else
            memcpy(hi, mid, sizeof mid);
    }
    st[0] = lo[0];
    st[1] = lo[1];
}

static int grow(void **buf, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t n = *cap ? 2 * *cap : 1024;
    while (n < need)
        n *= 2;
    void *p = realloc(*buf, n * size);
    if (p == NULL)
        return -1;
    *buf = p;
    *cap = n;
    return 0;
}

static void flush(draw_out *o)
{
    if (o->ntri == 0)
        return;
    uint32_t *idx = malloc(3 * o->ntri * sizeof(uint32_t));
    if (idx != NULL) {
        for (size_t k = 0; k < 3 * o->ntri; k++)
            idx[k] = (uint32_t)k;
        raster_mesh(o->r, o->tri_pos, o->tri_nrm, NULL, idx, o->ntri, o->color);
        if (o->wire) {
            static const double ink[3] = {0.08, 0.09, 0.14};
            for (size_t k = 0; k < o->ntri; k++)
                for (size_t e = 0; e < 3; e++)
                    raster_line(o->r, o->tri_pos + 9 * k + 3 * e, o->tri_pos + 9 * k + 3 * ((e + 1) % 3), 0.6, ink);
        }
    }
    free(idx);
    o->drawn += o->ntri;
    o->ntri = 0;
}

static int emit_triangle(draw_out *o, const double *p[3], const double *n[3])
{
    size_t cap = o->cap;
    if (grow((void **)&o->tri_pos, &cap, o->ntri + 1, 9 * sizeof(double)) != 0)
        return -1;
    if (cap != o->cap) { /* tri_nrm grows with tri_pos: the same capacity */
        double *nn = realloc(o->tri_nrm, cap * 9 * sizeof(double));
        if (nn == NULL)
            return -1;
        o->tri_nrm = nn;
        o->cap = cap;
    }
    for (int k = 0; k < 3; k++) {
        memcpy(o->tri_pos + 9 * o->ntri + 3 * (size_t)k, p[k], 3 * sizeof(double));
        memcpy(o->tri_nrm + 9 * o->ntri + 3 * (size_t)k, n[k], 3 * sizeof(double));
    }
    o->ntri++;
    return 0;
}

static int emit_segment(draw_out *o, const double *a, const double *b)
{
    if (grow((void **)&o->seg, &o->seg_cap, o->nseg + 1, 6 * sizeof(double)) != 0)
        return -1;
    memcpy(o->seg + 6 * o->nseg, a, 3 * sizeof(double));
    memcpy(o->seg + 6 * o->nseg + 3, b, 3 * sizeof(double));
    o->nseg++;
    return 0;
}

/* The boundary on the grid edge between samples a and b (one inside), found once per edge. */
static void edge_crossing(const patch_grid *g, size_t a, size_t b, double *st)
{
    size_t lo = a < b ? a : b, d = a < b ? b - a : a - b;
    double *c = g->cross + 6 * lo + (d == 1 ? 2 : d == g->nv + 1 ? 0 : 4);
    if (isnan(c[0])) {
        size_t i = g->in[a] ? a : b, o = g->in[a] ? b : a;
        double si[2] = {g->s[i], g->t[i]}, so[2] = {g->s[o], g->t[o]};
        crossing(g, si, so, c);
    }
    st[0] = c[0];
    st[1] = c[1];
}

/* Triangle of samples i[0..2]: drawn whole when all are inside, clipped at the boundary when some
 * are, the boundary's piece kept as a segment. */
static int triangle(const patch_grid *g, draw_out *o, const size_t i[3])
{
    int nin = g->in[i[0]] + g->in[i[1]] + g->in[i[2]];
    if (nin == 0)
        return 0;
    if (nin == 3) {
        const double *p[3] = {g->pos + 3 * i[0], g->pos + 3 * i[1], g->pos + 3 * i[2]};
        const double *n[3] = {g->nrm + 3 * i[0], g->nrm + 3 * i[1], g->nrm + 3 * i[2]};
        return emit_triangle(o, p, n);
    }
    /* the polygon of the inside part: corners inside and crossings, in order */
    double poly_p[4][3], poly_n[4][3], cross_p[2][3];
    int np = 0, nc = 0;
    for (int k = 0; k < 3; k++) {
        size_t a = i[k], b = i[(k + 1) % 3];
        if (g->in[a]) {
            memcpy(poly_p[np], g->pos + 3 * a, sizeof poly_p[np]);
            memcpy(poly_n[np], g->nrm + 3 * a, sizeof poly_n[np]);
            np++;
        }
        if (g->in[a] != g->in[b]) {
            double st[2];
            edge_crossing(g, a, b, st);
            eval_point(g, st[0], st[1], poly_p[np], poly_n[np]);
            memcpy(cross_p[nc++], poly_p[np], sizeof cross_p[0]);
            np++;
        }
    }
    for (int k = 1; k + 1 < np; k++) {
        const double *p[3] = {poly_p[0], poly_p[k], poly_p[k + 1]};
        const double *n[3] = {poly_n[0], poly_n[k], poly_n[k + 1]};
        if (emit_triangle(o, p, n) != 0)
            return -1;
    }
    return nc == 2 ? emit_segment(o, cross_p[0], cross_p[1]) : 0;
}

/* The grid's pieces along the patch's sides that lie on the face's box: edges of the face where
 * its trims run along its box (or its seam). */
static int box_sides(const patch_grid *g, draw_out *o)
{
    for (int side = 0; side < 4; side++) {
        if (!g->box_side[side])
            continue;
        size_t len = side < 2 ? g->nv : g->nu;
        for (size_t k = 0; k < len; k++) {
            size_t a, b;
            if (side < 2) {
                size_t row = side == 0 ? 0 : g->nu;
                a = row * (g->nv + 1) + k;
                b = a + 1;
            } else {
                size_t col = side == 2 ? 0 : g->nv;
                a = k * (g->nv + 1) + col;
                b = a + g->nv + 1;
            }
            if (!g->in[a] && !g->in[b])
                continue;
            double pa[3], pb[3], nrm[3];
            memcpy(pa, g->pos + 3 * a, sizeof pa);
            memcpy(pb, g->pos + 3 * b, sizeof pb);
            if (g->in[a] != g->in[b]) {
                double st[2];
                edge_crossing(g, a, b, st);
                eval_point(g, st[0], st[1], g->in[a] ? pb : pa, nrm);
            }
            if (emit_segment(o, pa, pb) != 0)
                return -1;
        }
    }
    return 0;
}

/* Lengths of the control polygons along u and along v (the longest row, column). */
static void net_lengths(const bs_patch *p, double *lu, double *lv)
{
    size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p), cnt = (m + 1) * (n + 1);
    double *net = malloc(3 * cnt * sizeof(double));
    *lu = *lv = 0.0;
    if (net == NULL || bs_patch_get_ctrl(p, net, 3 * cnt, NULL, 0) != BS_OK) {
        free(net);
        return;
    }
    for (size_t b = 0; b <= n; b++) {
        double len = 0.0;
        for (size_t a = 0; a < m; a++) {
            const double *x = net + 3 * (a * (n + 1) + b), *y = net + 3 * ((a + 1) * (n + 1) + b);
            len += sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
        }
        *lu = fmax(*lu, len);
    }
    for (size_t a = 0; a <= m; a++) {
        double len = 0.0;
        for (size_t b = 0; b < n; b++) {
            const double *x = net + 3 * (a * (n + 1) + b), *y = x + 3;
            len += sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
        }
        *lv = fmax(*lv, len);
    }
    free(net);
}

static size_t rate(double len, double k)
{
    double n = ceil(k * len);
    return !(n >= 2.0) ? 2 : n > MAX_RATE ? MAX_RATE : (size_t)n;
}

/* Sample, classify and draw patch g->id. */
static int draw_patch(patch_grid *g, draw_out *o)
{
    size_t ns = (g->nu + 1) * (g->nv + 1);
    uint32_t *ids = malloc(ns * sizeof(uint32_t)), *faces = malloc(ns * sizeof(uint32_t));
    double *uv = malloc(2 * ns * sizeof(double));
    g->s = malloc(ns * sizeof(double));
    g->t = malloc(ns * sizeof(double));
    g->pos = malloc(3 * ns * sizeof(double));
    g->nrm = malloc(3 * ns * sizeof(double));
    g->in = malloc(ns);
    g->cross = malloc(6 * ns * sizeof(double));
    int rc = ids && faces && uv && g->s && g->t && g->pos && g->nrm && g->in && g->cross ? 0 : -1;
    for (size_t k = 0; rc == 0 && k < 6 * ns; k++)
        g->cross[k] = NAN;
    for (size_t a = 0; rc == 0 && a <= g->nu; a++)
        for (size_t b = 0; b <= g->nv; b++) {
            size_t k = a * (g->nv + 1) + b;
            ids[k] = g->id;
            g->s[k] = (double)a / (double)g->nu;
            g->t[k] = (double)b / (double)g->nv;
        }
    ptrdiff_t d3 = 3 * sizeof(double);
    bs_cview cs = {g->s, ns, 0}, ct = {g->t, ns, 0}, cu = {uv, ns, 0}, cv = {uv + ns, ns, 0};
    bs_view uvv[2] = {{uv, ns, 0}, {uv + ns, ns, 0}};
    bs_view pv[3] = {{g->pos, ns, d3}, {g->pos + 1, ns, d3}, {g->pos + 2, ns, d3}};
    bs_view nv[3] = {{g->nrm, ns, d3}, {g->nrm + 1, ns, d3}, {g->nrm + 2, ns, d3}};
    if (rc == 0 && (bs_model_patch_to_face(g->m, ns, ids, &cs, &ct, faces, uvv) != BS_OK ||
                    bs_model_classify(g->m, ns, faces, &cu, &cv, g->tol, g->in) != BS_OK ||
                    bs_patch_eval_normal(g->p, ns, &cs, &ct, pv, nv, NULL) != BS_OK))
        rc = -1;
    for (size_t k = 0; rc == 0 && k < ns; k++) {
        g->in[k] = g->in[k] != BS_TRIM_OUTSIDE;
        for (int c = 0; c < 3; c++)
            g->pos[3 * k + (size_t)c] *= g->unit;
        double *n = g->nrm + 3 * k;
        if (!(isfinite(n[0]) && isfinite(n[1]) && isfinite(n[2])))
            n[0] = n[1] = 0.0, n[2] = 1.0;
    }
    for (size_t a = 0; rc == 0 && a < g->nu; a++)
        for (size_t b = 0; rc == 0 && b < g->nv; b++) {
            size_t k00 = a * (g->nv + 1) + b, k10 = k00 + g->nv + 1;
            size_t t1[3] = {k00, k10, k10 + 1}, t2[3] = {k00, k10 + 1, k00 + 1};
            if (triangle(g, o, t1) != 0 || triangle(g, o, t2) != 0)
                rc = -1;
        }
    if (rc == 0 && box_sides(g, o) != 0)
        rc = -1;
    free(ids);
    free(faces);
    free(uv);
    free(g->s);
    free(g->t);
    free(g->pos);
    free(g->nrm);
    free(g->in);
    free(g->cross);
    g->cross = NULL;
    g->s = g->t = g->pos = g->nrm = NULL;
    g->in = NULL;
    return rc;
}

/* Which sides of patch p lie on its face's box (native u0, u1, v0, v1). */
static void find_box_sides(const bs_model *m, uint32_t p, const bs_face_info *fi, int *side)
{
    static const double st[4][2] = {{0.0, 0.5}, {1.0, 0.5}, {0.5, 0.0}, {0.5, 1.0}};
    double wu = 1e-9 * (fi->u1 - fi->u0), wv = 1e-9 * (fi->v1 - fi->v0);
    for (int k = 0; k < 4; k++) {
        uint32_t face;
        double u, v;
        bs_cview cs = {&st[k][0], 1, 0}, ct = {&st[k][1], 1, 0};
        bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}};
        side[k] = bs_model_patch_to_face(m, 1, &p, &cs, &ct, &face, uv) == BS_OK && face != UINT32_MAX &&
                  (fabs(u - fi->u0) <= wu || fabs(u - fi->u1) <= wu || fabs(v - fi->v0) <= wv ||
                   fabs(v - fi->v1) <= wv);
    }
}

/* The model's watertight mesh (bs_model_tessellate within rel of its size), each triangle
 * shaded flat (a vertex on a sharp edge has one normal) and its edges drawn. */
static int draw_mesh(model_draw *md, raster *r, double unit, const double rgb[3], double rel, size_t budget,
                     size_t *ntri)
{
    bs_tess_options to;
    bs_tess_options_init(&to);
    to.method = BS_TESS_SUBDIVIDE;
    to.flags = BS_TESS_RELATIVE;
    to.tolerance = rel;
    to.max_triangles = budget;
    bs_mesh *mesh = NULL;
    bs_status st = bs_model_tessellate(md->model, &to, &mesh);
    if (st == BS_ERR_SIZE)
        return cli_fail("render", CLI_INPUT, "the mesh would have more triangles than the budget of %zu (--max-triangles N)",
                        budget);
    if (st != BS_OK)
        return cli_fail("render", CLI_INPUT, "the model's mesh: %s", bs_status_string(st));
    size_t nv = bs_mesh_vertex_count(mesh), nt = bs_mesh_triangle_count(mesh);
    double *xyz = malloc(3 * nv * sizeof(double) + 1);
    uint32_t *tri = malloc(3 * nt * sizeof(uint32_t) + 1), *face = malloc(nt * sizeof(uint32_t) + 1);
    int rc = xyz && tri && face ? CLI_OK : cli_fail("render", CLI_INTERNAL, "out of memory");
    bs_view pv[3] = {{xyz, nv, 3 * sizeof(double)}, {xyz + 1, nv, 3 * sizeof(double)}, {xyz + 2, nv, 3 * sizeof(double)}};
    if (rc == CLI_OK && (bs_mesh_copy_positions(mesh, pv) != BS_OK || bs_mesh_copy_triangles(mesh, tri, 3 * nt) != BS_OK ||
                         bs_mesh_copy_triangle_patch_ids(mesh, face, nt) != BS_OK))
        rc = cli_fail("render", CLI_INTERNAL, "the mesh could not be read");
    draw_out o;
    memset(&o, 0, sizeof o);
    o.r = r;
    o.wire = 1;
    double color[3];
    o.color = color;
    for (size_t t = 0; rc == CLI_OK && t < nt; t++) {
        if (t == 0 || face[t] != face[t - 1]) { /* a face's triangles are together */
            flush(&o);
            bs_face_info fi;
            fi.size = sizeof fi;
            if (md->faces && bs_model_face_info(md->model, face[t], &fi) == BS_OK) {
                model_draw_kind_color(fi.kind, color);
                md->kinds |= 1u << (fi.kind >= 0 && fi.kind < 9 ? fi.kind : 0);
            } else {
                memcpy(color, rgb, sizeof color);
            }
        }
        double p[3][3], n[3], e1[3], e2[3];
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                p[k][c] = xyz[3 * (size_t)tri[3 * t + (size_t)k] + (size_t)c] * unit;
        for (int c = 0; c < 3; c++) {
            e1[c] = p[1][c] - p[0][c];
            e2[c] = p[2][c] - p[0][c];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; c++)
            n[c] = len > 0.0 ? n[c] / len : (c == 2);
        const double *pp[3] = {p[0], p[1], p[2]}, *nn[3] = {n, n, n};
        if (emit_triangle(&o, pp, nn) != 0)
            rc = cli_fail("render", CLI_INTERNAL, "out of memory");
    }
    flush(&o);
    *ntri = o.drawn;
    free(o.tri_pos);
    free(o.tri_nrm);
    free(o.seg);
    free(xyz);
    free(tri);
    free(face);
    bs_mesh_destroy(mesh);
    return rc;
}

int model_draw_faces(model_draw *md, raster *r, double unit, const double rgb[3], int wire, double rel,
                     size_t budget, size_t *ntri)
{
    if (wire)
        return draw_mesh(md, r, unit, rgb, rel, budget, ntri);
    const bs_model *m = md->model;
    const bs_surface *s = bs_model_surface(m);
    size_t np = bs_surface_count(s), nf = bs_model_face_count(m);
    double area = 0.0;
    double *len = malloc(2 * np * sizeof(double) + 1);
    if (len == NULL)
        return cli_fail("render", CLI_INTERNAL, "out of memory");
    for (size_t p = 0; p < np; p++) {
        net_lengths(bs_surface_get(s, p), &len[2 * p], &len[2 * p + 1]);
        area += len[2 * p] * len[2 * p + 1];
    }
    /* about one triangle per two pixels of the picture is as fine as it shows */
    size_t target = r->w * r->h / 2 < MIN_TRIANGLES ? MIN_TRIANGLES : r->w * r->h / 2;
    if (target > DEFAULT_TRIANGLES)
        target = DEFAULT_TRIANGLES;
    if (budget != 0 && budget < target)
        target = budget;
    double k = area > 0.0 ? sqrt((double)target / (2.0 * area)) : 0.0;
    draw_out o;
    memset(&o, 0, sizeof o);
    o.r = r;
    o.wire = wire;
    int rc = CLI_OK;
    for (size_t f = 0; rc == CLI_OK && f < nf; f++) {
        bs_face_info fi;
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK)
            continue;
        double color[3];
        if (md->faces) {
            model_draw_kind_color(fi.kind, color);
            md->kinds |= 1u << (fi.kind >= 0 && fi.kind < 9 ? fi.kind : 0);
        } else {
            memcpy(color, rgb, sizeof color);
        }
        o.color = color;
        for (size_t p = fi.first_patch; rc == CLI_OK && p < fi.first_patch + fi.patch_count; p++) {
            patch_grid g;
            memset(&g, 0, sizeof g);
            g.m = m;
            g.p = bs_surface_get(s, p);
            g.id = (uint32_t)p;
            g.nu = rate(len[2 * p], k);
            g.nv = rate(len[2 * p + 1], k);
            g.tol = 0.0; /* the winding number alone: no distance to the boundary wanted */
            g.unit = unit;
            find_box_sides(m, g.id, &fi, g.box_side);
            if (draw_patch(&g, &o) != 0)
                rc = cli_fail("render", CLI_INTERNAL, "out of memory");
        }
        flush(&o);
    }
    if (rc == CLI_OK && md->faces) {
        static const double ink[3] = {0.05, 0.05, 0.07};
        for (size_t e = 0; e < o.nseg; e++)
            raster_line(r, o.seg + 6 * e, o.seg + 6 * e + 3, 1.3, ink);
    }
    *ntri = o.drawn;
    free(len);
    free(o.tri_pos);
    free(o.tri_nrm);
    free(o.seg);
    return rc;
}

/* Font dots in pixels for a picture h high (as the curvature legend). */
static size_t dot(size_t h) { return (h + 150) / 300 > 1 ? (h + 150) / 300 : 1; }

size_t model_draw_legend_strip(const model_draw *md, size_t w, size_t h)
{
    if (md == NULL || !md->faces)
        return 0;
    size_t s = dot(h), strip = (6 + 10 + 4 + 6 * 10 + 6) * s;
    return h >= 100 && 3 * strip <= w ? strip : 0;
}

void model_draw_legend(const model_draw *md, unsigned char *rgb, size_t w, size_t h)
{
    size_t strip = model_draw_legend_strip(md, w, h), s = dot(h);
    if (strip == 0)
        return;
    static const unsigned char ink[3] = {20, 20, 20}, frame[3] = {90, 90, 90};
    size_t x0 = w - strip + 6 * s, y = h * 15 / 100;
    font_draw(rgb, w, h, x0, y, "faces", s, ink);
    y += 16 * s;
    for (int kind = 0; kind < 9; kind++) {
        if (!(md->kinds & 1u << kind))
            continue;
        if (y + 10 * s > h)
            break;
        double c[3];
        model_draw_kind_color(kind, c);
        for (size_t yy = y; yy < y + 9 * s; yy++)
            for (size_t xx = x0; xx < x0 + 10 * s; xx++) {
                unsigned char *px = rgb + 3 * (yy * w + xx);
                int edge = yy == y || yy + 1 == y + 9 * s || xx == x0 || xx + 1 == x0 + 10 * s;
                for (int k = 0; k < 3; k++)
                    px[k] = edge ? frame[k] : raster_to_byte(c[k]);
            }
        font_draw(rgb, w, h, x0 + 14 * s, y + s, kind_names[kind], s, ink);
        y += 14 * s;
    }
}
