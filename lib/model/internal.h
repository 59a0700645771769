/*
 * Model layer, shared with lib/io/ (the readers build models with it): faces over exact rational
 * Bezier patches with their native parameter maps, trim loops of piecewise rational Bezier
 * curves, edges and shells. Not installed. docs/models.md describes the model; this header is
 * how the pieces fit:
 *
 *   axis.c       one direction's native parameter <-> (piece, local s)
 *   curve.c      trim and edge curves: lines, conics, B-splines as rational Bezier segments
 *   analytic.c   planes .. extrusions as exact rational Bezier patches over a parameter box
 *   model.c      the model: building it face by face, then frozen; the counts and face info
 *   face_map.c   native parameters -> patch and (s,t); face evaluation
 *   classify.c   inside / outside / on by a winding number over the exact trim curves
 *                (classify_box.c: where a box of parameters lies; classify_near.c: nearness)
 *   closest_trim.c  closest points on the faces' trims, for a model's locator (locator_model.c)
 *   properties.c area, volume and centroid by Green's theorem over the trimmed domains
 *                (quadrature.c: adaptive Gauss-Kronrod)
 *   sew.c        edges of files without topology: trims whose 3-D images coincide
 *   pcurve.c     trims computed by projecting 3-D edges onto the surface
 */
#ifndef BEZSURF_MODEL_INTERNAL_H
#define BEZSURF_MODEL_INTERNAL_H

#include "bezsurf.h"
#include "query/internal.h"
#include "bspline/internal.h"

/* ---- One direction of a face or a curve: native parameter -> (piece, local s) (axis.c) ----
 * LINEAR pieces map [b_k, b_k+1] linearly onto [0,1]. ANGULAR pieces are quadratic rational arcs
 * of weights (1, cos a, 1) spanning the angle 2a = radians * (b_k+1 - b_k); a native x at angle
 * phi = radians * (x - b_k) from the piece's start has the local parameter
 *   s = (1 + tan((phi - a) / 2) / tan(a / 2)) / 2,  and back  phi = a + 2 atan((2s - 1) tan(a / 2)). */
#define BSI_AXIS_LINEAR  0
#define BSI_AXIS_ANGULAR 1
#define BSI_QUARTER_TURN 1.5707963267948966 /* the widest angular piece, pi / 2 */

typedef struct bsi_axis {
    int kind;        /* BSI_AXIS_* */
    size_t n;        /* pieces (0: an empty axis) */
    double *breaks;  /* n + 1 increasing native values, owned */
    double *quarter; /* ANGULAR: tan(a / 2) of each piece, kept after the breaks in their block
                      * (the maps ask for it at every point); NULL: computed when asked */
    double radians;  /* ANGULAR: radians per native unit (1 when native angles are radians) */
} bsi_axis;

/* The piece holding x (the later piece at a break, the last one at the end) and the local s there:
 * 1 when found, 0 when x is NaN or outside [breaks[0], breaks[n]] (*piece and *s untouched). */
int bsi_axis_locate(const bsi_axis *a, double x, size_t *piece, double *s);
/* The native parameter of local s on piece k. */
double bsi_axis_native(const bsi_axis *a, size_t k, double s);
/* ds/dx at native x on piece k: the derivative of the map, for partials in native parameters. */
double bsi_axis_rate(const bsi_axis *a, size_t k, double x);
/* Breaks cutting [x0, x1] into pieces: ANGULAR ones at most a quarter turn each and of equal
 * width, LINEAR ones at the given interior breaks inner[0..ninner) that lie strictly inside.
 * BS_ERR_NO_MEMORY (a left empty) or BS_ERR_DOMAIN for x0 >= x1 or non-finite ends. */
bs_status bsi_axis_make(int kind, double radians, double x0, double x1, const double *inner,
                        size_t ninner, bsi_axis *a);
/* After the breaks were moved in place: the kept tangents made again from them (if kept). */
void bsi_axis_refresh(bsi_axis *a);
bs_status bsi_axis_copy(const bsi_axis *src, bsi_axis *dst);
void bsi_axis_free(bsi_axis *a);

/* ---- Piecewise rational Bezier curves in 2-D (trims, native uv) or 3-D (edges) (curve.c) ----
 * Segment k, point i, coordinate c at hom[(k * (degree + 1) + i) * (dim + 1) + c]: w*x, w*y (w*z),
 * then w. The axis maps the curve's native parameter to (segment, local t). */
