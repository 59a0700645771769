/*
 * Where native (u, v) lies with respect to a face's trim loops: BS_TRIM_INSIDE, OUTSIDE or ON.
 *
 * Candidates. NaN, or a point that no whole-period shift brings into the face's box, is OUTSIDE.
 * Along a periodic direction every shift u + k period inside the box is a candidate (a loop on a
 * cylinder may lie anywhere, e.g. over [-0.5, 5.5]); the point is INSIDE when one candidate is.
 * A face without loops is INSIDE its whole box.
 *
 * ON (3-D distance <= tol). P = S(u, v) on the surface; for each trim segment c(s), s in [0, 1],
 * a branch and bound over s: at the middle sm of a piece [s0, s1], D = |P - S(c(sm))| is a
 * distance to the boundary (ON when D <= tol), and every point of the piece is at least D - K / 2
 * from P, K = Lu |c_u'| + Lv |c_v'| a bound of the speed of S(c) over the piece's own [0, 1]: Lu,
 * Lv bound the surface's speed per native unit over the face's patches (the rational derivative
 * bound under "speed bounds" below, times the native -> local rate of the axis piece: 1 / width,
 * or radians / (2 sin a) on a quadratic arc of half angle a), the piece's speeds bound the same
 * way from its control points. A piece is dropped when D - K / 2 > tol: only the parts of the
 * boundary that can come within tol in 3-D are refined, wherever they lie in parameter space (a
 * pole: a degenerate trim along v = pi / 2 maps to one 3-D point; a seam: far in u, near in 3-D).
 * On a flat face (one polynomial parallelogram over linear axes, a plane's face) S is affine in
 * (u, v), so the piece's image seen from P is its control points mapped into 3-D, and the box of
 * those points bounds it from below instead (no surface point is evaluated).
 * Refinement stops when K / 2 is a thousandth of tol (the piece is then farther than 0.999 tol:
 * a point that near is left to the parity below, which is exact) or after a fixed number of
 * evaluations per segment. Seam trims (a constant u, or v, of a periodic
 * direction whose twin lies one period away, or an edge used twice by this face) are not a
 * boundary of the face and are left out of this test only.
 *
 * INSIDE / OUTSIDE. Even-odd parity of the crossings of the ray {(x, v): x > u} with every trim
 * of every loop (the outer loop and the holes, in whatever orientation the file gives them):
 * each rational Bezier segment is cut in halves (de Casteljau on homogeneous points) until the
 * control points' box of a piece lies above the ray's line (y >= v), below it (y < v), left of
 * the point (x < u): no crossing, or right of it (x > u): a crossing exactly when its two ends lie
 * on different sides of the line. The ends' points are computed once per parameter and shared by
 * the two pieces meeting there, and chords close the gaps between segments and between trims (a
 * file's loop closes only within its tolerance), so the chain is closed and each of its crossings
 * counted once. This is exact for points off the curve (a piece clear of the point is always
 * reached); a point on the curve stops at a depth of 50 halvings, decided there by the chord.
 */
#include "model/classify_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PARITY_DEPTH 50
#define PARITY_LOCAL_PIECES BSI_CUBIC_PIECES(PARITY_DEPTH)
#define MAX_SHIFTS 4 /* candidates per periodic direction */

/* 1 when the chord a -> b crosses the ray (the same half-open rule as the pieces). */
static int chord_crosses(const double *a, const double *b, double u, double v)
{
    if ((a[1] >= v) == (b[1] >= v))
        return 0;
    return a[0] + (b[0] - a[0]) * (v - a[1]) / (b[1] - a[1]) > u;
}

/* ---- parity of the crossings with the ray from (u, v) towards +u ---- */
typedef struct span {
    double s0, s1;
    double a[2], b[2]; /* the points at s0 and s1 */
    int depth;
} span;

/* Crossings of the ray with the degree-p segment, mod 2. The pieces waiting are kept whole beside
 * the stack and halved where taken (one pass of midpoints gives both halves and their shared
 * end); above cubic their block is allocated at the first halving, and without it each piece is
 * cut from the segment and its end evaluated there (two passes and one), the same answer for
 * points off the curve. */
