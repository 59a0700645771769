/* Tessellation on several threads (bs_tess_options.threads): the default is 1; every method, with
 * and without strips, gives the same mesh bit for bit on 1, 2, 7 and 0 (one per CPU) threads; the
 * errors and budgets are those of one thread. */
#include "harness.h"
#include "mesh_data.h"

#include <string.h>

static const size_t thread_counts[] = {2, 7, 0};

/* The mesh of o on each thread count equals its mesh on one thread. */
static void same_on_threads(const bs_surface *s, bs_tess_options o, const char *what)
{
    bs_mesh *ref = NULL;
    o.threads = 1;
    CHECK_STATUS(bs_surface_tessellate(s, &o, &ref), BS_OK);
    for (size_t k = 0; ref != NULL && k < sizeof thread_counts / sizeof thread_counts[0]; k++) {
        bs_mesh *m = NULL;
        o.threads = thread_counts[k];
        CHECK_STATUS(bs_surface_tessellate(s, &o, &m), BS_OK);
        CHECKF(m != NULL && same_mesh(m, ref), "%s: %zu threads differ from one", what, thread_counts[k]);
        bs_mesh_destroy(m);
    }
    bs_mesh_destroy(ref);
}

static void every_method(const bs_surface *s, const char *name)
{
    static const int methods[] = {BS_TESS_UNIFORM, BS_TESS_PER_PATCH, BS_TESS_SUBDIVIDE};
    for (size_t m = 0; m < 3; m++)
        for (int strips = 0; strips < 2; strips++) {
            bs_tess_options o;
            bs_tess_options_init(&o);
            o.method = methods[m];
            o.flags = BS_TESS_RELATIVE | (strips ? BS_TESS_STRIPS : 0);
            o.nu = 9;
            o.nv = 23;
            char what[64];
            snprintf(what, sizeof what, "%s method %d strips %d", name, methods[m], strips);
            same_on_threads(s, o, what);
        }
}

int main(void)
{
    bs_tess_options o;
    bs_tess_options_init(&o);
    CHECK(o.threads == 1);

    for (size_t k = 0; bs_builtin_name(k) != NULL; k++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create_builtin(bs_builtin_name(k), &s), BS_OK);
        every_method(s, bs_builtin_name(k));
        bs_surface_destroy(s);
    }
    bs_surface *grid = bumpy_grid(5, 7, 11);
    every_method(grid, "bumpy grid");

    /* one patch, and no patch: fewer patches than threads */
    bs_surface *one = NULL, *none = NULL;
    CHECK_STATUS(bs_surface_create(&one), BS_OK);
    CHECK_STATUS(bs_surface_create(&none), BS_OK);
    CHECK_STATUS(bs_surface_add(one, bs_surface_get(grid, 0), NULL), BS_OK);
    every_method(one, "one patch");
    every_method(none, "empty surface");

    /* errors and budgets do not depend on the thread count */
    bs_mesh *m = (bs_mesh *)&o;
    o.threads = 2;
    o.max_triangles = 10;
    CHECK_STATUS(bs_surface_tessellate(grid, &o, &m), BS_ERR_SIZE);
    CHECK(m == NULL);
    o.max_triangles = 0;
    o.nu = 0;
    CHECK_STATUS(bs_surface_tessellate(grid, &o, &m), BS_ERR_DOMAIN);
    o.nu = 4;
    o.size = sizeof(o) - sizeof(size_t); /* a struct without the threads field */
    CHECK_STATUS(bs_surface_tessellate(grid, &o, &m), BS_ERR_INVALID_ARG);
    o.size = sizeof(o);
    CHECK_STATUS(bs_surface_tessellate(NULL, &o, &m), BS_ERR_INVALID_ARG);
    o.threads = 0;
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = -1.0;
    CHECK_STATUS(bs_surface_tessellate(grid, &o, &m), BS_ERR_DOMAIN);

    bs_surface_destroy(one);
    bs_surface_destroy(none);
    bs_surface_destroy(grid);
    return bs_test_exit("test_tess_threads");
}
