/*
 * The test oracle: an independent, slow, extended-precision evaluator of Bezier patches.
 * Long double carries 64 significant bits on x86-64 (11 more than double), so its own rounding
 * error is ~1/2000 of the accuracy bounds the tests check. It shares no code with lib/: derivatives
 * come from the difference-net formula, rational ones from the quotient (Leibniz) rule.
 */
#ifndef BS_TEST_REFERENCE_H
#define BS_TEST_REFERENCE_H

#include <stdlib.h>
#include <string.h>

/* A net as the API packs it: point (i,j) coordinate c at ctrl[(i*(n+1)+j)*dim + c]; w NULL or weights. */
typedef struct ref_net {
    size_t m, n, dim;
    const double *ctrl;
    const double *w;
} ref_net;

/* de Casteljau's algorithm on b[0..deg] (overwritten): the curve's value at t. */
static inline long double ref_casteljau(long double *b, size_t deg, long double t)
{
    for (size_t r = 1; r <= deg; r++)
        for (size_t i = 0; i + r <= deg; i++)
            b[i] = (1.0L - t) * b[i] + t * b[i + 1];
    return b[0];
}

/* d^(k+l)/du^k dv^l of homogeneous coordinate c (c == dim: the weight; w*P_c when rational). */
static inline long double ref_hom_deriv(const ref_net *net, size_t c, unsigned k, unsigned l,
                                        long double u, long double v)
{
    size_t m = net->m, n = net->n, dim = net->dim;
    if (k > m || l > n)
        return 0.0L;
    long double plane[65][65], col[65];
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t idx = i * (n + 1) + j;
            long double w = net->w ? (long double)net->w[idx] : 1.0L;
            plane[i][j] = c == dim ? w : w * (long double)net->ctrl[idx * dim + c];
        }
    long double scale = 1.0L;
    for (unsigned r = 0; r < k; r++) { /* forward differences along i */
        scale *= (long double)(m - r);
        for (size_t i = 0; i + r < m; i++)
            for (size_t j = 0; j <= n; j++)
                plane[i][j] = plane[i + 1][j] - plane[i][j];
    }
    for (unsigned r = 0; r < l; r++) { /* forward differences along j */
        scale *= (long double)(n - r);
        for (size_t i = 0; i + k <= m; i++)
            for (size_t j = 0; j + r < n; j++)
                plane[i][j] = plane[i][j + 1] - plane[i][j];
    }
    size_t mm = m - k, nn = n - l;
    for (size_t j = 0; j <= nn; j++) {
        long double b[65];
        for (size_t i = 0; i <= mm; i++)
            b[i] = plane[i][j];
        col[j] = ref_casteljau(b, mm, u);
    }
    return scale * ref_casteljau(col, nn, v);
}

static inline long double ref_binom(unsigned n, unsigned k)
{
    long double r = 1.0L;
    for (unsigned i = 1; i <= k; i++)
        r = r * (long double)(n - k + i) / (long double)i;
    return r;
}

/* out[c] = d^(k+l) S_c / du^k dv^l at (u,v), c < dim. Returns 0 on allocation failure. */
static inline int ref_deriv(const ref_net *net, unsigned k, unsigned l, long double u, long double v,
                            long double *out)
{
    size_t dim = net->dim;
    if (net->w == NULL) {
        for (size_t c = 0; c < dim; c++)
            out[c] = ref_hom_deriv(net, c, k, l, u, v);
        return 1;
    }
    /* Leibniz on A = w S: S^(i,j) = (A^(i,j) - sum_{(a,b) != 0} C(i,a) C(j,b) w^(a,b) S^(i-a,j-b)) / w. */
    size_t stride = (size_t)l + 1;
    long double *s = malloc(((size_t)k + 1) * stride * dim * sizeof(long double));
    long double *wd = malloc(((size_t)k + 1) * stride * sizeof(long double));
    if (s == NULL || wd == NULL) {
        free(s);
        free(wd);
        return 0;
    }
    for (unsigned a = 0; a <= k; a++)
        for (unsigned b = 0; b <= l; b++)
            wd[a * stride + b] = ref_hom_deriv(net, dim, a, b, u, v);
    for (unsigned i = 0; i <= k; i++)
        for (unsigned j = 0; j <= l; j++)
            for (size_t c = 0; c < dim; c++) {
                long double acc = ref_hom_deriv(net, c, i, j, u, v);
                for (unsigned a = 0; a <= i; a++)
                    for (unsigned b = 0; b <= j; b++)
                        if (a || b)
                            acc -= ref_binom(i, a) * ref_binom(j, b) * wd[a * stride + b] *
                                   s[((i - a) * stride + (j - b)) * dim + c];
                s[(i * stride + j) * dim + c] = acc / wd[0];
            }
    memcpy(out, s + ((size_t)k * stride + l) * dim, dim * sizeof(long double));
    free(s);
    free(wd);
    return 1;
}

/* The point S(u,v). */
static inline void ref_eval(const ref_net *net, long double u, long double v, long double *out)
{
    (void)ref_deriv(net, 0, 0, u, v, out);
}

#endif
