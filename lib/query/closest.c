/*
 * Closest points on one patch (bezsurf/query.h): branch and bound over boxes of the domain.
 *
 * A box holds its sub-net (de Casteljau halving of its parent's, closest_bound.c). It is
 * discarded when a lower bound on the distance over it is at least the best distance found so
 * far minus the tolerance T = 0.5e-9 (D + best), which keeps half of the contract's tau for the
 * final rounding: when every box is gone, no point of the patch is closer than best - T. The
 * bounds are the bounding box of the sub-net (first order, cheap, tried first) and the smallest
 * Bernstein coefficient of f = |S - q|^2 (second order, closest_bound.c); the second shrinks as
 * h^2 |f''| for a box of size h, so the boxes around a minimum stop splitting after a few levels
 * instead of ~1/tau boxes. Surviving boxes are split across their longer side, depth first, the
 * child with the nearer bounding box first. In a surviving box the point of its smallest
 * coefficient is a candidate: where f there is below the best, projected Newton over the whole
 * domain (closest_newton.c) polishes it, so the best is a local minimum (interior, on an edge or
 * at a corner) as soon as there is one below it, and a square around it is certified by
 * convexity (certify below), which prunes the boxes next to the minimum at any size. Every bound
 * allows for the rounding of the halving, of the coefficients and of the evaluation.
 *
 * The work is capped (BOX_CAP boxes a query, w->depth levels): a search that reaches the cap,
 * or a box that survives at the deepest level, leaves the answer uncertified, which the callers
 * report as BS_ERR_PRECISION rather than give an answer that may be wrong.
 */
#include "query/closest.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* Boxes (second-order bounds computed) per query at most. */
#define BOX_CAP 20000

typedef struct box {
    double u0, u1, v0, v1, aabb;
    unsigned depth, slot;
    int dir;   /* the direction to split it (set when it survives), -1 for none */
    int where; /* BSI_CL_IN, or BSI_CL_CROSS until known (a search held to a part) */
} box;

/* Rounding of the Cartesian points of the nets of boxes at depth k (scaled units, the root
 * net's distances below 1): each halving moves a point by at most max(m,n) half-ulps of the
 * net's magnitude. For a rational net the midpoint of two homogeneous points w_a x_a and w_b x_b
 * is off by at most half an ulp of (w_a + w_b)/2 max|x|, the weight of the midpoint times the
 * largest distance: the errors stay proportional to the weights, level after level, and so does
 * the weights' own relative error (sums of positive terms). Dividing by the weight therefore
 * does not amplify them, whatever the weight ratio: twice the polynomial bound holds both. */
static double net_error(const bsi_cl *w, unsigned depth)
{
    size_t deg = w->m > w->n ? w->m : w->n;
    double e = ((double)depth + 4.0) * ((double)deg + 1.0) * 2.0 * DBL_EPSILON;
    return w->nc > w->dim ? 2.0 * e : e;
}

/* Regions around minima certified by convexity, kept at once. */
#define REGIONS 8

/* A box of the domain [x0, x1] x [x2, x3] over which the distance is at least lb. */
typedef struct region {
    double x[4], lb;
} region;

/* The best point so far and what it is compared with. */
typedef struct search {
    double incoming; /* the caller's best distance (scaled), INFINITY for none */
    double f, uv[2]; /* own best: f and where (f = INFINITY: none yet) */
    double diag;     /* D (scaled) for the tolerance */
    region reg[REGIONS];
    unsigned nreg;   /* regions filled, the next one replaced is nreg % REGIONS */
    int uncertified; /* a box was left that could not be pruned (the cap, or the deepest level) */
    const bsi_cl_part *part; /* NULL, or the part of the domain the search is held to */
} search;

static double current(const search *s) { return fmin(s->incoming, sqrt(s->f)); }

static double tolerance(const search *s)
{
    double c = current(s);
    return 0.5e-9 * (s->diag + (isfinite(c) ? c : 0.0));
}

/* 1 when a lower bound lb on the distance over a box cannot beat the best by more than T. */
static int pruned(const search *s, double lb) { return lb >= current(s) - tolerance(s); }

