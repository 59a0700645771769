/*
 * Closest points on one patch, private to the closest-point files of lib/query/ (closest.c,
 * closest_bound.c, closest_newton.c): the workspace of the queries on one patch, the bounds on
 * a sub-net and the projected Newton iteration. Not installed.
 *
 * Units. Each query works in scaled coordinates: the net and q are multiplied by s1 (a power of
 * two that brings the larger of them below 1), the differences P - q by s2 (a power of two that
 * brings them below 1). Scaling by powers of two is exact, so nothing overflows or underflows for
 * huge or tiny coordinates and f = |S - q|^2 is of order 1 at most.
 */
#ifndef BEZSURF_QUERY_CLOSEST_H
#define BEZSURF_QUERY_CLOSEST_H

#include "core/kernels.h"
#include "query/internal.h"

/* Deepest box (binary splits of the domain) of a polynomial patch. A rational one may need
 * more: its parametrisation can squeeze a part of the surface into a corner of the domain of
 * size (min w / max w) per direction, so it gets 2 log2(max w / min w) levels more, up to
 * BSI_CL_DEPTH_MAX; a weight ratio beyond that is not served (BS_ERR_PRECISION). Nets kept at
 * once: at most three more than the depth. */
#define BSI_CL_DEPTH 80
#define BSI_CL_DEPTH_MAX 400
#define BSI_CL_SLOTS (BSI_CL_DEPTH_MAX + 3)

typedef struct bsi_cl {
    const bs_patch *p;
    size_t m, n, dim, nc; /* degrees, dimension, doubles per net point (dim + 1 when rational) */
    size_t np;            /* doubles per net, (m+1)(n+1) nc */
    unsigned depth;       /* the deepest box (BSI_CL_DEPTH, more for a rational patch) */
    size_t bicubic;       /* m = n = dim = 3: nc, the kernels of closest_bicubic.c; else 0 */
    /* scratch sized for p, allocated once by bsi_cl_create */
    double *pool;      /* BSI_CL_SLOTS nets, point-major: coordinate c of (i,j) at [(i(n+1)+j) nc + c];
                        * homogeneous w (P - q) then w when rational, scaled */
    double *root;      /* the net of the whole domain (the same layout) */
    double *region;    /* the net of a region around a minimum */
    double *cart;      /* (m+1)(n+1) dim: the Cartesian points of one net */
    double *scaled;    /* np: one net times the binomials C(m,i) C(n,j) */
    double *nco, *wco; /* (2m+1)(2n+1): Bernstein coefficients of N = |w (S - q)|^2 and W = w^2,
                        * times the binomials C(2m,k) C(2n,l) */
    double *fco;       /* (2m+1)(2n+1): the ratios N_kl / W_kl, which f is a convex combination of */
    double *binom;     /* Pascal rows m, n, 2m, 2n */
    double *line;      /* max(m,n) + 1: one line of a net being split */
    double *dscratch;  /* bsi_deriv_table_scratch(p, 2, 2) */
    double *table;     /* 9 dim: the partials S^(a,b), a, b <= 2, at one point */
    /* set for each query by bsi_cl_setup */
    double s1, s2;           /* the scales (see above) */
    double qs[BS_MAX_DIM];   /* q s1 */
    double diag;             /* diagonal of the bounding box of the control points, scaled */
    double wmin;             /* smallest weight of the root net (the largest is scaled to 1) */
} bsi_cl;

/* What is known of one box from its sub-net. */
typedef struct bsi_cl_bound {
    double lbf;    /* lower bound on f over the box from the Bernstein coefficients of f, the
                    * rounding of their computation allowed for */
    double su, sv; /* where the smallest coefficient sits, in the box's own parameters */
    double err;    /* rounding of the coefficients of N (w->nco), relative of W (w->wco) */
    double rel;
} bsi_cl_bound;

/* The depth of the search on p (BSI_CL_DEPTH, more for a rational patch), 0 when the weight
 * ratio needs more than BSI_CL_DEPTH_MAX. */
unsigned bsi_cl_depth(const bs_patch *p);
/* The workspace for queries on p (lib/query/closest_bound.c), p of a depth other than 0; NULL
 * when out of memory. */
