/* Trim classification (to be written). */
#include "model/internal.h"

int bsi_face_classify(const bs_model *m, size_t f, double u, double v, double tol)
{
    (void)m; (void)f; (void)u; (void)v; (void)tol;
    return BS_TRIM_INSIDE;
}
