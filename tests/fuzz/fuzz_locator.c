/* libFuzzer target for the geometric queries (bezsurf/query.h): a small random patch (degrees 1 to
 * 5, polynomial or rational with weights 2^-w..2^w up to w = 40 (12 above degree (2,2)), sides
 * collapsed to poles) scaled
 * by 2^e over the exponent range the library serves, a copy scaled by another power of two, and
 * queries on both. Oracles besides "no crash, no leak, no out-of-bounds access":
 * - closest points (bs_patch_closest_point and a locator of the patch): BS_OK or BS_ERR_PRECISION,
 *   the same from both; a distance never farther than any corner or any point of a 9 x 9 grid,
 *   nor than the minimum of a 17 x 17 grid refined by projected Gauss-Newton, by more than
 *   tau = 1e-9 (D + d);
 * - rays down the normal at sampled regular points from a height h above them hit no later than
 *   h (plus tau);
 * - the scaled copy: the same normal kinds and normals, the same curvature kinds, the same
 *   curvatures scaled (away from collapsed sides, where they are ill-conditioned), the same
 *   closest distances scaled, and its rays hitting no later than the scaled height. */
#include <bezsurf.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Binary exponents served: control points up to about 2^(E_MAX + 3), down to 2^(E_MIN - 1). */
#define E_MIN -1000
#define E_MAX 1000

typedef struct reader {
    const uint8_t *p;
    size_t n;
} reader;

