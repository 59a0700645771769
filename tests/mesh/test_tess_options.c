/* Tessellation with options: the defaults; BS_TESS_UNIFORM and BS_TESS_PER_PATCH give meshes equal
 * bit for bit to bs_surface_tessellate_uniform() and _adaptive(); bs_surface_tessellate_count()
 * gives the counts of the mesh (tea set, poles, a patch closed on itself, a side from a vertex to
 * itself, shared sides of different rates, strips or not) and the known counts of disjoint patches;
 * budgets and the 32-bit limits of vertices and of triangles are refused without a large
 * allocation; every error path. */
#include "harness.h"
#include "bpt_reader.h"
#include "mesh_data.h"

#include <math.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

/* The mesh of o equals the 1.0 tessellator's (ref), and the counts are the mesh's. */
static void check_against(const bs_surface *s, const bs_tess_options *o, bs_mesh *ref, const char *what)
{
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_tessellate(s, o, &m), BS_OK);
    CHECKF(m != NULL && same_mesh(m, ref), "%s: the mesh differs from the 1.0 tessellator's", what);
    size_t nv = 0, nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, o, &nv, &nt), BS_OK);
    CHECKF(nv == bs_mesh_vertex_count(ref) && nt == bs_mesh_triangle_count(ref),
           "%s: counted %zu vertices, %zu triangles; the mesh has %zu, %zu", what, nv, nt,
           bs_mesh_vertex_count(ref), bs_mesh_triangle_count(ref));
    bs_mesh_destroy(m);
    bs_mesh_destroy(ref);
}

/* Method uniform (nu x nv) or per patch (tol) against the 1.0 tessellator with the same arguments. */
static void one_case(const bs_surface *s, int method, size_t nu, size_t nv, double tol, int flags,
                     const char *name)
{
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = method;
    o.nu = nu;
    o.nv = nv;
    o.tolerance = tol;
    o.flags = flags;
    bs_mesh *ref = NULL;
    if (method == BS_TESS_UNIFORM)
        CHECK_STATUS(bs_surface_tessellate_uniform(s, nu, nv, flags, &ref), BS_OK);
    else
        CHECK_STATUS(bs_surface_tessellate_adaptive(s, tol, flags, &ref), BS_OK);
    char what[96];
    snprintf(what, sizeof what, "%s method %d %zux%zu tolerance %g flags %d", name, method, nu, nv, tol, flags);
    check_against(s, &o, ref, what);
}

static void all_cases(const bs_surface *s, const char *name)
{
    static const size_t rates[][2] = {{1, 1}, {2, 2}, {3, 7}, {16, 16}, {1, 5}};
    for (size_t r = 0; r < sizeof rates / sizeof rates[0]; r++)
        for (int flags = 0; flags <= BS_TESS_STRIPS; flags += BS_TESS_STRIPS)
            one_case(s, BS_TESS_UNIFORM, rates[r][0], rates[r][1], 1e-3, flags, name);
    one_case(s, BS_TESS_PER_PATCH, 16, 16, 0.05, 0, name);
    one_case(s, BS_TESS_PER_PATCH, 16, 16, 0.01, BS_TESS_STRIPS, name);
    one_case(s, BS_TESS_PER_PATCH, 16, 16, 1e-3, BS_TESS_RELATIVE | BS_TESS_STRIPS, name);
}

static void defaults(void)
{
    bs_tess_options o;
    memset(&o, 0x5a, sizeof o);
    bs_tess_options_init(&o);
    CHECK(o.size == sizeof o && o.method == BS_TESS_UNIFORM && o.flags == 0);
    CHECK(o.nu == 16 && o.nv == 16 && o.tolerance == 1e-3);
    CHECK(o.max_vertices == 0 && o.max_triangles == 0);
    bs_tess_options_init(NULL);
}

static void tea_set(void)
{
    static const char *names[] = {"teapot.bpt", "teacup.bpt", "teaspoon.bpt"};
    for (size_t k = 0; k < 3; k++) {
        bs_surface *s = test_load_bpt(names[k]);
        CHECK(s != NULL);
        if (s != NULL)
            all_cases(s, names[k]);
        bs_surface_destroy(s);
    }
    /* 2N^2 triangles on each of the teapot's 32 patches, less the N that degenerate at each of
     * its 8 poles: counted without building the mesh. */
    bs_surface *s = test_load_bpt("teapot.bpt");
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.nu = o.nv = 1000;
    size_t nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, NULL, &nt), BS_OK);
    CHECK(nt == 32 * 2 * 1000 * 1000 - 8 * 1000);
    bs_surface_destroy(s);
}

/* One bicubic patch closed on itself along u (its sides u = 0 and u = 1 are one curve), with a
 * pole at v = 0: a cup of radius growing with v, the net's circle drawn by 4 points per row. */
