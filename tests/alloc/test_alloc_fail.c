/* Allocation-failure injection. The library's sources are linked into this program with malloc,
 * calloc, realloc and free wrapped (-Wl,--wrap=...): for every operation and every k, the k-th
 * allocation of the call fails. The call must then return BS_ERR_NO_MEMORY, leave its outputs
 * untouched (sentinel-filled buffers; new-handle outputs NULL) and hold no memory afterwards
 * (the wrappers count live blocks). k runs up from 1 until the call makes fewer than k
 * allocations, so every allocation of every operation fails once. */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t k, size_t n);
void *__real_realloc(void *p, size_t n);
void __real_free(void *p);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t k, size_t n);
void *__wrap_realloc(void *p, size_t n);
void __wrap_free(void *p);

static size_t fail_at; /* 0: never fail; else the index (from 1) of the allocation that fails */
static size_t n_alloc; /* allocations attempted since the counter was reset */
static int hit;        /* the injected failure happened */
static long live;      /* blocks allocated and not yet freed */

static int should_fail(void)
{
    n_alloc++;
    if (fail_at != 0 && n_alloc == fail_at) {
        hit = 1;
        return 1;
    }
    return 0;
}

void *__wrap_malloc(size_t n)
{
    if (should_fail())
        return NULL;
    void *p = __real_malloc(n);
    live += p != NULL;
    return p;
}

void *__wrap_calloc(size_t k, size_t n)
{
    if (should_fail())
        return NULL;
    void *p = __real_calloc(k, n);
    live += p != NULL;
    return p;
}

void *__wrap_realloc(void *p, size_t n)
{
    if (should_fail())
        return NULL;
    void *q = __real_realloc(p, n);
    if (p == NULL && q != NULL)
        live++;
    return q;
}

void __wrap_free(void *p)
{
    live -= p != NULL;
    __real_free(p);
}

/* ---- fixtures, made before injection starts ---- */
static bs_patch *P, *R, *HIGH;
static bs_surface *TEAPOT;
static char *teapot_text;
static size_t teapot_len;
static const double net3[27] = {0, 0, 0, 1, 0, 1, 2, 0, 0, 0, 1, 1, 1, 1, 2, 2, 1, 1, 0, 2, 0, 1, 2, 1, 2, 2, 0};
static const double w9[9] = {1, 2, 1, 0.5, 1, 3, 1, 1, 2};

#define SENT -999.0
enum { NPT = 300 };
static double obuf[3][NPT], ubuf[NPT], vbuf[NPT];
static unsigned char kbuf[NPT];
static char tbuf[8192];

static void fill_outputs(void)
{
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < NPT; k++)
            obuf[c][k] = SENT;
    memset(kbuf, 0xEE, sizeof kbuf);
    memset(tbuf, 'Q', sizeof tbuf);
}

static int outputs_untouched(void)
{
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < NPT; k++)
            if (obuf[c][k] != SENT)
                return 0;
    for (size_t k = 0; k < sizeof kbuf; k++)
        if (kbuf[k] != 0xEE)
            return 0;
    for (size_t k = 0; k < sizeof tbuf; k++)
        if (tbuf[k] != 'Q')
            return 0;
    return 1;
}

static bs_patch *const HSENT = (bs_patch *)(void *)&live;

/* Each operation: run the call, return its status; on failure, check its handles are NULL. */
typedef bs_status (*op_fn)(void);

/* After a call that makes n handles: on failure they must all be NULL, on success destroy them. */
static bs_status settle_handles(const char *what, bs_status st, bs_patch **h, int n)
{
    for (int k = 0; k < n; k++) {
        if (st != BS_OK)
            CHECKF(h[k] == NULL, "%s: handle %d not NULL", what, k);
        else
            bs_patch_destroy(h[k]);
    }
    return st;
}

