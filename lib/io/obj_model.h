/*
 * OBJ free-form models (bs_model_read_obj, bs_model_write_obj), private to lib/io/. Stages:
 *
 *   obj_model.c        the entry points: statements dispatched, the model finished
 *   obj_model_lex.c    tokens of a logical line (backslash continuations), numbers, indices
 *   obj_model_curve.c  curv2 bodies kept as B-splines; trim and hole statements made loops
 *   obj_model_face.c   a surf body's patches and its face with its loops
 *   obj_model_write.c  the writer
 *   obj_model_remap.c  the parameters faces with angular directions are written in
 *
 * Every array grows with the data read, never with a count the file declares; the geometry made
 * (patch and trim control points) is capped by OBJM_POINTS(len) so that memory stays bounded per
 * input byte. Not installed.
 */
#ifndef BEZSURF_IO_OBJ_MODEL_H
#define BEZSURF_IO_OBJ_MODEL_H

#include "io/internal.h"
#include "model/internal.h"

/* Control points (of patches and of trim curves) a text of len bytes may make: 16 per byte
 * (a control point is at most 4 doubles) and 2^16 more. */
#define OBJM_POINTS(len) ((len) < (SIZE_MAX - 65536) / 16 ? 16 * (len) + 65536 : SIZE_MAX)
/* Trims of a loop meet when their ends are this close, relative to the face's parameter box. */
#define OBJM_CLOSURE 1e-7

enum { OBJM_NONE, OBJM_SURF, OBJM_CURV2, OBJM_OTHER };          /* bodies */
enum { OBJM_TNONE, OBJM_BEZIER, OBJM_BSPLINE, OBJM_TOTHER };     /* cstype */

/* A curv2 as a B-spline: knots (count + deg + 1), then x y w per point, in cdata from `at`. */
typedef struct objm_curve {
    size_t deg, count, at;
    int rat;
    size_t line, col;
} objm_curve;

/* A loop of the open surface: its trims in `trims` from `first`; outer (trim) or inner (hole). */
typedef struct objm_loop {
    size_t first, count;
    int outer;
    size_t line, col;
} objm_loop;

typedef struct objm {
    const char *text;
    size_t len, pos;
    size_t line, line_start;  /* 1-based line of pos and the offset of its first byte */
    bs_parse_error *err;
    bsi_growing v;            /* 4 doubles per vertex: x y z w */
    bsi_growing vp;           /* 4 doubles per parameter vertex: u v w, and how many were given */
    int rat, type;            /* from the last cstype */
    size_t type_line;
    char type_name[16];
    size_t deg[2], ndeg;      /* from the last deg */
    int body;                 /* OBJM_* */
    size_t body_line, body_col, parm_line[2], parm_col[2];
    double range[4];          /* s0 s1 t0 t1 of the open surf */
    bsi_growing refs;         /* 0-based (parameter) vertex of each control point of the open body */
    bsi_growing parm[2];      /* parameter values along u and v */
    int have_parm[2];
    bsi_growing curves;       /* objm_curve of every curv2 read */
    bsi_growing cdata;        /* doubles of the curves */
    bsi_growing trims;        /* bsi_trim of the open surf's loops */
    bsi_growing loops;        /* objm_loop of the open surf */
    size_t points_left;       /* control points that may still be made */
    size_t found[4];          /* what else the text holds: f, l, p, curv statements */
    bs_model *m;
} objm;

/* ---- obj_model_lex.c ---- */
int bsi_objm_blank(char c);
/* BS_ERR_PARSE at byte offset `at` of the current line, with fmt and its one string argument. */
bs_status bsi_objm_fail(objm *o, size_t at, const char *fmt, const char *arg);
/* The next token of the statement; 0 at its end (newline, comment or end of the text). */
int bsi_objm_token(objm *o, size_t *start, size_t *tlen);
/* Skip what is left of the statement and its newline. */
void bsi_objm_end_line(objm *o);
int bsi_objm_is(const objm *o, size_t start, size_t tlen, const char *word);
bs_status bsi_objm_number(objm *o, size_t start, size_t tlen, const char *what, double *x);
bs_status bsi_objm_read_number(objm *o, const char *what, double *x);
bs_status bsi_objm_no_more(objm *o, const char *statement);
/* A 1-based index (or a negative one counted back from the last) into n items, as 0-based. */
bs_status bsi_objm_index(objm *o, size_t start, size_t tlen, size_t n, const char *what, size_t *idx);
/* Take `points` from the budget: BS_OK, or BS_ERR_SIZE with err at (line, col). */
bs_status bsi_objm_spend(objm *o, size_t points, size_t line, size_t col);

/* ---- obj_model_curve.c ---- */
/* `end` of a curv2 body: the curve checked and kept. */
bs_status bsi_objm_end_curve(objm *o);
/* `trim` (outer) or `hole` (inner) of the open surf, kw its keyword's offset. */
bs_status bsi_objm_loop(objm *o, size_t kw, int outer);
/* Free the open surf's trims and loops (they are kept for reuse, emptied). */
void bsi_objm_drop_loops(objm *o);

/* ---- obj_model_face.c ---- */
/* `end` of a surf body: its patches and its face added to the model. */
bs_status bsi_objm_end_surf(objm *o);

/* ---- obj_model_remap.c ---- */
#define OBJM_AS_IS   0 /* a trim written with its control points (angular coordinates mapped) */
#define OBJM_SEGMENT 1 /* a trim written as the segment between its mapped ends */
/* Native coordinate x along direction d of face f in the written parameters: 1, or 0 when x lies
 * outside the face's axis. */
int bsi_objm_map(const bsi_face *f, int d, double x, double *out);
/* How trim curve c of face f is written: OBJM_AS_IS, OBJM_SEGMENT, or -1 (not exactly). */
int bsi_objm_trim_form(const bsi_face *f, const bsi_curve *c);

#endif
