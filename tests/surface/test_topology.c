/* Internal topology (lib/topology.c): shared, open and collapsed sides on grids of patches built
 * with reversed and swapped parameter directions, and on the Utah teapot against a brute-force
 * pairwise comparison written independently here. */
#include "harness.h"
#include "bpt_reader.h"
#include "surface/internal.h"

#include <math.h>
#include <string.h>

/* Control point (i,j) of a bicubic patch covering cell (r,c) of the plane z = 0 (or a bump),
 * with its parameters transformed: flip_u, flip_v reverse a direction, swap exchanges u and v. */
static void cell_net(int r, int c, int flip_u, int flip_v, int swap, double *net)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int a = swap ? j : i, b = swap ? i : j; /* a along x, b along y */
            if (flip_u) { if (swap) b = 3 - b; else a = 3 - a; }
            if (flip_v) { if (swap) a = 3 - a; else b = 3 - b; }
            double x = c + a / 3.0, y = r + b / 3.0;
            double *p = net + (i * 4 + j) * 3;
            p[0] = x;
            p[1] = y;
            p[2] = sin(x) * cos(y); /* same value from both cells on a shared edge */
        }
}

/* Corner of the patch at (u,v) in {0,1}^2, taken from its net. */
static const double *corner(const bs_patch *p, double *store, int iu, int iv)
{
    size_t m = bs_patch_degree_u(p), n = bs_patch_degree_v(p);
    double net[65 * 65 * 3];
    bs_patch_get_ctrl(p, net, sizeof net / sizeof net[0], NULL, 0);
    size_t k = ((iu ? m : 0) * (n + 1) + (iv ? n : 0)) * 3;
    memcpy(store, net + k, 3 * sizeof(double));
    return store;
}

/* Start and end corners of a side in the direction of its parameter t. */
static void side_ends(const bs_patch *p, int side, double *s0, double *s1)
{
    static const int from[4][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}};
    static const int to[4][2] = {{1, 0}, {1, 1}, {1, 1}, {0, 1}};
    corner(p, s0, from[side][0], from[side][1]);
    corner(p, s1, to[side][0], to[side][1]);
}

static int same3(const double *a, const double *b)
{
    return fabs(a[0] - b[0]) < 1e-12 && fabs(a[1] - b[1]) < 1e-12 && fabs(a[2] - b[2]) < 1e-12;
}

/* For a planar grid every side is determined by its end points: check each link against them. */
static void check_grid(int rows, int cols, unsigned long long seed)
{
    bs_surface *s = NULL;
    bs_surface_create(&s);
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            int t = (int)(bs_test_rand_u64(&seed) & 7u);
            double net[48];
            cell_net(r, c, t & 1, (t >> 1) & 1, (t >> 2) & 1, net);
            bs_patch *p = NULL;
            bs_patch_create(3, 3, 3, net, NULL, &p);
            bs_surface_add(s, p, NULL);
            bs_patch_destroy(p);
        }
    bsi_topology topo;
    CHECK_STATUS(bsi_topology_build(s, 1e-9, &topo), BS_OK);
    CHECK(topo.npatch == (size_t)(rows * cols));
    size_t shared = 0, open = 0;
    for (size_t a = 0; a < topo.npatch; a++)
        for (int sa = 0; sa < 4; sa++) {
            const bsi_side_link *l = &topo.links[4 * a + (size_t)sa];
            double a0[3], a1[3];
            side_ends(bs_surface_get(s, a), sa, a0, a1);
            CHECK(!l->collapsed);
            /* Expected: some other side with the same end points exists iff the edge is interior. */
            int interior = 0;
            for (size_t b = 0; b < topo.npatch; b++)
                for (int sb = 0; sb < 4; sb++) {
                    if (b == a && sb == sa)
                        continue;
                    double b0[3], b1[3];
                    side_ends(bs_surface_get(s, b), sb, b0, b1);
                    int fwd = same3(a0, b0) && same3(a1, b1), rev = same3(a0, b1) && same3(a1, b0);
                    if (fwd || rev) {
                        interior = 1;
                        CHECKF(l->patch == b && l->side == sb && l->reversed == rev,
                               "patch %zu side %d: got %u/%d/%d want %zu/%d/%d", a, sa, l->patch, l->side,
                               l->reversed, b, sb, rev);
                    }
                }
            if (!interior)
                CHECK(l->patch == BSI_NO_PATCH);
            if (interior)
                shared++;
            else
                open++;
        }
    /* A rows x cols grid has rows(cols-1) + cols(rows-1) interior edges, each counted twice. */
    CHECK(shared == (size_t)2 * (size_t)(rows * (cols - 1) + cols * (rows - 1)));
    CHECK(open == (size_t)2 * (size_t)(rows + cols));
    bsi_topology_free(&topo);
    bs_surface_destroy(s);
}

