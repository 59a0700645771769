/*
 * Tessellation, edge phase: the point where two faces meet, near a point of their edge
 * (tess_edge.h). Files write the trims of one edge a little apart (a tolerance of the kernel
 * that wrote them); a vertex on both surfaces errs on neither face.
 */
#include "model/tess_edge.h"

#include <math.h>

#define MEET_STEPS 16
/* The share of a step taken on the first face (as a square root of a weight): small, so that
 * the meeting point is the one next to the first face's point rather than half-way. */
#define FIRST_SHARE 0.1

static double norm3(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* Solve the 3x3 system A x = b (Cramer); 0 when A is nearly singular. */
static int solve3(double A[3][3], const double *b, double *x)
{
    double c0 = A[1][1] * A[2][2] - A[1][2] * A[2][1];
    double c1 = A[1][2] * A[2][0] - A[1][0] * A[2][2];
    double c2 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    double det = A[0][0] * c0 + A[0][1] * c1 + A[0][2] * c2;
    /* A is J J^T of unit columns (two of them shortened): its determinant is small only where
     * the faces are nearly tangent, and there the meeting point is ill-defined */
    if (!(fabs(det) > 1e-8))
        return 0;
    for (int i = 0; i < 3; i++) {
        double M[3][3];
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                M[r][k] = k == i ? b[r] : A[r][k];
        x[i] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
               det;
    }
    return 1;
}

/* Newton on S_a(uva) - S_b(uvb) = 0, four unknowns and three equations: the step of least
 * weighted length, in lengths along the surfaces (columns scaled to unit vectors), the first
 * face's moves weighing 1 / FIRST_SHARE^2, so that its point moves as little as it must. */
int bsi_tm_meet(const bs_model *m, size_t fa, double *uva, size_t fb, double *uvb, double eps, double *X)
{
    double a[2] = {uva[0], uva[1]}, b[2] = {uvb[0], uvb[1]};
    for (int it = 0; it < MEET_STEPS; it++) {
        double pa[3], pb[3], col[4][3], len[4], F[3];
        if (!bsi_face_partials(m, fa, a[0], a[1], pa, col[0], col[1]) ||
            !bsi_face_partials(m, fb, b[0], b[1], pb, col[2], col[3]))
            return 0;
        for (int k = 0; k < 3; k++) {
            F[k] = pa[k] - pb[k];
            col[2][k] = -col[2][k];
            col[3][k] = -col[3][k];
        }
        if (norm3(F) <= eps) {
            for (int k = 0; k < 3; k++)
                X[k] = 0.5 * (pa[k] + pb[k]);
            uva[0] = a[0];
            uva[1] = a[1];
            uvb[0] = b[0];
            uvb[1] = b[1];
            return 1;
        }
        for (int c = 0; c < 4; c++) {
            len[c] = norm3(col[c]);
            if (!(len[c] > 0.0))
                return 0; /* a pole: no direction to move in */
            double share = c < 2 ? FIRST_SHARE : 1.0;
            len[c] /= share;
            for (int k = 0; k < 3; k++)
                col[c][k] /= len[c];
        }
        double A[3][3], y[3];
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                A[r][k] = col[0][r] * col[0][k] + col[1][r] * col[1][k] + col[2][r] * col[2][k] +
                          col[3][r] * col[3][k];
        if (!solve3(A, F, y))
            return 0;
        /* step = -J^T y, each unknown's share divided back by its column's scale */
        double step[4];
        for (int c = 0; c < 4; c++)
            step[c] = -(col[c][0] * y[0] + col[c][1] * y[1] + col[c][2] * y[2]) / len[c];
        a[0] += step[0];
        a[1] += step[1];
        b[0] += step[2];
        b[1] += step[3];
    }
    return 0;
}