/* Certify a square around the best point x* (a local minimum from Newton) in which no point
 * is closer: the second-order closure. With c = f(x*) and G = N - c W (G >= 0 exactly where
 * f >= c; G(x*) = 0), if G is convex over the square, with Hessian at least lambda, then
 * G(x) >= g_G . (x - x*) + lambda/2 |x - x*|^2 there, g_G = grad G(x*) = W(x*) grad f(x*) being
 * Newton's residual (zero at an interior minimum, pointing out of the domain at a minimum on an
 * edge or a corner). So f >= c - min(rho max W / min W, max W^2 |grad f|^2 / (2 lambda min W))
 * over the square, rho the largest decrease of the linear term on it, and every box inside the
 * square is pruned whatever its size, instead of being split until its own bounds reach T. */
static void certify(bsi_cl *w, search *s)
{
    double g[2], h[3], c = bsi_cl_grad(w, s->uv, g, h);
    /* For a polynomial patch G = f - c, and lambda bounds its Hessian from below over a square
     * that holds x*: where f's Hessian at x* is not positive definite (a minimum on an edge or
     * at a corner) no square can be shown convex, and only separable_bound is tried. A rational
     * patch's G is tried for convexity, else bounded the same way (separable_weighted). */
    int both = w->m > 0 && w->n > 0, poly = w->nc == w->dim && both;
    int convex = !poly || (h[0] > 0.0 && h[2] > 0.0 && h[0] * h[2] - h[1] * h[1] > 0.0);
    /* rounding of f(x*) (evaluation relative to q, amplified by s2) and of the square's net */
    /* S is a convex combination of the control points (weights B w / sum B w), so its rounding
     * is relative to the largest of them, whatever the weights; S_u is not: |w_u / w| reaches
     * m max w / min w */
    double rho_w = 1.0 / w->wmin;
    double dr = 8.0 * ((double)(w->m + w->n) + 2.0) * DBL_EPSILON * w->s2 * sqrt((double)w->dim);
    double noise = dr + net_error(w, 16);
    /* the gradient's own rounding: 2 |r| |S_u| with |r| off by dr, |S_u| <= 2 m rho_w (scaled) */
    double dg[2] = {4.0 * dr * (double)w->m * rho_w, 4.0 * dr * (double)w->n * rho_w};
    double g2 = 0.0;
    for (size_t i = 0; i < 2; i++)
        g2 += (fabs(g[i]) + dg[i]) * (fabs(g[i]) + dg[i]);
    for (int t = 0; t < 5; t++) { /* half-widths 1/8, 1/32, ..., 1/2048 */
        double r = ldexp(0.125, -2 * t);
        double x[4] = {fmax(0.0, s->uv[0] - r), fmin(1.0, s->uv[0] + r), fmax(0.0, s->uv[1] - r),
                       fmin(1.0, s->uv[1] + r)};
        bsi_cl_bound b;
        double wlo, whi, abc[3];
        bsi_cl_region(w, x);
        bsi_cl_fbound(w, w->region, &b);
        double lambda = bsi_cl_convex(w, &b, c, &wlo, &whi, abc);
        if (!(lambda > 0.0 && convex)) {
            /* a square kept only where it prunes now */
            double wr[4] = {wlo, whi, b.rel, dr * (2.0 * sqrt(c) + dr)};
            double sep = poly ? bsi_cl_separable_bound(s->uv, x, g, dg, abc)
                              : bsi_cl_separable_weighted(s->uv, x, g, dg, abc, wr);
            double lb = both ? sqrt(fmax(fmax(c + sep, b.lbf), 0.0)) - noise : -INFINITY;
            if (!pruned(s, lb))
                continue;
            region *rg = &s->reg[s->nreg++ % REGIONS];
            for (int i = 0; i < 4; i++)
                rg->x[i] = x[i];
            rg->lb = lb;
            return;
        }
        double rho = 0.0, width = 0.0; /* width: the longer side, over a direction that counts */
        for (size_t i = 0; i < 2; i++) {
            rho += dg[i] * (x[2 * i + 1] - x[2 * i]) -
                   fmin(0.0, fmin(g[i] * (x[2 * i] - s->uv[i]), g[i] * (x[2 * i + 1] - s->uv[i])));
            if ((i == 0 ? w->m : w->n) > 0)
                width = fmax(width, x[2 * i + 1] - x[2 * i]);
        }
        double strong = whi * whi * g2 * width * width / (2.0 * lambda * wlo);
        double lbf = fmax(c - fmin(rho * whi / wlo, strong), b.lbf);
        region *rg = &s->reg[s->nreg++ % REGIONS];
        for (int i = 0; i < 4; i++)
            rg->x[i] = x[i];
        rg->lb = sqrt(fmax(lbf, 0.0)) - noise;
        return;
    }
}