typedef struct bsi_curve {
    size_t dim;     /* 2 or 3 */
    size_t degree;  /* of every segment, 1 .. BS_MAX_DEGREE */
    bsi_axis axis;  /* axis.n segments */
    double *hom;    /* owned */
} bsi_curve;

void bsi_curve_free(bsi_curve *c);
bs_status bsi_curve_copy(const bsi_curve *src, bsi_curve *dst);
/* 1 when the 3-D curve c ends within tol of where it starts (its first and last control points). */
int bsi_curve_closed(const bsi_curve *c, double tol);
/* A closed curve over three of its periods (the period its parameter range), the same points one
 * period before and after: what a sweep of it needs for trims on either side of its start.
 * BS_ERR_DOMAIN for an empty curve; BS_ERR_NO_MEMORY. */
bs_status bsi_curve_repeat(const bsi_curve *src, bsi_curve *out);
/* p + t d for t in [t0, t1]: one segment of degree 1. */
bs_status bsi_curve_line(size_t dim, const double *p, const double *d, double t0, double t1,
                         bsi_curve *out);
/* c + rx cos(phi) x + ry sin(phi) y, phi = radians * t, for t in [t0, t1] (a circle when rx = ry,
 * an ellipse otherwise; x and y orthonormal, of dim coordinates): quadratic arcs of at most a
 * quarter turn, exact. */
bs_status bsi_curve_conic(size_t dim, const double *c, const double *x, const double *y, double rx,
                          double ry, double radians, double t0, double t1, bsi_curve *out);
/* A B-spline (rational when weights is not NULL) of count points of dim coordinates, restricted to
 * [t0, t1] inside its knot domain: its Bezier spans, cut at t0 and t1. BS_ERR_DEGREE,
 * BS_ERR_SIZE, BS_ERR_DOMAIN (knots, or the range), BS_ERR_NONFINITE as bs_surface_add_bspline. */
bs_status bsi_curve_bspline(size_t dim, size_t degree, size_t count, const double *knots,
                            const double *ctrl, const double *weights, double t0, double t1,
                            bsi_curve *out);
/* Apply p -> A p + b (A row-major 3x3 then b: 12 doubles) to a 3-D curve, or the 2-D affine
 * (a b c; d e f) (6 doubles) to a 2-D one. */
void bsi_curve_transform(bsi_curve *c, const double *affine);
/* The point at native t (0 when t is outside the curve's range) and at local s of segment k. */
int bsi_curve_eval(const bsi_curve *c, double t, double *p);
void bsi_curve_point(const bsi_curve *c, size_t k, double s, double *p);
/* The curve restricted to [t0, t1] inside its range, exactly and on the same kind of map (cut
 * arcs of an angular axis put back into the standard form of their map; curve_cut.c).
 * BS_ERR_DOMAIN for an empty or outside range, BS_ERR_NO_MEMORY. */
bs_status bsi_curve_cut(const bsi_curve *src, double t0, double t1, bsi_curve *out);
/* Bounding box of the control points: lo[dim], hi[dim]. */
void bsi_curve_bounds(const bsi_curve *c, double *lo, double *hi);

/* ---- Exact surfaces (analytic.c). Canonical parameters (those of STEP, ISO 10303-42):
 *   PLANE       o + u x + v y
 *   CYLINDER    o + r (cos u x + sin u y) + v z
 *   CONE        o + (r + v tan(r2)) (cos u x + sin u y) + v z     (r2 the semi-angle)
 *   SPHERE      o + r cos v (cos u x + sin u y) + r sin v z
 *   TORUS       o + (r + r2 cos v) (cos u x + sin u y) + r2 sin v z
 *   REVOLUTION  curve(v) turned by the angle u about the axis through o along z
 *   EXTRUSION   curve(u) + v dir
 *   BSPLINE     the B-spline at its knot parameters (u, v)
 * u and v angles in radians. */
typedef struct bsi_frame {
    double o[3], x[3], y[3], z[3]; /* origin and a right-handed orthonormal basis */
} bsi_frame;

typedef struct bsi_surface_def {
    int kind;                  /* BS_FACE_*, not BEZIER */
    bsi_frame f;
    double r, r2;              /* radii and the cone's semi-angle, as above */
    const bsi_curve *curve;    /* REVOLUTION, EXTRUSION: the 3-D curve */
    double curve_period;       /* REVOLUTION, EXTRUSION: the curve's period when it is closed (a
                                  whole conic: a torus written as its tube revolved), else 0 */
    double dir[3];             /* EXTRUSION: the sweep per unit v */
    const bs_bspline *bspline; /* BSPLINE: a 3-D B-spline */
} bsi_surface_def;