static bs_surface *closed_cup(void)
{
    static const double ring[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {1, 0}};
    double net[4 * 4 * 3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double r = j / 3.0, *p = net + (i * 4 + j) * 3;
            p[0] = r * ring[i][0] + (i == 1 ? 0.3 * j : 0.0);
            p[1] = r * ring[i][1];
            p[2] = j * j / 9.0;
        }
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, 3, 3, net, NULL);
    return s;
}

/* A tube of degree (3,1) closed on itself along u (its sides u = 0 and u = 1 are one segment, so
 * the ends of its side v = 0, a teardrop loop, are one vertex), and a patch 100 times larger
 * sharing its side v = 1. At a tolerance that gives the tube one segment in u and its neighbour
 * several, the tube's side v = 1 is stitched at the neighbour's rate while its side v = 0 stays one
 * segment from a vertex to itself, which gives no triangle. */
static bs_surface *tube_and_large_neighbour(void)
{
    static const double loop[4][2] = {{0, 0}, {1, 1}, {1, -1}, {0, 0}};
    double tube[4 * 2 * 3], big[4 * 2 * 3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 2; j++) {
            double *t = tube + (i * 2 + j) * 3, *b = big + (i * 2 + j) * 3, r = j == 0 ? 1.0 : 100.0;
            t[0] = loop[i][0];
            t[1] = loop[i][1];
            t[2] = j;
            b[0] = r * loop[i][0];
            b[1] = r * loop[i][1];
            b[2] = 1.0 + j;
        }
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, 3, 1, tube, NULL);
    add_patch(s, 3, 1, big, NULL);
    return s;
}

static void shapes(void)
{
    bs_surface *s = closed_cup();
    all_cases(s, "closed cup");
    bs_surface_destroy(s);
    s = tube_and_large_neighbour();
    all_cases(s, "tube and a large neighbour");
    for (double tol = 1.0; tol <= 64.0; tol *= 2.0)
        one_case(s, BS_TESS_PER_PATCH, 16, 16, tol, 0, "tube and a large neighbour");
    bs_surface_destroy(s);
    s = bumpy_grid(3, 4, 5);
    all_cases(s, "bumpy grid");
    bs_surface_destroy(s);
}

/* n flat unit squares side by side with gaps, no side shared. */
static bs_surface *apart(size_t n)
{
    bs_surface *s = NULL;
    bs_surface_create(&s);
    for (size_t k = 0; k < n; k++) {
        double x = 2.0 * (double)k, net[12] = {x, 0, 0, x, 1, 0, x + 1, 0, 0, x + 1, 1, 0};
        add_patch(s, 1, 1, net, NULL);
    }
    return s;
}

static long peak_kib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

/* 1 in a sanitizer build. Sanitizers reserve terabytes of address space and keep freed memory in
 * quarantine, so neither a cap on the address space nor the growth of the resident size speaks of
 * the library there. */
static int sanitized(void)
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    return 1;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
    return 1;
#endif
#endif
    return 0;
}

/* Valgrind (BS_TEST_QUICK) also runs its own allocator inside the limit. */
static int can_cap_address_space(void) { return !sanitized() && !bs_test_quick(); }

/* bs_surface_tessellate() in a child process whose address space is capped at `bytes`: its status,
 * or BS_ERR_INVALID_ARG when the child could not be run or capped. */
static bs_status tessellate_capped(const bs_surface *s, const bs_tess_options *o, rlim_t bytes)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        struct rlimit r = {bytes, bytes};
        bs_mesh *m = NULL;
        bs_status st = setrlimit(RLIMIT_AS, &r) == 0 ? bs_surface_tessellate(s, o, &m) : BS_ERR_INVALID_ARG;
        _exit(st == BS_ERR_SIZE ? 0 : st == BS_ERR_NO_MEMORY ? 1 : st == BS_OK ? 2 : 3);
    }
    int wst = 0;
    if (pid < 0 || waitpid(pid, &wst, 0) != pid || !WIFEXITED(wst))
        return BS_ERR_INVALID_ARG;
    static const bs_status by_code[] = {BS_ERR_SIZE, BS_ERR_NO_MEMORY, BS_OK, BS_ERR_INVALID_ARG};
    return by_code[WEXITSTATUS(wst) & 3];
}