/* 1 when box b lies in a certified region whose bound prunes it. */
static int in_region(const search *s, const box *b)
{
    unsigned k = s->nreg < REGIONS ? s->nreg : REGIONS;
    for (unsigned i = 0; i < k; i++) {
        const double *x = s->reg[i].x;
        if (b->u0 >= x[0] && b->u1 <= x[1] && b->v0 >= x[2] && b->v1 <= x[3] &&
            pruned(s, s->reg[i].lb))
            return 1;
    }
    return 0;
}

/* 1 when (u, v) is in the part the search is held to. */
static int in_part(const search *s, const double x[2])
{
    return s->part == NULL || s->part->point(s->part->ctx, s->part->patch, x[0], x[1]);
}

/* Newton from the box's candidate when f there is below the best; a new best is certified. In a
 * search held to a part, a minimum outside it does not count (the box's own point may). */
static void try_candidate(bsi_cl *w, search *s, const box *b, const bsi_cl_bound *fb)
{
    double x[2] = {b->u0 + fb->su * (b->u1 - b->u0), b->v0 + fb->sv * (b->v1 - b->v0)};
    double f0 = bsi_cl_f(w, x[0], x[1]), x0[2] = {x[0], x[1]};
    if (!(f0 < s->f))
        return;
    double f = bsi_cl_newton(w, x);
    if (!(f < s->f))
        return;
    if (!in_part(s, x)) {
        if (in_part(s, x0)) {
            s->f = f0;
            s->uv[0] = x0[0];
            s->uv[1] = x0[1];
        }
        return;
    }
    s->f = f;
    s->uv[0] = x[0];
    s->uv[1] = x[1];
    if (sqrt(f) > tolerance(s))
        certify(w, s);
}

/* Whether box b survives: its bounds against the best (its second-order bound computed, and
 * counted in *visited, only when the first-order one does not prune it); its candidate tried. */
static int survives(bsi_cl *w, search *s, box *b, size_t *visited)
{
    double err = net_error(w, b->depth), x[4] = {b->u0, b->u1, b->v0, b->v1};
    if (pruned(s, sqrt(b->aabb) - err) || in_region(s, b))
        return 0;
    if (b->where != BSI_CL_IN) {
        b->where = s->part->box(s->part->ctx, s->part->patch, x);
        if (b->where == BSI_CL_OUT)
            return 0;
    }
    bsi_cl_bound fb;
    bsi_cl_fbound(w, w->pool + b->slot * w->np, &fb);
    ++*visited;
    double lb = sqrt(fmax(fb.lbf, 0.0)) - err;
    /* a box the part's boundary crosses, without a minimum of f: its closest points of the part
     * are on that boundary (the caller's) */
    if (pruned(s, lb) || (b->where == BSI_CL_CROSS && bsi_cl_no_minimum(w, &fb, x)))
        return 0;
    /* the direction in which the second-order bound is loosest, else the net's longer side
     * (before the candidate, whose squares overwrite the coefficients) */
    int dir = bsi_cl_direction(w);
    b->dir = dir >= 0 ? dir : bsi_cl_longer(w, w->pool + b->slot * w->np);
    try_candidate(w, s, b, &fb);
    return !pruned(s, lb);
}

/* The branch and bound. Returns the boxes visited. */
static size_t search_patch(bsi_cl *w, search *s)
{
    box stack[BSI_CL_SLOTS];
    unsigned free_slots[BSI_CL_SLOTS], nfree = 0;
    for (unsigned k = BSI_CL_SLOTS - 1; k > 0; k--)
        free_slots[nfree++] = k;
    for (size_t k = 0; k < w->np; k++)
        w->pool[k] = w->root[k];
    stack[0] = (box){0.0, 1.0, 0.0, 1.0, bsi_cl_box(w, w->pool), 0, 0, -1,
                     s->part ? BSI_CL_CROSS : BSI_CL_IN};
    size_t top = 1, visited = 0;
    while (top > 0) {
        box b = stack[--top];
        if (sqrt(s->f) <= tolerance(s))
            break; /* q is on the patch, as far as T can tell */
        if (visited >= BOX_CAP) {
            s->uncertified = 1;
            break;
        }
        if (!survives(w, s, &b, &visited) || b.dir < 0) {
            free_slots[nfree++] = b.slot;
            continue;
        }
        if (b.depth >= w->depth) {
            s->uncertified = 1;
            free_slots[nfree++] = b.slot;
            continue;
        }
        box half[2] = {b, b};
        half[0].slot = free_slots[--nfree];
        half[1].slot = free_slots[--nfree];
        half[0].depth = half[1].depth = b.depth + 1;
        if (b.dir == BS_DIR_U)
            half[0].u1 = half[1].u0 = 0.5 * (b.u0 + b.u1);
        else
            half[0].v1 = half[1].v0 = 0.5 * (b.v0 + b.v1);
        double *net = w->pool + b.slot * w->np;
        bsi_cl_split(w, net, b.dir, w->pool + half[0].slot * w->np, w->pool + half[1].slot * w->np);
        free_slots[nfree++] = b.slot;
        for (int k = 0; k < 2; k++)
            half[k].aabb = bsi_cl_box(w, w->pool + half[k].slot * w->np);
        int near = half[1].aabb < half[0].aabb; /* popped first */
        stack[top++] = half[1 - near];
        stack[top++] = half[near];
    }
    return visited;
}

