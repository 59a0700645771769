/* Sewing (lib/model/sew.c) on models of Bezier faces built here: a cube (12 edges, closed), a
 * pyramid whose side faces collapse at the apex (degenerate trims get no edge), a tube whose seam
 * is on its own face, trims run the same way and opposite ways, sides split differently and
 * sides whose ends agree but whose middles differ (not joined), a grid of 40,000 trims (the cost
 * of the sort), allocation failures (the model as before). */
#include "harness.h"

#include "model/internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static size_t fail_in;
void *__wrap_malloc(size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_malloc(n);
}
void *__wrap_realloc(void *p, size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_realloc(p, n);
}
#endif

/* The straight trim from (u0, v0) to (u1, v1) over [0, 1]. */
static bsi_trim seg(double u0, double v0, double u1, double v1)
{
    bsi_trim t;
    memset(&t, 0, sizeof t);
    CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &t.uv.axis) == BS_OK);
    t.uv.dim = 2;
    t.uv.degree = 1;
    t.uv.hom = malloc(6 * sizeof(double));
    double h[6] = {u0, v0, 1.0, u1, v1, 1.0};
    memcpy(t.uv.hom, h, sizeof h);
    t.edge = BSI_NO_EDGE;
    return t;
}

/* A face over a patch with one loop: the unit square's sides (counter-clockwise, or clockwise
 * with each trim reversed in its curve when flip), or the trims given. */
static void add_face(bs_model *m, const bs_patch *p, bsi_trim *trims, size_t n, size_t shell)
{
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.patch = p;
    spec.trims = trims;
    spec.ntrim = n;
    spec.loop_len = &n;
    spec.nloop = 1;
    spec.shell = shell;
    CHECK(bsi_model_add_face(m, &spec, NULL) == BS_OK);
}

static void add_square(bs_model *m, const bs_patch *p, int flip, size_t shell)
{
    bsi_trim t[4];
    if (!flip) {
        t[0] = seg(0, 0, 1, 0), t[1] = seg(1, 0, 1, 1), t[2] = seg(1, 1, 0, 1), t[3] = seg(0, 1, 0, 0);
    } else { /* the same loop, each curve run backwards (the loop along it from its end) */
        t[0] = seg(1, 0, 0, 0), t[1] = seg(1, 1, 1, 0), t[2] = seg(0, 1, 1, 1), t[3] = seg(0, 0, 0, 1);
        for (int k = 0; k < 4; k++)
            t[k].reversed = 1;
    }
    add_face(m, p, t, 4, shell);
}

/* A bilinear patch through corners (0,0), (1,0), (0,1), (1,1) of its domain. */
static bs_patch *bilinear(const double *c00, const double *c10, const double *c01, const double *c11)
{
    double ctrl[12];
    memcpy(ctrl + 0, c00, 3 * sizeof(double));
    memcpy(ctrl + 3, c01, 3 * sizeof(double));
    memcpy(ctrl + 6, c10, 3 * sizeof(double));
    memcpy(ctrl + 9, c11, 3 * sizeof(double));
    bs_patch *p = NULL;
    CHECK(bs_patch_create(1, 1, 3, ctrl, NULL, &p) == BS_OK);
    return p;
}

static size_t joined(const bs_model *m)
{
    size_t n = 0;
    for (size_t t = 0; t < m->ntrim; t++)
        n += m->trims[t].edge != BSI_NO_EDGE;
    return n;
}

/* Each edge used by exactly two trims. */
static int edges_paired(const bs_model *m)
{
    for (size_t e = 0; e < m->nedge; e++) {
        size_t uses = 0;
        for (size_t t = 0; t < m->ntrim; t++)
            uses += m->trims[t].edge == e;
        if (uses != 2)
            return 0;
    }
    return 1;
}

static const double V[8][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0},
                               {0, 0, 2}, {2, 0, 2}, {0, 2, 2}, {2, 2, 2}};

/* The cube's six faces (corners as indices into V: c00 c10 c01 c11), outward. */
static const int CUBE[6][4] = {{0, 2, 1, 3}, {4, 5, 6, 7}, {0, 1, 4, 5},
                               {2, 6, 3, 7}, {0, 4, 2, 6}, {1, 3, 5, 7}};

static bs_model *cube(int split, int flip_odd)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    for (int f = 0; f < 6; f++) {
        bs_patch *p = bilinear(V[CUBE[f][0]], V[CUBE[f][1]], V[CUBE[f][2]], V[CUBE[f][3]]);
        if (split && f == 0) {
            bsi_trim t[5] = {seg(0, 0, 0.5, 0), seg(0.5, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 1),
                             seg(0, 1, 0, 0)};
            add_face(m, p, t, 5, 0);
        } else {
            add_square(m, p, flip_odd && f % 2, 0);
        }
        bs_patch_destroy(p);
    }
    return m;
}

