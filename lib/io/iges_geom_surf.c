/* IGES surfaces for models, each built once: 108 planes, 120 surfaces of revolution, 122 tabulated
 * cylinders, 128 B-spline surfaces, and the analytic 190 .. 198 (with their 116 points and 123
 * directions), transformations applied to their frames, curves and control points. The
 * parameters of the file's trim curves are mapped to the canonical ones of model/internal.h:
 * 190 .. 198 as written by OpenCASCADE measure angles in degrees and the cone's v along its slant,
 * and a torus's trims take (minor angle, minus the major angle), as the bottle's fillets show;
 * 120 takes (generatrix parameter, angle), the canonical (v, u); 122 runs over [0,1]^2. */
#include "io/iges_model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG 0.017453292519943295 /* radians per degree */

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static int unit3(double *a)
{
    double n = sqrt(dot3(a, a));
    if (!(n > 0.0) || !isfinite(n))
        return 0;
    for (size_t i = 0; i < 3; i++)
        a[i] /= n;
    return 1;
}

/* A right-handed frame of axis z and reference x (NULL or parallel to z: any perpendicular). */
static int frame(const double *o, const double *z, const double *ref, bsi_frame *f)
{
    memcpy(f->o, o, sizeof f->o);
    memcpy(f->z, z, sizeof f->z);
    if (!unit3(f->z))
        return 0;
    double x[3] = {1, 0, 0};
    if (ref != NULL)
        memcpy(x, ref, sizeof x);
    for (int pass = 0; pass < 2; pass++) {
        double d = dot3(x, f->z);
        for (size_t i = 0; i < 3; i++)
            f->x[i] = x[i] - d * f->z[i];
        if (unit3(f->x) && fabs(dot3(f->x, f->z)) < 1e-9)
            break;
        memset(x, 0, sizeof x); /* the world axis least along z */
        x[fabs(f->z[0]) <= fabs(f->z[1]) && fabs(f->z[0]) <= fabs(f->z[2]) ? 0 : fabs(f->z[1]) <= fabs(f->z[2]) ? 1 : 2] = 1.0;
    }
    cross3(f->z, f->x, f->y);
    return 1;
}

/* Apply a rigid 3x4 matrix to frame f: 0 when it scales or shears. A reflection (*flip set) turns
 * the frame's y around to keep it right-handed: the surface's u (a plane's v) then runs backwards. */
static int move_frame(const double *mat, bsi_frame *f, int *flip)
{
    bsi_frame g;
    for (size_t i = 0; i < 3; i++) {
        g.o[i] = mat[4 * i] * f->o[0] + mat[4 * i + 1] * f->o[1] + mat[4 * i + 2] * f->o[2] + mat[4 * i + 3];
        g.x[i] = mat[4 * i] * f->x[0] + mat[4 * i + 1] * f->x[1] + mat[4 * i + 2] * f->x[2];
        g.y[i] = mat[4 * i] * f->y[0] + mat[4 * i + 1] * f->y[1] + mat[4 * i + 2] * f->y[2];
        g.z[i] = mat[4 * i] * f->z[0] + mat[4 * i + 1] * f->z[1] + mat[4 * i + 2] * f->z[2];
    }
    double c[3];
    cross3(g.x, g.y, c);
    *flip = dot3(c, g.z) < 0.0;
    if (fabs(dot3(g.x, g.x) - 1) > 1e-9 || fabs(dot3(g.y, g.y) - 1) > 1e-9 || fabs(dot3(g.x, g.y)) > 1e-9 ||
        fabs(fabs(dot3(c, g.z)) - 1) > 1e-9)
        return 0;
    for (size_t i = 0; i < 3 && *flip; i++)
        g.y[i] = -g.y[i];
    *f = g;
    return 1;
}

