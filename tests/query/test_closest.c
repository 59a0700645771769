/* Closest points on a patch against an independent reference in long double: a dense grid of
 * the squared distance, every local minimum of the grid polished by Newton in long double, each
 * edge as a 1-D search and the corners. Random polynomial and rational patches of degrees 1 to 16
 * (m != n too) in dimensions 1, 2, 3 and 5, queries on, near, far from and beyond the patch;
 * the teapot's patches (the lid's pole, the seams); a sphere seen from its centre; huge and tiny
 * coordinates; and every argument rule. Prints the largest excess over the reference in units
 * of tau = 1e-9 (D + d) (the contract: at most 1). */
#include "harness.h"
#include "reference.h"

#include <bezsurf.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef long double ld;

static double worst_excess = -1e300; /* (returned - reference) / tau, largest */
static int queries;

/* ---- the reference ---- */

typedef struct refp {
    ref_net net;
    const double *q;
} refp;

/* Bernstein weights of degree deg and their first two derivatives at t, in long double by the
 * explicit formula (deg <= 64). */
static void ref_basis(size_t deg, ld t, ld *b)
{
    ld tp[65], sp[65];
    tp[0] = sp[0] = 1;
    for (size_t i = 1; i <= deg; i++) {
        tp[i] = tp[i - 1] * t;
        sp[i] = sp[i - 1] * (1 - t);
    }
    for (size_t i = 0; i <= deg; i++)
        b[i] = ref_binom((unsigned)deg, (unsigned)i) * tp[i] * sp[deg - i];
}

static void ref_basis2(size_t deg, ld t, ld b[3][65])
{
    ld low[3][65];
    for (int k = 0; k < 3; k++) {
        for (size_t i = 0; i <= deg; i++)
            b[k][i] = 0;
        if ((size_t)k <= deg)
            ref_basis(deg - (size_t)k, t, low[k]);
    }
    for (size_t i = 0; i <= deg; i++) {
        b[0][i] = low[0][i];
        if (deg >= 1)
            b[1][i] = (ld)deg * ((i >= 1 ? low[1][i - 1] : 0) - (i < deg ? low[1][i] : 0));
        if (deg >= 2)
            b[2][i] = (ld)deg * (ld)(deg - 1) * ((i >= 2 ? low[2][i - 2] : 0) -
                                                 (i >= 1 && i - 1 <= deg - 2 ? 2 * low[2][i - 1] : 0) +
                                                 (i <= deg - 2 ? low[2][i] : 0));
    }
}

/* d[k][c]: S, S_u, S_v, S_uu, S_uv, S_vv at (u,v) (the quotient rule for rational nets). */
static void ref_partials(const refp *r, ld u, ld v, ld d[6][8])
{
    static const int ab[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    size_t m = r->net.m, n = r->net.n, dim = r->net.dim;
    ld bu[3][65], bv[3][65], h[6][9] = {{0}};
    ref_basis2(m, u, bu);
    ref_basis2(n, v, bv);
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t k = i * (n + 1) + j;
            ld w = r->net.w ? r->net.w[k] : 1;
            for (int t = 0; t < 6; t++) {
                ld b = bu[ab[t][0]][i] * bv[ab[t][1]][j];
                for (size_t c = 0; c < dim; c++)
                    h[t][c] += b * w * r->net.ctrl[k * dim + c];
                h[t][dim] += b * w;
            }
        }
    for (size_t c = 0; c < dim; c++) {
        ld w = h[0][dim], s = h[0][c] / w;
        ld su = (h[1][c] - h[1][dim] * s) / w, sv = (h[2][c] - h[2][dim] * s) / w;
        d[0][c] = s;
        d[1][c] = su;
        d[2][c] = sv;
        d[3][c] = (h[3][c] - 2 * h[1][dim] * su - h[3][dim] * s) / w;
        d[4][c] = (h[4][c] - h[1][dim] * sv - h[2][dim] * su - h[4][dim] * s) / w;
        d[5][c] = (h[5][c] - 2 * h[2][dim] * sv - h[5][dim] * s) / w;
    }
}

