/* Scale invariance: a patch and its copies scaled by 2^e, e from -1000 to 1020, give the same
 * normals and normal kinds, the same curvature kinds and curvatures scaled by 2^-e, closest
 * distances (through the patch and through a locator) scaled by 2^e, and rays that hit the
 * scaled point at the scaled t, at the same (u, v), with the same normals (bs_patch_eval_normal's
 * bits); rays hit subnormal copies (2^-1030 .. 2^-1060) as they hit the same net scaled back to
 * unit size; the hostile boxes (tests/hostile/huge_box, tiny_box, subnormal_box) tessellate with
 * a relative tolerance into the unit box's mesh and normals; a limit curvature on a collapsed
 * side, the same at every scale, and the limit normal at a pole with wild weights. Before 1.2: normals (0,0,0) beyond
 * 1e154 and below 1e-162, no closest point through a locator beyond 1e154, rays missing at
 * 1e-170 and 1e200, 2 triangles for huge_box; ray hit normals beyond 2^1000 a few ulps off
 * bs_patch_eval_normal's and subnormal copies missed. */
#include "harness.h"
#include "shapes.h"

#include <bezsurf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* A wavy bicubic net in [-1, 1]^3, and its weights when rational. */
static void net(double *ctrl, double *w)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *p = ctrl + 3 * (4 * i + j);
            p[0] = (double)i / 1.5 - 1.0;
            p[1] = (double)j / 1.5 - 1.0;
            p[2] = 0.25 * (double)((i * 3 + j * 5) % 7) / 7.0 - 0.125 * (double)(i == j);
            w[4 * i + j] = 1.0 + 0.5 * (double)((i + 2 * j) % 3);
        }
}

typedef struct answers {
    double nrm[3], k[4], d, dl, t;
    unsigned char kind, ck;
    uint32_t id;
    bs_status st;
    double uv[2], rn[3], pn[3]; /* the ray hit's (u, v) and normal, bs_patch_eval_normal's there */
    unsigned char rk, pk;       /* their kinds */
} answers;

/* The ray o + t d against L, a locator of p alone: its patch, (u, v), t, normal and kind into a,
 * and bs_patch_eval_normal's normal and kind at that (u, v). */
static void ray(const bs_locator *L, const bs_patch *p, const double o[3], const double d[3], answers *a)
{
    bs_cview ov[3] = {{&o[0], 1, 0}, {&o[1], 1, 0}, {&o[2], 1, 0}};
    bs_cview dw[3] = {{&d[0], 1, 0}, {&d[1], 1, 0}, {&d[2], 1, 0}};
    bs_view tv = {&a->t, 1, 0}, uvv[2] = {{&a->uv[0], 1, 0}, {&a->uv[1], 1, 0}};
    bs_view rnv[3] = {{&a->rn[0], 1, 0}, {&a->rn[1], 1, 0}, {&a->rn[2], 1, 0}};
    CHECK_STATUS(bs_locator_intersect_kind(L, 1, ov, dw, NULL, &a->id, uvv, &tv, rnv, &a->rk), BS_OK);
    bs_cview hu = {&a->uv[0], 1, 0}, hv = {&a->uv[1], 1, 0};
    bs_view pnv[3] = {{&a->pn[0], 1, 0}, {&a->pn[1], 1, 0}, {&a->pn[2], 1, 0}};
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &hu, &hv, NULL, pnv, &a->pk), BS_OK);
}

/* The ray hit's normal is bs_patch_eval_normal's, bit for bit. */
static int same_normal(const answers *a)
{
    return a->rk == a->pk && a->rn[0] == a->pn[0] && a->rn[1] == a->pn[1] && a->rn[2] == a->pn[2];
}

