/* Tessellation: crack-freedom (every boundary edge of the mesh lies on an open side of the surface),
 * vertices on the surface at their parameters (long-double reference), unit normals, no NaN,
 * adaptive meshes within their chordal tolerance, strips equal to the triangle list, triangle counts
 * of uniform tessellations, stitched grids of patches with reversed and swapped neighbours, and
 * every error path. */
#include "harness.h"
#include "bpt_reader.h"
#include "mesh_data.h"
#include "mesh_sides.h"
#include "reference.h"

#include <math.h>
#include <string.h>

#define M_PI_2_ 1.57079632679489661923

static ref_net net_of(const bs_patch *p, double *store, double *wstore)
{
    ref_net r = {bs_patch_degree_u(p), bs_patch_degree_v(p), 3, store, NULL};
    bs_patch_get_ctrl(p, store, 65 * 65 * 3, wstore, 65 * 65);
    if (bs_patch_is_rational(p))
        r.w = wstore;
    return r;
}

typedef struct edge { uint32_t a, b; size_t tri; int k; } edge;

static int cmp_edge(const void *x, const void *y)
{
    const edge *e = x, *f = y;
    if (e->a != f->a) return e->a < f->a ? -1 : 1;
    if (e->b != f->b) return e->b < f->b ? -1 : 1;
    return 0;
}

/* The mesh checks shared by every test. tol > 0: the chordal tolerance to verify. Returns the
 * number of boundary edges (used by one triangle). */
