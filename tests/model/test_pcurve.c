/* Computed trims (lib/model/pcurve*.c): 3-D edges projected onto faces, the trim evaluated on the
 * surface (closed forms written here, or the face's patch) against the edge (its closed form or
 * exact control points written here) at 2001 parameters per edge: circles on planes, cylinders,
 * spheres, cones and tori, lines on planes and cones, meridians to a pole, curves on Bezier faces;
 * the unwrapping and placement of periodic parameters, loops closed across a seam; refusals. */
#include "harness.h"

#include "model/pcurve_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.141592653589793

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static size_t fail_in;
void *__wrap_malloc(size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_malloc(n);
}
void *__wrap_realloc(void *p, size_t n)
{
    if (fail_in != 0 && --fail_in == 0)
        return NULL;
    return __real_realloc(p, n);
}
#endif

/* ---- curves written here (independent of curve.c) ---- */
static bsi_curve alloc_curve(size_t dim, size_t degree, bsi_axis axis)
{
    bsi_curve c;
    c.dim = dim;
    c.degree = degree;
    c.axis = axis;
    c.hom = calloc(axis.n * (degree + 1) * (dim + 1), sizeof(double));
    return c;
}

static void set_hom(bsi_curve *c, size_t k, size_t i, const double *p, double w)
{
    double *h = c->hom + (k * (c->degree + 1) + i) * (c->dim + 1);
    for (size_t j = 0; j < c->dim; j++)
        h[j] = w * p[j];
    h[c->dim] = w;
}

/* c + rx cos t x + ry sin t y, t in [t0, t1] radians: exact quadratic arcs (affine images of
 * circular ones). */
static bsi_curve ellipse(const double *c, const double *x, const double *y, double rx, double ry,
                         double t0, double t1)
{
    bsi_axis a;
    CHECK(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, t0, t1, NULL, 0, &a) == BS_OK);
    bsi_curve k = alloc_curve(3, 2, a);
    for (size_t s = 0; s < a.n; s++) {
        double a0 = a.breaks[s], a1 = a.breaks[s + 1], half = 0.5 * (a1 - a0), mid = a0 + half;
        double ang[3] = {a0, mid, a1}, sc[3] = {1.0, 1.0 / cos(half), 1.0}, w[3] = {1.0, cos(half), 1.0};
        for (size_t i = 0; i < 3; i++) {
            double p[3];
            for (int j = 0; j < 3; j++)
                p[j] = c[j] + sc[i] * (rx * cos(ang[i]) * x[j] + ry * sin(ang[i]) * y[j]);
            set_hom(&k, s, i, p, w[i]);
        }
    }
    return k;
}

/* c + r (cos t x + sin t y), t in [t0, t1] radians: exact quadratic arcs. */
static bsi_curve circle(const double *c, const double *x, const double *y, double r, double t0, double t1)
{
    bsi_axis a;
    CHECK(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, t0, t1, NULL, 0, &a) == BS_OK);
    bsi_curve k = alloc_curve(3, 2, a);
    for (size_t s = 0; s < a.n; s++) {
        double a0 = a.breaks[s], a1 = a.breaks[s + 1], half = 0.5 * (a1 - a0), mid = a0 + half;
        double ang[3] = {a0, mid, a1}, rr[3] = {r, r / cos(half), r}, w[3] = {1.0, cos(half), 1.0};
        for (size_t i = 0; i < 3; i++) {
            double p[3];
            for (int j = 0; j < 3; j++)
                p[j] = c[j] + rr[i] * (cos(ang[i]) * x[j] + sin(ang[i]) * y[j]);
            set_hom(&k, s, i, p, w[i]);
        }
    }
    return k;
}

/* p + t d for t in [t0, t1]. */
static bsi_curve line(const double *p, const double *d, double t0, double t1)
{
    bsi_axis a;
    CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, t0, t1, NULL, 0, &a) == BS_OK);
    bsi_curve k = alloc_curve(3, 1, a);
    double q0[3], q1[3];
    for (int j = 0; j < 3; j++) {
        q0[j] = p[j] + t0 * d[j];
        q1[j] = p[j] + t1 * d[j];
    }
    set_hom(&k, 0, 0, q0, 1.0);
    set_hom(&k, 0, 1, q1, 1.0);
    return k;
}

/* Point of a piecewise rational Bezier curve at native t (de Casteljau, homogeneous). */
static void curve_at(const bsi_curve *c, double t, double *p)
{
    size_t k;
    double s;
    if (!bsi_axis_locate(&c->axis, t, &k, &s)) {
        for (size_t j = 0; j < c->dim; j++)
            p[j] = NAN;
        return;
    }
    double h[BS_MAX_DEGREE + 1][4];
    size_t n = c->degree, d1 = c->dim + 1;
    for (size_t i = 0; i <= n; i++)
        for (size_t j = 0; j < d1; j++)
            h[i][j] = c->hom[(k * (n + 1) + i) * d1 + j];
    for (size_t r = 1; r <= n; r++)
        for (size_t i = 0; i + r <= n; i++)
            for (size_t j = 0; j < d1; j++)
                h[i][j] = (1.0 - s) * h[i][j] + s * h[i + 1][j];
    for (size_t j = 0; j < c->dim; j++)
        p[j] = h[0][j] / h[0][c->dim];
}

/* ---- closed-form surfaces written here ---- */
static bsi_surface_def def_of(int kind, double r, double r2)
{
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = kind;
    d.r = r;
    d.r2 = r2;
    /* a tilted frame */
    double ca = cos(0.3), sa = sin(0.3), cb = cos(0.7), sb = sin(0.7);
    double x[3] = {cb, sb, 0.0}, y[3] = {-sb * ca, cb * ca, sa}, z[3] = {sb * sa, -cb * sa, ca};
    double o[3] = {0.25, -0.5, 1.0};
    memcpy(d.f.o, o, sizeof o);
    memcpy(d.f.x, x, sizeof x);
    memcpy(d.f.y, y, sizeof y);
    memcpy(d.f.z, z, sizeof z);
    return d;
}

static void def_point(const bsi_surface_def *d, double u, double v, double *p)
{
    double a, b, c, rho;
    switch (d->kind) {
    case BS_FACE_PLANE: a = u, b = v, c = 0.0; break;
    case BS_FACE_CYLINDER: a = d->r * cos(u), b = d->r * sin(u), c = v; break;
    case BS_FACE_CONE: rho = d->r + v * tan(d->r2), a = rho * cos(u), b = rho * sin(u), c = v; break;
    case BS_FACE_SPHERE: a = d->r * cos(v) * cos(u), b = d->r * cos(v) * sin(u), c = d->r * sin(v); break;
    default: rho = d->r + d->r2 * cos(v), a = rho * cos(u), b = rho * sin(u), c = d->r2 * sin(v); break;
    }
    for (int j = 0; j < 3; j++)
        p[j] = d->f.o[j] + a * d->f.x[j] + b * d->f.y[j] + c * d->f.z[j];
}

