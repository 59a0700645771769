/* Validation of caller views: the only place that decides whether a view may be read or written. */
#include "core/internal.h"

#include <math.h>

/* elem: the size of one element (double or float), also the stride that 0 stands for. */
static bs_status check_extent(const void *data, ptrdiff_t stride, size_t count, size_t n, size_t elem)
{
    if (data == NULL)
        return BS_ERR_INVALID_ARG;
    if ((uintptr_t)data % elem != 0 || stride % (ptrdiff_t)elem != 0)
        return BS_ERR_INVALID_ARG;
    if (count < n)
        return BS_ERR_SIZE;
    if (n == 0)
        return BS_OK;
    /* The bytes from the lowest to the end of the highest of the n elements must form an object:
     * (n-1) * |stride| + elem fits in ptrdiff_t, so that element addresses can be formed and
     * subtracted, ... */
    ptrdiff_t s = stride ? stride : (ptrdiff_t)elem;
    size_t mag = s < 0 ? (size_t)0 - (size_t)s : (size_t)s;
    size_t room = (size_t)PTRDIFF_MAX - elem;
    if (n > 1 && (n - 1) > room / mag)
        return BS_ERR_SIZE;
    /* ... and the first and the last element lie inside the address space: computing their
     * addresses must not wrap around. */
    size_t span = (n - 1) * mag;
    uintptr_t at = (uintptr_t)data;
    if (s < 0 ? at < span : at > UINTPTR_MAX - elem + 1 - span)
        return BS_ERR_SIZE;
    return BS_OK;
}

bs_status bsi_check_views(const bs_view *views, size_t k, size_t n)
{
    bs_status st = k > 0 && views == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    for (size_t c = 0; c < k && st == BS_OK; c++)
        st = check_extent(views[c].data, views[c].stride, views[c].count, n, sizeof(double));
    return st;
}

bs_status bsi_check_fviews(const bs_fview *views, size_t k, size_t n)
{
    bs_status st = k > 0 && views == NULL ? BS_ERR_INVALID_ARG : BS_OK;
    for (size_t c = 0; c < k && st == BS_OK; c++)
        st = check_extent(views[c].data, views[c].stride, views[c].count, n, sizeof(float));
    return st;
}

bs_status bsi_check_cview(const bs_cview *view, size_t n)
{
    if (view == NULL)
        return BS_ERR_INVALID_ARG;
    return check_extent(view->data, view->stride, view->count, n, sizeof(double));
}

int bsi_all_finite(const double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return 0;
    return 1;
}