/* Brute force: does side sa of a equal side sb of b (same degree, points within tol)? */
static int brute_equal(const bs_patch *a, int sa, const bs_patch *b, int sb, int rev, double tol)
{
    size_t ma = bs_patch_degree_u(a), na = bs_patch_degree_v(a);
    size_t mb = bs_patch_degree_u(b), nb = bs_patch_degree_v(b);
    size_t da = (sa == 0 || sa == 2) ? ma : na, db = (sb == 0 || sb == 2) ? mb : nb;
    if (da != db)
        return 0;
    static double na_[65 * 65 * 3], nb_[65 * 65 * 3];
    bs_patch_get_ctrl(a, na_, sizeof na_ / sizeof na_[0], NULL, 0);
    bs_patch_get_ctrl(b, nb_, sizeof nb_ / sizeof nb_[0], NULL, 0);
    for (size_t k = 0; k <= da; k++) {
        size_t kb = rev ? da - k : k;
        size_t ia = sa == 0 ? k * (na + 1) : sa == 1 ? ma * (na + 1) + k : sa == 2 ? k * (na + 1) + na : k;
        size_t ib = sb == 0 ? kb * (nb + 1) : sb == 1 ? mb * (nb + 1) + kb : sb == 2 ? kb * (nb + 1) + nb : kb;
        for (int c = 0; c < 3; c++)
            if (fabs(na_[ia * 3 + (size_t)c] - nb_[ib * 3 + (size_t)c]) > tol)
                return 0;
    }
    return 1;
}

static void check_teapot(void)
{
    bs_surface *s = test_load_bpt("teapot.bpt");
    CHECK(s != NULL);
    if (s == NULL)
        return;
    bsi_topology topo;
    CHECK_STATUS(bsi_topology_build(s, 1e-9, &topo), BS_OK);
    size_t shared = 0, open = 0, collapsed = 0;
    for (size_t a = 0; a < topo.npatch; a++)
        for (int sa = 0; sa < 4; sa++) {
            const bsi_side_link *l = &topo.links[4 * a + (size_t)sa];
            if (l->collapsed) {
                collapsed++;
                CHECK(l->patch == BSI_NO_PATCH);
                CHECK(brute_equal(bs_surface_get(s, a), sa, bs_surface_get(s, a), sa, 1, 1e-9));
                continue;
            }
            if (l->patch == BSI_NO_PATCH) {
                open++;
                /* Nothing else matches an open side (it may only match a side already taken). */
                continue;
            }
            shared++;
            const bsi_side_link *back = &topo.links[4 * (size_t)l->patch + l->side];
            CHECK(back->patch == a && back->side == sa && back->reversed == l->reversed);
            CHECK(brute_equal(bs_surface_get(s, a), sa, bs_surface_get(s, l->patch), l->side, l->reversed, 1e-9));
        }
    /* Brute force over all pairs: every pair of equal, non-collapsed sides is linked. */
    size_t pairs = 0;
    for (size_t a = 0; a < topo.npatch; a++)
        for (int sa = 0; sa < 4; sa++)
            for (size_t b = 0; b < topo.npatch; b++)
                for (int sb = 0; sb < 4; sb++) {
                    if ((b == a && sb == sa) || topo.links[4 * a + (size_t)sa].collapsed)
                        continue;
                    for (int rev = 0; rev < 2; rev++)
                        if (brute_equal(bs_surface_get(s, a), sa, bs_surface_get(s, b), sb, rev, 1e-9)) {
                            pairs++;
                            CHECK(topo.links[4 * a + (size_t)sa].patch == b);
                        }
                }
    CHECK(pairs == shared);
    /* The 32-patch teapot: 8 poles (4 at the lid knob's top, 4 at the bottom's centre); 16 open
     * sides (4 on the rim's top edge, 4 on the lid's lower edge, 2 at each end of the two-patch
     * handle and spout); the remaining 104 sides form 52 shared edges. */
    printf("teapot: %zu shared sides, %zu open, %zu collapsed\n", shared, open, collapsed);
    CHECK(collapsed == 8);
    CHECK(open == 16);
    CHECK(shared == 104);
    CHECK(shared + open + collapsed == 128);
    bsi_topology_free(&topo);
    bs_surface_destroy(s);
}