/* Frame vectors: the point of local (a, b, c) and the direction of (a, b, c). */
static void local_point(const bsi_surface_def *d, double a, double b, double c, double *p)
{
    for (int j = 0; j < 3; j++)
        p[j] = d->f.o[j] + a * d->f.x[j] + b * d->f.y[j] + c * d->f.z[j];
}

static void local_dir(const bsi_surface_def *d, double a, double b, double c, double *p)
{
    for (int j = 0; j < 3; j++)
        p[j] = a * d->f.x[j] + b * d->f.y[j] + c * d->f.z[j];
}

static double dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* The worst distance between trim-on-surface and edge over 2001 parameters; the trim's ends. */
typedef struct check_ctx {
    const bsi_surface_def *def; /* or the model face */
    const bs_model *m;
    size_t face;
    int swap;
} check_ctx;

static double worst_error(const check_ctx *x, const bsi_curve *edge, const bsi_trim *t)
{
    double e = 0.0, t0 = edge->axis.breaks[0], t1 = edge->axis.breaks[edge->axis.n];
    for (int i = 0; i <= 2000; i++) {
        double s = t0 + (t1 - t0) * i / 2000.0, uv[2], p[3], q[3];
        curve_at(&t->uv, s, uv);
        curve_at(edge, s, q);
        if (x->def != NULL)
            def_point(x->def, x->swap ? uv[1] : uv[0], x->swap ? uv[0] : uv[1], p);
        else if (!bsi_face_point(x->m, x->face, uv[0], uv[1], p))
            return INFINITY;
        e = fmax(e, dist3(p, q));
    }
    return e;
}

static const char *kind_name(int k)
{
    switch (k) {
    case BS_FACE_PLANE: return "plane";
    case BS_FACE_CYLINDER: return "cylinder";
    case BS_FACE_CONE: return "cone";
    case BS_FACE_SPHERE: return "sphere";
    case BS_FACE_TORUS: return "torus";
    default: return "bezier";
    }
}

static const double TOL = 1e-7 * 10.0; /* 1e-7 of parts of about 10 units */

/* Project, measure, print; returns the trim (caller frees) for more checks. */
static bsi_trim run_def(const bsi_surface_def *d, int swap, const double *box, const double *hint,
                        bsi_curve *edge, const char *what)
{
    bsi_trim t;
    bs_status st = bsi_pcurve_project_def(d, swap, box, hint, edge, TOL, &t);
    CHECKF(st == BS_OK, "%s %s: status %d", kind_name(d->kind), what, st);
    if (st == BS_OK) {
        check_ctx x = {d, NULL, 0, swap};
        double e = worst_error(&x, edge, &t);
        printf("  %-8s %-28s %4zu segments  worst %.3g (tol %.3g)\n", kind_name(d->kind), what,
               t.uv.axis.n, e, TOL);
        CHECKF(e <= TOL, "%s %s: %g", kind_name(d->kind), what, e);
        CHECK(t.computed == 1 && t.edge == BSI_NO_EDGE && t.uv.dim == 2);
        CHECK(t.uv.degree == (d->kind == BS_FACE_PLANE ? edge->degree : 3));
        CHECK(t.uv.axis.breaks[0] == edge->axis.breaks[0] &&
              t.uv.axis.breaks[t.uv.axis.n] == edge->axis.breaks[edge->axis.n]);
    }
    return t;
}

static void trim_ends(const bsi_trim *t, double *a, double *b)
{
    curve_at(&t->uv, t->uv.axis.breaks[0], a);
    curve_at(&t->uv, t->uv.axis.breaks[t->uv.axis.n], b);
}

