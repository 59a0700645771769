/* Sewing trims into edges (to be written). */
#include "model/internal.h"

bs_status bsi_model_sew(bs_model *m, double tol)
{
    (void)m; (void)tol;
    return BS_OK;
}
