/* Internal declarations shared by the files of lib/. Not installed. */
#ifndef BEZSURF_INTERNAL_H
#define BEZSURF_INTERNAL_H

#include "bezsurf.h"

#include <stdint.h>
#include <stdio.h>

/*
 * The patch object. Allocated as one block; never modified after bsi_patch_finish().
 * `ctrl` is the caller's packed Cartesian net, `weights` NULL or the weights. `hom` holds the same
 * net coordinate-major for evaluation: plane c (0 <= c < ncoord) is (deg_u+1)(deg_v+1) doubles
 * hom[c*nctrl + i*(deg_v+1) + j]; for rational patches the planes are w*P_c and the last plane is w
 * (ncoord = dim+1), for polynomial ones the planes are P_c (ncoord = dim).
 */
struct bs_patch {
    size_t deg_u, deg_v, dim;
    size_t nctrl;      /* (deg_u+1)(deg_v+1) */
    size_t ncoord;     /* planes in hom: dim, or dim+1 when rational */
    int rational;
    double *ctrl;      /* nctrl*dim, packed as in the API */
    double *weights;   /* nctrl or NULL */
    double *hom;       /* ncoord*nctrl, coordinate-major (homogeneous when rational) */
};

/* Allocate a patch with uninitialised ctrl (and weights when rational); degrees and dim must
 * already be valid. Fill ctrl/weights, then call bsi_patch_finish(). NULL when out of memory. */
bs_patch *bsi_patch_alloc(size_t deg_u, size_t deg_v, size_t dim, int rational);

/* Build hom from ctrl and weights. BS_ERR_NONFINITE if a coordinate or weight is invalid or w*P
 * overflows (the patch must then be destroyed by the caller). */
bs_status bsi_patch_finish(bs_patch *p);

/* Make a patch from a coordinate-major homogeneous net (layout of struct bs_patch's hom, planes
 * w*P then w when rational): Cartesian points are recovered by division. */
bs_status bsi_patch_from_hom(size_t deg_u, size_t deg_v, size_t dim, int rational,
                             const double *hom, bs_patch **out);

/* View checks: n elements from each of k views (k = 0 accepted). BS_ERR_INVALID_ARG for NULL
 * or misaligned data or strides, BS_ERR_SIZE when count < n or the byte extent overflows. */
bs_status bsi_check_views(const bs_view *views, size_t k, size_t n);
bs_status bsi_check_cview(const bs_cview *view, size_t n);

/* Byte stride of a view, with 0 meaning packed. */
static inline ptrdiff_t bsi_stride(ptrdiff_t stride) { return stride ? stride : (ptrdiff_t)sizeof(double); }

/* Element k of a view. */
static inline double *bsi_at(const bs_view *v, size_t k)
{
    return (double *)(void *)((char *)v->data + (ptrdiff_t)k * bsi_stride(v->stride));
}
static inline double bsi_cget(const bs_cview *v, size_t k)
{
    return *(const double *)(const void *)((const char *)v->data + (ptrdiff_t)k * bsi_stride(v->stride));
}

/* 1 if every one of the n values is finite. */
int bsi_all_finite(const double *x, size_t n);

/* ---- Topology of a surface: which patch sides are shared (lib/topology.c) ----
 * Sides of the unit square, counter-clockwise; t is the side's own parameter. */
#define BSI_SIDE_V0 0 /* v = 0, t = u */
#define BSI_SIDE_U1 1 /* u = 1, t = v */
#define BSI_SIDE_V1 2 /* v = 1, t = u */
#define BSI_SIDE_U0 3 /* u = 0, t = v */
#define BSI_NO_PATCH UINT32_MAX

typedef struct bsi_side_link {
    uint32_t patch;          /* the neighbour across this side, or BSI_NO_PATCH (open side) */
    unsigned char side;      /* the neighbour's side (BSI_SIDE_*) */
    unsigned char reversed;  /* 1 if t here is 1 - t on the neighbour's side */
    unsigned char collapsed; /* 1 if the side's control points coincide (a pole): no neighbour */
} bsi_side_link;

typedef struct bsi_topology {
    size_t npatch;
    bsi_side_link *links; /* links[4*patch + side] */
} bsi_topology;

