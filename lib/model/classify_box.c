/*
 * Where a box of native parameters lies in a face: inside, outside, or crossed by its boundary
 * (the closest-point search on a model's faces prunes boxes outside a face and treats crossed
 * ones apart, lib/query/closest.c).
 *
 * A box that no trim and no chord closing a loop passes through has the same parity everywhere
 * (classify.c), so the parity of its centre is its place. A trim segment stays clear of the box
 * when the box of its control points (the convex hull property, weights positive) does; a segment
 * whose control box meets the box is cut in halves to CLEAR_DEPTH levels before the box is called
 * crossed, which is the safe answer: a crossed box is only searched more. Along a periodic
 * direction the trims are tested at every shift by a whole period that can reach the box.
 */
#include "model/classify_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CLEAR_DEPTH 40

/* 1 when the box (lo, hi) of points meets nb shifted by (du, dv). */
static int meets(const double *lo, const double *hi, const double nb[4], double du, double dv)
{
    return lo[0] <= nb[1] + du && hi[0] >= nb[0] + du && lo[1] <= nb[3] + dv && hi[1] >= nb[2] + dv;
}

/* 1 when the box of the homogeneous points h[0..count) meets nb at one of the shifts. */
static int hull_meets(const double *h, size_t count, const double nb[4], const double *su, size_t nu,
                      const double *sv, size_t nv)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < count; i++)
        for (size_t d = 0; d < 2; d++) {
            double x = h[i * 3 + d] / h[i * 3 + 2];
            lo[d] = bsi_dmin(lo[d], x);
            hi[d] = bsi_dmax(hi[d], x);
        }
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++)
            if (meets(lo, hi, nb, su[i], sv[j]))
                return 1;
    return 0;
}

#define LOCAL_PIECES BSI_CUBIC_PIECES(CLEAR_DEPTH)

/* 1 when the degree-p segment may pass through nb: halved while its pieces' boxes meet it. The
 * pieces waiting are kept on the stack whole, and each is halved where it is taken, rather than
 * cut from the segment again (two de Casteljau passes each). Without memory for the pieces the
 * answer is 1, the safe one. */
static int seg_meets(const double *seg, size_t p, const double nb[4], const double *su, size_t nu,
                     const double *sv, size_t nv)
{
    if (!hull_meets(seg, p + 1, nb, su, nu, sv, nv))
        return 0;
    /* the segment's first point is on the curve: in the box, the curve passes through it */
    if (hull_meets(seg, 1, nb, su, nu, sv, nv))
        return 1;
    size_t len = (p + 1) * 3, top = 0;
    double local[LOCAL_PIECES];
    double *pieces = len * (CLEAR_DEPTH + 2) <= LOCAL_PIECES ? local : malloc((size_t)(CLEAR_DEPTH + 2) * len * sizeof *pieces);
    if (pieces == NULL)
        return 1;
    int depth[CLEAR_DEPTH + 2], found = 0;
    /* the segment's halves: the first half on top, taken first */
    bsi_seg_halve(seg, p, pieces + len, pieces);
    depth[0] = depth[1] = 1;
    top = 2;
    while (top > 0 && !found) {
        top--;
        double *h = pieces + top * len;
        if (!hull_meets(h, p + 1, nb, su, nu, sv, nv))
            continue;
        if (depth[top] >= CLEAR_DEPTH || hull_meets(h, 1, nb, su, nu, sv, nv)) {
            found = 1;
            continue;
        }
        bsi_seg_halve(h, p, h + len, h); /* the second half stays in place, the first goes on top */
        depth[top + 1] = ++depth[top];
        top += 2;
    }
    if (pieces != local)
        free(pieces);
    return found;
}

/* The shifts by whole periods (0 when not periodic) that can bring the curve range [lo, hi] of
 * one direction onto the box side [a, b]: their count (at most 3). */
static size_t period_shifts(double period, double lo, double hi, double a, double b, double *out)
{
    out[0] = 0.0;
    if (!(period > 0.0))
        return 1;
    size_t n = 0;
    for (int k = -1; k <= 1; k++) {
        double d = k * period;
        if (lo <= b + d && hi >= a + d)
            out[n++] = d;
    }
    return n;
}

/* 1 when the chord from a to b (Cartesian points) meets nb at a shift that can bring it there. */
static int chord_meets(const bsi_face *face, const double *a, const double *b, const double nb[4])
{
    double h[6] = {a[0], a[1], 1.0, b[0], b[1], 1.0}, su[3], sv[3];
    size_t nu = period_shifts(face->period[0], bsi_dmin(a[0], b[0]), bsi_dmax(a[0], b[0]), nb[0],
                              nb[1], su);
    size_t nv = period_shifts(face->period[1], bsi_dmin(a[1], b[1]), bsi_dmax(a[1], b[1]), nb[2],
                              nb[3], sv);
    return hull_meets(h, 2, nb, su, nu, sv, nv);
}

int bsi_face_box_place(const bs_model *m, size_t f, const double nb[4])
{
    const bsi_face *face = &m->faces[f];
    for (size_t l = face->first_loop; l < face->first_loop + face->loop_count; l++) {
        const bsi_loop *loop = &m->loops[l];
        double prev[2] = {NAN, NAN}, first[2] = {NAN, NAN};
        for (size_t t = loop->first_trim; t < loop->first_trim + loop->trim_count; t++) {
            const bsi_curve *c = &m->trims[t].uv;
            size_t n = c->axis.n, p = c->degree;
            if (n == 0)
                continue;
            double su[3], sv[3], head[2], tail[2];
            const double *lo = m->trims[t].lo, *hi = m->trims[t].hi;
            size_t nu = period_shifts(face->period[0], lo[0], hi[0], nb[0], nb[1], su);
            size_t nv = period_shifts(face->period[1], lo[1], hi[1], nb[2], nb[3], sv);
            bsi_seg_point(bsi_trim_segment(c, 0), p, 0.0, m->trims[t].reversed ? tail : head);
            bsi_seg_point(bsi_trim_segment(c, n - 1), p, 1.0, m->trims[t].reversed ? head : tail);
            if (isnan(first[0]))
                first[0] = head[0], first[1] = head[1];
            else if (chord_meets(face, prev, head, nb))
                return BSI_CL_CROSS;
            prev[0] = tail[0], prev[1] = tail[1];
            for (size_t k = 0; k < n && nu > 0 && nv > 0; k++) {
                if (seg_meets(bsi_trim_segment(c, k), p, nb, su, nu, sv, nv))
                    return BSI_CL_CROSS;
                if (k + 1 < n) {
                    double a[2], b[2];
                    bsi_seg_point(bsi_trim_segment(c, k), p, 1.0, a);
                    bsi_seg_point(bsi_trim_segment(c, k + 1), p, 0.0, b);
                    if (chord_meets(face, a, b, nb))
                        return BSI_CL_CROSS;
                }
            }
        }
        if (!isnan(first[0]) && chord_meets(face, prev, first, nb)) /* the loop's closing chord */
            return BSI_CL_CROSS;
    }
    return bsi_face_parity(m, f, 0.5 * (nb[0] + nb[1]), 0.5 * (nb[2] + nb[3])) ? BSI_CL_IN
                                                                                : BSI_CL_OUT;
}