static void budgets(void)
{
    bs_surface *s = test_load_bpt("teapot.bpt");
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.nu = 8;
    o.nv = 5;
    o.flags = BS_TESS_STRIPS;
    size_t nv = 0, nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    bs_mesh *m = NULL;
    o.max_vertices = nv;
    o.max_triangles = nt;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK); /* exactly at the budget */
    CHECK(bs_mesh_vertex_count(m) == nv && bs_mesh_triangle_count(m) == nt);
    bs_mesh_destroy(m);
    m = (bs_mesh *)&m;
    o.max_vertices = nv - 1;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    o.max_vertices = 0;
    o.max_triangles = nt - 1;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    /* the count ignores budgets, so a caller sees how far over they are */
    size_t nv2 = 0, nt2 = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv2, &nt2), BS_OK);
    CHECK(nv2 == nv && nt2 == nt);
    bs_surface_destroy(s);

    /* 100,000 patches at the largest rate: 1025^2 vertices each, far past 32-bit ids. Refused from
     * the counts, before the gigabytes of slots and arrays the mesh would need. */
    s = apart(100000);
    long before = peak_kib();
    bs_tess_options_init(&o);
    o.nu = o.nv = BS_TESS_MAX_RATE;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECK(nv == (size_t)100000 * 1025 * 1025 && nt == (size_t)100000 * 2 * 1024 * 1024);
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, BS_TESS_MAX_RATE, BS_TESS_MAX_RATE, 0, &m), BS_ERR_SIZE);
    long grown = peak_kib() - before;
    CHECKF(grown < 64 * 1024 || sanitized(), "refusing grew the peak memory by %ld KiB", grown);
    bs_surface_destroy(s);

    /* 4095 squares at 1024 x 1024: 4095 * 1025^2 = 4,302,392,375 vertices > UINT32_MAX - 1 */
    s = apart(4095);
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_SIZE);
    bs_surface_destroy(s);

    /* 700 squares at 1024 x 1024: 1,468,006,400 triangles > UINT32_MAX / 3 with only 735 M
     * vertices, so the triangles alone are over the limit. Refused from the counts too: in a child
     * whose address space is capped at 2 GiB, where a tessellator that allocated first would
     * fail with BS_ERR_NO_MEMORY. */
    s = apart(700);
    if (can_cap_address_space())
        CHECK_STATUS(tessellate_capped(s, &o, (rlim_t)2 << 30), BS_ERR_SIZE);
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECK(nv == (size_t)700 * 1025 * 1025 && nt == (size_t)700 * 2 * 1024 * 1024 && nt > UINT32_MAX / 3);
    bs_surface_destroy(s);
}

static void errors(void)
{
    bs_surface *s = bumpy_grid(1, 2, 3), *flat = NULL;
    bs_surface_create(&flat);
    double net2[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p2 = NULL;
    bs_patch_create(1, 1, 2, net2, NULL, &p2);
    bs_surface_add(flat, p2, NULL);
    bs_patch_destroy(p2);
    bs_tess_options o;
    bs_tess_options_init(&o);
    bs_mesh *m = (bs_mesh *)&m;
    size_t nv = 77, nt = 77;
    CHECK_STATUS(bs_surface_tessellate(NULL, &o, &m), BS_ERR_INVALID_ARG);
    CHECK(m == NULL);
    CHECK_STATUS(bs_surface_tessellate(s, NULL, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate(s, &o, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_count(NULL, &o, &nv, &nt), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_count(s, NULL, &nv, &nt), BS_ERR_INVALID_ARG);
    o.size = sizeof o - 1;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_ERR_INVALID_ARG);
    bs_tess_options_init(&o);
    o.method = 3;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_INVALID_ARG);
    o.method = -1;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_ERR_INVALID_ARG);
    bs_tess_options_init(&o);
    o.flags = 8;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_INVALID_ARG);
    bs_tess_options_init(&o);
    CHECK_STATUS(bs_surface_tessellate(flat, &o, &m), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_surface_tessellate_count(flat, &o, &nv, &nt), BS_ERR_DIMENSION);
    o.nu = 0;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_DOMAIN);
    o.nu = BS_TESS_MAX_RATE + 1;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_ERR_DOMAIN);
    bs_tess_options_init(&o);
    o.method = BS_TESS_PER_PATCH;
    static const double bad_tol[] = {0.0, -1.0, NAN, INFINITY};
    for (int k = 0; k < 4; k++) {
        o.tolerance = bad_tol[k];
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_ERR_DOMAIN);
        CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_ERR_DOMAIN);
    }
    CHECK(m == NULL && nv == 77 && nt == 77);
    /* a uniform method ignores the tolerance, a per-patch one the rates */
    bs_tess_options_init(&o);
    o.tolerance = NAN;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, NULL), BS_OK);
    CHECK(nv == 2 * 17 * 17 - 17);
    o.method = BS_TESS_PER_PATCH;
    o.tolerance = 0.1;
    o.nu = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, NULL, &nt), BS_OK);
    bs_surface *empty = NULL;
    bs_surface_create(&empty);
    bs_tess_options_init(&o);
    CHECK_STATUS(bs_surface_tessellate_count(empty, &o, &nv, &nt), BS_OK);
    CHECK(nv == 0 && nt == 0);
    bs_surface_destroy(empty);
    bs_surface_destroy(s);
    bs_surface_destroy(flat);
}

