/**
 * @file
 * libbezsurf meshes: tessellation of a surface into an indexed triangle mesh, read-back of the mesh
 * into caller buffers, and export to OBJ, PLY and STL. Include <bezsurf.h> rather than this file.
 */
#ifndef BEZSURF_MESH_H
#define BEZSURF_MESH_H

#include "core.h"
#include "surface.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Opaque, immutable triangle mesh made by a tessellator. Vertices carry a position, a unit normal,
 * a (u,v) parameter pair and the id of the patch they were evaluated on; triangles are index
 * triples, counter-clockwise seen from the side the normals point to. Any number of threads may
 * read the same `const bs_mesh *` at once. @since 1.0
 */
typedef struct bs_mesh bs_mesh;

/** Tessellation flag: the adaptive tolerance is a fraction of the surface's control-net bounding-box
 *  diagonal instead of an absolute distance. @since 1.0 */
#define BS_TESS_RELATIVE 1
/** Tessellation flag: also build triangle strips (see bs_mesh_copy_strips()). @since 1.0 */
#define BS_TESS_STRIPS 2
/** Tessellation flag: face the mesh the other way. Every vertex normal is negated and every
 *  triangle's winding reversed (still counter-clockwise seen from the side the normals point
 *  to), strips included; positions, parameters and ids are unchanged. The built-in tea set's
 *  patches face into the pot (docs/surfaces.md): this flag makes its meshes face outwards.
 *  A 1.1 library refuses it (BS_ERR_INVALID_ARG). @since 1.2 */
#define BS_TESS_REVERSE 4
/** Largest number of segments per patch and direction a tessellator uses. @since 1.0 */
#define BS_TESS_MAX_RATE 1024

/**
 * @brief Tessellate a 3-D surface with nu x nv segments per patch.
 * Vertices on sides shared by two patches (control points equal within 1e-9 times the largest
 * control-point coordinate) are computed once and shared, so the mesh has no cracks; a side shared
 * with a neighbour whose rate along it differs uses the larger rate, and the patch's interior grid is
 * stitched to it. Sides whose control points coincide (poles) become one vertex and the triangles
 * that degenerate there are dropped. An empty surface gives an empty mesh.
 * @param[in]  s      the surface (dim 3).
 * @param[in]  nu     segments along u per patch, 1..BS_TESS_MAX_RATE.
 * @param[in]  nv     segments along v per patch, 1..BS_TESS_MAX_RATE.
 * @param[in]  flags  0 or a combination of BS_TESS_STRIPS and BS_TESS_REVERSE (BS_TESS_RELATIVE is
 *                    accepted and ignored).
 * @param[out] out    receives the mesh (NULL on failure); release with bs_mesh_destroy().
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if s or out is NULL or flags has unknown bits.
 * @return BS_ERR_DIMENSION if the surface is not empty and its dimension is not 3.
 * @return BS_ERR_DOMAIN if nu or nv is 0 or above BS_TESS_MAX_RATE.
 * @return BS_ERR_SIZE if the mesh would need more than UINT32_MAX - 1 vertices or indices.
 * @return BS_ERR_NO_MEMORY if an allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_surface_tessellate_uniform(const bs_surface *s, size_t nu, size_t nv, int flags,
                                               bs_mesh **out);

/**
 * @brief Tessellate a 3-D surface so that every triangle lies within a chordal tolerance of the
 * surface: for every point of a triangle, the distance between the surface at that point's (u,v)
 * and the point is at most the tolerance. Each patch gets a segment count per direction from a
 * bound on its second derivatives (second differences of the control net); shared sides use the
 * larger count of their two patches (no T-junctions), and crack-freedom is as for
 * bs_surface_tessellate_uniform(). The bound is rigorous for polynomial patches; for rational
 * patches it is an estimate (the net's bound scaled by the ratio of the largest to the smallest
 * weight). Counts are capped at BS_TESS_MAX_RATE, where the tolerance may then not be met.
 * @param[in]  s          the surface (dim 3).
 * @param[in]  tolerance  finite and > 0: a distance, or with BS_TESS_RELATIVE a fraction of the
 *                        bounding-box diagonal of all control points.
 * @param[in]  flags      0 or a combination of BS_TESS_RELATIVE, BS_TESS_STRIPS and BS_TESS_REVERSE.
 * @param[out] out        receives the mesh (NULL on failure).
 * @return BS_OK on success.
 * @return BS_ERR_INVALID_ARG if s or out is NULL or flags has unknown bits.
 * @return BS_ERR_DIMENSION if the surface is not empty and its dimension is not 3.
 * @return BS_ERR_DOMAIN if tolerance is NaN, Inf, zero or negative.
 * @return BS_ERR_SIZE if the mesh would need more than UINT32_MAX - 1 vertices or indices.
 * @return BS_ERR_NO_MEMORY if an allocation fails.
 * @since 1.0
 */
