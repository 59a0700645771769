/*
 * A ray against one sub-patch of the locator. The net is expressed in a frame of the ray: two
 * unit vectors e1, e2 across it and its unit direction d, so that X_k = w (P - o).e_k and
 * T = w (P - o).d are again a Bezier net (the homogeneous net when rational), and the hits are
 * the common zeros of (X1, X2): a 2-D Bezier patch. A piece of it is discarded when its projected
 * net keeps the origin outside its box (enlarged by the rounding of the projection and the
 * halvings, which is what keeps shared sides watertight: both patches see the same bits there),
 * or its t range lies outside what is wanted, or a few GJK steps show the origin outside the
 * convex hull of its points. Otherwise Newton's method on (X1, X2) (ray_piece.h), started where
 * the bilinear patch of the piece's corners meets the ray and kept inside the piece, looks for
 * the zero, with damped (Levenberg-Marquardt) steps that stay finite at poles, where X_s vanishes
 * along a side. A zero found is the only one
 * of its piece when the hodographs of (X1, X2) along s and along r lie in two cones that do not
 * meet (the map is then one to one there); a piece without one is discarded when the origin is
 * shown to lie outside the convex hull of its projected net. Anything else is halved in both
 * directions, the nearest quarter searched first, down to a fixed depth; a piece with a side
 * collapsed to a point (a pole) is halved across that side only. Halved in both directions, the
 * pieces along a pole would double at every level, each holding the pole, which lies close to a
 * ray through a point next to it, so that none could be discarded and the budget ran out before
 * the piece holding the hit was reached; halved across the pole, one piece a level holds it, and
 * its hull shrinks onto the pole until the ray leaves it. A rational piece whose weights hand
 * over from one side to the other is cut where they do, not halved (ray_split.h).
 */
#include "query/ray_piece.h"
#include "query/ray_split.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define MAX_DEPTH 12   /* levels below a leaf at most (a sub-patch 2^-14 of its patch) */
#define POLE_DEPTH 48  /* the same for pieces halved across a pole or a cusp edge (2^-50 of the patch) */
#define BUDGET 4096    /* pieces looked at per sub-patch at most: a bound on the time of any ray */
#define SLOTS (3 * POLE_DEPTH + 4)

size_t bsi_ray_leaf_scratch(size_t max_ctrl)
{
    return (size_t)(SLOTS + 3) * NC * max_ctrl;
}

/* The cone of the differences of the projected net along dir: its two extreme vectors lo, hi
 * (the others lie between them). 0 if they do not all lie within 90 degrees of their sum, or
 * none is left. Differences below 1e-9 of the largest are left out: at a pole (a collapsed side)
 * they vanish but for the rounding and the differing weights of the pole's copies, and every zero
 * on that side is the same point. work: scratch for 3 (m+1)(n+1) doubles (the differences, read
 * twice). */
static int cone(const double *net, size_t m, size_t n, int dir, double lo[2], double hi[2],
                double *work)
{
    size_t ni = dir == BS_DIR_U ? m : m + 1, nj = dir == BS_DIR_U ? n + 1 : n, nd = 0;
    size_t step = dir == BS_DIR_U ? (n + 1) * NC : NC;
    double sx = 0.0, sy = 0.0, big = 0.0, *dx = work, *dy = work + ni * nj, *dm = dy + ni * nj;
    for (size_t i = 0; i < ni; i++)
        for (size_t j = 0; j < nj; j++, nd++) {
            const double *a = net + (i * (n + 1) + j) * NC;
            double x = a[step] - a[0], y = a[step + 1] - a[1];
            dx[nd] = x;
            dy[nd] = y;
            dm[nd] = greater(fabs(x), fabs(y));
            sx += x;
            sy += y;
            big = greater(big, dm[nd]);
        }
    double tlo = INFINITY, thi = -INFINITY; /* tangents of the angles to the sum */
    for (size_t k = 0; k < nd; k++) {
        double x = dx[k], y = dy[k];
        if (!(dm[k] > 1e-9 * big))
            continue;
        double along = sx * x + sy * y, across = sx * y - sy * x;
        if (!(along > 0.0))
            return 0;
        double tn = across / along;
        if (tn < tlo) {
            tlo = tn;
            lo[0] = x;
            lo[1] = y;
        }
        if (tn > thi) {
            thi = tn;
            hi[0] = x;
            hi[1] = y;
        }
    }
    return tlo <= thi;
}