/* The point of a 116 or the direction of a 123 at slot s (cached in its mat), transformed. */
static bs_status vector(igm *m, size_t s, size_t t, long type, double *p)
{
    igm_slot *e = &m->slot[t];
    bs_status r0 = bsi_igm_typed(m, s, t, type);
    if (r0 != BS_OK)
        return r0;
    if (e->mat == NULL) {
        iges_stream st;
        iges_field f;
        double v[3], mat[12];
        bs_status r = bsi_igm_open(m, t, &st);
        for (int k = 0; k < 3 && r == BS_OK; k++)
            r = bsi_iges_real(&m->g, &st, "a coordinate", &v[k], &f);
        if (r == BS_OK && (r = bsi_igm_rest(m, &st)) == BS_OK)
            r = bsi_igm_matrix(m, t, mat);
        if (r != BS_OK)
            return bsi_igm_name(m, t, r);
        if ((e->mat = malloc(3 * sizeof *e->mat)) == NULL)
            return BS_ERR_NO_MEMORY;
        for (size_t i = 0; i < 3; i++)
            e->mat[i] = mat[4 * i] * v[0] + mat[4 * i + 1] * v[1] + mat[4 * i + 2] * v[2] + (type == 116 ? mat[4 * i + 3] : 0.0);
    }
    memcpy(p, e->mat, 3 * sizeof *p);
    return BS_OK;
}

/* 190 .. 198: location or centre, then the fields of the type. */
static bs_status analytic(igm *m, size_t s, iges_stream *st, igm_surface *sf)
{
    long type = m->slot[s].type, form = m->slot[s].form;
    bsi_surface_def *d = &sf->def;
    double o[3], z[3] = {0, 0, 1}, ref[3], num[2] = {0, 0};
    size_t t;
    iges_field f;
    bs_status r = bsi_igm_ptr(m, s, st, "a point pointer", 0, &t, NULL);
    if (r == BS_OK)
        r = vector(m, s, t, 116, o);
    if (r == BS_OK && type == 196)
        r = bsi_iges_real(&m->g, st, "the radius", &num[0], &f);
    if (r == BS_OK && (type != 196 || form == 1) && (r = bsi_igm_ptr(m, s, st, "a direction pointer", 0, &t, NULL)) == BS_OK)
        r = vector(m, s, t, 123, z);
    for (int k = 0; r == BS_OK && k < (type == 192 ? 1 : type == 194 || type == 198 ? 2 : 0); k++)
        r = bsi_iges_real(&m->g, st, "a radius or angle", &num[k], &f);
    if (r == BS_OK && form == 1 && (r = bsi_igm_ptr(m, s, st, "a reference direction pointer", 0, &t, NULL)) == BS_OK)
        r = vector(m, s, t, 123, ref);
    if (r != BS_OK)
        return r;
    static const int kinds[5] = {BS_FACE_PLANE, BS_FACE_CYLINDER, BS_FACE_CONE, BS_FACE_SPHERE, BS_FACE_TORUS};
    d->kind = kinds[(type - 190) / 2];
    d->r = num[0];
    d->r2 = type == 194 ? num[1] * DEG : num[1];
    if (!frame(o, z, form == 1 ? ref : NULL, &d->f))
        return bsi_igm_fail(m, s, 1, "axis or normal of length 0");
    double a = type == 190 ? 1.0 : DEG; /* OpenCASCADE writes angles in degrees */
    double b = type == 190 ? 1.0 : type == 194 ? cos(d->r2) : type == 192 ? 1.0 : DEG;
    double aff[6] = {a, 0, 0, 0, b, 0};
    if (type == 198) { /* (minor angle, major angle measured backwards), as OpenCASCADE writes tori */
        double turned[6] = {DEG, 0, 0, 0, -DEG, 2 * 3.141592653589793};
        memcpy(aff, turned, sizeof aff);
        sf->swap = 1;
    }
    memcpy(sf->aff, aff, sizeof aff);
    sf->plane = type == 190;
    sf->param = form == 1;
    return BS_OK;
}

static bs_status plane_108(igm *m, size_t s, iges_stream *st, igm_surface *sf)
{
    double v[4];
    iges_field f;
    bs_status r = BS_OK;
    for (int k = 0; k < 4 && r == BS_OK; k++)
        r = bsi_iges_real(&m->g, st, "a coefficient of the plane", &v[k], &f);
    if (r != BS_OK || (r = bsi_igm_rest(m, st)) != BS_OK)
        return r;
    double n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double o[3] = {v[3] * v[0] / n2, v[3] * v[1] / n2, v[3] * v[2] / n2};
    sf->def.kind = BS_FACE_PLANE;
    if (!(n2 > 0.0) || !frame(o, v, NULL, &sf->def.f))
        return bsi_igm_fail(m, s, 1, "plane of normal 0");
    sf->plane = 1;
    return BS_OK;
}

