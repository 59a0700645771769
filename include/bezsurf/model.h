/**
 * @file
 * libbezsurf models: the trimmed B-rep parts CAD files hold. Include <bezsurf.h> rather than this
 * file.
 *
 * A model is a set of **faces**, each a piece of a surface bounded by **trim loops** (an outer loop
 * first, then any number of inner loops: holes), joined along **edges** into **shells** (a closed
 * shell bounds a solid). Every face's surface is stored as exact rational Bezier patches in one
 * bs_surface (bs_model_surface()), so everything the library does for patches works on models.
 * Planes, cylinders, cones, spheres, tori, surfaces of revolution and of linear extrusion are
 * converted with no approximation (quadratic rational arcs of at most 90 degrees along angular
 * directions); B-spline surfaces become their Bezier spans.
 *
 * A face keeps its **native parameters**, those of the file's surface (angles in radians along
 * angular directions, lengths along rulings and plane axes, knot values for B-splines), so that the
 * file's trim curves apply unchanged; bs_model_face_to_patch() maps them in closed form to a patch
 * and its local (s,t). docs/models.md gives each surface's parametrisation.
 *
 * Models are immutable once made: any number of threads may use the same `const bs_model *`.
 * The common rules of core.h apply: views, NULL meaning "not wanted", n = 0 a no-op, nothing
 * written on failure.
 */
#ifndef BEZSURF_MODEL_H
#define BEZSURF_MODEL_H

#include "core.h"
#include "surface.h"
#include "io.h"
#include "mesh.h"
#include "query.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A trimmed B-rep model (opaque, immutable once made). @since 1.2 */
typedef struct bs_model bs_model;

/** @name Surface kinds of a face (bs_face_info.kind)
 * @{ */
#define BS_FACE_BEZIER     0 /**< Bezier patches of the library (bs_model_from_surface, OBJ bezier) */
#define BS_FACE_BSPLINE    1 /**< B-spline or NURBS surface */
#define BS_FACE_PLANE      2 /**< plane: o + u x + v y */
#define BS_FACE_CYLINDER   3 /**< cylinder: o + r (cos u x + sin u y) + v z */
#define BS_FACE_CONE       4 /**< cone: o + (r + v tan a)(cos u x + sin u y) + v z */
#define BS_FACE_SPHERE     5 /**< sphere: o + r cos v (cos u x + sin u y) + r sin v z */
#define BS_FACE_TORUS      6 /**< torus: o + (R + r cos v)(cos u x + sin u y) + r sin v z */
#define BS_FACE_REVOLUTION 7 /**< a curve revolved about an axis */
#define BS_FACE_EXTRUSION  8 /**< a curve swept along a vector */
/** @} */

/** @name Where a point lies with respect to a trimmed face (bs_model_classify)
 * @{ */
#define BS_TRIM_OUTSIDE 0 /**< outside the face (or outside its surface's domain) */
#define BS_TRIM_INSIDE  1 /**< inside the face, farther than tol from its boundary */
#define BS_TRIM_ON      2 /**< within tol (3-D distance) of the face's boundary */
/** @} */

/**
 * What bs_model_face_info() tells about one face. The caller sets `size` to sizeof(bs_face_info)
 * before the call: fields may be appended in later versions, and only the first `size` bytes are
 * written. @since 1.2
 */
typedef struct bs_face_info {
    size_t size;           /**< sizeof(bs_face_info), set by the caller */
    int kind;              /**< BS_FACE_* */
    int reversed;          /**< 1: the outward normal is opposite the surface normal S_u x S_v */
    size_t shell;          /**< the face's shell, 0 .. bs_model_shell_count() - 1 */
    size_t instance;       /**< assembly placement id (0 without assemblies) */
    size_t first_patch;    /**< its patches in bs_model_surface(): first_patch .. +patch_count-1 */
    size_t patch_count;    /**< number of those patches */
    size_t loop_count;     /**< trim loops, the outer first; 0 = untrimmed (bounded by its box) */
    double u0;             /**< native parameter box of the trimmed face: u from u0 ... */
    double u1;             /**< ... to u1 */
    double v0;             /**< v from v0 ... */
    double v1;             /**< ... to v1 */
} bs_face_info;