static void test_analytic(void)
{
    double uv0[2], uv1[2];
    /* plane: a line and a circle */
    bsi_surface_def pl = def_of(BS_FACE_PLANE, 0.0, 0.0);
    double p[3], d[3], c[3], x[3], y[3];
    local_point(&pl, 1.0, 2.0, 0.0, p);
    local_dir(&pl, 0.6, -0.8, 0.0, d);
    bsi_curve e = line(p, d, -1.0, 3.0);
    bsi_trim t = run_def(&pl, 0, NULL, NULL, &e, "line");
    trim_ends(&t, uv0, uv1);
    CHECK(fabs(uv0[0] - 0.4) < 1e-12 && fabs(uv0[1] - 2.8) < 1e-12);
    bsi_curve_free(&t.uv);
    t = run_def(&pl, 1, NULL, NULL, &e, "line (swapped)");
    trim_ends(&t, uv0, uv1);
    CHECK(fabs(uv0[1] - 0.4) < 1e-12 && fabs(uv0[0] - 2.8) < 1e-12);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    local_point(&pl, -1.0, 0.5, 0.0, c);
    local_dir(&pl, 1.0, 0.0, 0.0, x);
    local_dir(&pl, 0.0, 1.0, 0.0, y);
    e = circle(c, x, y, 3.0, 0.0, 2.0 * PI);
    t = run_def(&pl, 0, NULL, NULL, &e, "circle");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);

    /* cylinder: a full circle runs u over [0, 2 pi]; a seam line at u = 0 (or 2 pi by a hint) */
    bsi_surface_def cy = def_of(BS_FACE_CYLINDER, 2.0, 0.0);
    local_point(&cy, 0.0, 0.0, 1.5, c);
    local_dir(&cy, 1.0, 0.0, 0.0, x);
    local_dir(&cy, 0.0, 1.0, 0.0, y);
    e = circle(c, x, y, 2.0, 0.0, 2.0 * PI);
    t = run_def(&cy, 0, NULL, NULL, &e, "circle, full turn");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0]) < 1e-12 && fabs(uv1[0] - 2.0 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    CHECK(fabs(uv0[1] - 1.5) < 1e-12);
    bsi_curve_free(&t.uv);
    /* the same circle backwards (y negated) from 2 pi down to 0, inside the default box */
    double ny[3] = {-y[0], -y[1], -y[2]};
    bsi_curve back = circle(c, x, ny, 2.0, 0.0, 2.0 * PI);
    t = run_def(&cy, 0, NULL, NULL, &back, "circle, backwards");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 2.0 * PI) < 1e-9 && fabs(uv1[0]) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&back);
    /* an arc across the seam: from -pi/4 to pi/4, placed in a box [-pi, pi] or by a hint */
    bsi_curve arc = circle(c, x, y, 2.0, -0.25 * PI, 0.25 * PI);
    double box[4] = {-PI, PI, 0.0, 3.0};
    t = run_def(&cy, 0, box, NULL, &arc, "arc across the seam, box");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] + 0.25 * PI) < 1e-9 && fabs(uv1[0] - 0.25 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    t = run_def(&cy, 0, NULL, NULL, &arc, "arc across the seam");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 1.75 * PI) < 1e-9 && fabs(uv1[0] - 2.25 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    double hint[2] = {-8.0, 0.0};
    t = run_def(&cy, 0, NULL, hint, &arc, "arc, hint");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - (-0.25 * PI - 2.0 * PI)) < 1e-9, "u %g", uv0[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&arc);
    bsi_curve_free(&e);
    local_point(&cy, 2.0, 0.0, -1.0, p);
    local_dir(&cy, 0.0, 0.0, 1.0, d);
    e = line(p, d, 0.0, 4.0);
    t = run_def(&cy, 0, NULL, NULL, &e, "seam line");
    trim_ends(&t, uv0, uv1);
    CHECK(fabs(uv0[0]) < 1e-12 && fabs(uv1[0]) < 1e-12 && fabs(uv1[1] - 3.0) < 1e-12);
    bsi_curve_free(&t.uv);
    hint[0] = 6.0;
    hint[1] = -1.0;
    t = run_def(&cy, 0, NULL, hint, &e, "seam line, hint 2 pi");
    trim_ends(&t, uv0, uv1);
    CHECK(fabs(uv0[0] - 2.0 * PI) < 1e-12);
    bsi_curve_free(&t.uv);
    t = run_def(&cy, 1, NULL, NULL, &e, "seam line (swapped)");
    trim_ends(&t, uv0, uv1);
    CHECK(fabs(uv0[1]) < 1e-12 && fabs(uv1[0] - 3.0) < 1e-12);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);

    /* sphere: a latitude circle, a meridian from the equator to the north pole and back */
    bsi_surface_def sp = def_of(BS_FACE_SPHERE, 1.5, 0.0);
    local_point(&sp, 0.0, 0.0, 1.5 * sin(0.3), c);
    e = circle(c, x, y, 1.5 * cos(0.3), 0.0, 2.0 * PI);
    local_dir(&sp, 1.0, 0.0, 0.0, x);
    local_dir(&sp, 0.0, 1.0, 0.0, y);
    bsi_curve_free(&e);
    e = circle(c, x, y, 1.5 * cos(0.3), 0.0, 2.0 * PI);
    t = run_def(&sp, 0, NULL, NULL, &e, "latitude circle");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    double z[3], o[3], m[3];
    local_dir(&sp, 0.0, 0.0, 1.0, z);
    local_point(&sp, 0.0, 0.0, 0.0, o);
    local_dir(&sp, cos(1.0), sin(1.0), 0.0, m);
    e = circle(o, m, z, 1.5, 0.0, 0.5 * PI);
    t = run_def(&sp, 0, NULL, NULL, &e, "meridian to the pole");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 1.0) < 1e-9 && fabs(uv1[0] - 1.0) < 1e-9 && fabs(uv1[1] - 0.5 * PI) < 1e-9,
           "u %g .. %g, v %g", uv0[0], uv1[0], uv1[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    e = circle(o, z, m, 1.5, 0.0, 0.5 * PI); /* from the pole down to the equator */
    t = run_def(&sp, 0, NULL, NULL, &e, "meridian from the pole");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 1.0) < 1e-9 && fabs(uv0[1] - 0.5 * PI) < 1e-9, "u %g v %g", uv0[0], uv0[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);

    e = circle(o, z, m, 1.5, 0.0, 0.5 * PI);
    t = run_def(&sp, 1, NULL, NULL, &e, "from the pole (swapped)");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[1] - 1.0) < 1e-9 && fabs(uv0[0] - 0.5 * PI) < 1e-9, "u %g v %g", uv0[0], uv0[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    e = circle(o, m, z, 1.5, -0.5 * PI, 0.5 * PI); /* pole to pole, swapped: the pole at both ends */
    t = run_def(&sp, 1, NULL, NULL, &e, "pole to pole (swapped)");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[1] - 1.0) < 1e-9 && fabs(uv1[1] - 1.0) < 1e-9, "v %g .. %g", uv0[1], uv1[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);

    /* cone: a circle, a generator line, a generator from the apex */
    bsi_surface_def co = def_of(BS_FACE_CONE, 1.0, 0.4);
    double rho = 1.0 + 2.0 * tan(0.4);
    local_point(&co, 0.0, 0.0, 2.0, c);
    e = circle(c, x, y, rho, 0.0, 2.0 * PI);
    t = run_def(&co, 0, NULL, NULL, &e, "circle");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    local_point(&co, cos(2.0), sin(2.0), 0.0, p);
    local_dir(&co, tan(0.4) * cos(2.0), tan(0.4) * sin(2.0), 1.0, d);
    e = line(p, d, -0.5, 3.0);
    t = run_def(&co, 0, NULL, NULL, &e, "generator");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    double apex_v = -1.0 / tan(0.4);
    local_point(&co, 0.0, 0.0, apex_v, p);
    e = line(p, d, 0.0, 2.0);
    t = run_def(&co, 0, NULL, NULL, &e, "generator from the apex");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 2.0) < 1e-9 && fabs(uv0[1] - apex_v) < 1e-9, "u %g v %g", uv0[0], uv0[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);

    /* torus: around the axis and around the tube (both periodic) */
    bsi_surface_def to = def_of(BS_FACE_TORUS, 3.0, 1.0);
    local_point(&to, 0.0, 0.0, sin(0.5), c);
    e = circle(c, x, y, 3.0 + cos(0.5), 0.0, 2.0 * PI);
    t = run_def(&to, 0, NULL, NULL, &e, "circle around the axis");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    local_point(&to, 3.0 * cos(1.0), 3.0 * sin(1.0), 0.0, c);
    e = circle(c, m, z, 1.0, -0.5 * PI, 1.5 * PI);
    t = run_def(&to, 0, NULL, NULL, &e, "circle around the tube");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv1[1] - uv0[1] - 2.0 * PI) < 1e-9 && uv0[1] >= 0.0, "v %g .. %g", uv0[1], uv1[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
}

/* ---- surfaces of patches built here (cylinder, sphere): continuation across patches ---- */

/* The quadratic rational arc over angles [a0, a1]: (cos, sin) of its points and its weights. */
static void arc3(double a0, double a1, double out[3][3])
{
    double half = 0.5 * (a1 - a0), mid = a0 + half;
    out[0][0] = cos(a0), out[0][1] = sin(a0), out[0][2] = 1.0;
    out[1][0] = cos(mid) / cos(half), out[1][1] = sin(mid) / cos(half), out[1][2] = cos(half);
    out[2][0] = cos(a1), out[2][1] = sin(a1), out[2][2] = 1.0;
}

typedef struct patched {
    bs_surface *s;
    bsi_axis au, av;
    bsi_pc_surf S;
} patched;