BS_API bs_status bs_surface_tessellate_adaptive(const bs_surface *s, double tolerance, int flags,
                                                bs_mesh **out);

/** Tessellation method (bs_tess_options.method): nu x nv segments per patch, as
 *  bs_surface_tessellate_uniform(). @since 1.1 */
#define BS_TESS_UNIFORM 0
/** Tessellation method: one segment count per patch and direction from a bound on its second
 *  derivatives, as bs_surface_tessellate_adaptive(). @since 1.1 */
#define BS_TESS_PER_PATCH 1
/** Tessellation method: recursive subdivision of each patch into a quadtree of sub-patches (halves
 *  or thirds per direction, one direction alone where the other is flat), split where a bound on
 *  the chordal error of the triangles exceeds the tolerance; same promise as
 *  bs_surface_tessellate_adaptive() with far fewer triangles. Leaves of different size, inside a
 *  patch and across shared sides, share their vertices (no cracks, no T-junctions). The bound is
 *  rigorous for polynomial patches and an estimate for rational ones; at most BS_TESS_MAX_RATE
 *  parts per patch and direction, where the tolerance may then not be met (docs/tessellation.md).
 *  @since 1.1 */
#define BS_TESS_SUBDIVIDE 2

/**
 * Options of bs_surface_tessellate() and bs_surface_tessellate_count(). Its first field is its
 * own size, so fields can be appended in later minor versions: always fill it with
 * bs_tess_options_init() and then change the fields you need. @since 1.1
 */
typedef struct bs_tess_options {
    size_t size;          /**< sizeof(bs_tess_options), set by bs_tess_options_init() */
    int method;           /**< BS_TESS_UNIFORM (default), BS_TESS_PER_PATCH or BS_TESS_SUBDIVIDE */
    int flags;            /**< 0 or a combination of BS_TESS_RELATIVE, BS_TESS_STRIPS and
                               BS_TESS_REVERSE (from 1.2) */
    size_t nu;            /**< BS_TESS_UNIFORM: segments along u per patch, 1..BS_TESS_MAX_RATE (default 16) */
    size_t nv;            /**< BS_TESS_UNIFORM: segments along v per patch (default 16) */
    double tolerance;     /**< the other methods: as in bs_surface_tessellate_adaptive() (default
                               1e-3 with BS_TESS_RELATIVE unset) */
    size_t max_vertices;  /**< budget: more vertices is BS_ERR_SIZE before any large allocation;
                               0 = only the 32-bit index limit (default) */
    size_t max_triangles; /**< budget on triangles, as max_vertices */
    size_t threads;       /**< threads sampling the vertices, the calling one included: 1 (default)
                               keeps the call on the calling thread, 0 = one per online CPU; the
                               mesh is bit-identical for every count (docs/threads.md) */
} bs_tess_options;

/**
 * @brief Fill an options struct with the defaults (uniform 16 x 16, tolerance 1e-3, no budget,
 * one thread: the calling one).
 * @param[out] o  the options; NULL is a no-op.
 * @since 1.1
 */
BS_API void bs_tess_options_init(bs_tess_options *o);