static void test_cube(void)
{
    for (int flip = 0; flip < 2; flip++) {
        bs_model *m = cube(0, flip);
        CHECK(bsi_model_finish(m) == BS_OK);
        CHECKF(m->nedge == 12 && joined(m) == 24 && edges_paired(m), "flip %d: %zu edges", flip, m->nedge);
        CHECK(bs_model_shell_closed(m, 0) == 1);
        bs_model_destroy(m);
    }
    /* ends a rounding outside the face's box are on its side */
    bs_model *r = cube(0, 0);
    r->trims[1].uv.hom[0] = 1.0 + 1e-12;
    r->trims[3].uv.hom[3] = -1e-12;
    CHECK(bsi_model_sew(r, 1e-7, 1e-7) == BS_OK);
    CHECKF(r->nedge == 12 && joined(r) == 24, "rounded ends: %zu edges", r->nedge);
    bs_model_destroy(r);
    /* one side split in two on one face only: those three trims are not joined */
    bs_model *m = cube(1, 0);
    CHECK(bsi_model_finish(m) == BS_OK);
    CHECKF(m->nedge == 11 && joined(m) == 22 && edges_paired(m), "split: %zu edges", m->nedge);
    CHECK(bs_model_shell_closed(m, 0) == 0);
    /* sewing again changes nothing: every trim left is unmatched */
    CHECK(bsi_model_sew(m, 1e-7, 1e-7) == BS_OK && m->nedge == 11);
    bs_model_destroy(m);
}

/* Four side faces collapsing at the apex and a base: the trims at the apex get no edge. */
static void test_pyramid(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    const double apex[3] = {1, 1, 1.5};
    const int ring[5] = {0, 1, 3, 2, 0};
    for (int k = 0; k < 4; k++) {
        bs_patch *p = bilinear(V[ring[k]], V[ring[k + 1]], apex, apex);
        add_square(m, p, k == 2, 0);
        bs_patch_destroy(p);
    }
    bs_patch *base = bilinear(V[0], V[2], V[1], V[3]);
    add_square(m, base, 0, 0);
    bs_patch_destroy(base);
    CHECK(bsi_model_finish(m) == BS_OK);
    CHECKF(m->nedge == 8 && joined(m) == 16 && edges_paired(m), "pyramid: %zu edges", m->nedge);
    for (size_t f = 0; f < 4; f++) /* the third trim of each side face runs along the apex */
        CHECK(m->trims[m->loops[m->faces[f].first_loop].first_trim + 2].edge == BSI_NO_EDGE);
    CHECK(bs_model_shell_closed(m, 0) == 1);
    bs_model_destroy(m);
}

/* A tube: a closed cubic (first and last control points equal) swept along z; its u = 0 and
 * u = 1 sides are one seam of the same face. */
static void test_seam(void)
{
    static const double loop[4][2] = {{0, 0}, {4, -3}, {4, 3}, {0, 0}};
    double ctrl[4 * 2 * 3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 2; j++) {
            double *q = ctrl + (i * 2 + j) * 3;
            q[0] = loop[i][0];
            q[1] = loop[i][1];
            q[2] = 2.0 * j;
        }
    bs_patch *p = NULL;
    CHECK(bs_patch_create(3, 1, 3, ctrl, NULL, &p) == BS_OK);
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    add_square(m, p, 0, 0);
    bs_patch_destroy(p);
    CHECK(bsi_model_finish(m) == BS_OK);
    CHECKF(m->nedge == 1, "seam: %zu edges", m->nedge);
    CHECK(m->trims[1].edge == 0 && m->trims[3].edge == 0);
    CHECK(m->trims[0].edge == BSI_NO_EDGE && m->trims[2].edge == BSI_NO_EDGE);
    CHECK(bs_model_shell_closed(m, 0) == 0);
    bs_model_destroy(m);
}

/* Two faces whose shared side agrees at its ends only (one bulges): not joined. */
static void test_bulge(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    bs_patch *a = bilinear(V[0], V[1], V[2], V[3]);
    add_square(m, a, 0, 0);
    bs_patch_destroy(a);
    /* biquadratic from x = 2 to 4 whose side x = 2 bulges up by 1e-3 in its middle */
    double ctrl[9 * 3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *q = ctrl + (i * 3 + j) * 3;
            q[0] = 2.0 + i;
            q[1] = j;
            q[2] = i == 0 && j == 1 ? 2e-3 : 0.0;
        }
    bs_patch *b = NULL;
    CHECK(bs_patch_create(2, 2, 3, ctrl, NULL, &b) == BS_OK);
    add_square(m, b, 0, 0);
    bs_patch_destroy(b);
    CHECK(bsi_model_sew(m, 1e-6, 1e-6) == BS_OK);
    CHECK(m->nedge == 0 && joined(m) == 0);
    /* the loose tolerance is for closed trims only */
    CHECK(bsi_model_sew(m, 1e-6, 2e-3) == BS_OK);
    CHECK(m->nedge == 0 && joined(m) == 0);
    /* within a looser tolerance they are one */
    CHECK(bsi_model_sew(m, 2e-3, 2e-3) == BS_OK);
    CHECK(m->nedge == 1 && m->trims[1].edge == 0 && m->trims[7].edge == 0);
    bs_model_destroy(m);
}

