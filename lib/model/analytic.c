/* Exact surfaces as rational Bezier patches (to be written). */
#include "model/internal.h"

#include <string.h>

bs_status bsi_surface_def_patches(const bsi_surface_def *def, const double *box, bs_surface *s,
                                  bsi_axis *au, bsi_axis *av)
{
    (void)def; (void)box; (void)s;
    memset(au, 0, sizeof *au);
    memset(av, 0, sizeof *av);
    return BS_ERR_UNSUPPORTED;
}

void bsi_surface_def_eval(const bsi_surface_def *def, double u, double v, double *p)
{
    (void)def; (void)u; (void)v;
    p[0] = p[1] = p[2] = 0.0;
}

void bsi_surface_def_periods(const bsi_surface_def *def, double *pu, double *pv)
{
    (void)def;
    *pu = *pv = 0.0;
}
