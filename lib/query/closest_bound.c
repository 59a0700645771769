/*
 * Closest points, the bounds on one box of the domain: the workspace, the scaled root net of a
 * query, de Casteljau halving of a sub-net, and the two lower bounds on f = |S - q|^2 over the
 * box that the branch and bound of closest.c prunes with.
 *
 * First order: the bounding box of the Cartesian sub-net contains the sub-patch (convex hull
 * property; the weights are positive), so the squared distance from q to it bounds f from below.
 * It is cheap, and prunes far boxes, but near a minimum it is off by O(h) for a box of size h.
 *
 * Second order: f = N / W with N = |A|^2, A = w (S - q) the homogeneous sub-net, W = w^2 (W = 1
 * for a polynomial patch). N and W are polynomials of degree (2m, 2n) whose Bernstein
 * coefficients on the box come from the sub-net by the product rule of Bernstein polynomials,
 * and with W_kl > 0, f = sum B_kl W_kl (N_kl / W_kl) / sum B_kl W_kl is a convex combination of
 * the ratios: min N_kl / W_kl bounds f from below. The coefficients of a polynomial converge to
 * its values as O(h^2) under subdivision, so this bound is off by O(h^2 |f''|): where f is flat
 * (near its minimum, or where every point is at the same distance, as from a sphere's centre,
 * whose f is constant and whose coefficients are then all equal) it is nearly exact.
 */
#include "query/closest.h"


#include <float.h>
#include <math.h>
#include <stdlib.h>

static size_t max_sz(size_t a, size_t b) { return a > b ? a : b; }

unsigned bsi_cl_depth(const bs_patch *p)
{
    if (!p->rational)
        return BSI_CL_DEPTH;
    double lo = INFINITY, hi = 0.0;
    for (size_t k = 0; k < p->nctrl; k++) {
        lo = fmin(lo, p->weights[k]);
        hi = fmax(hi, p->weights[k]);
    }
    /* the ratio's binary exponent, from the two exponents (the ratio itself may overflow) */
    int elo = 0, ehi = 0;
    (void)frexp(lo, &elo);
    (void)frexp(hi, &ehi);
    long extra = 2L * ((long)ehi - (long)elo + 1L);
    return extra <= BSI_CL_DEPTH_MAX - BSI_CL_DEPTH ? BSI_CL_DEPTH + (unsigned)extra : 0u;
}

bsi_cl *bsi_cl_create(const bs_patch *p)
{
    bsi_cl *w = malloc(sizeof *w);
    if (w == NULL)
        return NULL;
    size_t m = p->deg_u, n = p->deg_v, pts = (m + 1) * (n + 1), coef = (2 * m + 1) * (2 * n + 1);
    w->p = p;
    w->m = m;
    w->n = n;
    w->dim = p->dim;
    w->nc = p->ncoord;
    w->np = pts * w->nc;
    w->depth = bsi_cl_depth(p);
    w->bicubic = m == 3 && n == 3 && w->dim == 3 ? w->nc : 0;
    size_t slots = (size_t)w->depth + 3;
    size_t total = (slots + 2) * w->np + pts * w->dim + w->np + 3 * coef +
                   (m + n + 2 * m + 2 * n + 4) + max_sz(m, n) + 1 + bsi_deriv_table_scratch(p, 2, 2) +
                   9 * w->dim;
    w->pool = malloc(total * sizeof(double));
    if (w->pool == NULL) {
        free(w);
        return NULL;
    }
    w->root = w->pool + slots * w->np;
    w->region = w->root + w->np;
    w->cart = w->region + w->np;
    w->scaled = w->cart + pts * w->dim;
    w->nco = w->scaled + w->np;
    w->wco = w->nco + coef;
    w->fco = w->wco + coef;
    w->binom = w->fco + coef;
    w->line = w->binom + (m + n + 2 * m + 2 * n + 4);
    w->dscratch = w->line + max_sz(m, n) + 1;
    w->table = w->dscratch + bsi_deriv_table_scratch(p, 2, 2);
    bsi_binomial_row((unsigned)m, w->binom);
    bsi_binomial_row((unsigned)n, w->binom + m + 1);
    bsi_binomial_row((unsigned)(2 * m), w->binom + m + n + 2);
    bsi_binomial_row((unsigned)(2 * n), w->binom + 3 * m + n + 3);
    return w;
}

