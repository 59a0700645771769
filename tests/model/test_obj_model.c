/* OBJ free-form models (bs_model_read_obj, bs_model_write_obj): faces of B-spline and Bezier surfs
 * against de Boor and de Casteljau in long double, trim loops (a rational circle against its
 * closed form, classification inside / outside / on), the write -> read round trip bit for bit
 * (patches, axes, trims) on files and on models of surfaces, every refusal with its position, the
 * geometry cap and allocation failures. Internal: trims are compared as the model holds them. */
#include "harness.h"
#include "io/internal.h"
#include "model/internal.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
static size_t fail_in;
void *__wrap_malloc(size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_malloc(n);
}
#endif

#define DATA BS_TEST_SOURCE_DIR "/data/obj/"

/* A file's bytes, NUL-terminated for the string functions (the reader's buffer is not). */
static char *slurp(const char *name, size_t *len)
{
    char *text = NULL;
    *len = 0;
    CHECK_STATUS(bsi_read_file(name, NULL, &text, len), BS_OK);
    char *z = realloc(text, *len + 1);
    if (z == NULL) {
        free(text);
        return NULL;
    }
    z[*len] = '\0';
    return z;
}

/* ---- exact comparison of two models (edge ids, shells and instances aside) ---- */
static int same_axis(const bsi_axis *a, const bsi_axis *b)
{
    if (a->kind != b->kind || a->n != b->n)
        return 0;
    for (size_t k = 0; k <= a->n; k++)
        if (a->breaks[k] != b->breaks[k])
            return 0;
    return 1;
}

static int same_patch(const bs_patch *p, const bs_patch *q)
{
    if (p->deg_u != q->deg_u || p->deg_v != q->deg_v || p->rational != q->rational)
        return 0;
    for (size_t k = 0; k < p->nctrl; k++) {
        for (size_t c = 0; c < 3; c++)
            if (p->ctrl[3 * k + c] != q->ctrl[3 * k + c])
                return 0;
        if (p->rational && p->weights[k] != q->weights[k])
            return 0;
    }
    return 1;
}

/* p against q, or against q with its parameters exchanged when tr. */
static int same_patch_tr(const bs_patch *p, const bs_patch *q, int tr)
{
    if (!tr)
        return same_patch(p, q);
    if (p->deg_u != q->deg_v || p->deg_v != q->deg_u || p->rational != q->rational)
        return 0;
    for (size_t i = 0; i <= p->deg_u; i++)
        for (size_t j = 0; j <= p->deg_v; j++) {
            size_t x = i * (p->deg_v + 1) + j, y = j * (q->deg_v + 1) + i;
            for (size_t c = 0; c < 3; c++)
                if (p->ctrl[3 * x + c] != q->ctrl[3 * y + c])
                    return 0;
            if (p->rational && p->weights[x] != q->weights[y])
                return 0;
        }
    return 1;
}

static int same_trim(const bsi_trim *a, const bsi_trim *b)
{
    const bsi_curve *c = &a->uv, *d = &b->uv;
    if (a->reversed != b->reversed || c->dim != d->dim || c->degree != d->degree || !same_axis(&c->axis, &d->axis))
        return 0;
    for (size_t k = 0; k < c->axis.n * (c->degree + 1) * 3; k++)
        if (c->hom[k] != d->hom[k])
            return 0;
    return 1;
}

static void same_models(const bs_model *a, const bs_model *b, const char *what)
{
    CHECKF(a->nface == b->nface && a->nloop == b->nloop && a->ntrim == b->ntrim, "%s: counts", what);
    if (a->nface != b->nface || a->nloop != b->nloop || a->ntrim != b->ntrim)
        return;
    size_t bad = 0;
    for (size_t f = 0; f < a->nface; f++) {
        const bsi_face *x = &a->faces[f], *y = &b->faces[f];
        bad += x->kind != y->kind || x->reversed != y->reversed || x->swap != y->swap ||
               x->patch_count != y->patch_count || x->loop_count != y->loop_count ||
               memcmp(x->box, y->box, sizeof x->box) != 0 || !same_axis(&x->au, &y->au) ||
               !same_axis(&x->av, &y->av);
        for (size_t p = 0; p < x->patch_count && p < y->patch_count; p++)
            bad += !same_patch(bs_surface_get(a->surface, x->first_patch + p),
                               bs_surface_get(b->surface, y->first_patch + p));
    }
    for (size_t l = 0; l < a->nloop; l++)
        bad += a->loops[l].trim_count != b->loops[l].trim_count;
    for (size_t t = 0; t < a->ntrim; t++)
        bad += !same_trim(&a->trims[t], &b->trims[t]);
    CHECKF(bad == 0, "%s: %zu differences", what, bad);
}

/* m written and read back, compared exactly; the text written again is the same. */
static void round_trip(const bs_model *m, const char *what)
{
    size_t size = 0, size2 = 0;
    CHECK_STATUS(bs_model_write_obj(m, NULL, 0, &size), BS_OK);
    char *text = malloc(size + 1), *again = NULL;
    CHECK_STATUS(bs_model_write_obj(m, text, size + 1, &size), BS_OK);
    CHECK(strlen(text) == size);
    bs_model *back = NULL;
    bs_parse_error err = {0, 0, ""};
    CHECK_STATUS(bs_model_read_obj(text, size, &err, &back), BS_OK);
    CHECKF(back != NULL, "%s: line %zu column %zu: %s", what, err.line, err.column, err.message);
    if (back != NULL) {
        same_models(m, back, what);
        CHECK_STATUS(bs_model_write_obj(back, NULL, 0, &size2), BS_OK);
        again = malloc(size2 + 1);
        CHECK_STATUS(bs_model_write_obj(back, again, size2 + 1, &size2), BS_OK);
        CHECKF(size2 == size && memcmp(text, again, size) == 0, "%s: the text written again differs", what);
    }
    printf("%s: %zu faces, %zu bytes written, read back bit for bit\n", what, m->nface, size);
    free(again);
    free(text);
    bs_model_destroy(back);
}

