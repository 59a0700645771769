/*
 * The STEP reader (ISO 10303-21), private to lib/io/:
 *   step_lex.c      the text -> instances, their parameters stored flat (one node per value)
 *   step_parse.c    the entity index, typed access to parameters, units
 *   step_curve.c    curves (3-D edges and 2-D parameter-space curves) and their parameters
 *   step_surface.c  surfaces -> bsi_surface_def
 *   step_topo.c     faces: loops of oriented edges, their trims
 *   step_assembly.c assemblies: where each shell is placed, once per placement
 *   step_read.c     the entry points: shells and solids of the file
 * Memory: at most one node (24 bytes) per byte of the DATA section plus one instance record per
 * instance; nothing is sized from a count written in the file.
 */
#ifndef BEZSURF_IO_STEP_H
#define BEZSURF_IO_STEP_H

#include "io/internal.h"
#include "model/internal.h"

#include <stdint.h>

#define STP_NEST_MAX 32 /* deepest nesting of parameter lists accepted */
#define STP_DEPTH 16    /* deepest chain of curve references followed (trimmed of trimmed ...) */
#define STP_BYTES_PER_PLACED_FACE 32 /* assemblies place at most one face per 32 bytes of the file */

enum { STP_INT, STP_REAL, STP_STR, STP_ENUM, STP_REF, STP_LIST, STP_UNSET, STP_DERIVED, STP_TYPED };

/* One parameter value. A LIST's children follow it; a TYPED value (KEYWORD(...), also each part of
 * a complex instance) is followed by its one LIST. */
typedef struct stp_node {
    unsigned char kind;
    uint32_t span;   /* nodes of this subtree, itself included */
    uint32_t count;  /* LIST: children */
    uint32_t len;    /* STR, ENUM, TYPED: text length */
    union {
        double num;  /* INT, REAL */
        size_t ref;  /* REF: the entity number */
        size_t off;  /* STR, ENUM, TYPED: text offset */
    } v;
} stp_node;

/* A rigid motion p -> r p + t (r row-major, orthonormal). */
typedef struct stp_xf {
    double r[9], t[3];
} stp_xf;

/* One link of an assembly: representation class `child` placed in class `parent` by xf. */
typedef struct stp_link {
    size_t child, parent, seq; /* seq: the link's place in the file, for a stable order */
    stp_xf xf;
} stp_link;

/* The assembly structure of the file (step_assembly.c). A class is a set of representations
 * joined by relationships without a motion (a part's SHAPE_REPRESENTATION and its
 * ADVANCED_BREP_SHAPE_REPRESENTATION): the same shape. */
typedef struct stp_asm {
    size_t *cls;        /* per instance: union-find parent (representations), else itself */
    size_t *holder;     /* per instance: the representation holding this shell, SIZE_MAX if none */
    size_t *count;      /* per class: its placements, 0 = not counted yet (NULL without links) */
    size_t *base;       /* per class: 1 + the instance id of its first placement, 0 = none given yet */
    unsigned char *busy;/* per class: being counted (a cycle of links) */
    bsi_growing links;  /* stp_link, sorted by child class */
    size_t next;        /* the next instance id to give */
} stp_asm;

/* One instance #id = ...: root is a TYPED node (simple) or a LIST of TYPED nodes (complex). */
typedef struct stp_inst {
    size_t id;
    size_t root;
    uint32_t line, col;
} stp_inst;

typedef struct stp {
    const char *text;
    size_t len;
    bs_parse_error *err;
    bsi_growing nodes;    /* stp_node */
    bsi_growing inst;     /* stp_inst, in file order */
    size_t *order;        /* instance indices sorted by id */
    /* units: radians per plane angle unit of the file */
    double angle;
    double tol;           /* 3-D tolerance for computed trims: 1e-7 of the points' extent */
    double lo[3], hi[3];  /* extent of the file's 3-D points */
    bs_model *model;
    uint32_t *edge_id;    /* per instance: its model edge (EDGE_CURVE), BSI_NO_EDGE before use */
    unsigned char *busy;  /* per instance: being resolved (reference cycles) */
    unsigned char *flip;  /* per instance: a shell used reversed (ORIENTED_CLOSED_SHELL .F.) */
    stp_asm as;
    /* while a placed copy of a shell is read: the motion applied to every 3-D point and
     * direction, the instance id of its faces, and the first model edge of this copy (edge ids
     * below it belong to another copy) */
    int moved;
    stp_xf xf;
    size_t instance;
    uint32_t edge_base;
} stp;

/* ---- step_lex.c ---- */
/* Parse the whole text into s->nodes and s->inst (s->text, len and err set). */
bs_status bsi_stp_lex(stp *s);

/* ---- step_parse.c ---- */
static inline const stp_node *stp_at(const stp *s, size_t n) { return (const stp_node *)s->nodes.data + n; }
static inline const stp_inst *stp_inst_at(const stp *s, size_t i) { return (const stp_inst *)s->inst.data + i; }
/* Sort the index; BS_ERR_PARSE for a number defined twice. */
bs_status bsi_stp_index(stp *s);
void bsi_stp_free(stp *s);
/* The instance of entity number id: 1 and *i, or 0. */
int bsi_stp_find(const stp *s, size_t id, size_t *i);
/* 1 when instance i is (or, complex, has a part) named name. */
int bsi_stp_is(const stp *s, size_t i, const char *name);
/* The name of instance i (its first part's for complex ones), and its length. */
const char *bsi_stp_name(const stp *s, size_t i, int *len);
/* The LIST node of the part `name` of instance i (a simple instance of that name, or a part of a
 * complex one): 1 and *list, else 0. */