/* d as patches over u in [0, 2 pi], v over [v0, v1] (cylinder) or [-pi/2, pi/2] (sphere). */
static void make_patched(const bsi_surface_def *d, double v0, double v1, patched *out)
{
    int sphere = d->kind == BS_FACE_SPHERE;
    CHECK(bs_surface_create(&out->s) == BS_OK);
    CHECK(bsi_axis_make(BSI_AXIS_ANGULAR, 1.0, 0.0, 2.0 * PI, NULL, 0, &out->au) == BS_OK);
    CHECK(bsi_axis_make(sphere ? BSI_AXIS_ANGULAR : BSI_AXIS_LINEAR, 1.0, v0, v1, NULL, 0, &out->av) == BS_OK);
    for (size_t i = 0; i < out->au.n; i++)
        for (size_t j = 0; j < out->av.n; j++) {
            double U[3][3], W[3][3] = {{1, v0, 1}, {1, v1, 1}, {0, 0, 0}};
            arc3(out->au.breaks[i], out->au.breaks[i + 1], U);
            if (sphere)
                arc3(out->av.breaks[j], out->av.breaks[j + 1], W);
            size_t nv = sphere ? 3 : 2;
            double ctrl[9 * 3], w[9];
            for (size_t a = 0; a < 3; a++)
                for (size_t b = 0; b < nv; b++) {
                    double rho = sphere ? d->r * W[b][0] : d->r, z = sphere ? d->r * W[b][1] : W[b][1];
                    local_point(d, rho * U[a][0], rho * U[a][1], z, ctrl + (a * nv + b) * 3);
                    w[a * nv + b] = U[a][2] * (sphere ? W[b][2] : 1.0);
                }
            bs_patch *p = NULL;
            CHECK(bs_patch_create(2, nv - 1, 3, ctrl, w, &p) == BS_OK);
            CHECK(bs_surface_add(out->s, p, NULL) == BS_OK);
            bs_patch_destroy(p);
        }
    memset(&out->S, 0, sizeof out->S);
    out->S.s = out->s;
    out->S.au = &out->au;
    out->S.av = &out->av;
    out->S.box[0] = 0.0, out->S.box[1] = 2.0 * PI, out->S.box[2] = v0, out->S.box[3] = v1;
    out->S.period[0] = 2.0 * PI;
}

static void free_patched(patched *p)
{
    bs_surface_destroy(p->s);
    bsi_axis_free(&p->au);
    bsi_axis_free(&p->av);
}

static bsi_trim run_patched(const patched *P, const bsi_surface_def *d, const double *hint,
                            bsi_curve *edge, const char *what)
{
    bsi_trim t;
    bs_status st = bsi_pc_fit(&P->S, edge, hint, P->S.box, TOL, &t);
    CHECKF(st == BS_OK, "%s patches %s: status %d", kind_name(d->kind), what, st);
    if (st == BS_OK) {
        check_ctx x = {d, NULL, 0, 0};
        double e = worst_error(&x, edge, &t);
        printf("  %-8s %-28s %4zu segments  worst %.3g (tol %.3g)\n", kind_name(d->kind), what,
               t.uv.axis.n, e, TOL);
        CHECKF(e <= TOL, "%s patches %s: %g", kind_name(d->kind), what, e);
    }
    return t;
}

static void test_patches(void)
{
    double uv0[2], uv1[2], c[3], x[3], y[3], p[3], d[3];
    bsi_surface_def cy = def_of(BS_FACE_CYLINDER, 2.0, 0.0);
    patched P;
    make_patched(&cy, -1.0, 4.0, &P);
    local_point(&cy, 0.0, 0.0, 1.5, c);
    local_dir(&cy, 1.0, 0.0, 0.0, x);
    local_dir(&cy, 0.0, 1.0, 0.0, y);
    bsi_curve e = circle(c, x, y, 2.0, 0.0, 2.0 * PI);
    bsi_trim t = run_patched(&P, &cy, NULL, &e, "circle, full turn");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0]) < 1e-9 && fabs(uv1[0] - 2.0 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    /* the cut by a tilted plane through the axis: an ellipse; v = 2 tan(0.5) cos u */
    double tx[3];
    local_dir(&cy, 1.0 / sqrt(1.0 + tan(0.5) * tan(0.5)), 0.0, tan(0.5) / sqrt(1.0 + tan(0.5) * tan(0.5)), tx);
    local_point(&cy, 0.0, 0.0, 1.0, c);
    e = ellipse(c, tx, y, 2.0 * sqrt(1.0 + tan(0.5) * tan(0.5)), 2.0, 0.0, 2.0 * PI);
    t = run_patched(&P, &cy, NULL, &e, "ellipse (tilted cut)");
    bsi_curve_free(&t.uv);
    t = run_def(&cy, 0, NULL, NULL, &e, "ellipse (tilted cut)");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    local_point(&cy, 0.0, 0.0, 1.5, c);
    e = circle(c, x, y, 2.0, -0.25 * PI, 0.25 * PI);
    t = run_patched(&P, &cy, NULL, &e, "arc across the seam");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 1.75 * PI) < 1e-9 && fabs(uv1[0] - 2.25 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    double hint[2] = {-8.0, 0.0};
    t = run_patched(&P, &cy, hint, &e, "arc, hint");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - (-0.25 * PI - 2.0 * PI)) < 1e-9, "u %g", uv0[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    /* closed but not periodic (as a closed B-spline): circles starting on the seam go the right way */
    P.S.period[0] = 0.0;
    e = circle(c, x, y, 2.0, 0.0, 2.0 * PI);
    t = run_patched(&P, &cy, NULL, &e, "circle, closed not periodic");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0]) < 1e-9 && fabs(uv1[0] - 2.0 * PI) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    double ny[3] = {-y[0], -y[1], -y[2]};
    e = circle(c, x, ny, 2.0, 0.0, 2.0 * PI);
    t = run_patched(&P, &cy, NULL, &e, "backwards, closed not periodic");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 2.0 * PI) < 1e-9 && fabs(uv1[0]) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    P.S.period[0] = 2.0 * PI;
    local_point(&cy, 2.0, 0.0, -1.0, p);
    local_dir(&cy, 0.0, 0.0, 1.0, d);
    e = line(p, d, 0.0, 5.0);
    t = run_patched(&P, &cy, NULL, &e, "seam line");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0]) < 1e-9 && fabs(uv1[0]) < 1e-9, "u %g .. %g", uv0[0], uv1[0]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    free_patched(&P);

    bsi_surface_def sp = def_of(BS_FACE_SPHERE, 1.5, 0.0);
    make_patched(&sp, -0.5 * PI, 0.5 * PI, &P);
    local_point(&sp, 0.0, 0.0, 1.5 * sin(0.3), c);
    e = circle(c, x, y, 1.5 * cos(0.3), 0.0, 2.0 * PI);
    t = run_patched(&P, &sp, NULL, &e, "latitude circle");
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    double z[3], o[3], m[3];
    local_dir(&sp, 0.0, 0.0, 1.0, z);
    local_point(&sp, 0.0, 0.0, 0.0, o);
    local_dir(&sp, cos(1.0), sin(1.0), 0.0, m);
    e = circle(o, m, z, 1.5, -0.5 * PI, 0.5 * PI);
    t = run_patched(&P, &sp, NULL, &e, "meridian pole to pole");
    trim_ends(&t, uv0, uv1);
    CHECKF(fabs(uv0[0] - 1.0) < 1e-6 && fabs(uv1[0] - 1.0) < 1e-6 && fabs(uv1[1] - 0.5 * PI) < 1e-9,
           "u %g .. %g, v %g", uv0[0], uv1[0], uv1[1]);
    bsi_curve_free(&t.uv);
    bsi_curve_free(&e);
    /* an edge away from the sphere */
    e = circle(o, m, z, 1.6, 0.0, 0.5 * PI);
    CHECK(bsi_pc_fit(&P.S, &e, NULL, P.S.box, TOL, &t) == BS_ERR_DOMAIN);
    bsi_curve_free(&e);
    free_patched(&P);
}

