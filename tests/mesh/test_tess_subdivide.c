/* Tessellation by subdivision (BS_TESS_SUBDIVIDE): on the tea set, a spindle closed on itself
 * between two poles and a grid of reversed and swapped patches, the documented chordal error (21
 * barycentric points per triangle against the long-double reference) within the tolerance and at
 * least half of it; every edge used twice, or once on an open side of the surface (found by brute
 * force: across shared sides this also finds T-junctions); no T-junction inside a patch (no corner
 * of a patch's triangles inside an edge of another triangle of that patch, exactly in (u,v); the
 * checker is shown to catch one); no two vertices at the same place; the counts of the documented
 * rule on a parabolic patch (halves and thirds, one direction only); counts equal to the mesh; the
 * same mesh twice; strips; budgets; rational patches (weights in a ratio up to 1000); every error. */
#include "harness.h"
#include "bpt_reader.h"
#include "chordal.h"
#include "mesh_data.h"
#include "mesh_sides.h"

#include <math.h>
#include <string.h>

static bs_status subdivide(const bs_surface *s, double tol, int flags, size_t max_tri, bs_mesh **m)
{
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = tol;
    o.flags = flags;
    o.max_triangles = max_tri;
    return bs_surface_tessellate(s, &o, m);
}

typedef struct corner_pt { uint32_t patch; double a, b; uint32_t id; } corner_pt;

static int cmp_pt(const void *x, const void *y)
{
    const corner_pt *p = x, *q = y;
    if (p->patch != q->patch) return p->patch < q->patch ? -1 : 1;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return (p->id > q->id) - (p->id < q->id);
}

/* Corners of the triangles inside an edge of another triangle of the same patch, in (u,v): the
 * corners sorted by (u,v) (along v-lines) and by (v,u) (along u-lines and diagonals). */
static size_t t_junctions(size_t nt, const uint32_t *tri, const uint32_t *tpatch, const double *cuv)
{
    corner_pt *byu = xmalloc(3 * nt * sizeof(corner_pt)), *byv = xmalloc(3 * nt * sizeof(corner_pt));
    for (size_t k = 0; k < 3 * nt; k++) {
        corner_pt p = {tpatch[k / 3], cuv[2 * k], cuv[2 * k + 1], tri[k]};
        byu[k] = p;
    }
    qsort(byu, 3 * nt, sizeof(corner_pt), cmp_pt);
    size_t n = 0; /* each point once (it is a corner of several triangles) */
    for (size_t k = 0; k < 3 * nt; k++)
        if (n == 0 || cmp_pt(&byu[n - 1], &byu[k]) != 0) {
            corner_pt q = {byu[k].patch, byu[k].b, byu[k].a, byu[k].id};
            byu[n] = byu[k];
            byv[n++] = q;
        }
    qsort(byv, n, sizeof(corner_pt), cmp_pt);
    size_t found = 0;
    for (size_t t = 0; t < nt; t++)
        for (int e = 0; e < 3; e++) {
            size_t i0 = 3 * t + (size_t)e, i1 = 3 * t + (size_t)(e + 1) % 3;
            double u0 = cuv[2 * i0], v0 = cuv[2 * i0 + 1], u1 = cuv[2 * i1], v1 = cuv[2 * i1 + 1];
            int vline = u0 == u1; /* scan the corners with u = u0, else those with v between v0, v1 */
            const corner_pt *list = vline ? byu : byv;
            double a0 = vline ? u0 : fmin(v0, v1), a1 = vline ? u0 : fmax(v0, v1);
            corner_pt key = {tpatch[t], a0, -INFINITY, 0};
            size_t lo = 0, hi = n;
            while (lo < hi) {
                size_t mid = (lo + hi) / 2;
                if (cmp_pt(&list[mid], &key) < 0) lo = mid + 1; else hi = mid;
            }
            for (size_t k = lo; k < n && list[k].patch == tpatch[t] && list[k].a <= a1; k++) {
                double pu = vline ? list[k].a : list[k].b, pv = vline ? list[k].b : list[k].a;
                if (list[k].id == tri[i0] || list[k].id == tri[i1])
                    continue;
                double cross = (u1 - u0) * (pv - v0) - (v1 - v0) * (pu - u0);
                double dot = (pu - u0) * (u1 - u0) + (pv - v0) * (v1 - v0), len2 = (u1 - u0) * (u1 - u0) + (v1 - v0) * (v1 - v0);
                if (fabs(cross) <= 1e-15 * len2 && dot > 0.0 && dot < len2 && !(pu == u0 && pv == v0) &&
                    !(pu == u1 && pv == v1))
                    found++;
            }
        }
    free(byu);
    free(byv);
    return found;
}