static size_t check_mesh(const bs_surface *s, const bs_mesh *m, double tol, const char *what)
{
    mesh_data d;
    read_mesh(m, &d);
    size_t np = bs_surface_count(s);
    double scale = 0.0;
    int nan = 0, nonunit = 0, badpatch = 0;
    for (size_t k = 0; k < d.nv; k++) {
        for (int c = 0; c < 3; c++) {
            nan |= !isfinite(d.pos[3 * k + (size_t)c]) || !isfinite(d.nrm[3 * k + (size_t)c]);
            scale = fmax(scale, fabs(d.pos[3 * k + (size_t)c]));
        }
        const double *n = d.nrm + 3 * k;
        nonunit += !(fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) <= 1e-12);
        badpatch += d.vpatch[k] >= np || !(d.uv[2 * k] >= 0.0 && d.uv[2 * k] <= 1.0);
    }
    CHECKF(!nan, "%s: NaN in the mesh", what);
    CHECKF(nonunit == 0, "%s: %d normals are not unit", what, nonunit);
    CHECKF(badpatch == 0, "%s: %d vertices with a bad patch id or uv", what, badpatch);

    /* Every corner's vertex is the surface at the corner's (u,v) on the triangle's patch (this also
     * checks that welded vertices were matched with the right orientation), and every triangle is
     * within tol of the surface at its centroid and edge midpoints. */
    static double store[65 * 65 * 3], wstore[65 * 65];
    long double worst_vertex = 0.0L, worst_chord = 0.0L;
    uint32_t last = UINT32_MAX;
    ref_net net = {0, 0, 3, NULL, NULL};
    for (size_t t = 0; t < d.nt; t++) {
        if (d.tpatch[t] != last) {
            last = d.tpatch[t];
            net = net_of(bs_surface_get(s, last), store, wstore);
        }
        const double *cu = d.cuv + 6 * t;
        long double S[3];
        for (int k = 0; k < 3; k++) {
            ref_eval(&net, cu[2 * k], cu[2 * k + 1], S);
            const double *x = d.pos + 3 * (size_t)d.tri[3 * t + (size_t)k];
            for (int c = 0; c < 3; c++)
                worst_vertex = fmaxl(worst_vertex, fabsl(S[c] - x[c]));
        }
        static const double bary[4][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
        for (int q = 0; q < 4; q++) {
            long double u = 0, v = 0, P[3] = {0, 0, 0};
            for (int k = 0; k < 3; k++) {
                u += bary[q][k] * (long double)cu[2 * k];
                v += bary[q][k] * (long double)cu[2 * k + 1];
                for (int c = 0; c < 3; c++)
                    P[c] += bary[q][k] * (long double)d.pos[3 * (size_t)d.tri[3 * t + (size_t)k] + (size_t)c];
            }
            ref_eval(&net, u, v, S);
            long double dist = sqrtl((S[0] - P[0]) * (S[0] - P[0]) + (S[1] - P[1]) * (S[1] - P[1]) +
                                     (S[2] - P[2]) * (S[2] - P[2]));
            worst_chord = fmaxl(worst_chord, dist);
        }
    }
    CHECKF(worst_vertex <= 1e-13 * fmax(scale, 1.0), "%s: vertex off the surface by %Lg", what, worst_vertex);
    /* Winding: counter-clockwise in the (u,v) domain of the triangle's patch, stitched ones too. */
    size_t clockwise = 0;
    for (size_t t = 0; t < d.nt; t++) {
        const double *c = d.cuv + 6 * t;
        clockwise += (c[2] - c[0]) * (c[5] - c[1]) - (c[3] - c[1]) * (c[4] - c[0]) <= 0.0;
    }
    CHECKF(clockwise == 0, "%s: %zu triangles not counter-clockwise in (u,v)", what, clockwise);
    if (tol > 0.0)
        CHECKF(worst_chord <= tol, "%s: chordal error %Lg above tolerance %g", what, worst_chord, tol);

    /* Edges: used at most twice; an edge used once must lie on an open side of the surface. */
    edge *e = xmalloc(3 * d.nt * sizeof(edge));
    int degenerate = 0;
    for (size_t t = 0; t < d.nt; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = d.tri[3 * t + (size_t)k], b = d.tri[3 * t + (size_t)(k + 1) % 3];
            degenerate += a == b;
            edge x = {a < b ? a : b, a < b ? b : a, t, k};
            e[3 * t + (size_t)k] = x;
        }
    CHECKF(degenerate == 0, "%s: %d degenerate triangles", what, degenerate);
    qsort(e, 3 * d.nt, sizeof(edge), cmp_edge);
    unsigned char *open = xmalloc(4 * np);
    open_sides(s, open);
    size_t boundary = 0, crack = 0, over = 0;
    for (size_t i = 0; i < 3 * d.nt;) {
        size_t j = i;
        while (j < 3 * d.nt && e[j].a == e[i].a && e[j].b == e[i].b)
            j++;
        if (j - i > 2)
            over++;
        if (j - i == 1) {
            boundary++;
            size_t t = e[i].tri;
            int k = e[i].k, k1 = (k + 1) % 3;
            const double *cu = d.cuv + 6 * t;
            int side = common_side(cu[2 * k], cu[2 * k + 1], cu[2 * k1], cu[2 * k1 + 1]);
            if (side < 0 || !open[4 * (size_t)d.tpatch[t] + (size_t)side])
                crack++;
        }
        i = j;
    }
    CHECKF(crack == 0, "%s: %zu of %zu boundary edges are cracks", what, crack, boundary);
    /* At one segment per patch the two halves of the handle and of the spout are the same quad: only
     * from two segments on is every edge of the mesh used at most twice. */
    if (strcmp(what, "teapot uniform 1") != 0)
        CHECKF(over == 0, "%s: %zu edges used by more than two triangles", what, over);

    /* Strips: their non-degenerate triangles are the triangle list, same winding. */
    if (d.ns > 0) {
        edge *a = xmalloc(d.nt * sizeof(edge)), *b = xmalloc(d.nsi * sizeof(edge));
        size_t na = 0, nb = 0;
        for (size_t t = 0; t < d.nt; t++) {
            uint32_t x = d.tri[3 * t], y = d.tri[3 * t + 1], z = d.tri[3 * t + 2];
            /* canonical rotation: smallest index first; (a,b) packs the other two */
            while (x > y || x > z) { uint32_t w = x; x = y; y = z; z = w; }
            edge q = {x, y, z, 0};
            a[na++] = q;
        }
        for (size_t k = 0; k < d.ns; k++)
            for (uint32_t i = d.sstart[k]; i + 2 < d.sstart[k + 1]; i++) {
                uint32_t x = d.sidx[i], y = d.sidx[i + 1], z = d.sidx[i + 2];
                if ((i - d.sstart[k]) % 2) { uint32_t w = x; x = y; y = w; }
                if (x == y || y == z || x == z)
                    continue;
                while (x > y || x > z) { uint32_t w = x; x = y; y = z; z = w; }
                edge q = {x, y, z, 0};
                b[nb++] = q;
            }
        int same = na == nb;
        qsort(a, na, sizeof(edge), cmp_edge);
        qsort(b, nb, sizeof(edge), cmp_edge);
        for (size_t i = 0; same && i < na; i++)
            same = a[i].a == b[i].a && a[i].b == b[i].b && a[i].tri == b[i].tri;
        CHECKF(same, "%s: strips (%zu triangles) differ from the list (%zu)", what, nb, na);
        CHECK(d.sstart[0] == 0 && d.sstart[d.ns] == d.nsi);
        free(a);
        free(b);
    }
    printf("%s: %zu vertices, %zu triangles, %zu boundary edges, chordal error %.3Lg\n", what, d.nv, d.nt,
           boundary, worst_chord);
    free(open);
    free(e);
    free_mesh(&d);
    return boundary;
}

