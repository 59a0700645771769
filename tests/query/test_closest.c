/* Closest points on a patch against an independent reference in long double: a dense grid of
 * the squared distance, every local minimum of the grid polished by Newton in long double, each
 * edge as a 1-D search and the corners. Random polynomial and rational patches of degrees 1 to 16
 * (m != n too) in dimensions 1, 2, 3 and 5, queries on, near, far from and beyond the patch;
 * the teapot's patches (the lid's pole, the seams); a sphere seen from its centre; huge and tiny
 * coordinates; and every argument rule. Prints the largest excess over the reference in units
 * of tau = 1e-9 (D + d) (the contract: at most 1). */
#include "harness.h"
#include "reference.h"
#include "shapes.h"

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
    if (bs_test_quick())
        return 0.0; /* the library's own work is done; the long double reference adds no memory check */
    refp r = {{m, n, dim, ctrl, w}, q};
    size_t deg = m > n ? m : n, grid = 4 * deg + 17 > G ? G : 4 * deg + 17;
    ld d = reference(&r, grid);
    double D = net_diag(ctrl, (m + 1) * (n + 1), dim), tau = 1e-9 * (D + (double)d);
    double diff = (double)((ld)a.dist - d);
    double excess = tau > 0 ? diff / tau : diff > 0 ? INFINITY : 0.0; /* tau = 0: a point patch */
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

/* The teapot: random points around each patch, the poles of the lid and the bottom (collapsed
 * sides) seen from above, below and aside, and points near the seams between patches. */
static void teapot(void)
{
    bs_surface *s;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    unsigned long long rng = 7;
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        double ctrl[16 * 3], q[3];
        CHECK_STATUS(bs_patch_get_ctrl(p, ctrl, 48, NULL, 0), BS_OK);
        refp r = {{3, 3, 3, ctrl, NULL}, q};
        double D = net_diag(ctrl, 16, 3);
        for (int k = 0; k < 6; k++) {
            ld u = bs_test_rand(&rng, 0, 1), v = bs_test_rand(&rng, 0, 1);
            if (k == 1 || k == 2) /* a corner: the poles are corners of the lid's patches */
                u = k == 1 ? 0 : 1, v = bs_test_rand_u64(&rng) % 2;
            if (k == 3) /* a seam: a side of the patch */
                u = bs_test_rand_u64(&rng) % 2;
            point_near(&rng, &r, u, v, k == 0 ? 0.3 * D : k == 4 ? 0.0 : 0.05 * D, q);
            if (k == 5) /* far above or below */
                q[2] += (bs_test_rand_u64(&rng) % 2 ? 1 : -1) * 2 * D;
            check_query(p, ctrl, NULL, q, "teapot");
        }
    }
    bs_surface_destroy(s);
}

#define R 2.5
static bs_patch *sphere_octant(double *ctrl, double *w)
{
    shape_sphere_octant_net(R, ctrl, w);
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(2, 2, 3, ctrl, w, &p), BS_OK);
    return p;
}

/* Seen from its centre every point of a sphere is closest: any answer, at distance R within
 * tau, and in bounded time. Near the centre the distance is nearly constant (the hardest case
 * for bounds of the distance, the easiest for bounds of its square). Also the octant elevated
 * to degree (8, 8). */
static void sphere_centre(void)
{
    double ctrl[27], w[9];
    bs_patch *p = sphere_octant(ctrl, w), *e = NULL;
    CHECK_STATUS(bs_patch_elevate(p, 6, 6, &e), BS_OK);
    const double q[4][3] = {{0, 0, 0}, {1e-7, 0, 0}, {0, -1e-5, 2e-5}, {0.3, 0.3, 0.3}};
    for (int k = 0; k < 4; k++) {
        answer a;
        check_query(p, ctrl, w, q[k], "sphere");
        CHECK_STATUS(closest(e, q[k], &a), BS_OK);
        double d = sqrt(q[k][0] * q[k][0] + q[k][1] * q[k][1] + q[k][2] * q[k][2]);
        double want = R - d; /* along the ray from the centre through q, or anywhere for q = 0 */
        if (k == 1 || k == 2) /* the nearest point of the octant is where the ray from the centre
                               * through q meets it, if it does; else on its boundary */
            continue;
        CHECKF(fabs(a.dist - want) <= 1e-9 * (2 * R + want), "elevated sphere: %.17g, want %.17g",
               a.dist, want);
    }
    bs_patch_destroy(e);
    bs_patch_destroy(p);
}

/* Huge and tiny coordinates: scaling the net and the query by a power of two scales the
 * distance exactly and keeps (u,v); near the top of the range the squares would overflow. */