/* Append to s the exact patches of def over the canonical box (u0 u1 v0 v1, u0 < u1, v0 < v1),
 * angular directions cut into equal pieces of at most a quarter turn, curve directions at their
 * segments' breaks, B-splines at their knots; au and av receive the maps, patch (i, j) being the
 * (i * av->n + j)-th appended. On failure s is unchanged and au, av are empty.
 * BS_ERR_DOMAIN for a box outside the surface's domain (a B-spline's, a curve's range), bad radii
 * or a degenerate frame; BS_ERR_NONFINITE; BS_ERR_NO_MEMORY. */
bs_status bsi_surface_def_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                                  bsi_axis *au, bsi_axis *av);
/* The closed-form point of def at canonical (u, v) (for BSPLINE, REVOLUTION and EXTRUSION through
 * de Boor / the curve): the reference the exactness tests compare with. */
void bsi_surface_def_eval(const bsi_surface_def *def, double u, double v, double *p);
/* Period of canonical u and v (2 pi along the angular directions of closed surfaces, the curve's
 * period along the curve of a sweep of a closed curve), 0 if none. */
void bsi_surface_def_periods(const bsi_surface_def *def, double *pu, double *pv);
/* The canonical (u, v) of the point of def nearest p, in closed form for PLANE .. TORUS: 1, or 0
 * (uv untouched) for the other kinds and where u (or a torus's v) is undefined: on the axis, at
 * the centre of a sphere or the core circle of a torus. Angles are in [0, 2 pi) (a sphere's v in
 * [-pi/2, pi/2]), or with a finite hint the ones nearest hint[0] (and a torus's v nearest
 * hint[1]) by whole turns, for continuity along a curve. */
int bsi_surface_def_inverse(const bsi_surface_def *def, const double *p, const double *hint, double *uv);

/* ---- The model (model.c, face_map.c) ---- */
#define BSI_NO_EDGE UINT32_MAX
/* How far apart, in units of the model's diagonal, a file may write the two trims of one edge
 * (a kernel's edge tolerance: block.igs, 6.3e-4): sewing joins closed trims that far apart
 * (sew.c) and the tessellator gives such an edge one set of vertices (tess_edges.c). */
#define BSI_LOOSE_GAP 2e-3

typedef struct bsi_trim {
    bsi_curve uv;     /* dim 2, in the face's native parameters */
    int reversed;     /* 1: the loop runs along it from its end to its start */
    uint32_t edge;    /* model edge, or BSI_NO_EDGE until sewn */
    int computed;     /* 1: projected from the 3-D edge (pcurve.c) */
    double lo[2], hi[2]; /* bsi_curve_bounds of uv, set as the face is added (the tests of a
                          * point against the loops ask for them at every point) */
} bsi_trim;

typedef struct bsi_loop {
    size_t first_trim, trim_count;
} bsi_loop;

typedef struct bsi_face {
    int kind, reversed;
    int swap;                  /* 1: native (u, v) is the surface's canonical (v, u) */
    size_t shell, instance;
    size_t first_patch, patch_count;
    bsi_axis au, av;           /* canonical directions; patch (i, j) = first_patch + i * av.n + j */
    double period[2];          /* native periods of u and v (0: not periodic) */
    size_t first_loop, loop_count;
    int untrimmed;             /* 1: its one loop is its surface's own box (reported as 0 loops) */
    double box[4];             /* native u0 u1 v0 v1 */
    double lip[2];             /* bounds of |S_u|, |S_v| over the face (native parameters) */
} bsi_face;

typedef struct bsi_edge {
    size_t uses;               /* trims referring to it */
    uint32_t face[2];          /* the first two faces using it */
} bsi_edge;

struct bs_model {
    bs_surface *surface;
    bsi_face *faces;
    size_t nface, face_cap;
    bsi_loop *loops;
    size_t nloop, loop_cap;
    bsi_trim *trims;
    size_t ntrim, trim_cap;
    bsi_edge *edges;
    size_t nedge, edge_cap;
    size_t nshell;
    unsigned char *shell_closed; /* nshell flags, set by bsi_model_finish */
};

/* An empty model to be filled by a reader. BS_ERR_NO_MEMORY. */
bs_status bsi_model_create(bs_model **out);

/* A face for bsi_model_add_face(). Its loops are trims[0 .. loop_len[0]), then the next
 * loop_len[1], ...; the outer loop first. Each loop must be closed (end of each trim at the start
 * of the next within the reader's tolerance). */