/* ---- surfaces of analytic.c's patches: B-spline, extrusion, revolution (the definition path) ---- */
static void solve(size_t n, double *A, double *b);
static double binom(size_t n, size_t k);

/* The B-spline basis functions of degree p at x (knots t, count of them n): N[0 .. n). */
static void basis(const double *t, size_t p, size_t n, double x, double *N)
{
    double B[64];
    size_t m = n + p; /* knot intervals */
    for (size_t i = 0; i < m; i++)
        B[i] = (t[i] <= x && x < t[i + 1]) || (x == t[m] && t[i] < t[i + 1] && t[i + 1] == t[m]) ? 1.0 : 0.0;
    for (size_t d = 1; d <= p; d++)
        for (size_t i = 0; i + d < m; i++) {
            double a = t[i + d] > t[i] ? (x - t[i]) / (t[i + d] - t[i]) * B[i] : 0.0;
            double b = t[i + d + 1] > t[i + 1] ? (t[i + d + 1] - x) / (t[i + d + 1] - t[i + 1]) * B[i + 1] : 0.0;
            B[i] = a + b;
        }
    memcpy(N, B, n * sizeof *N);
}

static const double KU[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, KV[9] = {0, 0, 0, 0, 1.5, 3, 3, 3, 3};
static double BCTRL[6 * 5 * 3];

static void bspline_point(double u, double v, double *p)
{
    double Nu[6], Nv[5];
    basis(KU, 3, 6, u, Nu);
    basis(KV, 3, 5, v, Nv);
    p[0] = p[1] = p[2] = 0.0;
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 5; j++)
            for (int c = 0; c < 3; c++)
                p[c] += Nu[i] * Nv[j] * BCTRL[(i * 5 + j) * 3 + (size_t)c];
}

/* The worst distance between the trim on a surface given by a point function and the edge. */
static double worst_on(void (*point)(const void *, double, double, double *), const void *ctx,
                       const bsi_curve *edge, const bsi_trim *t)
{
    double e = 0.0, t0 = edge->axis.breaks[0], t1 = edge->axis.breaks[edge->axis.n];
    for (int i = 0; i <= 2000; i++) {
        double s = t0 + (t1 - t0) * i / 2000.0, uv[2], p[3], q[3];
        curve_at(&t->uv, s, uv);
        curve_at(edge, s, q);
        point(ctx, uv[0], uv[1], p);
        e = fmax(e, dist3(p, q));
    }
    return e;
}

static void bspline_at(const void *ctx, double u, double v, double *p)
{
    (void)ctx;
    bspline_point(u, v, p);
}

static void extrusion_at(const void *ctx, double u, double v, double *p)
{
    const bsi_surface_def *d = ctx;
    curve_at(d->curve, u, p);
    for (int c = 0; c < 3; c++)
        p[c] += v * d->dir[c];
}

static void revolution_at(const void *ctx, double u, double v, double *p)
{
    const bsi_surface_def *d = ctx;
    double q[3], e[3];
    curve_at(d->curve, v, q);
    for (int c = 0; c < 3; c++)
        e[c] = q[c] - d->f.o[c];
    double a = e[0] * d->f.x[0] + e[1] * d->f.x[1] + e[2] * d->f.x[2];
    double b = e[0] * d->f.y[0] + e[1] * d->f.y[1] + e[2] * d->f.y[2];
    double z = e[0] * d->f.z[0] + e[1] * d->f.z[1] + e[2] * d->f.z[2];
    local_point(d, a * cos(u) - b * sin(u), a * sin(u) + b * cos(u), z, p);
}

static int run_other(const bsi_surface_def *d, void (*point)(const void *, double, double, double *),
                     bsi_curve *edge, const char *what)
{
    bsi_trim t;
    bs_status st = bsi_pcurve_project_def(d, 0, NULL, NULL, edge, TOL, &t);
    if (st == BS_ERR_UNSUPPORTED) {
        printf("  %-30s skipped: no patches of this surface yet\n", what);
        return 0;
    }
    CHECKF(st == BS_OK, "%s: status %d", what, st);
    if (st != BS_OK)
        return 0;
    double e = worst_on(point, d, edge, &t);
    printf("  %-39s %4zu segments  worst %.3g (tol %.3g)\n", what, t.uv.axis.n, e, TOL);
    CHECKF(e <= TOL, "%s: %g", what, e);
    bsi_curve_free(&t.uv);
    return 1;
}