/* 1 if (X1, X2) is one to one on the sub-patch of this net: every difference along s crossed with
 * every difference along r has the same sign (checked on the cones' extremes, which span the
 * rest), so any two vectors of the cones the partials lie in are independent, and
 * N(q) - N(p) = ds A + dr B (A, B in those cones) vanishes only for ds = dr = 0. work: scratch as
 * for cone. */
static int one_to_one(const double *net, size_t m, size_t n, double *work)
{
    double s[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, r[2][2] = {{0.0, 0.0}, {0.0, 0.0}}; /* set by cone() */
    if (m == 0 || n == 0 || !cone(net, m, n, BS_DIR_U, s[0], s[1], work) ||
        !cone(net, m, n, BS_DIR_V, r[0], r[1], work))
        return 0;
    int pos = 0, neg = 0;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            double x = s[a][0] * r[b][1] - s[a][1] * r[b][0];
            double scale = (fabs(s[a][0]) + fabs(s[a][1])) * (fabs(r[b][0]) + fabs(r[b][1]));
            pos += x > 1e-9 * scale;
            neg += x < -1e-9 * scale;
        }
    return pos == 4 || neg == 4;
}

/* The differences of a net of 4-double points along u (point (i+1, j) - (i, j)) or along v, as
 * x, y, z and length; their count. */
static size_t net_differences(const double *net, size_t m, size_t n, int along_u, double (*d)[4])
{
    size_t row = (n + 1) * NC, step = along_u ? row : NC, count = 0;
    for (size_t i = 0; i + (along_u ? 1 : 0) <= m; i++)
        for (size_t j = 0; j + (along_u ? 0 : 1) <= n; j++, count++) {
            const double *p = net + i * row + j * NC;
            for (size_t c = 0; c < 3; c++)
                d[count][c] = p[step + c] - p[c];
            d[count][3] = sqrt(bsi_dot3(d[count], d[count]));
        }
    return count;
}

void bsi_ray_leaf_cone(const double *net, size_t m, size_t n, int rat, bsi_leaf_cone *cone)
{
    *cone = BSI_NO_CONE;
    size_t np = (m + 1) * (n + 1);
    if (rat || m == 0 || n == 0 || np > 64) /* pairs of differences: (mn)^2 cross products */
        return;
    double du[64][4], dv[64][4], su[3] = {0.0, 0.0, 0.0}, sv[3] = {0.0, 0.0, 0.0}, least = INFINITY;
    size_t nu = net_differences(net, m, n, 1, du), nv = net_differences(net, m, n, 0, dv);
    for (size_t k = 0; k < nu; k++) /* the sums, point by point as the net is stored */
        for (size_t c = 0; c < 3; c++)
            su[c] += du[k][c];
    for (size_t k = 0; k < nv; k++)
        for (size_t c = 0; c < 3; c++)
            sv[c] += dv[k][c];
    double axis[3];
    bsi_cross3(su, sv, axis);
    double alen = sqrt(bsi_dot3(axis, axis)), cmin = 1.0;
    if (!(alen > 0.0) || !isfinite(alen))
        return;
    for (size_t a = 0; a < nu; a++)
        for (size_t b = 0; b < nv; b++) {
            double x[3];
            bsi_cross3(du[a], dv[b], x);
            double la = du[a][3], lb = dv[b][3], lx = sqrt(bsi_dot3(x, x));
            if (!(lx >= 1e-3 * la * lb) || !(la * lb < INFINITY)) /* nearly parallel, or huge */
                return;
            cmin = lesser(cmin, bsi_dot3(x, axis) / (lx * alen));
            least = lesser(least, lesser(la, lb));
        }
    if (!(cmin > 0.0))
        return;
    double spread = sqrt(1.0 - cmin * cmin) + 1e-3;
    if (!(spread < 1.0))
        return;
    *cone = (bsi_leaf_cone){{axis[0] / alen, axis[1] / alen, axis[2] / alen}, spread, least};
}

/* 1 if the ray sees the leaf one to one by its cone of normals (bsi_leaf_cone), big being the
 * largest coordinate of the leaf's net seen from the ray's origin. */