/* Match the sides of all patches of s whose boundary control points agree within tol (absolute,
 * per coordinate). BS_ERR_NO_MEMORY on failure (out is then empty). */
bs_status bsi_topology_build(const bs_surface *s, double tol, bsi_topology *out);
void bsi_topology_free(bsi_topology *t);

/* ---- .bpt numbers (lib/bpt_number.c): locale-independent decimal text ---- */
#define BSI_NUMBER_MAX 400 /* longest number token accepted, in bytes */

/* Parse the whole token tok[0..len) as a C-notation decimal number (no hex, no nan/inf). Returns 1
 * and sets *out when it is valid and finite, 0 when it is not a number, -1 when it is a number too
 * large for a double (the value underflows quietly to a subnormal or zero, correctly rounded). */
int bsi_parse_double(const char *tok, size_t len, double *out);

/* Write the shortest of "%.15g", "%.16g", "%.17g" that reads back to x exactly, with '.' as the
 * decimal point, into buf (room for 32 bytes); returns its length (NUL not counted). */
size_t bsi_format_double(double x, char *buf);

/* The built-in tea set's .bpt texts (lib/teaset_data.c, generated from data/ at build time). */
typedef struct bsi_builtin {
    const char *name;
    const char *text;
    size_t len;
} bsi_builtin;
extern const bsi_builtin bsi_builtins[];
extern const size_t bsi_builtin_count;

/* Small helpers of the evaluation loops (BSI_HOT below): GCC does not inline a function of the
 * default target into a loop compiled for another by itself, so they are forced inline (and then
 * compiled for the loop's target). */
#if defined(__GNUC__)
#define BSI_INLINE static inline __attribute__((always_inline))
#else
#define BSI_INLINE static inline
#endif

/* ---- Bernstein basis (lib/basis.c) ----
 * All by the triangular recurrence B(r,k) = (1-t) B(r-1,k) + t B(r-1,k-1), so every value is a
 * sum of non-negative terms for t in [0,1]. */

/* b[0..deg] = B(deg,i)(t). */
void bsi_bernstein(size_t deg, double t, double *b);
/* b[0..deg] = B(deg,i)(t) and, when deg > 0, bm[0..deg-1] = B(deg-1,i)(t) (the weights of the
 * first-derivative difference net). b is bit-identical to bsi_bernstein(deg, t, b). */
void bsi_bernstein_first(size_t deg, double t, double *b, double *bm);
/* bsi_bernstein_first for degree 3, written out: the same operations (same bits). */
BSI_INLINE void bsi_bernstein3_first(double x, double w[4], double wm[3])
{
    double s = 1.0 - x;
    double a0 = 0.0 + s * 1.0, a1 = x * 1.0;
    wm[0] = 0.0 + s * a0;
    wm[1] = x * a0 + s * a1;
    wm[2] = x * a1;
    w[0] = 0.0 + s * wm[0];
    w[1] = x * wm[0] + s * wm[1];
    w[2] = x * wm[1] + s * wm[2];
    w[3] = x * wm[2];
}
/* b[0..deg] = d^k/dt^k B(deg,i)(t): B(deg-k, .) differenced k times and scaled by deg!/(deg-k)!;
 * all zero when k > deg. */
void bsi_bernstein_deriv(size_t deg, unsigned k, double t, double *b);

/* ---- Evaluation kernels (lib/eval.c, lib/deriv.c) ---- */

/* Marks the loops that carry evaluation. With BSI_CPU_DISPATCH (GCC on x86-64, see
 * lib/CMakeLists.txt) each is compiled for AVX-512, AVX2 and baseline SSE2, and the loader picks
 * the widest the CPU has. Every version performs the same IEEE operations in the same order (no
 * FMA: -ffp-contract=off; no reassociation), only on more points per instruction, so results are
 * the same bits whichever runs. */
#ifdef BSI_CPU_DISPATCH
#define BSI_HOT __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define BSI_HOT
#endif

/* Points per block of the scattered evaluators. Every point's arithmetic is the same whatever
 * its position in a block, so results do not depend on batch size. */
#define BSI_BLOCK ((size_t)8)

/* Parameters k0 .. k0+nb-1 (nb <= BSI_BLOCK) of a scattered call as one block: ub, vb and bad
 * get BSI_BLOCK entries; slots past nb and non-finite pairs become (0,0) with bad set for the
 * latter, so the kernels only ever see finite parameters (lib/eval.c). */