static void query(const bs_patch *p, double s, answers *a)
{
    double u = 0.3, v = 0.7, x[3];
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
    bs_view nv[3] = {{&a->nrm[0], 1, 0}, {&a->nrm[1], 1, 0}, {&a->nrm[2], 1, 0}};
    bs_view kv[4] = {{&a->k[0], 1, 0}, {&a->k[1], 1, 0}, {&a->k[2], 1, 0}, {&a->k[3], 1, 0}};
    CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, xv, nv, &a->kind), BS_OK);
    CHECK_STATUS(bs_patch_eval_curvature(p, 1, &cu, &cv, kv, NULL, NULL, &a->ck), BS_OK);
    double q[3] = {0.2 * s, -0.3 * s, 1.5 * s};
    bs_cview qv[3] = {{&q[0], 1, 0}, {&q[1], 1, 0}, {&q[2], 1, 0}};
    bs_view dv = {&a->d, 1, 0}, dl = {&a->dl, 1, 0};
    a->st = bs_patch_closest_point(p, 1, qv, NULL, &dv, NULL);
    bs_locator *L = shape_locator(p);
    CHECK_STATUS(bs_locator_closest_point(L, 1, qv, NULL, NULL, &dl, NULL), a->st);
    /* a ray down the normal from 0.5 s above the point */
    double o[3], d[3];
    for (int c = 0; c < 3; c++) {
        o[c] = x[c] + 0.5 * s * a->nrm[c];
        d[c] = -a->nrm[c];
    }
    ray(L, p, o, d, a);
    bs_locator_destroy(L);
}

static void copies(int rational)
{
    double ctrl[48], w[16], sc[48];
    net(ctrl, w);
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(3, 3, 3, ctrl, rational ? w : NULL, &p), BS_OK);
    answers ref;
    query(p, 1.0, &ref);
    bs_patch_destroy(p);
    CHECK(ref.kind == BS_NORMAL_REGULAR && ref.ck == BS_CURV_REGULAR && ref.st == BS_OK && ref.id == 0);
    int worst_e = 0;
    double worst = 0.0;
    for (int e = -1000; e <= 1020; e += e >= 1000 ? 5 : bs_test_quick() ? 100 : 20) {
        double s = ldexp(1.0, e);
        for (int k = 0; k < 48; k++)
            sc[k] = ctrl[k] * s;
        p = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, sc, rational ? w : NULL, &p), BS_OK);
        if (p == NULL)
            continue;
        answers a;
        query(p, s, &a);
        double dn = fabs(a.nrm[0] - ref.nrm[0]) + fabs(a.nrm[1] - ref.nrm[1]) + fabs(a.nrm[2] - ref.nrm[2]);
        CHECKF(a.kind == ref.kind && dn <= 1e-13, "2^%d: normal kind %d, off by %g", e, a.kind, dn);
        CHECKF(a.ck == ref.ck, "2^%d: curvature kind %d", e, a.ck);
        for (int c = 1; c < 4; c++) /* H, k_min, k_max scale by 2^-e */
            CHECKF(fabs(ldexp(a.k[c], e) - ref.k[c]) <= 1e-9 * (fabs(ref.k[2]) + fabs(ref.k[3]) + 1.0),
                   "2^%d: curvature %d is %g, %g expected", e, c, ldexp(a.k[c], e), ref.k[c]);
        CHECKF(a.st == BS_OK && fabs(ldexp(a.d, -e) - ref.d) <= 1e-12 && fabs(ldexp(a.dl, -e) - ref.d) <= 1e-12,
               "2^%d: closest status %d, distances %g and %g, %g expected", e, a.st, ldexp(a.d, -e),
               ldexp(a.dl, -e), ref.d);
        CHECKF(a.id == 0 && fabs(ldexp(a.t, -e) - ref.t) <= 1e-12, "2^%d: ray patch %u t %g, %g expected", e,
               a.id, ldexp(a.t, -e), ref.t);
        double rn = fabs(a.rn[0] - ref.rn[0]) + fabs(a.rn[1] - ref.rn[1]) + fabs(a.rn[2] - ref.rn[2]);
        /* beyond 2^1000 from the scaled copy: the unit copy's bits */
        int bits = rn == 0.0 && a.uv[0] == ref.uv[0] && a.uv[1] == ref.uv[1];
        CHECKF(same_normal(&a) && a.rk == ref.rk && rn <= 1e-13 && (e <= 1000 || bits) &&
                   fabs(a.uv[0] - ref.uv[0]) + fabs(a.uv[1] - ref.uv[1]) <= 1e-12,
               "2^%d: ray hit normal kind %d (the patch's %d), off by %g, at (%.17g, %.17g), (%.17g, %.17g) "
               "expected", e, a.rk, a.pk, rn, a.uv[0], a.uv[1], ref.uv[0], ref.uv[1]);
        double off = fabs(ldexp(a.d, -e) - ref.d);
        if (off > worst) {
            worst = off;
            worst_e = e;
        }
        bs_patch_destroy(p);
    }
    printf("%s: scaled copies 2^-1000 .. 2^1020 agree (closest distances within %.2g, at 2^%d)\n",
           rational ? "rational" : "polynomial", worst, worst_e);
}