void bsi_cl_free(bsi_cl *w)
{
    if (w != NULL)
        free(w->pool);
    free(w);
}

/* The power of two 2^-e with x 2^-e in [0.5, 1) (1 for x = 0 or not finite), at most 2^1000:
 * for subnormal x the rest is left to the next scale (s2 after s1), since 2^-e overflows. */
static double unit_scale(double x)
{
    int e = 0;
    if (!(x > 0.0 && x <= DBL_MAX))
        return 1.0;
    (void)frexp(x, &e);
    return ldexp(1.0, e < -1000 ? 1000 : -e);
}

void bsi_cl_setup(bsi_cl *w, const double *q)
{
    const bs_patch *p = w->p;
    size_t dim = w->dim, pts = p->nctrl;
    double big = 0.0, wmax = 0.0;
    for (size_t c = 0; c < dim; c++)
        big = fmax(big, fabs(q[c]));
    for (size_t k = 0; k < pts * dim; k++)
        big = fmax(big, fabs(p->ctrl[k]));
    w->s1 = unit_scale(big);
    for (size_t c = 0; c < dim; c++)
        w->qs[c] = q[c] * w->s1;
    double diff = 0.0, lo[BS_MAX_DIM], hi[BS_MAX_DIM];
    for (size_t c = 0; c < dim; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t k = 0; k < pts; k++) {
        for (size_t c = 0; c < dim; c++) {
            double x = p->ctrl[k * dim + c] * w->s1;
            diff = fmax(diff, fabs(x - w->qs[c]));
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
        if (p->rational)
            wmax = fmax(wmax, p->weights[k]);
    }
    w->s2 = unit_scale(diff);
    double d2 = 0.0;
    for (size_t c = 0; c < dim; c++)
        d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    w->diag = sqrt(d2) * w->s2;
    double ws = p->rational ? unit_scale(wmax) : 1.0;
    w->wmin = 1.0;
    double *net = w->root;
    for (size_t k = 0; k < pts; k++) {
        double wk = p->rational ? p->weights[k] * ws : 1.0;
        w->wmin = fmin(w->wmin, wk);
        for (size_t c = 0; c < dim; c++)
            net[k * w->nc + c] = wk * ((p->ctrl[k * dim + c] * w->s1 - w->qs[c]) * w->s2);
        if (p->rational)
            net[k * w->nc + dim] = wk;
    }
}

/* One line of deg+1 values at src, stride apart, halved: the left half to lo, the right to hi. */
BSI_INLINE void split_line(const double *src, size_t deg, size_t stride, double *lo, double *hi,
                       double *t)
{
    for (size_t k = 0; k <= deg; k++)
        t[k] = src[k * stride];
    lo[0] = t[0];
    hi[deg * stride] = t[deg];
    for (size_t r = 1; r <= deg; r++) {
        for (size_t k = 0; k + r <= deg; k++)
            t[k] = 0.5 * (t[k] + t[k + 1]);
        lo[r * stride] = t[0];
        hi[(deg - r) * stride] = t[deg - r];
    }
}

void bsi_cl_split(bsi_cl *w, const double *src, int dir, double *lo, double *hi)
{
    size_t m = w->m, n = w->n, nc = w->nc;
    if (BSI_CL_BICUBIC3(w)) {
        bsi_cl_split3(src, dir, lo, hi);
    } else if (BSI_CL_BICUBIC4(w)) {
        bsi_cl_split4(src, dir, lo, hi);
    } else if (dir == BS_DIR_U) {
        for (size_t j = 0; j <= n; j++)
            for (size_t c = 0; c < nc; c++) {
                size_t o = j * nc + c;
                split_line(src + o, m, (n + 1) * nc, lo + o, hi + o, w->line);
            }
    } else {
        for (size_t i = 0; i <= m; i++)
            for (size_t c = 0; c < nc; c++) {
                size_t o = i * (n + 1) * nc + c;
                split_line(src + o, n, nc, lo + o, hi + o, w->line);
            }
    }
}

/* The Cartesian points of a net into w->cart. */
static void cartesian(bsi_cl *w, const double *net)
{
    size_t dim = w->dim, nc = w->nc, pts = (w->m + 1) * (w->n + 1);
    for (size_t k = 0; k < pts; k++) {
        double inv = nc > dim ? 1.0 / net[k * nc + dim] : 1.0;
        for (size_t c = 0; c < dim; c++)
            w->cart[k * dim + c] = nc > dim ? net[k * nc + c] * inv : net[k * nc + c];
    }
}

double bsi_cl_box(bsi_cl *w, const double *net)
{
    if (BSI_CL_BICUBIC3(w))
        return bsi_cl_box3(net);
    if (BSI_CL_BICUBIC4(w))
        return bsi_cl_box4(net);
    if (w->nc > w->dim) {
        cartesian(w, net);
        net = w->cart;
    }
    return bsi_cl_box_gap2(net, (w->m + 1) * (w->n + 1), w->dim);
}

int bsi_cl_longer(bsi_cl *w, const double *net)
{
    size_t m = w->m, n = w->n, dim = w->dim;
    cartesian(w, net);
    /* the largest step between neighbours along u (times m) against along v (times n), a bound
     * on |S_u| and |S_v| over the box */
    double lu = 0.0, lv = 0.0;
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            const double *x = w->cart + (i * (n + 1) + j) * dim;
            double du = 0.0, dv = 0.0;
            for (size_t c = 0; c < dim; c++) {
                if (i < m)
                    du += fabs(x[(n + 1) * dim + c] - x[c]);
                if (j < n)
                    dv += fabs(x[dim + c] - x[c]);
            }
            lu = du > lu ? du : lu;
            lv = dv > lv ? dv : lv;
        }
    lu *= (double)m;
    lv *= (double)n;
    return m == 0 && n == 0 ? -1 : (n == 0 || (m > 0 && lu >= lv)) ? BS_DIR_U : BS_DIR_V;
}