/* The first and last control points of a one-segment line. */
static int line_ends(const igm_slot *e, double *p0, double *p1)
{
    if (e->npieces != 1 || e->pieces[0].degree != 1 || e->pieces[0].axis.n != 1)
        return 0;
    const double *h = e->pieces[0].hom;
    for (size_t i = 0; i < 3; i++) {
        p0[i] = h[i] / h[3];
        p1[i] = h[4 + i] / h[7];
    }
    return 1;
}

/* 1 when c ends where it starts, within 1e-12 of its control points' size: its sweep is periodic
 * along it. */
static int closed_curve(const bsi_curve *c)
{
    double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0}, size = 0.0; /* a 2-D curve fills two */
    bsi_curve_bounds(c, lo, hi);
    for (size_t k = 0; k < 3; k++)
        size = fmax(size, fmax(fabs(lo[k]), fabs(hi[k])));
    return bsi_curve_closed(c, 1e-12 * size);
}

static bs_status swept(igm *m, size_t s, iges_stream *st, igm_surface *sf, int depth)
{
    long type = m->slot[s].type;
    size_t l = 0, c;
    double v[3];
    iges_field f;
    bs_status r = BS_OK;
    if (type == 120)
        r = bsi_igm_ptr(m, s, st, "the axis pointer", 0, &l, NULL);
    if (r == BS_OK)
        r = bsi_igm_ptr(m, s, st, "the curve pointer", 0, &c, NULL);
    for (int k = 0; k < (type == 120 ? 2 : 3) && r == BS_OK; k++)
        r = bsi_iges_real(&m->g, st, type == 120 ? "an angle" : "a coordinate", &v[k], &f);
    if (r == BS_OK)
        r = bsi_igm_rest(m, st);
    if (r == BS_OK && type == 120 && m->slot[l].type != 110)
        return bsi_igm_fail(m, s, 1, "axis of entity %ld, not a line 110", m->slot[l].type);
    if (r != BS_OK || (type == 120 && (r = bsi_igm_curve(m, l, depth + 1)) != BS_OK) ||
        (r = bsi_igm_curve(m, c, depth + 1)) != BS_OK)
        return r;
    const igm_slot *ce = &m->slot[c];
    if (ce->npieces != 1) {
        (void)bsi_igm_fail(m, s, 1, "curve of several pieces (composite) not read");
        return BS_ERR_UNSUPPORTED;
    }
    /* a closed curve over three turns, its sweep periodic along it: trims may cross its start */
    int closed = closed_curve(&ce->pieces[0]);
    if ((r = closed ? bsi_curve_repeat(&ce->pieces[0], &sf->curve) : bsi_curve_copy(&ce->pieces[0], &sf->curve)) != BS_OK)
        return r;
    /* the curve's own range (the file's parameters map onto it), and the range it is swept over */
    const bsi_axis *own = &ce->pieces[0].axis, *ax = &sf->curve.axis;
    double c0 = own->breaks[0], c1 = own->breaks[own->n], t0 = ax->breaks[0], t1 = ax->breaks[ax->n], p0[3], p1[3];
    sf->def.curve = &sf->curve;
    sf->def.curve_period = closed ? c1 - c0 : 0.0;
    sf->param = sf->has_box = 1;
    if (type == 120) {
        double z[3];
        if (!line_ends(&m->slot[l], p0, p1))
            return bsi_igm_fail(m, s, 1, "axis line not read as one segment");
        for (size_t i = 0; i < 3; i++)
            z[i] = p1[i] - p0[i];
        if (!frame(p0, z, NULL, &sf->def.f))
            return bsi_igm_fail(m, s, 1, "axis line of length 0");
        if (!(v[1] > v[0]))
            return bsi_igm_fail(m, s, 1, "terminate angle not after the start angle");
        sf->def.kind = BS_FACE_REVOLUTION;
        sf->swap = 1;
        double box[4] = {t0, t1, v[0], v[1]}, aff[6] = {1, 0, 0, 0, 1, 0};
        memcpy(sf->box, box, sizeof box);
        memcpy(sf->aff, aff, sizeof aff);
        return BS_OK;
    }
    double z[3] = {0, 0, 1};
    (void)bsi_curve_eval(&sf->curve, c0, p0);
    for (size_t i = 0; i < 3; i++)
        sf->def.dir[i] = v[i] - p0[i];
    (void)frame(p0, z, NULL, &sf->def.f);
    sf->def.kind = BS_FACE_EXTRUSION;
    double box[4] = {t0, t1, 0, 1}, aff[6] = {c1 - c0, 0, c0, 0, 1, 0};
    memcpy(sf->box, box, sizeof box);
    memcpy(sf->aff, aff, sizeof aff);
    return BS_OK;
}

