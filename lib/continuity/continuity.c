/* Continuity across the shared edges of a surface, on top of the topology (lib/surface/topology.c). */
#include "surface/internal.h"

#include <math.h>
#include <stdlib.h>

#define MAX_SAMPLES 4096

static size_t edge_degree(const bs_patch *p, int side)
{
    return (side == BSI_SIDE_V0 || side == BSI_SIDE_V1) ? p->deg_u : p->deg_v;
}

static size_t cross_degree(const bs_patch *p, int side)
{
    return (side == BSI_SIDE_V0 || side == BSI_SIDE_V1) ? p->deg_v : p->deg_u;
}

/* Packed index of control point k along a side, `depth` rows in from it. */
static size_t net_index(const bs_patch *p, int side, size_t k, size_t depth)
{
    size_t m = p->deg_u, n = p->deg_v;
    switch (side) {
    case BSI_SIDE_V0: return k * (n + 1) + depth;
    case BSI_SIDE_U1: return (m - depth) * (n + 1) + k;
    case BSI_SIDE_V1: return k * (n + 1) + (n - depth);
    default:          return depth * (n + 1) + k;
    }
}

/* (u, v) of the point at edge parameter t on a side. */
static void side_param(int side, double t, double *u, double *v)
{
    switch (side) {
    case BSI_SIDE_V0: *u = t;   *v = 0.0; break;
    case BSI_SIDE_U1: *u = 1.0; *v = t;   break;
    case BSI_SIDE_V1: *u = t;   *v = 1.0; break;
    default:          *u = 0.0; *v = t;   break;
    }
}

/* Outward cross-boundary derivative control point k: deg * (boundary - next row inward). */
static void outward(const bs_patch *p, int side, size_t k, double d[3])
{
    size_t deg = cross_degree(p, side);
    const double *b = p->ctrl + 3 * net_index(p, side, k, 0);
    const double *in = deg > 0 ? p->ctrl + 3 * net_index(p, side, k, 1) : b;
    for (int c = 0; c < 3; c++)
        d[c] = (double)deg * (b[c] - in[c]);
}

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* Scratch for the normal samples of both sides: u, v, normals (3 planes) and kinds, per side. */
typedef struct samples_buf {
    double *uv;          /* 4 * ns: ua, va, ub, vb */
    double *nrm;         /* 6 * ns: na (3 planes), nb (3 planes) */
    unsigned char *kind; /* 2 * ns */
} samples_buf;

static bs_status normals_on_side(const bs_patch *p, int side, int rev, size_t ns, double *u, double *v,
                                 double *nrm, unsigned char *kind)
{
    for (size_t k = 0; k < ns; k++) {
        double t = ((double)k + 0.5) / (double)ns;
        side_param(side, rev ? 1.0 - t : t, &u[k], &v[k]);
    }
    bs_cview cu = {u, ns, 0}, cv = {v, ns, 0};
    bs_view n3[3] = {{nrm, ns, 0}, {nrm + ns, ns, 0}, {nrm + 2 * ns, ns, 0}};
    return bs_patch_eval_normal(p, ns, &cu, &cv, NULL, n3, kind);
}

