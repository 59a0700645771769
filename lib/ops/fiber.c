/* Fibre-by-fibre application of curve operations to coordinate-major nets: the one place that
 * knows how rows and columns of a tensor-product net are laid out. */
#include "ops/internal.h"

/* Element stride of a fibre along dir, and the offset of fibre f, in a plane of degree (du, dv). */
static size_t fiber_step(int dir, size_t dv) { return dir == BS_DIR_U ? dv + 1 : 1; }
static size_t fiber_start(int dir, size_t dv, size_t f) { return dir == BS_DIR_U ? f : f * (dv + 1); }

void bsi_net_map(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                 size_t deg_out, bsi_fiber_op op, const void *ctx, double *out)
{
    size_t deg_in = dir == BS_DIR_U ? deg_u : deg_v;
    size_t nfib = (dir == BS_DIR_U ? deg_v : deg_u) + 1;
    size_t out_u = dir == BS_DIR_U ? deg_out : deg_u, out_v = dir == BS_DIR_U ? deg_v : deg_out;
    size_t in_plane = (deg_u + 1) * (deg_v + 1), out_plane = (out_u + 1) * (out_v + 1);
    size_t in_step = fiber_step(dir, deg_v), out_step = fiber_step(dir, out_v);
    double a[BSI_FIBER_MAX], b[BSI_FIBER_MAX];
    for (size_t c = 0; c < ncoord; c++)
        for (size_t f = 0; f < nfib; f++) {
            const double *src = in + c * in_plane + fiber_start(dir, deg_v, f);
            double *dst = out + c * out_plane + fiber_start(dir, out_v, f);
            for (size_t k = 0; k <= deg_in; k++)
                a[k] = src[k * in_step];
            op(a, deg_in, b, deg_out, ctx);
            for (size_t k = 0; k <= deg_out; k++)
                dst[k * out_step] = b[k];
        }
}

void bsi_net_slice(const double *in, size_t ncoord, size_t deg_u, size_t deg_v, int dir,
                   size_t first, size_t deg_out, double *out)
{
    size_t nfib = (dir == BS_DIR_U ? deg_v : deg_u) + 1;
    size_t out_u = dir == BS_DIR_U ? deg_out : deg_u, out_v = dir == BS_DIR_U ? deg_v : deg_out;
    size_t in_plane = (deg_u + 1) * (deg_v + 1), out_plane = (out_u + 1) * (out_v + 1);
    size_t in_step = fiber_step(dir, deg_v), out_step = fiber_step(dir, out_v);
    for (size_t c = 0; c < ncoord; c++)
        for (size_t f = 0; f < nfib; f++) {
            const double *src = in + c * in_plane + fiber_start(dir, deg_v, f) + first * in_step;
            double *dst = out + c * out_plane + fiber_start(dir, out_v, f);
            for (size_t k = 0; k <= deg_out; k++)
                dst[k * out_step] = src[k * in_step];
        }
}