/**
 * @brief Read a STEP file (ISO 10303-21, AP203/AP214/AP242 geometry) held in memory.
 * Reads the B-rep solids and shells of the file (docs/models.md lists the entities read and those
 * refused). Lengths stay in the file's length unit; angles are converted to radians.
 * @param[in]  text  the bytes; NULL only when len is 0 (a parse error: no data section).
 * @param[in]  len   number of bytes, at most 256 MiB.
 * @param[out] err   NULL, or receives the line, column and reason of the first error.
 * @param[out] out   receives the new model (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if out is NULL or text is NULL with len > 0; BS_ERR_PARSE for
 *         malformed text or a file with no face (err says what was found); BS_ERR_UNSUPPORTED for
 *         an entity the geometry needs that is not read (err names it and its line);
 *         BS_ERR_SIZE past the documented caps; BS_ERR_NO_MEMORY.
 * @since 1.2
 */
BS_API bs_status bs_model_read_step(const char *text, size_t len, bs_parse_error *err, bs_model **out);

/**
 * @brief Read a STEP file (as bs_model_read_step() on the file's bytes; the file rules of
 * bs_surface_read_bpt_file()).
 * @param[in]  path  file name.
 * @param[out] err   NULL, or receives the error position and reason.
 * @param[out] out   receives the new model (NULL on failure).
 * @return the statuses of bs_model_read_step(); BS_ERR_INVALID_ARG if path is NULL; BS_ERR_IO.
 * @since 1.2
 */
BS_API bs_status bs_model_read_step_file(const char *path, bs_parse_error *err, bs_model **out);

/**
 * @brief Read an IGES 5.3 file held in memory as a model: trimmed surfaces (144, 143), B-rep
 * solids (186) and untrimmed B-spline surfaces (128), with the curves and surfaces
 * docs/models.md lists.
 * @param[in]  text  the bytes; NULL only when len is 0.
 * @param[in]  len   number of bytes, at most 256 MiB.
 * @param[out] err   NULL, or receives the line, column and reason of the first error.
 * @param[out] out   receives the new model (NULL on failure).
 * @return the statuses of bs_model_read_step().
 * @since 1.2
 */
BS_API bs_status bs_model_read_iges(const char *text, size_t len, bs_parse_error *err, bs_model **out);

/**
 * @brief Read an IGES file as a model (as bs_model_read_iges() on the file's bytes).
 * @param[in]  path  file name.
 * @param[out] err   NULL, or receives the error position and reason.
 * @param[out] out   receives the new model (NULL on failure).
 * @return the statuses of bs_model_read_step_file().
 * @since 1.2
 */
BS_API bs_status bs_model_read_iges_file(const char *path, bs_parse_error *err, bs_model **out);

/**
 * @brief Read OBJ free-form text held in memory as a model: each `surf` a face, trimmed by its
 * `trim` and `hole` loops of `curv2` curves.
 * @param[in]  text  the bytes; NULL only when len is 0.
 * @param[in]  len   number of bytes, at most 256 MiB.
 * @param[out] err   NULL, or receives the line, column and reason of the first error.
 * @param[out] out   receives the new model (NULL on failure).
 * @return the statuses of bs_model_read_step().
 * @since 1.2
 */
BS_API bs_status bs_model_read_obj(const char *text, size_t len, bs_parse_error *err, bs_model **out);

/**
 * @brief Read an OBJ file as a model (as bs_model_read_obj() on the file's bytes).
 * @param[in]  path  file name.
 * @param[out] err   NULL, or receives the error position and reason.
 * @param[out] out   receives the new model (NULL on failure).
 * @return the statuses of bs_model_read_step_file().
 * @since 1.2
 */