typedef struct bsi_face_spec {
    const bsi_surface_def *def;  /* the surface; NULL for BEZIER faces (patch given) */
    const bs_patch *patch;       /* BEZIER: the one patch, native parameters its (0,1)^2 */
    int reversed, swap;
    size_t shell, instance;
    const double *box;           /* NULL: the loops' bounding box (native); else u0 u1 v0 v1 */
    bsi_trim *trims;             /* moved into the model: the caller's curves are emptied */
    size_t ntrim;
    const size_t *loop_len;
    size_t nloop;
    int untrimmed;               /* 1: the one loop is the surface's own box (an IGES lone 128) */
} bsi_face_spec;

/* Append a face: its patches over its box, its loops. On failure the model is as before (the
 * trims' curves are freed either way). BS_ERR_DOMAIN for an empty box, the statuses of
 * bsi_surface_def_patches(), BS_ERR_SIZE past UINT32_MAX faces or patches, BS_ERR_NO_MEMORY. */
bs_status bsi_model_add_face(bs_model *m, const bsi_face_spec *spec, size_t *face);
/* A new edge id (uses counted as trims name it). BS_ERR_SIZE, BS_ERR_NO_MEMORY. */
bs_status bsi_model_add_edge(bs_model *m, uint32_t *edge);
/* Done reading: shells' count and closedness from the edges' uses (sew.c joins the trims left
 * without an edge first). BS_ERR_NO_MEMORY. */
bs_status bsi_model_finish(bs_model *m);

/* The diagonal of the bounding box of the model's patches (0 for an empty model). */
double bsi_model_diagonal(const bs_model *m);

/* Native (u, v) of face f -> patch id and local (s, t): 1, or 0 outside its patches. Periodic
 * directions are first brought into the face's box by whole periods. */
int bsi_face_locate(const bs_model *m, size_t f, double u, double v, uint32_t *patch, double *st);
/* The point of face f at native (u, v): 1, or 0 outside (p untouched). */
int bsi_face_point(const bs_model *m, size_t f, double u, double v, double *p);
/* The point and its partials along native u and v (the surface's own, `reversed` not applied):
 * 1, or 0 outside. */
int bsi_face_partials(const bs_model *m, size_t f, double u, double v, double *p, double *pu,
                      double *pv);
/* bsi_face_partials, and cell[6]: the native u and v ranges of the patch holding the point (u0 u1
 * v0 v1) and the point itself brought into the face's box (u, v), in the same frame. */
int bsi_face_partials_cell(const bs_model *m, size_t f, double u, double v, double *p, double *pu,
                           double *pv, double *cell);
/* The face holding patch p (a valid patch id of the model). */
size_t bsi_face_of_patch(const bs_model *m, uint32_t p);
/* The face of patch p and the native (u, v) of the patch's (s, t) there. */
size_t bsi_patch_native(const bs_model *m, uint32_t p, double s, double t, double native[2]);
/* Bring u into [lo, lo + period) when period > 0. */
double bsi_wrap(double u, double lo, double period);

/* ---- Classification (classify.c) ---- */
/* The bounds of the face's 3-D speeds along native u and v, kept in face->lip as it is added. */
void bsi_face_speed(const bs_model *m, const bsi_face *face, double lip[2]);
/* BS_TRIM_* of native (u, v) on face f (a valid id), tol a finite 3-D distance >= 0. */
int bsi_face_classify(const bs_model *m, size_t f, double u, double v, double tol);
/* 1 when the point is within tol of the face: bsi_face_classify would not say OUTSIDE, or it is
 * within tol of a seam (a seam's points are the face's). Answered by the cheap parity test first:
 * the certified search for nearness to the trims runs only for points outside the loops. */
int bsi_face_covers(const bs_model *m, size_t f, double u, double v, double tol);
/* 1 when the loops' parity alone puts (u, v) inside face f (no ON test; exact off the trims). */
int bsi_face_parity(const bs_model *m, size_t f, double u, double v);
/* Where the native box nb = (u0, u1, v0, v1) inside face f's box lies: BSI_CL_IN, BSI_CL_OUT, or
 * BSI_CL_CROSS when a trim, or a chord closing a loop, may pass through it (classify_box.c). */
int bsi_face_box_place(const bs_model *m, size_t f, const double nb[4]);
/* Closest points on the boundaries of a model's faces (closest_trim.c): bounds made once per
 * trim segment, then a certified search per query. diag: the D of the tolerance 0.5e-9 (D + d). */