/* Two inputs of fuzz_locator, nets in units of 2^-7 with collapsed sides, and a point where the
 * curvature is a limit: a polynomial (2,4) net whose four sides are one point, at (0.644, 0) on a
 * side, and a (5,3) net (rational, weights 1) of two points A, B whose u = 0 and u = 1 sides are
 * one point, at (2^-19, 2^-19) next to a corner. Copies scaled by 2^-202 .. 2^-200 (the first)
 * and 2^-255 .. 2^-199 and 2^236 .. 2^256 (the second) gave BS_CURV_UNDEFINED: the partials of
 * their limit samples differ by 2^40 and more, and their products underflowed or overflowed. Every
 * copy 2^-1000 .. 2^1000 must give the unit copy's kind and limit, scaled. */
#define A 127, 127, 127
#define B 13, 13, 13
static const double sides4[15][3] = {
    {85, -81, -47},  {85, -81, -47},     {85, -81, -47},     {85, -81, -47},     {85, -81, -47},
    {85, -81, -47},  {-12, -127, -32},   {63, -105, -12},    {-127, 117, -67},   {85, -81, -47},
    {85, -81, -47},  {-128, -127, -125}, {-128, -127, -125}, {-128, -127, -125}, {85, -81, -47}};
static const double two_points[24][3] = {{A}, {A}, {A},           {A}, {A}, {A}, {127, 127, 13}, {B},
                                         {B}, {B}, {B},           {B}, {B}, {B}, {B},            {B},
                                         {B}, {13, 13, 127}, {A}, {A}, {127, 13, 13}, {127, 13, 13},
                                         {127, 13, 13}, {127, 13, 13}};
#undef A
#undef B

static void collapsed_limit(const double (*net)[3], size_t m, size_t n, int rational, double u, double v,
                            const char *what)
{
    double ref[4] = {0, 0, 0, 0}, ones[24] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
                                              1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    unsigned char ref_kind = 9;
    size_t np = (m + 1) * (n + 1);
    for (int e = 0; e >= -1000; e = e == 1000 ? -1 : e >= 0 ? e + 1 : e - 1) {
        double ctrl[72], k[4] = {0, 0, 0, 0};
        for (size_t i = 0; i < np; i++)
            for (size_t c = 0; c < 3; c++)
                ctrl[3 * i + c] = ldexp(net[i][c], e - 7);
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(m, n, 3, ctrl, rational ? ones : NULL, &p), BS_OK);
        unsigned char kind = 9;
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view kv[4] = {{&k[0], 1, 0}, {&k[1], 1, 0}, {&k[2], 1, 0}, {&k[3], 1, 0}};
        CHECK_STATUS(bs_patch_eval_curvature(p, 1, &cu, &cv, kv, NULL, NULL, &kind), BS_OK);
        bs_patch_destroy(p);
        if (e == 0) {
            CHECKF(kind == BS_CURV_LIMIT, "%s, unit copy: curvature kind %d", what, kind);
            ref_kind = kind;
            for (int c = 1; c < 4; c++)
                ref[c] = k[c];
            continue;
        }
        CHECKF(kind == ref_kind, "%s, 2^%d: curvature kind %d, %d at unit size", what, e, kind, ref_kind);
        for (int c = 1; c < 4 && kind == ref_kind; c++)
            CHECKF(fabs(ldexp(k[c], e) - ref[c]) <= 1e-6 * (fabs(ref[2]) + fabs(ref[3]) + 1.0),
                   "%s, 2^%d: curvature %d is %g, %g expected", what, e, c, ldexp(k[c], e), ref[c]);
    }
}

/* fuzz_locator's pole_weights_limit_normal: a rational (1,2) net in units of 2^-7 whose u = 0 side
 * is a pole, weights 2^-21 .. 2^4 */