BS_API bs_status bs_model_read_obj_file(const char *path, bs_parse_error *err, bs_model **out);

/**
 * @brief A model of a surface's patches: each patch an untrimmed face of kind BS_FACE_BEZIER on
 * native parameters (0,1)^2, shared sides joined as edges, one shell per connected set of patches
 * (closed when no side is left open).
 * @param[in]  s    a surface of 3-D patches (a copy is kept: s may be destroyed afterwards).
 * @param[out] out  receives the new model (NULL on failure).
 * @return BS_OK; BS_ERR_INVALID_ARG if s or out is NULL; BS_ERR_DIMENSION if the patches are not
 *         3-D; BS_ERR_SIZE if s is empty; BS_ERR_NO_MEMORY.
 * @since 1.2
 */
BS_API bs_status bs_model_from_surface(const bs_surface *s, bs_model **out);

/**
 * @brief Release a model. NULL does nothing. The surface of bs_model_surface() goes with it.
 * @param[in] m  the model, or NULL.
 * @since 1.2
 */
BS_API void bs_model_destroy(bs_model *m);

/**
 * @brief Write a model as OBJ free-form text: one `surf` per face (a `bezier` surf, or a `bspline`
 * surf whose spans are the face's patches), its trim and hole loops as `curv2` curves, numbers in
 * their shortest exact form, so that bs_model_read_obj() reads a model written from OBJ back
 * value for value. A face along an angular direction is written in its patches' parameters; its
 * trims must then be exact there (constant angles, or one coordinate varying monotonically),
 * else BS_ERR_UNSUPPORTED (docs/models.md says what OBJ cannot carry: orientation flags, shells,
 * surface kinds).
 * @param[in]  m     the model.
 * @param[out] buf   NULL (size query) or room for cap bytes; the text is NUL-terminated.
 * @param[in]  cap   bytes of buf.
 * @param[out] size  receives the bytes needed, the final NUL not counted.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or size is NULL; BS_ERR_SIZE if buf is not NULL and cap
 *         is below *size + 1 (*size is still set, nothing written); BS_ERR_UNSUPPORTED for a
 *         face whose trims OBJ cannot hold exactly; BS_ERR_NO_MEMORY.
 * @since 1.2
 */
BS_API bs_status bs_model_write_obj(const bs_model *m, char *buf, size_t cap, size_t *size);

/**
 * @brief Write a model as an OBJ file (as bs_model_write_obj(); the file is replaced atomically).
 * @param[in] m     the model.
 * @param[in] path  file name.
 * @return the statuses of bs_model_write_obj(); BS_ERR_INVALID_ARG if path is NULL; BS_ERR_IO.
 * @since 1.2
 */
BS_API bs_status bs_model_write_obj_file(const bs_model *m, const char *path);

/**
 * @brief Number of faces (0 for NULL).
 * @param[in] m  the model.
 * @return the count.
 * @since 1.2
 */
BS_API size_t bs_model_face_count(const bs_model *m);

/**
 * @brief Number of edges: 3-D edges shared by faces, each counted once (0 for NULL).
 * @param[in] m  the model.
 * @return the count.
 * @since 1.2
 */
BS_API size_t bs_model_edge_count(const bs_model *m);

/**
 * @brief Number of shells (0 for NULL).
 * @param[in] m  the model.
 * @return the count.
 * @since 1.2
 */
BS_API size_t bs_model_shell_count(const bs_model *m);

/**
 * @brief Whether a shell is closed: every edge of its faces used by exactly two faces of the
 * shell, so that it bounds a solid.
 * @param[in] m      the model.
 * @param[in] shell  shell id.
 * @return 1 closed, 0 open, -1 for NULL or a shell id out of range.
 * @since 1.2
 */
BS_API int bs_model_shell_closed(const bs_model *m, size_t shell);

