/*
 * Subdivision phase 1: each patch cut recursively into sub-patches until every leaf is flat enough.
 *
 * The bound. For a polynomial sub-patch of degree (m, n) with net Q over its own unit square,
 * |S_uu| <= m(m-1) max|D2u Q|, |S_uv| <= mn max|DuDv Q|, |S_vv| <= n(n-1) max|D2v Q| (convex hull
 * of the derivative nets). For a triangle whose corners p_k lie on the sub-patch (surface points at
 * (u_k, v_k) in the leaf's rectangle) and a point with barycentric weights l_k, Taylor's theorem
 * at the point's (u,v) = x gives |S(x) - sum l_k S(p_k)| <= 1/2 sum l_k (Muu du_k^2 +
 * 2 Muv |du_k dv_k| + Mvv dv_k^2), du_k = u_k - x_u; sum l_k du_k^2 is a variance of values in an
 * interval of length 1, so at most 1/4, and by Cauchy-Schwarz sum l_k |du_k dv_k| <= 1/4. Hence
 * every such triangle errs by at most eu + euv + ev with eu = Muu/8, euv = Muv/4, ev = Mvv/8, and
 * after splitting the leaf into fu x fv equal parts by eu/fu^2 + euv/(fu fv) + ev/fv^2. This holds
 * whatever the triangulation of a leaf, so leaves can be fanned to finer neighbours freely.
 * Rational patches: the same terms from the projected net, scaled by the ratio of the largest to
 * the smallest weight of the sub-patch; an estimate, not a bound (the ratio tends to 1 as leaves
 * shrink).
 *
 * The split. A node that fails the tolerance looks for the cheapest total split (fu, fv), products
 * of 2s and 3s, fewest leaves, that would meet it if its children were no flatter than itself,
 * and takes the first step of it: a half or a third in u, in v, or both (anisotropic where one
 * direction is flat). The children, usually flatter, decide again. The total split of a direction
 * is capped at BS_TESS_MAX_RATE, where the tolerance may then not be met.
 */
#include "mesh/subdiv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Products of 2s and 3s up to BS_TESS_MAX_RATE: the total splits a direction can take. */
static const uint32_t smooth[] = {1,   2,   3,   4,   6,   8,   9,   12,  16,  18,  24,  27,  32,  36,
                                  48,  54,  64,  72,  81,  96,  108, 128, 144, 162, 192, 216, 243, 256,
                                  288, 324, 384, 432, 486, 512, 576, 648, 729, 768, 864, 972, 1024};
#define NSMOOTH (sizeof smooth / sizeof smooth[0])
/* Each level splits a direction by at least 2, at most 10 times per direction. */
#define MAX_LEVELS 22
/* Nets per level: the strips of a split along u, then the children of one strip along v. */
#define LEVEL_NETS 6

typedef struct tree {
    subdiv *s;
    size_t m, n, hd;  /* degrees; homogeneous dimension: 3, or 4 when rational (w x, w y, w z, w) */
    size_t netsz;     /* doubles per net */
    int rational;
    double *nets;     /* LEVEL_NETS per level, then the root's */
    double *pts;      /* the projected net of a rational node */
    double *sq;       /* squared coordinate differences of one row of a net */
    unsigned char collapsed[4]; /* the patch's sides that are poles */
} tree;

/* Cut the curve of deg + 1 points (hd doubles each, `stride` doubles apart) at t by de Casteljau:
 * the part over [0, t] into l, the part over [t, 1] in place of r. */
static void cut_curve(double *r, double *l, size_t deg, size_t stride, size_t hd, double t)
{
    for (size_t k = 0; k < hd; k++)
        l[k] = r[k];
    for (size_t rnd = 1; rnd <= deg; rnd++) {
        for (size_t i = 0; i + rnd <= deg; i++)
            for (size_t k = 0; k < hd; k++)
                r[i * stride + k] = (1.0 - t) * r[i * stride + k] + t * r[(i + 1) * stride + k];
        for (size_t k = 0; k < hd; k++)
            l[rnd * stride + k] = r[k];
    }
}