/* Two faces sharing a side, one trim along it a quadratic of uneven speed: joined by the search
 * for the nearest point (the same fractions of the two ranges are different points). */
static void test_speed(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    bs_patch *a = bilinear(V[0], V[1], V[2], V[3]);
    add_square(m, a, 0, 0);
    bs_patch_destroy(a);
    const double c10[3] = {4, 0, 0}, c11[3] = {4, 2, 0};
    bs_patch *b = bilinear(V[1], c10, V[3], c11);
    bsi_trim t[4] = {seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 1), seg(0, 1, 0, 0)};
    /* u = 0 from v = 1 down to v = 0 with control points 1, 0.1, 0 */
    double *h = realloc(t[3].uv.hom, 9 * sizeof(double));
    CHECK(h != NULL);
    double q[9] = {0, 1, 1, 0, 0.1, 1, 0, 0, 1};
    memcpy(h, q, sizeof q);
    t[3].uv.hom = h;
    t[3].uv.degree = 2;
    add_face(m, b, t, 4, 0);
    bs_patch_destroy(b);
    CHECK(bsi_model_sew(m, 1e-7, 1e-7) == BS_OK);
    CHECK(m->nedge == 1 && m->trims[1].edge == 0 && m->trims[7].edge == 0);
    bs_model_destroy(m);
}

/* A full circle of centre (0.5, 0.5), radius 0.25 in uv as one trim of four quarter arcs,
 * starting at angle a0, counter-clockwise or not. */
static bsi_trim circle_trim(double a0, int ccw)
{
    bsi_trim t;
    memset(&t, 0, sizeof t);
    CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 4.0, (const double[]){1.0, 2.0, 3.0}, 3, &t.uv.axis) == BS_OK);
    t.uv.dim = 2;
    t.uv.degree = 2;
    t.uv.hom = malloc(4 * 3 * 3 * sizeof(double));
    double q = 1.5707963267948966 * (ccw ? 1.0 : -1.0), w = cos(0.25 * 3.141592653589793);
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 3; i++) {
            double a = a0 + q * (k + 0.5 * i), r = i == 1 ? 0.25 / w : 0.25, wt = i == 1 ? w : 1.0;
            double *h = t.uv.hom + (k * 3 + i) * 3;
            h[0] = wt * (0.5 + r * cos(a));
            h[1] = wt * (0.5 + r * sin(a));
            h[2] = wt;
        }
    t.edge = BSI_NO_EDGE;
    return t;
}

/* A plate over the patch p (trims 0..4) with a round hole (its trim 4, starting at angle 0). */
static void add_plate_with_hole(bs_model *m, const bs_patch *p)
{
    bsi_trim plate[5] = {seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 1), seg(0, 1, 0, 0), circle_trim(0.0, 0)};
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.patch = p;
    spec.trims = plate;
    spec.ntrim = 5;
    size_t lens[2] = {4, 1};
    spec.loop_len = lens;
    spec.nloop = 2;
    CHECK(bsi_model_add_face(m, &spec, NULL) == BS_OK);
}

/* A plate with a round hole and the plug filling it, each side of the hole one closed trim
 * starting at a different point: joined by their images. */
static void test_hole(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    const double c11[3] = {2, 2, 0.5};
    bs_patch *p = bilinear(V[0], V[1], V[2], c11);
    add_plate_with_hole(m, p);
    bsi_trim plug[1] = {circle_trim(2.0, 1)};
    add_face(m, p, plug, 1, 0);
    bs_patch_destroy(p);
    /* a plug of another plate 1 higher: its loop matches nothing */
    const double l00[3] = {0, 0, 1}, l10[3] = {2, 0, 1}, l01[3] = {0, 2, 1}, l11[3] = {2, 2, 1.5};
    p = bilinear(l00, l10, l01, l11);
    bsi_trim other[1] = {circle_trim(1.0, 1)};
    add_face(m, p, other, 1, 0);
    bs_patch_destroy(p);
    CHECK(bsi_model_sew(m, 1e-7, 1e-7) == BS_OK);
    CHECKF(m->nedge == 1 && m->trims[4].edge == 0 && m->trims[5].edge == 0, "hole: %zu edges", m->nedge);
    CHECK(m->trims[6].edge == BSI_NO_EDGE);
    bs_model_destroy(m);
}

