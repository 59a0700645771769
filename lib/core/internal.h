/*
 * Core layer, shared with every layer above it: the patch object, the checks and accessors of
 * strided views, the CPU-dispatch macros, the table of all partials at one point and the
 * curvature's partials of a chunk of points (what queries build on), and files written
 * atomically. The evaluation loops are the core's own business and live in
 * core/kernels.h. Not installed.
 */
#ifndef BEZSURF_CORE_INTERNAL_H
#define BEZSURF_CORE_INTERNAL_H

#include "bezsurf.h"

#include <stddef.h>
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
 * or misaligned data or strides, BS_ERR_SIZE when count < n, the byte extent overflows or the
 * address of the first or the last element wraps around the address space. */
bs_status bsi_check_views(const bs_view *views, size_t k, size_t n);
bs_status bsi_check_cview(const bs_cview *view, size_t n);
/* The same checks for float views (alignment and stride in units of sizeof(float)). */
bs_status bsi_check_fviews(const bs_fview *views, size_t k, size_t n);

/* Byte stride of a view, with 0 meaning packed. */
static inline ptrdiff_t bsi_stride(ptrdiff_t stride) { return stride ? stride : (ptrdiff_t)sizeof(double); }

/* Element k of a view. */
static inline double *bsi_at(const bs_view *v, size_t k)
{
    return (double *)(void *)((char *)v->data + (ptrdiff_t)k * bsi_stride(v->stride));
}
static inline float *bsi_fat(const bs_fview *v, size_t k)
{
    ptrdiff_t s = v->stride ? v->stride : (ptrdiff_t)sizeof(float);
    return (float *)(void *)((char *)v->data + (ptrdiff_t)k * s);
}
static inline double bsi_cget(const bs_cview *v, size_t k)
{
    return *(const double *)(const void *)((const char *)v->data + (ptrdiff_t)k * bsi_stride(v->stride));
}

/* A view's elements from `first` on (first <= count), for handing a part of a batch to a call. */
static inline bs_cview bsi_sub_cview(const bs_cview *v, size_t first)
{
    bs_cview r = {(const double *)(const void *)((const char *)v->data + (ptrdiff_t)first * bsi_stride(v->stride)),
                  v->count - first, v->stride};
    return r;
}
/* The same for k views, into out[k]; NULL when views is NULL. */
static inline const bs_view *bsi_sub_views(const bs_view *views, size_t k, size_t first, bs_view *out)
{
    if (views == NULL)
        return NULL;
    for (size_t c = 0; c < k; c++) {
        out[c].data = bsi_at(&views[c], first);
        out[c].count = views[c].count - first;
        out[c].stride = views[c].stride;
    }
    return out;
}

/* All Cartesian partials S^(a,b), a <= ka, b <= kb, at one finite point (lib/core/deriv.c):
 * out[(a*(kb+1) + b)*dim + c]. scratch holds bsi_deriv_table_scratch(p, ka, kb) doubles. */
size_t bsi_deriv_table_scratch(const bs_patch *p, unsigned ka, unsigned kb);
void bsi_deriv_table(const bs_patch *p, double u, double v, unsigned ka, unsigned kb,
                     double *scratch, double *out);

/* ---- CPU dispatch, for the vectorised loops of every layer ----
 * Small helpers of those loops (BSI_HOT below): GCC does not inline a function of the default
 * target into a loop compiled for another by itself, so they are forced inline (and then
 * compiled for the loop's target). */
#if defined(__GNUC__)
#define BSI_INLINE static inline __attribute__((always_inline))
#else
#define BSI_INLINE static inline
#endif

/* Marks the loops that carry evaluation (and the curvature's formulas). With BSI_CPU_DISPATCH
 * (GCC on x86-64, see lib/CMakeLists.txt) each is compiled for AVX-512, AVX2 and baseline SSE2,
 * and the loader picks the widest the CPU has. Every version performs the same IEEE operations
 * in the same order (no FMA: -ffp-contract=off; no reassociation), only on more points per
 * instruction, so results are the same bits whichever runs. */
#if defined(BSI_CPU_DISPATCH) && defined(BSI_CPU_NO_AVX512) /* -DBS_CPU_AVX512=OFF */
#define BSI_HOT __attribute__((target_clones("avx2", "default")))
#elif defined(BSI_CPU_DISPATCH)
#define BSI_HOT __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define BSI_HOT
#endif

/* ---- Normal scales and curvature partials (lib/core/normal.c, lib/core/partials2.c) ----
 * Per-patch derivative scales for the zero tests of the normal rule (see docs/normals.md). */
typedef struct bsi_nscale {
    double lu, lv;   /* m D, n D: scales of |S_u| and |S_v| (their bounds for a polynomial patch) */
    double noise;    /* 2 (m+n+1) eps max|P| rho: rounding scale of positions */
    double rho;      /* wmax / wmin, 1 for polynomial patches */
    double wmax;     /* largest weight, 1 for polynomial patches */
    double fu, fv;   /* CLEAN times the rounding bound of S_u, S_v per unit of wmax / w(u,v) */
    double zu, zv;   /* |S_u| <= zu, |S_v| <= zv count as zero anywhere (with wmax / w = rho) */
} bsi_nscale;