static int cone_clear(const bsi_leaf_cone *cone, const bsi_ray *ray, double big)
{
    return fabs(bsi_dot3(cone->axis, ray->d)) > cone->spread && big <= 0x1p24 * cone->least;
}

/* 1 if the origin lies within tol of the box (lo, hi) in X1, X2 */
static inline int box_near(const double lo[3], const double hi[3], double tol)
{
    return lo[0] <= tol && hi[0] >= -tol && lo[1] <= tol && hi[1] >= -tol;
}

/* Box of the projected net (X / W; rat: the net is rational, else W = 1): 1 if the origin lies
 * within tol of it (X1, X2), with lo, hi its corners (X1, X2, T). */
SPECIALISE int near_origin(const double *net, size_t np, int rat, double tol, double lo[3],
                           double hi[3])
{
    for (int c = 0; c < 3; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t k = 0; k < np; k++) {
        const double *a = net + k * NC;
        double inv = rat ? 1.0 / a[3] : 1.0;
        double x = rat ? a[0] * inv : a[0], y = rat ? a[1] * inv : a[1], z = rat ? a[2] * inv : a[2];
        lo[0] = lesser(lo[0], x);
        hi[0] = greater(hi[0], x);
        lo[1] = lesser(lo[1], y);
        hi[1] = greater(hi[1], y);
        lo[2] = lesser(lo[2], z);
        hi[2] = greater(hi[2], z);
    }
    return box_near(lo, hi, tol);
}

/* The point of segment a b nearest to the origin into x; 1 if it lies strictly between them. */
static inline int segment_nearest(const double a[2], const double b[2], double x[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1], dd = dx * dx + dy * dy;
    double lam = dd > 0.0 ? -(a[0] * dx + a[1] * dy) / dd : 0.0;
    lam = lam < 0.0 ? 0.0 : lam > 1.0 ? 1.0 : lam;
    x[0] = a[0] + lam * dx;
    x[1] = a[1] + lam * dy;
    return lam > 0.0 && lam < 1.0;
}

/* 1 if the origin lies more than tol outside the convex hull of the projected net's points (the
 * net then has no zero); 0 if it lies within tol of it or inside; -1 if the steps ran out. The
 * certificate is a direction x with p.x > tol |x| for every point p of the net. x is found by a
 * few steps of Gilbert's iteration in the plane kept on a simplex (GJK): started at g, a point
 * of the hull (a corner of the net, or the point nearest to the ray that Newton found), each step
 * adds the support point opposite the current nearest point and moves to the nearest point of
 * the simplex, an edge of the hull or a triangle holding the origin. pts: scratch for np points
 * when rat (a polynomial net is read as it is). Boxes that only skim the ray are excluded long
 * before their axis-aligned box is. */
SPECIALISE int separated(const double *net, size_t np, int rat, const double g[2], double tol,
                         double *pts)
{
    size_t st = rat ? 2 : NC;
    if (rat) {
        for (size_t k = 0; k < np; k++) {
            double inv = 1.0 / net[k * NC + 3];
            pts[2 * k] = net[k * NC] * inv;
            pts[2 * k + 1] = net[k * NC + 1] * inv;
        }
    } else
        pts = (double *)net;
    double x[2] = {g[0], g[1]}, sa[2] = {g[0], g[1]}, sb[2] = {0.0, 0.0};
    int ns = 1; /* the simplex: sa, or the edge sa sb */
    for (int it = 0; it < 8; it++) {
        double len = norm2(x[0], x[1]);
        if (!(len > tol))
            return 0;
        size_t at = 0;
        double low = INFINITY;
        for (size_t k = 0; k < np; k++) {
            double h = pts[st * k] * x[0] + pts[st * k + 1] * x[1];
            if (h < low) {
                low = h;
                at = k;
            }
        }
        if (low > tol * len)
            return 1;
        double c[2] = {pts[st * at], pts[st * at + 1]};
        if (ns == 1) {
            ns = segment_nearest(sa, c, x) ? 2 : 1;
            if (ns == 2) {
                sb[0] = c[0];
                sb[1] = c[1];
            } else if (x[0] == c[0] && x[1] == c[1]) {
                sa[0] = c[0];
                sa[1] = c[1];
            }
            continue;
        }
        /* the triangle sa sb c: the origin inside it lies in the hull */
        double d1 = (sb[0] - sa[0]) * -sa[1] - (sb[1] - sa[1]) * -sa[0];
        double d2 = (c[0] - sb[0]) * -sb[1] - (c[1] - sb[1]) * -sb[0];
        double d3 = (sa[0] - c[0]) * -c[1] - (sa[1] - c[1]) * -c[0];
        if ((d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0) || (d1 <= 0.0 && d2 <= 0.0 && d3 <= 0.0))
            return 0;
        /* else the nearest point of its edges through c */
        double xa[2], xb[2];
        int ia = segment_nearest(sa, c, xa), ib = segment_nearest(sb, c, xb);
        int use_a = xa[0] * xa[0] + xa[1] * xa[1] <= xb[0] * xb[0] + xb[1] * xb[1];
        double *keep = use_a ? sa : sb, *xn = use_a ? xa : xb;
        int inner = use_a ? ia : ib;
        x[0] = xn[0];
        x[1] = xn[1];
        sa[0] = inner ? keep[0] : x[0];
        sa[1] = inner ? keep[1] : x[1];
        sb[0] = c[0];
        sb[1] = c[1];
        ns = inner ? 2 : 1;
    }
    return -1;
}