static const double pole_net[6][4] = {{28, -78, 47, 0x1p-21},  {28, -78, 47, 0x1p-14}, {28, -78, 47, 0x1p-13},
                                      {127, 127, -124, 0x1p4}, {127, 0, 0, 0x1p-16},  {52, 47, 22, 0x1p-21}};

/* Normals at the pole (its corners and a point of it) and next to it: the same kinds and normals
 * at every scale 2^-1000 .. 2^1000 as at unit size. The limit normal at the pole was (0,0,0) "undefined" at 2^973 .. 2^1000, where the
 * general rule's partials (the weights' ratio times the net) overflowed. */
static void pole_weight_normals(void)
{
    static const double at[5][2] = {{0.0, 0.0}, {0.0, 1.0}, {0.0, 0.5}, {0x1p-20, 0.5}, {0x1p-40, 0x1p-40}};
    double ref[5][3] = {{0}}, ctrl[18], w[6];
    unsigned char ref_kind[5] = {9, 9, 9, 9, 9};
    for (int e = 0; e >= -1000; e = e == 1000 ? -1 : e >= 0 ? e + 1 : e - 1) {
        for (int k = 0; k < 6; k++) {
            for (int c = 0; c < 3; c++)
                ctrl[3 * k + c] = ldexp(pole_net[k][c], e - 7);
            w[k] = pole_net[k][3];
        }
        bs_patch *p = NULL;
        CHECK_STATUS(bs_patch_create(1, 2, 3, ctrl, w, &p), BS_OK);
        for (int q = 0; q < 5 && p != NULL; q++) {
            double u = at[q][0], v = at[q][1], x[3], n[3];
            unsigned char kind = 9;
            bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
            bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
            bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
            CHECK_STATUS(bs_patch_eval_normal(p, 1, &cu, &cv, xv, nv, &kind), BS_OK);
            if (e == 0) {
                CHECKF(kind != BS_NORMAL_UNDEFINED, "pole weights, unit size: no normal at (%g, %g)", u, v);
                ref_kind[q] = kind;
                for (int c = 0; c < 3; c++)
                    ref[q][c] = n[c];
                continue;
            }
            CHECKF(kind == ref_kind[q] && fabs(n[0] - ref[q][0]) + fabs(n[1] - ref[q][1]) + fabs(n[2] - ref[q][2]) <= 1e-9,
                   "pole weights, 2^%d, (%g, %g): kind %d normal (%g %g %g), at unit size %d (%g %g %g)", e, u, v,
                   kind, n[0], n[1], n[2], ref_kind[q], ref[q][0], ref[q][1], ref[q][2]);
        }
        bs_patch_destroy(p);
    }
}

/* Rays at a subnormal copy of the net (2^e, e from -1030 to -1060: 44 to 14 bits left) and at
 * that copy scaled back to unit size (exactly): the same patch, the same (u, v) and normal bit
 * for bit, t scaled to within the copy's last bits (rounded to them). A ray from 2^30 away hits
 * the subnormal copy too. */
