/* bs_patch_eval: worked examples, reference agreement, properties of Bezier patches, and
 * independence of batch size, strides and alignment. */
#include "eval_util.h"

static const double ex1[27] = {1, 0, 2, 1, 2, 4, 1, 3, 2, 2, 1, 0, 2, 2, 2, 2, 4, 0, 4, 1, 0, 3, 3, 2, 4, 4, 2};
static const double ex2[27] = {0, 0, 4, 0, 2, 4, 0, 4, 0, 2, 0, 0, 2, 2, 4, 2, 4, 0, 4, 0, 0, 4, 2, 0, 4, 4, 8};

static void eval1(const bs_patch *p, double u, double v, double *s, double *su, double *sv)
{
    size_t dim = bs_patch_dim(p);
    bs_cview cu = cview_of(&u, 1), cv = cview_of(&v, 1);
    bs_view vs[BS_MAX_DIM], vu[BS_MAX_DIM], vv[BS_MAX_DIM];
    views_of(s, dim, 1, vs);
    views_of(su, dim, 1, vu);
    views_of(sv, dim, 1, vv);
    CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, vs, vu, vv), BS_OK);
}

static void test_worked_examples(void)
{
    bs_patch *p = NULL;
    double s[3], su[3], sv[3];
    CHECK_STATUS(bs_patch_create(2, 2, 3, ex1, NULL, &p), BS_OK);
    eval1(p, 0.5, 0.5, s, su, sv);
    CHECKF(s[0] == 17.0 / 8 && s[1] == 9.0 / 4 && s[2] == 13.0 / 8, "(%.17g %.17g %.17g)", s[0], s[1], s[2]);
    bs_patch_destroy(p);
    CHECK_STATUS(bs_patch_create(2, 2, 3, ex2, NULL, &p), BS_OK);
    eval1(p, 0.25, 0.25, s, su, sv);
    CHECKF(s[0] == 1.0 && s[1] == 1.0 && s[2] == 173.0 / 64, "(%.17g %.17g %.17g)", s[0], s[1], s[2]);
    /* the same point through a rational patch with all weights 2 */
    double w[9];
    for (int k = 0; k < 9; k++)
        w[k] = 2.0;
    bs_patch_destroy(p);
    CHECK_STATUS(bs_patch_create(2, 2, 3, ex2, w, &p), BS_OK);
    eval1(p, 0.25, 0.25, s, su, sv);
    CHECKF(s[0] == 1.0 && s[1] == 1.0 && s[2] == 173.0 / 64, "(%.17g %.17g %.17g)", s[0], s[1], s[2]);
    bs_patch_destroy(p);
}

/* Value and first derivatives against the reference, every coordinate within the bound. */
static void test_against_reference(void)
{
    unsigned long long rng = 11;
    double worst = 0.0;
    for (int trial = 0; trial < 120; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 13), n = (size_t)(bs_test_rand_u64(&rng) % 13);
        if (trial % 10 == 0) {
            m = (size_t)(bs_test_rand_u64(&rng) % 65);
            n = (size_t)(bs_test_rand_u64(&rng) % 65);
        }
        size_t dim = 1 + (size_t)(bs_test_rand_u64(&rng) % 8);
        int rational = trial % 3 == 0;
        tnet t = tnet_random(&rng, m, n, dim, rational, 0.5, 2.0);
        ref_net r = tnet_ref(&t);
        bs_patch *p = tnet_patch(&t);
        CHECK(p != NULL);
        double bnd[3] = {accuracy_bound(&t, 0, 0), accuracy_bound(&t, 1, 0), accuracy_bound(&t, 0, 1)};
        for (int k = 0; k < 6; k++) {
            double u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1);
            if (k == 0)
                u = 0.0;
            if (k == 1)
                v = 1.0;
            double s[3][BS_MAX_DIM];
            eval1(p, u, v, s[0], s[1], s[2]);
            long double e[3][BS_MAX_DIM];
            ref_deriv(&r, 0, 0, u, v, e[0]);
            ref_deriv(&r, 1, 0, u, v, e[1]);
            ref_deriv(&r, 0, 1, u, v, e[2]);
            for (int d = 0; d < 3; d++)
                for (size_t c = 0; c < dim; c++) {
                    double err = (double)fabsl((long double)s[d][c] - e[d][c]);
                    worst = fmax(worst, err / bnd[d]);
                    CHECKF(err <= bnd[d], "deg (%zu,%zu) rational %d d%d c%zu err %g bound %g", m, n,
                           rational, d, c, err, bnd[d]);
                }
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
    printf("value/first derivatives: worst error %.3g of the bound\n", worst);
}