bsi_cl *bsi_cl_create(const bs_patch *p);
void bsi_cl_free(bsi_cl *w);
/* Scales for the finite query point q, and the root net of q in w->root. */
void bsi_cl_setup(bsi_cl *w, const double *q);
/* de Casteljau at 1/2 along dir: the halves of src into lo and hi. */
void bsi_cl_split(bsi_cl *w, const double *src, int dir, double *lo, double *hi);
/* The squared distance from q to the bounding box of the Cartesian sub-net (first order). */
double bsi_cl_box(bsi_cl *w, const double *net);
/* The direction to split the box of the last bsi_cl_fbound from the coefficients of f
 * (bsi_cl_slack below): BS_DIR_U or BS_DIR_V, -1 when they do not tell. */
int bsi_cl_direction(const bsi_cl *w);
/* The direction to split a sub-net across its longer side (BS_DIR_U or BS_DIR_V; -1 for a
 * constant patch): where the coefficients of f do not tell. */
int bsi_cl_longer(bsi_cl *w, const double *net);
/* b->lbf, b->su and b->sv of a sub-net: the second-order bound (N and W left in w->nco, w->wco,
 * the ratios in w->fco). */
void bsi_cl_fbound(bsi_cl *w, const double *net, bsi_cl_bound *b);
/* The sub-net of the box [x[0], x[1]] x [x[2], x[3]] of the root net into w->region. */
void bsi_cl_region(bsi_cl *w, const double x[4]);
/* How convex G = N - c W is over the box of the last bsi_cl_fbound (b its result): a lower bound
 * on the smallest eigenvalue of G's Hessian in the box's own parameters (s, t in [0,1]) from its
 * second-difference coefficients, their rounding allowed for; 0 or less when G is not shown
 * convex there, INFINITY for a constant patch. *wlo and *whi receive bounds on W over the box,
 * abc the bounds A <= G_ss, |G_st| <= B, C <= G_tt over it (NAN where not found). */
double bsi_cl_convex(const bsi_cl *w, const bsi_cl_bound *b, double c, double *wlo, double *whi,
                     double abc[3]);

/* A lower bound on f - c over the square x around the point uv of a polynomial patch where f's
 * Hessian is not shown positive (a minimum on an edge or at a corner): g the gradient there, dg
 * its rounding, abc the bounds of bsi_cl_convex (lib/query/closest_bound.c). */
double bsi_cl_separable_bound(const double uv[2], const double x[4], const double g[2],
                              const double dg[2], const double abc[3]);
/* The same for a rational patch (G = N - c W), a lower bound on f - c: wr holds the bounds of
 * bsi_cl_convex on W over the square, bsi_cl_fbound's relative rounding of W and the rounding
 * of c = f(x*) (lib/query/closest_rational.c). */
double bsi_cl_separable_weighted(const double uv[2], const double x[4], const double g[2],
                                 const double dg[2], const double abc[3], const double wr[4]);
/* 1 when the box x of the last bsi_cl_fbound (b its result, w->nco and w->wco still its
 * coefficients) holds no local minimum of f over the patch's domain: a partial derivative keeps
 * one sign over it and the box does not reach the side of the domain it points to
 * (lib/query/closest_grad.c). */
int bsi_cl_no_minimum(bsi_cl *w, const bsi_cl_bound *b, const double x[4]);

/* f = |S - q|^2 at (u,v) in scaled units (lib/query/closest_newton.c). */
double bsi_cl_f(bsi_cl *w, double u, double v);
/* Projected Newton on f over [0,1]^2 from x (updated): returns f there. Iterates on the free
 * coordinates (an edge or a corner where the gradient points out of the domain is held), with a
 * Gauss-Newton or gradient step where the Hessian is not positive, and halving steps until f
 * decreases. */
double bsi_cl_newton(bsi_cl *w, double x[2]);
/* f, its gradient g[2] and its Hessian h[3] (uu, uv, vv) at x. */
double bsi_cl_grad(bsi_cl *w, const double x[2], double g[2], double h[3]);

/* bsi_patch_closest_one, also counting the boxes whose second-order bound was computed
 * (lib/query/closest.c; boxes may be NULL; -2 as bsi_patch_closest_one). */
