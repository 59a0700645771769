/*
 * What the exact surfaces' two files share (analytic.c, analytic_sweep.c): the standard
 * quadratic arc, the frame's check, and a grid of patches made one by one and appended at once.
 */
#include "model/analytic.h"

#include <math.h>
#include <stdlib.h>

void bsi_arc_points(double a0, double a1, double *cx, double *cy, double *w)
{
    double half = 0.5 * (a1 - a0), mid = 0.5 * (a0 + a1), c = cos(half);
    cx[0] = cos(a0), cy[0] = sin(a0), w[0] = 1.0;
    cx[1] = cos(mid) / c, cy[1] = sin(mid) / c, w[1] = c;
    cx[2] = cos(a1), cy[2] = sin(a1), w[2] = 1.0;
}

int bsi_frame_valid(const bsi_frame *f)
{
    const double *axes[3] = {f->x, f->y, f->z};
    for (int a = 0; a < 3; a++) {
        for (int b = a; b < 3; b++) {
            double d = bsi_dot3(axes[a], axes[b]), want = a == b ? 1.0 : 0.0;
            if (!(fabs(d - want) <= 1e-9))
                return 0;
        }
    }
    double cross[3];
    bsi_cross3(f->x, f->y, cross);
    return bsi_dot3(cross, f->z) > 0.0 && bsi_all_finite(f->o, 3);
}

bs_status bsi_patch_grid(bs_surface *s, const bsi_axis *au, const bsi_axis *av, void *ctx,
                         bsi_grid_patch_fn make)
{
    size_t count = au->n * av->n;
    // NOLINTNEXTLINE(bugprone-sizeof-expression): an array of pointers
    bs_patch **made = calloc(count ? count : 1, sizeof *made);
    if (made == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status st = BS_OK;
    for (size_t i = 0; i < au->n && st == BS_OK; i++)
        for (size_t j = 0; j < av->n && st == BS_OK; j++)
            st = make(ctx, i, j, &made[i * av->n + j]);
    if (st == BS_OK)
        st = bsi_surface_adopt(s, made, count);
    if (st != BS_OK)
        for (size_t k = 0; k < count; k++)
            bs_patch_destroy(made[k]);
    free(made);
    return st;
}