static bs_status build(igm *m, size_t s, igm_surface *sf, int depth)
{
    long type = m->slot[s].type;
    iges_stream st;
    bs_status r = bsi_igm_open(m, s, &st);
    double aff[6] = {1, 0, 0, 0, 1, 0}, mat[12];
    memcpy(sf->aff, aff, sizeof aff);
    if (r != BS_OK)
        return r;
    if (type == 108)
        r = plane_108(m, s, &st, sf);
    else if (type == 120 || type == 122)
        r = swept(m, s, &st, sf, depth);
    else if (type == 128)
        r = bsi_igm_bspline_128(m, s, &st, sf);
    else if ((r = analytic(m, s, &st, sf)) == BS_OK)
        r = bsi_igm_rest(m, &st);
    if (r != BS_OK || (r = bsi_igm_matrix(m, s, mat)) != BS_OK)
        return r;
    if (type == 128) {
        for (size_t k = 0; k < sf->b.count_u * sf->b.count_v; k++) {
            double *p = (double *)sf->b.ctrl + 3 * k, x[3] = {p[0], p[1], p[2]};
            for (size_t i = 0; i < 3; i++)
                p[i] = mat[4 * i] * x[0] + mat[4 * i + 1] * x[1] + mat[4 * i + 2] * x[2] + mat[4 * i + 3];
        }
        return BS_OK;
    }
    int flip;
    if (!move_frame(mat, &sf->def.f, &flip)) {
        (void)bsi_igm_fail(m, s, 7, "transformation that scales or shears the surface");
        return BS_ERR_UNSUPPORTED;
    }
    bsi_frame *f = &sf->def.f;
    if (flip && sf->def.kind == BS_FACE_REVOLUTION) { /* a mirrored turn is a turn the other way round */
        for (size_t i = 0; i < 3; i++)
            f->z[i] = -f->z[i];
        cross3(f->z, f->x, f->y);
    } else if (flip && sf->def.kind != BS_FACE_EXTRUSION) {
        size_t row = sf->def.kind == BS_FACE_PLANE || sf->swap ? 3 : 0;
        for (size_t i = row; i < row + 3; i++)
            sf->aff[i] = -sf->aff[i];
    }
    if (sf->def.curve != NULL)
        bsi_igm_move(&sf->curve, mat);
    for (size_t i = 0; i < 3 && type == 122; i++) { /* the sweep is a vector */
        double d[3] = {sf->def.dir[0], sf->def.dir[1], sf->def.dir[2]};
        sf->def.dir[i] = mat[4 * i] * d[0] + mat[4 * i + 1] * d[1] + mat[4 * i + 2] * d[2];
    }
    return BS_OK;
}

bs_status bsi_igm_surface(igm *m, size_t s, int depth)
{
    igm_slot *e = &m->slot[s];
    long type = e->type;
    if (type != 108 && type != 120 && type != 122 && type != 128 &&
        !(type >= 190 && type <= 198 && type % 2 == 0)) {
        (void)bsi_igm_fail(m, s, 1, "surface type not read");
        return BS_ERR_UNSUPPORTED;
    }
    if (e->state == IGM_DONE)
        return BS_OK;
    if (e->state == IGM_BUSY || depth > IGM_DEPTH)
        return bsi_igm_fail(m, s, 1, "surfaces nested deeper than %d or circular", IGM_DEPTH);
    e->state = IGM_BUSY;
    igm_surface *sf = calloc(1, sizeof *sf);
    if (sf == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status r = build(m, s, sf, depth);
    if (r != BS_OK) {
        bsi_curve_free(&sf->curve);
        free(sf->data);
        free(sf);
        return bsi_igm_name(m, s, r);
    }
    if (type == 128)
        sf->def.bspline = &sf->b;
    e->surf = sf;
    e->state = IGM_DONE;
    return BS_OK;
}