void bsi_normal_scale(const bs_patch *p, bsi_nscale *sc);

/* Points per chunk of bsi_curv_partials_chunk. */
#define BSI_PCHUNK ((size_t)32)

/* The partials a curvature needs at nb <= BSI_PCHUNK finite points (u[k], v[k]) of a 3-D patch,
 * polynomial or rational, in one pass per point (lib/core/partials2.c): d[(3 j + c) BSI_PCHUNK + k]
 * for S_u, S_v, S_uu, S_uv, S_vv (j = 0..4), coordinate c, point k; the unit normal
 * nrm[c BSI_PCHUNK + k] and its kind exactly as bs_patch_eval_normal gives them (S_u and S_v come
 * from the same operations as its evaluators, so the normal rule sees the same bits). sc from
 * bsi_normal_scale(p). */
void bsi_curv_partials_chunk(const bs_patch *p, const bsi_nscale *sc, size_t nb, const double *u,
                             const double *v, double *d, double *nrm, unsigned char *kind);

/* Row k of Pascal's triangle: c[a] = C(k, a), a <= k (rounded beyond 2^53). */
void bsi_binomial_row(unsigned k, double *c);

/* A file being written: a temporary file in the target's directory, renamed over the target by
 * bsi_out_close() only after a complete, flushed and synced write. */
typedef struct bsi_out_file {
    FILE *f;          /* the temporary file, open for writing */
    char *tmp;        /* its name */
    const char *path; /* the target */
} bsi_out_file;

/* Start writing path. BS_ERR_IO (errno set) if path is an existing directory (EISDIR) or other
 * non-regular file (EINVAL), or the temporary file cannot be created; BS_ERR_NO_MEMORY. */
bs_status bsi_out_open(const char *path, bsi_out_file *o);
/* Finish: with ok, flush, sync, close and rename over the target; on any failure (or !ok) close
 * and remove the temporary file, leave the target as it was, and return BS_ERR_IO with errno
 * telling why (the first failure's errno; with !ok, errno as the caller left it, else EIO). */
bs_status bsi_out_close(bsi_out_file *o, int ok);

/* 1 if every one of the n values is finite. */
int bsi_all_finite(const double *x, size_t n);

/* ---- Work shared between threads (lib/core/parallel.c) ---- */

/* Workers to use for a caller's thread count (0 = one per online CPU), never more than items
 * (at least 1). */
size_t bsi_thread_count(size_t threads, size_t items);
/* One item of work; worker < the workers passed to bsi_parallel(), so that per-worker scratch
 * needs no lock. Items must write disjoint memory for results not to depend on the threads. */
typedef bs_status (*bsi_task)(void *ctx, size_t item, size_t worker);
/* Run fn on items 0..n-1 with up to `workers` threads, the calling one included; every thread is
 * joined before it returns, and a thread that cannot be created leaves its share to the others.
 * Items are taken in ascending order; after a failure no new item starts. Returns BS_OK, or the
 * status of the lowest failing item. */
bs_status bsi_parallel(size_t workers, size_t n, bsi_task fn, void *ctx);

/* ---- Growing arrays (lib/core/grow.c) ---- */
/* Make room for `need` elements of `size` bytes in *p (capacity *cap, doubled as needed): 1, or
 * 0 when the size overflows or realloc fails (*p and *cap unchanged). */
int bsi_grow_array(void **p, size_t *cap, size_t need, size_t size);

/* ---- Normals at single points for the layers above (lib/core/normal.c) ---- */

/* 1 for a net whose largest coordinate lies within [2^-lo, 2^hi] (or is 0), else the power of
 * two (at most 2^1000) that brings it near 1. Beyond 2^1000 the evaluators' first differences
 * overflow, and beyond 2^LARGE_NET already a rational net's partials at a pole, its coordinates
 * times the ratio of its weights (2^25 took a pole's limit normal to "undefined" from 2^973);
 * below 2^-SMALL_NET the partials at points next to a pole, still served by the
 * general rule (down to 2^-30 of the net's scale, and the net's differences may be far smaller
 * than its coordinates), fall into the subnormal range and lose their bits. So scale-invariant
 * results (normals, kinds, ray hits) come from a copy scaled by it (lo = SMALL_NET, hi =
 * LARGE_NET); the curvature's limit rule multiplies partials, and takes the copy beyond 2^64
 * (64, 64). (lib/core/normal.c) */
#define SMALL_NET 900
#define LARGE_NET 512
double bsi_extreme_scale(const bs_patch *p, int lo, int hi);
/* p with its control points times sig (weights kept) into *out; BS_ERR_NO_MEMORY. */
bs_status bsi_scaled_patch(const bs_patch *p, double sig, bs_patch **out);

/* bs_patch_eval_normal at one finite point of a 3-D patch, with sc from bsi_normal_scale(p) made
 * once by the caller: the same position, normal and kind bits. */
void bsi_eval_normal_one(const bs_patch *p, const bsi_nscale *sc, double u, double v,
                         double pos[3], double nrm[3], unsigned char *kind);

/* bs_patch_eval's position at one point (u, v), into pos[dim]: the same bits, without the views
 * (for callers inside the library that evaluate point by point). Non-finite u or v give NaN. */
void bsi_eval_point(const bs_patch *p, double u, double v, double *pos);

#endif