/* The checker catches a T-junction: a unit square cut into two leaves on the left (u < 1/2, split
 * at v = 1/2) and one on the right whose left edge spans the point (1/2, 1/2). */
static void t_junction_checker(void)
{
    static const double uv[][2] = {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}, {0.5, 1}, {0, 1}, {1, 0}, {1, 1}};
    uint32_t tri[] = {0, 1, 3, 3, 1, 2, 3, 2, 5, 5, 2, 4, 1, 6, 4, 4, 6, 7}, tp[6] = {0};
    double cuv[36];
    for (size_t k = 0; k < 18; k++) {
        cuv[2 * k] = uv[tri[k]][0];
        cuv[2 * k + 1] = uv[tri[k]][1];
    }
    CHECK(t_junctions(6, tri, tp, cuv) == 1);
    uint32_t fixed[] = {0, 1, 3, 3, 1, 2, 3, 2, 5, 5, 2, 4, 1, 6, 2, 2, 6, 7, 2, 7, 4};
    uint32_t tp2[7] = {0};
    double cuv2[42];
    for (size_t k = 0; k < 21; k++) {
        cuv2[2 * k] = uv[fixed[k]][0];
        cuv2[2 * k + 1] = uv[fixed[k]][1];
    }
    CHECK(t_junctions(7, fixed, tp2, cuv2) == 0);
}

typedef struct edge { uint32_t a, b; size_t tri; int k; } edge;

static int cmp_edge(const void *x, const void *y)
{
    const edge *e = x, *f = y;
    if (e->a != f->a) return e->a < f->a ? -1 : 1;
    return (e->b > f->b) - (e->b < f->b);
}

typedef struct placed { double x[3]; size_t id; } placed;

static int cmp_pos(const void *a, const void *b)
{
    const placed *p = a, *q = b;
    for (int c = 0; c < 3; c++)
        if (p->x[c] != q->x[c])
            return p->x[c] < q->x[c] ? -1 : 1;
    return 0;
}

/* 1 if vertex k lies on a side of its patch that is open (no neighbour, not a pole). */
static int on_open_side(const mesh_data *d, const unsigned char *open, size_t k)
{
    double u = d->uv[2 * k], v = d->uv[2 * k + 1];
    const unsigned char *o = open + 4 * (size_t)d->vpatch[k];
    return (v == 0.0 && o[0]) || (u == 1.0 && o[1]) || (v == 1.0 && o[2]) || (u == 0.0 && o[3]);
}

/* Watertightness: edges used more than twice, edges used once off an open side, degenerate
 * triangles, and vertices at the same place as another. */