/* The `parts` equal parts of net src along u (along_u) or v into dst[0 .. parts). */
static void split_net(const tree *tr, const double *src, double *const *dst, uint32_t parts, int along_u)
{
    size_t m = tr->m, n = tr->n, hd = tr->hd;
    double *rest = dst[parts - 1];
    memcpy(rest, src, tr->netsz * sizeof(double));
    for (uint32_t a = 0; a + 1 < parts; a++) {
        double t = 1.0 / (double)(parts - a); /* of what is left */
        if (along_u)
            for (size_t j = 0; j <= n; j++)
                cut_curve(rest + j * hd, dst[a] + j * hd, m, (n + 1) * hd, hd, t);
        else
            for (size_t i = 0; i <= m; i++)
                cut_curve(rest + i * (n + 1) * hd, dst[a] + i * (n + 1) * hd, n, hd, hd, t);
    }
}

/* Largest sum of squares of the first `count` triples of sq, or at least `mx`. */
static double row_max(const double *sq, size_t count, double mx)
{
    for (size_t j = 0; j < count; j++) {
        double q = sq[3 * j] + sq[3 * j + 1] + sq[3 * j + 2];
        mx = q > mx ? q : mx;
    }
    return mx;
}

/* Error terms e = (eu, euv, ev) of a net (see the top of this file). */
static void bound_terms(const tree *tr, const double *net, double e[3])
{
    size_t m = tr->m, n = tr->n, hd = tr->hd, w = n + 1;
    const double *x = net;
    double scale = 1.0;
    if (tr->rational) {
        double *pts = tr->pts;
        double wlo = INFINITY, whi = 0.0;
        for (size_t k = 0; k < (m + 1) * w; k++) {
            const double *h = net + k * hd;
            pts[3 * k] = h[0] / h[3];
            pts[3 * k + 1] = h[1] / h[3];
            pts[3 * k + 2] = h[2] / h[3];
            wlo = h[3] < wlo ? h[3] : wlo;
            whi = h[3] > whi ? h[3] : whi;
        }
        scale = whi / wlo;
        x = pts;
    }
    /* squared lengths of the second differences, row by row of the flattened net (L doubles) */
    size_t L = 3 * w;
    double a = 0.0, b = 0.0, c = 0.0, *sq = tr->sq;
    for (size_t i = 0; i + 2 <= m; i++) {
        const double *r0 = x + i * L, *r1 = r0 + L, *r2 = r1 + L;
        for (size_t k = 0; k < L; k++) {
            double d = r2[k] - 2.0 * r1[k] + r0[k];
            sq[k] = d * d;
        }
        a = row_max(sq, w, a);
    }
    for (size_t i = 0; i <= m; i++) {
        const double *r0 = x + i * L;
        for (size_t k = 0; k + 6 < L; k++) {
            double d = r0[k + 6] - 2.0 * r0[k + 3] + r0[k];
            sq[k] = d * d;
        }
        if (n >= 2)
            c = row_max(sq, n - 1, c);
    }
    for (size_t i = 0; i + 1 <= m; i++) {
        const double *r0 = x + i * L, *r1 = r0 + L;
        for (size_t k = 0; k + 3 < L; k++) {
            double d = r1[k + 3] - r1[k] - r0[k + 3] + r0[k];
            sq[k] = d * d;
        }
        if (n >= 1)
            b = row_max(sq, n, b);
    }
    e[0] = scale * (double)(m * (m ? m - 1 : 0)) * sqrt(a) / 8.0;
    e[1] = scale * (double)(m * n) * sqrt(b) / 4.0;
    e[2] = scale * (double)(n * (n ? n - 1 : 0)) * sqrt(c) / 8.0;
}

static double split_error(const double e[3], double fu, double fv)
{
    return e[0] / (fu * fu) + e[1] / (fu * fv) + e[2] / (fv * fv);
}

/* Smallest factor at least x, or 0 when above the table. */
static uint32_t smooth_at_least(double x)
{
    for (size_t k = 0; k < NSMOOTH; k++)
        if ((double)smooth[k] >= x)
            return smooth[k];
    return 0;
}