/* The plate with a hole, and the plug of a plate 1e-3 higher (a file's trims of one hole written
 * apart): joined only within the loose tolerance. */
static void test_hole_apart(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    const double c11[3] = {2, 2, 0.5};
    bs_patch *p = bilinear(V[0], V[1], V[2], c11);
    add_plate_with_hole(m, p);
    bs_patch_destroy(p);
    const double l00[3] = {0, 0, 1e-3}, l10[3] = {2, 0, 1e-3}, l01[3] = {0, 2, 1e-3}, l11[3] = {2, 2, 0.5 + 1e-3};
    p = bilinear(l00, l10, l01, l11);
    bsi_trim plug[1] = {circle_trim(2.0, 1)};
    add_face(m, p, plug, 1, 0);
    bs_patch_destroy(p);
    CHECK(bsi_model_sew(m, 1e-7, 5e-4) == BS_OK);
    CHECKF(m->nedge == 0, "hole 1e-3 apart at 5e-4: %zu edges", m->nedge);
    CHECK(bsi_model_sew(m, 1e-7, 2e-3) == BS_OK);
    CHECKF(m->nedge == 1 && m->trims[4].edge == 0 && m->trims[5].edge == 0, "hole 1e-3 apart at 2e-3: %zu edges",
           m->nedge);
    bs_model_destroy(m);
}

/* An N x N grid of wavy bilinear faces, alternate faces' trims run backwards. */
static bs_model *grid(size_t N)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    for (size_t i = 0; i < N; i++)
        for (size_t j = 0; j < N; j++) {
            double c[4][3];
            for (int k = 0; k < 4; k++) {
                double x = (double)(i + (size_t)(k & 1)), y = (double)(j + (size_t)(k >> 1));
                c[k][0] = x;
                c[k][1] = y;
                c[k][2] = 0.3 * sin(0.7 * x) * cos(0.4 * y);
            }
            bs_patch *p = bilinear(c[0], c[1], c[2], c[3]);
            add_square(m, p, (i + j) % 2, 0);
            bs_patch_destroy(p);
        }
    return m;
}

static void test_grid(void)
{
    size_t N = bs_test_quick() ? 20 : 100;
    bs_model *m = grid(N);
    clock_t c0 = clock();
    CHECK(bsi_model_sew(m, 1e-6, 1e-6) == BS_OK);
    double secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
    printf("  grid of %zu faces, %zu trims: %zu edges sewn in %.3f s\n", N * N, m->ntrim, m->nedge, secs);
    CHECK(m->nedge == 2 * N * (N - 1) && edges_paired(m));
    bs_model_destroy(m);
}

static void test_small(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    CHECK(bsi_model_sew(m, 1e-7, 1e-7) == BS_OK && m->nedge == 0); /* no trims */
    CHECK(bsi_model_finish(m) == BS_OK);
    bs_model_destroy(m);
    /* a trim with an edge already is left alone; so is one off its face */
    m = cube(0, 0);
    m->trims[0].edge = 0;
    CHECK(bsi_model_add_edge(m, &(uint32_t){0}) == BS_OK);
    bsi_curve *c = &m->trims[5].uv;
    c->hom[0] = 7.0; /* starts at u = 7: outside the face */
    CHECK(bsi_model_sew(m, 1e-7, 1e-7) == BS_OK);
    CHECK(m->trims[0].edge == 0 && m->trims[5].edge == BSI_NO_EDGE);
    CHECKF(m->nedge == 11, "%zu edges", m->nedge);
    bs_model_destroy(m);
}

static void test_no_memory(void)
{
#ifdef BS_WRAP_MALLOC
    int failed = 0;
    for (size_t n = 1; n < 20; n++) {
        bs_model *m = cube(0, 0);
        fail_in = n;
        bs_status st = bsi_model_sew(m, 1e-7, 1e-7);
        fail_in = 0;
        if (st == BS_OK) {
            CHECK(m->nedge == 12);
            bs_model_destroy(m);
            break;
        }
        CHECK(st == BS_ERR_NO_MEMORY && m->nedge == 0 && joined(m) == 0);
        failed++;
        bs_model_destroy(m);
    }
    CHECK(failed >= 4);
#endif
}

int main(void)
{
    test_cube();
    test_pyramid();
    test_seam();
    test_bulge();
    test_speed();
    test_hole();
    test_hole_apart();
    test_grid();
    test_small();
    test_no_memory();
    return bs_test_exit("test_sew");
}