static void check_welds(const bs_surface *s, const mesh_data *d, const char *what)
{
    size_t np = bs_surface_count(s), ne = 3 * d->nt, over = 0, crack = 0, boundary = 0, degenerate = 0;
    edge *e = xmalloc(ne * sizeof(edge));
    for (size_t t = 0; t < d->nt; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = d->tri[3 * t + (size_t)k], b = d->tri[3 * t + (size_t)(k + 1) % 3];
            degenerate += a == b;
            edge x = {a < b ? a : b, a < b ? b : a, t, k};
            e[3 * t + (size_t)k] = x;
        }
    qsort(e, ne, sizeof(edge), cmp_edge);
    unsigned char *open = xmalloc(4 * np);
    open_sides(s, open);
    for (size_t i = 0; i < ne;) {
        size_t j = i;
        while (j < ne && e[j].a == e[i].a && e[j].b == e[i].b)
            j++;
        over += j - i > 2;
        if (j - i == 1) {
            boundary++;
            const double *cu = d->cuv + 6 * e[i].tri;
            int k = e[i].k, k1 = (k + 1) % 3;
            int side = common_side(cu[2 * k], cu[2 * k + 1], cu[2 * k1], cu[2 * k1 + 1]);
            crack += side < 0 || !open[4 * (size_t)d->tpatch[e[i].tri] + (size_t)side];
        }
        i = j;
    }
    /* Vertices at one place are one vertex, except where an open side merely touches the surface
     * (the teapot's handle ends on a corner of the body, a side of the spoon folds onto itself). */
    placed *pos = xmalloc(d->nv * sizeof(placed));
    for (size_t k = 0; k < d->nv; k++) {
        memcpy(pos[k].x, d->pos + 3 * k, sizeof pos[k].x);
        pos[k].id = k;
    }
    qsort(pos, d->nv, sizeof(placed), cmp_pos);
    size_t same = 0;
    for (size_t k = 1; k < d->nv; k++)
        same += cmp_pos(pos + k - 1, pos + k) == 0 &&
                !on_open_side(d, open, pos[k - 1].id) && !on_open_side(d, open, pos[k].id);
    CHECKF(degenerate == 0, "%s: %zu degenerate triangles", what, degenerate);
    CHECKF(over == 0, "%s: %zu edges used by more than two triangles", what, over);
    CHECKF(crack == 0, "%s: %zu of %zu edges used once are not on an open side", what, crack, boundary);
    CHECKF(same == 0, "%s: %zu vertices at the place of another, neither on an open side", what, same);
    size_t tj = t_junctions(d->nt, d->tri, d->tpatch, d->cuv);
    CHECKF(tj == 0, "%s: %zu T-junctions", what, tj);
    free(pos);
    free(open);
    free(e);
}

/* Mesh and counts of s at tol; the error within tol (and at least min_ratio of it). */
static void check_surface(const bs_surface *s, double tol, double min_ratio, const char *what)
{
    bs_mesh *m = NULL;
    CHECK_STATUS(subdivide(s, tol, 0, 0, &m), BS_OK);
    if (m == NULL)
        return;
    mesh_data d;
    read_mesh(m, &d);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = tol;
    size_t nv = 0, nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECKF(nv == d.nv && nt == d.nt, "%s: counted %zu %zu, built %zu %zu", what, nv, nt, d.nv, d.nt);
    double err = chordal_error(s, &d);
    CHECKF(err <= tol, "%s: error %g above the tolerance %g", what, err, tol);
    CHECKF(err >= min_ratio * tol, "%s: error %g below %g of the tolerance", what, err / tol, min_ratio);
    check_welds(s, &d, what);
    printf("%s: %zu vertices, %zu triangles, error %.3f of the tolerance\n", what, d.nv, d.nt, err / tol);
    free_mesh(&d);
    bs_mesh_destroy(m);
}

/* The built-in tea set (the data of the .bpt files in data/). */
static void tea_set(void)
{
    const char *name;
    for (size_t k = 0; (name = bs_builtin_name(k)) != NULL; k++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create_builtin(name, &s), BS_OK);
        char what[64];
        /* at least half the tolerance once the leaves are many */
        double finest = bs_test_quick() ? 0.9e-2 : 0.9e-3;
        for (double tol = 1e-1; s != NULL && tol >= finest; tol /= 10.0) {
            snprintf(what, sizeof what, "%s %g", name, tol);
            check_surface(s, tol, tol < 0.05 ? 0.5 : 0.0, what);
        }
        bs_surface_destroy(s);
    }
}