/**
 * @brief Tessellate a 3-D surface as the options say, refusing before any large allocation when
 * the mesh would exceed a budget or the 32-bit index space.
 * @param[in]  s    the surface (dim 3).
 * @param[in]  o    the options, filled by bs_tess_options_init().
 * @param[out] out  receives the mesh (NULL on failure); release with bs_mesh_destroy().
 * @return BS_OK; BS_ERR_INVALID_ARG if s, o or out is NULL, o->size is smaller than the 1.1
 *         struct, or the method or flags are unknown; BS_ERR_DIMENSION as the 1.0 tessellators;
 *         BS_ERR_DOMAIN for a rate or tolerance out of range; BS_ERR_SIZE when the mesh would have
 *         more vertices or triangles than a budget allows or than 32-bit indices can address;
 *         BS_ERR_NO_MEMORY.
 * @since 1.1
 */
BS_API bs_status bs_surface_tessellate(const bs_surface *s, const bs_tess_options *o, bs_mesh **out);

/**
 * @brief The vertex and triangle counts bs_surface_tessellate() would produce with the same
 * arguments, computed without building the mesh (memory O(number of patches), plus the quadtree for
 * BS_TESS_SUBDIVIDE). Budgets give no error, so a caller can see that they are exceeded. With
 * BS_TESS_SUBDIVIDE a budget bounds the work: as soon as the mesh surely exceeds it, counting stops
 * and the counts returned are lower bounds, already over the budget (since 1.2; set no budget
 * for the exact counts, at the cost of the whole quadtree: about 16 bytes per leaf).
 * @param[in]  s          the surface (dim 3).
 * @param[in]  o          the options.
 * @param[out] vertices   NULL or receives the vertex count.
 * @param[out] triangles  NULL or receives the triangle count.
 * @return as bs_surface_tessellate(), except that budgets give no error; BS_ERR_SIZE only when a
 *         count does not fit in size_t.
 * @since 1.1
 */
BS_API bs_status bs_surface_tessellate_count(const bs_surface *s, const bs_tess_options *o,
                                             size_t *vertices, size_t *triangles);

/**
 * @brief Release a mesh.
 * @param[in] m  the mesh; NULL is a no-op.
 * @since 1.0
 */
BS_API void bs_mesh_destroy(bs_mesh *m);

/**
 * @brief Number of vertices.
 * @param[in] m  the mesh, or NULL.
 * @return the number of vertices; 0 for NULL.
 * @since 1.0
 */
BS_API size_t bs_mesh_vertex_count(const bs_mesh *m);
/**
 * @brief Number of triangles.
 * @param[in] m  the mesh, or NULL.
 * @return the number of triangles; 0 for NULL.
 * @since 1.0
 */
BS_API size_t bs_mesh_triangle_count(const bs_mesh *m);
/**
 * @brief Number of triangle strips.
 * @param[in] m  the mesh, or NULL.
 * @return the number of strips: 0 unless the mesh was built with BS_TESS_STRIPS, or for NULL.
 * @since 1.0
 */
BS_API size_t bs_mesh_strip_count(const bs_mesh *m);
/**
 * @brief Total number of indices in all strips.
 * @param[in] m  the mesh, or NULL.
 * @return the number of strip indices; 0 for NULL.
 * @since 1.0
 */
BS_API size_t bs_mesh_strip_index_count(const bs_mesh *m);