/* The cheapest total split (fu <= fumax, fv <= fvmax) meeting tol, 0 x 0 when there is none. */
static void cheapest_split(const double e[3], double tol, uint32_t fumax, uint32_t fvmax, uint32_t *bu, uint32_t *bv)
{
    double best = INFINITY, best_err = INFINITY;
    *bu = *bv = 0;
    for (size_t k = 0; k < NSMOOTH && smooth[k] <= fumax && (double)smooth[k] < best; k++) {
        double fu = smooth[k], rem = tol - e[0] / (fu * fu), lin = e[1] / fu;
        if (!(rem > 0.0))
            continue;
        /* smallest fv with e2 / fv^2 + lin / fv <= rem: x = 1 / fv solves e2 x^2 + lin x = rem */
        double x = e[2] > 0.0 ? (-lin + sqrt(lin * lin + 4.0 * e[2] * rem)) / (2.0 * e[2])
                              : lin > 0.0 ? rem / lin : INFINITY;
        uint32_t fv = smooth_at_least(x > 0.0 ? 1.0 / x : INFINITY);
        while (fv != 0 && fv <= fvmax && split_error(e, fu, fv) > tol)
            fv = smooth_at_least((double)fv + 1.0);
        if (fv == 0 || fv > fvmax)
            continue;
        double cost = fu * (double)fv, err = split_error(e, fu, fv);
        if (cost < best || (cost == best && err < best_err)) {
            best = cost;
            best_err = err;
            *bu = smooth[k];
            *bv = fv;
        }
    }
}

/* First step of a total split f: a half when f is even, else a third. */
static uint32_t first_step(uint32_t f) { return f <= 1 ? 1 : f % 2 == 0 ? 2 : 3; }

/* Keep the leaf. A leaf that touches no collapsed side and does not span its patch has four
 * distinct corner vertices, so it gives at least two triangles; leaves have distinct corners
 * (u0,v0), each one vertex when inside the patch. Those bound the counts from below, and budgets
 * are refused while the trees are still small. */
static bs_status add_leaf(tree *tr, uint32_t u0, uint32_t u1, uint32_t v0, uint32_t v1)
{
    subdiv *s = tr->s;
    if (s->nleaf == s->leaf_cap) {
        if (s->leaf_cap >= UINT32_MAX / 2)
            return BS_ERR_SIZE;
        size_t cap = s->leaf_cap ? 2 * s->leaf_cap : 1024;
        sd_leaf *nl = realloc(s->leaf, cap * sizeof(sd_leaf));
        if (nl == NULL)
            return BS_ERR_NO_MEMORY;
        s->leaf = nl;
        s->leaf_cap = cap;
    }
    sd_leaf l = {u0, u1, v0, v1};
    s->leaf[s->nleaf++] = l;
    const unsigned char *c = tr->collapsed;
    int pole = (c[BSI_SIDE_V0] && v0 == 0) || (c[BSI_SIDE_U1] && u1 == SD_N) || (c[BSI_SIDE_V1] && v1 == SD_N) ||
               (c[BSI_SIDE_U0] && u0 == 0);
    if (!pole && (u0 != 0 || u1 != SD_N) && (v0 != 0 || v1 != SD_N))
        s->tri_lower += 2;
    s->vert_lower += u0 != 0 && v0 != 0; /* a point inside a patch is welded to nothing */
    int over = (s->max_tri != 0 && s->tri_lower > s->max_tri) || (s->max_vert != 0 && s->vert_lower > s->max_vert);
    return over ? BS_ERR_SIZE : BS_OK;
}