/* z = a u^2 over the unit square (degree 2 in u, 1 in v): |S_uu| = 2a, so the bound is a/4 per
 * leaf, a / (4 f^2) after f equal parts in u, and nothing in v. The rule gives f = the smallest
 * product of 2s and 3s with a / (4 f^2) <= tol, one leaf across v: f + 1 points on each of the
 * two sides, 2f triangles. The error of a triangle at barycentric weights l is a Var_l(u), at most
 * a h^2 / 4 (h = 1/f) at an edge's midpoint; the 21 points see at most 0.4 * 0.6 a h^2. */
static void parabola(void)
{
    static const struct { double a, tol; size_t f; } cases[] = {
        {1.0, 1e-3, 16}, {1.0, 0.25 / 80.0, 9}, {1.0, 0.25 / 30.0, 6}, {4.0, 1.0, 1}, {4.0, 0.26, 2}, {1.0, 1e-6, 512}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double a = cases[c].a, net[18];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 2; j++) {
                double *p = net + (i * 2 + j) * 3;
                p[0] = i / 2.0;
                p[1] = j;
                p[2] = i == 2 ? a : 0.0; /* Bernstein coefficients of a u^2: 0, 0, a */
            }
        bs_surface *s = NULL;
        bs_surface_create(&s);
        add_patch(s, 2, 1, net, NULL);
        bs_mesh *m = NULL;
        CHECK_STATUS(subdivide(s, cases[c].tol, 0, 0, &m), BS_OK);
        size_t f = cases[c].f;
        CHECKF(bs_mesh_vertex_count(m) == 2 * (f + 1) && bs_mesh_triangle_count(m) == 2 * f,
               "a %g tolerance %g: %zu vertices %zu triangles, expected %zu parts", a, cases[c].tol,
               bs_mesh_vertex_count(m), bs_mesh_triangle_count(m), f);
        mesh_data d;
        read_mesh(m, &d);
        double err = chordal_error(s, &d), seen = 0.24 * a / (double)(f * f);
        CHECKF(fabs(err - seen) <= 1e-12 * a, "error %g, expected %g", err, seen);
        free_mesh(&d);
        bs_mesh_destroy(m);
        bs_surface_destroy(s);
    }
}

/* A rational quarter cylinder (exact circle arcs along u, straight along v) and a paraboloid of
 * strongly varying weights: their bound is an estimate; measured within the tolerance here. A grid
 * of patches with reversed and swapped neighbours. The relative tolerance on the teapot. */