static void test_other_surfaces(void)
{
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 5; j++) {
            double *q = BCTRL + (i * 5 + j) * 3;
            q[0] = 2.0 * (double)i;
            q[1] = 2.5 * (double)j + 0.3 * (double)(i % 2);
            q[2] = ((i + j) % 3 == 0 ? 1.2 : -0.4) + 0.05 * (double)(i * j);
        }
    bs_bspline b = {3, 3, 6, 5, 3, KU, KV, BCTRL, NULL};
    bsi_surface_def bd;
    memset(&bd, 0, sizeof bd);
    bd.kind = BS_FACE_BSPLINE;
    bd.bspline = &b;
    /* the iso-curve v = 0.7: a B-spline of degree 3 on KU, its points the columns blended at 0.7 */
    double Nv[5], iso[6 * 3];
    basis(KV, 3, 5, 0.7, Nv);
    for (size_t i = 0; i < 6; i++)
        for (int c = 0; c < 3; c++) {
            iso[i * 3 + (size_t)c] = 0.0;
            for (size_t j = 0; j < 5; j++)
                iso[i * 3 + (size_t)c] += Nv[j] * BCTRL[(i * 5 + j) * 3 + (size_t)c];
        }
    bsi_curve e;
    CHECK(bsi_curve_bspline(3, 3, 6, KU, iso, NULL, 0.0, 3.0, &e) == BS_OK);
    if (!run_other(&bd, bspline_at, &e, "bspline  iso-curve v = 0.7 (3 spans)")) {
        bsi_curve_free(&e);
        return;
    }
    bsi_curve_free(&e);
    /* a straight line of (u, v) inside one span: a degree-6 Bezier through 7 of its points */
    bsi_axis ax;
    CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &ax) == BS_OK);
    e = alloc_curve(3, 6, ax);
    {
        double A[49], rhs[3][7];
        for (size_t i = 0; i <= 6; i++) {
            double x = (double)i / 6.0, q[3];
            bspline_point(1.1 + 0.8 * x, 0.2 + 1.2 * x, q);
            for (size_t j = 0; j <= 6; j++)
                A[i * 7 + j] = binom(6, j) * pow(x, (double)j) * pow(1.0 - x, (double)(6 - j));
            for (int c = 0; c < 3; c++)
                rhs[c][i] = q[c];
        }
        for (int c = 0; c < 3; c++) {
            double M[49];
            memcpy(M, A, sizeof M);
            solve(7, M, rhs[c]);
        }
        for (size_t i = 0; i <= 6; i++)
            set_hom(&e, 0, i, (const double[]){rhs[0][i], rhs[1][i], rhs[2][i]}, 1.0);
    }
    run_other(&bd, bspline_at, &e, "bspline  line of (u, v) in a span");
    {
        /* the same with the face's box given, swapped */
        bsi_trim t;
        double box[4] = {0.0, 3.0, 0.0, 3.0};
        CHECK(bsi_pcurve_project_def(&bd, 1, box, NULL, &e, TOL, &t) == BS_OK);
        double uv0[2], uv1[2];
        trim_ends(&t, uv0, uv1);
        CHECKF(fabs(uv0[1] - 1.1) < 1e-6 && fabs(uv0[0] - 0.2) < 1e-6, "uv %g %g", uv0[0], uv0[1]);
        CHECKF(fabs(uv1[1] - 1.9) < 1e-6 && fabs(uv1[0] - 1.4) < 1e-6, "uv %g %g", uv1[0], uv1[1]);
        bsi_curve_free(&t.uv);
    }
    bsi_curve_free(&e);

    /* an extruded arc and a line along the sweep */
    bsi_surface_def ex = def_of(BS_FACE_EXTRUSION, 0.0, 0.0);
    double c[3], x[3], y[3], p[3];
    local_point(&ex, 0.0, 0.0, 0.0, c);
    local_dir(&ex, 1.0, 0.0, 0.0, x);
    local_dir(&ex, 0.0, 1.0, 0.0, y);
    bsi_curve arc = circle(c, x, y, 2.0, 0.0, 1.5);
    local_dir(&ex, 0.2, 0.1, 1.0, ex.dir);
    ex.curve = &arc;
    curve_at(&arc, 0.9, p);
    e = line(p, ex.dir, -0.5, 2.0);
    run_other(&ex, extrusion_at, &e, "extrusion line along the sweep");
    bsi_curve_free(&e);
    bsi_curve_free(&arc);

    /* a revolved segment (a cone's piece) and the circle at v = 0.4 */
    bsi_surface_def rv = def_of(BS_FACE_REVOLUTION, 0.0, 0.0);
    double a0[3], dz[3], cc[3];
    local_point(&rv, 1.0, 0.0, 0.0, a0);
    local_dir(&rv, 1.0, 0.0, 1.5, dz);
    bsi_curve gen = line(a0, dz, 0.0, 1.0);
    rv.curve = &gen;
    local_point(&rv, 0.0, 0.0, 0.6, cc);
    local_dir(&rv, 1.0, 0.0, 0.0, x);
    local_dir(&rv, 0.0, 1.0, 0.0, y);
    e = circle(cc, x, y, 1.4, 0.0, 2.0 * PI);
    run_other(&rv, revolution_at, &e, "revolution circle, full turn");
    bsi_curve_free(&e);
    bsi_curve_free(&gen);
}

/* ---- Bezier faces: the model path (certified closest points, Newton continuation) ---- */

/* Solve the n x n system A x = b in place (partial pivoting). */
static void solve(size_t n, double *A, double *b)
{
    for (size_t k = 0; k < n; k++) {
        size_t piv = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[piv * n + k]))
                piv = i;
        for (size_t j = 0; j < n; j++) {
            double tmp = A[k * n + j];
            A[k * n + j] = A[piv * n + j];
            A[piv * n + j] = tmp;
        }
        double tmp = b[k];
        b[k] = b[piv];
        b[piv] = tmp;
        for (size_t i = k + 1; i < n; i++) {
            double f = A[i * n + k] / A[k * n + k];
            for (size_t j = k; j < n; j++)
                A[i * n + j] -= f * A[k * n + j];
            b[i] -= f * b[k];
        }
    }
    for (size_t k = n; k-- > 0;) {
        for (size_t j = k + 1; j < n; j++)
            b[k] -= A[k * n + j] * b[j];
        b[k] /= A[k * n + k];
    }
}

static double binom(size_t n, size_t k)
{
    double r = 1.0;
    for (size_t i = 1; i <= k; i++)
        r = r * (double)(n - k + i) / (double)i;
    return r;
}

/* The degree-6 polynomial image of the straight line (s, t) = a + x (b - a), x in [0, 1], on a
 * bicubic polynomial patch: its exact Bezier points by interpolation at 7 parameters. */
static bsi_curve image_of_line(const bs_patch *P, const double *a, const double *b)
{
    bsi_axis ax;
    CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &ax) == BS_OK);
    bsi_curve k = alloc_curve(3, 6, ax);
    double A[49], rhs[3][7];
    for (size_t i = 0; i <= 6; i++) {
        double x = (double)i / 6.0, s = a[0] + x * (b[0] - a[0]), t = a[1] + x * (b[1] - a[1]), q[3];
        bs_cview cu = {&s, 1, 0}, cv = {&t, 1, 0};
        bs_view pos[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
        CHECK(bs_patch_eval(P, 1, &cu, &cv, pos, NULL, NULL) == BS_OK);
        for (size_t j = 0; j <= 6; j++)
            A[i * 7 + j] = binom(6, j) * pow(x, (double)j) * pow(1.0 - x, (double)(6 - j));
        for (int c = 0; c < 3; c++)
            rhs[c][i] = q[c];
    }
    for (int c = 0; c < 3; c++) {
        double M[49];
        memcpy(M, A, sizeof M);
        solve(7, M, rhs[c]);
    }
    for (size_t i = 0; i <= 6; i++) {
        double q[3] = {rhs[0][i], rhs[1][i], rhs[2][i]};
        set_hom(&k, 0, i, q, 1.0);
    }
    return k;
}

static bs_patch *wavy_patch(void)
{
    double ctrl[16 * 3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *q = ctrl + (i * 4 + j) * 3;
            q[0] = 3.0 * i + 0.3 * j;
            q[1] = 2.5 * j - 0.2 * i * i;
            q[2] = ((i + j) % 2 ? 1.5 : -1.0) + 0.1 * i * j;
        }
    bs_patch *p = NULL;
    CHECK(bs_patch_create(3, 3, 3, ctrl, NULL, &p) == BS_OK);
    return p;
}

