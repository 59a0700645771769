/* bs_surface_eval_normal_mt(): positions, normals and kinds bit-identical to bs_surface_eval_normal()
 * on 1, 2, 3, 7 and 0 (one per CPU) threads, for points in runs of equal ids cut by the pieces of
 * 4096, degenerate corners (limit normals) and NaN/Inf parameters; every bad argument gives the
 * single-threaded function's status with nothing written. */
#include "harness.h"
#include "shapes.h"

#include <bezsurf.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const size_t thread_counts[] = {1, 2, 3, 7, 0};
#define NTHREADS (sizeof thread_counts / sizeof thread_counts[0])
#define NPT (3 * 4096 + 29)
#define SENT -7777.0
#define KSENT 0xC3

/* Positions then normals, packed coordinate by coordinate, and the kinds. */
static double ref[6 * NPT], out[6 * NPT];
static unsigned char rkind[NPT], okind[NPT];
static uint32_t ids[NPT];
static double u[NPT], v[NPT];

static void set_views(bs_view *views, double *buf)
{
    for (size_t c = 0; c < 6; c++)
        views[c] = (bs_view){buf + c * NPT, NPT, (ptrdiff_t)sizeof(double)};
}

static void fill_out(void)
{
    for (size_t k = 0; k < 6 * NPT; k++)
        out[k] = SENT;
    memset(okind, KSENT, sizeof okind);
}

static int out_untouched(void)
{
    for (size_t k = 0; k < 6 * NPT; k++)
        if (out[k] != SENT)
            return 0;
    for (size_t k = 0; k < NPT; k++)
        if (okind[k] != KSENT)
            return 0;
    return 1;
}

static void make_points(size_t np)
{
    unsigned long long seed = 23;
    for (size_t k = 0; k < NPT; k++) {
        ids[k] = (uint32_t)((k / 7) % np); /* runs of equal ids, some cut by the pieces */
        u[k] = bs_test_rand(&seed, -0.1, 1.1);
        v[k] = bs_test_rand(&seed, 0.0, 1.0);
        if (k % 11 == 0) { /* corners: degenerate on the teapot's lid and bottom */
            u[k] = (double)(k % 2);
            v[k] = (double)((k / 2) % 2);
        }
    }
    u[5] = NAN;
    v[4100] = INFINITY;
    u[NPT - 1] = -INFINITY;
}

static void identical(const bs_surface *s)
{
    bs_cview cu = {u, NPT, 0}, cv = {v, NPT, 0};
    bs_view rv[6], ov[6];
    set_views(rv, ref);
    set_views(ov, out);
    CHECK_STATUS(bs_surface_eval_normal(s, NPT, ids, &cu, &cv, rv, rv + 3, rkind), BS_OK);
    CHECK(isnan(ref[5]) && isnan(ref[3 * NPT + 4100]) && rkind[NPT - 1] == BS_NORMAL_UNDEFINED);
    int limits = 0;
    for (size_t k = 0; k < NPT; k++)
        limits += rkind[k] == BS_NORMAL_LIMIT;
    CHECKF(limits > 0, "no limit normal among the corners");
    for (size_t t = 0; t < NTHREADS; t++) {
        fill_out();
        CHECK_STATUS(bs_surface_eval_normal_mt(s, NPT, ids, &cu, &cv, ov, ov + 3, okind, thread_counts[t]), BS_OK);
        CHECKF(memcmp(out, ref, sizeof out) == 0 && memcmp(okind, rkind, sizeof okind) == 0,
               "eval_normal_mt on %zu threads differs", thread_counts[t]);
        /* one output at a time */
        fill_out();
        CHECK_STATUS(bs_surface_eval_normal_mt(s, NPT, ids, &cu, &cv, NULL, ov + 3, NULL, thread_counts[t]), BS_OK);
        CHECK(memcmp(out + 3 * NPT, ref + 3 * NPT, 3 * NPT * sizeof(double)) == 0 && out[0] == SENT &&
              okind[0] == KSENT);
        fill_out();
        CHECK_STATUS(bs_surface_eval_normal_mt(s, NPT, ids, &cu, &cv, NULL, NULL, okind, thread_counts[t]), BS_OK);
        CHECK(memcmp(okind, rkind, sizeof okind) == 0 && out[0] == SENT);
    }
    /* strided and reversed views: every other point, read backwards */
    size_t half = NPT / 2;
    bs_cview bu = {u + 2 * (half - 1), half, -2 * (ptrdiff_t)sizeof(double)};
    bs_cview bv = {v + 2 * (half - 1), half, -2 * (ptrdiff_t)sizeof(double)};
    uint32_t *bid = malloc(half * sizeof(uint32_t));
    for (size_t k = 0; k < half; k++)
        bid[k] = ids[2 * (half - 1 - k)];
    CHECK_STATUS(bs_surface_eval_normal(s, half, bid, &bu, &bv, rv, rv + 3, rkind), BS_OK);
    for (size_t t = 0; t < NTHREADS; t++) {
        fill_out();
        CHECK_STATUS(bs_surface_eval_normal_mt(s, half, bid, &bu, &bv, ov, ov + 3, okind, thread_counts[t]), BS_OK);
        int same = memcmp(okind, rkind, half) == 0;
        for (size_t c = 0; c < 6; c++)
            same &= memcmp(out + c * NPT, ref + c * NPT, half * sizeof(double)) == 0;
        CHECKF(same, "strided eval_normal_mt on %zu threads differs", thread_counts[t]);
    }
    free(bid);
}