/**
 * @brief Copy the vertex positions into 3 views (x, y, z) of bs_mesh_vertex_count() elements.
 * @param[in]  m    the mesh.
 * @param[out] xyz  3 views: x, y and z of each vertex.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or xyz is NULL or a view's data is NULL or misaligned;
 *         BS_ERR_SIZE if a view is too short (nothing is written then). With 0 vertices the views
 *         are not read.
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_positions(const bs_mesh *m, const bs_view xyz[3]);

/**
 * @brief Copy the unit vertex normals into 3 views. Never NaN: where the surface has no normal at a
 * vertex (a net degenerate to a line) the average of the adjacent triangles' normals, weighted by
 * their areas, is used, or (0,0,1) if that vanishes too.
 * @param[in]  m    the mesh.
 * @param[out] nrm  3 views: the normal's x, y and z of each vertex.
 * @return as bs_mesh_copy_positions().
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_normals(const bs_mesh *m, const bs_view nrm[3]);

/**
 * @brief Copy the vertex (u,v) parameters into 2 views. A vertex shared by several patches keeps the
 * parameters on the patch it was evaluated on (the one with the lowest patch id among those that
 * share it; see bs_mesh_copy_patch_ids()).
 * @param[in]  m    the mesh.
 * @param[out] uv   2 views: u and v of each vertex.
 * @return as bs_mesh_copy_positions().
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_uv(const bs_mesh *m, const bs_view uv[2]);

/**
 * @brief bs_mesh_copy_positions() into float views, e.g. for a GPU vertex buffer (an interleaved
 * x, y, z buffer is 3 views with a stride of 3 * sizeof(float)). Each value is the double that
 * bs_mesh_copy_positions() gives, correctly rounded to float.
 * @param[in]  m    the mesh.
 * @param[out] xyz  3 float views (see bs_fview): x, y and z of each vertex.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or xyz is NULL or a view's data is NULL or misaligned for
 *         float or its stride not a multiple of sizeof(float); BS_ERR_SIZE if a view is too short
 *         (nothing is written then). With 0 vertices the views are not read.
 * @since 1.1
 */
BS_API bs_status bs_mesh_copy_positions_f32(const bs_mesh *m, const bs_fview xyz[3]);

/**
 * @brief bs_mesh_copy_normals() into float views: each value is the double normal coordinate,
 * correctly rounded to float.
 * @param[in]  m    the mesh.
 * @param[out] nrm  3 float views: the normal's x, y and z of each vertex.
 * @return as bs_mesh_copy_positions_f32().
 * @since 1.1
 */
BS_API bs_status bs_mesh_copy_normals_f32(const bs_mesh *m, const bs_fview nrm[3]);

/**
 * @brief bs_mesh_copy_uv() into float views: each parameter is the double one, correctly rounded
 * to float.
 * @param[in]  m    the mesh.
 * @param[out] uv   2 float views: u and v of each vertex.
 * @return as bs_mesh_copy_positions_f32().
 * @since 1.1
 */
BS_API bs_status bs_mesh_copy_uv_f32(const bs_mesh *m, const bs_fview uv[2]);

/**
 * @brief Copy the per-vertex patch ids (the patch each vertex was evaluated on).
 * @param[in]  m    the mesh.
 * @param[out] ids  room for cap ids (not read when there are no vertices).
 * @param[in]  cap  number of ids ids can hold.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or ids is NULL; BS_ERR_SIZE if cap < bs_mesh_vertex_count().
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_patch_ids(const bs_mesh *m, uint32_t *ids, size_t cap);

/**
 * @brief Copy the triangles as 3 * bs_mesh_triangle_count() vertex indices.
 * @param[in]  m    the mesh.
 * @param[out] idx  room for cap indices, three per triangle (counter-clockwise seen from the normal).
 * @param[in]  cap  number of indices idx can hold.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or idx is NULL; BS_ERR_SIZE if cap is too small.
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_triangles(const bs_mesh *m, uint32_t *idx, size_t cap);

/**
 * @brief Copy, per triangle, the id of the patch it tessellates.
 * @param[in]  m    the mesh.
 * @param[out] ids  room for cap ids.
 * @param[in]  cap  number of ids ids can hold.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or ids is NULL; BS_ERR_SIZE if cap < bs_mesh_triangle_count().
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_triangle_patch_ids(const bs_mesh *m, uint32_t *ids, size_t cap);

/**
 * @brief Copy the (u,v) of every triangle corner on the triangle's own patch (3 per triangle, in
 * index order). Unlike bs_mesh_copy_uv() this is exact on shared sides, e.g. for texturing.
 * @param[in]  m   the mesh.
 * @param[out] uv  2 views of 3 * bs_mesh_triangle_count() elements.
 * @return as bs_mesh_copy_positions().
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_corner_uv(const bs_mesh *m, const bs_view uv[2]);

/**
 * @brief Copy the triangle strips. Strip k is idx[start[k]] .. idx[start[k+1]-1]; its triangle i is
 * (s[i], s[i+1], s[i+2]) for even i and (s[i+1], s[i], s[i+2]) for odd i, so every triangle keeps the
 * winding of bs_mesh_copy_triangles(). Strips may hold degenerate triangles (a repeated index) at
 * poles; drop them. The non-degenerate triangles of all strips are exactly the triangle list.
 * @param[in]  m          the mesh.
 * @param[out] idx        room for idx_cap indices (bs_mesh_strip_index_count()).
 * @param[in]  idx_cap    capacity of idx.
 * @param[out] start      room for start_cap offsets (bs_mesh_strip_count() + 1).
 * @param[in]  start_cap  capacity of start.
 * @return BS_OK; BS_ERR_INVALID_ARG if m, idx or start is NULL; BS_ERR_SIZE if a capacity is too small.
 * @since 1.0
 */