static bs_status measure_edge(const bs_surface *s, uint32_t ia, int sa, const bsi_side_link *l, double tol,
                              size_t ns, samples_buf *buf, bs_edge_continuity *e)
{
    const bs_patch *a = bs_surface_get(s, ia), *b = bs_surface_get(s, l->patch);
    int sb = l->side, rev = l->reversed;
    e->patch_a = ia;
    e->patch_b = l->patch;
    e->side_a = sa;
    e->side_b = sb;
    e->reversed = rev;

    size_t d = edge_degree(a, sa);
    int rational = a->rational || b->rational;
    double gap = 0.0, defect = 0.0;
    for (size_t k = 0; k <= d; k++) {
        size_t kb = rev ? d - k : k;
        const double *pa = a->ctrl + 3 * net_index(a, sa, k, 0), *pb = b->ctrl + 3 * net_index(b, sb, kb, 0);
        double diff[3] = {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
        gap = fmax(gap, norm3(diff));
        if (!rational) {
            double da[3], db[3];
            outward(a, sa, k, da);
            outward(b, sb, kb, db);
            double sum[3] = {da[0] + db[0], da[1] + db[1], da[2] + db[2]};
            defect = fmax(defect, norm3(sum));
        }
    }
    e->c0_gap = gap;
    e->c1_defect = rational ? NAN : defect;
    e->c1 = !rational && defect <= tol;

    double *na = buf->nrm, *nb = buf->nrm + 3 * ns;
    unsigned char *ka = buf->kind, *kb = buf->kind + ns;
    bs_status st = normals_on_side(a, sa, 0, ns, buf->uv, buf->uv + ns, na, ka);
    if (st == BS_OK)
        st = normals_on_side(b, sb, rev, ns, buf->uv + 2 * ns, buf->uv + 3 * ns, nb, kb);
    if (st != BS_OK)
        return st;
    double worst = 0.0;
    size_t used = 0, opposite = 0;
    for (size_t k = 0; k < ns; k++) {
        if (ka[k] == BS_NORMAL_UNDEFINED || kb[k] == BS_NORMAL_UNDEFINED)
            continue;
        double x[3] = {na[k], na[ns + k], na[2 * ns + k]}, y[3] = {nb[k], nb[ns + k], nb[2 * ns + k]};
        double dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        double cr[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
        /* atan2 keeps small angles accurate where acos(dot) would not. */
        worst = fmax(worst, atan2(norm3(cr), fabs(dot)));
        used++;
        opposite += dot < 0.0;
    }
    e->g1_angle = worst;
    e->samples = (int)used;
    e->flipped = 2 * opposite > used;
    return BS_OK;
}

/* 1 if side `side` of patch i is the first-named end of its shared edge. */
static int first_of_pair(size_t i, int side, const bsi_side_link *l)
{
    return l->patch != BSI_NO_PATCH && (l->patch > i || (l->patch == i && l->side > side));
}

bs_status bs_surface_continuity(const bs_surface *s, double tol, size_t samples, bs_edge_continuity *edges,
                                size_t edges_cap, size_t *n_edges, bs_open_edge *open, size_t open_cap,
                                size_t *n_open)
{
    if (s == NULL)
        return BS_ERR_INVALID_ARG;
    size_t np = bs_surface_count(s);
    if (np > 0 && bs_surface_dim(s) != 3)
        return BS_ERR_DIMENSION;
    if (!(tol >= 0.0) || !isfinite(tol) || samples == 0 || samples > MAX_SAMPLES)
        return BS_ERR_DOMAIN;
    bsi_topology topo;
    bs_status st = bsi_topology_build(s, tol, &topo);
    if (st != BS_OK)
        return st;
    size_t ne = 0, no = 0;
    for (size_t i = 0; i < np; i++)
        for (int side = 0; side < 4; side++) {
            const bsi_side_link *l = &topo.links[4 * i + (size_t)side];
            ne += (size_t)first_of_pair(i, side, l);
            no += l->patch == BSI_NO_PATCH && !l->collapsed;
        }
    if ((edges != NULL && edges_cap < ne) || (open != NULL && open_cap < no)) {
        bsi_topology_free(&topo);
        return BS_ERR_SIZE;
    }
    samples_buf buf = {NULL, NULL, NULL};
    if (edges != NULL && ne > 0) {
        buf.uv = malloc(4 * samples * sizeof(double));
        buf.nrm = malloc(6 * samples * sizeof(double));
        buf.kind = malloc(2 * samples);
        if (buf.uv == NULL || buf.nrm == NULL || buf.kind == NULL)
            st = BS_ERR_NO_MEMORY;
    }
    /* Measure into scratch first so that a failure leaves the caller's arrays untouched. */
    bs_edge_continuity *tmp = NULL;
    if (st == BS_OK && edges != NULL && ne > 0 && (tmp = malloc(ne * sizeof(*tmp))) == NULL)
        st = BS_ERR_NO_MEMORY;
    size_t ke = 0;
    for (size_t i = 0; st == BS_OK && tmp != NULL && i < np; i++)
        for (int side = 0; st == BS_OK && side < 4; side++) {
            const bsi_side_link *l = &topo.links[4 * i + (size_t)side];
            if (first_of_pair(i, side, l))
                st = measure_edge(s, (uint32_t)i, side, l, tol, samples, &buf, &tmp[ke++]);
        }
    if (st == BS_OK) {
        for (size_t k = 0; k < ke; k++)
            edges[k] = tmp[k];
        size_t ko = 0;
        for (size_t i = 0; open != NULL && i < np; i++)
            for (int side = 0; side < 4; side++) {
                const bsi_side_link *l = &topo.links[4 * i + (size_t)side];
                if (l->patch == BSI_NO_PATCH && !l->collapsed) {
                    open[ko].patch = (uint32_t)i;
                    open[ko].side = side;
                    ko++;
                }
            }
        if (n_edges != NULL)
            *n_edges = ne;
        if (n_open != NULL)
            *n_open = no;
    }
    free(tmp);
    free(buf.uv);
    free(buf.nrm);
    free(buf.kind);
    bsi_topology_free(&topo);
    return st;
}