static void scales(void)
{
    unsigned long long rng = 31;
    double ctrl[4 * 5 * 3], big[4 * 5 * 3], w[20], q[3], qb[3];
    random_net(&rng, 3, 4, 3, ctrl, w);
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(3, 4, 3, ctrl, w, &p), BS_OK);
    const int exps[] = {1000, 600, -600, -1000};
    for (int t = 0; t < 8; t++) {
        for (int c = 0; c < 3; c++)
            q[c] = bs_test_rand(&rng, -1, 2);
        answer a;
        CHECK_STATUS(closest(p, q, &a), BS_OK);
        check_query(p, ctrl, w, q, "scale 1");
        for (int x = 0; x < 4; x++) {
            for (int k = 0; k < 60; k++)
                big[k] = ldexp(ctrl[k], exps[x]);
            for (int c = 0; c < 3; c++)
                qb[c] = ldexp(q[c], exps[x]);
            bs_patch *pb;
            answer b;
            CHECK_STATUS(bs_patch_create(3, 4, 3, big, w, &pb), BS_OK);
            CHECK_STATUS(closest(pb, qb, &b), BS_OK);
            double ratio = ldexp(b.dist, -exps[x]) / a.dist;
            CHECKF(isfinite(b.dist) && fabs(ratio - 1) < 1e-9, "scale 2^%d: distance %.17g, unscaled %.17g",
                   exps[x], ldexp(b.dist, -exps[x]), a.dist);
            bs_patch_destroy(pb);
        }
    }
    bs_patch_destroy(p);
}

/* A cone: the side u = 0 collapsed to the apex. Points around the apex, beyond it, and on the
 * axis (every point of the rim circle equally far). */
static void cone(void)
{
    const double h = sqrt(0.5);
    double ctrl[18] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1}, w[6] = {1, h, 1, 1, h, 1};
    bs_patch *p;
    CHECK_STATUS(bs_patch_create(1, 2, 3, ctrl, w, &p), BS_OK);
    const double q[5][3] = {{0, 0, -1}, {0.1, 0.1, -0.05}, {-0.2, 0.3, 0.1}, {0, 0, 3}, {0.3, 0.4, 0.5}};
    for (int k = 0; k < 5; k++)
        check_query(p, ctrl, w, q[k], "cone");
    bs_patch_destroy(p);
}

/* A cylinder seen from its axis: the minima form a line of the domain (every point of a circle
 * is closest), at the patch's mid-height or not, and for the degree-elevated patch. */
static void cylinder_axis(void)
{
    double ctrl[18], w[6];
    shape_cylinder_quarter(R, 4.0, ctrl, w);
    bs_patch *p, *e;
    CHECK_STATUS(bs_patch_create(1, 2, 3, ctrl, w, &p), BS_OK);
    CHECK_STATUS(bs_patch_elevate(p, 4, 3, &e), BS_OK);
    const double q[4][3] = {{0, 0, 2}, {0, 0, 2.1}, {1e-9, 0, 1.3}, {0, 0, -0.5}};
    for (int k = 0; k < 4; k++) {
        check_query(p, ctrl, w, q[k], "cylinder axis");
        answer an;
        CHECK_STATUS(closest(e, q[k], &an), BS_OK);
        double want = k == 3 ? hypot(R, 0.5) : R - q[k][0]; /* below the rim, or radially out */
        CHECKF(fabs(an.dist - want) <= 1e-9 * (2 * R + want), "elevated cylinder: %.17g, want %.17g",
               an.dist, want);
    }
    bs_patch_destroy(e);
    bs_patch_destroy(p);
}

/* Degenerate nets: degree 0 in a direction or both, every point the same, a collapsed row in
 * the plane (a fold), weights from 1e-3 to 1e3, q on a control point. */
static void degenerate(void)
{
    static const size_t deg[][3] = {{0, 0, 3}, {0, 3, 3}, {4, 0, 2}, {2, 3, 3}, {3, 3, 2}, {3, 2, 3}};
    unsigned long long rng = 77;
    double ctrl[16 * 3], w[16], q[3];
    for (size_t t = 0; t < sizeof deg / sizeof deg[0]; t++) {
        size_t m = deg[t][0], n = deg[t][1], dim = deg[t][2], pts = (m + 1) * (n + 1);
        random_net(&rng, m, n, dim, ctrl, w);
        if (t == 3) /* every point the same */
            for (size_t k = 1; k < pts; k++)
                memcpy(ctrl + k * dim, ctrl, dim * sizeof(double));
        if (t == 4) /* row i = 0 collapsed */
            for (size_t j = 1; j <= n; j++)
                memcpy(ctrl + j * dim, ctrl, dim * sizeof(double));
        for (size_t k = 0; k < pts; k++)
            w[k] = t == 5 ? pow(10.0, bs_test_rand(&rng, -3, 3)) : w[k];
        bs_patch *p;
        CHECK_STATUS(bs_patch_create(m, n, dim, ctrl, w, &p), BS_OK);
        refp r = {{m, n, dim, ctrl, w}, q};
        for (int k = 0; k < 6; k++) {
            if (k == 0)
                memcpy(q, ctrl + (pts - 1) * dim, dim * sizeof(double));
            else
                point_near(&rng, &r, bs_test_rand(&rng, 0, 1), bs_test_rand(&rng, 0, 1), 0.5 * k, q);
            check_query(p, ctrl, w, q, "degenerate");
        }
        bs_patch_destroy(p);
    }
}