BS_API bs_status bs_mesh_copy_strips(const bs_mesh *m, uint32_t *idx, size_t idx_cap, uint32_t *start,
                                     size_t start_cap);

/** Export format: Wavefront OBJ (v, vt, vn, f v/vt/vn), numbers with 17 significant digits. @since 1.0 */
#define BS_MESH_OBJ 0
/** Export format: PLY, binary little-endian, float32 properties and uint32 indices. @since 1.0 */
#define BS_MESH_PLY 1
/** Export format: PLY, ASCII, numbers with 9 significant digits. @since 1.0 */
#define BS_MESH_PLY_ASCII 2
/** Export format: binary STL (float32, facet normals from the triangles' geometry). @since 1.0 */
#define BS_MESH_STL 3

/**
 * @brief Write a mesh to a file. Numbers are written the same in every C locale.
 * The file is replaced atomically, as by bs_surface_write_bpt_file(): written to a temporary file
 * in the same directory, flushed, synced and renamed over path; on failure the temporary file is
 * removed and an existing file at path is left untouched. An existing directory, FIFO or device at
 * path is never replaced.
 * @param[in] m       the mesh.
 * @param[in] format  BS_MESH_OBJ, BS_MESH_PLY, BS_MESH_PLY_ASCII or BS_MESH_STL.
 * @param[in] path    file name.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or path is NULL or format is unknown; BS_ERR_IO if path is
 *         not a regular file or the file cannot be created, written, synced or renamed, with errno
 *         telling why (e.g. ENOSPC, EFBIG, EACCES; EISDIR for a directory, EINVAL for another
 *         non-regular file); BS_ERR_SIZE if the mesh has more triangles than binary STL can count
 *         (UINT32_MAX).
 * @since 1.0
 */
BS_API bs_status bs_mesh_write(const bs_mesh *m, int format, const char *path);

/**
 * @brief Write a mesh into memory: ask for the size with buf NULL, then copy into a buffer that
 * large. The bytes are exactly those bs_mesh_write() puts in a file.
 * @param[in]  m       the mesh.
 * @param[in]  format  as for bs_mesh_write().
 * @param[out] buf     NULL to ask for the size, or room for cap bytes.
 * @param[in]  cap     capacity of buf (ignored when buf is NULL).
 * @param[out] size    receives the number of bytes (needed, or written).
 * @return BS_OK; BS_ERR_INVALID_ARG if m or size is NULL or format is unknown; BS_ERR_SIZE if cap is
 *         smaller than the size (nothing is written then, *size untouched) or for STL as above.
 * @since 1.0
 */
BS_API bs_status bs_mesh_write_memory(const bs_mesh *m, int format, void *buf, size_t cap, size_t *size);

#ifdef __cplusplus
}
#endif

#endif