/* out[(i+i')(2n+1) + j+j'] += f x[i][j] y[i'][j'] over all pairs with i' >= i (f = 2 where i' > i):
 * the self-product x y of one coordinate plane when y = x (planes (m+1) x (n+1), row-major). */
static void self_product(const double *x, size_t m, size_t n, double *out)
{
    size_t n1 = n + 1, n2 = 2 * n + 1;
    for (size_t i = 0; i <= m; i++)
        for (size_t i2 = i; i2 <= m; i2++) {
            double f = i2 == i ? 1.0 : 2.0;
            const double *row = x + i2 * n1;
            double *o = out + (i + i2) * n2;
            for (size_t j = 0; j <= n; j++) {
                double a = f * x[i * n1 + j];
                for (size_t j2 = 0; j2 <= n; j2++)
                    o[j + j2] += a * row[j2];
            }
        }
}

void bsi_cl_fbound_finish(bsi_cl *w, bsi_cl_bound *b, double low, size_t arg, double err,
                          double rel)
{
    size_t m = w->m, n = w->n, n2 = 2 * n + 1;
    b->lbf = low > 0.0 ? low * (1.0 - 4.0 * DBL_EPSILON) : low;
    b->err = err;
    b->rel = rel;
    size_t ka = arg / n2, la = arg % n2; /* the coefficient's indices */
    b->su = m > 0 ? (double)ka / (double)(2 * m) : 0.5;
    b->sv = n > 0 ? (double)la / (double)(2 * n) : 0.5;
}