void bsi_load_block(const bs_cview *u, const bs_cview *v, size_t k0, size_t nb,
                    double *ub, double *vb, int *bad);

/* Homogeneous value h and, when first != 0, first partials hu, hv at BSI_BLOCK finite parameter
 * pairs; each output is [ncoord][BSI_BLOCK]. The u-direction is contracted first (per column j,
 * i ascending), then v (j ascending), with the derivatives taken from inline difference nets;
 * the grid evaluator repeats exactly this arithmetic. */
void bsi_eval_first_block(const bs_patch *p, const double *u, const double *v, int first,
                          double *h, double *hu, double *hv);

/* Points per chunk of the bicubic kernels, which share their set-up over more points. */
#define BSI_CHUNK ((size_t)32)

/* bsi_eval_first_block with first != 0 for a polynomial bicubic patch, on BSI_CHUNK finite
 * parameter pairs; outputs [dim][BSI_CHUNK]. The same arithmetic per point (same bits). */
void bsi_bicubic_first_chunk(const bs_patch *p, const double *u, const double *v, double *h,
                             double *hu, double *hv);

/* Cartesian S (and S_u, S_v when su != NULL) of one point from its homogeneous values; element c
 * of h, hu, hv is at index c*stride. */
void bsi_project_first(const bs_patch *p, const double *h, const double *hu, const double *hv,
                       size_t stride, double *s, double *su, double *sv);

/* All Cartesian partials S^(a,b), a <= ka, b <= kb, at one finite point:
 * out[(a*(kb+1) + b)*dim + c]. scratch holds bsi_deriv_table_scratch(p, ka, kb) doubles. */
size_t bsi_deriv_table_scratch(const bs_patch *p, unsigned ka, unsigned kb);
void bsi_deriv_table(const bs_patch *p, double u, double v, unsigned ka, unsigned kb,
                     double *scratch, double *out);

/* ---- Normals (lib/normal.c) ---- */

/* Per-patch derivative scales for the zero tests of the normal rule (see docs/normals.md). */
typedef struct bsi_nscale {
    double lu, lv;   /* bounds on |S_u| and |S_v| over the unit square */
    double noise;    /* 2 (m+n+1) eps max|P| rho: rounding scale of positions */
    double rho;      /* wmax / wmin, 1 for polynomial patches */
    double zu, zv;   /* |S_u| <= zu, |S_v| <= zv count as zero */
} bsi_nscale;

void bsi_normal_scale(const bs_patch *p, bsi_nscale *sc);
/* The normal rule at one point from its S_u and S_v: writes nrm[3], returns the kind. */
unsigned char bsi_normal(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                         const double *su, const double *sv, double *nrm);
/* bsi_normal at nb points, the regular case vectorised: su[c][b], sv[c][b] in, nrm[c][b] and
 * kind[b] out; point b is at (u[b*ustep], v[b]). Same bits as bsi_normal point by point. */
void bsi_normal_block(const bs_patch *p, const bsi_nscale *sc, size_t nb, const double *u,
                      size_t ustep, const double *v, const double *const *su,
                      const double *const *sv, double *const *nrm, unsigned char *kind);
/* ---- Curve operations applied fibre by fibre to coordinate-major nets (lib/fiber.c) ----
 * A net here is ncoord planes of (deg_u+1)(deg_v+1) doubles, as struct bs_patch's hom. A fibre is
 * one row of a plane along a direction: fixed j for BS_DIR_U (index i), fixed i for BS_DIR_V. */
#define BSI_FIBER_MAX (2 * BS_MAX_DEGREE + 1)

/* One coordinate of a curve: in[0..deg_in] -> out[0..deg_out] (deg_out < BSI_FIBER_MAX). */
typedef void (*bsi_fiber_op)(const double *in, size_t deg_in, double *out, size_t deg_out,
                             const void *ctx);

/* Apply op along dir to every fibre of every plane; out has degree deg_out along dir. */
void bsi_net_map(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                 size_t deg_out, bsi_fiber_op op, const void *ctx, double *out);