int bsi_stp_part(const stp *s, size_t i, const char *name, size_t *list);
/* The k-th child node of LIST node list: 1 and *node, or 0 past the end. */
int bsi_stp_arg(const stp *s, size_t list, size_t k, size_t *node);
/* Fail at instance i's line and column, the message prefixed with "#id NAME: ". */
bs_status bsi_stp_fail(const stp *s, size_t i, const char *fmt, ...);
/* Node n as a number (LENGTH_MEASURE(25.4) and the like unwrapped): 1 and *x, or 0 when it is
 * none. */
int bsi_stp_number(const stp *s, size_t n, double *x);
/* 1 when node n is the enumeration .word. */
int bsi_stp_enum(const stp *s, size_t n, const char *word);
/* Argument k of list (of instance i) as a number / an entity reference (its instance) / a LIST node
 * / an enumeration (1 .T., 0 .F.) : BS_ERR_PARSE naming `what` otherwise. */
bs_status bsi_stp_num(const stp *s, size_t i, size_t list, size_t k, const char *what, double *x);
bs_status bsi_stp_ref(const stp *s, size_t i, size_t list, size_t k, const char *what, size_t *ref);
bs_status bsi_stp_list(const stp *s, size_t i, size_t list, size_t k, const char *what, size_t *node);
bs_status bsi_stp_bool(const stp *s, size_t i, size_t list, size_t k, const char *what, int *b);
/* The reference held by node n: 1 and its instance, 0 when n is not a reference; a reference to an
 * undefined number fails (BS_ERR_PARSE, instance i named). */
bs_status bsi_stp_deref(const stp *s, size_t i, size_t n, const char *what, size_t *ref);
/* The plane angle unit of the file into s->angle (1 when none is found). */
bs_status bsi_stp_units(stp *s);

/* ---- step_curve.c ---- */
enum { STP_LINE, STP_CONIC, STP_BSPLINE };
/* A curve of the file in its own parameter (conics: angles in the file's unit). */
typedef struct stp_curve {
    int kind;
    size_t dim;
    double p[3], d[3];                    /* LINE: point + t d */
    double c[3], x[3], y[3], rx, ry;      /* CONIC: c + rx cos(t a) x + ry sin(t a) y, a = s->angle */
    size_t degree, count;
    double *data;                         /* BSPLINE: knots (count + degree + 1), points, weights */
    double *knots, *ctrl, *weights;       /* into data; weights NULL when not rational */
} stp_curve;

void bsi_stp_curve_free(stp_curve *c);
/* The curve of instance i (LINE, CIRCLE, ELLIPSE, B-spline with knots, rational or not; TRIMMED_CURVE
 * gives its basis) in dim (2 or 3) coordinates. */
bs_status bsi_stp_curve(stp *s, size_t i, size_t dim, int depth, stp_curve *out);
/* The period of the curve's parameter (conics), else 0; its natural domain into lo, hi. */
double bsi_stp_curve_period(const stp *s, const stp_curve *c, double *lo, double *hi);
/* The parameter of the point of c nearest to p (dim coordinates). */
double bsi_stp_curve_param(const stp *s, const stp_curve *c, const double *p);
/* The curve over [t0, t1] as a bsi_curve (B-splines: the range clamped to the knots' domain). */
bs_status bsi_stp_curve_make(const stp *s, const stp_curve *c, double t0, double t1, bsi_curve *out);
/* A CARTESIAN_POINT (dim coordinates), a DIRECTION (unit), a placement (AXIS2_PLACEMENT_3D or 2D:
 * origin, x and y = z cross x in frame f; 2D: z unused). In 3-D, moved by s->xf when s->moved
 * (a placement's frame is made first, then moved: its default reference direction is the file's). */
bs_status bsi_stp_point(const stp *s, size_t i, size_t dim, double *p);
bs_status bsi_stp_direction(const stp *s, size_t i, size_t dim, double *d);
bs_status bsi_stp_placement(const stp *s, size_t i, size_t dim, bsi_frame *f);

/* ---- step_surface.c ---- */
typedef struct stp_surf {
    bsi_surface_def def;
    bsi_curve curve;      /* REVOLUTION, EXTRUSION: the swept curve def.curve points to */
    bs_bspline b;         /* BSPLINE: def.bspline points to it */
    double *data;         /* b's arrays, owned */
    double scale[2];      /* file parameter -> native (the angle unit on angular directions) */
    double dom[4];        /* natural native domain (+-inf where unbounded) */
} stp_surf;

void bsi_stp_surf_free(stp_surf *sf);
/* The surface of instance i. BS_ERR_UNSUPPORTED naming others. */
bs_status bsi_stp_surface(stp *s, size_t i, stp_surf *out);

/* ---- step_assembly.c ---- */
/* Read the file's representations, the shells they hold and the links that place one in another
 * (REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION, MAPPED_ITEM). */
bs_status bsi_stp_assembly(stp *s);
/* How many times shell instance i is placed (1 for a shell outside any assembly). */
bs_status bsi_stp_placement_count(stp *s, size_t i, size_t *n);
/* The world motions of shell instance i into *out (stp_xf, cleared first), and the instance id of
 * the first (the others follow it): 0 in a file without assemblies; in one with, each class of
 * representations holding shells gets ids of its own, in the order its shells are read. */
bs_status bsi_stp_placements(stp *s, size_t i, bsi_growing *out, size_t *first);
void bsi_stp_assembly_free(stp *s);

/* ---- step_topo.c ---- */
/* The face of instance i (ADVANCED_FACE or FACE_SURFACE) into shell `shell`, turned inside out
 * when flip (a shell used reversed: a void of BREP_WITH_VOIDS). */
bs_status bsi_stp_face(stp *s, size_t i, size_t shell, int flip);

#endif