static void check_tolerance_and_degree(void)
{
    double n1[48], n2[48];
    cell_net(0, 0, 0, 0, 0, n1);
    cell_net(0, 1, 0, 0, 0, n2);
    n2[(0 * 4 + 1) * 3 + 2] += 1e-7; /* perturb a shared control point of the second patch */
    bs_patch *p1, *p2;
    bs_patch_create(3, 3, 3, n1, NULL, &p1);
    bs_patch_create(3, 3, 3, n2, NULL, &p2);
    bs_surface *s;
    bs_surface_create(&s);
    bs_surface_add(s, p1, NULL);
    bs_surface_add(s, p2, NULL);
    bsi_topology t;
    CHECK_STATUS(bsi_topology_build(s, 1e-6, &t), BS_OK);
    CHECK(t.links[4 * 0 + BSI_SIDE_U1].patch == 1 && t.links[4 * 1 + BSI_SIDE_U0].patch == 0);
    bsi_topology_free(&t);
    CHECK_STATUS(bsi_topology_build(s, 1e-9, &t), BS_OK);
    CHECK(t.links[4 * 0 + BSI_SIDE_U1].patch == BSI_NO_PATCH);
    bsi_topology_free(&t);
    bs_surface_destroy(s);

    /* Degree 3 against a linear patch on the same straight edge: not matched (documented). */
    double lin[12] = {1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0};
    double flat[48];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            flat[(i * 4 + j) * 3 + 0] = i / 3.0;
            flat[(i * 4 + j) * 3 + 1] = j / 3.0;
            flat[(i * 4 + j) * 3 + 2] = 0;
        }
    bs_patch *pl, *pf;
    bs_patch_create(1, 1, 3, lin, NULL, &pl);
    bs_patch_create(3, 3, 3, flat, NULL, &pf);
    bs_surface_create(&s);
    bs_surface_add(s, pf, NULL);
    bs_surface_add(s, pl, NULL);
    CHECK_STATUS(bsi_topology_build(s, 1e-9, &t), BS_OK);
    CHECK(t.links[4 * 0 + BSI_SIDE_U1].patch == BSI_NO_PATCH);
    CHECK(t.links[4 * 1 + BSI_SIDE_U0].patch == BSI_NO_PATCH);
    bsi_topology_free(&t);
    bs_surface_destroy(s);

    /* A single patch closed on itself (a cylinder): u = 0 and u = 1 are the same side. */
    double cyl[2 * 2 * 3] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0};
    bs_patch *pc;
    bs_patch_create(1, 1, 3, cyl, NULL, &pc);
    bs_surface_create(&s);
    bs_surface_add(s, pc, NULL);
    CHECK_STATUS(bsi_topology_build(s, 0.0, &t), BS_OK);
    CHECK(t.links[BSI_SIDE_U0].patch == 0 && t.links[BSI_SIDE_U0].side == BSI_SIDE_U1);
    CHECK(t.links[BSI_SIDE_U0].reversed == 0);
    CHECK(t.links[BSI_SIDE_V0].collapsed && t.links[BSI_SIDE_V1].collapsed);
    bsi_topology_free(&t);
    bs_surface_destroy(s);

    /* Empty surface. */
    bs_surface_create(&s);
    CHECK_STATUS(bsi_topology_build(s, 0.0, &t), BS_OK);
    CHECK(t.npatch == 0 && t.links == NULL);
    bsi_topology_free(&t);
    bs_surface_destroy(s);
    bs_patch_destroy(p1);
    bs_patch_destroy(p2);
    bs_patch_destroy(pl);
    bs_patch_destroy(pf);
    bs_patch_destroy(pc);
}

int main(void)
{
    check_grid(1, 1, 1);
    check_grid(3, 4, 2);
    for (unsigned long long seed = 10; seed < 20; seed++)
        check_grid(4, 5, seed);
    check_tolerance_and_degree();
    check_teapot();
    return bs_test_exit("test_topology");
}