/* Copy fibre positions first..first+deg_out along dir of every plane into a net of degree deg_out. */
void bsi_net_slice(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                   size_t first, size_t deg_out, double *out);

/* Size in doubles of a net with ncoord planes and the given degrees. */
static inline size_t bsi_net_size(size_t ncoord, size_t deg_u, size_t deg_v)
{
    return ncoord * (deg_u + 1) * (deg_v + 1);
}

/* Raise a net's degree along dir by raise (deg + raise <= BS_MAX_DEGREE), writing a net of degree
 * deg + raise along dir to out (lib/elevate.c). BS_ERR_NO_MEMORY on failure. */
bs_status bsi_elevate_net(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                          size_t raise, double *out);

/* ---- Meshes (lib/mesh.c); filled by lib/tessellate.c, read by the exporters ----
 * Arrays are packed: pos, nrm 3 per vertex, uv 2 per vertex, tri 3 per triangle; strip k is
 * strip_idx[strip_start[k] .. strip_start[k+1]). A triangle corner's (u,v) on the triangle's
 * patch is its vertex's uv, except for the corners listed in ascending order in xcorner (index
 * 3 * triangle + corner) with their own (u,v) in xuv (2 each): corners on a shared edge that the
 * neighbour's parameters own, and at poles. Every array is its own malloc block (NULL when empty)
 * freed by bs_mesh_destroy(). */
struct bs_mesh {
    size_t nvert, ntri, nstrip, nstrip_idx, nx;
    double *pos, *nrm, *uv, *xuv;
    size_t *xcorner;
    uint32_t *vpatch, *tri, *tpatch, *strip_idx, *strip_start;
};

/* ---- Mesh export (lib/export.c and lib/export_*.c) ----
 * A byte sink: a FILE, a caller buffer of cap bytes, or neither (only counts). Writes past cap or
 * failing writes set err; len counts every byte asked for. */
typedef struct bsi_sink {
    FILE *f;
    unsigned char *buf;
    size_t cap, len;
    int err;
} bsi_sink;

void bsi_sink_put(bsi_sink *s, const void *data, size_t n);
void bsi_sink_str(bsi_sink *s, const char *text);
/* A double in %.<digits>g form with '.' as decimal point whatever the C locale. */
void bsi_sink_double(bsi_sink *s, double x, int digits);
void bsi_sink_uint(bsi_sink *s, size_t x);
void bsi_sink_f32le(bsi_sink *s, double x);
void bsi_sink_u32le(bsi_sink *s, uint32_t x);

void bsi_export_obj(const bs_mesh *m, bsi_sink *s);
void bsi_export_ply(const bs_mesh *m, int binary, bsi_sink *s);
void bsi_export_stl(const bs_mesh *m, bsi_sink *s);

/* ---- The regular normal rule at one point (lib/normal.c, lib/eval_grid.c) ----
 * N = (S_u x S_v) / |S_u x S_v| with the fast tests of bsi_normal; flag 0.0 when settled, 1.0
 * when the point needs bsi_normal. Inline so that every vectorised caller does the same
 * operations (and gets the same bits). zu2, zv2: the squared zero thresholds of bsi_nscale. */
#include <math.h>
typedef struct bsi_rnormal {
    double n0, n1, n2, flag;
} bsi_rnormal;
static inline bsi_rnormal bsi_regular_normal(double x0, double x1, double x2, double y0,
                                             double y1, double y2, double zu2, double zv2)
{
    double qa = x0 * x0 + x1 * x1 + x2 * x2;
    double qb = y0 * y0 + y1 * y1 + y2 * y2;
    double c0 = x1 * y2 - x2 * y1, c1 = x2 * y0 - x0 * y2, c2 = x0 * y1 - x1 * y0;
    double qc = c0 * c0 + c1 * c1 + c2 * c2;
    long ok = (qa > 0x1p-450) & (qa < 0x1p450) & (qb > 0x1p-450) & (qb < 0x1p450) & (qa > zu2) &
              (qb > zv2) & (qc > 0x1p-60 * (qa * qb));
    double inv = 1.0 / sqrt(qc);
    bsi_rnormal r;
    r.n0 = c0 * inv;
    r.n1 = c1 * inv;
    r.n2 = c2 * inv;
    r.flag = ok ? 0.0 : 1.0;
    return r;
}

#endif