static unsigned rd_byte(reader *r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

/* An exponent in [lo, hi] from two bytes. */
static int rd_exp(reader *r, int lo, int hi)
{
    unsigned x = rd_byte(r) << 8 | rd_byte(r);
    return lo + (int)(x % (unsigned)(hi - lo + 1));
}

/* A coordinate in [-1, 1] on a grid of 1/128. */
static double rd_coord(reader *r) { return ((double)rd_byte(r) - 128.0) / 128.0; }

/* A parameter in [0, 1]: mostly inside, 0 and 1 and points 2^-k from the sides too. */
static double rd_param(reader *r)
{
    unsigned b = rd_byte(r);
    if (b < 200)
        return (double)b / 199.0;
    int k = 4 + (int)(b % 24);
    return b % 2 ? ldexp(1.0, -k) : 1.0 - ldexp(1.0, -k);
}

static void fail(void) { abort(); }

static double dist3(const double *a, const double *b)
{
    double s = fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
    if (s == 0.0)
        return 0.0;
    double x = (a[0] - b[0]) / s, y = (a[1] - b[1]) / s, z = (a[2] - b[2]) / s;
    return s * sqrt(x * x + y * y + z * z);
}

/* S, S_u, S_v at (u, v). */
static void eval1(const bs_patch *p, double u, double v, double *x, double *xu, double *xv)
{
    double du[3], dv[3];
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view o[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
    bs_view ou[3] = {{&du[0], 1, 0}, {&du[1], 1, 0}, {&du[2], 1, 0}};
    bs_view ov[3] = {{&dv[0], 1, 0}, {&dv[1], 1, 0}, {&dv[2], 1, 0}};
    if (bs_patch_eval(p, 1, &cu, &cv, o, xu ? ou : NULL, xv ? ov : NULL) != BS_OK)
        fail();
    for (int c = 0; c < 3; c++) {
        if (xu)
            xu[c] = du[c];
        if (xv)
            xv[c] = dv[c];
    }
}

/* An upper bound on the distance from q to p: the best of a (g+1) x (g+1) grid, its three best
 * refined by projected Gauss-Newton (in units of the scale s, to keep the squares
 * safe). */
static double brute(const bs_patch *p, const double *q, int g, int refine, double s)
{
    double best = INFINITY, cand[3][3] = {{INFINITY, 0, 0}, {INFINITY, 0, 0}, {INFINITY, 0, 0}};
    for (int i = 0; i <= g; i++)
        for (int j = 0; j <= g; j++) {
            double u = (double)i / g, v = (double)j / g, x[3];
            eval1(p, u, v, x, NULL, NULL);
            double d = dist3(x, q);
            best = fmin(best, d);
            for (int k = 0; k < 3; k++)
                if (d < cand[k][0]) {
                    for (int l = 2; l > k; l--)
                        memcpy(cand[l], cand[l - 1], sizeof cand[l]);
                    cand[k][0] = d;
                    cand[k][1] = u;
                    cand[k][2] = v;
                    break;
                }
        }
    for (int k = 0; refine && k < 3; k++) {
        double u = cand[k][1], v = cand[k][2];
        for (int it = 0; it < 30; it++) {
            double x[3], xu[3], xv[3], a = 0, b = 0, c = 0, gu = 0, gv = 0;
            eval1(p, u, v, x, xu, xv);
            best = fmin(best, dist3(x, q));
            for (int d = 0; d < 3; d++) {
                double r = (x[d] - q[d]) / s, su = xu[d] / s, sv = xv[d] / s;
                a += su * su;
                b += su * sv;
                c += sv * sv;
                gu += su * r;
                gv += sv * r;
            }
            double det = a * c - b * b;
            if (!(det > 1e-300))
                break;
            double nu = u - (c * gu - b * gv) / det, nv = v - (a * gv - b * gu) / det;
            nu = nu < 0 ? 0 : nu > 1 ? 1 : nu;
            nv = nv < 0 ? 0 : nv > 1 ? 1 : nv;
            if (!(nu == nu && nv == nv) || (nu == u && nv == v))
                break;
            u = nu;
            v = nv;
        }
    }
    return best;
}

typedef struct closest_out {
    bs_status st;
    double d;
} closest_out;

/* The closest point to q through the patch and through the locator: the same status, the
 * distance within tau of each other. */
static closest_out closest(const bs_patch *p, const bs_locator *L, const double *q, double D)
{
    double u = 0, v = 0, d = -1, d2 = -1;
    uint32_t id = 7;
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    bs_view uv[2] = {{&u, 1, 0}, {&v, 1, 0}}, dv = {&d, 1, 0}, dv2 = {&d2, 1, 0};
    closest_out r = {bs_patch_closest_point(p, 1, qv, uv, &dv, NULL), d};
    bs_status st2 = bs_locator_closest_point(L, 1, qv, &id, NULL, &dv2, NULL);
    if (r.st != st2 || (r.st != BS_OK && r.st != BS_ERR_PRECISION))
        fail();
    if (r.st != BS_OK) {
        if (d != -1 || d2 != -1 || id != 7) /* nothing written */
            fail();
        return r;
    }
    double tau = 1e-9 * (D + d);
    if (!(fabs(d - d2) <= 2 * tau) || id != 0)
        fail();
    r.d = d;
    return r;
}

/* A ray from h above S(u, v) down its unit normal: a hit no later than h (t from the origin). */
static double ray_down(const bs_locator *L, const double *x, const double *nrm, double h, double tau)
{
    double o[3], d[3], t = -1;
    uint32_t id = 7;
    for (int c = 0; c < 3; c++) {
        o[c] = x[c] + h * nrm[c];
        d[c] = -nrm[c];
    }
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dv[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_view tv = {&t, 1, 0};
    if (bs_locator_intersect(L, 1, ov, dv, NULL, &id, NULL, &tv, NULL) != BS_OK)
        fail();
    if (id != 0 || !(t <= h + tau))
        fail();
    return t;
}

static double diagonal(const double *ctrl, size_t np)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < np; k++)
        for (size_t c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], ctrl[3 * k + c]);
            hi[c] = fmax(hi[c], ctrl[3 * k + c]);
        }
    return dist3(lo, hi);
}

