/* Iso-curves: the curve's net equals the exact de Casteljau points of the net's fibres, the curve
 * evaluates to the surface along u = t or v = t, and t = 0, 1 copy the boundary exactly. */
#include "ops_check.h"

static double worst_net, worst_extra, worst_eval;

static void check_iso(const tnet *net, const bs_patch *p, int dir, double t, double growth, unsigned long long *rng)
{
    size_t dim = net->dim, count = (dir == BS_DIR_U ? net->n : net->m) + 1;
    double *ctrl = malloc(count * dim * sizeof(double)), *w = malloc(count * sizeof(double));
    bs_status st = bs_patch_isocurve(p, dir, t, ctrl, count * dim, w, count);
    CHECKF(st == BS_OK, "status %d", st);
    if (st == BS_OK) {
        /* exact points: blossom of each fibre at (t, ..., t), homogeneous */
        lnet l = lnet_of(net);
        size_t deg = dir == BS_DIR_U ? net->m : net->n;
        double amp = pow(growth, (double)(net->m + net->n));
        double bound = ops_bound(net->m, net->n, net) * amp;
        double wb = 4.0 * (double)(net->m + net->n + 1) * OPS_EPS * tnet_wmax(net) * amp;
        long double b[BS_MAX_DEGREE + 1], h[BS_MAX_DIM + 1];
        double *worst = growth > 1.0 ? &worst_extra : &worst_net;
        for (size_t k = 0; k < count; k++) {
            for (size_t c = 0; c <= dim; c++) {
                for (size_t i = 0; i <= deg; i++)
                    b[i] = dir == BS_DIR_U ? *lnet_at(&l, c, i, k) : *lnet_at(&l, c, k, i);
                h[c] = ld_blossom(b, deg, 0, t, t);
            }
            double e = (double)fabsl((long double)w[k] - h[dim]) / wb;
            CHECKF(e <= 1.0, "weight error %g of bound", e);
            *worst = e > *worst ? e : *worst;
            if (net->w == NULL)
                CHECK(w[k] == 1.0);
            for (size_t c = 0; c < dim; c++) {
                e = (double)fabsl((long double)ctrl[k * dim + c] - h[c] / h[dim]) / bound;
                CHECKF(e <= 1.0, "point error %g of bound, (%zu,%zu) dir %d t %g", e, net->m, net->n, dir, t);
                *worst = e > *worst ? e : *worst;
            }
        }
        /* the curve evaluates to the surface */
        ref_net curve = {dir == BS_DIR_U ? 0 : net->m, dir == BS_DIR_U ? net->n : 0, dim, ctrl, net->w ? w : NULL};
        ref_net surf = tnet_ref(net);
        long double x[BS_MAX_DIM], y[BS_MAX_DIM];
        for (int k = 0; k < 4; k++) {
            long double s = (long double)bs_test_rand(rng, 0, 1);
            ref_eval(&curve, dir == BS_DIR_U ? 0.0L : s, dir == BS_DIR_U ? s : 0.0L, x);
            ref_eval(&surf, dir == BS_DIR_U ? (long double)t : s, dir == BS_DIR_U ? s : (long double)t, y);
            for (size_t c = 0; c < dim; c++) {
                double e = (double)fabsl(x[c] - y[c]) / bound;
                CHECKF(e <= 1.0, "evaluation error %g of bound", e);
                worst_eval = e > worst_eval ? e : worst_eval;
            }
        }
        free(l.h);
    }
    free(ctrl);
    free(w);
}

/* t = 0 and t = 1 give the boundary rows/columns bit for bit (weights included). */
static void check_boundaries(const tnet *net, const bs_patch *p)
{
    for (int dir = BS_DIR_U; dir <= BS_DIR_V; dir++)
        for (int end = 0; end <= 1; end++) {
            size_t dim = net->dim, count = (dir == BS_DIR_U ? net->n : net->m) + 1;
            double ctrl[(BS_MAX_DEGREE + 1) * BS_MAX_DIM], w[BS_MAX_DEGREE + 1];
            CHECK_STATUS(bs_patch_isocurve(p, dir, end, ctrl, count * dim, w, count), BS_OK);
            size_t fixed = end ? (dir == BS_DIR_U ? net->m : net->n) : 0;
            int same = 1;
            for (size_t k = 0; k < count; k++) {
                size_t idx = dir == BS_DIR_U ? fixed * (net->n + 1) + k : k * (net->n + 1) + fixed;
                same &= memcmp(ctrl + k * dim, net->ctrl + idx * dim, dim * sizeof(double)) == 0;
                same &= w[k] == (net->w ? net->w[idx] : 1.0);
            }
            CHECKF(same, "boundary dir %d end %d not copied exactly", dir, end);
        }
}

static void test_random(void)
{
    unsigned long long rng = 51;
    for (size_t d = 0; d < OPS_NDEGREES; d++)
        for (int rational = 0; rational <= 1; rational++) {
            size_t m = ops_degrees[d][0], n = ops_degrees[d][1], dim = 1 + (d + 3 * (size_t)rational) % 8;
            tnet net = tnet_random(&rng, m, n, dim, rational, 0.25, 4.0);
            bs_patch *p = tnet_patch(&net);
            for (int dir = BS_DIR_U; dir <= BS_DIR_V; dir++) {
                check_iso(&net, p, dir, bs_test_rand(&rng, 0, 1), 1.0, &rng);
                check_iso(&net, p, dir, 0.5, 1.0, &rng);
                if (!rational && m + n <= 20)
                    check_iso(&net, p, dir, -0.3, 1.6, &rng); /* extrapolated */
            }
            check_boundaries(&net, p);
            /* weights not wanted is allowed, for rational patches too */
            double ctrl[(BS_MAX_DEGREE + 1) * BS_MAX_DIM];
            CHECK_STATUS(bs_patch_isocurve(p, BS_DIR_V, 0.25, ctrl, (m + 1) * dim, NULL, 0), BS_OK);
            bs_patch_destroy(p);
            tnet_free(&net);
        }
}

int main(void)
{
    test_random();
    print_worst("iso-curve points vs exact (t in [0,1])", worst_net);
    print_worst("iso-curve points vs exact (extrapolated)", worst_extra);
    print_worst("iso-curve evaluation vs surface", worst_eval);
    return bs_test_exit("test_isocurve");
}
