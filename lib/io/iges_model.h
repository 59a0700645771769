/*
 * The IGES model reader (iges_model*.c, iges_geom*.c): every directory entry parsed at most once
 * into its slot (curves as 3-D pieces with their transformations applied, surfaces as definitions
 * of lib/model/), then faces built from 144 trimmed surfaces or the 186 B-rep. Private to lib/io/.
 */
#ifndef BEZSURF_IO_IGES_MODEL_H
#define BEZSURF_IO_IGES_MODEL_H

#include "io/iges.h"
#include "model/internal.h"

#define IGM_DEPTH 16 /* deepest nesting followed: composites of composites, chains of 124 */

enum { IGM_NEW, IGM_BUSY, IGM_DONE };

/* A surface of the file as the model stores it. */
typedef struct igm_surface {
    bsi_surface_def def;
    bsi_curve curve;   /* REVOLUTION, EXTRUSION: the curve def.curve points to */
    bs_bspline b;      /* BSPLINE: def.bspline points to it */
    double *data;      /* b's knots, points and weights, owned */
    int swap;          /* native (u, v) is the canonical (v, u) */
    int plane;         /* 1: trims from 3-D curves by the plane's affine map (exact) */
    int param;         /* 1: the file's parameter-space curves apply (through aff) */
    double aff[6];     /* file parameters (x, y) -> native: (a b c; d e f) */
    int has_box;
    double box[4];     /* native box of the whole surface (128's range, 120's), when bounded */
} igm_surface;

typedef struct igm_slot {
    unsigned char state, used;
    long type, form;
    bsi_curve *pieces;     /* curves: consecutive 3-D pieces */
    size_t npieces;
    igm_surface *surf;     /* surfaces */
    double *mat;           /* 116, 123: the point or direction, transformed (124s: iges_matrix.c) */
    long *edge_curve;      /* 504: each edge's curve pointer */
    uint32_t *edge_id;     /* 504: each edge's model edge, BSI_NO_EDGE until used */
    size_t nedge;
} igm_slot;

typedef struct igm {
    iges g;
    igm_slot *slot;        /* one per directory entry */
    size_t nslot;
    bs_model *model;
    bsi_growing vals;      /* scratch reals */
    int named;             /* the error message names its entity */
    size_t copies;         /* control points copied into composites and trims (bsi_igm_spend) */
} igm;

/* ---- iges_model.c ---- */
/* Fail naming entity s (slot index) and its DE number at field f (1..20) of its directory entry. */
bs_status bsi_igm_fail(igm *m, size_t s, int f, const char *fmt, ...);
/* After a failure inside entity s's parameters: prefix the message with the entity's name. */
bs_status bsi_igm_name(igm *m, size_t s, bs_status st);
/* The parameter data of slot s, its type field read and its P records' back pointers checked. */
bs_status bsi_igm_open(igm *m, size_t s, iges_stream *st);
/* The slot a DE pointer read from entity s's parameters designates (at stream position pos):
 * BS_ERR_PARSE when it is not the first record of a directory entry. */
bs_status bsi_igm_ref(igm *m, size_t s, const iges_stream *st, size_t pos, long ptr, size_t *out);
/* The next field as a DE pointer (0 allowed when zero_ok). */
bs_status bsi_igm_ptr(igm *m, size_t s, iges_stream *st, const char *what, int zero_ok, size_t *out,
                      int *none);
/* The fields up to the record delimiter, read and not used. */
bs_status bsi_igm_rest(igm *m, iges_stream *st);

/* ---- iges_geom.c: transformations and curves ---- */
/* The 3x4 matrix of slot s's chain of 124 (identity without one). */
bs_status bsi_igm_matrix(igm *m, size_t s, double *mat);
/* Apply a 3x4 matrix to a 3-D curve. */
void bsi_igm_move(bsi_curve *c, const double *mat);
/* The curve of slot s (100, 102, 104, 110, 126), built once. */
bs_status bsi_igm_curve(igm *m, size_t s, int depth);
/* Count the control points of slot c's pieces as copied once more by entity s: BS_ERR_PARSE past
 * 8 per byte of the file (curves reused so often that copies would outgrow the input). */
bs_status bsi_igm_spend(igm *m, size_t s, size_t c);
/* A 2-D curve (p -> (A p) of rows A[0..3], A[4..7]) of a 3-D piece. */
bs_status bsi_igm_curve2(const bsi_curve *c, const double *a, bsi_curve *out);

/* ---- iges_geom_surf.c: surfaces ---- */
/* The surface of slot s (108, 120, 122, 128, 190 .. 198), built once. */
bs_status bsi_igm_surface(igm *m, size_t s, int depth);
/* The fields of a 128 after its type into sf (iges_geom_128.c). */
bs_status bsi_igm_bspline_128(igm *m, size_t s, iges_stream *st, igm_surface *sf);
/* Fail unless slot t (pointed to by entity s) has the given type. */
bs_status bsi_igm_typed(igm *m, size_t s, size_t t, long type);

/* ---- iges_model_face.c: faces ---- */
/* A face's trims as they are read: loops of lens[k] trims each. */
typedef struct igm_acc {
    bsi_growing trims;     /* bsi_trim */
    bsi_growing lens;      /* size_t */
    size_t open;           /* trims of the loop being read */
    double period[2];      /* native periods of the face's surface */
    const igm_surface *sf; /* the face's surface, once a trim is read */
    int untrimmed;         /* the loop is the surface's own box (a lone 128): reported untrimmed */
} igm_acc;

void bsi_igm_acc_free(igm_acc *a);
/* The trims of curve slot c on the surface of slot ss (built): from its parameter-space pieces
 * (space 0), or from its 3-D pieces (space 1; run backwards when reversed) mapped exactly onto a
 * plane or projected. The first trim gets edge, the others none. Entity s is named in errors. */
bs_status bsi_igm_trims(igm *m, size_t s, size_t ss, size_t c, int space, int reversed, uint32_t edge,
                        igm_acc *a);
/* End the loop being read (nothing when it is empty): a loop with projected trims is made
 * continuous across seams by whole periods, and a gap between a trim's end and the next one's
 * start (a pole the file leaves out) is closed by a line. */
bs_status bsi_igm_close_loop(igm_acc *a);
/* The face of the surface at slot ss with the loops of a (emptied), in shell `shell`. */
bs_status bsi_igm_add_face(igm *m, size_t s, size_t ss, igm_acc *a, int reversed, size_t shell);
/* The face of a 144 (or 143) at slot s, in shell `shell`. */
bs_status bsi_igm_trimmed(igm *m, size_t s, size_t shell);
/* The untrimmed face of the surface at slot s. */
bs_status bsi_igm_untrimmed(igm *m, size_t s, size_t shell);
/* The faces of the 186 B-rep at slot s, its shells from *shell on (advanced). */
bs_status bsi_igm_brep(igm *m, size_t s, size_t *shell);
/* After the 186s: each 514 shell no solid holds as a shell of its own, then the 510 faces no
 * shell holds as one shell, from *shell on (advanced). */
bs_status bsi_igm_loose_brep(igm *m, size_t *shell);

#endif