static bs_locator *locator_of(const bs_patch *p)
{
    bs_surface *s = NULL;
    bs_locator *L = NULL;
    if (bs_surface_create(&s) != BS_OK || bs_surface_add(s, p, NULL) != BS_OK ||
        bs_locator_create(s, &L) != BS_OK) {
        bs_surface_destroy(s);
        return NULL; /* out of memory only */
    }
    bs_surface_destroy(s);
    return L;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader r = {data, size};
    size_t m = 1 + rd_byte(&r) % 5, n = 1 + rd_byte(&r) % 5, np = (m + 1) * (n + 1);
    unsigned flags = rd_byte(&r);
    /* weight exponents up to 40 on bilinear to biquadratic nets, 12 above (a rational search
     * with wide weights may take the whole box cap, seconds under the sanitizers) */
    int rational = flags & 1, wexp = (int)(rd_byte(&r) % (m * n <= 4 ? 41u : 13u));
    int e1 = rd_exp(&r, E_MIN, E_MAX), e2 = rd_exp(&r, E_MIN, E_MAX);
    double ctrl[3 * 36], ctrl2[3 * 36], wt[36];
    for (size_t k = 0; k < np; k++) {
        for (size_t c = 0; c < 3; c++)
            ctrl[3 * k + c] = rd_coord(&r);
        wt[k] = rational ? ldexp(1.0, wexp ? (int)(rd_byte(&r) % (unsigned)(2 * wexp + 1)) - wexp : 0) : 1.0;
    }
    /* collapsed sides (bits 1..4: u = 0, u = 1, v = 0, v = 1), each to its first point */
    for (int side = 0; side < 4; side++) {
        if (!(flags >> (side + 1) & 1))
            continue;
        size_t count = side < 2 ? n + 1 : m + 1, first = side == 1 ? m * (n + 1) : side == 3 ? n : 0;
        size_t step = side < 2 ? 1 : n + 1;
        for (size_t k = 1; k < count; k++)
            for (size_t c = 0; c < 3; c++)
                ctrl[3 * (first + k * step) + c] = ctrl[3 * first + c];
    }
    double s1 = ldexp(1.0, e1), s2 = ldexp(1.0, e2);
    /* the two copies are one surface unless a coordinate lost bits in the subnormal range: then
     * their normals and curvatures next to a collapsed side (ill-conditioned there, as eps over
     * the squared distance) may rightly differ by far more than the comparisons below allow */
    int exact = 1;
    for (size_t k = 0; k < 3 * np; k++) {
        double unit = ctrl[k];
        ctrl2[k] = unit * s2;
        ctrl[k] = unit * s1;
        exact &= ldexp(ctrl2[k], -e2) == unit && ldexp(ctrl[k], -e1) == unit;
    }
    bs_patch *p = NULL, *p2 = NULL;
    if (bs_patch_create(m, n, 3, ctrl, rational ? wt : NULL, &p) != BS_OK ||
        bs_patch_create(m, n, 3, ctrl2, rational ? wt : NULL, &p2) != BS_OK) {
        bs_patch_destroy(p);
        return 0;
    }
    double D = diagonal(ctrl, np), D2 = diagonal(ctrl2, np);
    bs_locator *L = locator_of(p), *L2 = locator_of(p2);
    if (L == NULL || L2 == NULL || !(D > 0.0))
        goto done;
    /* closest points: a query near the patch (within 2 D of the unit net's box) */
    for (int k = 0; k < 1; k++) {
        double q[3], q2[3];
        for (int c = 0; c < 3; c++) {
            double x = 2.0 * rd_coord(&r);
            q[c] = x * s1;
            q2[c] = x * s2;
        }
        closest_out a = closest(p, L, q, D), b = closest(p2, L2, q2, D2);
        (void)L2;
        if (a.st != BS_OK || b.st != BS_OK)
            continue;
        double tau = 1e-9 * (D + a.d);
        if (!(a.d <= brute(p, q, 8, 0, s1) + tau) || !(a.d <= brute(p, q, 16, 1, s1) + tau))
            fail();
        /* the scaled copy's distance is the scaled distance */
        if (!(fabs(ldexp(b.d, e1 - e2) - a.d) <= 2 * tau))
            fail();
    }
    /* normals, curvature and rays at sampled points */
    for (int k = 0; k < 3; k++) {
        double u = rd_param(&r), v = rd_param(&r), x[3], nrm[3], x2[3], nrm2[3];
        double curv[4], curv2[4];
        unsigned char kind = 9, kind2 = 9, ck = 9, ck2 = 9;
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        bs_view nv[3] = {{&nrm[0], 1, 0}, {&nrm[1], 1, 0}, {&nrm[2], 1, 0}};
        bs_view xv2[3] = {{&x2[0], 1, 0}, {&x2[1], 1, 0}, {&x2[2], 1, 0}};
        bs_view nv2[3] = {{&nrm2[0], 1, 0}, {&nrm2[1], 1, 0}, {&nrm2[2], 1, 0}};
        bs_view kv[4] = {{&curv[0], 1, 0}, {&curv[1], 1, 0}, {&curv[2], 1, 0}, {&curv[3], 1, 0}};
        bs_view kv2[4] = {{&curv2[0], 1, 0}, {&curv2[1], 1, 0}, {&curv2[2], 1, 0}, {&curv2[3], 1, 0}};
        if (bs_patch_eval_normal(p, 1, &cu, &cv, xv, nv, &kind) != BS_OK ||
            bs_patch_eval_normal(p2, 1, &cu, &cv, xv2, nv2, &kind2) != BS_OK)
            fail();
        /* the same kind and normal on the scaled copy (next to a collapsed side the normal is
         * ill-conditioned: two correct evaluations differ by up to eps over the squared distance) */
        int inner = !(flags & 0x1e) || (u >= 1.0 / 32 && u <= 31.0 / 32 && v >= 1.0 / 32 && v <= 31.0 / 32);
        if (exact && (kind != kind2 || !(fabs(nrm[0] - nrm2[0]) + fabs(nrm[1] - nrm2[1]) + fabs(nrm[2] - nrm2[2]) <=
                                         (inner ? 1e-9 : 1e-5))))
            fail();
        if (kind != BS_NORMAL_UNDEFINED && !(fabs(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2] - 1.0) <= 1e-12))
            fail();
        if (bs_patch_eval_curvature(p, 1, &cu, &cv, kv, NULL, NULL, &ck) != BS_OK ||
            bs_patch_eval_curvature(p2, 1, &cu, &cv, kv2, NULL, NULL, &ck2) != BS_OK)
            fail();
        if (exact && ck != ck2)
            fail();
        /* the values where they are well conditioned: next to a collapsed side two correct
         * evaluations may differ by far more than their rounding */
        if (exact && ck == BS_CURV_REGULAR && !(flags & 0x1e)) {
            /* k scales by 2^(e2 - e1): compare k_min, k_max with the larger of them as scale */
            double big = fmax(fabs(curv[2]), fabs(curv[3])) + 1.0 / D;
            for (int c = 2; c < 4; c++) { /* equal infinities where the curvature overflows */
                double want = ldexp(curv2[c], e2 - e1);
                /* the copy's curvature may overflow where this one does not: then its infinity
                 * is the right answer (curvature 2^40 times 2.2e298 seen) */
                if (isinf(curv2[c]) && !(fabs(ldexp(curv[c], e1 - e2)) < 0x1p-1 * DBL_MAX))
                    continue;
                if (!(want == curv[c] || fabs(want - curv[c]) <= 1e-7 * big))
                    fail();
            }
        }
        if (kind != BS_NORMAL_REGULAR || !(u > 0.0 && u < 1.0 && v > 0.0 && v < 1.0))
            continue;
        double h = ldexp(D, -(int)(rd_byte(&r) % 12)), tau = 1e-9 * D + 0x1p-40 * h;
        double t = ray_down(L, x, nrm, h, tau);
        double t2 = kind2 != BS_NORMAL_REGULAR ? 0.0 : ray_down(L2, x2, nrm2, ldexp(h, e2 - e1), ldexp(tau, e2 - e1));
        (void)t;
        (void)t2;
    }
done:
    bs_locator_destroy(L);
    bs_locator_destroy(L2);
    bs_patch_destroy(p);
    bs_patch_destroy(p2);
    return 0;
}