/**
 * @brief Describe one face.
 * @param[in]     m     the model.
 * @param[in]     face  face id, below bs_model_face_count().
 * @param[in,out] info  info->size set by the caller; the first info->size bytes are written.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or info is NULL or info->size is below the size of the
 *         1.2 struct; BS_ERR_DOMAIN if face is out of range.
 * @since 1.2
 */
BS_API bs_status bs_model_face_info(const bs_model *m, size_t face, bs_face_info *info);

/**
 * @brief Every face's patches, as one surface owned by the model (valid until
 * bs_model_destroy()). Face f's patches are given by bs_model_face_info().
 * @param[in] m  the model.
 * @return the surface, or NULL for NULL.
 * @since 1.2
 */
BS_API const bs_surface *bs_model_surface(const bs_model *m);

/**
 * @brief Evaluate faces at native parameters: positions and outward unit normals (the face's
 * `reversed` applied).
 * A parameter outside the face's patches' domain (outside its parameter box, widened for periodic
 * directions by whole periods, by more than 1e-9 of the box's width) gives NaN in that point; NaN
 * parameters give NaN.
 * @param[in]  m      the model.
 * @param[in]  n      number of points.
 * @param[in]  faces  n face ids.
 * @param[in]  u      n native u parameters.
 * @param[in]  v      n native v parameters.
 * @param[out] pos    NULL or 3 views of n: positions.
 * @param[out] nrm    NULL or 3 views of n: outward unit normals (limit normals at poles).
 * @param[out] kind   NULL or n bytes: BS_NORMAL_* of each normal.
 * @return BS_OK; BS_ERR_INVALID_ARG for a NULL m, a NULL faces, u or v when n > 0, a misaligned
 *         view or a face id out of range; BS_ERR_SIZE for a view shorter than n.
 * @since 1.2
 */
BS_API bs_status bs_model_face_eval(const bs_model *m, size_t n, const uint32_t *faces,
                                    const bs_cview *u, const bs_cview *v, const bs_view *pos,
                                    const bs_view *nrm, unsigned char *kind);

/**
 * @brief Map native face parameters to the patch holding them and the local (s,t) there, in
 * closed form (linear along straight directions and knot spans, the tangent-half-angle map of the
 * quadratic rational arc along angular ones).
 * Parameters outside a face's patches give patch UINT32_MAX and (s,t) NaN.
 * @param[in]  m      the model.
 * @param[in]  n      number of points.
 * @param[in]  faces  n face ids.
 * @param[in]  u      n native u parameters.
 * @param[in]  v      n native v parameters.
 * @param[out] patch  NULL or n patch ids of bs_model_surface().
 * @param[out] st     NULL or 2 views of n: local (s,t) on that patch.
 * @return the statuses of bs_model_face_eval().
 * @since 1.2
 */
BS_API bs_status bs_model_face_to_patch(const bs_model *m, size_t n, const uint32_t *faces,
                                        const bs_cview *u, const bs_cview *v, uint32_t *patch,
                                        const bs_view *st);

/**
 * @brief Map points of the model's patches back to native face parameters: the inverse of
 * bs_model_face_to_patch(), in closed form (linear along straight directions and knot spans, the
 * inverse tangent-half-angle map along angular ones).
 * Local (s,t) outside [0,1] or NaN give face UINT32_MAX and (u,v) NaN.
 * @param[in]  m      the model.
 * @param[in]  n      number of points.
 * @param[in]  patch  n patch ids of bs_model_surface().
 * @param[in]  s      n local s parameters.
 * @param[in]  t      n local t parameters.
 * @param[out] face   NULL or n face ids: the face holding each patch.
 * @param[out] uv     NULL or 2 views of n: native (u,v) on that face.
 * @return BS_OK; BS_ERR_INVALID_ARG for a NULL m, a NULL patch, s or t when n > 0, a misaligned
 *         view or a patch id out of range; BS_ERR_SIZE for a view shorter than n.
 * @since 1.2
 */