/* Of the four corners of the projected net (points of the surface), the one nearest to the
 * origin, as (X1, X2) / W into g. */
SPECIALISE void nearest_corner(const double *net, size_t m, size_t n, int rat, double g[2])
{
    const size_t corner[4] = {0, n, m * (n + 1), m * (n + 1) + n};
    double best = INFINITY;
    for (int k = 0; k < 4; k++) {
        const double *a = net + corner[k] * NC;
        double x = WDIV(rat, a[0], a[3]), y = WDIV(rat, a[1], a[3]), d = x * x + y * y;
        if (d < best) {
            best = d;
            g[0] = x;
            g[1] = y;
        }
    }
}

/* The leaf's net in the ray's frame from origin o, and its box as near_origin makes it (rbox:
 * lower corner, upper corner); returns the largest |P - o| coordinate. (w times each product: for
 * a polynomial net w = 1, and the product itself is the same bits.) */
SPECIALISE double project(const double *net, size_t np, int rat, const bsi_ray *ray, const double o[3],
                          double *out, double rbox[6])
{
    double big = 0.0, lo0 = INFINITY, lo1 = INFINITY, lo2 = INFINITY;
    double hi0 = -INFINITY, hi1 = -INFINITY, hi2 = -INFINITY;
    for (size_t k = 0; k < np; k++) {
        const double *p = net + k * NC;
        double a[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]}, w = p[3];
        double *q = out + k * NC, inv = rat ? 1.0 / w : 1.0;
        q[0] = rat ? w * bsi_dot3(a, ray->e1) : bsi_dot3(a, ray->e1);
        q[1] = rat ? w * bsi_dot3(a, ray->e2) : bsi_dot3(a, ray->e2);
        q[2] = rat ? w * bsi_dot3(a, ray->d) : bsi_dot3(a, ray->d);
        q[3] = w;
        double x = rat ? q[0] * inv : q[0], y = rat ? q[1] * inv : q[1], z = rat ? q[2] * inv : q[2];
        lo0 = lesser(lo0, x);
        hi0 = greater(hi0, x);
        lo1 = lesser(lo1, y);
        hi1 = greater(hi1, y);
        lo2 = lesser(lo2, z);
        hi2 = greater(hi2, z);
        big = greater(big, greater(fabs(a[0]), greater(fabs(a[1]), fabs(a[2]))));
    }
    rbox[0] = lo0;
    rbox[1] = lo1;
    rbox[2] = lo2;
    rbox[3] = hi0;
    rbox[4] = hi1;
    rbox[5] = hi2;
    return big;
}

/* 1 when the largest |P - o| of a leaf is within [2^-64, 2^64], else the power of two that
 * brings it near 1: the products of Newton's step, of the cones and of the hull test are then
 * formed without overflow or underflow (rays at surfaces beyond about 1e77 or below 1e-77 from
 * their origin missed), and the scaling is exact. The usual range keeps its bits. */
static double leaf_scale(double big)
{
    if (!(big > 0.0 && big <= DBL_MAX) || (big >= 0x1p-64 && big <= 0x1p64))
        return 1.0;
    int e = 0;
    (void)frexp(big, &e);
    return ldexp(1.0, -e);
}

