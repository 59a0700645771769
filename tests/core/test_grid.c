/* bs_patch_eval_grid: bit-identical to the scattered evaluators for every output and every
 * combination of outputs taken (each has its own path), across the column-pass boundary, with NaN
 * parameters, negative and interleaved strides. */
#include "eval_util.h"

#ifndef BS_DATA_DIR
#define BS_DATA_DIR "data"
#endif

/* Evaluate the grid both ways and compare bits. */
static void compare(const bs_patch *p, size_t nu, const double *u, size_t nv, const double *v)
{
    size_t dim = bs_patch_dim(p), tot = nu * nv;
    int normals = dim == 3;
    double *g = malloc(4 * BS_MAX_DIM * tot * sizeof(double)), *s = malloc(4 * BS_MAX_DIM * tot * sizeof(double));
    unsigned char *gk = malloc(tot), *sk = malloc(tot);
    double *su = malloc(tot * sizeof(double)), *sv = malloc(tot * sizeof(double));
    for (size_t a = 0; a < nu; a++)
        for (size_t b = 0; b < nv; b++) {
            su[a * nv + b] = u[a];
            sv[a * nv + b] = v[b];
        }
    bs_view gv[4][BS_MAX_DIM], sview[4][BS_MAX_DIM];
    for (int d = 0; d < 4; d++) {
        views_of(g + (size_t)d * BS_MAX_DIM * tot, dim, tot, gv[d]);
        views_of(s + (size_t)d * BS_MAX_DIM * tot, dim, tot, sview[d]);
    }
    bs_cview cu = cview_of(u, nu), cv = cview_of(v, nv), csu = cview_of(su, tot), csv = cview_of(sv, tot);
    CHECK_STATUS(bs_patch_eval_grid(p, nu, &cu, nv, &cv, gv[0], gv[1], gv[2], normals ? gv[3] : NULL,
                                    normals ? gk : NULL),
                 BS_OK);
    CHECK_STATUS(bs_patch_eval(p, tot, &csu, &csv, sview[0], sview[1], sview[2]), BS_OK);
    int same = 1;
    for (int d = 0; d < 3; d++)
        for (size_t c = 0; c < dim; c++)
            same &= memcmp(gv[d][c].data, sview[d][c].data, tot * sizeof(double)) == 0;
    CHECKF(same, "grid %zu x %zu differs from scattered", nu, nv);
    if (normals) {
        CHECK_STATUS(bs_patch_eval_normal(p, tot, &csu, &csv, NULL, sview[3], sk), BS_OK);
        same = memcmp(gk, sk, tot) == 0;
        for (size_t c = 0; c < 3; c++)
            same &= memcmp(gv[3][c].data, sview[3][c].data, tot * sizeof(double)) == 0;
        CHECKF(same, "grid normals %zu x %zu differ from scattered", nu, nv);
        /* positions and normals without derivatives (the fused cubic-row path) are the same bits */
        CHECK_STATUS(bs_patch_eval_grid(p, nu, &cu, nv, &cv, gv[1], NULL, NULL, gv[2], gk), BS_OK);
        same = memcmp(gk, sk, tot) == 0;
        for (size_t c = 0; c < 3; c++)
            same &= memcmp(gv[1][c].data, gv[0][c].data, tot * sizeof(double)) == 0 &&
                    memcmp(gv[2][c].data, sview[3][c].data, tot * sizeof(double)) == 0;
        CHECKF(same, "grid positions + normals %zu x %zu differ from scattered", nu, nv);
        /* positions alone (no derivative work) are the same bits too */
        CHECK_STATUS(bs_patch_eval_grid(p, nu, &cu, nv, &cv, sview[0], NULL, NULL, NULL, NULL), BS_OK);
        same = 1;
        for (size_t c = 0; c < 3; c++)
            same &= memcmp(gv[0][c].data, sview[0][c].data, tot * sizeof(double)) == 0;
        CHECK(same);
        /* positions and first partials without normals (their own path) are the same bits */
        CHECK_STATUS(bs_patch_eval_grid(p, nu, &cu, nv, &cv, gv[0], gv[1], gv[2], NULL, NULL), BS_OK);
        CHECK_STATUS(bs_patch_eval(p, tot, &csu, &csv, sview[0], sview[1], sview[2]), BS_OK);
        same = 1;
        for (int d = 0; d < 3; d++)
            for (size_t c = 0; c < 3; c++)
                same &= memcmp(gv[d][c].data, sview[d][c].data, tot * sizeof(double)) == 0;
        CHECKF(same, "grid positions + S_u + S_v %zu x %zu differ from scattered", nu, nv);
    }
    free(g);
    free(s);
    free(gk);
    free(sk);
    free(su);
    free(sv);
}

