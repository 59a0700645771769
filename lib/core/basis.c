/* Bernstein basis values and derivatives by the stable triangular recurrence. */
#include "core/kernels.h"

/* One step of the recurrence: b[0..r-1] (degree r-1) becomes b[0..r] (degree r). */
static void raise_step(double *b, size_t r, double t, double s)
{
    double saved = 0.0;
    for (size_t k = 0; k < r; k++) {
        double tmp = b[k];
        b[k] = saved + s * tmp;
        saved = t * tmp;
    }
    b[r] = saved;
}

void bsi_bernstein(size_t deg, double t, double *b)
{
    double s = 1.0 - t;
    b[0] = 1.0;
    for (size_t r = 1; r <= deg; r++)
        raise_step(b, r, t, s);
}

void bsi_bernstein_first(size_t deg, double t, double *b, double *bm)
{
    if (deg == 0) {
        b[0] = 1.0;
        return;
    }
    if (deg == 3) {
        bsi_bernstein3_first(t, b, bm);
        return;
    }
    bsi_bernstein(deg - 1, t, bm);
    for (size_t k = 0; k < deg; k++)
        b[k] = bm[k];
    raise_step(b, deg, t, 1.0 - t);
}

void bsi_bernstein_deriv(size_t deg, unsigned k, double t, double *b)
{
    if (k > deg) {
        for (size_t i = 0; i <= deg; i++)
            b[i] = 0.0;
        return;
    }
    bsi_bernstein(deg - k, t, b);
    /* d/dt B(r,i) = r (B(r-1,i-1) - B(r-1,i)): difference downwards so b[i-1] is still old. */
    for (size_t r = deg - k + 1; r <= deg; r++) {
        double scale = (double)r;
        b[r] = scale * b[r - 1];
        for (size_t i = r - 1; i > 0; i--)
            b[i] = scale * (b[i - 1] - b[i]);
        b[0] = scale * (0.0 - b[0]);
    }
}
