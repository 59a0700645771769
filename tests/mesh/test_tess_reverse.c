/* BS_TESS_REVERSE: the mesh of every method (uniform, per patch, subdivision; strips or not) faced
 * the other way: the same vertices, parameters and ids, normals negated, each triangle (a, b, c)
 * as (a, c, b) with its corners' own (u,v), strips whose non-degenerate triangles are the reversed
 * list; the teapot's patches face into the pot (negative signed volume) and its reversed meshes
 * outwards (positive), the teacup's and the teaspoon's the other way round; flags beyond the known
 * ones refused. */
#include "harness.h"
#include "mesh_data.h"

#include <math.h>
#include <string.h>

typedef struct tri3 { uint32_t a, b, c; } tri3;

static int cmp_tri(const void *x, const void *y)
{
    const tri3 *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    if (p->c != q->c) return p->c < q->c ? -1 : 1;
    return 0;
}

static tri3 canonical(uint32_t x, uint32_t y, uint32_t z)
{
    while (x > y || x > z) { uint32_t w = x; x = y; y = z; z = w; }
    tri3 t = {x, y, z};
    return t;
}

/* The non-degenerate triangles of the strips are the triangle list, winding included. */
static int strips_are_list(const mesh_data *d)
{
    tri3 *a = xmalloc(d->nt * sizeof(tri3)), *b = xmalloc(d->nsi * sizeof(tri3));
    size_t nb = 0;
    for (size_t t = 0; t < d->nt; t++)
        a[t] = canonical(d->tri[3 * t], d->tri[3 * t + 1], d->tri[3 * t + 2]);
    for (size_t k = 0; k < d->ns; k++)
        for (uint32_t i = d->sstart[k]; i + 2 < d->sstart[k + 1]; i++) {
            uint32_t x = d->sidx[i], y = d->sidx[i + 1], z = d->sidx[i + 2];
            if ((i - d->sstart[k]) % 2) { uint32_t w = x; x = y; y = w; }
            if (x != y && y != z && x != z)
                b[nb++] = canonical(x, y, z);
        }
    int same = nb == d->nt && d->sstart[0] == 0 && d->sstart[d->ns] == d->nsi;
    qsort(a, d->nt, sizeof(tri3), cmp_tri);
    qsort(b, nb, sizeof(tri3), cmp_tri);
    for (size_t i = 0; same && i < nb; i++)
        same = cmp_tri(&a[i], &b[i]) == 0;
    free(a);
    free(b);
    return same;
}

/* Signed volume enclosed by the triangles (divergence theorem): positive when they face outwards. */
static double signed_volume(const mesh_data *d)
{
    double v = 0.0;
    for (size_t t = 0; t < d->nt; t++) {
        const double *p = d->pos + 3 * d->tri[3 * t], *q = d->pos + 3 * d->tri[3 * t + 1],
                     *r = d->pos + 3 * d->tri[3 * t + 2];
        v += p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
             p[2] * (q[0] * r[1] - q[1] * r[0]);
    }
    return v / 6.0;
}

/* Mesh of s with the options, plain and reversed, compared. Returns the plain mesh's volume and
 * sets *rvol to the reversed one's. */
