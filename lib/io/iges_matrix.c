/* IGES 124 transformation matrices, shared by both IGES readers: each parsed on its first use and
 * kept by directory entry, since any number of entities may point at one (and a 124 padded with
 * blanks would otherwise be scanned once per entity). */
#include "io/iges.h"

#include <math.h>
#include <stdlib.h>

/* 1 when the 3 x 3 part maps space onto a plane or less: its determinant is zero or negligible
 * against its entries (an all-zero rotation was accepted once, collapsing every point to T). */
static int singular(const double *m)
{
    double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                 m[2] * (m[4] * m[9] - m[5] * m[8]);
    double big = 0.0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            big = fabs(m[4 * r + c]) > big ? fabs(m[4 * r + c]) : big;
    return !(fabs(det) > 1e-12 * big * big * big);
}

bs_status bsi_iges_124(iges *g, size_t de, const double **mat)
{
    if (g->mat == NULL) { /* on the first 124 only: files without one pay nothing */
        g->mat = calloc(g->count[IGES_D] / 2 + 1, sizeof *g->mat);
        if (g->mat == NULL)
            return BS_ERR_NO_MEMORY;
    }
    iges_124 *e = &g->mat[de / 2];
    if (!e->read) {
        iges_stream s;
        iges_field f;
        long type;
        bs_status st = bsi_iges_open(g, de, &s);
        if (st == BS_OK)
            st = bsi_iges_int(g, &s, "the entity type of the directory entry", 124, 124, &type);
        for (size_t k = 0; k < 12 && st == BS_OK; k++)
            st = bsi_iges_real(g, &s, "a matrix entry", &e->m[k], &f);
        if (st == BS_OK)
            st = bsi_iges_rest(g, &s);
        if (st == BS_OK && singular(e->m))
            st = bsi_fail(g->err, g->first[IGES_D] + de + 1, 1, "transformation matrix (124) is singular");
        if (st != BS_OK)
            return st;
        e->read = 1;
    }
    *mat = e->m;
    return BS_OK;
}

void bsi_iges_free(iges *g)
{
    free(g->rec);
    free(g->mat);
    g->rec = NULL;
    g->mat = NULL;
}