BS_API bs_status bs_model_patch_to_face(const bs_model *m, size_t n, const uint32_t *patch,
                                        const bs_cview *s, const bs_cview *t, uint32_t *face,
                                        const bs_view *uv);

/**
 * @brief Classify native face parameters against the face's trim loops: inside, outside, or on
 * the boundary within tol.
 * Exact for points farther than tol (3-D distance) from the boundary: a winding number over the
 * exact trim curves, not over a polygon of them. Points of periodic directions are taken modulo
 * the period; points outside the face's surface domain are OUTSIDE; NaN parameters are OUTSIDE.
 * @param[in]  m      the model.
 * @param[in]  n      number of points.
 * @param[in]  faces  n face ids.
 * @param[in]  u      n native u parameters.
 * @param[in]  v      n native v parameters.
 * @param[in]  tol    3-D distance, finite and >= 0.
 * @param[out] where  n bytes: BS_TRIM_*.
 * @return the statuses of bs_model_face_eval(); BS_ERR_INVALID_ARG if where is NULL (n > 0);
 *         BS_ERR_DOMAIN if tol is negative or not finite.
 * @since 1.2
 */
BS_API bs_status bs_model_classify(const bs_model *m, size_t n, const uint32_t *faces,
                                   const bs_cview *u, const bs_cview *v, double tol,
                                   unsigned char *where);

/**
 * @brief Area of the faces, volume enclosed by the closed shells and centroid, computed on the
 * exact surfaces.
 * Each face's integrals are taken over its trimmed parameter domain by Green's theorem: a line
 * integral along the exact trim curves of an inner integral across the face, both by adaptive
 * Gauss-Kronrod quadrature whose error estimates are held below rel_tol times the quantity's
 * scale (docs/models.md). The volume is the divergence theorem over the closed shells, each face
 * with its outward side; faces of open shells count in the area only.
 * @param[in]  m         the model.
 * @param[in]  rel_tol   relative tolerance, from 1e-12 up to 0.1 (1e-10 is met on the parts of
 *                       data/cad/, docs/models.md). A model far from the origin is held to
 *                       16 eps times (its largest coordinate / its box's diagonal) when that is
 *                       larger: its coordinates carry no more digits.
 * @param[out] area      NULL or: the total area of the faces.
 * @param[out] volume    NULL or: the volume enclosed by the closed shells (NaN when no shell is
 *                       closed).
 * @param[out] centroid  NULL or 3 doubles: the centroid of that volume, or of the area when no
 *                       shell is closed (NaN for an empty model); within rel_tol of the box's
 *                       diagonal.
 * @return BS_OK; BS_ERR_INVALID_ARG if m is NULL; BS_ERR_DOMAIN if rel_tol is out of range or
 *         NaN; BS_ERR_UNSUPPORTED if a face's integrals do not converge within the work cap (a
 *         trim loop that is not closed); nothing is written on failure.
 * @since 1.2
 */
BS_API bs_status bs_model_properties(const bs_model *m, double rel_tol, double *area,
                                     double *volume, double *centroid);

