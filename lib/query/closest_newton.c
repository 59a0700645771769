/*
 * Closest points, the local step: f = |S - q|^2 and a projected Newton iteration on it over the
 * domain [0,1]^2. Newton only finds good candidates (upper bounds); the branch and bound of
 * closest.c certifies them, so this may stop anywhere without harm to the guarantee.
 *
 * The squared distance is smooth also where q lies on the surface (the distance is not), so the
 * iteration works on f. Its gradient is 2 J^T r and its Hessian 2 (J^T J + sum_c r_c S_c''),
 * r = S - q, J = (S_u S_v). On an edge or a corner of the domain whose gradient points outwards
 * that coordinate is held and Newton runs on the edge curve (the 1-D problem) or stops at the
 * corner; where the Hessian is not positive definite (a saddle, or a pole where S_u = 0) the
 * Gauss-Newton matrix 2 J^T J takes its place, and where that is singular too the gradient.
 */
#include "query/closest.h"

#include <math.h>

/* f at (u,v) in scaled units; with g, also its gradient g[2], Hessian h[3] (uu, uv, vv) and
 * Gauss-Newton matrix gn[3]. */
static double eval(bsi_cl *w, double u, double v, double *g, double *h, double *gn)
{
    size_t dim = w->dim;
    unsigned k = g != NULL ? 2u : 0u;
    if (BSI_CL_BICUBIC3(w))
        bsi_cl_deriv3(w->p->hom, u, v, k, w->table);
    else if (BSI_CL_BICUBIC4(w))
        bsi_cl_deriv4(w->p->hom, u, v, k, w->table);
    else
        bsi_deriv_table(w->p, u, v, k, k, w->dscratch, w->table);
    const double *t = w->table;
    double s1 = w->s1, s2 = w->s2, f = 0.0; /* applied one after the other (see closest.h) */
    if (g != NULL)
        for (int i = 0; i < 3; i++)
            h[i] = gn[i] = g[i % 2] = 0.0;
    for (size_t c = 0; c < dim; c++) {
        double r = (t[c] * w->s1 - w->qs[c]) * w->s2;
        f += r * r;
        if (g == NULL)
            continue;
        /* table index (a*3 + b)*dim + c holds S^(a,b) */
        double su = t[3 * dim + c] * s1 * s2, sv = t[dim + c] * s1 * s2;
        double suu = t[6 * dim + c] * s1 * s2, suv = t[4 * dim + c] * s1 * s2, svv = t[2 * dim + c] * s1 * s2;
        g[0] += 2.0 * r * su;
        g[1] += 2.0 * r * sv;
        gn[0] += 2.0 * su * su;
        gn[1] += 2.0 * su * sv;
        gn[2] += 2.0 * sv * sv;
        h[0] += 2.0 * r * suu;
        h[1] += 2.0 * r * suv;
        h[2] += 2.0 * r * svv;
    }
    if (g != NULL)
        for (int i = 0; i < 3; i++)
            h[i] += gn[i];
    return f;
}

double bsi_cl_f(bsi_cl *w, double u, double v) { return eval(w, u, v, NULL, NULL, NULL); }

double bsi_cl_grad(bsi_cl *w, const double x[2], double g[2], double h[3])
{
    double gn[3];
    return eval(w, x[0], x[1], g, h, gn);
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

/* The step d on the free coordinates (fu, fv): Newton, else Gauss-Newton, else the gradient. */
static void step(const double *g, const double *h, const double *gn, int fu, int fv, double *d)
{
    d[0] = d[1] = 0.0;
    if (fu && fv) {
        const double *a[2] = {h, gn};
        for (int k = 0; k < 2; k++) {
            double det = a[k][0] * a[k][2] - a[k][1] * a[k][1];
            if (a[k][0] > 0.0 && a[k][2] > 0.0 && det > 1e-14 * a[k][0] * a[k][2]) {
                d[0] = -(a[k][2] * g[0] - a[k][1] * g[1]) / det;
                d[1] = -(a[k][0] * g[1] - a[k][1] * g[0]) / det;
                return;
            }
        }
        double s = fmax(fabs(h[0]) + fabs(h[2]), gn[0] + gn[2]);
        if (s > 0.0) {
            d[0] = -g[0] / s;
            d[1] = -g[1] / s;
        }
        return;
    }
    size_t i = fu ? 0 : 1;
    if (!fu && !fv)
        return;
    double c = h[2 * i] > 0.0 ? h[2 * i] : gn[2 * i];
    if (c > 0.0)
        d[i] = -g[i] / c;
    else if (fabs(h[2 * i]) > 0.0)
        d[i] = -g[i] / fabs(h[2 * i]);
}

double bsi_cl_newton(bsi_cl *w, double x[2])
{
    double g[2], h[3], gn[3], d[2];
    double f = eval(w, x[0], x[1], g, h, gn);
    for (int it = 0; it < 40 && f > 0.0; it++) {
        /* a coordinate at a bound whose gradient points out is held; so is one the patch does
         * not depend on (degree 0) */
        int fu = w->m > 0 && !((x[0] <= 0.0 && g[0] > 0.0) || (x[0] >= 1.0 && g[0] < 0.0));
        int fv = w->n > 0 && !((x[1] <= 0.0 && g[1] > 0.0) || (x[1] >= 1.0 && g[1] < 0.0));
        step(g, h, gn, fu, fv, d);
        if (d[0] == 0.0 && d[1] == 0.0)
            break;
        double y[2] = {x[0], x[1]};
        int moved = 0;
        for (int ls = 0; ls < 40 && !moved; ls++) { /* steps 1, 1/2, 1/4, ... */
            double t = ldexp(1.0, -ls);
            y[0] = clamp01(x[0] + t * d[0]);
            y[1] = clamp01(x[1] + t * d[1]);
            if (y[0] == x[0] && y[1] == x[1])
                break;
            moved = bsi_cl_f(w, y[0], y[1]) < f;
        }
        if (!moved)
            break;
        double dx = fabs(y[0] - x[0]) + fabs(y[1] - x[1]);
        x[0] = y[0];
        x[1] = y[1];
        f = eval(w, x[0], x[1], g, h, gn);
        if (dx < 1e-15)
            break;
    }
    return f;
}