/* ---- references in long double ---- */
/* de Boor: point of a non-rational B-spline curve of n points (stride 3 doubles, coordinate c). */
static long double de_boor(const double *k, size_t p, size_t n, const double *pts, size_t step, long double t)
{
    size_t i = p;
    while (i + 1 < n && t >= k[i + 1])
        i++;
    long double d[BS_MAX_DEGREE + 1];
    for (size_t j = 0; j <= p; j++)
        d[j] = pts[(i - p + j) * step];
    for (size_t r = 1; r <= p; r++)
        for (size_t j = p; j >= r; j--) {
            size_t a = i - p + j;
            long double al = (t - k[a]) / ((long double)k[a + p + 1 - r] - k[a]);
            d[j] = (1 - al) * d[j - 1] + al * d[j];
        }
    return d[p];
}

static const double plate_ku[] = {0, 0, 0, 0, 1, 2, 2, 2, 2}, plate_kv[] = {0, 0, 0, 1, 2, 2, 2};

/* The plate's point (the file's 5 x 4 net, u fastest) by de Boor along u then v. */
static void plate_point(const double *net, long double u, long double v, long double *out)
{
    for (int c = 0; c < 3; c++) {
        double col[4];
        for (size_t j = 0; j < 4; j++)
            col[j] = (double)de_boor(plate_ku, 3, 5, net + 15 * j + (size_t)c, 3, u);
        out[c] = de_boor(plate_kv, 2, 4, col, 1, v);
    }
}

static void eval_face(const bs_model *m, double u, double v, double *p, double *n)
{
    uint32_t face = 0;
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view pv[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
    bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
    CHECK_STATUS(bs_model_face_eval(m, 1, &face, &cu, &cv, pv, n ? nv : NULL, NULL), BS_OK);
}

static int classify(const bs_model *m, double u, double v, double tol)
{
    uint32_t face = 0;
    unsigned char where = 255;
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, tol, &where), BS_OK);
    return where;
}

static void test_plate(void)
{
    bs_parse_error err = {0, 0, ""};
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_obj_file(DATA "plate_hole.obj", &err, &m), BS_OK);
    if (m == NULL) {
        fprintf(stderr, "plate_hole.obj: line %zu column %zu: %s\n", err.line, err.column, err.message);
        return;
    }
    bs_face_info fi;
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_OK);
    CHECK(bs_model_face_count(m) == 1 && fi.kind == BS_FACE_BSPLINE && fi.reversed == 0);
    CHECK(fi.patch_count == 4 && fi.loop_count == 2 && fi.u0 == 0 && fi.u1 == 2 && fi.v0 == 0 && fi.v1 == 2);
    CHECK(m->loops[0].trim_count == 2 && m->loops[1].trim_count == 1 && m->trims[2].reversed == 1);
    /* the face against de Boor on the file's net */
    double net[60];
    size_t len;
    char *text = slurp(DATA "plate_hole.obj", &len);
    const char *at = text;
    for (size_t k = 0; k < 20 && (at = strstr(at, "\nv ")) != NULL; k++, at++)
        CHECK(sscanf(at + 3, "%lf %lf %lf", &net[3 * k], &net[3 * k + 1], &net[3 * k + 2]) == 3);
    double worst = 0.0;
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            double u = 0.25 * i, v = 0.25 * j, p[3];
            long double q[3];
            eval_face(m, u, v, p, NULL);
            plate_point(net, u, v, q);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, (double)fabsl(p[c] - q[c]));
        }
    printf("test_obj_model: plate against de Boor: largest error %.3g\n", worst);
    CHECK(worst < 1e-14);
    /* the hole: a circle of radius 0.5 about (1, 1) */
    double rmax = 0.0;
    for (size_t k = 0; k < m->trims[2].uv.axis.n; k++)
        for (int i = 0; i <= 16; i++) {
            double xy[2];
            bsi_curve_point(&m->trims[2].uv, k, i / 16.0, xy);
            rmax = fmax(rmax, fabs(hypot(xy[0] - 1.0, xy[1] - 1.0) - 0.5));
        }
    printf("test_obj_model: hole against the circle: largest radius error %.3g\n", rmax);
    CHECK(rmax < 1e-15);
    CHECK(classify(m, 1.0, 1.0, 1e-9) == BS_TRIM_OUTSIDE);
    CHECK(classify(m, 0.3, 0.3, 1e-9) == BS_TRIM_INSIDE);
    CHECK(classify(m, 1.8, 1.0, 1e-9) == BS_TRIM_INSIDE);
    CHECK(classify(m, 1.9, 1.0, 1e-9) == BS_TRIM_ON);
    CHECK(classify(m, 0.05, 1.0, 1e-9) == BS_TRIM_OUTSIDE);
    CHECK(classify(m, 1.5, 1.0, 1e-9) == BS_TRIM_ON);
    CHECK(bs_model_edge_count(m) == 0 && bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == 0);
    round_trip(m, "plate_hole.obj");
    /* the same text in memory, and one surf after another */
    bs_model *twice = NULL;
    char *two = malloc(2 * len);
    memcpy(two, text, len);
    memcpy(two + len, text, len);
    CHECK_STATUS(bs_model_read_obj(two, 2 * len, NULL, &twice), BS_OK);
    CHECK(bs_model_face_count(twice) == 2 && bs_surface_count(bs_model_surface(twice)) == 8);
    round_trip(twice, "plate_hole.obj twice");
    bs_model_destroy(twice);
    free(two);
    free(text);
    bs_model_destroy(m);
}