static void test_bezier_face(void)
{
    bs_model *m = NULL;
    CHECK(bsi_model_create(&m) == BS_OK);
    bs_patch *P = wavy_patch();
    bsi_face_spec spec;
    memset(&spec, 0, sizeof spec);
    spec.patch = P;
    size_t f;
    CHECK(bsi_model_add_face(m, &spec, &f) == BS_OK);
    spec.swap = 1;
    size_t g;
    CHECK(bsi_model_add_face(m, &spec, &g) == BS_OK);
    static const double lines[][4] = {
        {0.0, 0.0, 1.0, 1.0}, {0.1, 0.9, 0.8, 0.05}, {0.0, 0.3, 1.0, 0.3}, {0.5, 0.0, 0.5, 1.0}, {0.2, 0.7, 0.21, 0.72}};
    const char *names[] = {"diagonal", "anti-diagonal", "isoparametric v", "isoparametric u", "short"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        bsi_curve e = image_of_line(P, lines[i], lines[i] + 2);
        for (int sw = 0; sw < 2; sw++) {
            bsi_trim t;
            bs_status st = bsi_pcurve_project(m, sw ? g : f, &e, TOL, &t);
            CHECKF(st == BS_OK, "%s: %d", names[i], st);
            if (st != BS_OK)
                continue;
            check_ctx x = {NULL, m, sw ? g : f, 0};
            double err = worst_error(&x, &e, &t), uv0[2], uv1[2];
            printf("  bezier   %-16s%s %4zu segments  worst %.3g (tol %.3g)\n", names[i],
                   sw ? " (swapped)" : "          ", t.uv.axis.n, err, TOL);
            CHECKF(err <= TOL, "%s: %g", names[i], err);
            trim_ends(&t, uv0, uv1);
            CHECK(fabs(uv0[sw] - lines[i][0]) < 1e-6 && fabs(uv0[!sw] - lines[i][1]) < 1e-6);
            CHECK(fabs(uv1[sw] - lines[i][2]) < 1e-6 && fabs(uv1[!sw] - lines[i][3]) < 1e-6);
            bsi_curve_free(&t.uv);
        }
        bsi_curve_free(&e);
    }
    /* a piecewise edge (two segments, as a B-spline's spans): the images of two halves of a line */
    {
        bsi_curve h0 = image_of_line(P, (const double[]){0.05, 0.2}, (const double[]){0.5, 0.9});
        bsi_curve h1 = image_of_line(P, (const double[]){0.5, 0.9}, (const double[]){0.95, 0.1});
        bsi_axis ax;
        CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 2.0, 4.0, (const double[]){3.0}, 1, &ax) == BS_OK);
        bsi_curve two = alloc_curve(3, 6, ax);
        memcpy(two.hom, h0.hom, 7 * 4 * sizeof(double));
        memcpy(two.hom + 7 * 4, h1.hom, 7 * 4 * sizeof(double));
        bsi_trim t;
        CHECK(bsi_pcurve_project(m, f, &two, TOL, &t) == BS_OK);
        check_ctx x = {NULL, m, f, 0};
        double err = worst_error(&x, &two, &t);
        printf("  bezier   %-28s %4zu segments  worst %.3g (tol %.3g)\n", "two-span edge with a corner",
               t.uv.axis.n, err, TOL);
        CHECK(err <= TOL && t.uv.axis.breaks[0] == 2.0 && t.uv.axis.breaks[t.uv.axis.n] == 4.0);
        bsi_curve_free(&t.uv);
        bsi_curve_free(&two);
        bsi_curve_free(&h0);
        bsi_curve_free(&h1);
    }
    /* an edge off the face: refused */
    double p[3] = {0.0, 0.0, 50.0}, d[3] = {1.0, 1.0, 0.0};
    bsi_curve off = line(p, d, 0.0, 1.0);
    bsi_trim t;
    CHECK(bsi_pcurve_project(m, f, &off, TOL, &t) == BS_ERR_DOMAIN);
    CHECK(t.uv.hom == NULL);
    /* an edge on the face but leaving it past its side: refused */
    bsi_curve e = image_of_line(P, (const double[]){0.5, 0.5}, (const double[]){1.3, 0.5});
    CHECK(bsi_pcurve_project(m, f, &e, TOL, &t) == BS_ERR_DOMAIN);
    /* arguments */
    CHECK(bsi_pcurve_project(NULL, 0, &off, TOL, &t) == BS_ERR_INVALID_ARG);
    CHECK(bsi_pcurve_project(m, 7, &off, TOL, &t) == BS_ERR_INVALID_ARG);
    CHECK(bsi_pcurve_project(m, f, NULL, TOL, &t) == BS_ERR_INVALID_ARG);
    CHECK(bsi_pcurve_project(m, f, &off, 0.0, &t) == BS_ERR_INVALID_ARG);
    CHECK(bsi_pcurve_project(m, f, &off, NAN, &t) == BS_ERR_INVALID_ARG);
#ifdef BS_WRAP_MALLOC
    bsi_curve good = image_of_line(P, (const double[]){0.1, 0.1}, (const double[]){0.9, 0.6});
    int failed = 0;
    for (size_t n = 1; n < 40; n++) {
        fail_in = n;
        bs_status st = bsi_pcurve_project(m, f, &good, TOL, &t);
        fail_in = 0;
        if (st == BS_OK) {
            bsi_curve_free(&t.uv);
            break;
        }
        CHECKF(st == BS_ERR_NO_MEMORY && t.uv.hom == NULL, "allocation %zu: %d", n, st);
        failed++;
    }
    CHECK(failed > 0);
    bsi_curve_free(&good);
#endif
    bsi_curve_free(&e);
    bsi_curve_free(&off);
    bs_patch_destroy(P);
    bs_model_destroy(m);
}

static void test_refusals(void)
{
    bsi_surface_def cy = def_of(BS_FACE_CYLINDER, 2.0, 0.0);
    double p[3] = {10.0, 10.0, 10.0}, d[3] = {0.0, 0.0, 1.0};
    bsi_curve e = line(p, d, 0.0, 1.0);
    bsi_trim t;
    CHECK(bsi_pcurve_project_def(&cy, 0, NULL, NULL, &e, TOL, &t) == BS_ERR_DOMAIN);
    CHECK(bsi_pcurve_project_def(&cy, 0, NULL, NULL, &e, 0.0, &t) == BS_ERR_INVALID_ARG);
    bsi_surface_def pl = def_of(BS_FACE_PLANE, 0.0, 0.0);
    CHECK(bsi_pcurve_project_def(&pl, 0, NULL, NULL, &e, TOL, &t) == BS_ERR_DOMAIN);
#ifdef BS_WRAP_MALLOC
    double c[3], x[3], y[3];
    local_point(&pl, 0.0, 0.0, 0.0, c);
    local_dir(&pl, 1.0, 0.0, 0.0, x);
    local_dir(&pl, 0.0, 1.0, 0.0, y);
    bsi_curve arc = circle(c, x, y, 1.0, 0.0, 2.0);
    const bsi_surface_def *defs[2] = {&pl, &cy};
    for (int k = 0; k < 2; k++) {
        if (k == 1) {
            bsi_curve_free(&arc);
            local_point(&cy, 0.0, 0.0, 1.0, c);
            arc = circle(c, x, y, 2.0, 0.0, 2.0);
        }
        int failed = 0;
        for (size_t n = 1; n < 20; n++) {
            fail_in = n;
            bs_status st = bsi_pcurve_project_def(defs[k], 0, NULL, NULL, &arc, TOL, &t);
            fail_in = 0;
            if (st == BS_OK) {
                bsi_curve_free(&t.uv);
                break;
            }
            CHECK(st == BS_ERR_NO_MEMORY && t.uv.hom == NULL);
            failed++;
        }
        CHECK(failed >= 2);
    }
    bsi_curve_free(&arc);
#endif
    CHECK(bsi_pcurve_project_def(NULL, 0, NULL, NULL, &e, TOL, &t) == BS_ERR_INVALID_ARG);
    CHECK(bsi_pcurve_project_def(&cy, 0, NULL, NULL, NULL, TOL, &t) == BS_ERR_INVALID_ARG);
    bsi_curve flat = e;
    flat.dim = 2;
    CHECK(bsi_pcurve_project_def(&cy, 0, NULL, NULL, &flat, TOL, &t) == BS_ERR_INVALID_ARG);
    /* a revolution without its curve, an extrusion without a direction: no domain */
    bsi_surface_def rev = def_of(BS_FACE_REVOLUTION, 0.0, 0.0);
    CHECK(bsi_pcurve_project_def(&rev, 0, NULL, NULL, &e, TOL, &t) == BS_ERR_DOMAIN);
    bsi_surface_def ex = def_of(BS_FACE_EXTRUSION, 0.0, 0.0);
    ex.curve = &e;
    CHECK(bsi_pcurve_project_def(&ex, 0, NULL, NULL, &e, TOL, &t) == BS_ERR_DOMAIN);
    bsi_curve_free(&e);
}

