/* Every error path of the four evaluators: the documented status, in the documented order, and
 * no output touched (outputs are sentinel-filled and checked afterwards). */
#include "eval_util.h"

#include <stdint.h>

#define SENT 12345.0
#define KSENT 0xAB
enum { N = 4 };

static double out[4][3][N + 2]; /* [output][coord][element]; one spare at each end */
static unsigned char kinds[N + 2];
static bs_view vw[4][3];

static void fill(void)
{
    for (int d = 0; d < 4; d++)
        for (int c = 0; c < 3; c++) {
            for (int k = 0; k < N + 2; k++)
                out[d][c][k] = SENT;
            vw[d][c].data = &out[d][c][1];
            vw[d][c].count = N;
            vw[d][c].stride = 0;
        }
    memset(kinds, KSENT, sizeof kinds);
}

static int untouched(void)
{
    for (int d = 0; d < 4; d++)
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < N + 2; k++)
                if (out[d][c][k] != SENT)
                    return 0;
    for (int k = 0; k < N + 2; k++)
        if (kinds[k] != KSENT)
            return 0;
    return 1;
}

#define EXPECT(call, status)                                                             \
    do {                                                                                 \
        CHECK_STATUS(call, status);                                                      \
        CHECKF(untouched(), "outputs written by a failing %s", #call);                   \
        fill();                                                                          \
    } while (0)

static double ubuf[N + 1], vbuf[N];

/* Out of memory: with glibc, and without a sanitizer that owns malloc, the test replaces malloc
 * (the library's calls resolve to it) and makes the next allocation fail. */
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define TEST_NO_MEMORY 1
extern void *__libc_malloc(size_t n);
static int fail_next_malloc;
void *malloc(size_t n)
{
    if (fail_next_malloc) {
        fail_next_malloc = 0;
        return NULL;
    }
    return __libc_malloc(n);
}
#endif

/* One bad input view at a time (u or v), in each of the ways a view can be bad. */
static void bad_cviews(const bs_patch *p, const bs_patch *p2)
{
    bs_cview good = {vbuf, N, 0};
    bs_cview bad[6] = {
        {NULL, N, 0},                                            /* NULL data */
        {(const double *)(const void *)((const char *)ubuf + 4), N, 0}, /* misaligned data */
        {ubuf, N, 12},                                           /* stride not a multiple of 8 */
        {ubuf, N - 1, 0},                                        /* short */
        {ubuf, SIZE_MAX, PTRDIFF_MAX / 2 + 1},                   /* extent overflows */
        {ubuf, N, 4},                                            /* stride 4 */
    };
    bs_status want[6] = {BS_ERR_INVALID_ARG, BS_ERR_INVALID_ARG, BS_ERR_INVALID_ARG, BS_ERR_SIZE, BS_ERR_INVALID_ARG,
                         BS_ERR_INVALID_ARG};
    bad[4].stride = (PTRDIFF_MAX / 16) * 8; /* aligned, but (N-1)*stride overflows */
    want[4] = BS_ERR_SIZE;
    for (int k = 0; k < 6; k++) {
        for (int which = 0; which < 2; which++) {
            const bs_cview *u = which ? &good : &bad[k], *v = which ? &bad[k] : &good;
            EXPECT(bs_patch_eval(p, N, u, v, vw[0], vw[1], vw[2]), want[k]);
            EXPECT(bs_patch_eval_deriv(p, 1, 1, N, u, v, vw[0]), want[k]);
            EXPECT(bs_patch_eval_normal(p, N, u, v, vw[0], vw[3], kinds), want[k]);
            /* the grid reads only 2 of the N parameters: a short view must hold fewer than 2 */
            bs_cview shortv = {ubuf, 1, 0};
            if (k == 3) {
                u = which ? &good : &shortv;
                v = which ? &shortv : &good;
            }
            /* an extent overflow needs N elements: a 4 x 1 or 1 x 4 grid */
            size_t nu = k == 4 ? (which ? 1 : N) : 2, nv = k == 4 ? (which ? N : 1) : 2;
            EXPECT(bs_patch_eval_grid(p, nu, u, nv, v, vw[0], vw[1], vw[2], vw[3], kinds), want[k]);
            EXPECT(bs_patch_eval_grid(p2, nu, u, nv, v, vw[0], vw[1], vw[2], NULL, NULL), want[k]);
        }
    }
    EXPECT(bs_patch_eval(p, N, NULL, &good, vw[0], NULL, NULL), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval(p, N, &good, NULL, vw[0], NULL, NULL), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_deriv(p, 0, 0, N, NULL, &good, vw[0]), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_normal(p, N, &good, NULL, vw[0], NULL, NULL), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_grid(p, 2, NULL, 2, &good, vw[0], NULL, NULL, NULL, NULL), BS_ERR_INVALID_ARG);
}

/* Bad output views: each output in turn, with the other outputs valid (still untouched). */
static void bad_outputs(const bs_patch *p)
{
    bs_cview cu = {ubuf, N, 0}, cv = {vbuf, N, 0};
    for (int k = 0; k < 5; k++)
        for (int d = 0; d < 4; d++)
            for (int c = 0; c < 3; c++) {
                bs_status want = BS_ERR_INVALID_ARG;
                if (k == 0)
                    vw[d][c].data = NULL;
                else if (k == 1)
                    vw[d][c].data = (double *)(void *)((char *)vw[d][c].data + 2);
                else if (k == 2)
                    vw[d][c].stride = -20;
                else if (k == 3) {
                    vw[d][c].count = N - 1;
                    want = BS_ERR_SIZE;
                } else {
                    vw[d][c].stride = (PTRDIFF_MAX / 16) * 8;
                    want = BS_ERR_SIZE;
                }
                bs_view save = vw[d][c];
                if (d < 3) {
                    EXPECT(bs_patch_eval(p, N, &cu, &cv, d == 0 ? vw[0] : NULL, d == 1 ? vw[1] : vw[0],
                                         d == 2 ? vw[2] : NULL),
                           want);
                    vw[d][c] = save;
                    EXPECT(bs_patch_eval_deriv(p, 2, 0, N, &cu, &cv, vw[d]), want);
                    vw[d][c] = save;
                }
                EXPECT(bs_patch_eval_normal(p, N, &cu, &cv, d == 0 ? vw[0] : vw[1], vw[d == 0 ? 1 : d], kinds),
                       want);
                vw[d][c] = save;
                EXPECT(bs_patch_eval_grid(p, 2, &cu, 2, &cv, vw[0], vw[1], vw[2], vw[3], kinds), want);
            }
    EXPECT(bs_patch_eval_deriv(p, 0, 0, N, &cu, &cv, NULL), BS_ERR_INVALID_ARG);
    /* the grid needs nu*nv elements: 2 x 3 = 6 > N */
    EXPECT(bs_patch_eval_grid(p, 2, &cu, 3, &cv, vw[0], NULL, NULL, NULL, NULL), BS_ERR_SIZE);
    EXPECT(bs_patch_eval_grid(p, 2, &cu, 3, &cv, NULL, NULL, NULL, vw[3], NULL), BS_ERR_SIZE);
    /* nu*nv overflows size_t */
    bs_cview huge = {ubuf, SIZE_MAX, 0};
    size_t big = (size_t)1 << (sizeof(size_t) * 4);
    EXPECT(bs_patch_eval_grid(p, big, &huge, big, &huge, vw[0], NULL, NULL, NULL, NULL), BS_ERR_SIZE);
    /* a scattered count whose byte extent overflows ptrdiff_t */
    size_t nbig = (size_t)PTRDIFF_MAX / 4;
    EXPECT(bs_patch_eval(p, nbig, &huge, &huge, vw[0], NULL, NULL), BS_ERR_SIZE);
}

/* The order of the checks: p, then orders, then dimension, then views. */
static void check_order(const bs_patch *p3, const bs_patch *p2)
{
    bs_cview cu = {ubuf, N, 0}, bad = {NULL, 0, 0};
    EXPECT(bs_patch_eval(NULL, N, &bad, &bad, vw[0], vw[1], vw[2]), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_deriv(NULL, 99, 0, N, &bad, &bad, NULL), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_normal(NULL, N, &bad, &bad, vw[0], vw[3], kinds), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_grid(NULL, 2, &bad, 2, &bad, vw[0], vw[1], vw[2], vw[3], kinds), BS_ERR_INVALID_ARG);
    EXPECT(bs_patch_eval_deriv(p3, BS_MAX_DEGREE + 1, 0, N, &bad, &bad, NULL), BS_ERR_DEGREE);
    EXPECT(bs_patch_eval_deriv(p3, 0, 1000, N, &cu, &cu, vw[0]), BS_ERR_DEGREE);
    EXPECT(bs_patch_eval_deriv(p3, BS_MAX_DEGREE + 1, 0, 0, &cu, &cu, vw[0]), BS_ERR_DEGREE);
    EXPECT(bs_patch_eval_normal(p2, N, &bad, &bad, vw[0], vw[3], kinds), BS_ERR_DIMENSION);
    EXPECT(bs_patch_eval_normal(p2, 0, &cu, &cu, NULL, NULL, NULL), BS_ERR_DIMENSION);
    EXPECT(bs_patch_eval_grid(p2, 2, &bad, 2, &bad, vw[0], NULL, NULL, vw[3], NULL), BS_ERR_DIMENSION);
    EXPECT(bs_patch_eval_grid(p2, 2, &cu, 2, &cu, NULL, NULL, NULL, NULL, kinds), BS_ERR_DIMENSION);
    /* a 2-D patch without normals is fine */
    CHECK_STATUS(bs_patch_eval_grid(p2, 2, &cu, 2, &cu, vw[0], NULL, NULL, NULL, NULL), BS_OK);
    fill();
}

/* n = 0 succeeds without reading the views; orders beyond the degree are fine. */
static void zero_counts(const bs_patch *p)
{
    bs_cview bad = {NULL, 0, 3};
    EXPECT(bs_patch_eval(p, 0, &bad, NULL, vw[0], vw[1], vw[2]), BS_OK);
    EXPECT(bs_patch_eval_deriv(p, 3, 3, 0, NULL, NULL, NULL), BS_OK);
    EXPECT(bs_patch_eval_normal(p, 0, NULL, &bad, vw[0], vw[3], kinds), BS_OK);
    EXPECT(bs_patch_eval_grid(p, 0, &bad, 5, NULL, vw[0], vw[1], vw[2], vw[3], kinds), BS_OK);
    EXPECT(bs_patch_eval_grid(p, 5, NULL, 0, &bad, vw[0], vw[1], vw[2], vw[3], kinds), BS_OK);
    bs_cview cu = {ubuf, N, 0};
    CHECK_STATUS(bs_patch_eval_deriv(p, BS_MAX_DEGREE, BS_MAX_DEGREE, N, &cu, &cu, vw[0]), BS_OK);
    CHECK(out[0][0][1] == 0.0 && out[0][2][N] == 0.0 && out[0][0][0] == SENT && out[0][0][N + 1] == SENT);
    fill();
}

static void no_memory(const bs_patch *p3, const bs_patch *p2)
{
#ifdef TEST_NO_MEMORY
    bs_cview cu = {ubuf, N, 0};
    fail_next_malloc = 1;
    EXPECT(bs_patch_eval_grid(p3, 2, &cu, 2, &cu, vw[0], vw[1], vw[2], vw[3], kinds), BS_ERR_NO_MEMORY);
    fail_next_malloc = 1;
    EXPECT(bs_patch_eval_deriv(p2, 2, 1, N, &cu, &cu, vw[0]), BS_ERR_NO_MEMORY);
    fail_next_malloc = 0;
    /* and the same calls succeed once memory is there */
    CHECK_STATUS(bs_patch_eval_grid(p3, 2, &cu, 2, &cu, vw[0], vw[1], vw[2], vw[3], kinds), BS_OK);
    CHECK_STATUS(bs_patch_eval_deriv(p2, 2, 1, N, &cu, &cu, vw[0]), BS_OK);
    fill();
#else
    (void)p3;
    (void)p2;
    printf("out-of-memory paths not exercised in this build\n");
#endif
}

int main(void)
{
    for (int k = 0; k <= N; k++)
        ubuf[k] = vbuf[k % N] = 0.25 * k;
    unsigned long long rng = 800;
    tnet t3 = tnet_random(&rng, 3, 2, 3, 0, 0, 0), t2 = tnet_random(&rng, 2, 2, 2, 1, 0.5, 2);
    bs_patch *p3 = tnet_patch(&t3), *p2 = tnet_patch(&t2);
    fill();
    check_order(p3, p2);
    zero_counts(p3);
    bad_cviews(p3, p2);
    bad_outputs(p3);
    no_memory(p3, p2);
    bs_patch_destroy(p3);
    bs_patch_destroy(p2);
    tnet_free(&t3);
    tnet_free(&t2);
    return bs_test_exit("test_eval_errors");
}