/* |pos - q| without overflow or underflow in the squares. */
static double distance(const double *pos, const double *q, size_t dim)
{
    double big = 0.0, sum = 0.0;
    for (size_t c = 0; c < dim; c++)
        big = fmax(big, fabs(pos[c] - q[c]));
    if (big == 0.0 || isinf(big))
        return big;
    for (size_t c = 0; c < dim; c++) {
        double x = (pos[c] - q[c]) / big;
        sum += x * x;
    }
    return big * sqrt(sum);
}

/* Squared distance |S(uv) - q|^2 in the caller's units, S as bs_patch_eval gives it. */
static double distance2(const bs_patch *p, const double *q, const double uv[2], double *pos)
{
    bs_cview cu = {&uv[0], 1, 0}, cv = {&uv[1], 1, 0};
    bs_view out[BS_MAX_DIM];
    for (size_t c = 0; c < p->dim; c++)
        out[c] = (bs_view){&pos[c], 1, 0};
    (void)bs_patch_eval(p, 1, &cu, &cv, out, NULL, NULL); /* valid views: cannot fail */
    double d2 = 0.0;
    for (size_t c = 0; c < p->dim; c++)
        d2 += (pos[c] - q[c]) * (pos[c] - q[c]);
    return d2;
}

/* The distance from q to the bounding box of the control points (the convex hull), without
 * overflow or underflow (+Inf only beyond DBL_MAX). */
static double hull_distance(const bs_patch *p, const double *q)
{
    double half[BS_MAX_DIM], zero[BS_MAX_DIM];
    for (size_t c = 0; c < p->dim; c++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t k = 0; k < p->nctrl; k++) {
            lo = fmin(lo, p->ctrl[k * p->dim + c]);
            hi = fmax(hi, p->ctrl[k * p->dim + c]);
        }
        half[c] = fmax(0.0, fmax(0.5 * lo - 0.5 * q[c], 0.5 * q[c] - 0.5 * hi));
        zero[c] = 0.0;
    }
    return 2.0 * distance(half, zero, p->dim);
}

/* The search for one finite q against the distance *best_d (not squared: distances of huge
 * coordinates do not overflow); pos receives S(uv) as bs_patch_eval gives it when 1 is
 * returned; -2 when the search could not be certified (nothing changed). The scales are applied
 * one after the other: their product may overflow for subnormal coordinates. */
static int closest_with(bsi_cl *w, const double *q, double d_scale, double *best_d, double uv[2],
                        double *pos, size_t *boxes, const bsi_cl_part *part)
{
    bsi_cl_setup(w, q);
    search st = {*best_d * w->s1 * w->s2, INFINITY, {0.5, 0.5},
                 fmax(w->diag, d_scale * w->s1 * w->s2), {{{0}, 0}}, 0, 0, part};
    size_t visited = search_patch(w, &st);
    if (boxes != NULL)
        *boxes = visited;
    if (st.uncertified)
        return -2;
    if (!(st.f < INFINITY))
        return 0; /* every box was farther than the caller's best */
    (void)distance2(w->p, q, st.uv, pos);
    double d = distance(pos, q, w->dim);
    if (!(d < *best_d) && *best_d < INFINITY)
        return 0;
    *best_d = d;
    uv[0] = st.uv[0];
    uv[1] = st.uv[1];
    return 1;
}