/* A loop of a cylinder's face from computed trims: bottom circle, seam up, top circle back,
 * seam down; closed across the seam the two seam uses land at 2 pi and 0. */
static void test_close_loop(void)
{
    bsi_surface_def cy = def_of(BS_FACE_CYLINDER, 2.0, 0.0);
    double c0[3], c1[3], x[3], y[3], p[3], d[3];
    local_point(&cy, 0.0, 0.0, 0.0, c0);
    local_point(&cy, 0.0, 0.0, 3.0, c1);
    local_dir(&cy, 1.0, 0.0, 0.0, x);
    local_dir(&cy, 0.0, 1.0, 0.0, y);
    local_point(&cy, 2.0, 0.0, 0.0, p);
    local_dir(&cy, 0.0, 0.0, 1.0, d);
    bsi_curve edges[4] = {circle(c0, x, y, 2.0, 0.0, 2.0 * PI), line(p, d, 0.0, 3.0),
                          circle(c1, x, y, 2.0, 0.0, 2.0 * PI), line(p, d, 0.0, 3.0)};
    bsi_trim trims[4];
    for (int i = 0; i < 4; i++)
        CHECK(bsi_pcurve_project_def(&cy, 0, NULL, NULL, &edges[i], TOL, &trims[i]) == BS_OK);
    trims[2].reversed = trims[3].reversed = 1;
    bsi_pcurve_close_loop_def(&cy, 0, NULL, 1e-9, trims, 4);
    double a[2], b[2];
    trim_ends(&trims[1], a, b);
    CHECKF(fabs(a[0] - 2.0 * PI) < 1e-9 && fabs(b[0] - 2.0 * PI) < 1e-9, "seam up at %g", a[0]);
    trim_ends(&trims[2], a, b);
    CHECKF(fabs(a[0]) < 1e-9 && fabs(b[0] - 2.0 * PI) < 1e-9, "top %g .. %g", a[0], b[0]);
    trim_ends(&trims[3], a, b);
    CHECKF(fabs(a[0]) < 1e-9, "seam down at %g", a[0]);
    for (int i = 0; i < 4; i++) {
        bsi_curve_free(&trims[i].uv);
        bsi_curve_free(&edges[i]);
    }
}

/* The seam of a closed B-spline (first and last rows alike), not periodic: trims on it are put on
 * the side where the loop goes on. */
static void closed_seam(const bsi_surface_def *d, double w)
{
    for (int swap = 0; swap < 2; swap++) {
        /* (u0 u1 v0 v1): bottom 0 -> w at v = 0, seam up (wrongly at u = 0), top back at v = 1,
         * seam down (wrongly at u = w) */
        double q[4][4] = {{0, w, 0, 0}, {0, 0, 0, 1}, {w, 0, 1, 1}, {w, w, 1, 0}};
        bsi_trim t[4];
        for (int k = 0; k < 4; k++) {
            memset(&t[k], 0, sizeof t[k]);
            bsi_axis ax;
            CHECK(bsi_axis_make(BSI_AXIS_LINEAR, 1.0, 0.0, 1.0, NULL, 0, &ax) == BS_OK);
            t[k].uv = alloc_curve(2, 1, ax);
            double a[2] = {q[k][0], q[k][2]}, z[2] = {q[k][1], q[k][3]};
            if (swap) {
                double h = a[0];
                a[0] = a[1], a[1] = h;
                h = z[0];
                z[0] = z[1], z[1] = h;
            }
            set_hom(&t[k].uv, 0, 0, a, 1.0);
            set_hom(&t[k].uv, 0, 1, z, 1.0);
        }
        bsi_pcurve_close_loop_def(d, swap, NULL, 1e-9, t, 4);
        double a0[2], a1[2];
        trim_ends(&t[1], a0, a1);
        CHECKF(a0[swap] == w && a1[swap] == w, "seam up at %g", a0[swap]);
        trim_ends(&t[3], a0, a1);
        CHECKF(a0[swap] == 0.0 && a1[swap] == 0.0, "seam down at %g", a0[swap]);
        for (int k = 0; k < 4; k++)
            bsi_curve_free(&t[k].uv);
    }
}

static void test_closed_seam(void)
{
    static const double ku[6] = {0, 0, 0, 1, 1, 1}, kv[4] = {0, 0, 1, 1};
    double ctrl[3 * 2 * 3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 2; j++) {
            double *q = ctrl + (i * 2 + j) * 3;
            q[0] = i == 1 ? 2.0 : 0.0;
            q[1] = i == 1 ? 1.0 : 0.0;
            q[2] = j;
        }
    bs_bspline b = {2, 1, 3, 2, 3, ku, kv, ctrl, NULL};
    bsi_surface_def d;
    memset(&d, 0, sizeof d);
    d.kind = BS_FACE_BSPLINE;
    d.bspline = &b;
    /* an extrusion of a closed curve (a full circle over [0, 2 pi]) */
    bsi_surface_def ex = def_of(BS_FACE_EXTRUSION, 0.0, 0.0);
    double c[3], x[3], y[3];
    local_point(&ex, 0.0, 0.0, 0.0, c);
    local_dir(&ex, 1.0, 0.0, 0.0, x);
    local_dir(&ex, 0.0, 1.0, 0.0, y);
    local_dir(&ex, 0.0, 0.0, 1.0, ex.dir);
    bsi_curve loop = circle(c, x, y, 1.0, 0.0, 2.0 * PI);
    ex.curve = &loop;
    closed_seam(&ex, 2.0 * PI);
    bsi_curve_free(&loop);
    closed_seam(&d, 1.0);
}

int main(void)
{
    printf("closed forms:\n");
    test_analytic();
    printf("patches built here:\n");
    test_patches();
    printf("surfaces of analytic.c's patches:\n");
    test_other_surfaces();
    printf("Bezier faces:\n");
    test_bezier_face();
    test_refusals();
    test_close_loop();
    test_closed_seam();
    return bs_test_exit("test_pcurve");
}