/* Rational Bezier point of the strip's segment (a: 0 or 1) at local (s, t), long double. */
static void strip_point(const double *net, size_t a, long double s, long double t, long double *out)
{
    long double h[2][3][4];
    for (size_t j = 0; j < 2; j++)
        for (size_t i = 0; i < 3; i++) {
            const double *x = net + 4 * (j * 5 + 2 * a + i);
            for (int c = 0; c < 3; c++)
                h[j][i][c] = (long double)x[c] * x[3];
            h[j][i][3] = x[3];
        }
    long double r[2][4];
    for (size_t j = 0; j < 2; j++)
        for (int c = 0; c < 4; c++) {
            long double b0 = h[j][0][c], b1 = h[j][1][c], b2 = h[j][2][c];
            r[j][c] = (1 - s) * (1 - s) * b0 + 2 * s * (1 - s) * b1 + s * s * b2;
        }
    for (int c = 0; c < 3; c++)
        out[c] = ((1 - t) * r[0][c] + t * r[1][c]) / ((1 - t) * r[0][3] + t * r[1][3]);
}

static void test_strip(void)
{
    bs_parse_error err = {0, 0, ""};
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_obj_file(DATA "bezier_strip.obj", &err, &m), BS_OK);
    if (m == NULL) {
        fprintf(stderr, "bezier_strip.obj: line %zu column %zu: %s\n", err.line, err.column, err.message);
        return;
    }
    bs_face_info fi;
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_OK);
    CHECK(fi.kind == BS_FACE_BEZIER && fi.patch_count == 2 && fi.loop_count == 2);
    CHECK(fi.u0 == 0 && fi.u1 == 3 && fi.v0 == 0 && fi.v1 == 2);
    CHECK(m->loops[0].trim_count == 4 && m->loops[1].trim_count == 1);
    double net[40];
    size_t len;
    char *text = slurp(DATA "bezier_strip.obj", &len);
    const char *at = text;
    for (size_t k = 0; k < 10 && (at = strstr(at, "\nv ")) != NULL; k++, at++)
        CHECK(sscanf(at + 3, "%lf %lf %lf %lf", &net[4 * k], &net[4 * k + 1], &net[4 * k + 2], &net[4 * k + 3]) == 4);
    free(text);
    double worst = 0.0;
    for (int i = 0; i <= 12; i++)
        for (int j = 0; j <= 4; j++) {
            double u = 0.25 * i, v = 0.5 * j, p[3];
            long double q[3];
            eval_face(m, u, v, p, NULL);
            if (u <= 1.0)
                strip_point(net, 0, u, v / 2, q);
            else
                strip_point(net, 1, (u - 1) / 2, v / 2, q);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, (double)fabsl(p[c] - q[c]));
        }
    printf("test_obj_model: strip against de Casteljau: largest error %.3g\n", worst);
    CHECK(worst < 1e-14);
    CHECK(classify(m, 1.5, 0.8, 1e-9) == BS_TRIM_OUTSIDE); /* in the triangle */
    CHECK(classify(m, 0.2, 1.8, 1e-9) == BS_TRIM_INSIDE);
    CHECK(classify(m, 2.9, 0.1, 1e-9) == BS_TRIM_INSIDE);
    round_trip(m, "bezier_strip.obj");
    bs_model_destroy(m);
}

/* A unit cube of bilinear patches (outward normals) and a biquadratic patch. */
static bs_surface *cube(void)
{
    static const double corners[6][4][3] = {
        {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}},
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 0}, {1, 1, 1}},
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 1, 1}}, {{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}},
    };
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    for (int f = 0; f < 6; f++) {
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(1, 1, 3, &corners[f][0][0], NULL, &p), BS_OK);
        CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
        bs_patch_destroy(p);
    }
    return s;
}