static double compare(const bs_surface *s, bs_tess_options *o, const char *what, double *rvol)
{
    bs_mesh *m = NULL, *r = NULL;
    CHECK_STATUS(bs_surface_tessellate(s, o, &m), BS_OK);
    o->flags |= BS_TESS_REVERSE;
    CHECK_STATUS(bs_surface_tessellate(s, o, &r), BS_OK);
    size_t nv = 0, nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, o, &nv, &nt), BS_OK);
    o->flags &= ~BS_TESS_REVERSE;
    mesh_data a, b;
    read_mesh(m, &a);
    read_mesh(r, &b);
    CHECKF(a.nv == b.nv && a.nt == b.nt && a.ns == b.ns && nv == b.nv && nt == b.nt, "%s: counts", what);
    if (a.nv == b.nv && a.nt == b.nt && a.ns == b.ns) {
        CHECKF(same_bytes(a.pos, b.pos, 3 * a.nv * sizeof(double)) &&
               same_bytes(a.uv, b.uv, 2 * a.nv * sizeof(double)) &&
               same_bytes(a.vpatch, b.vpatch, a.nv * sizeof(uint32_t)) &&
               same_bytes(a.tpatch, b.tpatch, a.nt * sizeof(uint32_t)), "%s: vertices or ids differ", what);
        size_t bad = 0;
        for (size_t k = 0; k < 3 * a.nv; k++)
            bad += b.nrm[k] != -a.nrm[k];
        CHECKF(bad == 0, "%s: %zu normal coordinates not negated", what, bad);
        bad = 0;
        for (size_t t = 0; t < a.nt; t++) {
            static const int perm[3] = {0, 2, 1};
            for (int c = 0; c < 3; c++) {
                size_t i = 3 * t + (size_t)c, j = 3 * t + (size_t)perm[c];
                bad += b.tri[i] != a.tri[j] || b.cuv[2 * i] != a.cuv[2 * j] || b.cuv[2 * i + 1] != a.cuv[2 * j + 1];
            }
        }
        CHECKF(bad == 0, "%s: %zu triangle corners not reversed", what, bad);
        CHECKF(b.ns == 0 || strips_are_list(&b), "%s: the reversed strips are not the reversed triangles", what);
    }
    double v = signed_volume(&a);
    *rvol = signed_volume(&b);
    free_mesh(&a);
    free_mesh(&b);
    bs_mesh_destroy(m);
    bs_mesh_destroy(r);
    return v;
}

static void tea_set(void)
{
    static const char *names[] = {"teapot", "teacup", "teaspoon"};
    for (size_t k = 0; k < 3; k++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create_builtin(names[k], &s), BS_OK);
        for (int method = BS_TESS_UNIFORM; method <= BS_TESS_SUBDIVIDE; method++)
            for (int flags = 0; flags <= BS_TESS_STRIPS; flags += BS_TESS_STRIPS) {
                bs_tess_options o;
                bs_tess_options_init(&o);
                o.method = method;
                o.nu = o.nv = 5;
                o.tolerance = 0.01;
                o.flags = flags;
                char what[64];
                snprintf(what, sizeof what, "%s method %d flags %d", names[k], method, flags);
                double rv = 0.0, v = compare(s, &o, what, &rv);
                CHECKF(fabs(rv + v) <= 1e-9 * fabs(v), "%s: volumes %g and %g", what, v, rv);
                /* the teapot's patches face inwards (about -25.9 plain), the cup's and the spoon's
                 * outwards */
                if (k == 0)
                    CHECKF(v < -25.0 && rv > 25.0, "%s: volume %g plain, %g reversed", what, v, rv);
                else
                    CHECKF(v > 0.0 && rv < 0.0, "%s: volume %g plain, %g reversed", what, v, rv);
            }
        bs_surface_destroy(s);
    }
}

static void flags(void)
{
    bs_surface *s = NULL;
    bs_mesh *m = NULL, *r = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teacup", &s), BS_OK);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 3, 4, BS_TESS_REVERSE | BS_TESS_STRIPS, &m), BS_OK);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.nu = 3;
    o.nv = 4;
    o.flags = BS_TESS_REVERSE | BS_TESS_STRIPS;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &r), BS_OK);
    CHECK(m != NULL && r != NULL && same_mesh(m, r));
    bs_mesh_destroy(m);
    bs_mesh_destroy(r);
    CHECK_STATUS(bs_surface_tessellate_adaptive(s, 0.01, BS_TESS_REVERSE, &m), BS_OK);
    CHECK(m != NULL && bs_mesh_triangle_count(m) > 0);
    bs_mesh_destroy(m);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 3, 4, 8, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    o.flags = BS_TESS_REVERSE << 1;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_INVALID_ARG);
    /* an empty surface reversed is an empty mesh */
    bs_surface *e = NULL;
    CHECK_STATUS(bs_surface_create(&e), BS_OK);
    o.flags = BS_TESS_REVERSE | BS_TESS_STRIPS;
    CHECK_STATUS(bs_surface_tessellate(e, &o, &m), BS_OK);
    CHECK(m != NULL && bs_mesh_triangle_count(m) == 0 && bs_mesh_strip_count(m) == 0);
    bs_mesh_destroy(m);
    bs_surface_destroy(e);
    bs_surface_destroy(s);
}

int main(void)
{
    tea_set();
    flags();
    return bs_test_exit("test_tess_reverse");
}