void bsi_cl_fbound(bsi_cl *w, const double *net, bsi_cl_bound *b)
{
    size_t m = w->m, n = w->n, dim = w->dim, nc = w->nc, pts = (m + 1) * (n + 1);
    if (BSI_CL_BICUBIC3(w)) {
        bsi_cl_fbound3(w, net, b);
        return;
    }
    if (BSI_CL_BICUBIC4(w)) {
        bsi_cl_fbound4(w, net, b);
        return;
    }
    size_t n2 = 2 * n + 1, coef = (2 * m + 1) * n2;
    int rational = nc > dim;
    const double *bm = w->binom, *bn = bm + m + 1, *b2m = bn + n + 1, *b2n = b2m + 2 * m + 1;
    double amax = 0.0;
    /* the net times C(m,i) C(n,j), coordinate-major: plane c at scaled + c pts; amax the
     * largest |A_ij|^2 (polynomial) or |A_ij / w_ij|^2 (rational, see the rounding below) */
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t k = i * (n + 1) + j;
            double s = bm[i] * bn[j], a2 = 0.0;
            for (size_t c = 0; c < nc; c++) {
                double x = net[k * nc + c];
                w->scaled[c * pts + k] = s * x;
                a2 += c < dim ? x * x : 0.0;
            }
            if (rational)
                a2 = a2 / (net[k * nc + dim] * net[k * nc + dim]) * (1.0 + 8.0 * DBL_EPSILON);
            amax = a2 > amax ? a2 : amax;
        }
    for (size_t k = 0; k < coef; k++)
        w->nco[k] = w->wco[k] = 0.0;
    /* N = sum over pairs of net points of C(m,i)C(m,i')C(n,j)C(n,j') A_ij . A_i'j'
     * B(2m, i+i') B(2n, j+j') / (C(2m,i+i') C(2n,j+j')); W likewise from the weights. */
    for (size_t c = 0; c < dim; c++)
        self_product(w->scaled + c * pts, m, n, w->nco);
    if (rational)
        self_product(w->scaled + dim * pts, m, n, w->wco);
    /* Rounding: each N_kl sums at most pts dim products whose magnitudes, over the binomials,
     * add up to at most amax; each W_kl is a sum of positive terms. For a rational net
     * |A_ij| = w_ij |x_ij| (x_ij the Cartesian point), so the products of N_kl add up to at most
     * amax W_kl with amax the largest |x_ij|^2: the error of N_kl / W_kl is then relative to the
     * distances, not amplified by the weight ratio, and err (the absolute error of every N_kl)
     * is amax times the largest W_kl. */
    double e = (double)(pts * dim + 16) * DBL_EPSILON * amax, err = e;
    double rel = (double)(pts + 16) * DBL_EPSILON;
    double best = INFINITY, low = INFINITY;
    size_t arg = 0;
    for (size_t k = 0; k <= 2 * m; k++)
        for (size_t l = 0; l < n2; l++) {
            size_t at = k * n2 + l;
            double scale = b2m[k] * b2n[l];
            double num = w->nco[at] / scale, den = rational ? w->wco[at] / scale : 1.0;
            double ratio = num / den, lowk = num - err;
            w->fco[at] = ratio;
            if (ratio < best) {
                best = ratio;
                arg = at;
            }
            if (rational) { /* a weight square that underflowed to 0 gives no bound */
                double ek = e * den * (1.0 + rel);
                err = fmax(err, ek);
                lowk = num - ek;
                lowk = den > 0.0 ? lowk / (den * (lowk > 0.0 ? 1.0 + rel : 1.0 - rel)) : -INFINITY;
            }
            low = lowk < low ? lowk : low;
        }
    bsi_cl_fbound_finish(w, b, low, arg, err, rel);
}

int bsi_cl_direction(const bsi_cl *w)
{
    return w->bicubic != 0 ? bsi_cl_slack3(w) : bsi_cl_slack(w, w->m, w->n);
}