typedef struct bsi_trim_search bsi_trim_search;
bs_status bsi_trim_search_create(const bs_model *m, double diag, bsi_trim_search **out);
void bsi_trim_search_free(bsi_trim_search *ts);
/* A point of a boundary nearer to q than *best_d: 1 with *best_d, *patch and st (its patch and
 * local parameters) set, 0 when there is none, -2 when the search cannot be certified. */
int bsi_trim_search_closest(const bsi_trim_search *ts, const double *q, double *best_d,
                            uint32_t *patch, double st[2]);
/* 1 when trim t of face f is a seam of the face, not a boundary (classify_near.c). */
int bsi_trim_is_seam(const bs_model *m, size_t f, size_t t);

/* ---- Sewing (sew.c): trims without an edge whose 3-D images coincide within tol become one
 * edge, closed trims left over within loose_tol; called by bsi_model_finish.
 * BS_ERR_NO_MEMORY. ---- */
bs_status bsi_model_sew(bs_model *m, double tol, double loose_tol);

/* ---- Computed parameter-space curves (pcurve.c) ---- */
/* The trim on face f's surface of the 3-D curve edge over its whole range, from certified closest
 * points at enough parameters that the trim, evaluated on the surface, stays within tol of the
 * edge; out->computed is set. Needs the face's patches (call after the face is added with a
 * provisional box, or give the def and box). BS_ERR_DOMAIN when the edge leaves the surface by
 * more than tol, BS_ERR_NO_MEMORY. */
bs_status bsi_pcurve_project(const bs_model *m, size_t f, const bsi_curve *edge, double tol,
                             bsi_trim *out);
/* Method: feet of the edge at its segment ends, reached by continuation (periodic parameters
 * unwrap along the edge: a full circle of a cylinder runs u over 2 pi), joined by cubic Hermite
 * segments (uv' = J+ C') bisected until their images are within tol/2 of the edge beyond the edge's
 * own distance to the surface (at most 4096 segments, else BS_ERR_DOMAIN). The trim's axis is LINEAR
 * over the edge's native range (trim parameter = edge parameter), breaks at the segments' ends.
 * At a pole (u undefined) u is the neighbouring foot's. Periodic directions are placed by whole
 * periods inside the face's box when the trim's range fits there, else with its start in
 * [box lo, box lo + period): a seam edge comes out at the box's low side (u = 0, not 2 pi); fix
 * loops with bsi_pcurve_close_loop(). BS_ERR_INVALID_ARG for a bad face, edge or tol <= 0. */

/* The same from the face's surface definition, before the face is added (STEP edges with only 3-D
 * curves). def: the face's surface; swap: as bsi_face_spec.swap; box: NULL or the native
 * u0 u1 v0 v1 the face will cover: BSPLINE, REVOLUTION and EXTRUSION are projected onto their
 * patches over it (NULL: the B-spline's knot domain; a revolution's [0, 2 pi] x its curve's range;
 * an extrusion's curve range x the edge's extent along the sweep), CYLINDER .. TORUS use closed forms
 * and box only for placing periodic parameters (NULL: [0, period]); hint: NULL or a native (u, v)
 * the trim's start is put nearest to by whole periods (then box places nothing). Statuses as
 * bsi_pcurve_project, and those of bsi_surface_def_patches. A PLANE's trim is exact: the edge's own
 * control points in the plane's (u, v) over the edge's own axis (rational arcs stay arcs). */
bs_status bsi_pcurve_project_def(const bsi_surface_def *def, int swap, const double *box,
                                 const double *hint, const bsi_curve *edge, double tol,
                                 bsi_trim *out);
/* Shift trims[1 .. n) of one loop, each by whole periods (period[2], native; 0: none), so that
 * each starts where the one before ends (in the loop's direction: `reversed` trims start at their
 * curve's end): a seam edge used twice lands at u = 0 once and at u = 2 pi once. trims[0] stays. */
void bsi_pcurve_close_loop(bsi_trim *trims, size_t n, const double *period);
/* The same for one loop of trims computed on def (as bsi_pcurve_project_def: swap, box): the def's
 * periodic directions as above, and where the surface is closed without being periodic (a clamped
 * B-spline whose first and last rows of control points agree within tol, as a lofted tube; an
 * extrusion or revolution of a closed curve) each trim lying on that seam is put on the domain's
 * low or high side, whichever the trims before and after it in the loop are nearer to. Without
 * it both uses of such a seam edge come out on the side the closest point happens to give. */
void bsi_pcurve_close_loop_def(const bsi_surface_def *def, int swap, const double *box, double tol,
                               bsi_trim *trims, size_t n);

#endif