/* Two unit squares side by side in the plane z = 0, scaled by k, the second's shared side moved by
 * (0, 0, delta) x k: welded when delta is within 1e-9 of the largest coordinate (2k). */
static size_t vertices_of_pair(double k, double delta)
{
    double a[12] = {0, 0, 0, 0, k, 0, k, 0, 0, k, k, 0};
    double b[12] = {k, 0, delta * k, k, k, delta * k, 2 * k, 0, 0, 2 * k, k, 0};
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, 1, 1, a, NULL);
    add_patch(s, 1, 1, b, NULL);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.nu = o.nv = 4;
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
    size_t nv = bs_mesh_vertex_count(m);
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
    return nv;
}

/* Welding, rates and sampling against the documented rules (docs/tessellation.md). */
static void documented_rules(void)
{
    /* 4 x 4 segments: 25 vertices a patch, 5 of them on the shared side */
    static const double scales[] = {1.0, 1e6, 1e-6};
    for (int k = 0; k < 3; k++) {
        CHECK(vertices_of_pair(scales[k], 0.0) == 45);
        CHECK(vertices_of_pair(scales[k], 0.9e-9) == 45);  /* 0.9e-9 k <= 1e-9 x 2k */
        CHECK(vertices_of_pair(scales[k], 1.9e-9) == 45);
        CHECK(vertices_of_pair(scales[k], 2.2e-9) == 50);  /* past 1e-9 x 2k: two sides */
    }

    /* Rates from the bound, n_u = ceil(1.5 sqrt((M_uu + M_uv) / (4 tol))) and likewise n_v, on a
     * net of degree (2,1) flat but for z = c at point (2,1): its largest second difference along u
     * and mixed difference are both c, so M_uu = m(m-1) c = 2c, M_uv = mn c = 2c, M_vv = 0. */
    double c = 3.0, tol = 1e-3;
    double net[3 * 2 * 3] = {0, 0, 0, 0, 1, 0, 0.5, 0, 0, 0.5, 1, 0, 1, 0, 0, 1, 1, c};
    bs_surface *s = NULL;
    bs_surface_create(&s);
    add_patch(s, 2, 1, net, NULL);
    double muu = 2.0 * c, muv = 2.0 * c, mvv = 0.0;
    size_t ru = (size_t)ceil(1.5 * sqrt((muu + muv) / (4.0 * tol)));
    size_t rv = (size_t)ceil(1.5 * sqrt((mvv + muv) / (4.0 * tol)));
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_PER_PATCH;
    o.tolerance = tol;
    size_t nv = 0, nt = 0;
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, &nv, &nt), BS_OK);
    CHECKF(nv == (ru + 1) * (rv + 1) && nt == 2 * ru * rv, "rates %zu x %zu: %zu vertices, %zu triangles", ru, rv,
           nv, nt);

    /* A ruled patch of rate 1 x 1 sharing that patch's side u = 1 as its own side u = 0: a shared
     * side is sampled at the larger rate, so the ruled patch's triangles have rv + 1 distinct
     * corners on it. */
    double flat[12] = {1, 0, 0, 1, 1, c, 2, 0, 0, 2, 1, c};
    add_patch(s, 1, 1, flat, NULL);
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
    mesh_data d;
    read_mesh(m, &d);
    double seen[BS_TESS_MAX_RATE + 2];
    size_t nseen = 0;
    for (size_t t = 0; t < d.nt; t++)
        for (int k = 0; k < 3 && d.tpatch[t] == 1; k++) {
            double u = d.cuv[6 * t + 2 * (size_t)k], v = d.cuv[6 * t + 2 * (size_t)k + 1];
            size_t j = 0;
            while (j < nseen && seen[j] != v)
                j++;
            if (u == 0.0 && j == nseen && nseen < BS_TESS_MAX_RATE + 2)
                seen[nseen++] = v;
        }
    CHECKF(nseen == rv + 1, "shared side sampled at %zu points, not the larger rate %zu + 1", nseen, rv);
    free_mesh(&d);
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
}

/* Subdivision goes through the same entry points (tested in test_tess_subdivide). */
static void subdivide(void)
{
    bs_surface *s = bumpy_grid(1, 1, 1);
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    bs_mesh *m = NULL;
    size_t nt = 0;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
    CHECK_STATUS(bs_surface_tessellate_count(s, &o, NULL, &nt), BS_OK);
    CHECK(m != NULL && nt > 0 && bs_mesh_triangle_count(m) == nt);
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
}

int main(void)
{
    defaults();
    errors();
    subdivide();
    tea_set();
    shapes();
    budgets();
    documented_rules();
    return bs_test_exit("test_tess_options");
}