static void teapot(void)
{
    bs_surface *s = test_load_bpt("teapot.bpt");
    CHECK(s != NULL);
    if (s == NULL)
        return;
    /* BS_TEST_QUICK (memcheck): the same checks without the two finest meshes */
    static const size_t rates[] = {1, 2, 4, 8, 16, 64};
    size_t nrates = sizeof rates / sizeof rates[0] - (bs_test_quick() ? 1 : 0);
    for (size_t r = 0; r < nrates; r++) {
        size_t N = rates[r];
        bs_mesh *m = NULL;
        CHECK_STATUS(bs_surface_tessellate_uniform(s, N, N, BS_TESS_STRIPS, &m), BS_OK);
        char what[64];
        snprintf(what, sizeof what, "teapot uniform %zu", N);
        check_mesh(s, m, 0.0, what);
        /* 2N^2 triangles per patch, less the N that degenerate on each of the 8 poles. */
        CHECKF(bs_mesh_triangle_count(m) == 32 * 2 * N * N - 8 * N, "%s: %zu triangles", what,
               bs_mesh_triangle_count(m));
        bs_mesh_destroy(m);
    }
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 3, 7, 0, &m), BS_OK);
    check_mesh(s, m, 0.0, "teapot uniform 3x7");
    CHECK(bs_mesh_strip_count(m) == 0 && bs_mesh_strip_index_count(m) == 0);
    bs_mesh_destroy(m);
    static const double tols[] = {0.1, 0.01, 0.001};
    size_t prev = 0;
    for (size_t k = 0; k < (bs_test_quick() ? 2u : 3u); k++) {
        CHECK_STATUS(bs_surface_tessellate_adaptive(s, tols[k], BS_TESS_STRIPS, &m), BS_OK);
        char what[64];
        snprintf(what, sizeof what, "teapot adaptive %g", tols[k]);
        check_mesh(s, m, tols[k], what);
        CHECK(bs_mesh_triangle_count(m) > prev);
        prev = bs_mesh_triangle_count(m);
        bs_mesh_destroy(m);
    }
    /* Relative: 1e-3 of the diagonal of the control points' box. */
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, 1e-3, BS_TESS_RELATIVE, &m), BS_OK);
    {
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, net[48];
        for (size_t i = 0; i < bs_surface_count(s); i++) {
            bs_patch_get_ctrl(bs_surface_get(s, i), net, 48, NULL, 0);
            for (int k = 0; k < 16; k++)
                for (int c = 0; c < 3; c++) {
                    lo[c] = fmin(lo[c], net[3 * k + c]);
                    hi[c] = fmax(hi[c], net[3 * k + c]);
                }
        }
        double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                           (hi[2] - lo[2]) * (hi[2] - lo[2]));
        check_mesh(s, m, 1e-3 * diag, "teapot adaptive relative 1e-3");
    }
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
}