/**
 * @brief Tessellate the model's trimmed faces into one watertight triangle mesh.
 * Each model edge is sampled once, adaptively, and its vertices are shared by the faces on both
 * sides, so a closed shell gives a closed mesh (every mesh edge in exactly two triangles) and no
 * T-junctions. Each face is meshed in its native parameters as a constrained Delaunay
 * triangulation in a metric of its surface, its trim loops the constraints, refined inside until
 * the error estimate of every triangle is within the tolerance (docs/tessellation.md: a
 * second-order estimate from its sides' middles and centroid, as rational patches are in 1.1: an
 * estimate, not a bound) and, within a budget, until no corner angle is below 20 degrees in
 * that metric where the point that would fix it lies inside the face. Triangles wind
 * counter-clockwise seen from outside (the face's `reversed` applied); bs_mesh_copy_patch_ids()
 * and bs_mesh_copy_triangle_patch_ids() give **face** ids, bs_mesh_copy_uv() a vertex's native
 * parameters on the face it was made on, bs_mesh_copy_corner_uv() each corner's native
 * parameters on its triangle's face. Normals are the faces' outward unit normals (at poles the
 * mean of the triangles around). Vertices closer than 1e-6 D (D the diagonal of the model's
 * control points) are one. Faces are meshed on up to o->threads threads; the mesh is
 * bit-identical for every count.
 * @param[in]  m    the model.
 * @param[in]  o    options: method BS_TESS_SUBDIVIDE or BS_TESS_PER_PATCH (the same method here),
 *                  tolerance (absolute, or with BS_TESS_RELATIVE a fraction of D), BS_TESS_REVERSE,
 *                  max_vertices, max_triangles, threads.
 * @param[out] out  receives the mesh (bs_mesh_destroy()); NULL on failure.
 * @return BS_OK (an empty model gives an empty mesh); BS_ERR_INVALID_ARG if m, o or out is NULL,
 *         o->size is too small, the method is unknown or flags has unknown bits;
 *         BS_ERR_UNSUPPORTED for BS_TESS_UNIFORM and BS_TESS_STRIPS (untrimmed faces, such as
 *         an IGES file's lone surfaces and the faces of bs_model_from_surface(), are bounded by
 *         their boxes and are meshed);
 *         BS_ERR_DOMAIN if the tolerance is NaN, Inf, zero or negative, or a face's trim loops
 *         cross or are not closed; BS_ERR_SIZE over a budget (a face's points are counted as they
 *         are made, so the work stops soon after) or past 32-bit indices; BS_ERR_NO_MEMORY.
 * @since 1.2
 */
BS_API bs_status bs_model_tessellate(const bs_model *m, const bs_tess_options *o, bs_mesh **out);

/**
 * @brief The vertex and triangle counts bs_model_tessellate() would give with the same options,
 * without building the mesh (the faces are meshed, which is most of the work).
 * @param[in]  m          the model.
 * @param[in]  o          as for bs_model_tessellate().
 * @param[out] vertices   NULL or the vertex count.
 * @param[out] triangles  NULL or the triangle count.
 * @return the statuses of bs_model_tessellate() (BS_ERR_INVALID_ARG if m or o is NULL).
 * @since 1.2
 */
BS_API bs_status bs_model_tessellate_count(const bs_model *m, const bs_tess_options *o,
                                           size_t *vertices, size_t *triangles);

/**
 * @brief A locator of the model's trimmed faces, for rays (bs_locator_intersect() and its
 * variants) and closest points (bs_locator_closest_point() and its variant). A ray's answer is its first hit inside a trimmed face: hits on a face's surface
 * outside its trims are skipped and the search goes on beyond them; a point within 1e-7 D of a
 * trim (D the diagonal of the model's control points) counts as inside, so that a ray through the
 * edge between two faces hits one of them even where the file's trims of the two stand a little
 * apart. `patch` receives the **face** id, `uv` the native face parameters, `nrm` the face's
 * outward normal (`reversed` applied; kinds as for a surface's locator). The guarantee of rays
 * is that of bs_locator_intersect() on the faces' patches, restricted to the trimmed faces.
 * A closest point is the closest point of the union of the trimmed faces, within
 * tau = 1e-9 (D + d) of the exact distance d as on a surface (on a trim where the surface's own
 * closest point lies outside the face), reported as the face id, its native (u, v), the point
 * and the distance; a point of the surface within 1e-10 D of a trim counts as on the face.
 * The locator refers to the model: m must outlive it (m is not changed; models are immutable).
 * @param[in]  m    the model.
 * @param[out] out  receives the locator (bs_locator_destroy()); NULL on failure.
 * @return BS_OK; BS_ERR_INVALID_ARG if m or out is NULL; BS_ERR_NO_MEMORY.
 * @since 1.2
 */
BS_API bs_status bs_locator_create_model(const bs_model *m, bs_locator **out);

#ifdef __cplusplus
}
#endif

#endif