/* The status of the single-threaded function, and the same with nothing written on 1, 3 and 7. */
#define SAME_ERROR(expected, s_, n_, ids_, u_, v_, pos_, nrm_, kind_)                                        \
    do {                                                                                                   \
        CHECK_STATUS(bs_surface_eval_normal(s_, n_, ids_, u_, v_, pos_, nrm_, kind_), expected);           \
        for (size_t t_ = 1; t_ < 8; t_ += 3) {                                                             \
            fill_out();                                                                                    \
            CHECK_STATUS(bs_surface_eval_normal_mt(s_, n_, ids_, u_, v_, pos_, nrm_, kind_, t_), expected); \
            CHECKF(out_untouched(), "a failing call on %zu threads wrote into an output", t_);             \
        }                                                                                                  \
    } while (0)

static void errors(const bs_surface *s)
{
    bs_cview cu = {u, NPT, 0}, cv = {v, NPT, 0}, short_u = {u, NPT - 1, 0}, null_u = {NULL, NPT, 0};
    bs_cview mis = {(const double *)(const void *)((const char *)u + 4), NPT - 1, 0};
    bs_view ov[6];
    set_views(ov, out);
    SAME_ERROR(BS_ERR_INVALID_ARG, NULL, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, NULL, &cu, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, NULL, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &cu, NULL, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &null_u, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT - 1, ids, &mis, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_SIZE, s, NPT, ids, &short_u, &cv, ov, ov + 3, okind);
    /* outputs: short, NULL data, misaligned stride, in the last coordinate */
    ov[5].count = NPT - 1;
    SAME_ERROR(BS_ERR_SIZE, s, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    ov[5].count = NPT;
    ov[2].data = NULL;
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    ov[2].data = out + 2 * NPT;
    ov[4].stride = 12;
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    ov[4].stride = (ptrdiff_t)sizeof(double);
    /* an id out of range in the last piece only */
    ids[NPT - 2] = (uint32_t)bs_surface_count(s);
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    ids[NPT - 2] = UINT32_MAX;
    SAME_ERROR(BS_ERR_INVALID_ARG, s, NPT, ids, &cu, &cv, ov, ov + 3, okind);
    ids[NPT - 2] = 0;
    /* n = 0: a no-op with a surface, whatever else is NULL; an error without one */
    SAME_ERROR(BS_OK, s, 0, NULL, NULL, NULL, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_INVALID_ARG, NULL, 0, ids, &cu, &cv, ov, ov + 3, okind);

    /* normals need dim 3: a plane patch of dim 2, and an empty surface */
    bs_surface *flat = shape_flat_surface(), *empty = NULL;
    CHECK_STATUS(bs_surface_create(&empty), BS_OK);
    uint32_t zeros[4] = {0, 0, 0, 0};
    SAME_ERROR(BS_ERR_DIMENSION, flat, 4, zeros, &cu, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_ERR_DIMENSION, flat, 4, zeros, &cu, &cv, NULL, NULL, NULL);
    SAME_ERROR(BS_ERR_DIMENSION, empty, 4, zeros, &cu, &cv, ov, ov + 3, okind);
    SAME_ERROR(BS_OK, empty, 0, zeros, &cu, &cv, ov, ov + 3, okind);
    bs_surface_destroy(flat);
    bs_surface_destroy(empty);
}

int main(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    make_points(bs_surface_count(s));
    identical(s);
    errors(s);
    bs_surface_destroy(s);
    return bs_test_exit("test_surface_normal_threads");
}