/* Argument rules, NaN queries, strided batches against one point at a time. */
static void arguments(void)
{
    double ctrl[27], w[9];
    bs_patch *p = sphere_octant(ctrl, w);
    double qx[3] = {1, NAN, 0.5}, qy[3] = {1, 1, INFINITY}, qz[3] = {1, 1, 1};
    double out[6][3];
    memset(out, 0, sizeof out);
    bs_cview q[3] = {{qx, 3, 0}, {qy, 3, 0}, {qz, 3, 0}};
    bs_view uv[2] = {{out[0], 3, 0}, {out[1], 3, 0}}, d = {out[2], 3, 0};
    bs_view pos[3] = {{out[3], 3, 0}, {out[4], 3, 0}, {out[5], 3, 0}};
    CHECK_STATUS(bs_patch_closest_point(NULL, 3, q, uv, &d, pos), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_patch_closest_point(p, 0, NULL, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_patch_closest_point(p, 3, NULL, uv, &d, pos), BS_ERR_INVALID_ARG);
    bs_cview qshort[3] = {q[0], {qy, 2, 0}, q[2]};
    CHECK_STATUS(bs_patch_closest_point(p, 3, qshort, uv, &d, pos), BS_ERR_SIZE);
    bs_cview qnull[3] = {q[0], {NULL, 3, 0}, q[2]};
    CHECK_STATUS(bs_patch_closest_point(p, 3, qnull, uv, &d, pos), BS_ERR_INVALID_ARG);
    bs_view odd[2] = {{(double *)(void *)((char *)out[0] + 1), 3, 0}, uv[1]};
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, odd, &d, pos), BS_ERR_INVALID_ARG);
    bs_view oddstride = {out[2], 3, 3};
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, uv, &oddstride, pos), BS_ERR_INVALID_ARG);
    bs_view dshort = {out[2], 2, 0};
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, uv, &dshort, pos), BS_ERR_SIZE);
    bs_view pshort[3] = {pos[0], pos[1], {out[5], 1, 0}};
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, uv, &d, pshort), BS_ERR_SIZE);
    int untouched = 1;
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 3; k++)
            untouched &= out[i][k] == 0.0;
    CHECK(untouched); /* nothing written by a failed check */
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, uv, &d, pos), BS_OK);
    CHECK(!isnan(out[0][0]) && !isnan(out[2][0]) && !isnan(out[5][0]));
    int nan = 1;
    for (int i = 0; i < 6; i++)
        nan &= isnan(out[i][1]) && isnan(out[i][2]);
    CHECK(nan); /* a NaN or infinite coordinate: NaN in every output of that point only */
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, NULL, NULL, NULL), BS_OK);
    CHECK_STATUS(bs_patch_closest_point(p, 3, q, NULL, &d, NULL), BS_OK);
    /* a strided batch (negative stride in, every other element out): one point at a time's bits */
    enum { NB = 20 };
    double in[3][NB], res[6][2 * NB];
    unsigned long long rng = 5;
    for (int k = 0; k < NB; k++)
        for (int c = 0; c < 3; c++)
            in[c][k] = bs_test_rand(&rng, -1, 4);
    bs_cview bq[3];
    for (int c = 0; c < 3; c++)
        bq[c] = (bs_cview){&in[c][NB - 1], NB, -(ptrdiff_t)sizeof(double)};
    bs_view bo[6];
    for (int i = 0; i < 6; i++)
        bo[i] = (bs_view){res[i], NB, 2 * (ptrdiff_t)sizeof(double)};
    CHECK_STATUS(bs_patch_closest_point(p, NB, bq, bo, bo + 2, bo + 3), BS_OK);
    int same = 1;
    for (int k = 0; k < NB; k++) {
        double one[3] = {in[0][NB - 1 - k], in[1][NB - 1 - k], in[2][NB - 1 - k]};
        answer a;
        closest(p, one, &a);
        double got[6] = {a.uv[0], a.uv[1], a.dist, a.pos[0], a.pos[1], a.pos[2]};
        for (int i = 0; i < 6; i++)
            same &= memcmp(&got[i], &res[i][2 * k], sizeof(double)) == 0;
    }
    CHECK(same);
    bs_patch_destroy(p);
}

int main(void)
{
    random_patches();
    teapot();
    sphere_centre();
    scales();
    cone();
    cylinder_axis();
    degenerate();
    printf("closest points: %d queries, largest excess over the reference %.3g tau (contract 1)\n",
           queries, worst_excess);
    arguments();
    return bs_test_exit("test_closest");
}
