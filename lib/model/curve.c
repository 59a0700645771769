/* Piecewise rational Bezier curves (to be written). */
#include "model/internal.h"

#include <stdlib.h>
#include <string.h>

void bsi_curve_free(bsi_curve *c)
{
    bsi_axis_free(&c->axis);
    free(c->hom);
    c->hom = NULL;
}

bs_status bsi_curve_copy(const bsi_curve *src, bsi_curve *dst) { (void)src; memset(dst, 0, sizeof *dst); return BS_ERR_UNSUPPORTED; }
bs_status bsi_curve_line(size_t dim, const double *p, const double *d, double t0, double t1, bsi_curve *out)
{ (void)dim; (void)p; (void)d; (void)t0; (void)t1; memset(out, 0, sizeof *out); return BS_ERR_UNSUPPORTED; }
bs_status bsi_curve_conic(size_t dim, const double *c, const double *x, const double *y, double rx,
                          double ry, double radians, double t0, double t1, bsi_curve *out)
{ (void)dim; (void)c; (void)x; (void)y; (void)rx; (void)ry; (void)radians; (void)t0; (void)t1; memset(out, 0, sizeof *out); return BS_ERR_UNSUPPORTED; }
bs_status bsi_curve_bspline(size_t dim, size_t degree, size_t count, const double *knots,
                            const double *ctrl, const double *weights, double t0, double t1,
                            bsi_curve *out)
{ (void)dim; (void)degree; (void)count; (void)knots; (void)ctrl; (void)weights; (void)t0; (void)t1; memset(out, 0, sizeof *out); return BS_ERR_UNSUPPORTED; }
void bsi_curve_transform(bsi_curve *c, const double *affine) { (void)c; (void)affine; }
int bsi_curve_eval(const bsi_curve *c, double t, double *p) { (void)c; (void)t; (void)p; return 0; }
void bsi_curve_point(const bsi_curve *c, size_t k, double s, double *p) { (void)c; (void)k; (void)s; (void)p; }
void bsi_curve_bounds(const bsi_curve *c, double *lo, double *hi)
{
    for (size_t i = 0; i < c->dim; i++)
        lo[i] = hi[i] = 0.0;
}