static void test_random_grids(void)
{
    unsigned long long rng = 700;
    size_t sizes[][2] = {{1, 1}, {3, 5}, {7, 1}, {1, 9}, {4, 255}, {3, 256}, {2, 257}, {5, 600}, {33, 17}};
    for (int trial = 0; trial < 18; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 8), n = (size_t)(bs_test_rand_u64(&rng) % 8);
        if (trial == 5) {
            m = 64;
            n = 41;
        }
        size_t dim = trial % 3 == 0 ? 2 : 3;
        tnet t = tnet_random(&rng, m, n, dim, trial % 2, 0.5, 2.0);
        bs_patch *p = tnet_patch(&t);
        size_t nu = sizes[trial % 9][0], nv = sizes[trial % 9][1];
        double *u = malloc(nu * sizeof(double)), *v = malloc(nv * sizeof(double));
        grid_params(&rng, nu, u, nv, v);
        if (nv > 3)
            v[2] = NAN;
        if (nu > 2)
            u[1] = -INFINITY;
        compare(p, nu, u, nv, v);
        free(u);
        free(v);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Teapot patches: including the collapsed edges, where limit normals are taken. */
static void test_teapot_grid(void)
{
    bs_patch *patches[32];
    size_t np = teapot_patches(BS_DATA_DIR "/teapot.bpt", patches);
    CHECK(np == 32);
    double u[11], v[11];
    for (int k = 0; k <= 10; k++)
        u[k] = v[k] = k / 10.0;
    for (size_t k = 0; k < np; k++) {
        compare(patches[k], 11, u, 11, v);
        bs_patch_destroy(patches[k]);
    }
}

/* Polynomial 3-D nets of degree (m, 3), finite parameters: positions + normals take the fused
 * cubic-row path, across the column-pass boundary. */
static void test_cubic_rows(void)
{
    unsigned long long rng = 702;
    for (size_t m = 1; m <= 6; m++) {
        tnet t = tnet_random(&rng, m, 3, 3, 0, 1.0, 1.0);
        bs_patch *p = tnet_patch(&t);
        size_t nu = 5, nv = 300;
        double u[5], v[300];
        grid_params(&rng, nu, u, nv, v);
        compare(p, nu, u, nv, v);
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Negative and interleaved output strides give the same bits as packed ones. */
static void test_strides(void)
{
    unsigned long long rng = 701;
    tnet t = tnet_random(&rng, 3, 4, 3, 1, 0.5, 2.0);
    bs_patch *p = tnet_patch(&t);
    enum { NU = 6, NV = 9, T = NU * NV };
    double u[NU], v[NV], ur[NU];
    for (int a = 0; a < NU; a++)
        u[a] = bs_test_rand(&rng, 0, 1);
    for (int b = 0; b < NV; b++)
        v[b] = bs_test_rand(&rng, 0, 1);
    for (int a = 0; a < NU; a++)
        ur[NU - 1 - a] = u[a];
    double packed[3 * T], inter[3 * T + 1];
    bs_view vp[3], vi[3];
    views_of(packed, 3, T, vp);
    for (int c = 0; c < 3; c++) {
        vi[c].data = inter + 1 + (size_t)(T - 1) * 3 + (size_t)c; /* element 0 last: stride -24 */
        vi[c].count = T;
        vi[c].stride = -24;
    }
    bs_cview cu = cview_of(u, NU), cv = cview_of(v, NV), cur = {ur + NU - 1, NU, -8};
    CHECK_STATUS(bs_patch_eval_grid(p, NU, &cu, NV, &cv, NULL, NULL, vp, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_patch_eval_grid(p, NU, &cur, NV, &cv, NULL, NULL, vi, NULL, NULL), BS_OK);
    int same = 1;
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < T; k++)
            same &= memcmp(&packed[c * T + k], &inter[1 + (size_t)(T - 1 - k) * 3 + (size_t)c], 8) == 0;
    CHECK(same);
    bs_patch_destroy(p);
    tnet_free(&t);
}

int main(void)
{
    test_random_grids();
    test_teapot_grid();
    test_cubic_rows();
    test_strides();
    return bs_test_exit("test_grid");
}