/* Partition of unity: a net of ones gives 1 and zero derivatives. */
static void test_partition_of_unity(void)
{
    static double ones[65 * 65];
    for (size_t k = 0; k < 65 * 65; k++)
        ones[k] = 1.0;
    unsigned long long rng = 3;
    for (size_t m = 0; m <= 64; m += 8)
        for (size_t n = 0; n <= 64; n += 16) {
            bs_patch *p = NULL;
            CHECK_STATUS(bs_patch_create(m, n, 1, ones, NULL, &p), BS_OK);
            for (int k = 0; k < 5; k++) {
                double s, su, sv;
                eval1(p, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), &s, &su, &sv);
                CHECKF(fabs(s - 1.0) <= 2.0 * (double)(m + n + 1) * EPS, "deg (%zu,%zu): %.17g", m, n, s);
                CHECK(su == 0.0 && sv == 0.0);
            }
            bs_patch_destroy(p);
        }
}

/* Corners are control points (exactly for polynomial patches); edges are the boundary curves. */
static void test_corners_and_boundaries(void)
{
    unsigned long long rng = 5;
    for (int trial = 0; trial < 20; trial++) {
        size_t m = 1 + (size_t)(bs_test_rand_u64(&rng) % 9), n = (size_t)(bs_test_rand_u64(&rng) % 9);
        size_t dim = 3;
        tnet t = tnet_random(&rng, m, n, dim, trial % 2, 0.25, 4.0);
        bs_patch *p = tnet_patch(&t);
        size_t ci[4] = {0, m, 0, m}, cj[4] = {0, 0, n, n};
        for (int k = 0; k < 4; k++) {
            double s[3], su[3], sv[3];
            eval1(p, (double)(k & 1), (double)(k >> 1), s, su, sv);
            const double *P = t.ctrl + (ci[k] * (n + 1) + cj[k]) * dim;
            for (size_t c = 0; c < dim; c++) {
                if (t.w == NULL)
                    CHECK(s[c] == P[c]);
                else
                    CHECKF(fabs(s[c] - P[c]) <= 4 * EPS * fabs(P[c]), "%g vs %g", s[c], P[c]);
            }
        }
        /* boundary curve v = 0: the Bezier curve of net column j = 0, by de Casteljau */
        for (int k = 0; k < 5; k++) {
            double u = bs_test_rand(&rng, 0, 1), s[3], su[3], sv[3];
            eval1(p, u, 0.0, s, su, sv);
            for (size_t c = 0; c < dim; c++) {
                long double num[65], den[65];
                for (size_t i = 0; i <= m; i++) {
                    long double w = t.w ? t.w[i * (n + 1)] : 1.0L;
                    num[i] = w * t.ctrl[i * (n + 1) * dim + c];
                    den[i] = w;
                }
                long double e = ref_casteljau(num, m, u) / ref_casteljau(den, m, u);
                CHECKF(fabsl(s[c] - e) <= accuracy_bound(&t, 0, 0), "edge v=0: %g vs %Lg", s[c], e);
            }
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* Swapping u and v (transposing the net) gives the same surface with S_u and S_v exchanged. */
static void test_uv_symmetry(void)
{
    unsigned long long rng = 7;
    for (int trial = 0; trial < 20; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 12), n = (size_t)(bs_test_rand_u64(&rng) % 12);
        size_t dim = 2;
        tnet t = tnet_random(&rng, m, n, dim, trial % 2, 0.5, 2.0);
        tnet s = {n, m, dim, malloc((m + 1) * (n + 1) * dim * sizeof(double)), NULL};
        if (t.w)
            s.w = malloc((m + 1) * (n + 1) * sizeof(double));
        for (size_t i = 0; i <= m; i++)
            for (size_t j = 0; j <= n; j++) {
                for (size_t c = 0; c < dim; c++)
                    s.ctrl[(j * (m + 1) + i) * dim + c] = t.ctrl[(i * (n + 1) + j) * dim + c];
                if (t.w)
                    s.w[j * (m + 1) + i] = t.w[i * (n + 1) + j];
            }
        bs_patch *p = tnet_patch(&t), *q = tnet_patch(&s);
        for (int k = 0; k < 5; k++) {
            double u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1);
            double a[3][2], b[3][2];
            eval1(p, u, v, a[0], a[1], a[2]);
            eval1(q, v, u, b[0], b[1], b[2]);
            for (size_t c = 0; c < dim; c++) {
                CHECK(fabs(a[0][c] - b[0][c]) <= 2 * accuracy_bound(&t, 0, 0));
                CHECK(fabs(a[1][c] - b[2][c]) <= 2 * accuracy_bound(&t, 1, 0));
                CHECK(fabs(a[2][c] - b[1][c]) <= 2 * accuracy_bound(&t, 0, 1));
            }
        }
        bs_patch_destroy(p);
        bs_patch_destroy(q);
        tnet_free(&t);
        tnet_free(&s);
    }
}

/* de Casteljau, two-step (u then v, and v then u) and one-step (bilinear cells), in long double. */
static long double casteljau_two_step(const tnet *t, size_t c, long double u, long double v, int v_first)
{
    size_t m = t->m, n = t->n, dim = t->dim;
    long double outer[65];
    size_t no = v_first ? m : n, ni = v_first ? n : m;
    for (size_t a = 0; a <= no; a++) {
        long double b[65];
        for (size_t k = 0; k <= ni; k++) {
            size_t i = v_first ? a : k, j = v_first ? k : a;
            b[k] = t->ctrl[(i * (n + 1) + j) * dim + c];
        }
        outer[a] = ref_casteljau(b, ni, v_first ? v : u);
    }
    return ref_casteljau(outer, no, v_first ? u : v);
}

static long double casteljau_one_step(const tnet *t, size_t c, long double u, long double v)
{
    size_t m = t->m, n = t->n, dim = t->dim;
    static long double g[65][65];
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++)
            g[i][j] = t->ctrl[(i * (n + 1) + j) * dim + c];
    size_t mi = m, nj = n;
    while (mi > 0 && nj > 0) { /* bilinear steps */
        for (size_t i = 0; i < mi; i++)
            for (size_t j = 0; j < nj; j++)
                g[i][j] = (1 - u) * (1 - v) * g[i][j] + u * (1 - v) * g[i + 1][j] +
                          (1 - u) * v * g[i][j + 1] + u * v * g[i + 1][j + 1];
        mi--;
        nj--;
    }
    while (mi > 0) { /* remaining univariate steps */
        for (size_t i = 0; i < mi; i++)
            g[i][0] = (1 - u) * g[i][0] + u * g[i + 1][0];
        mi--;
    }
    while (nj > 0) {
        for (size_t j = 0; j < nj; j++)
            g[0][j] = (1 - v) * g[0][j] + v * g[0][j + 1];
        nj--;
    }
    return g[0][0];
}