static int seg_parity(const double *seg, size_t p, double u, double v)
{
    span stack[PARITY_DEPTH + 2];
    size_t top = 0, len = (p + 1) * 3;
    double local[PARITY_LOCAL_PIECES], cut[BSI_SEG_MAX];
    int small = len * (PARITY_DEPTH + 2) <= PARITY_LOCAL_PIECES, asked = small, parity = 0;
    double *pieces = small ? local : NULL;
    if (small)
        memcpy(local, seg, len * sizeof *local);
    stack[top].s0 = 0.0;
    stack[top].s1 = 1.0;
    bsi_seg_point(seg, p, 0.0, stack[top].a);
    bsi_seg_point(seg, p, 1.0, stack[top].b);
    stack[top++].depth = 0;
    while (top > 0) {
        span sp = stack[--top];
        const double *pts = pieces != NULL ? pieces + top * len : cut;
        if (pieces == NULL)
            bsi_seg_piece(seg, p, sp.s0, sp.s1, cut);
        /* the box of the control points and of the ends as computed: a piece judged above or
         * below the line has its ends on that side for its neighbours too */
        double xlo = bsi_dmin(sp.a[0], sp.b[0]), xhi = bsi_dmax(sp.a[0], sp.b[0]);
        double ylo = bsi_dmin(sp.a[1], sp.b[1]), yhi = bsi_dmax(sp.a[1], sp.b[1]);
        for (size_t i = 0; i <= p; i++) {
            double x = pts[i * 3] / pts[i * 3 + 2], y = pts[i * 3 + 1] / pts[i * 3 + 2];
            xlo = bsi_dmin(xlo, x), xhi = bsi_dmax(xhi, x), ylo = bsi_dmin(ylo, y), yhi = bsi_dmax(yhi, y);
        }
        if (yhi < v || ylo >= v || xhi < u)
            continue;
        int cross = (sp.a[1] >= v) != (sp.b[1] >= v);
        if (xlo > u) {
            parity ^= cross;
            continue;
        }
        if (sp.depth >= PARITY_DEPTH) { /* on the curve to rounding: the chord decides */
            parity ^= chord_crosses(sp.a, sp.b, u, v);
            continue;
        }
        if (!asked) { /* the first halving, of the whole segment (top is 0) */
            asked = 1;
            if ((pieces = malloc((size_t)(PARITY_DEPTH + 2) * len * sizeof *pieces)) != NULL)
                memcpy(pieces, seg, len * sizeof *pieces);
        }
        double sm = 0.5 * (sp.s0 + sp.s1), mid[2];
        if (pieces != NULL) { /* the second half stays in place, the first goes on top */
            double *h = pieces + top * len;
            bsi_seg_halve(h, p, h + len, h);
            mid[0] = h[0] / h[2], mid[1] = h[1] / h[2]; /* both halves' end there */
        } else {
            bsi_seg_point(seg, p, sm, mid);
        }
        span left = sp, right = sp;
        left.s1 = right.s0 = sm;
        memcpy(left.b, mid, sizeof mid);
        memcpy(right.a, mid, sizeof mid);
        left.depth = right.depth = sp.depth + 1;
        stack[top++] = right;
        stack[top++] = left;
    }
    if (pieces != local)
        free(pieces);
    return parity;
}

/* Even-odd parity over every trim of every loop of the face: 1 inside. Each loop is closed by
 * chords between the end of one segment and the start of the next (zero or within the file's
 * tolerance), so that every crossing of the closed chain is counted once whatever the gaps. */
