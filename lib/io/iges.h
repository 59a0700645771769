/*
 * The IGES readers' records and parameter fields (iges_records.c) and 124 matrices (iges_matrix.c),
 * used by iges_read.c and the model reader (iges_model.h). Private
 * to lib/io/; not installed. docs/formats.md describes the subset read.
 */
#ifndef BEZSURF_IO_IGES_H
#define BEZSURF_IO_IGES_H

#include "io/internal.h"

#include <math.h>

enum { IGES_S, IGES_G, IGES_D, IGES_P, IGES_T, IGES_SECTIONS };

typedef struct iges {
    const char *text;
    size_t len;
    bs_parse_error *err;
    size_t *rec;                     /* offset of each record's first byte; record r is line r + 1 */
    size_t nrec, rec_cap;
    size_t first[IGES_SECTIONS];     /* first record of each section */
    size_t count[IGES_SECTIONS];     /* its number of records */
    char pdelim, rdelim;             /* parameter and record delimiters of the global section */
    size_t points;                   /* patch control points made so far (BSI_READ_POINTS caps them) */
    struct iges_124 *mat;            /* 124 matrices by directory entry (bsi_iges_124), or NULL */
} iges;

/* A 124's 3 x 4 matrix (rows R | T), once parsed. */
typedef struct iges_124 {
    double m[12];
    int read;
} iges_124;

/* Parameters spread over consecutive records: columns 1..width of records first .. first+nrec-1. */
typedef struct iges_stream {
    size_t first, nrec, width;
    size_t pos;                      /* next character, counted over the records' data columns */
    int ended;                       /* the record delimiter has been read */
} iges_stream;

/* One parameter: its characters at stream positions start .. start+len-1 (a Hollerith string's
 * text without its count and H), blanks around it left out. */
typedef struct iges_field {
    size_t start, len;
    int hollerith;
    int last;                        /* ended by the record delimiter */
} iges_field;

/* Index the records and the sections; BS_ERR_PARSE (err filled) or BS_ERR_NO_MEMORY. */
bs_status bsi_iges_records(iges *g);
/* Read the delimiters and check the fields of the global section. */
bs_status bsi_iges_global(iges *g);
/* Fail at the record and column of stream position pos. */
bs_status bsi_iges_fail_at(const iges *g, const iges_stream *s, size_t pos, const char *fmt, ...);
/* The next field; BS_ERR_PARSE after the record delimiter, at the stream's end or on a malformed
 * Hollerith string. */
bs_status bsi_iges_field(const iges *g, iges_stream *s, iges_field *f);
/* The next field as a real (integers and D exponents accepted, an empty field is 0) or as an
 * integer in [lo, hi] (an empty field is 0); what names it in the error message. */
bs_status bsi_iges_real(const iges *g, iges_stream *s, const char *what, double *x, iges_field *f);
bs_status bsi_iges_int(const iges *g, iges_stream *s, const char *what, long lo, long hi, long *x);
/* The parameter data of the directory entry whose first record is D record de (its fields 2 and
 * 14), the back pointer of each of its P records checked to name that entry: BS_ERR_PARSE when
 * the records lie outside the P section or one names another entry. */
bs_status bsi_iges_open(const iges *g, size_t de, iges_stream *s);
/* Integer field f (1..20) of the directory entry whose first record is D record de: BS_ERR_PARSE
 * when it is not blank or an integer. */
bs_status bsi_iges_de_field(const iges *g, size_t de, int f, long *x);

/* The fields up to the record delimiter (optional pointers): checked, not used. */
bs_status bsi_iges_rest(const iges *g, iges_stream *s);
/* The matrix of the 124 whose directory entry starts at D record de (its type checked by the
 * caller), parsed on its first use and kept: however many entities point at it, a 124 is scanned
 * once per read. BS_ERR_PARSE (singular: at its field 1) or BS_ERR_NO_MEMORY. */
bs_status bsi_iges_124(iges *g, size_t de, const double **mat);
/* Free what reading allocated in g. */
void bsi_iges_free(iges *g);

#endif