static void test_models_of_surfaces(void)
{
    bs_surface *s = cube();
    bs_model *m = NULL, *back = NULL;
    CHECK_STATUS(bs_model_from_surface(s, &m), BS_OK);
    bs_surface_destroy(s);
    round_trip(m, "cube of 6 Bezier faces");
    size_t size;
    CHECK_STATUS(bs_model_write_obj(m, NULL, 0, &size), BS_OK);
    char *text = malloc(size + 1);
    CHECK_STATUS(bs_model_write_obj(m, text, size + 1, &size), BS_OK);
    CHECK_STATUS(bs_model_read_obj(text, size, NULL, &back), BS_OK);
    /* the reader sews the faces again: 12 edges, a closed shell */
    CHECK(bs_model_edge_count(back) == 12 && bs_model_shell_count(back) == 1 && bs_model_shell_closed(back, 0) == 1);
    bs_model_destroy(back);
    free(text);

    /* a reversed face: u and v exchanged, the outward normal kept */
    static const double net[27] = {0, 0, 0, 0, 1, 0.5, 0, 2, 0, 1, 0, 0.25, 1, 1, 1, 1, 2, 0.2,
                                   2, 0, 0, 2, 1, -0.5, 2, 2.5, 0.3};
    static const double w[9] = {1, 2, 1, 0.5, 1, 3, 1, 1, 0.75};
    bs_patch *p = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net, w, &p), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    bs_patch_destroy(p);
    bs_model *r = NULL;
    CHECK_STATUS(bs_model_from_surface(s, &r), BS_OK);
    bs_surface_destroy(s);
    r->faces[0].reversed = 1;
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_OK);
    text = malloc(size + 1);
    CHECK_STATUS(bs_model_write_obj(r, text, size + 1, &size), BS_OK);
    CHECK_STATUS(bs_model_read_obj(text, size, NULL, &back), BS_OK);
    free(text);
    double worst = 0.0;
    for (int i = 0; back != NULL && i <= 4; i++)
        for (int j = 0; j <= 4; j++) {
            double u = 0.25 * i, v = 0.25 * j, a[3], na[3], b[3], nb[3];
            eval_face(r, u, v, a, na);
            eval_face(back, v, u, b, nb);
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, fmax(fabs(a[c] - b[c]), fabs(na[c] - nb[c])));
        }
    CHECKF(back != NULL && back->faces[0].reversed == 0 && worst < 1e-15, "reversed face: %.3g", worst);
    bs_model_destroy(back);

    /* what the writer refuses or cannot fit */
    char small[8];
    CHECK_STATUS(bs_model_write_obj(r, small, sizeof small, &size), BS_ERR_SIZE);
    CHECK(size > sizeof small);
    CHECK_STATUS(bs_model_write_obj(NULL, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_write_obj_file(r, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_write_obj_file(NULL, "x.obj"), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_write_obj_file(r, "/nonexistent-dir/x.obj"), BS_ERR_IO);
    CHECK_STATUS(bs_model_write_obj_file(r, "test_obj_model.tmp.obj"), BS_OK);
    CHECK_STATUS(bs_model_read_obj_file("test_obj_model.tmp.obj", NULL, &back), BS_OK);
    CHECK(bs_model_face_count(back) == 1);
    bs_model_destroy(back);
    (void)remove("test_obj_model.tmp.obj");
    /* an angular u: the sides (constant u, or constant v and monotone u) are written; a diagonal
     * or a trim beyond the axis is refused */
    r->faces[0].au.kind = BSI_AXIS_ANGULAR;
    r->faces[0].au.radians = 1.0;
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_OK);
    double *h0 = r->trims[0].uv.hom, *h1 = r->trims[1].uv.hom, keep = h0[4];
    h0[4] = 0.5; /* side 0 from (0, 0) to (1, 0.5) */
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    CHECK_STATUS(bs_model_write_obj_file(r, "test_obj_model.tmp.obj"), BS_ERR_UNSUPPORTED);
    h0[4] = keep;
    keep = h0[3];
    h0[3] = 5.0; /* side 0 running past u = 1 */
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    h0[3] = keep;
    h1[0] = h1[3] = 5.0; /* side 1 at u = 5 */
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    h1[0] = h1[3] = 1.0;
    r->faces[0].au.kind = BSI_AXIS_LINEAR;
    r->trims[0].uv.dim = 3;
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    r->trims[0].uv.dim = 2;
    r->faces[0].kind = BS_FACE_PLANE; /* a plane is written as a B-spline surface */
    CHECK_STATUS(bs_model_write_obj(r, NULL, 0, &size), BS_OK);
    bs_model_destroy(r);
    bs_model_destroy(m);
}

/* Odd but valid text: CR LF, tabs, colours, continuations with blanks after the backslash, a
 * backslash at the very end, a 3-D curve's body skipped; a Bezier surface of 2 x 2 segments and
 * one of degree 0. Then faces the writer must write as B-splines or refuse. */