static int loops_parity(const bs_model *m, const bsi_face *face, double u, double v)
{
    int parity = 0;
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[l];
        double first[2] = {0.0, 0.0}, prev[2] = {0.0, 0.0};
        int started = 0;
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++) {
            const bsi_curve *c = &m->trims[t].uv;
            size_t n = c->axis.n, p = c->degree;
            if (n == 0)
                continue;
            double head[2], tail[2];
            const double *lo = m->trims[t].lo, *hi = m->trims[t].hi;
            bsi_seg_point(bsi_trim_segment(c, 0), p, 0.0, m->trims[t].reversed ? tail : head);
            bsi_seg_point(bsi_trim_segment(c, n - 1), p, 1.0, m->trims[t].reversed ? head : tail);
            if (started)
                parity ^= chord_crosses(prev, head, u, v);
            else
                memcpy(first, head, sizeof head), started = 1;
            memcpy(prev, tail, sizeof tail);
            if (hi[1] < v || lo[1] >= v || hi[0] < u)
                continue;
            for (size_t k = 0; k < n; k++) {
                parity ^= seg_parity(bsi_trim_segment(c, k), p, u, v);
                if (k + 1 < n) {
                    double a[2], b[2];
                    bsi_seg_point(bsi_trim_segment(c, k), p, 1.0, a);
                    bsi_seg_point(bsi_trim_segment(c, k + 1), p, 0.0, b);
                    parity ^= chord_crosses(a, b, u, v);
                }
            }
        }
        if (started)
            parity ^= chord_crosses(prev, first, u, v);
    }
    return parity;
}

/* ---- the candidates ---- */
/* Values of x shifted by whole periods into [lo, hi] (x itself when not periodic): their count. */
static size_t shifts(double x, double lo, double hi, double period, double *out)
{
    if (!(period > 0.0)) {
        out[0] = x;
        return x >= lo && x <= hi;
    }
    size_t n = 0;
    double y = bsi_wrap(x, lo, period);
    while (y <= hi && n < MAX_SHIFTS) {
        out[n++] = y;
        y += period;
    }
    return n;
}

/* (u, v) of face f brought into its box by whole periods, every way it lands there (us, vs and
 * their counts; 0 when outside the box or NaN). */
static int placed(const bsi_face *face, double u, double v, double *us, size_t *nu, double *vs, size_t *nv)
{
    if (isnan(u) || isnan(v))
        return 0;
    *nu = shifts(u, face->box[0], face->box[1], face->period[0], us);
    *nv = shifts(v, face->box[2], face->box[3], face->period[1], vs);
    return *nu > 0 && *nv > 0;
}

/* 1 when the loops' parity puts some placement of the point inside */
static int parity_inside(const bs_model *m, const bsi_face *face, const double *us, size_t nu,
                         const double *vs, size_t nv)
{
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++)
            if (loops_parity(m, face, us[i], vs[j]))
                return 1;
    return 0;
}

int bsi_face_classify(const bs_model *m, size_t f, double u, double v, double tol)
{
    const bsi_face *face = &m->faces[f];
    double us[MAX_SHIFTS], vs[MAX_SHIFTS];
    size_t nu = 0, nv = 0;
    if (!placed(face, u, v, us, &nu, vs, &nv))
        return BS_TRIM_OUTSIDE;
    if (face->loop_count == 0)
        return BS_TRIM_INSIDE;
    if (bsi_face_near_boundary(m, f, us[0], vs[0], tol, 0))
        return BS_TRIM_ON;
    return parity_inside(m, face, us, nu, vs, nv) ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE;
}

int bsi_face_covers(const bs_model *m, size_t f, double u, double v, double tol)
{
    const bsi_face *face = &m->faces[f];
    double us[MAX_SHIFTS], vs[MAX_SHIFTS];
    size_t nu = 0, nv = 0;
    if (!placed(face, u, v, us, &nu, vs, &nv))
        return 0;
    return face->loop_count == 0 || parity_inside(m, face, us, nu, vs, nv) ||
           bsi_face_near_boundary(m, f, us[0], vs[0], tol, 1);
}

int bsi_face_parity(const bs_model *m, size_t f, double u, double v)
{
    const bsi_face *face = &m->faces[f];
    double us[MAX_SHIFTS], vs[MAX_SHIFTS];
    size_t nu = 0, nv = 0;
    if (!placed(face, u, v, us, &nu, vs, &nv))
        return 0;
    return face->loop_count == 0 || parity_inside(m, face, us, nu, vs, nv);
}