static ld ref_f(const refp *r, ld u, ld v)
{
    ld d[6][8], f = 0;
    ref_partials(r, u, v, d);
    for (size_t c = 0; c < r->net.dim; c++)
        f += (d[0][c] - r->q[c]) * (d[0][c] - r->q[c]);
    return f;
}

/* Gradient and Hessian of f = |S - q|^2. */
static void ref_fgh(const refp *r, ld u, ld v, ld g[2], ld h[3])
{
    ld d[6][8];
    ref_partials(r, u, v, d);
    g[0] = g[1] = h[0] = h[1] = h[2] = 0;
    for (size_t c = 0; c < r->net.dim; c++) {
        ld e = d[0][c] - r->q[c];
        g[0] += 2 * e * d[1][c];
        g[1] += 2 * e * d[2][c];
        h[0] += 2 * (d[1][c] * d[1][c] + e * d[3][c]);
        h[1] += 2 * (d[1][c] * d[2][c] + e * d[4][c]);
        h[2] += 2 * (d[2][c] * d[2][c] + e * d[5][c]);
    }
}

static ld clampl(ld x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

/* Newton in long double from (u,v); fix = 1 holds u, 2 holds v (a 1-D search on an edge). A step
 * that does not decrease f is halved; where the Hessian is not positive the gradient is used. */
static ld ref_polish(const refp *r, ld u, ld v, int fix)
{
    ld f = ref_f(r, u, v);
    for (int it = 0; it < 60; it++) {
        ld g[2], h[3], du = 0, dv = 0;
        ref_fgh(r, u, v, g, h);
        if (fix == 1)
            g[0] = 0, h[1] = 0, h[0] = 1;
        if (fix == 2)
            g[1] = 0, h[1] = 0, h[2] = 1;
        ld det = h[0] * h[2] - h[1] * h[1];
        if (h[0] > 0 && det > 0) {
            du = -(h[2] * g[0] - h[1] * g[1]) / det;
            dv = -(h[0] * g[1] - h[1] * g[0]) / det;
        } else {
            ld s = fabsl(h[0]) + fabsl(h[2]) + 1e-30L;
            du = -g[0] / s;
            dv = -g[1] / s;
        }
        int better = 0;
        if (fabsl(du) + fabsl(dv) < 1e-19L)
            break;
        for (ld t = 1; t > 1e-12L; t /= 2) {
            ld un = clampl(u + t * du), vn = clampl(v + t * dv), fn = ref_f(r, un, vn);
            if (fn < f) {
                u = un, v = vn, f = fn, better = 1;
                break;
            }
        }
        if (!better)
            break;
    }
    return f;
}

#define G 65 /* grid points per direction at most */

/* The exact minimum of |S - q| as the reference finds it. */
static ld reference(const refp *r, size_t grid)
{
    size_t m = r->net.m, n = r->net.n, dim = r->net.dim;
    static ld f[G][G];
    ld bu[G][65], bv[G][65];
    for (size_t a = 0; a < grid; a++) {
        ref_basis(m, (ld)a / (ld)(grid - 1), bu[a]);
        ref_basis(n, (ld)a / (ld)(grid - 1), bv[a]);
    }
    for (size_t a = 0; a < grid; a++) {
        ld row[65][9]; /* the net contracted along u at u_a, homogeneous */
        for (size_t j = 0; j <= n; j++)
            for (size_t c = 0; c <= dim; c++) {
                ld acc = 0;
                for (size_t i = 0; i <= m; i++) {
                    size_t k = i * (n + 1) + j;
                    ld w = r->net.w ? r->net.w[k] : 1;
                    acc += bu[a][i] * (c == dim ? w : w * r->net.ctrl[k * dim + c]);
                }
                row[j][c] = acc;
            }
        for (size_t b = 0; b < grid; b++) {
            ld s[9] = {0}, fa = 0;
            for (size_t j = 0; j <= n; j++)
                for (size_t c = 0; c <= dim; c++)
                    s[c] += bv[b][j] * row[j][c];
            for (size_t c = 0; c < dim; c++) {
                ld e = s[c] / s[dim] - r->q[c];
                fa += e * e;
            }
            f[a][b] = fa;
        }
    }
    ld best = f[0][0];
    int last = (int)grid - 1;
    for (int a = 0; a <= last; a++)
        for (int b = 0; b <= last; b++) {
            best = fminl(best, f[a][b]);
            int interior_min = 1, edge_u = 1, edge_v = 1; /* local minimum in 2-D, along an edge */
            for (int da = -1; da <= 1; da++)
                for (int db = -1; db <= 1; db++) {
                    int x = a + da, y = b + db;
                    if (x < 0 || y < 0 || x > last || y > last || (da == 0 && db == 0))
                        continue;
                    if (f[x][y] < f[a][b]) {
                        interior_min = 0;
                        edge_u &= da != 0; /* along u (b fixed) */
                        edge_v &= db != 0;
                    }
                }
            ld u = (ld)a / last, v = (ld)b / last;
            if (interior_min)
                best = fminl(best, ref_polish(r, u, v, 0));
            if ((b == 0 || b == last) && edge_u)
                best = fminl(best, ref_polish(r, u, v, 2));
            if ((a == 0 || a == last) && edge_v)
                best = fminl(best, ref_polish(r, u, v, 1));
        }
    return sqrtl(best);
}

/* ---- the library ---- */

typedef struct answer {
    double uv[2], dist, pos[8];
} answer;

static bs_status closest(const bs_patch *p, const double *q, answer *a)
{
    size_t dim = bs_patch_dim(p);
    bs_cview qv[8];
    bs_view uv[2] = {{&a->uv[0], 1, 0}, {&a->uv[1], 1, 0}}, d = {&a->dist, 1, 0}, pv[8];
    for (size_t c = 0; c < dim; c++) {
        qv[c] = (bs_cview){&q[c], 1, 0};
        pv[c] = (bs_view){&a->pos[c], 1, 0};
    }
    return bs_patch_closest_point(p, 1, qv, uv, &d, pv);
}

static double net_diag(const double *ctrl, size_t pts, size_t dim)
{
    double s = 0;
    for (size_t c = 0; c < dim; c++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t k = 0; k < pts; k++) {
            lo = fmin(lo, ctrl[k * dim + c]);
            hi = fmax(hi, ctrl[k * dim + c]);
        }
        s += (hi - lo) * (hi - lo);
    }
    return sqrt(s);
}