static void test_quirks(void)
{
    static const char text[] =
        "# quirks\r\nv 0 0 0 0.5 0.5 0.5\r\nv 1 0 0\t\r\nv 0 1 \\  \t\r\n  0.25\r\nv 1 1 0\r\n"
        "curv 0 1 1 2\r\nparm u 0 1\r\nend\r\n"
        "cstype bezier\r\ndeg 1 1\r\nsurf 0 1 0 1 1 2 3 4 # one patch\r\nend\r\n"
        "v 0 0 0\nv 1 0 0\nv 2 0 1\nv 0 1 0\nv 1 1 2\nv 2 1 0\nv 0 2 1\nv 1 2 0\nv 2 2 0\n"
        "surf 0 2 0 2 -9 -8 -7 -6 -5 -4 -3 -2 -1\nparm u 0 1 2\nparm v 0 1 2\nend\n"
        "deg 0 1\nsurf 0 1 0 1 1 2\nend\nv 2 2 2 \\";
    bs_parse_error err = {0, 0, ""};
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_obj(text, sizeof text - 1, &err, &m), BS_OK);
    CHECKF(m != NULL && bs_model_face_count(m) == 3, "%zu:%zu %s", err.line, err.column, err.message);
    if (m == NULL)
        return;
    const bs_patch *p0 = bs_surface_get(m->surface, 0);
    CHECK(p0->ctrl[3 * 1 + 2] == 0.25 && m->faces[1].patch_count == 4 && m->faces[2].patch_count == 1);
    round_trip(m, "quirks");
    /* shared sides that differ: written as a B-spline of separate spans, the patches kept */
    bs_patch *p = (bs_patch *)bs_surface_get(m->surface, m->faces[1].first_patch);
    p->ctrl[3 * 1 + 2] = 0.5; /* point (0, 1): the side shared with the next patch along v */
    size_t size;
    CHECK_STATUS(bs_model_write_obj(m, NULL, 0, &size), BS_OK);
    char *out = malloc(size + 1);
    CHECK_STATUS(bs_model_write_obj(m, out, size + 1, &size), BS_OK);
    bs_model *back = NULL;
    CHECK_STATUS(bs_model_read_obj(out, size, NULL, &back), BS_OK);
    free(out);
    CHECK(back != NULL && back->faces[1].kind == BS_FACE_BSPLINE && back->faces[1].patch_count == 4);
    for (size_t k = 0; back != NULL && k < 4; k++)
        CHECK(same_patch(bs_surface_get(m->surface, m->faces[1].first_patch + k),
                         bs_surface_get(back->surface, back->faces[1].first_patch + k)));
    bs_model_destroy(back);
    /* patches of two degrees in one face; a B-spline face of degree 0 */
    p = (bs_patch *)bs_surface_get(m->surface, m->faces[1].first_patch + 1);
    p->deg_u++;
    CHECK_STATUS(bs_model_write_obj(m, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    p->deg_u--;
    m->faces[2].kind = BS_FACE_BSPLINE;
    CHECK_STATUS(bs_model_write_obj(m, NULL, 0, &size), BS_ERR_UNSUPPORTED);
    bs_model_destroy(m);
}

/* The value after `key` in a CAD part's .ref file. */
static double ref_value(const char *part, const char *key)
{
    char path[512], line[256];
    double x = NAN;
    (void)snprintf(path, sizeof path, "%s/%s.ref", BS_CAD_DIR, part);
    FILE *f = fopen(path, "r");
    size_t n = strlen(key);
    while (f != NULL && fgets(line, sizeof line, f) != NULL)
        if (strncmp(line, key, n) == 0 && line[n] == ' ')
            x = strtod(line + n + 1, NULL);
    if (f != NULL)
        (void)fclose(f);
    return x;
}

/* CAD parts read from IGES, written and read back: the same patches bit for bit, edges, closed
 * shells, and area and volume as OpenCASCADE's; parts with trims that angular parameters cannot
 * carry exactly are refused and leave no file. */
static void test_cad(void)
{
    static const char *const parts[][2] = {{"duct", "duct.igs"}, {"duct", "duct-brep.igs"}, {"wedge", "wedge.igs"},
                                           {"wedge", "wedge-brep.igs"}, {"cone", "cone-brep.igs"},
                                           {"sphere", "sphere-brep.igs"}, {"bottle", "bottle.igs"},
                                           {"block", "block-brep.igs"}};
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        char path[512];
        (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, parts[k][1]);
        bs_model *m = NULL, *back = NULL;
        bs_parse_error err = {0, 0, ""};
        CHECKF(bs_model_read_iges_file(path, &err, &m) == BS_OK, "%s: %s", parts[k][1], err.message);
        if (m == NULL)
            continue;
        if (k >= 6) {
            CHECK_STATUS(bs_model_write_obj_file(m, "test_obj_model.cad.obj"), BS_ERR_UNSUPPORTED);
            FILE *left = fopen("test_obj_model.cad.obj", "r");
            CHECK(left == NULL);
            if (left != NULL)
                (void)fclose(left);
            printf("test_obj_model: %s: refused (trims not exact in the patches' parameters)\n", parts[k][1]);
            bs_model_destroy(m);
            continue;
        }
        CHECK_STATUS(bs_model_write_obj_file(m, "test_obj_model.cad.obj"), BS_OK);
        CHECK_STATUS(bs_model_read_obj_file("test_obj_model.cad.obj", &err, &back), BS_OK);
        (void)remove("test_obj_model.cad.obj");
        if (back == NULL) {
            bs_model_destroy(m);
            continue;
        }
        size_t bad = 0;
        for (size_t f = 0; f < m->nface && m->nface == back->nface; f++) {
            const bsi_face *x = &m->faces[f], *y = &back->faces[f];
            int tr = x->swap != x->reversed; /* written with u and v exchanged */
            bad += x->patch_count != y->patch_count || y->reversed != 0;
            for (size_t a = 0; a < x->au.n && x->patch_count == y->patch_count; a++)
                for (size_t b = 0; b < x->av.n; b++)
                    bad += !same_patch_tr(bs_surface_get(m->surface, x->first_patch + a * x->av.n + b),
                                          bs_surface_get(back->surface, y->first_patch +
                                                                            (tr ? b * x->au.n + a : a * x->av.n + b)),
                                          tr);
        }
        double area = 0, volume = 0, a0 = 0, v0 = 0, ra = ref_value(parts[k][0], "area"), rv = ref_value(parts[k][0], "volume");
        CHECK_STATUS(bs_model_properties(back, 1e-10, &area, &volume, NULL), BS_OK);
        CHECK_STATUS(bs_model_properties(m, 1e-10, &a0, &v0, NULL), BS_OK);
        int closed = bs_model_shell_count(back) == 1 && bs_model_shell_closed(back, 0) == 1;
        CHECKF(back->nface == m->nface && bad == 0 && bs_model_edge_count(back) == bs_model_edge_count(m) && closed &&
               fabs(area - a0) <= 1e-9 * a0 && fabs(volume - v0) <= 1e-9 * v0,
               "%s: %zu faces, %zu patches differ, area %.17g (%.17g), volume %.17g (%.17g)", parts[k][1],
               back->nface, bad, area, a0, volume, v0);
        printf("test_obj_model: %s: %zu faces, %zu edges, closed, same patches; area %.12g (before %.12g, "
               "OpenCASCADE %.12g), volume %.12g (%.12g, %.12g) after OBJ\n", parts[k][1], back->nface,
               bs_model_edge_count(back), area, a0, ra, volume, v0, rv);
        bs_model_destroy(back);
        bs_model_destroy(m);
    }
}