/* The node over [u0,u1] x [v0,v1] with net `net`: a leaf, or split and its children visited. */
static bs_status node(tree *tr, size_t level, const double *net, uint32_t u0, uint32_t u1, uint32_t v0, uint32_t v1)
{
    double e[3];
    bound_terms(tr, net, e);
    uint32_t fumax = BS_TESS_MAX_RATE / (SD_N / (u1 - u0)), fvmax = BS_TESS_MAX_RATE / (SD_N / (v1 - v0));
    uint32_t su = 1, sv = 1, bu = 1, bv = 1;
    if (split_error(e, 1.0, 1.0) > tr->s->tol && level + 1 < MAX_LEVELS) {
        cheapest_split(e, tr->s->tol, fumax, fvmax, &bu, &bv);
        if (bu == 0) { /* the cap: split what is left where the curvature is */
            bu = e[0] + e[1] > 0.0 ? fumax : 1;
            bv = e[2] + e[1] > 0.0 ? fvmax : 1;
        }
        su = first_step(bu);
        sv = first_step(bv);
    }
    if (su == 1 && sv == 1)
        return add_leaf(tr, u0, u1, v0, v1);
    double *buf = tr->nets + level * LEVEL_NETS * tr->netsz;
    double *strip[3] = {buf, buf + tr->netsz, buf + 2 * tr->netsz};
    double *kid[3] = {buf + 3 * tr->netsz, buf + 4 * tr->netsz, buf + 5 * tr->netsz};
    uint32_t wu = (u1 - u0) / su, wv = (v1 - v0) / sv;
    if (!tr->rational && su == bu && sv == bv && split_error(e, su, sv) <= tr->s->tol) {
        /* The children are leaves: their nets' differences are convex combinations of this net's
         * scaled by 1/su, 1/sv per order, so their terms are at most eu/su^2, euv/(su sv), ev/sv^2. */
        for (uint32_t a = 0; a < su; a++)
            for (uint32_t b = 0; b < sv; b++) {
                bs_status st = add_leaf(tr, u0 + a * wu, u0 + (a + 1) * wu, v0 + b * wv, v0 + (b + 1) * wv);
                if (st != BS_OK)
                    return st;
            }
        return BS_OK;
    }
    split_net(tr, net, strip, su, 1);
    for (uint32_t a = 0; a < su; a++) {
        split_net(tr, strip[a], kid, sv, 0);
        for (uint32_t b = 0; b < sv; b++) {
            bs_status st = node(tr, level + 1, kid[b], u0 + a * wu, u0 + (a + 1) * wu, v0 + b * wv, v0 + (b + 1) * wv);
            if (st != BS_OK)
                return st;
        }
    }
    return BS_OK;
}

bs_status bsi_subdiv_trees(subdiv *s)
{
    s->leaf0 = malloc((s->np + 1) * sizeof(size_t));
    if (s->leaf0 == NULL)
        return BS_ERR_NO_MEMORY;
    bs_status st = BS_OK;
    for (size_t p = 0; p < s->np && st == BS_OK; p++) {
        const bs_patch *patch = bs_surface_get(s->s, p);
        tree tr = {s, patch->deg_u, patch->deg_v, patch->rational ? 4u : 3u, 0, patch->rational, NULL, NULL, NULL, {0, 0, 0, 0}};
        for (int side = 0; side < 4; side++)
            tr.collapsed[side] = s->topo.links[4 * p + (size_t)side].collapsed;
        tr.netsz = (tr.m + 1) * (tr.n + 1) * tr.hd;
        tr.nets = malloc((LEVEL_NETS * MAX_LEVELS + 3) * tr.netsz * sizeof(double));
        if (tr.nets == NULL)
            return BS_ERR_NO_MEMORY;
        double *root = tr.nets + (size_t)LEVEL_NETS * MAX_LEVELS * tr.netsz;
        tr.pts = root + tr.netsz;
        tr.sq = tr.pts + tr.netsz;
        for (size_t k = 0; k < patch->nctrl; k++) {
            double w = patch->rational ? patch->weights[k] : 1.0;
            for (size_t c = 0; c < 3; c++)
                root[k * tr.hd + c] = w * patch->ctrl[3 * k + c];
            if (patch->rational)
                root[k * tr.hd + 3] = w;
        }
        s->leaf0[p] = s->nleaf;
        st = node(&tr, 0, root, 0, SD_N, 0, SD_N);
        free(tr.nets);
    }
    s->leaf0[s->np] = s->nleaf;
    return st;
}