static void rational_and_relative(void)
{
    static const double ring[3][2] = {{1, 0}, {1, 1}, {0, 1}}, w3[3] = {1, 0.70710678118654752, 1};
    double net[18], w[6];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 2; j++) {
            double *p = net + (i * 2 + j) * 3;
            p[0] = ring[i][0];
            p[1] = ring[i][1];
            p[2] = 2.0 * j;
            w[i * 2 + j] = w3[i];
        }
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, 2, 1, net, w);
    check_surface(s, 1e-3, 0.0, "quarter cylinder");
    bs_surface_destroy(s);
    /* A bicubic paraboloid whose middle rows weigh 1/1000 of its outer ones: the estimate must
     * grow with the weight ratio (not shrink by it) to keep this within the tolerance. */
    double para[16 * 3], wp[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *p = para + (i * 4 + j) * 3;
            p[0] = i;
            p[1] = j;
            p[2] = 0.3 * (i - 1.5) * (i - 1.5) + 0.2 * (j - 1.5) * (j - 1.5);
            wp[i * 4 + j] = i == 1 || i == 2 ? 1e-3 : 1.0;
        }
    s = NULL;
    bs_surface_create(&s);
    add_patch(s, 3, 3, para, wp);
    check_surface(s, 1e-2, 0.0, "weights 1e-3 to 1");
    bs_surface_destroy(s);
    /* A spindle: poles at v = 0 and v = 1, and its sides u = 0 and u = 1 one curve (the ring of
     * the net closes on itself), so a side is shared with the same patch. */
    static const double loop[4][2] = {{1, 0}, {-0.5, 1.5}, {-0.5, -1.5}, {1, 0}};
    double spindle[4 * 4 * 3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double r = (j == 0 || j == 3) ? 0.0 : 1.0, *p = spindle + (i * 4 + j) * 3;
            p[0] = r * loop[i][0];
            p[1] = r * loop[i][1];
            p[2] = j - 1.5;
        }
    s = NULL;
    bs_surface_create(&s);
    add_patch(s, 3, 3, spindle, NULL);
    check_surface(s, 10.0, 0.0, "spindle 10"); /* leaves across the seam between poles: no triangle */
    check_surface(s, 0.3, 0.0, "spindle 0.3");
    check_surface(s, 1e-3, 0.5, "spindle 1e-3");
    bs_surface_destroy(s);
    s = bumpy_grid(3, 4, 5); /* neighbours reversed and swapped, curvature growing along x */
    check_surface(s, 1e-3, 0.5, "bumpy grid");
    bs_surface_destroy(s);

    s = test_load_bpt("teapot.bpt");
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, ctrl[16 * 3];
    for (size_t p = 0; p < bs_surface_count(s); p++) {
        bs_patch_get_ctrl(bs_surface_get(s, p), ctrl, 16 * 3, NULL, 0);
        for (size_t k = 0; k < 16 * 3; k++) {
            lo[k % 3] = fmin(lo[k % 3], ctrl[k]);
            hi[k % 3] = fmax(hi[k % 3], ctrl[k]);
        }
    }
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
    bs_mesh *ma = NULL, *mb = NULL;
    CHECK_STATUS(subdivide(s, 1e-3 / diag, BS_TESS_RELATIVE, 0, &ma), BS_OK);
    CHECK_STATUS(subdivide(s, 1e-3, 0, 0, &mb), BS_OK);
    CHECK(bs_mesh_triangle_count(ma) > 0 && bs_mesh_triangle_count(ma) == bs_mesh_triangle_count(mb));
    bs_mesh_destroy(ma);
    bs_mesh_destroy(mb);
    bs_surface_destroy(s);
}

