/* The bad-input matrix: every public function against every class of bad input that applies to it
 * (NULL handle, NULL views, short counts, n x stride overflow, misaligned data or strides, degrees
 * and dimensions out of range, NaN/Inf control points, weights and parameters, zero-length
 * intervals, truncated and hostile .bpt, OBJ and IGES text). Each case checks the documented status, that every
 * caller buffer (sentinel-filled) is untouched on failure, and that new-handle outputs are NULL.
 * The program prints the size of the matrix it ran. */
#include "harness.h"

#include <bezsurf.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SENT -7777.0
#define KSENT 0xC3
enum { N = 4, SLACK = 2 };

static double obuf[4][BS_MAX_DIM][N + 2 * SLACK]; /* [output][coord][element], slack both ends */
static unsigned char kbuf[N + 2 * SLACK];
static bs_view ov[4][BS_MAX_DIM];
static double cbuf[64 * 8 + 2], wbuf[64 + 2]; /* flat outputs (get_ctrl, isocurve, bounds) */
static char tbuf[256];                        /* text output */
static bs_patch *const HSENT = (bs_patch *)(void *)&bs_test_checks;
static bs_patch *h[4];
static bs_surface *hs;
static bs_parse_error perr;

static double ugood[N] = {0.0, 0.25, 0.5, 1.0}, vgood[N] = {1.0, 0.5, 0.125, 0.0};
static double umis[N + 1];

static void reset(void)
{
    for (int d = 0; d < 4; d++)
        for (int c = 0; c < BS_MAX_DIM; c++) {
            for (int k = 0; k < N + 2 * SLACK; k++)
                obuf[d][c][k] = SENT;
            ov[d][c] = (bs_view){&obuf[d][c][SLACK], N, 0};
        }
    memset(kbuf, KSENT, sizeof kbuf);
    for (size_t k = 0; k < sizeof cbuf / sizeof cbuf[0]; k++)
        cbuf[k] = SENT;
    for (size_t k = 0; k < sizeof wbuf / sizeof wbuf[0]; k++)
        wbuf[k] = SENT;
    memset(tbuf, 'Z', sizeof tbuf);
    for (int k = 0; k < 4; k++)
        h[k] = HSENT;
    hs = (bs_surface *)(void *)HSENT;
    memset(&perr, 0x5A, sizeof perr);
}

static int untouched(void)
{
    for (int d = 0; d < 4; d++)
        for (int c = 0; c < BS_MAX_DIM; c++)
            for (int k = 0; k < N + 2 * SLACK; k++)
                if (obuf[d][c][k] != SENT)
                    return 0;
    for (size_t k = 0; k < sizeof kbuf; k++)
        if (kbuf[k] != KSENT)
            return 0;
    for (size_t k = 0; k < sizeof cbuf / sizeof cbuf[0]; k++)
        if (cbuf[k] != SENT)
            return 0;
    for (size_t k = 0; k < sizeof wbuf / sizeof wbuf[0]; k++)
        if (wbuf[k] != SENT)
            return 0;
    for (size_t k = 0; k < sizeof tbuf; k++)
        if (tbuf[k] != 'Z')
            return 0;
    return 1;
}

/* New-handle outputs that were passed must be NULL; the others keep the sentinel. */
static int handles_ok(void)
{
    for (int k = 0; k < 4; k++)
        if (h[k] != NULL && h[k] != HSENT)
            return 0;
    return hs == NULL || hs == (bs_surface *)(void *)HSENT;
}

/* The matrix: distinct functions and classes seen, and cases run. */
static const char *fn_seen[256], *cls_seen[256];
static int n_fn, n_cls, n_cases;

static void note(const char **seen, int *count, const char *name)
{
    for (int k = 0; k < *count; k++)
        if (strcmp(seen[k], name) == 0)
            return;
    if (*count < 256)
        seen[(*count)++] = name;
}

/* A failing case: expected status, nothing written, handles NULL. */
#define BAD(fn, cls, expected, call)                                                                   \
    do {                                                                                               \
        reset();                                                                                       \
        bs_status got_ = (call);                                                                       \
        note(fn_seen, &n_fn, fn);                                                                      \
        note(cls_seen, &n_cls, cls);                                                                   \
        n_cases++;                                                                                     \
        CHECKF(got_ == (expected), "%s [%s]: got %d, expected %s", fn, cls, got_, #expected);          \
        CHECKF(untouched(), "%s [%s]: a failing call wrote into a caller buffer", fn, cls);            \
        CHECKF(handles_ok(), "%s [%s]: a new-handle output is not NULL", fn, cls);                     \
    } while (0)

/* A handle output that must have been set to NULL. */
#define NULLED(x) CHECKF((x) == NULL, "new-handle output %s not set to NULL", #x)

static bs_patch *P3, *R3, *P2;
static bs_surface *S3, *S2;

static const double net3[27] = {0, 0, 0, 1, 0, 1, 2, 0, 0, 0, 1, 1, 1, 1, 2, 2, 1, 1, 0, 2, 0, 1, 2, 1, 2, 2, 0};
static const double w9[9] = {1, 2, 1, 0.5, 1, 3, 1, 1, 2};
static const double net2[8] = {0, 0, 1, 0, 0, 1, 1, 1};

static void setup(void)
{
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &P3), BS_OK);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, w9, &R3), BS_OK);
    CHECK_STATUS(bs_patch_create(1, 1, 2, net2, NULL, &P2), BS_OK);
    CHECK_STATUS(bs_surface_create(&S3), BS_OK);
    CHECK_STATUS(bs_surface_add(S3, P3, NULL), BS_OK);
    CHECK_STATUS(bs_surface_add(S3, R3, NULL), BS_OK);
    CHECK_STATUS(bs_surface_create(&S2), BS_OK);
    CHECK_STATUS(bs_surface_add(S2, P2, NULL), BS_OK);
}

/* Input views, bad in each way a view can be. */
typedef struct bad_cview {
    const char *cls;
    bs_status st;
    bs_cview v;
} bad_cview;

enum { N_BAD_IN = 8, N_SPOIL = 7 };
static bad_cview bad_in[N_BAD_IN];

/* A stride whose (N-1) multiples fit in ptrdiff_t, but which moves the last of N elements out of the
 * address space: backwards past address 0, or forwards past the end of any object. */
#define WRAP_STRIDE ((ptrdiff_t)((PTRDIFF_MAX / (N - 1)) & ~(ptrdiff_t)7))

static void make_bad_inputs(void)
{
    const double *mis = (const double *)(const void *)((const char *)umis + 4);
    bad_cview b[N_BAD_IN] = {
        {"NULL view data", BS_ERR_INVALID_ARG, {NULL, N, 0}},
        {"misaligned data", BS_ERR_INVALID_ARG, {mis, N, 0}},
        {"misaligned stride", BS_ERR_INVALID_ARG, {ugood, N, 12}},
        {"count too small", BS_ERR_SIZE, {ugood, N - 1, 0}},
        {"n x stride overflows", BS_ERR_SIZE, {ugood, SIZE_MAX, PTRDIFF_MAX / 2 + 1}},
        {"negative misaligned stride", BS_ERR_INVALID_ARG, {ugood + N - 1, N, -4}},
        {"element address wraps", BS_ERR_SIZE, {ugood, N, -WRAP_STRIDE}},
        {"element address wraps", BS_ERR_SIZE, {ugood, N, WRAP_STRIDE}},
    };
    memcpy(bad_in, b, sizeof b);
}

/* Output views of output d, bad in coordinate c in one way. */
static void spoil(int d, int c, int how)
{
    switch (how) {
    case 0: ov[d][c].data = NULL; break;
    case 1: ov[d][c].data = (double *)(void *)((char *)ov[d][c].data + 4); break;
    case 2: ov[d][c].stride = 12; break;
    case 3: ov[d][c].count = N - 1; break;
    case 5: ov[d][c].stride = -WRAP_STRIDE; break;
    case 6: ov[d][c].stride = WRAP_STRIDE; break;
    default: ov[d][c].count = SIZE_MAX; ov[d][c].stride = PTRDIFF_MAX / 2 + 1; break;
    }
}
static const char *const spoil_cls[N_SPOIL] = {"NULL view data", "misaligned data", "misaligned stride",
                                                "count too small", "n x stride overflows",
                                                "element address wraps", "element address wraps"};
static const bs_status spoil_st[N_SPOIL] = {BS_ERR_INVALID_ARG, BS_ERR_INVALID_ARG, BS_ERR_INVALID_ARG, BS_ERR_SIZE,
                                            BS_ERR_SIZE, BS_ERR_SIZE, BS_ERR_SIZE};