void bsi_cl_region(bsi_cl *w, const double x[4])
{
    size_t m = w->m, n = w->n, nc = w->nc;
    for (size_t k = 0; k < w->np; k++)
        w->region[k] = w->root[k];
    if (BSI_CL_BICUBIC3(w)) {
        bsi_cl_region3(w->region, x);
        return;
    }
    if (BSI_CL_BICUBIC4(w)) {
        bsi_cl_region4(w->region, x);
        return;
    }
    for (size_t j = 0; j <= n; j++)
        for (size_t c = 0; c < nc; c++)
            bsi_sub_line(w->region + j * nc + c, m, (n + 1) * nc, 1, x[0], x[1]);
    for (size_t i = 0; i <= m; i++)
        for (size_t c = 0; c < nc; c++)
            bsi_sub_line(w->region + i * (n + 1) * nc + c, n, nc, 1, x[2], x[3]);
}

double bsi_cl_convex(const bsi_cl *w, const bsi_cl_bound *b, double c, double *wlo, double *whi,
                     double abc[3])
{
    abc[0] = abc[1] = abc[2] = NAN;
    size_t K = 2 * w->m, L = 2 * w->n, n2 = L + 1;
    int rational = w->nc > w->dim;
    const double *b2m = w->binom + w->m + w->n + 2, *b2n = b2m + K + 1;
    /* G_kl = N_kl - c W_kl into w->scaled (free after bsi_cl_fbound), and max W / min W */
    double *g = w->scaled, lo = INFINITY, hi = 0.0;
    for (size_t k = 0; k <= K; k++)
        for (size_t l = 0; l <= L; l++) {
            double scale = b2m[k] * b2n[l], wk = rational ? w->wco[k * n2 + l] / scale : 1.0;
            g[k * n2 + l] = w->nco[k * n2 + l] / scale - c * wk;
            lo = wk < lo ? wk : lo;
            hi = wk > hi ? wk : hi;
        }
    *wlo = lo;
    *whi = hi;
    if (!(lo > 0.0))
        return 0.0;
    double e = 2.0 * (b->err + c * hi * b->rel); /* rounding of each G_kl, with margin */
    double alo = INFINITY, clo = INFINITY, bhi = 0.0;
#define G(k, l) g[(k) * n2 + (l)]
    for (size_t k = 0; k <= K; k++)
        for (size_t l = 0; l <= L; l++) {
            if (k + 2 <= K) {
                double d = G(k + 2, l) - 2.0 * G(k + 1, l) + G(k, l) - 4.0 * e;
                alo = d < alo ? d : alo;
            }
            if (l + 2 <= L) {
                double d = G(k, l + 2) - 2.0 * G(k, l + 1) + G(k, l) - 4.0 * e;
                clo = d < clo ? d : clo;
            }
            if (k < K && l < L) {
                double d = fabs(G(k + 1, l + 1) - G(k + 1, l) - G(k, l + 1) + G(k, l)) + 4.0 * e;
                bhi = d > bhi ? d : bhi;
            }
        }
#undef G
    /* Hessian in the box's parameters: A = K(K-1) alo <= G_ss, C = L(L-1) clo <= G_tt,
     * |G_st| <= B = K L bhi; the smallest eigenvalue of [a b; b c] grows with a and c and falls
     * with |b|, so it is at least that of [A B; B C]. A direction of degree 0 does not count. */
    double kk = (double)K, ll = (double)L;
    double A = kk * (kk - 1.0) * alo, C = ll * (ll - 1.0) * clo, B = kk * ll * bhi;
    abc[0] = A;
    abc[1] = B;
    abc[2] = C;
    if (K == 0)
        return L == 0 ? INFINITY : C;
    if (L == 0)
        return A;
    if (!(A > 0.0 && C > 0.0))
        return 0.0;
    return 0.5 * ((A + C) - sqrt((A - C) * (A - C) + 4.0 * B * B));
}