/* The same mesh twice, strips equal to the triangle list, budgets. */
static void repeat_strips_budgets(void)
{
    bs_surface *s = test_load_bpt("teapot.bpt");
    bs_mesh *ma = NULL, *mb = NULL, *ms = NULL;
    CHECK_STATUS(subdivide(s, 1e-2, 0, 0, &ma), BS_OK);
    CHECK_STATUS(subdivide(s, 1e-2, 0, 0, &mb), BS_OK);
    CHECK_STATUS(subdivide(s, 1e-2, BS_TESS_STRIPS, 0, &ms), BS_OK);
    mesh_data a, b, c;
    read_mesh(ma, &a);
    read_mesh(mb, &b);
    read_mesh(ms, &c);
    CHECK(a.nv == b.nv && a.nt == b.nt && memcmp(a.pos, b.pos, 3 * a.nv * sizeof(double)) == 0 &&
          memcmp(a.nrm, b.nrm, 3 * a.nv * sizeof(double)) == 0 && memcmp(a.tri, b.tri, 3 * a.nt * sizeof(uint32_t)) == 0 &&
          memcmp(a.cuv, b.cuv, 6 * a.nt * sizeof(double)) == 0);
    CHECK(c.nt == a.nt && memcmp(c.tri, a.tri, 3 * a.nt * sizeof(uint32_t)) == 0);
    int strips_ok = c.ns == c.nt && c.nsi == 3 * c.nt;
    for (size_t k = 0; strips_ok && k < c.ns; k++)
        strips_ok = c.sstart[k] == 3 * k && memcmp(c.sidx + 3 * k, c.tri + 3 * k, 3 * sizeof(uint32_t)) == 0;
    CHECK(strips_ok);
    size_t nt = a.nt;
    free_mesh(&a);
    free_mesh(&b);
    free_mesh(&c);
    bs_mesh_destroy(ma);
    bs_mesh_destroy(mb);
    bs_mesh_destroy(ms);

    bs_mesh *m = (bs_mesh *)&m;
    CHECK_STATUS(subdivide(s, 1e-2, 0, nt - 1, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    CHECK_STATUS(subdivide(s, 1e-2, 0, nt, &m), BS_OK);
    bs_mesh_destroy(m);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = 1e-2;
    o.max_vertices = 10;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    { /* the vertex budget is inclusive as well: exactly the mesh's count is made, one less not */
        size_t nv_at = 0, nt_at = 0;
        o.max_vertices = 0;
        CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv_at, &nt_at), BS_OK);
        o.max_vertices = nv_at;
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
        bs_mesh_destroy(m);
        o.max_vertices = nv_at - 1;
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    }
    /* far beyond the budget: refused while the trees are small (each leaf away from the poles
     * gives two triangles or more) */
    o.max_vertices = 0;
    o.max_triangles = 1000;
    o.tolerance = 1e-12;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    o.max_vertices = 1000; /* the vertices likewise: a point inside a patch is one vertex */
    o.max_triangles = 0;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    /* counting under a budget stops there too: lower bounds over the budget, below the exact
     * counts (at 1e-12 without a budget the trees would take gigabytes) */
    size_t nv = 0, exact_nv = 0, exact_nt = 0;
    o.max_vertices = 0;
    o.tolerance = 1e-4;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &exact_nv, &exact_nt), BS_OK);
    o.max_triangles = exact_nt / 8;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECKF(nt > o.max_triangles && nt < exact_nt && nv < exact_nv, "count under a budget of %zu: %zu (exact %zu)",
           o.max_triangles, nt, exact_nt);
    o.max_triangles = 0;
    o.max_vertices = exact_nv / 8;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECKF(nv > o.max_vertices && nv < exact_nv, "count under a budget of %zu vertices: %zu (exact %zu)",
           o.max_vertices, nv, exact_nv);
    o.max_vertices = 0;
    o.max_triangles = 1000;
    o.tolerance = 1e-12;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECK(nt > 1000);
    bs_surface_destroy(s);
}

static void errors(void)
{
    bs_surface *s = test_load_bpt("teaspoon.bpt");
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    bs_mesh *m = (bs_mesh *)&m;
    size_t nv = 7, nt = 7;
    static const double bad[] = {0.0, -1e-3, NAN, INFINITY};
    for (size_t k = 0; k < 4; k++) {
        o.tolerance = bad[k];
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_DOMAIN);
        CHECK(m == NULL);
        CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_ERR_DOMAIN);
        CHECK(nv == 7 && nt == 7);
    }
    o.tolerance = 1e-3;
    o.flags = 8;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_INVALID_ARG);
    o.flags = 0;
    CHECK_STATUS(bs_surface_tessellate(NULL, &o, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, NULL, NULL), BS_OK);
    bs_surface *e = NULL;
    bs_surface_create(&e);
    CHECK_STATUS(bs_surface_tessellate(e, &o, &m), BS_OK);
    CHECK(m != NULL && bs_mesh_vertex_count(m) == 0 && bs_mesh_triangle_count(m) == 0);
    bs_mesh_destroy(m);
    double line[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    bs_patch *p2 = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 2, line, NULL, &p2), BS_OK);
    bs_surface *flat = NULL;
    bs_surface_create(&flat);
    bs_surface_add(flat, p2, NULL);
    CHECK_STATUS(bs_surface_tessellate(flat, &o, &m), BS_ERR_DIMENSION);
    bs_patch_destroy(p2);
    bs_surface_destroy(flat);
    bs_surface_destroy(e);
    bs_surface_destroy(s);
}

int main(void)
{
    t_junction_checker();
    parabola();
    tea_set();
    rational_and_relative();
    repeat_strips_budgets();
    errors();
    return bs_test_exit("test_tess_subdivide");
}