static void grids(void)
{
    for (unsigned long long seed = 1; seed <= 6; seed++) {
        bs_surface *s = bumpy_grid(3, 4, seed);
        bs_mesh *m = NULL;
        char what[64];
        CHECK_STATUS(bs_surface_tessellate_adaptive(s, 0.01, BS_TESS_STRIPS, &m), BS_OK);
        snprintf(what, sizeof what, "grid %llu adaptive 0.01", seed);
        check_mesh(s, m, 0.01, what);
        bs_mesh_destroy(m);
        CHECK_STATUS(bs_surface_tessellate_uniform(s, 2, 5, BS_TESS_STRIPS, &m), BS_OK);
        snprintf(what, sizeof what, "grid %llu uniform 2x5", seed);
        size_t boundary = check_mesh(s, m, 0.0, what);
        /* A 3 x 4 grid has one boundary: 2(3+4) open sides of 2 or 5 segments each (a cell's
         * parameters may be swapped), so between 2*14 and 5*14 boundary edges. */
        CHECKF(boundary >= 2 * 14 && boundary <= 5 * 14, "%s: %zu boundary edges", what, boundary);
        bs_mesh_destroy(m);
        bs_surface_destroy(s);
    }
}

/* A full circular cylinder of radius 2 and height 3 from four rational quarter patches (quadratic
 * in u with weights 1, 1/sqrt(2), 1; linear in v): shared sides found through proportional weights,
 * and the adaptive mesh within its tolerance of the exact surface. */
static void cylinder(void)
{
    bs_surface *s = NULL;
    bs_surface_create(&s);
    double h = sqrt(0.5);
    for (int q = 0; q < 4; q++) {
        double a0 = q * M_PI_2_, a1 = a0 + M_PI_2_, net[3 * 2 * 3], w[6];
        double px[3] = {cos(a0), cos(a0) + cos(a1), cos(a1)}, py[3] = {sin(a0), sin(a0) + sin(a1), sin(a1)};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 2; j++) {
                double *p = net + (i * 2 + j) * 3;
                p[0] = 2 * px[i];
                p[1] = 2 * py[i];
                p[2] = 3.0 * j;
                w[i * 2 + j] = i == 1 ? h : 1.0;
            }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(2, 1, 3, net, w, &p), BS_OK);
        bs_surface_add(s, p, NULL);
        bs_patch_destroy(p);
    }
    static const double tols[] = {0.05, 1e-3};
    for (int k = 0; k < 2; k++) {
        bs_mesh *m = NULL;
        CHECK_STATUS(bs_surface_tessellate_adaptive(s, tols[k], BS_TESS_STRIPS, &m), BS_OK);
        char what[64];
        snprintf(what, sizeof what, "rational cylinder adaptive %g", tols[k]);
        check_mesh(s, m, tols[k], what);
        bs_mesh_destroy(m);
    }
    bs_surface_destroy(s);
}