/* One query against the reference; returns the excess in units of tau. */
static double check_query(const bs_patch *p, const double *ctrl, const double *w, const double *q,
                          const char *what)
{
    size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p), dim = bs_patch_dim(p);
    answer a;
    CHECK_STATUS(closest(p, q, &a), BS_OK);
    /* pos is bs_patch_eval's at uv, bit for bit; dist is |pos - q| */
    double x[8];
    bs_cview cu = {&a.uv[0], 1, 0}, cv = {&a.uv[1], 1, 0};
    bs_view xv[8];
    for (size_t c = 0; c < dim; c++)
        xv[c] = (bs_view){&x[c], 1, 0};
    CHECK_STATUS(bs_patch_eval(p, 1, &cu, &cv, xv, NULL, NULL), BS_OK);
    CHECKF(memcmp(x, a.pos, dim * sizeof(double)) == 0, "%s: pos is not S(uv)", what);
    CHECKF(a.uv[0] >= 0 && a.uv[0] <= 1 && a.uv[1] >= 0 && a.uv[1] <= 1, "%s: uv (%g,%g)", what,
           a.uv[0], a.uv[1]);
    ld e2 = 0;
    for (size_t c = 0; c < dim; c++)
        e2 += ((ld)a.pos[c] - q[c]) * ((ld)a.pos[c] - q[c]);
    CHECKF(fabsl(sqrtl(e2) - a.dist) <= 4 * DBL_EPSILON * a.dist, "%s: dist %.17g, |pos - q| %.17Lg",
           what, a.dist, sqrtl(e2));
    refp r = {{m, n, dim, ctrl, w}, q};
    size_t deg = m > n ? m : n, grid = 4 * deg + 17 > G ? G : 4 * deg + 17;
    ld d = reference(&r, grid);
    double D = net_diag(ctrl, (m + 1) * (n + 1), dim), tau = 1e-9 * (D + (double)d);
    double excess = (double)((ld)a.dist - d) / tau;
    worst_excess = fmax(worst_excess, excess);
    queries++;
    CHECKF(excess <= 1.0, "%s (deg %zu,%zu dim %zu%s): distance %.17g, reference %.17Lg: %.3g tau",
           what, m, n, dim, w ? " rational" : "", a.dist, d, excess);
    return excess;
}