static void test_casteljau_forms(void)
{
    unsigned long long rng = 9;
    for (int trial = 0; trial < 30; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 20), n = (size_t)(bs_test_rand_u64(&rng) % 20);
        tnet t = tnet_random(&rng, m, n, 3, 0, 0, 0);
        bs_patch *p = tnet_patch(&t);
        double bnd = accuracy_bound(&t, 0, 0);
        for (int k = 0; k < 4; k++) {
            double u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1), s[3], su[3], sv[3];
            eval1(p, u, v, s, su, sv);
            for (size_t c = 0; c < 3; c++) {
                long double a = casteljau_two_step(&t, c, u, v, 0), b = casteljau_two_step(&t, c, u, v, 1);
                long double o = casteljau_one_step(&t, c, u, v);
                CHECKF(fabsl(a - b) <= 1e-3 * bnd && fabsl(a - o) <= 1e-3 * bnd, "forms disagree");
                CHECKF(fabsl(s[c] - a) <= bnd, "deg (%zu,%zu): %.17g vs %.17Lg", m, n, s[c], a);
            }
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* The same points give the same bits in one batch, one at a time, through negative and
 * interleaved strides, and at another alignment. */
static void test_layout_independence(void)
{
    unsigned long long rng = 13;
    enum { N = 37 };
    for (int trial = 0; trial < 6; trial++) {
        size_t m = (size_t)(bs_test_rand_u64(&rng) % 10), n = (size_t)(bs_test_rand_u64(&rng) % 10);
        size_t dim = 3;
        tnet t = tnet_random(&rng, m, n, dim, trial % 2, 0.5, 2.0);
        bs_patch *p = tnet_patch(&t);
        double u[N], v[N];
        for (int k = 0; k < N; k++) {
            u[k] = bs_test_rand(&rng, -0.2, 1.2);
            v[k] = bs_test_rand(&rng, -0.2, 1.2);
        }
        u[5] = NAN;
        v[20] = INFINITY;
        double base[3][3 * N];
        bs_view vb[3][3];
        for (int d = 0; d < 3; d++)
            views_of(base[d], dim, N, vb[d]);
        bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
        CHECK_STATUS(bs_patch_eval(p, N, &cu, &cv, vb[0], vb[1], vb[2]), BS_OK);
        CHECK(isnan(base[0][5]) && isnan(base[1][N + 5]) && isnan(base[2][2 * N + 20]));
        CHECK(!isnan(base[0][6]) && !isnan(base[0][19]) && !isnan(base[0][21]));
        /* one at a time */
        int same = 1;
        for (int k = 0; k < N; k++) {
            double s[3][3];
            eval1(p, u[k], v[k], s[0], s[1], s[2]);
            for (int d = 0; d < 3; d++)
                for (size_t c = 0; c < dim; c++)
                    same &= memcmp(&s[d][c], &base[d][c * N + (size_t)k], sizeof(double)) == 0;
        }
        CHECK(same);
        /* reversed inputs through negative strides, interleaved xyz outputs, odd offset */
        double ur[N], vr[N];
        for (int k = 0; k < N; k++) {
            ur[N - 1 - k] = u[k];
            vr[N - 1 - k] = v[k];
        }
        bs_cview nu = {ur + N - 1, N, -8}, nv = {vr + N - 1, N, -8};
        double inter[3][3 * N + 1];
        bs_view vi[3][3];
        for (int d = 0; d < 3; d++)
            for (size_t c = 0; c < dim; c++) {
                vi[d][c].data = inter[d] + 1 + c;
                vi[d][c].count = N;
                vi[d][c].stride = 24;
            }
        CHECK_STATUS(bs_patch_eval(p, N, &nu, &nv, vi[0], vi[1], vi[2]), BS_OK);
        same = 1;
        for (int d = 0; d < 3; d++)
            for (size_t c = 0; c < dim; c++)
                for (int k = 0; k < N; k++)
                    same &= memcmp(&inter[d][1 + (size_t)k * 3 + c], &base[d][c * N + (size_t)k], 8) == 0;
        CHECK(same);
        /* batches of every size */
        for (size_t bsz = 1; bsz <= 17; bsz += 4) {
            double part[3 * N];
            bs_view vp[3];
            views_of(part, dim, N, vp);
            for (size_t k0 = 0; k0 < N; k0 += bsz) {
                size_t cnt = N - k0 < bsz ? N - k0 : bsz;
                bs_cview pu = cview_of(u + k0, cnt), pv = cview_of(v + k0, cnt);
                bs_view vq[3];
                for (size_t c = 0; c < dim; c++) {
                    vq[c] = vp[c];
                    vq[c].data += k0;
                    vq[c].count = cnt;
                }
                CHECK_STATUS(bs_patch_eval(p, cnt, &pu, &pv, vq, NULL, NULL), BS_OK);
            }
            CHECK(memcmp(part, base[0], sizeof part) == 0);
        }
        bs_patch_destroy(p);
        tnet_free(&t);
    }
}

/* A call of one point takes its own path (one lane of the block's arithmetic): the same bits as
 * the same point inside a block of eight, for every degree up to 16 and rational nets, values
 * alone and with partials. */
static void test_single_point_bits(void)
{
    unsigned long long rng = 29;
    enum { N = 8 };
    int same = 1;
    for (size_t m = 0; m <= 16; m++)
        for (size_t n = 0; n <= 16; n += (n < 4 ? 1 : 3))
            for (int rational = 0; rational < 2; rational++) {
                size_t dim = 1 + (m + n) % 4;
                tnet t = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
                bs_patch *p = tnet_patch(&t);
                double u[N], v[N], blk[3][4 * N], val[4 * N];
                for (int k = 0; k < N; k++) {
                    u[k] = bs_test_rand(&rng, -0.1, 1.1);
                    v[k] = bs_test_rand(&rng, -0.1, 1.1);
                }
                bs_view vb[3][4], vv[4];
                for (int d = 0; d < 3; d++)
                    views_of(blk[d], dim, N, vb[d]);
                views_of(val, dim, N, vv);
                bs_cview cu = cview_of(u, N), cv = cview_of(v, N);
                CHECK_STATUS(bs_patch_eval(p, N, &cu, &cv, vb[0], vb[1], vb[2]), BS_OK);
                CHECK_STATUS(bs_patch_eval(p, N, &cu, &cv, vv, NULL, NULL), BS_OK);
                for (int k = 0; k < N; k++) {
                    double s[3][4], s0[4];
                    bs_cview ou = cview_of(&u[k], 1), ov = cview_of(&v[k], 1);
                    bs_view o0[4];
                    views_of(s0, dim, 1, o0);
                    CHECK_STATUS(bs_patch_eval(p, 1, &ou, &ov, o0, NULL, NULL), BS_OK);
                    eval1(p, u[k], v[k], s[0], s[1], s[2]);
                    for (size_t c = 0; c < dim; c++) {
                        same &= memcmp(&s0[c], &val[c * N + (size_t)k], sizeof(double)) == 0;
                        for (int d = 0; d < 3; d++)
                            same &= memcmp(&s[d][c], &blk[d][c * N + (size_t)k], sizeof(double)) == 0;
                    }
                }
                CHECKF(same, "deg (%zu,%zu) rational %d: one point differs from its block", m, n, rational);
                bs_patch_destroy(p);
                tnet_free(&t);
            }
}

int main(void)
{
    test_worked_examples();
    test_against_reference();
    test_partition_of_unity();
    test_corners_and_boundaries();
    test_uv_symmetry();
    test_casteljau_forms();
    test_layout_independence();
    test_single_point_bits();
    return bs_test_exit("test_eval");
}