static int closest_on(const bs_patch *p, const double *q, double d_scale, double *best_d,
                      double uv[2], size_t *boxes, const bsi_cl_part *part)
{
    if (boxes != NULL)
        *boxes = 0;
    if (hull_distance(p, q) > *best_d)
        return 0;
    if (bsi_cl_depth(p) == 0)
        return -2;
    bsi_cl *w = bsi_cl_create(p);
    if (w == NULL)
        return -1;
    double pos[BS_MAX_DIM] = {0.0};
    int r = closest_with(w, q, d_scale, best_d, uv, pos, boxes, part);
    bsi_cl_free(w);
    return r;
}

int bsi_patch_closest_dist(const bs_patch *p, const double *q, double d_scale, double *best_d,
                           double uv[2], size_t *boxes)
{
    return closest_on(p, q, d_scale, best_d, uv, boxes, NULL);
}

int bsi_patch_closest_part(const bs_patch *p, const double *q, double d_scale, double *best_d,
                           double uv[2], const bsi_cl_part *part)
{
    return closest_on(p, q, d_scale, best_d, uv, NULL, part);
}

int bsi_patch_closest_count(const bs_patch *p, const double *q, double d_scale, double *best_d2,
                            double uv[2], size_t *boxes)
{
    double best = sqrt(*best_d2);
    int r = bsi_patch_closest_dist(p, q, d_scale, &best, uv, boxes);
    if (r == 1)
        *best_d2 = best * best;
    return r;
}

int bsi_patch_closest_one(const bs_patch *p, const double *q, double d_scale, double *best_d2,
                          double uv[2])
{
    return bsi_patch_closest_count(p, q, d_scale, best_d2, uv, NULL);
}

bs_status bs_patch_closest_point(const bs_patch *p, size_t n, const bs_cview *q, const bs_view *uv,
                                 const bs_view *dist, const bs_view *pos)
{
    if (p == NULL)
        return BS_ERR_INVALID_ARG;
    if (n == 0)
        return BS_OK;
    if (q == NULL)
        return BS_ERR_INVALID_ARG;
    size_t dim = p->dim;
    bs_status st;
    for (size_t c = 0; c < dim; c++)
        if ((st = bsi_check_cview(&q[c], n)) != BS_OK)
            return st;
    if ((uv && (st = bsi_check_views(uv, 2, n)) != BS_OK) ||
        (dist && (st = bsi_check_views(dist, 1, n)) != BS_OK) ||
        (pos && (st = bsi_check_views(pos, dim, n)) != BS_OK))
        return st;
    if (bsi_cl_depth(p) == 0)
        return BS_ERR_PRECISION;
    /* the workspace and the answers' parameters, before anything is written: a query that cannot
     * be certified fails the call with nothing written */
    bsi_cl *w = bsi_cl_create(p);
    double *ats = w != NULL ? malloc(2 * n * sizeof *ats) : NULL;
    if (ats == NULL) {
        bsi_cl_free(w);
        return BS_ERR_NO_MEMORY;
    }
    for (size_t k = 0; k < n; k++) {
        double x[BS_MAX_DIM] = {0.0}, y[BS_MAX_DIM] = {0.0}, best = INFINITY;
        int finite = 1;
        ats[2 * k] = ats[2 * k + 1] = NAN;
        for (size_t c = 0; c < dim; c++) {
            x[c] = bsi_cget(&q[c], k);
            finite &= isfinite(x[c]) != 0;
        }
        if (finite && closest_with(w, x, 0.0, &best, &ats[2 * k], y, NULL, NULL) == -2) { /* distance */
            free(ats);
            bsi_cl_free(w);
            return BS_ERR_PRECISION;
        }
    }
    for (size_t k = 0; k < n; k++) {
        double x[BS_MAX_DIM] = {0.0}, *at = &ats[2 * k], y[BS_MAX_DIM], d = NAN;
        for (size_t c = 0; c < dim; c++) {
            x[c] = bsi_cget(&q[c], k);
            y[c] = NAN;
        }
        if (!isnan(at[0])) { /* a finite query: its answer's point, as bs_patch_eval gives it */
            (void)distance2(p, x, at, y);
            d = distance(y, x, dim);
        }
        if (uv) {
            *bsi_at(&uv[0], k) = at[0];
            *bsi_at(&uv[1], k) = at[1];
        }
        if (dist)
            *bsi_at(dist, k) = d;
        for (size_t c = 0; pos && c < dim; c++)
            *bsi_at(&pos[c], k) = y[c];
    }
    free(ats);
    bsi_cl_free(w);
    return BS_OK;
}