static void subnormal(int rational)
{
    double ctrl[48], w[16], sc[48], unit[48];
    net(ctrl, w);
    for (int e = -1030; e >= -1060; e -= 15) {
        for (int k = 0; k < 48; k++) {
            sc[k] = ldexp(ctrl[k], e);
            unit[k] = ldexp(sc[k], -e);
        }
        bs_patch *p = NULL, *q = NULL;
        CHECK_STATUS(bs_patch_create(3, 3, 3, sc, rational ? w : NULL, &p), BS_OK);
        CHECK_STATUS(bs_patch_create(3, 3, 3, unit, rational ? w : NULL, &q), BS_OK);
        if (p == NULL || q == NULL)
            continue;
        /* down the unit copy's normal at (0.3, 0.7) from 0.5 above, the origin in the copy's bits */
        double u = 0.3, v = 0.7, x[3], n[3], o[3], ou[3], d[3];
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view xv[3] = {{&x[0], 1, 0}, {&x[1], 1, 0}, {&x[2], 1, 0}};
        bs_view nv[3] = {{&n[0], 1, 0}, {&n[1], 1, 0}, {&n[2], 1, 0}};
        CHECK_STATUS(bs_patch_eval_normal(q, 1, &cu, &cv, xv, nv, NULL), BS_OK);
        for (int c = 0; c < 3; c++) {
            o[c] = ldexp(x[c] + 0.5 * n[c], e);
            ou[c] = ldexp(o[c], -e);
            d[c] = -n[c];
        }
        answers a, b;
        bs_locator *L = shape_locator(p), *M = shape_locator(q);
        ray(L, p, o, d, &a);
        ray(M, q, ou, d, &b);
        double quantum = ldexp(1.0, -1074 - e); /* the copy's last bit, at unit size */
        double rn = fabs(a.rn[0] - b.rn[0]) + fabs(a.rn[1] - b.rn[1]) + fabs(a.rn[2] - b.rn[2]);
        CHECKF(a.id == 0 && b.id == 0 && fabs(ldexp(a.t, -e) - b.t) <= 2 * quantum && same_normal(&a) &&
                   a.rk == b.rk && rn == 0.0 && a.uv[0] == b.uv[0] && a.uv[1] == b.uv[1],
               "2^%d: patch %u t %.17g (u,v) (%.17g, %.17g) normal off by %g; unit copy: patch %u t %.17g "
               "(u,v) (%.17g, %.17g)", e, a.id, ldexp(a.t, -e), a.uv[0], a.uv[1], rn, b.id, b.t, b.uv[0], b.uv[1]);
        for (int c = 0; c < 3; c++)
            o[c] = 0x1p30 * n[c];
        ray(L, p, o, d, &a);
        bs_locator_destroy(L);
        bs_locator_destroy(M);
        CHECKF(a.id == 0 && fabs(a.t - 0x1p30) <= 0x1p-20 && same_normal(&a), "2^%d from 2^30: patch %u t %.17g",
               e, a.id, a.t);
        bs_patch_destroy(p);
        bs_patch_destroy(q);
    }
}

/* The hostile boxes: a relative tolerance gives the unit box's triangles and normals. */
static void boxes(void)
{
    const char *names[4] = {"unit_box.bpt", "huge_box.bpt", "tiny_box.bpt", "subnormal_box.bpt"};
    size_t ntri0 = 0;
    double n0[3] = {0, 0, 0};
    for (int k = 0; k < 4; k++) {
        char path[512];
        (void)snprintf(path, sizeof path, "%s/%s", BS_HOSTILE_DIR, names[k]);
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_read_bpt_file(path, NULL, &s), BS_OK);
        if (s == NULL)
            continue;
        bs_tess_options o;
        bs_tess_options_init(&o);
        o.method = BS_TESS_PER_PATCH;
        o.flags = BS_TESS_RELATIVE;
        bs_mesh *m = NULL;
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
        size_t nt = bs_mesh_triangle_count(m), nv = bs_mesh_vertex_count(m);
        double *nrm = malloc(3 * (nv ? nv : 1) * sizeof(double));
        bs_view nvw[3] = {{nrm, nv, 3 * sizeof(double)}, {nrm + 1, nv, 3 * sizeof(double)}, {nrm + 2, nv, 3 * sizeof(double)}};
        CHECK_STATUS(bs_mesh_copy_normals(m, nvw), BS_OK);
        if (k == 0) {
            ntri0 = nt;
            for (int c = 0; c < 3; c++)
                n0[c] = nrm[c];
        }
        CHECKF(nt == ntri0 && nt > 2, "%s: %zu triangles, the unit box %zu", names[k], nt, ntri0);
        CHECKF(fabs(nrm[0] - n0[0]) + fabs(nrm[1] - n0[1]) + fabs(nrm[2] - n0[2]) <= 1e-12,
               "%s: first normal (%g %g %g), the unit box's (%g %g %g)", names[k], nrm[0], nrm[1], nrm[2],
               n0[0], n0[1], n0[2]);
        free(nrm);
        bs_mesh_destroy(m);
        bs_surface_destroy(s);
    }
}

int main(void)
{
    copies(0);
    copies(1);
    collapsed_limit(sides4, 2, 4, 0, 0x1.49539e3b2d067p-1, 0.0, "four sides one point");
    collapsed_limit(two_points, 5, 3, 1, 0x1p-19, 0x1p-19, "two points, two poles");
    pole_weight_normals();
    subnormal(0);
    subnormal(1);
    boxes();
    return bs_test_exit("test_scale");
}