/* The smallest of q(x) = gam x + a x^2 / 2 over x in [l, h] (l <= 0 <= h) for every gam in
 * [g0, g1] (it is concave in gam: attained at g0 or g1); *mag grows to the largest magnitude of
 * the terms (for the rounding). */
static double quad_min(double g0, double g1, double a, double l, double h, double *mag)
{
    double least = 0.0, gs[2] = {g0, g1};
    for (int k = 0; k < 2; k++) {
        double gam = gs[k], xs[2] = {l, h};
        for (int i = 0; i < 2; i++) {
            double lin = gam * xs[i], sq = 0.5 * a * xs[i] * xs[i];
            least = fmin(least, lin + sq);
            *mag = fmax(*mag, fabs(lin) + fabs(sq));
        }
        if (a > 0.0 && -gam >= a * l && -gam <= a * h) { /* the vertex -gam/a lies in [l, h] */
            double v = gam * gam / (2.0 * a);
            least = fmin(least, -v);
            *mag = fmax(*mag, v);
        }
    }
    return least;
}

/* A lower bound on f - c over the square x around x* = uv of a polynomial patch (G = f - c)
 * without convexity, for minima on an edge or at a corner: with A <= G_ss, C <= G_tt, |G_st| <= B
 * in the square's parameters (abc), Taylor's formula with the integral remainder gives
 * G(x* + d) >= G(x*) + gam . d + (A ds^2 + C dt^2) / 2 - B |ds dt|, and for any alpha > 0
 * B |ds dt| <= B (alpha ds^2 + dt^2 / alpha) / 2 splits it into two quadratics of one variable,
 * each bounded over its range of d (exactly, at its ends or its vertex). gam is the gradient g in
 * the square's parameters, off by dg; several alpha are tried, the best bound kept. */
double bsi_cl_separable_bound(const double uv[2], const double x[4], const double g[2],
                              const double dg[2], const double abc[3])
{
    double A = abc[0], B = abc[1], C = abc[2], lo[2], hi[2], g0[2], g1[2];
    double up = 1.0 + 4.0 * DBL_EPSILON, down = 1.0 - 4.0 * DBL_EPSILON;
    for (size_t i = 0; i < 2; i++) {
        /* the ranges of d and of the gradient, widened by their rounding (an end at x* exact) */
        double width = x[2 * i + 1] - x[2 * i], at = (uv[i] - x[2 * i]) / width;
        lo[i] = uv[i] == x[2 * i] ? 0.0 : -(at + 8.0 * DBL_EPSILON);
        hi[i] = uv[i] == x[2 * i + 1] ? 0.0 : (1.0 - at) + 8.0 * DBL_EPSILON;
        double a = g[i] - dg[i], b = g[i] + dg[i];
        g0[i] = a * width * (a > 0.0 ? down : up);
        g1[i] = b * width * (b > 0.0 ? up : down);
    }
    if (!(B >= 0.0 && isfinite(A) && isfinite(B) && isfinite(C)))
        return -INFINITY;
    /* alpha = 1; the t part convex (C - B / alpha = C / 2); the s part convex; balanced */
    double alphas[4] = {1.0, C > 0.0 && B > 0.0 ? 2.0 * B / C : 1.0,
                        A > 0.0 && B > 0.0 ? A / (2.0 * B) : 1.0,
                        A > 0.0 && C > 0.0 ? sqrt(C / A) : 1.0};
    double best = -INFINITY;
    for (int k = 0; k < 4; k++) {
        double al = alphas[k], mag = 0.0;
        if (!(al > 0.0 && isfinite(al)))
            continue;
        double d = quad_min(g0[0], g1[0], A - B * al, lo[0], hi[0], &mag) +
                   quad_min(g0[1], g1[1], C - B / al, lo[1], hi[1], &mag);
        best = fmax(best, d - 16.0 * DBL_EPSILON * mag);
    }
    return best;
}