int bsi_patch_closest_count(const bs_patch *p, const double *q, double d_scale, double *best_d2,
                            double uv[2], size_t *boxes);

/* The bicubic 3-D polynomial patch (m = n = 3, dim = nc = 3) and the rational one (nc = 4),
 * lib/query/closest_bicubic.c: bsi_cl_split, bsi_cl_box, bsi_cl_fbound and the partials on
 * constant sizes (3: polynomial, 4: rational). */
#define BSI_CL_BICUBIC3(w) ((w)->bicubic == 3)
#define BSI_CL_BICUBIC4(w) ((w)->bicubic == 4)
void bsi_cl_split3(const double *src, int dir, double *lo, double *hi);
void bsi_cl_split4(const double *src, int dir, double *lo, double *hi);
double bsi_cl_box3(const double *net);
double bsi_cl_box4(const double *net);
void bsi_cl_fbound3(bsi_cl *w, const double *net, bsi_cl_bound *b);
void bsi_cl_fbound4(bsi_cl *w, const double *net, bsi_cl_bound *b);
/* bsi_cl_region's subdivision of a copy of the root net to the box x (the same bits). */
void bsi_cl_region3(double *net, const double x[4]);
void bsi_cl_region4(double *net, const double x[4]);
/* bsi_deriv_table(p, u, v, k, k, ...) for k = 0 or 2, hom = p->hom: the same bits. */
void bsi_cl_deriv3(const double *hom, double u, double v, unsigned k, double *out);
void bsi_cl_deriv4(const double *hom, double u, double v, unsigned k, double *out);
/* The end of bsi_cl_fbound: what b receives from the smallest ratio (at arg), the smallest lower
 * bound low on the ratios and the rounding terms err and rel. */
void bsi_cl_fbound_finish(bsi_cl *w, bsi_cl_bound *b, double low, size_t arg, double err,
                          double rel);
/* bsi_cl_slack(w, 3, 3). */
int bsi_cl_slack3(const bsi_cl *w);

/* The squared distance from the origin to the bounding box of pts points x of dimension dim. */
BSI_INLINE double bsi_cl_box_gap2(const double *x, size_t pts, size_t dim)
{
    double lo[BS_MAX_DIM], hi[BS_MAX_DIM];
    for (size_t c = 0; c < dim; c++)
        lo[c] = hi[c] = x[c];
    for (size_t k = 1; k < pts; k++)
        for (size_t c = 0; c < dim; c++) {
            double y = x[k * dim + c];
            lo[c] = y < lo[c] ? y : lo[c];
            hi[c] = y > hi[c] ? y : hi[c];
        }
    double gap2 = 0.0;
    for (size_t c = 0; c < dim; c++) {
        double g = fmax(0.0, fmax(lo[c], -hi[c]));
        gap2 += g * g;
    }
    return gap2;
}

/* The direction in which the coefficients of f (the ratios N_kl / W_kl, in w->fco) differ most
 * from f: their second differences along it times the degree, the size of the gap between
 * coefficients and values that halving the box along it divides by 4. -1 when both are zero
 * (then the net's longer side decides). Where f does not depend on one direction (a cylinder
 * seen from its axis: a line of minima) only the other is split. */
BSI_INLINE int bsi_cl_slack(const bsi_cl *w, size_t m, size_t n)
{
    size_t K = 2 * m, L = 2 * n, n2 = L + 1;
    const double *f = w->fco;
    double eu = 0.0, ev = 0.0;
    for (size_t k = 0; k + 2 <= K; k++)
        for (size_t l = 0; l <= L; l++) {
            double d = fabs(f[(k + 2) * n2 + l] - 2.0 * f[(k + 1) * n2 + l] + f[k * n2 + l]);
            eu = d > eu ? d : eu;
        }
    for (size_t k = 0; k <= K; k++)
        for (size_t l = 0; l + 2 <= L; l++) {
            double d = fabs(f[k * n2 + l + 2] - 2.0 * f[k * n2 + l + 1] + f[k * n2 + l]);
            ev = d > ev ? d : ev;
        }
    eu *= (double)K;
    ev *= (double)L;
    if (eu == ev) /* both zero, or a tie */
        return -1;
    return eu > ev ? BS_DIR_U : BS_DIR_V;
}

#endif