/* 1 unless the locator is a model's and the point (s, r) of the leaf lies outside its face's trim */
static int inside_trim(const bs_locator *L, const bsi_loc_leaf *leaf, double s, double r)
{
    const double side = 1.0 / BSI_LOC_SPLIT;
    return L->trim == NULL || L->trim->inside(L->trim, leaf->patch, leaf->u0 + s * side, leaf->v0 + r * side);
}

static int wanted(const bsi_ray *ray, double t, double best)
{
    return (ray->open ? t > ray->tmin : t >= ray->tmin) && t <= ray->tmax && t < best;
}

/* bsi_ray_leaf for a rational net (rat) or a polynomial one, each compiled for its case */
SPECIALISE void search(const bs_locator *L, size_t k, const bsi_ray *ray, double *scratch,
                       bsi_ray_hit *hit, int rat)
{
    const bsi_loc_leaf *leaf = &L->leaves[k];
    const bs_patch *p = L->patches[leaf->patch];
    size_t m = p->deg_u, n = p->deg_v, np = p->nctrl, len = NC * np;
    double *root = scratch, *half[2] = {root + len, root + 2 * len}, *slot = root + 3 * len;
    /* the net of a patch beyond 2^512 or below 2^-900 is stored times ps, and o is taken alike */
    const double *net0 = L->nets + leaf->net;
    double ps;
    (void)bsi_loc_patch(L, leaf->patch, &ps);
    double o[3] = {ray->o[0] * ps, ray->o[1] * ps, ray->o[2] * ps};
    if (!bsi_finite3(o)) { /* a patch below 2^-1000 seen from beyond 2^23: the ray's units */
        for (size_t q = 0; q < len; q++)
            half[0][q] = q % NC < 3 ? net0[q] / ps : net0[q];
        net0 = half[0];
        ps = 1.0;
        memcpy(o, ray->o, sizeof o);
    }
    double rbox[6], big = project(net0, np, rat, ray, o, root, rbox);
    /* every piece is one to one (not asked of a net taken back to the ray's units: the cone's
     * least difference is in the stored net's) */
    int clear = net0 == L->nets + leaf->net && cone_clear(&leaf->cone, ray, big);
    /* the leaf's frame scaled by sig at extreme distances: lengths below are the ray's times
     * ps sig, t as well (t / sig / ps is the ray's) */
    double sig = leaf_scale(big), diag = fmin(DBL_MAX, L->diag * ps);
    if (sig != 1.0) {
        for (size_t q = 0; q < np; q++)
            for (size_t c = 0; c < 3; c++)
                root[q * NC + c] *= sig;
        for (int c = 0; c < 6; c++)
            rbox[c] *= sig;
        big *= sig;
        diag = fmin(DBL_MAX, diag * sig);
    }
    double tmin = ray->tmin * ps * sig;
    /* rounding of the projection and of the halvings, and the distance accepted as a hit */
    double tol = 1e-13 * diag + 256 * DBL_EPSILON * big;
    double accept = 1e-11 * diag + 1024 * DBL_EPSILON * big, floor_dist = 4 * DBL_EPSILON * big;
    /* slots: those freed, then those never used; the leaf's own net stays in root (slot -1) */
    int free_slot[SLOTS], nfree = 0, unused = 0, top = 0;
    pending stack[SLOTS];
    stack[top++] = (pending){0.0, 0.0, 1.0, 1.0, -INFINITY, 0, 0, -1};
    for (int looked = 0; top > 0 && looked < BUDGET; looked++) {
        pending e = stack[--top];
        double *net = e.slot < 0 ? root : slot + (size_t)e.slot * len, lo[3], hi[3];
        double tmax = lesser(hit->t, ray->tmax) * ps * sig;
        if (e.slot >= 0)
            free_slot[nfree++] = e.slot;
        int near;
        if (e.slot < 0) { /* the leaf's own box, made with its projection */
            for (int c = 0; c < 3; c++) {
                lo[c] = rbox[c];
                hi[c] = rbox[3 + c];
            }
            near = box_near(lo, hi, tol);
        } else
            near = near_origin(net, np, rat, tol, lo, hi);
        if (e.tlo > tmax || !near || hi[2] + tol < tmin || lo[2] - tol > tmax)
            continue;
        double within = greater(greater(-lo[0], hi[0]), greater(-lo[1], hi[1]));
        /* most pieces the box test lets through hold no zero: shown first, without Newton,
         * from the corner of the net nearest to the ray */
        double s, r, t, g[2] = {0.0, 0.0};
        nearest_corner(net, m, n, rat, g);
        int sep = separated(net, np, rat, g, tol, half[1]);
        if (sep > 0)
            continue;
        bilinear_start(net, m, n, rat, &e, &s, &r);
        int found = newton(root, m, n, rat, &e, s, r, floor_dist, accept, &s, &r, &t, g);
        found |= within <= accept && isfinite(t); /* every point of the piece is near enough */
        if (found && wanted(ray, t / sig / ps, hit->t) && inside_trim(L, leaf, s, r)) {
            hit->t = t / sig / ps;
            hit->s = s;
            hit->r = r;
            hit->leaf = k;
        }
        /* done: a zero shown to be the only one; no zero; a piece wholly within the accepted
         * distance of the ray (seen from far away), where Newton's point is as good a hit as any */
        if ((found && (clear || one_to_one(net, m, n, half[1]))) || (!found && sep < 0 && separated(net, np, rat, g, tol, half[1]) > 0) ||
            within <= accept || e.level >= POLE_DEPTH)
            continue;
        int dir = pole_split(net, m, n, rat, lo, hi);
        /* past MAX_DEPTH only next to a singular corner (partials within 2^-8 of parallel at a
         * corner), where a hit may lie on the boundary of pieces Newton cannot settle */
        if (dir == -1 && e.depth >= MAX_DEPTH && !singular_corner(net, m, n, rat, 0x1p-8, 0.0))
            continue;
        /* the four parts (two across a pole), nearest t first: halves, or cut where the weights
         * hand over (fs, fr: the fractions of the width that the first parts take) */
        pending kids[4];
        int nk = 0;
        double fs = dir == BS_DIR_V ? 1.0 : handover(net, m, n, rat, BS_DIR_U);
        double fr = dir == BS_DIR_U ? 1.0 : handover(net, m, n, rat, BS_DIR_V);
        net_cut(net, m, n, dir < 0 ? BS_DIR_U : dir, dir == BS_DIR_V ? fr : fs, half[0], half[1]);
        for (int a = 0; a < 2; a++) {
            double *cn[2];
            int nb = dir < 0 ? 2 : 1;
            for (int b = 0; b < nb; b++) {
                pending *c = &kids[nk + b];
                int ia = dir == BS_DIR_V ? 0 : a, ib = dir == BS_DIR_V ? a : b;
                double ws = ia ? (1.0 - fs) * e.w : fs * e.w, wr = ib ? (1.0 - fr) * e.wr : fr * e.wr;
                *c = (pending){e.s0 + ia * fs * e.w, e.r0 + ib * fr * e.wr, ws, wr,
                               INFINITY, e.depth + (dir < 0), e.level + 1,
                               nfree > 0 ? free_slot[--nfree] : unused++};
                cn[b] = slot + (size_t)c->slot * len;
            }
            if (dir < 0)
                net_cut(half[a], m, n, BS_DIR_V, fr, cn[0], cn[1]);
            else
                for (size_t q = 0; q < len; q++)
                    cn[0][q] = half[a][q];
            nk += nb;
        }
        for (int a = 0; a < nk; a++) {
            pending *c = &kids[a];
            const double *cn = slot + (size_t)c->slot * len;
            for (size_t q = 0; q < np; q++)
                c->tlo = lesser(c->tlo, WDIV(rat, cn[q * NC + 2], cn[q * NC + 3]));
            c->tlo -= tol;
        }
        for (int a = 1; a < nk; a++) /* insertion sort, farthest first onto the stack */
            for (int b = a; b > 0 && kids[b].tlo > kids[b - 1].tlo; b--) {
                pending x = kids[b];
                kids[b] = kids[b - 1];
                kids[b - 1] = x;
            }
        for (int a = 0; a < nk; a++)
            stack[top++] = kids[a];
    }
}

void bsi_ray_leaf(const bs_locator *L, size_t k, const bsi_ray *ray, double *scratch,
                  bsi_ray_hit *hit)
{
    if (L->patches[L->leaves[k].patch]->rational)
        search(L, k, ray, scratch, hit, 1);
    else
        search(L, k, ray, scratch, hit, 0);
}
