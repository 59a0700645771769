/* Parameter-space curves projected from 3-D edges (to be written). */
#include "model/internal.h"

#include <string.h>

bs_status bsi_pcurve_project(const bs_model *m, size_t f, const bsi_curve *edge, double tol,
                             bsi_trim *out)
{
    (void)m; (void)f; (void)edge; (void)tol;
    memset(out, 0, sizeof *out);
    return BS_ERR_UNSUPPORTED;
}