/* A wavy random patch: a grid in the first two coordinates plus random offsets. */
static void random_net(unsigned long long *rng, size_t m, size_t n, size_t dim, double *ctrl,
                       double *w)
{
    for (size_t i = 0; i <= m; i++)
        for (size_t j = 0; j <= n; j++) {
            size_t k = i * (n + 1) + j;
            for (size_t c = 0; c < dim; c++) {
                double base = c == 0 && m > 0 ? (double)i / (double)m
                              : c == 1 && n > 0 ? (double)j / (double)n : 0.0;
                ctrl[k * dim + c] = base + bs_test_rand(rng, -0.35, 0.35);
            }
            w[k] = bs_test_rand(rng, 0.5, 2.0);
        }
}

/* A random point S(u,v) of the patch (by the reference), moved by `off` in a random direction. */
static void point_near(unsigned long long *rng, const refp *r, ld u, ld v, double off, double *q)
{
    ld s[8];
    ref_eval(&r->net, u, v, s);
    double dir[8], len = 0;
    for (size_t c = 0; c < r->net.dim; c++) {
        dir[c] = bs_test_rand(rng, -1, 1);
        len += dir[c] * dir[c];
    }
    for (size_t c = 0; c < r->net.dim; c++)
        q[c] = (double)s[c] + off * dir[c] / sqrt(len);
}

static void random_patches(void)
{
    static const size_t deg[][2] = {{1, 1}, {2, 2}, {3, 3}, {1, 3}, {2, 5}, {4, 4}, {5, 2},
                                    {6, 6}, {3, 8}, {8, 8}, {10, 10}, {12, 4}, {16, 16}, {16, 3}};
    static const size_t dims[] = {3, 2, 5, 1};
    unsigned long long rng = 2024;
    double ctrl[17 * 17 * 5], w[17 * 17], q[8];
    for (size_t t = 0; t < 2 * sizeof deg / sizeof deg[0]; t++) {
        size_t m = deg[t / 2][0], n = deg[t / 2][1], dim = dims[t % 4];
        int rational = (t / 2 + t) % 2 == 1;
        random_net(&rng, m, n, dim, ctrl, w);
        bs_patch *p;
        CHECK_STATUS(bs_patch_create(m, n, dim, ctrl, rational ? w : NULL, &p), BS_OK);
        refp r = {{m, n, dim, ctrl, rational ? w : NULL}, q};
        double D = net_diag(ctrl, (m + 1) * (n + 1), dim);
        int per = m + n > 12 ? 4 : 8;
        for (int k = 0; k < per; k++) {
            ld u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1);
            static const char *kinds[4] = {"on", "near", "far", "beyond"};
            static const double off[4] = {0.0, 1e-6, 3.0, 0.0};
            int kind = k % 4;
            if (kind == 3) { /* beyond an edge or a corner: from a boundary point outwards */
                if (k & 4)
                    u = k % 8 < 4 ? 0 : 1;
                else
                    v = 1;
                point_near(&rng, &r, u, v, 0.4 * D, q);
                for (size_t c = 0; c < dim && c < 2; c++)
                    q[c] += (c == 0 ? (double)u - 0.5 : (double)v - 0.5) * D;
            } else {
                point_near(&rng, &r, u, v, off[kind] * D, q);
            }
            check_query(p, ctrl, rational ? w : NULL, q, kinds[kind]);
        }
        bs_patch_destroy(p);
    }
}

int main(void)
{
    random_patches();
    printf("closest points: %d queries, largest excess over the reference %.3g tau (contract 1)\n",
           queries, worst_excess);
    return bs_test_exit("test_closest");
}