#define ONE_HANDLE(name, call)                                  \
    static bs_status name(void)                                 \
    {                                                           \
        bs_patch *q = HSENT;                                    \
        bs_status st = (call);                                  \
        if (st != BS_OK)                                        \
            CHECKF(q == NULL, "%s: handle not NULL", #name);    \
        bs_patch_destroy(st == BS_OK ? q : NULL);               \
        return st;                                              \
    }

ONE_HANDLE(op_create, bs_patch_create(2, 2, 3, net3, NULL, &q))
ONE_HANDLE(op_create_rational, bs_patch_create(2, 2, 3, net3, w9, &q))
ONE_HANDLE(op_clone, bs_patch_clone(R, &q))
ONE_HANDLE(op_subpatch, bs_patch_subpatch(R, 0.25, 0.75, 0.5, 0.0, &q))
ONE_HANDLE(op_elevate, bs_patch_elevate(R, 2, 1, &q))
ONE_HANDLE(op_derivative, bs_patch_derivative(P, 1, 2, &q))
ONE_HANDLE(op_transform, bs_patch_transform(R, (const double[12]){0, 1, 0, 1, 1, 0, 0, 2, 0, 0, 2, 3}, &q))
ONE_HANDLE(op_swap, bs_patch_swap_uv(R, &q))
ONE_HANDLE(op_reverse, bs_patch_reverse(P, BS_DIR_V, &q))

static const double c0[9] = {0, 0, 0, 1, 0, 1, 2, 0, 0}, c1[6] = {0, 1, 0, 2, 1, 0};
static const double s0[6] = {0, 0, 0, 0, 1, 0}, s1[6] = {2, 0, 0, 2, 1, 0};
ONE_HANDLE(op_ruled, bs_patch_ruled(&(bs_curve){2, 3, c0, NULL}, &(bs_curve){1, 3, c1, (const double[2]){1, 2}}, &q))
ONE_HANDLE(op_coons, bs_patch_coons(&(bs_curve){2, 3, c0, NULL}, &(bs_curve){1, 3, c1, NULL},
                                    &(bs_curve){1, 3, s0, NULL}, &(bs_curve){1, 3, s1, NULL}, &q))

static bs_status op_split(void)
{
    bs_patch *h[2] = {HSENT, HSENT};
    return settle_handles("split", bs_patch_split(R, BS_DIR_U, 0.3, &h[0], &h[1]), h, 2);
}

static bs_status op_split4(void)
{
    bs_patch *h[4] = {HSENT, HSENT, HSENT, HSENT};
    return settle_handles("split4", bs_patch_split4(R, 0.3, 0.6, h), h, 4);
}

static bs_status op_eval_deriv_rational(void)
{
    bs_view o[3] = {{obuf[0], NPT, 0}, {obuf[1], NPT, 0}, {obuf[2], NPT, 0}};
    bs_cview u = {ubuf, NPT, 0}, v = {vbuf, NPT, 0};
    return bs_patch_eval_deriv(R, 2, 3, NPT, &u, &v, o);
}

static bs_status op_eval_grid(void)
{
    bs_view o[3] = {{obuf[0], NPT, 0}, {obuf[1], NPT, 0}, {obuf[2], NPT, 0}};
    bs_cview u = {ubuf, 15, 0}, v = {vbuf, 20, 0};
    return bs_patch_eval_grid(HIGH, 15, &u, 20, &v, NULL, NULL, NULL, o, kbuf);
}

static bs_status op_closest(void)
{
    bs_view o[3] = {{obuf[0], NPT, 0}, {obuf[1], NPT, 0}, {obuf[2], NPT, 0}};
    bs_cview q[3] = {{ubuf, 10, 0}, {vbuf, 10, 0}, {ubuf + 5, 10, 0}};
    return bs_patch_closest_point(HIGH, 10, q, NULL, NULL, o);
}

static bs_status op_surface_eval(void)
{
    bs_view o[3] = {{obuf[0], NPT, 0}, {obuf[1], NPT, 0}, {obuf[2], NPT, 0}};
    bs_cview u = {ubuf, NPT, 0}, v = {vbuf, NPT, 0};
    uint32_t ids[NPT];
    for (uint32_t k = 0; k < NPT; k++)
        ids[k] = k % 32;
    return bs_surface_eval_normal(TEAPOT, NPT, ids, &u, &v, o, NULL, kbuf);
}

static bs_status op_surface_build(void)
{
    bs_surface *s = (bs_surface *)(void *)HSENT, *c = (bs_surface *)(void *)HSENT;
    bs_status st = bs_surface_create(&s);
    if (st != BS_OK) {
        CHECK(s == NULL);
        return st;
    }
    for (int k = 0; k < 40 && st == BS_OK; k++) {
        size_t idx = 12345;
        st = bs_surface_add(s, k % 2 ? P : R, &idx);
        if (st != BS_OK)
            CHECKF(idx == 12345 && bs_surface_count(s) == (size_t)k, "add: surface changed on failure");
    }
    if (st == BS_OK) {
        st = bs_surface_clone(s, &c);
        if (st != BS_OK)
            CHECK(c == NULL);
        else
            bs_surface_destroy(c);
    }
    bs_surface_destroy(s);
    return st;
}

static bs_status op_read_bpt(void)
{
    bs_surface *s = (bs_surface *)(void *)HSENT;
    bs_parse_error err;
    memset(&err, 0x33, sizeof err);
    bs_status st = bs_surface_read_bpt(teapot_text, teapot_len, &err, &s);
    if (st != BS_OK)
        CHECK(s == NULL && err.line == 0x3333333333333333ull);
    bs_surface_destroy(s == (bs_surface *)(void *)HSENT ? NULL : s);
    return st;
}

static bs_status op_builtin(void)
{
    bs_surface *s = (bs_surface *)(void *)HSENT;
    bs_status st = bs_surface_create_builtin("teacup", &s);
    if (st != BS_OK)
        CHECK(s == NULL);
    bs_surface_destroy(s == (bs_surface *)(void *)HSENT ? NULL : s);
    return st;
}

static bs_status op_write_bpt(void)
{
    size_t size = 777;
    bs_status st = bs_surface_write_bpt(TEAPOT, tbuf, sizeof tbuf, &size);
    if (st != BS_OK)
        CHECK(size == 777);
    return st;
}

static const char *tmp_path;
static bs_status op_write_bpt_file(void) { return bs_surface_write_bpt_file(TEAPOT, tmp_path); }

/* A rational B-spline and a two-segment Bezier surface: both conversions of the OBJ reader. */
static const char obj_text[] = "v 0 0 0\nv 1 0 0 2\nv 0 1 0\nv 1 1 0\nv 2 0 1\nv 2 1 1\n"
                               "cstype rat bspline\ndeg 1 1\nsurf 0 2 0 1 1 2 5 3 4 6\n"
                               "parm u 0 0 1 2 2\nparm v 0 0 1 1\nend\n"
                               "cstype bezier\ndeg 1 1\nsurf 0 2 0 1 1 2 5 \\\n 3 4 6\nparm u 0 1 2\nend\n";

static bs_status op_read_obj(void)
{
    bs_surface *s = (bs_surface *)(void *)HSENT;
    bs_status st = bs_surface_read_obj(obj_text, sizeof obj_text - 1, NULL, &s);
    if (st != BS_OK)
        CHECK(s == NULL);
    else
        CHECK(bs_surface_count(s) == 4);
    bs_surface_destroy(s == (bs_surface *)(void *)HSENT ? NULL : s);
    return st;
}

static bs_status op_write_obj_file(void) { return bs_surface_write_obj_file(TEAPOT, tmp_path); }

/* An IGES file whose reading makes `patches` patches. */
static bs_status read_iges(const char *path, size_t patches)
{
    bs_surface *s = (bs_surface *)(void *)HSENT;
    bs_status st = bs_surface_read_iges_file(path, NULL, &s);
    if (st != BS_OK)
        CHECK(s == NULL);
    else
        CHECK(bs_surface_count(s) == patches);
    bs_surface_destroy(s == (bs_surface *)(void *)HSENT ? NULL : s);
    return st;
}

/* An OpenCASCADE file of a B-spline over a sub-range of its knots: spans cut by sub-patches. */
static bs_status op_read_iges_file(void) { return read_iges(BS_IGES_FIXTURE, 6); }

/* One whose 128 points at a 124: the cache of parsed 124s allocates too. */
static bs_status op_read_iges_124(void) { return read_iges(BS_IGES_124_FIXTURE, 1); }

static bs_status op_continuity(void)
{
    bs_edge_continuity e[64];
    bs_open_edge o[64];
    size_t ne = 5, no = 5;
    memset(e, 0x44, sizeof e);
    bs_status st = bs_surface_continuity(TEAPOT, 1e-6, 8, e, 64, &ne, o, 64, &no);
    if (st != BS_OK)
        CHECK(ne == 5 && no == 5 && e[0].patch_a == 0x44444444u);
    return st;
}

static bs_status op_tessellate(void)
{
    bs_mesh *m = (bs_mesh *)(void *)HSENT;
    bs_status st = bs_surface_tessellate_uniform(TEAPOT, 3, 2, BS_TESS_STRIPS, &m);
    if (st != BS_OK) {
        CHECK(m == NULL);
        return st;
    }
    size_t size = 0;
    static char buf[1 << 17];
    for (int f = BS_MESH_OBJ; f <= BS_MESH_STL && st == BS_OK; f++)
        st = bs_mesh_write_memory(m, f, buf, sizeof buf, &size);
    bs_mesh_destroy(m);
    return st;
}

static bs_status op_tessellate_adaptive(void)
{
    bs_mesh *m = (bs_mesh *)(void *)HSENT;
    bs_status st = bs_surface_tessellate_adaptive(TEAPOT, 0.05, 0, &m);
    if (st != BS_OK)
        CHECK(m == NULL);
    else
        bs_mesh_destroy(m);
    return st;
}

static bs_status op_tessellate_subdivide(void)
{
    bs_mesh *m = (bs_mesh *)(void *)HSENT;
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = 0.05;
    o.flags = BS_TESS_STRIPS | BS_TESS_REVERSE; /* the reversal allocates too */
    size_t nt = 7;
    bs_status st = bs_surface_tessellate_count(TEAPOT, &o, NULL, &nt);
    if (st != BS_OK) {
        CHECK(nt == 7);
        return st;
    }
    st = bs_surface_tessellate(TEAPOT, &o, &m);
    if (st != BS_OK)
        CHECK(m == NULL);
    else
        bs_mesh_destroy(m);
    return st;
}

/* A NURBS of 2 x 3 spans added to a surface that already holds 9 patches (so that its array
 * grows): on failure the surface, the spans and the count are as they were. */
static bs_status op_add_bspline(void)
{
    static const double ku[] = {0, 0, 0, 1, 2, 2, 2}, kv[] = {0, 0, 1, 2, 3, 3};
    double ctrl[4 * 4 * 3], w[16], spans[24];
    for (int k = 0; k < 48; k++)
        ctrl[k] = (double)(k % 7);
    for (int k = 0; k < 16; k++)
        w[k] = 1.0 + 0.125 * k;
    bs_bspline b = {2, 1, 4, 4, 3, ku, kv, ctrl, w};
    bs_surface *s = NULL;
    bs_status st = bs_surface_create(&s);
    for (int k = 0; k < 9 && st == BS_OK; k++)
        st = bs_surface_add(s, P, NULL);
    if (st != BS_OK) {
        bs_surface_destroy(s);
        return st;
    }
    for (int k = 0; k < 24; k++)
        spans[k] = SENT;
    size_t count = 777;
    st = bs_surface_add_bspline(s, &b, spans, 24, &count);
    if (st != BS_OK) {
        int untouched = count == 777 && bs_surface_count(s) == 9;
        for (int k = 0; k < 24; k++)
            untouched &= spans[k] == SENT;
        CHECKF(untouched, "bs_surface_add_bspline: outputs or surface changed on failure");
    } else {
        CHECK(count == 6 && bs_surface_count(s) == 15);
    }
    bs_surface_destroy(s);
    return st;
}

/* The locator: made from the teapot, then rays and closest points through one made beforehand
 * (LOC), their outputs in the shared buffers. */
static bs_locator *LOC;
static bs_status locator_create(const bs_surface *s)
{
    bs_locator *L = (bs_locator *)(void *)HSENT;
    bs_status st = bs_locator_create(s, &L);
    if (st != BS_OK)
        CHECK(L == NULL);
    else
        bs_locator_destroy(L);
    return st;
}

static bs_status op_locator_create(void)
{
    return locator_create(TEAPOT);
}

/* A locator of patches below 2^-1000 and beyond 2^1000 keeps their scaled copies. */
static bs_surface *EXTREME;
static bs_status op_locator_create_extreme(void)
{
    return locator_create(EXTREME);
}

static const double ray_o[3][4] = {{5, -5, 0.5, 9}, {0, 0.5, 0.2, 9}, {1, 1.5, 9, 9}};
static const double ray_d[3][4] = {{-1, 1, 0.1, -1}, {0, 0, 0.1, -1}, {0, 0, -1, -1}};

static bs_status op_locator_intersect(void)
{
    bs_cview o[3], d[3];
    for (int c = 0; c < 3; c++) {
        o[c] = (bs_cview){ray_o[c], 4, 0};
        d[c] = (bs_cview){ray_d[c], 4, 0};
    }
    bs_view uv[2] = {{obuf[1], 4, 0}, {obuf[2], 4, 0}}, t = {obuf[0], 4, 0};
    return bs_locator_intersect(LOC, 4, o, d, NULL, NULL, uv, &t, NULL);
}

static bs_status op_locator_closest(void)
{
    bs_cview q[3];
    for (int c = 0; c < 3; c++)
        q[c] = (bs_cview){ray_o[c], 4, 0};
    bs_view uv[2] = {{obuf[1], 4, 0}, {obuf[2], 4, 0}}, dist = {obuf[0], 4, 0};
    return bs_locator_closest_point(LOC, 4, q, NULL, uv, &dist, NULL);
}

/* Models: the teapot's model (faces, trims, edges, shells), and the CAD readers on small parts. */
static bs_status op_model_from_surface(void)
{
    bs_model *m = (bs_model *)(void *)HSENT;
    bs_status st = bs_model_from_surface(TEAPOT, &m);
    if (st != BS_OK)
        CHECK(m == NULL);
    else
        CHECK(bs_model_face_count(m) == 32);
    bs_model_destroy(m == (bs_model *)(void *)HSENT ? NULL : m);
    return st;
}

/* Rays on a CAD part's trimmed faces (the duct: trims of degree 6 to 14). The trims' nearness
 * test allocates room for its pieces and does without it, so a failure there must leave the
 * answer as it is; any other failure is BS_ERR_NO_MEMORY as everywhere. */
enum { MODEL_RAYS = 100 };
static bs_model *DUCT;
static bs_locator *DUCT_LOC;
static double model_o[3][MODEL_RAYS], model_d[3][MODEL_RAYS];

static void load_duct(void)
{
    CHECK_STATUS(bs_model_read_step_file(BS_CAD_FIXTURE ".step", NULL, &DUCT), BS_OK);
    CHECK_STATUS(bs_locator_create_model(DUCT, &DUCT_LOC), BS_OK);
    FILE *f = fopen(BS_CAD_FIXTURE ".ref", "r");
    CHECK(f != NULL);
    char line[512];
    size_t n = 0;
    while (f != NULL && n < MODEL_RAYS && fgets(line, sizeof line, f))
        n += sscanf(line, "ray %lf %lf %lf %lf %lf %lf", &model_o[0][n], &model_o[1][n], &model_o[2][n],
                    &model_d[0][n], &model_d[1][n], &model_d[2][n]) == 6;
    if (f != NULL)
        fclose(f);
    CHECK(n == MODEL_RAYS);
}

static bs_status op_model_intersect(void)
{
    bs_cview o[3], d[3];
    for (int c = 0; c < 3; c++) {
        o[c] = (bs_cview){model_o[c], MODEL_RAYS, sizeof(double)};
        d[c] = (bs_cview){model_d[c], MODEL_RAYS, sizeof(double)};
    }
    bs_view uv[2] = {{obuf[1], MODEL_RAYS, sizeof(double)}, {obuf[2], MODEL_RAYS, sizeof(double)}};
    bs_view t = {obuf[0], MODEL_RAYS, sizeof(double)};
    return bs_locator_intersect(DUCT_LOC, MODEL_RAYS, o, d, NULL, NULL, uv, &t, NULL);
}

/* Points of a grid over each of the duct's faces classified with a tolerance that puts many ON:
 * the nearness test decides them (its allocation, as for the rays, may be refused). */
enum { CLASSIFY_SIDE = 6, CLASSIFY_MAX = NPT };
static uint32_t cls_face[CLASSIFY_MAX];
static double cls_u[CLASSIFY_MAX], cls_v[CLASSIFY_MAX];
static size_t cls_n;

static void grid_duct_faces(void)
{
    for (size_t f = 0; f < bs_model_face_count(DUCT); f++) {
        bs_face_info info;
        memset(&info, 0, sizeof info);
        info.size = sizeof info;
        CHECK_STATUS(bs_model_face_info(DUCT, f, &info), BS_OK);
        for (int i = 0; i < CLASSIFY_SIDE; i++)
            for (int j = 0; j < CLASSIFY_SIDE && cls_n < CLASSIFY_MAX; j++, cls_n++) {
                cls_face[cls_n] = (uint32_t)f;
                cls_u[cls_n] = info.u0 + (info.u1 - info.u0) * (i + 0.5) / CLASSIFY_SIDE;
                cls_v[cls_n] = info.v0 + (info.v1 - info.v0) * (j + 0.5) / CLASSIFY_SIDE;
            }
    }
}

static bs_status op_model_classify(void)
{
    bs_cview u = {cls_u, cls_n, sizeof(double)}, v = {cls_v, cls_n, sizeof(double)};
    return bs_model_classify(DUCT, cls_n, cls_face, &u, &v, 0.3, kbuf);
}

typedef struct op {
    const char *name;
    op_fn fn;
    int writes_views; /* check the shared output buffers */
    int may_do_without; /* a failed allocation may also end in BS_OK with the answer unchanged */
} op;

static const op ops[] = {
    {"bs_patch_create", op_create, 0, 0},
    {"bs_patch_create (rational)", op_create_rational, 0, 0},
    {"bs_patch_clone", op_clone, 0, 0},
    {"bs_patch_split", op_split, 0, 0},
    {"bs_patch_split4", op_split4, 0, 0},
    {"bs_patch_subpatch", op_subpatch, 0, 0},
    {"bs_patch_elevate", op_elevate, 0, 0},
    {"bs_patch_derivative", op_derivative, 0, 0},
    {"bs_patch_transform", op_transform, 0, 0},
    {"bs_patch_swap_uv", op_swap, 0, 0},
    {"bs_patch_reverse", op_reverse, 0, 0},
    {"bs_patch_ruled", op_ruled, 0, 0},
    {"bs_patch_coons", op_coons, 0, 0},
    {"bs_patch_eval_deriv (rational)", op_eval_deriv_rational, 1, 0},
    {"bs_patch_eval_grid", op_eval_grid, 1, 0},
    {"bs_surface_eval_normal", op_surface_eval, 1, 0},
    {"bs_patch_closest_point", op_closest, 1, 0},
    {"bs_surface_create/add/clone", op_surface_build, 0, 0},
    {"bs_surface_read_bpt", op_read_bpt, 0, 0},
    {"bs_surface_create_builtin", op_builtin, 0, 0},
    {"bs_surface_write_bpt", op_write_bpt, 1, 0},
    {"bs_surface_write_bpt_file", op_write_bpt_file, 0, 0},
    {"bs_surface_add_bspline", op_add_bspline, 0, 0},
    {"bs_surface_read_obj", op_read_obj, 0, 0},
    {"bs_surface_write_obj_file", op_write_obj_file, 0, 0},
    {"bs_surface_read_iges_file", op_read_iges_file, 0, 0},
    {"bs_surface_read_iges_file (124)", op_read_iges_124, 0, 0},
    {"bs_surface_continuity", op_continuity, 0, 0},
    {"bs_surface_tessellate_uniform+write", op_tessellate, 0, 0},
    {"bs_surface_tessellate_adaptive", op_tessellate_adaptive, 0, 0},
    {"bs_surface_tessellate (subdivide, count)", op_tessellate_subdivide, 0, 0},
    {"bs_locator_create", op_locator_create, 0, 0},
    {"bs_locator_create (extreme scales)", op_locator_create_extreme, 0, 0},
    {"bs_locator_intersect", op_locator_intersect, 1, 0},
    {"bs_locator_closest_point", op_locator_closest, 1, 0},
    {"bs_model_from_surface", op_model_from_surface, 0, 0},
    {"bs_locator_intersect (model)", op_model_intersect, 1, 1},
    {"bs_model_classify (near trims)", op_model_classify, 1, 1},
};

int main(void)
{
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &P), BS_OK);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, w9, &R), BS_OK);
    CHECK_STATUS(bs_patch_elevate(R, 10, 12, &HIGH), BS_OK);
    CHECK_STATUS(bs_surface_create_builtin("teapot", &TEAPOT), BS_OK);
    CHECK_STATUS(bs_locator_create(TEAPOT, &LOC), BS_OK);
    CHECK_STATUS(bs_surface_create(&EXTREME), BS_OK);
    for (int e = 0; e < 3; e++) { /* 1, 2^-1060, 2^1015 */
        double sc[27];
        bs_patch *q = NULL;
        for (int k = 0; k < 27; k++)
            sc[k] = ldexp(net3[k], e == 0 ? 0 : e == 1 ? -1060 : 1015);
        CHECK_STATUS(bs_patch_create(2, 2, 3, sc, NULL, &q), BS_OK);
        CHECK_STATUS(bs_surface_add(EXTREME, q, NULL), BS_OK);
        bs_patch_destroy(q);
    }
    CHECK_STATUS(bs_surface_write_bpt(TEAPOT, NULL, 0, &teapot_len), BS_OK);
    teapot_text = malloc(teapot_len);
    CHECK_STATUS(bs_surface_write_bpt(TEAPOT, teapot_text, teapot_len, &teapot_len), BS_OK);
    teapot_len--; /* without the NUL */
    tmp_path = getenv("BS_ALLOC_TMP") ? getenv("BS_ALLOC_TMP") : "alloc_fail_out.bpt";
    for (int k = 0; k < NPT; k++) {
        ubuf[k] = (k % 17) / 16.0;
        vbuf[k] = (k % 23) / 22.0;
    }
    load_duct();
    grid_duct_faces();
    size_t total_failures = 0, done_without = 0;
    static double answer[3][NPT]; /* an op's outputs without failures (ops that may do without) */
    static unsigned char answer_k[NPT];
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        if (ops[i].may_do_without) {
            fill_outputs();
            CHECK_STATUS(ops[i].fn(), BS_OK);
            memcpy(answer, obuf, sizeof answer);
            memcpy(answer_k, kbuf, sizeof answer_k);
        }
        size_t k;
        for (k = 1;; k++) {
            fill_outputs();
            long live0 = live;
            n_alloc = 0;
            hit = 0;
            fail_at = k;
            bs_status st = ops[i].fn();
            fail_at = 0;
            CHECKF(live == live0, "%s, allocation %zu fails: %ld blocks leaked", ops[i].name, k, live - live0);
            if (!hit) {
                CHECKF(st == BS_OK, "%s without failures: status %d", ops[i].name, st);
                break;
            }
            if (ops[i].may_do_without && st == BS_OK) {
                CHECKF(memcmp(obuf, answer, sizeof answer) == 0 && memcmp(kbuf, answer_k, sizeof answer_k) == 0,
                       "%s, allocation %zu fails: answer changed",
                       ops[i].name, k);
                done_without++;
                continue;
            }
            CHECKF(st == BS_ERR_NO_MEMORY, "%s, allocation %zu fails: status %d", ops[i].name, k, st);
            if (ops[i].writes_views)
                CHECKF(outputs_untouched(), "%s, allocation %zu fails: outputs written", ops[i].name, k);
            total_failures++;
        }
        printf("%-34s %3zu allocations, each failed once\n", ops[i].name, k - 1);
    }
    printf("allocation failures injected: %zu; done without the memory: %zu\n", total_failures, done_without);
    CHECK(done_without > 0); /* the model ops did reach the nearness test's allocation */
    remove(tmp_path);
    free(teapot_text);
    bs_locator_destroy(LOC);
    bs_locator_destroy(DUCT_LOC);
    bs_model_destroy(DUCT);
    bs_surface_destroy(TEAPOT);
    bs_surface_destroy(EXTREME);
    bs_patch_destroy(P);
    bs_patch_destroy(R);
    bs_patch_destroy(HIGH);
    CHECKF(live == 0, "%ld blocks live at exit", live);
    return bs_test_exit("test_alloc_fail");
}