/* ---- refusals ---- */
typedef struct bad_text {
    const char *text;
    bs_status st;
    size_t line, column; /* column 0: not checked */
    const char *says;
} bad_text;

static const bad_text bad[] = {
    {"surf 0 1 0 1 1\n", BS_ERR_PARSE, 1, 1, "surf before any cstype"},
    {"cstype bezier\nsurf 0 1 0 1\n", BS_ERR_PARSE, 2, 1, "two degrees"},
    {"cstype taylor\ndeg 1 1\nsurf 0 1 0 1\n", BS_ERR_UNSUPPORTED, 3, 1, "taylor"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1\n", BS_ERR_PARSE, 3, 14, "vertex index beyond"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1 -1\n", BS_ERR_PARSE, 3, 14, "relative vertex index"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1 x\n", BS_ERR_PARSE, 3, 14, "expected a vertex index"},
    {"v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\n", BS_ERR_PARSE, 4, 1, "surface without end"},
    {"v 0 0 0\ncstype bezier\ndeg 1\ncurv2 1\nend\n", BS_ERR_PARSE, 4, 7, "parameter vertex index beyond"},
    {"vp 0\ncstype bezier\ndeg 1\ncurv2 1 1\nend\n", BS_ERR_PARSE, 4, 7, "needs u and v"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 1 1\ncurv2 1 2\nend\n", BS_ERR_PARSE, 5, 1, "one degree"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 0\ncurv2 1 2\nend\n", BS_ERR_PARSE, 5, 1, "1 or more"},
    {"cstype bezier\ndeg 1\ncurv2\nend\n", BS_ERR_PARSE, 3, 1, "needs control points"},
    {"vp 0 0\nvp 1 0\ncstype bspline\ndeg 1\ncurv2 1 2\nend\n", BS_ERR_PARSE, 5, 1, "needs parm u"},
    {"vp 0 0\nvp 1 0\ncstype bspline\ndeg 1\ncurv2 1 2\nparm u 0 1\nend\n", BS_ERR_PARSE, 5, 1, "does not match"},
    {"vp 0 0\nvp 1 0\ncstype bspline\ndeg 1\ncurv2 1 2\nparm u 0 1 0.5 1\nend\n", BS_ERR_PARSE, 5, 1, "must not decrease"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2 1\nend\n", BS_ERR_PARSE, 5, 1, "does not match"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nparm u 0\nend\n", BS_ERR_PARSE, 5, 1, "at least two"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nparm u 1 0\nend\n", BS_ERR_PARSE, 5, 1, "must increase"},
    {"vp 0 0 0\ncstype rat bezier\ndeg 1\ncurv2 1 1\nend\n", BS_ERR_PARSE, 4, 7, "positive"},
    {"vp 1e300 0 1e10\nvp 0 0\ncstype rat bezier\ndeg 1\ncurv2 1 2\nend\n", BS_ERR_PARSE, 5, 1, "overflows"},
    {"vp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nparm v 0 1\nend\n", BS_ERR_PARSE, 6, 6, "no parameter v"},
    {"vp 0 0\ncstype bezier\ndeg 1\ncurv2 1 1\nsurf 0 1 0 1\n", BS_ERR_PARSE, 5, 1, "before the end of the previous"},
    {"vp 0 0\ncstype bezier\ndeg 1\ncurv2 1 1\n", BS_ERR_PARSE, 4, 1, "curve without end"},
    {"vp 0 0\ncstype bezier\ndeg 1\ncurv2 1 1\ndeg 2\n", BS_ERR_PARSE, 5, 1, "deg before the end"},
    {"trim 0 1 1\n", BS_ERR_PARSE, 1, 1, "trim outside a surface"},
    {"curv 0 1 1\nhole 0 1 1\nend\n", BS_ERR_PARSE, 2, 1, "hole outside a surface"},
    {"parm u 0 1\n", BS_ERR_PARSE, 1, 1, "parm outside"},
    {"end\n", BS_ERR_PARSE, 1, 1, "end without"},
    {"v 1 2\n", BS_ERR_PARSE, 1, 6, "x y z"},
    {"v 1 2 3 4 5 6 7\n", BS_ERR_PARSE, 1, 15, "too many values for a vertex"},
    {"vp\n", BS_ERR_PARSE, 1, 3, "u [v [w]]"},
    {"vp 1 2 3 4\n", BS_ERR_PARSE, 1, 10, "too many values for a parameter vertex"},
    {"v 1e999 0 0\n", BS_ERR_PARSE, 1, 3, "out of range"},
    {"v x 0 0\n", BS_ERR_PARSE, 1, 3, "finite decimal"},
    {"cstype\n", BS_ERR_PARSE, 1, 7, "expected a curve type"},
    {"cstype rat\n", BS_ERR_PARSE, 1, 11, "after rat"},
    {"cstype nurbs\n", BS_ERR_PARSE, 1, 8, "unknown curve type"},
    {"cstype bezier x\n", BS_ERR_PARSE, 1, 15, "after the cstype"},
    {"deg\n", BS_ERR_PARSE, 1, 4, "expected a degree"},
    {"deg 1 2 3\n", BS_ERR_PARSE, 1, 9, "more than two"},
    {"deg x\n", BS_ERR_PARSE, 1, 5, "non-negative"},
    {"deg 65\n", BS_ERR_PARSE, 1, 5, "at most 64"},
    {"1 2 3\n", BS_ERR_PARSE, 1, 1, "keyword"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 x\n", BS_ERR_PARSE, 3, 10, "expected t0"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0\n", BS_ERR_PARSE, 3, 11, "expected t1"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\nparm\n", BS_ERR_PARSE, 4, 5, "u or v"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\nparm u 0 1\nparm u 0 1\n", BS_ERR_PARSE, 5, 6, "second parm"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\nparm u 0 x\n", BS_ERR_PARSE, 4, 10, "parameter value"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\ncstype bspline\n", BS_ERR_PARSE, 4, 1, "cstype before the end"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\ncurv 0 1\n", BS_ERR_PARSE, 4, 1, "curve before the end"},
    {"v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0\nend\n", BS_ERR_PARSE, 5, 6, "two values"},
    {"v 0 0 0\ncstype bezier\ndeg 0 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 1 2\nend\n", BS_ERR_PARSE, 5, 6, "degree 0"},
    {"v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm v 1 0\nend\n", BS_ERR_PARSE, 5, 6, "must increase"},
    {"v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1\nend\n", BS_ERR_PARSE, 4, 1, "does not match"},
    {"v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1 1\nend\n", BS_ERR_PARSE, 4, 1, "does not match"},
    {"cstype bezier\ndeg 1 1\nsurf 0 1 0 1\nend\n", BS_ERR_PARSE, 3, 1, "fewer control"},
    {"v 0 0 0 0\ncstype rat bezier\ndeg 1 1\nsurf 0 1 0 1 1\n", BS_ERR_PARSE, 4, 14, "positive"},
    {"v 1e300 0 0 1e10\ncstype rat bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n", BS_ERR_PARSE, 4, 1, "overflows"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n", BS_ERR_PARSE, 4, 1, "needs parm u and parm v"},
    {"v 0 0 0\ncstype bspline\ndeg 0 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 4, 1, "1 or more"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 5, 6, "too few knots"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 4, 1, "does not match"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1 1\nparm v 0 1 0 1\nend\n", BS_ERR_PARSE, 6, 6, "knots decrease"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 1 1 0 0\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 5, 6, "knots decrease"},
    {"v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 2 3 0 1 1 1 1 1\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 4, 1, "range is empty"},
    {"v 1e300 0 0 1e10\ncstype rat bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 4, 1, "overflows"},
    {"v 1e300 0 0 1e10\ncstype rat bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1 1 1\nparm u 0 0 0.5 1 1\nparm v 0 0 1 1\nend\n", BS_ERR_PARSE, 4, 1, "overflows"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 0 1 2\n", BS_ERR_PARSE, 10, 10, "curv2 index beyond"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 0 1\n", BS_ERR_PARSE, 10, 9, "expected a curv2 index"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 0\n", BS_ERR_PARSE, 10, 7, "expected u1"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nhole\n", BS_ERR_PARSE, 10, 5, "expected u0 u1"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim x\n", BS_ERR_PARSE, 10, 6, "u0"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 1 1 1\n", BS_ERR_PARSE, 10, 10, "is empty"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 0 2 1\n", BS_ERR_PARSE, 10, 10, "leaves the curve"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\ntrim 0 1 1\n", BS_ERR_PARSE, 10, 1, "loop not closed"},
    {"v 0 0 0\nvp 0 0\nvp 1 0\nvp 0 1\ncstype bezier\ndeg 1\ncurv2 1 2 3 1\nparm u 0 1 2 3\nend\ndeg 1 1\n"
     "surf 0 1 0 1 1 1 1 1\ntrim 0 3 1\ntrim 3 0 1\nend\n", BS_ERR_UNSUPPORTED, 13, 1, "second trim loop"},
    {"cstype bmatrix\ndeg 1\ncurv2 1\n", BS_ERR_UNSUPPORTED, 3, 1, "bmatrix"},
    {"v 0 0 0\nv 1 0 0\nf 1 2 1\nf 1 2 2\nl 1 2\np 1\ncurv 0 1 1 2\nend\n", BS_ERR_PARSE, 9, 1,
     "no free-form surface: 2 polygon faces, 1 line, 1 point, 1 3-D curve"},
    {"# nothing\nv 0 0 0\n", BS_ERR_PARSE, 3, 1, "no free-form surface: 1 vertices and no surf"},
    {"", BS_ERR_PARSE, 1, 1, "no surf statement"},
    {"v 0 0 0\nv 1 \\\n 2 x\n", BS_ERR_PARSE, 3, 4, "finite decimal"},
};

static void test_refusals(void)
{
    size_t n = sizeof bad / sizeof bad[0], wrong = 0;
    for (size_t k = 0; k < n; k++) {
        bs_parse_error err = {0, 0, ""};
        bs_model *m = (bs_model *)&err;
        bs_status st = bs_model_read_obj(bad[k].text, strlen(bad[k].text), &err, &m);
        int ok = st == bad[k].st && m == NULL && err.line == bad[k].line &&
                 (bad[k].column == 0 || err.column == bad[k].column) && strstr(err.message, bad[k].says) != NULL;
        wrong += !ok;
        CHECKF(ok, "case %zu: status %d at %zu:%zu \"%s\"", k, st, err.line, err.column, err.message);
        bs_model_destroy(st == BS_OK ? m : NULL);
    }
    printf("test_obj_model: %zu refusals, each with its position (%zu wrong)\n", n, wrong);
    /* a NUL byte, the argument rules, a missing file, the size limit */
    bs_parse_error err = {0, 0, ""};
    bs_model *m = (bs_model *)&err;
    static const char nul[] = "v 0 0 0\nv 1\0 0 0\n";
    CHECK_STATUS(bs_model_read_obj(nul, sizeof nul - 1, &err, &m), BS_ERR_PARSE);
    CHECK(m == NULL && err.line == 2 && err.column == 4 && strstr(err.message, "NUL") != NULL);
    CHECK_STATUS(bs_model_read_obj(NULL, 1, &err, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_obj("", 0, &err, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_obj(nul, BSI_FILE_MAX + 1, &err, &m), BS_ERR_SIZE);
    CHECK_STATUS(bs_model_read_obj_file(NULL, &err, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_obj_file(DATA "plate_hole.obj", &err, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_model_read_obj_file(DATA "missing.obj", &err, &m), BS_ERR_IO);
    CHECK_STATUS(bs_model_read_obj_file(DATA "polygons.obj", &err, &m), BS_ERR_PARSE);
    CHECK(m == NULL && strstr(err.message, "no free-form surface: 2 polygon faces, 1 line") != NULL);
}

/* A curve of many segments referenced by many trims: the geometry cap, not the memory, stops it. */
static void test_cap(void)
{
    size_t npt = 20000, ntrim = 200;
    size_t cap = 64 * npt + 32 * ntrim + 256, len = 0;
    char *text = malloc(cap);
    len += (size_t)snprintf(text + len, cap - len, "v 0 0 0\n");
    for (size_t k = 0; k < npt; k++)
        len += (size_t)snprintf(text + len, cap - len, "vp %zu 0\n", k);
    len += (size_t)snprintf(text + len, cap - len, "cstype bspline\ndeg 1\ncurv2");
    for (size_t k = 0; k < npt; k++)
        len += (size_t)snprintf(text + len, cap - len, " %zu", k + 1);
    len += (size_t)snprintf(text + len, cap - len, "\nparm u 0");
    for (size_t k = 0; k < npt; k++)
        len += (size_t)snprintf(text + len, cap - len, " %zu", k);
    len += (size_t)snprintf(text + len, cap - len, " %zu\nend\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1 1\n"
                            "parm v 0 0 1 1\ntrim", npt - 1);
    for (size_t k = 0; k < ntrim; k++)
        len += (size_t)snprintf(text + len, cap - len, " 0 %zu 1", npt - 1);
    len += (size_t)snprintf(text + len, cap - len, "\nend\n");
    bs_parse_error err = {0, 0, ""};
    bs_model *m = NULL;
    CHECK_STATUS(bs_model_read_obj(text, len, &err, &m), BS_ERR_SIZE);
    CHECKF(m == NULL && strstr(err.message, "control points") != NULL && err.line > 1, "%zu:%zu %s", err.line,
           err.column, err.message);
    free(text);
}

#ifdef BS_WRAP_MALLOC
/* Every allocation of reading and writing fails in turn: NO_MEMORY, no model, nothing written. */
static void test_no_memory(void)
{
    const char *files[2] = {DATA "plate_hole.obj", DATA "bezier_strip.obj"};
    int failures = 0;
    for (int f = 0; f < 2; f++) {
        size_t len;
        char *text = slurp(files[f], &len);
        bs_model *ref = NULL;
        CHECK_STATUS(bs_model_read_obj(text, len, NULL, &ref), BS_OK);
        int done = 0;
        for (size_t n = 1; !done && n < 5000; n++) {
            bs_model *m = NULL;
            fail_in = n;
            bs_status st = bs_model_read_obj(text, len, NULL, &m);
            fail_in = 0;
            CHECK(st == BS_OK || (st == BS_ERR_NO_MEMORY && m == NULL));
            failures += st == BS_ERR_NO_MEMORY;
            done = st == BS_OK;
            bs_model_destroy(m);
        }
        CHECK(done);
        done = 0;
        for (size_t n = 1; !done && n < 100; n++) {
            fail_in = n;
            bs_status st = bs_model_write_obj_file(ref, "test_obj_model.nomem.obj");
            fail_in = 0;
            CHECK(st == BS_OK || st == BS_ERR_NO_MEMORY);
            failures += st == BS_ERR_NO_MEMORY;
            done = st == BS_OK;
        }
        CHECK(done);
        (void)remove("test_obj_model.nomem.obj");
        bs_model_destroy(ref);
        free(text);
    }
    printf("test_obj_model: %d allocation failures reported as BS_ERR_NO_MEMORY\n", failures);
}
#endif

int main(void)
{
    test_plate();
    test_strip();
    test_models_of_surfaces();
    test_quirks();
    test_cad();
    test_refusals();
    test_cap();
#ifdef BS_WRAP_MALLOC
    test_no_memory();
#endif
    return bs_test_exit("test_obj_model");
}