static void errors(void)
{
    bs_surface *s = NULL, *empty = NULL, *flat = NULL;
    bs_surface_create(&empty);
    bs_surface_create(&flat);
    s = bumpy_grid(1, 2, 3);
    double net2[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p2;
    bs_patch_create(1, 1, 2, net2, NULL, &p2);
    bs_surface_add(flat, p2, NULL);
    bs_patch_destroy(p2);
    bs_mesh *m = (bs_mesh *)&m;
    CHECK_STATUS(bs_surface_tessellate_uniform(NULL, 4, 4, 0, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 4, 4, 0, NULL), BS_ERR_INVALID_ARG);
    m = (bs_mesh *)&m;
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 4, 4, 8, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 0, 4, 0, &m), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 4, BS_TESS_MAX_RATE + 1, 0, &m), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_tessellate_uniform(flat, 4, 4, 0, &m), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_tessellate_adaptive(flat, 0.1, 0, &m), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_tessellate_adaptive(NULL, 0.1, 0, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, 0.1, 8, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, 0.0, 0, &m), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, -1.0, 0, &m), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, NAN, 0, &m), BS_ERR_DOMAIN);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, INFINITY, 0, &m), BS_ERR_DOMAIN);
    CHECK(m == NULL);

    CHECK_STATUS(bs_surface_tessellate_uniform(empty, 4, 4, BS_TESS_STRIPS, &m), BS_OK);
    CHECK(m != NULL && bs_mesh_vertex_count(m) == 0 && bs_mesh_triangle_count(m) == 0);
    bs_mesh_destroy(m);

    CHECK_STATUS(bs_surface_tessellate_uniform(s, 2, 2, 0, &m), BS_OK);
    size_t nv = bs_mesh_vertex_count(m), nt = bs_mesh_triangle_count(m);
    CHECK(nv == 15 && nt == 16); /* two 2x2 grids sharing a 3-vertex side */
    double buf[64];
    uint32_t ids[64];
    for (int k = 0; k < 64; k++)
        buf[k] = -7.0;
    bs_view v3[3] = {{buf, nv, 0}, {buf + 16, nv, 0}, {buf + 32, nv - 1, 0}};
    CHECK_STATUS(bs_mesh_copy_positions(m, v3), BS_ERR_SIZE);
    CHECK(buf[0] == -7.0 && buf[16] == -7.0);
    CHECK_STATUS(bs_mesh_copy_positions(NULL, v3), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_copy_positions(m, NULL), BS_ERR_INVALID_ARG);
    bs_view bad[3] = {{NULL, nv, 0}, {buf, nv, 0}, {buf, nv, 0}};
    CHECK_STATUS(bs_mesh_copy_normals(m, bad), BS_ERR_INVALID_ARG);
    bs_view mis[2] = {{(double *)(void *)((char *)buf + 1), nv, 0}, {buf, nv, 0}};
    CHECK_STATUS(bs_mesh_copy_uv(m, mis), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_copy_corner_uv(m, v3), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_patch_ids(m, ids, nv - 1), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_patch_ids(m, NULL, 64), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_copy_triangles(m, ids, 3 * nt - 1), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_triangle_patch_ids(m, ids, nt - 1), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_triangle_patch_ids(NULL, ids, 64), BS_ERR_INVALID_ARG);
    CHECK(bs_mesh_strip_count(m) == 0);
    CHECK_STATUS(bs_mesh_copy_strips(m, ids, 0, ids, 1), BS_OK);
    CHECK(ids[0] == 0);
    CHECK_STATUS(bs_mesh_copy_strips(m, ids, 0, ids, 0), BS_ERR_SIZE);
    CHECK_STATUS(bs_mesh_copy_strips(m, NULL, 0, ids, 1), BS_ERR_INVALID_ARG);
    CHECK(bs_mesh_vertex_count(NULL) == 0 && bs_mesh_triangle_count(NULL) == 0);
    CHECK(bs_mesh_strip_count(NULL) == 0 && bs_mesh_strip_index_count(NULL) == 0);
    bs_mesh_destroy(m);
    bs_mesh_destroy(NULL);
    bs_surface_destroy(s);
    bs_surface_destroy(empty);
    bs_surface_destroy(flat);
}

int main(void)
{
    errors();
    grids();
    cylinder();
    teapot();
    return bs_test_exit("test_tessellate");
}