/* Output spoiling needs reset() to run first: these macros do it inside the call expression. */
static const bs_view *sp(int d, int c, int how)
{
    reset();
    spoil(d, c, how);
    return ov[d];
}

#define BAD_SPOILED(fn, how, expected, call)                                                       \
    do {                                                                                           \
        note(fn_seen, &n_fn, fn);                                                                  \
        note(cls_seen, &n_cls, spoil_cls[how]);                                                    \
        n_cases++;                                                                                 \
        bs_status got_ = (call);                                                                   \
        CHECKF(got_ == (expected), "%s [%s output]: got %d", fn, spoil_cls[how], got_);            \
        /* the spoiled view may point into the buffer: compare buffer contents only */             \
        CHECKF(untouched(), "%s [%s output]: a failing call wrote into a caller buffer", fn,       \
               spoil_cls[how]);                                                                    \
    } while (0)

static void test_evaluators(void)
{
    bs_cview u = {ugood, N, 0}, v = {vgood, N, 0};
    uint32_t ids[N] = {0, 1, 1, 0}, bad_ids[N] = {0, 1, 2, 0};
    /* NULL handle, NULL parameter views */
    BAD("bs_patch_eval", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_eval(NULL, N, &u, &v, ov[0], ov[1], ov[2]));
    BAD("bs_patch_eval", "NULL views", BS_ERR_INVALID_ARG, bs_patch_eval(P3, N, NULL, &v, ov[0], NULL, NULL));
    BAD("bs_patch_eval", "NULL views", BS_ERR_INVALID_ARG, bs_patch_eval(P3, N, &u, NULL, ov[0], NULL, NULL));
    BAD("bs_patch_eval_deriv", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_eval_deriv(NULL, 1, 1, N, &u, &v, ov[0]));
    BAD("bs_patch_eval_deriv", "NULL views", BS_ERR_INVALID_ARG, bs_patch_eval_deriv(P3, 1, 1, N, &u, &v, NULL));
    BAD("bs_patch_eval_deriv", "NULL views", BS_ERR_INVALID_ARG, bs_patch_eval_deriv(P3, 1, 1, N, NULL, &v, ov[0]));
    BAD("bs_patch_eval_deriv", "order > max", BS_ERR_DEGREE,
        bs_patch_eval_deriv(P3, BS_MAX_DEGREE + 1, 0, N, &u, &v, ov[0]));
    BAD("bs_patch_eval_deriv", "order > max", BS_ERR_DEGREE, bs_patch_eval_deriv(R3, 0, 4000000000u, N, &u, &v, ov[0]));
    BAD("bs_patch_eval_normal", "NULL handle", BS_ERR_INVALID_ARG,
        bs_patch_eval_normal(NULL, N, &u, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_patch_eval_normal", "NULL views", BS_ERR_INVALID_ARG,
        bs_patch_eval_normal(P3, N, &u, NULL, ov[0], ov[3], kbuf + 1));
    BAD("bs_patch_eval_normal", "dim out of range", BS_ERR_DIMENSION,
        bs_patch_eval_normal(P2, N, &u, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_patch_eval_grid", "NULL handle", BS_ERR_INVALID_ARG,
        bs_patch_eval_grid(NULL, 2, &u, 2, &v, ov[0], NULL, NULL, NULL, NULL));
    BAD("bs_patch_eval_grid", "NULL views", BS_ERR_INVALID_ARG,
        bs_patch_eval_grid(P3, 2, NULL, 2, &v, ov[0], NULL, NULL, NULL, NULL));
    BAD("bs_patch_eval_grid", "dim out of range", BS_ERR_DIMENSION,
        bs_patch_eval_grid(P2, 2, &u, 2, &v, ov[0], NULL, NULL, ov[3], NULL));
    BAD("bs_patch_eval_grid", "dim out of range", BS_ERR_DIMENSION,
        bs_patch_eval_grid(P2, 2, &u, 2, &v, ov[0], NULL, NULL, NULL, kbuf + 1));
    BAD("bs_patch_eval_grid", "nu x nv overflows", BS_ERR_SIZE,
        bs_patch_eval_grid(P3, SIZE_MAX / 2, &u, 3, &v, ov[0], NULL, NULL, NULL, NULL));
    BAD("bs_surface_eval", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_eval(NULL, N, ids, &u, &v, ov[0], NULL, NULL));
    BAD("bs_surface_eval", "NULL views", BS_ERR_INVALID_ARG, bs_surface_eval(S3, N, NULL, &u, &v, ov[0], NULL, NULL));
    BAD("bs_surface_eval", "NULL views", BS_ERR_INVALID_ARG, bs_surface_eval(S3, N, ids, &u, NULL, ov[0], NULL, NULL));
    BAD("bs_surface_eval", "id out of range", BS_ERR_INVALID_ARG,
        bs_surface_eval(S3, N, bad_ids, &u, &v, ov[0], ov[1], ov[2]));
    BAD("bs_surface_eval_normal", "NULL handle", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal(NULL, N, ids, &u, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_surface_eval_normal_mt", "NULL handle", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal_mt(NULL, N, ids, &u, &v, ov[0], ov[3], kbuf + 1, 2));
    BAD("bs_surface_eval_normal", "NULL views", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal(S3, N, ids, NULL, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_surface_eval_normal_mt", "NULL views", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal_mt(S3, N, ids, NULL, &v, ov[0], ov[3], kbuf + 1, 2));
    BAD("bs_surface_eval_normal", "dim out of range", BS_ERR_DIMENSION,
        bs_surface_eval_normal(S2, N, ids, &u, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_surface_eval_normal_mt", "dim out of range", BS_ERR_DIMENSION,
        bs_surface_eval_normal_mt(S2, N, ids, &u, &v, ov[0], ov[3], kbuf + 1, 2));
    BAD("bs_surface_eval_normal", "id out of range", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal(S3, N, bad_ids, &u, &v, ov[0], ov[3], kbuf + 1));
    BAD("bs_surface_eval_normal_mt", "id out of range", BS_ERR_INVALID_ARG,
        bs_surface_eval_normal_mt(S3, N, bad_ids, &u, &v, ov[0], ov[3], kbuf + 1, 2));

    /* every bad input view, as u and as v */
    for (int k = 0; k < N_BAD_IN; k++) {
        const bad_cview *b = &bad_in[k];
        for (int which = 0; which < 2; which++) {
            const bs_cview *bu = which ? &u : &b->v, *bv = which ? &b->v : &v;
            BAD("bs_patch_eval", b->cls, b->st, bs_patch_eval(P3, N, bu, bv, ov[0], ov[1], ov[2]));
            BAD("bs_patch_eval_deriv", b->cls, b->st, bs_patch_eval_deriv(R3, 1, 2, N, bu, bv, ov[0]));
            BAD("bs_patch_eval_normal", b->cls, b->st, bs_patch_eval_normal(R3, N, bu, bv, ov[0], ov[3], kbuf + 1));
            BAD("bs_patch_eval_grid", b->cls, b->st,
                bs_patch_eval_grid(P3, which ? 1 : N, bu, which ? N : 1, bv, ov[0], ov[1], ov[2], ov[3], kbuf + 1));
            BAD("bs_surface_eval", b->cls, b->st, bs_surface_eval(S3, N, ids, bu, bv, ov[0], ov[1], ov[2]));
            BAD("bs_surface_eval_normal", b->cls, b->st,
                bs_surface_eval_normal(S3, N, ids, bu, bv, ov[0], ov[3], kbuf + 1));
            BAD("bs_surface_eval_normal_mt", b->cls, b->st,
                bs_surface_eval_normal_mt(S3, N, ids, bu, bv, ov[0], ov[3], kbuf + 1, 2));
        }
    }
    /* two elements whose byte distance fits in ptrdiff_t, but whose second address does not exist */
    {
        const bs_cview back = {ugood, 2, -((ptrdiff_t)1 << 62)}, fwd = {ugood, 2, PTRDIFF_MAX - 7};
        BAD("bs_patch_eval", "element address wraps", BS_ERR_SIZE, bs_patch_eval(P3, 2, &back, &v, ov[0], NULL, NULL));
        BAD("bs_patch_eval", "element address wraps", BS_ERR_SIZE, bs_patch_eval(P3, 2, &u, &fwd, ov[0], NULL, NULL));
        BAD("bs_patch_eval", "element address wraps", BS_ERR_SIZE,
            (ov[0][1].stride = -((ptrdiff_t)1 << 62), ov[0][1].count = 2, bs_patch_eval(P3, 2, &u, &v, ov[0], NULL, NULL)));
        BAD("bs_patch_eval", "element address wraps", BS_ERR_SIZE,
            (ov[0][2].stride = PTRDIFF_MAX - 7, bs_patch_eval(P3, 2, &u, &v, ov[0], NULL, NULL)));
    }
    /* every bad output view, in each output and coordinate */
    for (int how = 0; how < N_SPOIL; how++)
        for (int d = 0; d < 3; d++)
            for (int c = 0; c < 3; c++) {
                const bs_view *o = NULL;
                BAD_SPOILED("bs_patch_eval", how, spoil_st[how],
                            (o = sp(d, c, how), bs_patch_eval(R3, N, &u, &v, ov[0], ov[1], ov[2])));
                BAD_SPOILED("bs_patch_eval_deriv", how, spoil_st[how],
                            (o = sp(d, c, how), bs_patch_eval_deriv(R3, 1, 1, N, &u, &v, o)));
                BAD_SPOILED("bs_patch_eval_normal", how, spoil_st[how],
                            (o = sp(d == 0 ? 0 : 3, c, how), bs_patch_eval_normal(P3, N, &u, &v, ov[0], ov[3], kbuf + 1)));
                BAD_SPOILED("bs_patch_eval_grid", how, spoil_st[how],
                            (o = sp(d, c, how), bs_patch_eval_grid(P3, 2, &u, 2, &v, ov[0], ov[1], ov[2], ov[3], kbuf + 1)));
                BAD_SPOILED("bs_surface_eval", how, spoil_st[how],
                            (o = sp(d, c, how), bs_surface_eval(S3, N, ids, &u, &v, ov[0], ov[1], ov[2])));
                BAD_SPOILED("bs_surface_eval_normal", how, spoil_st[how],
                            (o = sp(d == 0 ? 0 : 3, c, how),
                             bs_surface_eval_normal(S3, N, ids, &u, &v, ov[0], ov[3], kbuf + 1)));
                BAD_SPOILED("bs_surface_eval_normal_mt", how, spoil_st[how],
                            (o = sp(d == 0 ? 0 : 3, c, how),
                             bs_surface_eval_normal_mt(S3, N, ids, &u, &v, ov[0], ov[3], kbuf + 1, 2)));
                (void)o;
            }
}

/* NaN and Inf parameters are not errors: BS_OK, NaN in that point's outputs only. */
static void test_nonfinite_parameters(void)
{
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 3; k++)
        for (int which = 0; which < 2; which++) {
            double uu[N], vv[N];
            memcpy(uu, ugood, sizeof uu);
            memcpy(vv, vgood, sizeof vv);
            (which ? vv : uu)[2] = bad[k];
            bs_cview u = {uu, N, 0}, v = {vv, N, 0};
            uint32_t ids[N] = {1, 0, 1, 0};
            for (int f = 0; f < 4; f++) {
                reset();
                bs_status st = f == 0   ? bs_patch_eval(R3, N, &u, &v, ov[0], ov[1], ov[2])
                               : f == 1 ? bs_patch_eval_normal(P3, N, &u, &v, ov[0], ov[3], kbuf + SLACK)
                               : f == 2 ? bs_surface_eval(S3, N, ids, &u, &v, ov[0], ov[1], ov[2])
                                        : bs_surface_eval_normal_mt(S3, N, ids, &u, &v, ov[0], ov[3], kbuf + SLACK, 2);
                static const char *const names[4] = {"bs_patch_eval", "bs_patch_eval_normal", "bs_surface_eval",
                                                      "bs_surface_eval_normal_mt"};
                note(fn_seen, &n_fn, names[f]);
                note(cls_seen, &n_cls, "NaN/Inf parameters");
                n_cases++;
                CHECK_STATUS(st, BS_OK);
                int ok = 1;
                for (int c = 0; c < 3; c++)
                    for (int e = 0; e < N; e++)
                        ok &= (e == 2) == (isnan(obuf[0][c][SLACK + e]) != 0);
                ok &= obuf[0][0][0] == SENT && obuf[0][0][SLACK + N] == SENT;
                if (f == 1 || f == 3)
                    ok &= kbuf[SLACK + 2] == BS_NORMAL_UNDEFINED && isnan(obuf[3][0][SLACK + 2]);
                CHECKF(ok, "NaN/Inf parameter %d in %s of call %d: NaN not confined to its point", k,
                       which ? "v" : "u", f);
            }
        }
}

static void test_create_and_accessors(void)
{
    double big[(BS_MAX_DEGREE + 2) * 2 * 3];
    for (size_t k = 0; k < sizeof big / sizeof big[0]; k++)
        big[k] = (double)k;
    BAD("bs_patch_create", "NULL views", BS_ERR_INVALID_ARG, bs_patch_create(2, 2, 3, NULL, NULL, &h[0]));
    BAD("bs_patch_create", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_create(2, 2, 3, net3, NULL, NULL));
    BAD("bs_patch_create", "degree > max", BS_ERR_DEGREE, bs_patch_create(BS_MAX_DEGREE + 1, 1, 3, big, NULL, &h[0]));
    BAD("bs_patch_create", "degree > max", BS_ERR_DEGREE, bs_patch_create(1, SIZE_MAX, 3, big, NULL, &h[0]));
    BAD("bs_patch_create", "dim out of range", BS_ERR_DIMENSION, bs_patch_create(1, 1, 0, big, NULL, &h[0]));
    BAD("bs_patch_create", "dim out of range", BS_ERR_DIMENSION, bs_patch_create(1, 1, BS_MAX_DIM + 1, big, NULL, &h[0]));
    BAD("bs_patch_create", "dim out of range", BS_ERR_DIMENSION, bs_patch_create(1, 1, SIZE_MAX, big, NULL, &h[0]));
    const double nonfinite[4] = {NAN, INFINITY, -INFINITY, -NAN};
    for (int k = 0; k < 4; k++)
        for (int at = 0; at < 27; at += 13) {
            double c[27], w[9];
            memcpy(c, net3, sizeof c);
            memcpy(w, w9, sizeof w);
            c[at] = nonfinite[k];
            BAD("bs_patch_create", "NaN/Inf control points", BS_ERR_NONFINITE, bs_patch_create(2, 2, 3, c, NULL, &h[0]));
            BAD("bs_patch_create", "NaN/Inf control points", BS_ERR_NONFINITE, bs_patch_create(2, 2, 3, c, w9, &h[0]));
            w[at / 3] = nonfinite[k];
            BAD("bs_patch_create", "NaN/Inf weights", BS_ERR_NONFINITE, bs_patch_create(2, 2, 3, net3, w, &h[0]));
        }
    const double bad_w[4] = {0.0, -0.0, -1.0, -DBL_MIN};
    for (int k = 0; k < 4; k++) {
        double w[9];
        memcpy(w, w9, sizeof w);
        w[4] = bad_w[k];
        BAD("bs_patch_create", "non-positive weights", BS_ERR_NONFINITE, bs_patch_create(2, 2, 3, net3, w, &h[0]));
    }
    double cbig[27], wbig[9];
    memcpy(cbig, net3, sizeof cbig);
    memcpy(wbig, w9, sizeof wbig);
    cbig[5] = 1e300;
    wbig[1] = 1e300;
    BAD("bs_patch_create", "w x P overflows", BS_ERR_NONFINITE, bs_patch_create(2, 2, 3, cbig, wbig, &h[0]));

    BAD("bs_patch_clone", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_clone(NULL, &h[0]));
    BAD("bs_patch_clone", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_clone(P3, NULL));
    BAD("bs_patch_get_ctrl", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_get_ctrl(NULL, cbuf, 27, wbuf, 9));
    BAD("bs_patch_get_ctrl", "count too small", BS_ERR_SIZE, bs_patch_get_ctrl(P3, cbuf, 26, wbuf, 9));
    BAD("bs_patch_get_ctrl", "count too small", BS_ERR_SIZE, bs_patch_get_ctrl(R3, cbuf, 27, wbuf, 8));
    BAD("bs_patch_get_ctrl", "count too small", BS_ERR_SIZE, bs_patch_get_ctrl(R3, cbuf, 0, NULL, 0));

    /* queries of a NULL handle return their documented neutral values */
    note(fn_seen, &n_fn, "bs_patch_degree_u");
    note(fn_seen, &n_fn, "bs_patch_degree_v");
    note(fn_seen, &n_fn, "bs_patch_dim");
    note(fn_seen, &n_fn, "bs_patch_is_rational");
    note(fn_seen, &n_fn, "bs_patch_destroy");
    note(fn_seen, &n_fn, "bs_surface_destroy");
    note(fn_seen, &n_fn, "bs_surface_count");
    note(fn_seen, &n_fn, "bs_surface_dim");
    note(fn_seen, &n_fn, "bs_surface_get");
    note(fn_seen, &n_fn, "bs_status_string");
    note(fn_seen, &n_fn, "bs_builtin_name");
    n_cases += 13;
    CHECK(bs_patch_degree_u(NULL) == 0 && bs_patch_degree_v(NULL) == 0 && bs_patch_dim(NULL) == 0);
    CHECK(bs_patch_is_rational(NULL) == 0);
    bs_patch_destroy(NULL);
    bs_surface_destroy(NULL);
    CHECK(bs_surface_count(NULL) == 0 && bs_surface_dim(NULL) == 0 && bs_surface_get(NULL, 0) == NULL);
    CHECK(bs_surface_get(S3, 2) == NULL && bs_surface_get(S3, SIZE_MAX) == NULL);
    CHECK(strcmp(bs_status_string(-13), "unknown status") == 0);
    CHECK(strcmp(bs_status_string(BS_ERR_PRECISION), "unknown status") != 0);
    CHECK(strcmp(bs_status_string(1), "unknown status") == 0);
    CHECK(bs_status_string(-2147483647 - 1) != NULL);
    CHECK(bs_builtin_name(3) == NULL && bs_builtin_name(SIZE_MAX) == NULL);
}

static void test_operations(void)
{
    const double bad_t[6] = {0.0, 1.0, -0.25, 1.25, NAN, INFINITY};
    BAD("bs_patch_split", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_split(NULL, 0, 0.5, &h[0], &h[1]));
    BAD("bs_patch_split", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_split(P3, 0, 0.5, NULL, &h[1]));
    BAD("bs_patch_split", "bad direction", BS_ERR_INVALID_ARG, bs_patch_split(P3, 2, 0.5, &h[0], &h[1]));
    BAD("bs_patch_split4", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_split4(NULL, 0.5, 0.5, h));
    BAD("bs_patch_split4", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_split4(P3, 0.5, 0.5, NULL));
    for (int k = 0; k < 6; k++) {
        const char *cls = k < 4 ? "zero-length intervals" : "NaN/Inf parameters";
        BAD("bs_patch_split", cls, BS_ERR_DOMAIN, bs_patch_split(R3, k & 1, bad_t[k], &h[0], &h[1]));
        NULLED(h[0]);
        NULLED(h[1]);
        BAD("bs_patch_split4", cls, BS_ERR_DOMAIN, bs_patch_split4(R3, bad_t[k], 0.5, h));
        BAD("bs_patch_split4", cls, BS_ERR_DOMAIN, bs_patch_split4(P3, 0.5, bad_t[k], h));
        NULLED(h[3]);
    }
    BAD("bs_patch_subpatch", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_subpatch(NULL, 0, 1, 0, 1, &h[0]));
    BAD("bs_patch_subpatch", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_subpatch(P3, 0, 1, 0, 1, NULL));
    BAD("bs_patch_subpatch", "zero-length intervals", BS_ERR_DOMAIN, bs_patch_subpatch(P3, 0.5, 0.5, 0, 1, &h[0]));
    BAD("bs_patch_subpatch", "zero-length intervals", BS_ERR_DOMAIN, bs_patch_subpatch(R3, 0, 1, 0.25, 0.25, &h[0]));
    BAD("bs_patch_subpatch", "NaN/Inf parameters", BS_ERR_DOMAIN, bs_patch_subpatch(P3, NAN, 1, 0, 1, &h[0]));
    BAD("bs_patch_subpatch", "NaN/Inf parameters", BS_ERR_DOMAIN, bs_patch_subpatch(P3, 0, 1, 0, -INFINITY, &h[0]));
    NULLED(h[0]);
    BAD("bs_patch_elevate", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_elevate(NULL, 1, 1, &h[0]));
    BAD("bs_patch_elevate", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_elevate(P3, 1, 1, NULL));
    BAD("bs_patch_elevate", "degree > max", BS_ERR_DEGREE, bs_patch_elevate(P3, BS_MAX_DEGREE - 1, 0, &h[0]));
    BAD("bs_patch_elevate", "degree > max", BS_ERR_DEGREE, bs_patch_elevate(R3, 0, SIZE_MAX, &h[0]));
    BAD("bs_patch_derivative", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_derivative(NULL, 1, 0, &h[0]));
    BAD("bs_patch_derivative", "order > max", BS_ERR_DEGREE, bs_patch_derivative(P3, BS_MAX_DEGREE + 1, 0, &h[0]));
    BAD("bs_patch_derivative", "rational unsupported", BS_ERR_UNSUPPORTED, bs_patch_derivative(R3, 1, 0, &h[0]));
    BAD("bs_patch_isocurve", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_isocurve(NULL, 0, 0.5, cbuf, 9, wbuf, 3));
    BAD("bs_patch_isocurve", "NULL views", BS_ERR_INVALID_ARG, bs_patch_isocurve(P3, 0, 0.5, NULL, 9, wbuf, 3));
    BAD("bs_patch_isocurve", "bad direction", BS_ERR_INVALID_ARG, bs_patch_isocurve(P3, -1, 0.5, cbuf, 9, wbuf, 3));
    BAD("bs_patch_isocurve", "count too small", BS_ERR_SIZE, bs_patch_isocurve(P3, 0, 0.5, cbuf, 8, wbuf, 3));
    BAD("bs_patch_isocurve", "count too small", BS_ERR_SIZE, bs_patch_isocurve(R3, 1, 0.5, cbuf, 9, wbuf, 2));
    BAD("bs_patch_isocurve", "NaN/Inf parameters", BS_ERR_DOMAIN, bs_patch_isocurve(R3, 1, NAN, cbuf, 9, wbuf, 3));
    BAD("bs_patch_isocurve", "NaN/Inf parameters", BS_ERR_DOMAIN, bs_patch_isocurve(P3, 0, INFINITY, cbuf, 9, NULL, 0));
    BAD("bs_patch_bounds", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_bounds(NULL, cbuf, wbuf));
    BAD("bs_patch_bounds", "NULL views", BS_ERR_INVALID_ARG, bs_patch_bounds(P3, NULL, wbuf));
    BAD("bs_patch_bounds", "NULL views", BS_ERR_INVALID_ARG, bs_patch_bounds(P3, cbuf, NULL));
    double aff[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    BAD("bs_patch_transform", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_transform(NULL, aff, &h[0]));
    BAD("bs_patch_transform", "NULL views", BS_ERR_INVALID_ARG, bs_patch_transform(P3, NULL, &h[0]));
    BAD("bs_patch_transform", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_transform(P3, aff, NULL));
    aff[3] = NAN;
    BAD("bs_patch_transform", "NaN/Inf control points", BS_ERR_NONFINITE, bs_patch_transform(R3, aff, &h[0]));
    aff[3] = 0;
    aff[0] = 1e308;
    BAD("bs_patch_transform", "overflow", BS_ERR_NONFINITE, bs_patch_transform(P3, aff, &h[0]));
    NULLED(h[0]);
    BAD("bs_patch_swap_uv", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_swap_uv(NULL, &h[0]));
    BAD("bs_patch_swap_uv", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_swap_uv(P3, NULL));
    BAD("bs_patch_reverse", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_reverse(NULL, 0, &h[0]));
    BAD("bs_patch_reverse", "bad direction", BS_ERR_INVALID_ARG, bs_patch_reverse(P3, 7, &h[0]));
}

static void test_constructions(void)
{
    const double c3[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    const double d3[9] = {0, 1, 0, 1, 1, 0, 2, 1, 0};
    const double nanc[9] = {0, 0, 0, NAN, 0, 0, 2, 0, 0};
    const double w3[3] = {1, 2, 1}, wbad[3] = {1, 0, 1};
    bs_curve a = {2, 3, c3, NULL}, b = {2, 3, d3, NULL};
    bs_curve deg = {BS_MAX_DEGREE + 1, 3, c3, NULL}, dim0 = {2, 0, c3, NULL}, dim9 = {0, 9, c3, NULL};
    bs_curve nctrl = {2, 3, NULL, NULL}, nanv = {2, 3, nanc, NULL}, d2 = {1, 2, c3, NULL};
    bs_curve rat = {2, 3, c3, w3}, ratbad = {2, 3, c3, wbad};
    BAD("bs_patch_ruled", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_ruled(NULL, &b, &h[0]));
    BAD("bs_patch_ruled", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_ruled(&a, &b, NULL));
    BAD("bs_patch_ruled", "NULL views", BS_ERR_INVALID_ARG, bs_patch_ruled(&a, &nctrl, &h[0]));
    BAD("bs_patch_ruled", "degree > max", BS_ERR_DEGREE, bs_patch_ruled(&deg, &b, &h[0]));
    BAD("bs_patch_ruled", "dim out of range", BS_ERR_DIMENSION, bs_patch_ruled(&a, &dim0, &h[0]));
    BAD("bs_patch_ruled", "dim out of range", BS_ERR_DIMENSION, bs_patch_ruled(&dim9, &b, &h[0]));
    BAD("bs_patch_ruled", "incompatible", BS_ERR_INCOMPATIBLE, bs_patch_ruled(&a, &d2, &h[0]));
    BAD("bs_patch_ruled", "NaN/Inf control points", BS_ERR_NONFINITE, bs_patch_ruled(&a, &nanv, &h[0]));
    BAD("bs_patch_ruled", "NaN/Inf weights", BS_ERR_NONFINITE, bs_patch_ruled(&ratbad, &b, &h[0]));
    NULLED(h[0]);
    /* Coons: corners of a, b with two straight sides */
    const double s0[6] = {0, 0, 0, 0, 1, 0}, s1[6] = {2, 0, 0, 2, 1, 0}, s1off[6] = {2, 0, 0.5, 2, 1, 0};
    bs_curve u0 = {1, 3, s0, NULL}, u1 = {1, 3, s1, NULL}, u1off = {1, 3, s1off, NULL};
    BAD("bs_patch_coons", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_coons(&a, &b, NULL, &u1, &h[0]));
    BAD("bs_patch_coons", "NULL handle", BS_ERR_INVALID_ARG, bs_patch_coons(&a, &b, &u0, &u1, NULL));
    BAD("bs_patch_coons", "NULL views", BS_ERR_INVALID_ARG, bs_patch_coons(&a, &nctrl, &u0, &u1, &h[0]));
    BAD("bs_patch_coons", "degree > max", BS_ERR_DEGREE, bs_patch_coons(&a, &b, &u0, &deg, &h[0]));
    BAD("bs_patch_coons", "dim out of range", BS_ERR_DIMENSION, bs_patch_coons(&dim0, &b, &u0, &u1, &h[0]));
    BAD("bs_patch_coons", "incompatible", BS_ERR_INCOMPATIBLE, bs_patch_coons(&a, &b, &u0, &u1off, &h[0]));
    BAD("bs_patch_coons", "rational unsupported", BS_ERR_UNSUPPORTED, bs_patch_coons(&rat, &b, &u0, &u1, &h[0]));
    BAD("bs_patch_coons", "NaN/Inf control points", BS_ERR_NONFINITE, bs_patch_coons(&a, &b, &u0, &nanv, &h[0]));
    NULLED(h[0]);
}

/* The bad arguments of a surface text writer and of its file twin. */
typedef bs_status (*text_writer)(const bs_surface *, char *, size_t, size_t *);
typedef bs_status (*file_writer)(const bs_surface *, const char *);
static void writer_rows(const char *name, text_writer w, const char *file_name, file_writer wf)
{
    size_t ne = 99;
    BAD(name, "NULL handle", BS_ERR_INVALID_ARG, w(NULL, tbuf, sizeof tbuf, &ne));
    BAD(name, "NULL views", BS_ERR_INVALID_ARG, w(S3, tbuf, sizeof tbuf, NULL));
    BAD(name, "count too small", BS_ERR_SIZE, w(S3, tbuf, 10, &ne));
    BAD(name, "dim out of range", BS_ERR_DIMENSION, w(S2, tbuf, sizeof tbuf, &ne));
    BAD(file_name, "NULL handle", BS_ERR_INVALID_ARG, wf(NULL, "x.out"));
    BAD(file_name, "NULL views", BS_ERR_INVALID_ARG, wf(S3, NULL));
    BAD(file_name, "dim out of range", BS_ERR_DIMENSION, wf(S2, "x.out"));
    BAD(file_name, "I/O failure", BS_ERR_IO, wf(S3, "/nonexistent-directory/x.out"));
    CHECK(ne == 99);
}

static void test_surfaces(void)
{
    bs_edge_continuity edges[4];
    bs_open_edge open[8];
    size_t ne = 99, no = 99;
    BAD("bs_surface_create", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_create(NULL));
    BAD("bs_surface_clone", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_clone(NULL, &hs));
    NULLED(hs);
    BAD("bs_surface_clone", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_clone(S3, NULL));
    BAD("bs_surface_add", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_add(NULL, P3, NULL));
    BAD("bs_surface_add", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_add(S3, NULL, NULL));
    BAD("bs_surface_add", "incompatible", BS_ERR_INCOMPATIBLE, bs_surface_add(S3, P2, NULL));
    CHECK(bs_surface_count(S3) == 2);
    BAD("bs_surface_continuity", "NULL handle", BS_ERR_INVALID_ARG,
        bs_surface_continuity(NULL, 0, 4, edges, 4, &ne, open, 8, &no));
    BAD("bs_surface_continuity", "dim out of range", BS_ERR_DIMENSION,
        bs_surface_continuity(S2, 0, 4, edges, 4, &ne, open, 8, &no));
    const double bad_tol[3] = {-1e-9, NAN, INFINITY};
    for (int k = 0; k < 3; k++)
        BAD("bs_surface_continuity", "NaN/Inf parameters", BS_ERR_DOMAIN,
            bs_surface_continuity(S3, bad_tol[k], 4, edges, 4, &ne, open, 8, &no));
    BAD("bs_surface_continuity", "count too small", BS_ERR_DOMAIN,
        bs_surface_continuity(S3, 0, 0, edges, 4, &ne, open, 8, &no));
    BAD("bs_surface_continuity", "count too small", BS_ERR_DOMAIN,
        bs_surface_continuity(S3, 0, 4097, edges, 4, &ne, open, 8, &no));
    CHECK(ne == 99 && no == 99);
    /* too small a caller array for the open edges (the two patches have 8 open sides) */
    memset(open, 0x77, sizeof open);
    BAD("bs_surface_continuity", "count too small", BS_ERR_SIZE,
        bs_surface_continuity(S3, 0, 4, edges, 4, &ne, open, 1, &no));
    CHECK(open[0].patch == 0x77777777u);

    writer_rows("bs_surface_write_bpt", bs_surface_write_bpt, "bs_surface_write_bpt_file", bs_surface_write_bpt_file);
    BAD("bs_surface_create_builtin", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_create_builtin(NULL, &hs));
    NULLED(hs);
    BAD("bs_surface_create_builtin", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_create_builtin("teapot", NULL));
    BAD("bs_surface_create_builtin", "unknown name", BS_ERR_INVALID_ARG, bs_surface_create_builtin("Teapot", &hs));
    BAD("bs_surface_create_builtin", "unknown name", BS_ERR_INVALID_ARG, bs_surface_create_builtin("", &hs));
    NULLED(hs);
}

static void test_meshes(void)
{
    bs_mesh *m = NULL, *hm = (bs_mesh *)(void *)HSENT;
    CHECK_STATUS(bs_surface_tessellate_uniform(S3, 2, 2, 0, &m), BS_OK);
    const double bad_tol[5] = {0.0, -1.0, NAN, INFINITY, -INFINITY};
#define MESH_BAD(fn, cls, expected, call)                                            \
    do {                                                                             \
        hm = (bs_mesh *)(void *)HSENT;                                               \
        BAD(fn, cls, expected, call);                                                \
        CHECKF(hm == NULL, "%s [%s]: mesh handle not NULL", fn, cls);                \
    } while (0)
    MESH_BAD("bs_surface_tessellate_uniform", "NULL handle", BS_ERR_INVALID_ARG,
             bs_surface_tessellate_uniform(NULL, 2, 2, 0, &hm));
    BAD("bs_surface_tessellate_uniform", "NULL handle", BS_ERR_INVALID_ARG,
        bs_surface_tessellate_uniform(S3, 2, 2, 0, NULL));
    MESH_BAD("bs_surface_tessellate_uniform", "bad flags", BS_ERR_INVALID_ARG,
             bs_surface_tessellate_uniform(S3, 2, 2, 64, &hm));
    MESH_BAD("bs_surface_tessellate_uniform", "dim out of range", BS_ERR_DIMENSION,
             bs_surface_tessellate_uniform(S2, 2, 2, 0, &hm));
    MESH_BAD("bs_surface_tessellate_uniform", "count too small", BS_ERR_DOMAIN,
             bs_surface_tessellate_uniform(S3, 0, 2, 0, &hm));
    MESH_BAD("bs_surface_tessellate_uniform", "rate > max", BS_ERR_DOMAIN,
             bs_surface_tessellate_uniform(S3, 2, BS_TESS_MAX_RATE + 1, 0, &hm));
    MESH_BAD("bs_surface_tessellate_uniform", "rate > max", BS_ERR_DOMAIN,
             bs_surface_tessellate_uniform(S3, SIZE_MAX, 2, 0, &hm));
    MESH_BAD("bs_surface_tessellate_adaptive", "NULL handle", BS_ERR_INVALID_ARG,
             bs_surface_tessellate_adaptive(NULL, 0.1, 0, &hm));
    MESH_BAD("bs_surface_tessellate_adaptive", "bad flags", BS_ERR_INVALID_ARG,
             bs_surface_tessellate_adaptive(S3, 0.1, -1, &hm));
    MESH_BAD("bs_surface_tessellate_adaptive", "dim out of range", BS_ERR_DIMENSION,
             bs_surface_tessellate_adaptive(S2, 0.1, 0, &hm));
    for (int k = 0; k < 5; k++)
        MESH_BAD("bs_surface_tessellate_adaptive", "NaN/Inf parameters", BS_ERR_DOMAIN,
                 bs_surface_tessellate_adaptive(S3, bad_tol[k], BS_TESS_RELATIVE, &hm));
    /* 1.1: options, budgets and counts; the counts are written only on success */
    bs_tess_options o;
    bs_tess_options_init(&o);
    bs_tess_options_init(NULL);
    note(fn_seen, &n_fn, "bs_tess_options_init");
    size_t cv = 77, ct = 77;
    MESH_BAD("bs_surface_tessellate", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_tessellate(NULL, &o, &hm));
    MESH_BAD("bs_surface_tessellate", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_tessellate(S3, NULL, &hm));
    BAD("bs_surface_tessellate", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_tessellate(S3, &o, NULL));
    BAD("bs_surface_tessellate_count", "NULL handle", BS_ERR_INVALID_ARG,
        bs_surface_tessellate_count(NULL, &o, &cv, &ct));
    MESH_BAD("bs_surface_tessellate", "dim out of range", BS_ERR_DIMENSION, bs_surface_tessellate(S2, &o, &hm));
    BAD("bs_surface_tessellate_count", "dim out of range", BS_ERR_DIMENSION,
        bs_surface_tessellate_count(S2, &o, &cv, &ct));
    o.flags = 64;
    MESH_BAD("bs_surface_tessellate", "bad flags", BS_ERR_INVALID_ARG, bs_surface_tessellate(S3, &o, &hm));
    BAD("bs_surface_tessellate_count", "bad flags", BS_ERR_INVALID_ARG, bs_surface_tessellate_count(S3, &o, &cv, &ct));
    bs_tess_options_init(&o);
    o.method = 99;
    MESH_BAD("bs_surface_tessellate", "bad direction/flags", BS_ERR_INVALID_ARG, bs_surface_tessellate(S3, &o, &hm));
    bs_tess_options_init(&o);
    o.size = sizeof o / 2;
    MESH_BAD("bs_surface_tessellate", "count too small", BS_ERR_INVALID_ARG, bs_surface_tessellate(S3, &o, &hm));
    bs_tess_options_init(&o);
    o.nu = BS_TESS_MAX_RATE + 1;
    MESH_BAD("bs_surface_tessellate", "rate > max", BS_ERR_DOMAIN, bs_surface_tessellate(S3, &o, &hm));
    BAD("bs_surface_tessellate_count", "rate > max", BS_ERR_DOMAIN, bs_surface_tessellate_count(S3, &o, &cv, &ct));
    bs_tess_options_init(&o);
    o.method = BS_TESS_PER_PATCH;
    for (int k = 0; k < 5; k++) {
        o.tolerance = bad_tol[k];
        MESH_BAD("bs_surface_tessellate", "NaN/Inf parameters", BS_ERR_DOMAIN, bs_surface_tessellate(S3, &o, &hm));
        BAD("bs_surface_tessellate_count", "NaN/Inf parameters", BS_ERR_DOMAIN,
            bs_surface_tessellate_count(S3, &o, &cv, &ct));
    }
    bs_tess_options_init(&o);
    o.max_triangles = 1;
    MESH_BAD("bs_surface_tessellate", "over budget", BS_ERR_SIZE, bs_surface_tessellate(S3, &o, &hm));
    CHECK(cv == 77 && ct == 77);
    uint32_t ids[N + 2 * SLACK];
    memset(ids, 0x5C, sizeof ids);
    size_t nvtx = bs_mesh_vertex_count(m);
    CHECK(nvtx > N && bs_mesh_vertex_count(NULL) == 0 && bs_mesh_triangle_count(NULL) == 0);
    BAD("bs_mesh_copy_positions", "NULL handle", BS_ERR_INVALID_ARG, bs_mesh_copy_positions(NULL, ov[0]));
    BAD("bs_mesh_copy_positions", "NULL views", BS_ERR_INVALID_ARG, bs_mesh_copy_positions(m, NULL));
    BAD("bs_mesh_copy_positions", "count too small", BS_ERR_SIZE, bs_mesh_copy_positions(m, ov[0]));
    BAD("bs_mesh_copy_normals", "count too small", BS_ERR_SIZE, bs_mesh_copy_normals(m, ov[1]));
    BAD("bs_mesh_copy_uv", "count too small", BS_ERR_SIZE, bs_mesh_copy_uv(m, ov[2]));
    BAD("bs_mesh_copy_corner_uv", "count too small", BS_ERR_SIZE, bs_mesh_copy_corner_uv(m, ov[2]));
    BAD("bs_mesh_copy_patch_ids", "NULL views", BS_ERR_INVALID_ARG, bs_mesh_copy_patch_ids(m, NULL, 99));
    BAD("bs_mesh_copy_patch_ids", "count too small", BS_ERR_SIZE, bs_mesh_copy_patch_ids(m, ids, N));
    BAD("bs_mesh_copy_triangles", "count too small", BS_ERR_SIZE, bs_mesh_copy_triangles(m, ids, N));
    BAD("bs_mesh_copy_triangle_patch_ids", "count too small", BS_ERR_SIZE, bs_mesh_copy_triangle_patch_ids(m, ids, 1));
    BAD("bs_mesh_copy_strips", "NULL handle", BS_ERR_INVALID_ARG, bs_mesh_copy_strips(NULL, ids, 4, ids, 4));
    for (size_t k = 0; k < sizeof ids / sizeof ids[0]; k++)
        CHECK(ids[k] == 0x5C5C5C5Cu);
    BAD("bs_mesh_write_memory", "NULL handle", BS_ERR_INVALID_ARG, bs_mesh_write_memory(NULL, 0, tbuf, 10, &nvtx));
    BAD("bs_mesh_write_memory", "bad format", BS_ERR_INVALID_ARG, bs_mesh_write_memory(m, 99, tbuf, 10, &nvtx));
    BAD("bs_mesh_write_memory", "count too small", BS_ERR_SIZE, bs_mesh_write_memory(m, BS_MESH_PLY, tbuf, 10, &nvtx));
    BAD("bs_mesh_write", "NULL views", BS_ERR_INVALID_ARG, bs_mesh_write(m, BS_MESH_OBJ, NULL));
    BAD("bs_mesh_write", "bad format", BS_ERR_INVALID_ARG, bs_mesh_write(m, -1, "x.obj"));
    BAD("bs_mesh_write", "I/O failure", BS_ERR_IO, bs_mesh_write(m, BS_MESH_STL, "/nonexistent-directory/x.stl"));
    bs_mesh_destroy(m);
    /* queries and destruction of a NULL mesh: neutral values, no crash */
    bs_mesh_destroy(NULL);
    CHECK(bs_mesh_strip_count(NULL) == 0 && bs_mesh_strip_index_count(NULL) == 0);
    note(fn_seen, &n_fn, "bs_mesh_destroy");
    note(fn_seen, &n_fn, "bs_mesh_vertex_count");
    note(fn_seen, &n_fn, "bs_mesh_triangle_count");
    note(fn_seen, &n_fn, "bs_mesh_strip_count");
    note(fn_seen, &n_fn, "bs_mesh_strip_index_count");
    n_cases += 5;
#undef MESH_BAD
}

/* Truncated and hostile .bpt texts: each one BS_ERR_PARSE with a position, no surface. */
static void test_hostile_bpt(void)
{
    static const char *const texts[] = {
        "",
        "   \n\t ",
        "1",
        "1\n",
        "1\n3",
        "1\n3 3\n",
        "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1",
        "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1 junk",
        "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n2",
        "-1\n",
        "1\n-1 1\n",
        "1\n65 1\n",
        "1\n18446744073709551617 1\n",
        "18446744073709551616\n1 1\n",
        "4294967296\n1 1\n0 0 0\n",
        "1000000\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n64 64\n0 0 0\n",
        "1\n1 1\nnan 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n0 inf 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n0 0 1e999\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n0 0 -1e309\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n0x10 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n0,5 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n1e 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n. 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1\n--1 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1 1 w\n0 0 0 1\n1 0 0 0\n0 1 0 1\n1 1 1 1\n",
        "1\n1 1 w\n0 0 0 1\n1 0 0 -2\n0 1 0 1\n1 1 1 1\n",
        "1\n1 1 w\n0 0 0 1\n1 0 0 nan\n0 1 0 1\n1 1 1 1\n",
        "1\n1 1 w\n0 0 0 1\n1 0 0\n0 1 0 1\n1 1 1 1\n",
        "1\n1 1 x\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n",
        "1\n1.5 1\n",
        "1.0\n1 1\n",
        "1\n1 1\n\x80\xff 0 0\n",
    };
    char nul_text[] = "1\n1 1\n0 0 0\n1 0\0 0\n0 1 0\n1 1 1\n";
    char long_num[600];
    memcpy(long_num, "1\n0 0\n", 6);
    memset(long_num + 6, '1', 500);
    memcpy(long_num + 506, " 0 0\n", 6);
    for (size_t k = 0; k < sizeof texts / sizeof texts[0]; k++) {
        BAD("bs_surface_read_bpt", "truncated or hostile text", BS_ERR_PARSE,
            bs_surface_read_bpt(texts[k], strlen(texts[k]), &perr, &hs));
        NULLED(hs);
        CHECKF(perr.line >= 1 && perr.column >= 1 && memchr(perr.message, '\0', sizeof perr.message) != NULL,
               "text %zu: no error position", k);
    }
    BAD("bs_surface_read_bpt", "truncated or hostile text", BS_ERR_PARSE,
        bs_surface_read_bpt(nul_text, sizeof nul_text - 1, &perr, &hs));
    BAD("bs_surface_read_bpt", "truncated or hostile text", BS_ERR_PARSE,
        bs_surface_read_bpt(long_num, strlen(long_num), NULL, &hs));
    /* every prefix of a valid rational file is truncated: parse error, never a crash */
    const char *good = "2\n1 1 w\n0 0 0 1\n1 0 0 2\n0 1 0 0.5\n1 1 1 1\n0 0\n3 4 5\n";
    size_t glen = strlen(good);
    for (size_t len = 0; len + 1 < glen; len++) {
        int cut_in_number = len > 0 && good[len - 1] != '\n' && good[len - 1] != ' ' && good[len] != ' ' &&
                            good[len] != '\n';
        if (cut_in_number)
            continue; /* "1" of "12" is a valid number: only cuts between tokens are errors for sure */
        BAD("bs_surface_read_bpt", "truncated or hostile text", BS_ERR_PARSE, bs_surface_read_bpt(good, len, &perr, &hs));
    }
    reset();
    CHECK_STATUS(bs_surface_read_bpt(good, glen, NULL, &hs), BS_OK);
    CHECK(bs_surface_count(hs) == 2);
    bs_surface_destroy(hs);
    BAD("bs_surface_read_bpt", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_read_bpt(good, glen, NULL, NULL));
    BAD("bs_surface_read_bpt", "NULL views", BS_ERR_INVALID_ARG, bs_surface_read_bpt(NULL, 5, NULL, &hs));
    NULLED(hs);
    BAD("bs_surface_read_bpt", "count too small", BS_ERR_PARSE, bs_surface_read_bpt(NULL, 0, NULL, &hs));
    BAD("bs_surface_read_bpt_file", "NULL views", BS_ERR_INVALID_ARG, bs_surface_read_bpt_file(NULL, NULL, &hs));
    BAD("bs_surface_read_bpt_file", "NULL handle", BS_ERR_INVALID_ARG, bs_surface_read_bpt_file("x", NULL, NULL));
    BAD("bs_surface_read_bpt_file", "I/O failure", BS_ERR_IO,
        bs_surface_read_bpt_file("/nonexistent-directory/x.bpt", &perr, &hs));
    NULLED(hs);
    BAD("bs_surface_read_bpt_file", "I/O failure", BS_ERR_IO, bs_surface_read_bpt_file("/", &perr, &hs));
}

/* The bad arguments of a text reader (good: a text it reads) and of its file twin. */
typedef bs_status (*text_reader)(const char *, size_t, bs_parse_error *, bs_surface **);
typedef bs_status (*file_reader)(const char *, bs_parse_error *, bs_surface **);
static void reader_rows(const char *name, text_reader r, const char *file_name, file_reader rf, const char *good)
{
    BAD(name, "NULL handle", BS_ERR_INVALID_ARG, r(good, strlen(good), NULL, NULL));
    BAD(name, "NULL views", BS_ERR_INVALID_ARG, r(NULL, 5, NULL, &hs));
    NULLED(hs);
    BAD(file_name, "NULL views", BS_ERR_INVALID_ARG, rf(NULL, NULL, &hs));
    BAD(file_name, "NULL handle", BS_ERR_INVALID_ARG, rf("x", NULL, NULL));
    BAD(file_name, "I/O failure", BS_ERR_IO, rf("/nonexistent-directory/x", &perr, &hs));
    NULLED(hs);
    CHECK(perr.line == 0 && perr.column == 0);
    BAD(file_name, "I/O failure", BS_ERR_IO, rf("/", &perr, &hs));
    NULLED(hs);
}

/* Hostile OBJ and IGES texts: each one fails with its status and a position, no surface; the OBJ
 * writer's bad arguments. */
static void test_hostile_free_form(void)
{
    static const char *const obj[] = {
        "v 0 0\n",
        "v 0 nan 0\n",
        "v 0 0,5 0\n",
        "v 0 1e999 0\n",
        "7 0 0\n",
        "deg 65 1\n",
        "deg 184467440737095516170 1\n",
        "cstype nurbs\n",
        "end\n",
        "v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 2\nend\n",
        "v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 -2\nend\n",
        "v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1\nend\n",
        "v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\n",
        "v 0 0 0 0\ncstype rat bezier\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n",
        "v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1 1\nparm v 1 1 0 0\nend\n",
        "v 0 0 0\ncstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nparm u 0 0 1 1 1\nparm v 0 0 1 1\nend\n",
        "v 0 0 0\nv 1 0\0 0\n",
    };
    for (size_t k = 0; k < sizeof obj / sizeof obj[0]; k++) {
        size_t len = strlen(obj[k]) + (k + 1 == sizeof obj / sizeof obj[0] ? 5 : 0);
        BAD("bs_surface_read_obj", "truncated or hostile text", BS_ERR_PARSE, bs_surface_read_obj(obj[k], len, &perr, &hs));
        NULLED(hs);
        CHECKF(perr.line >= 1 && perr.column >= 1, "OBJ text %zu: no error position", k);
    }
    BAD("bs_surface_read_obj", "unsupported curve type", BS_ERR_UNSUPPORTED,
        bs_surface_read_obj("v 0 0 0\ncstype taylor\ndeg 1 1\nsurf 0 1 0 1 1 1 1 1\nend\n", 48, &perr, &hs));
    CHECK(perr.line == 4 && perr.column == 1);
    reader_rows("bs_surface_read_obj", bs_surface_read_obj, "bs_surface_read_obj_file", bs_surface_read_obj_file,
                "v 0 0 0\n");
    writer_rows("bs_surface_write_obj", bs_surface_write_obj, "bs_surface_write_obj_file", bs_surface_write_obj_file);

    /* IGES: a valid file (S, G, D, P, T) spoiled record by record */
    static const char good[] =
        "                                                                        S0000001\n"
        ",,;                                                                     G0000001\n"
        "     128       1       0       0       0       0       0       000000000D0000001\n"
        "     128       0       0       2       0                                D0000002\n"
        "128,1,1,1,1,0,0,1,0,0,0,0,1,1,0,0,1,1,1,1,1,1,0,0,0,1,0,0,0,1,0,       1P0000001\n"
        "1,1,1,0,1,0,1;                                                         1P0000002\n"
        "S0000001G0000001D0000002P0000002                                        T0000001\n";
    char t[sizeof good];
    memcpy(t, good, sizeof good);
    reset();
    CHECK_STATUS(bs_surface_read_iges(t, sizeof t - 1, &perr, &hs), BS_OK);
    CHECK(bs_surface_count(hs) == 1);
    bs_surface_destroy(hs);
    static const struct { size_t at; const char *with; } spoil[] = {
        {0, ""}, {72, "C"}, {81 + 72, "X"}, {81 + 2, "H"}, {2 * 81 + 15, "7"}, {3 * 81 + 31, "9"},
        {2 * 81 + 55, "4"}, {2 * 81 + 55, "1"}, {3 * 81 + 38, "10"}, {4 * 81, "126"}, {4 * 81 + 4, "0"},
        {4 * 81 + 8, "99"}, {4 * 81 + 12, "3"}, {4 * 81 + 24, "-"}, {4 * 81 + 36, "0"}, {4 * 81 + 22, "x"},
        {5 * 81 + 13, " "}, {5 * 81 + 6, "9"}, {4 * 81 + 38, "0"}, {6 * 81 - 1, "\n\n"}, {6 * 81, "x"},
    };
    for (size_t k = 0; k < sizeof spoil / sizeof spoil[0]; k++) {
        char u[sizeof good + 4];
        memcpy(u, t, sizeof t);
        size_t len = sizeof t - 1;
        if (k == 0)
            len = 0;
        else if (k == sizeof spoil / sizeof spoil[0] - 1)
            len = 6 * 81; /* no T section */
        else
            memcpy(u + spoil[k].at, spoil[k].with, strlen(spoil[k].with));
        BAD("bs_surface_read_iges", "truncated or hostile text", BS_ERR_PARSE, bs_surface_read_iges(u, len, &perr, &hs));
        NULLED(hs);
        CHECKF(perr.line >= 1 && perr.column >= 1, "IGES spoil %zu: no error position", k);
    }
    reader_rows("bs_surface_read_iges", bs_surface_read_iges, "bs_surface_read_iges_file", bs_surface_read_iges_file,
                good);
}

/* Models: the readers' argument rules, and the evaluators of a model against every bad view. */
typedef bs_status (*model_text_reader)(const char *, size_t, bs_parse_error *, bs_model **);
typedef bs_status (*model_file_reader)(const char *, bs_parse_error *, bs_model **);

static void model_reader_rows(const char *name, model_text_reader r, const char *file_name, model_file_reader rf)
{
    bs_model *m = (bs_model *)(void *)HSENT;
    BAD(name, "NULL handle", BS_ERR_INVALID_ARG, r("x", 1, NULL, NULL));
    BAD(name, "NULL views", BS_ERR_INVALID_ARG, r(NULL, 5, NULL, &m));
    NULLED(m);
    m = (bs_model *)(void *)HSENT;
    BAD(name, "empty text", BS_ERR_PARSE, r("", 0, &perr, &m));
    NULLED(m);
    m = (bs_model *)(void *)HSENT;
    BAD(file_name, "NULL views", BS_ERR_INVALID_ARG, rf(NULL, NULL, &m));
    NULLED(m);
    BAD(file_name, "NULL handle", BS_ERR_INVALID_ARG, rf("x", NULL, NULL));
    m = (bs_model *)(void *)HSENT;
    BAD(file_name, "I/O failure", BS_ERR_IO, rf("/nonexistent-directory/x", &perr, &m));
    NULLED(m);
    CHECK(perr.line == 0 && perr.column == 0);
    m = (bs_model *)(void *)HSENT;
    BAD(file_name, "I/O failure", BS_ERR_IO, rf("/", &perr, &m));
    NULLED(m);
}

static void test_models(void)
{
    model_reader_rows("bs_model_read_step", bs_model_read_step, "bs_model_read_step_file", bs_model_read_step_file);
    model_reader_rows("bs_model_read_iges", bs_model_read_iges, "bs_model_read_iges_file", bs_model_read_iges_file);
    model_reader_rows("bs_model_read_obj", bs_model_read_obj, "bs_model_read_obj_file", bs_model_read_obj_file);
    bs_model *m = (bs_model *)(void *)HSENT;
    BAD("bs_model_from_surface", "NULL handle", BS_ERR_INVALID_ARG, bs_model_from_surface(NULL, &m));
    NULLED(m);
    BAD("bs_model_from_surface", "dimension out of range", BS_ERR_DIMENSION, bs_model_from_surface(S2, &m));
    NULLED(m);
    CHECK_STATUS(bs_model_from_surface(S3, &m), BS_OK);
    uint32_t faces[N] = {0, 1, 0, 1}, bad_faces[N] = {0, 1, 2, 0};
    bs_cview u = {ugood, N, 0}, v = {vgood, N, 0};
    size_t size = 0;
    BAD("bs_model_face_eval", "NULL handle", BS_ERR_INVALID_ARG, bs_model_face_eval(NULL, N, faces, &u, &v, ov[0], ov[1], kbuf + SLACK));
    BAD("bs_model_face_eval", "id out of range", BS_ERR_INVALID_ARG, bs_model_face_eval(m, N, bad_faces, &u, &v, ov[0], ov[1], kbuf + SLACK));
    BAD("bs_model_face_eval", "NULL views", BS_ERR_INVALID_ARG, bs_model_face_eval(m, N, NULL, &u, &v, ov[0], ov[1], kbuf + SLACK));
    BAD("bs_model_face_to_patch", "id out of range", BS_ERR_INVALID_ARG, bs_model_face_to_patch(m, N, bad_faces, &u, &v, NULL, ov[0]));
    BAD("bs_model_classify", "NULL views", BS_ERR_INVALID_ARG, bs_model_classify(m, N, faces, &u, &v, 0.0, NULL));
    BAD("bs_model_classify", "NaN tolerance", BS_ERR_DOMAIN, bs_model_classify(m, N, faces, &u, &v, NAN, kbuf + SLACK));
    BAD("bs_model_classify", "negative tolerance", BS_ERR_DOMAIN, bs_model_classify(m, N, faces, &u, &v, -1.0, kbuf + SLACK));
    for (int b = 0; b < N_BAD_IN; b++) {
        BAD("bs_model_face_eval", bad_in[b].cls, bad_in[b].st, bs_model_face_eval(m, N, faces, &bad_in[b].v, &v, ov[0], ov[1], kbuf + SLACK));
        BAD("bs_model_face_eval", bad_in[b].cls, bad_in[b].st, bs_model_face_eval(m, N, faces, &u, &bad_in[b].v, ov[0], ov[1], kbuf + SLACK));
        BAD("bs_model_face_to_patch", bad_in[b].cls, bad_in[b].st, bs_model_face_to_patch(m, N, faces, &bad_in[b].v, &v, NULL, ov[0]));
        BAD("bs_model_classify", bad_in[b].cls, bad_in[b].st, bs_model_classify(m, N, faces, &u, &bad_in[b].v, 0.0, kbuf + SLACK));
    }
    for (int how = 0; how < N_SPOIL; how++)
        for (int c = 0; c < 3; c++) {
            BAD_SPOILED("bs_model_face_eval", how, spoil_st[how], bs_model_face_eval(m, N, faces, &u, &v, sp(0, c, how), ov[1], kbuf + SLACK));
            BAD_SPOILED("bs_model_face_eval", how, spoil_st[how], bs_model_face_eval(m, N, faces, &u, &v, ov[0], sp(1, c, how), kbuf + SLACK));
            if (c < 2)
                BAD_SPOILED("bs_model_face_to_patch", how, spoil_st[how], bs_model_face_to_patch(m, N, faces, &u, &v, NULL, sp(0, c, how)));
        }
    BAD("bs_model_write_obj", "NULL handle", BS_ERR_INVALID_ARG, bs_model_write_obj(NULL, tbuf, sizeof tbuf, &size));
    BAD("bs_model_write_obj", "NULL views", BS_ERR_INVALID_ARG, bs_model_write_obj(m, tbuf, sizeof tbuf, NULL));
    BAD("bs_model_write_obj", "count too small", BS_ERR_SIZE, bs_model_write_obj(m, tbuf, 8, &size));
    BAD("bs_model_write_obj_file", "NULL handle", BS_ERR_INVALID_ARG, bs_model_write_obj_file(NULL, "x.obj"));
    BAD("bs_model_write_obj_file", "NULL views", BS_ERR_INVALID_ARG, bs_model_write_obj_file(m, NULL));
    BAD("bs_model_write_obj_file", "I/O failure", BS_ERR_IO, bs_model_write_obj_file(m, "/nonexistent-directory/x.obj"));
    bs_face_info fi;
    fi.size = 4;
    BAD("bs_model_face_info", "struct size too small", BS_ERR_INVALID_ARG, bs_model_face_info(m, 0, &fi));
    fi.size = sizeof fi;
    BAD("bs_model_face_info", "id out of range", BS_ERR_DOMAIN, bs_model_face_info(m, 2, &fi));
    bs_model_destroy(m);
}

int main(void)
{
    setup();
    make_bad_inputs();
    test_evaluators();
    test_nonfinite_parameters();
    test_create_and_accessors();
    test_operations();
    test_constructions();
    test_surfaces();
    test_hostile_bpt();
    test_hostile_free_form();
    test_meshes();
    test_models();
    bs_patch_destroy(P3);
    bs_patch_destroy(R3);
    bs_patch_destroy(P2);
    bs_surface_destroy(S3);
    bs_surface_destroy(S2);
    printf("bad-input matrix: %d public functions x %d input classes, %d cases\n", n_fn, n_cls, n_cases);
    return bs_test_exit("test_bad_input");
}
