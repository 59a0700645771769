/* Model tessellation when memory runs out: each allocation of bs_model_tessellate (and of
 * bs_model_tessellate_count) failing in turn must give BS_ERR_NO_MEMORY and no mesh (and, under
 * the sanitizers and valgrind, no leak); then the call succeeds with the mesh it gives when
 * nothing fails. Parts: the cone (a seam, circles, planes), the sphere (poles), the IGES torus
 * (slits), the block's IGES B-rep (a closed edge whose trims start apart). */
#include "harness.h"

#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
void *__real_calloc(size_t n, size_t k);
void *__wrap_calloc(size_t n, size_t k);
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static size_t fail_in;
static int fails(void) { return fail_in != 0 && --fail_in == 0; }
void *__wrap_malloc(size_t n) { return fails() ? NULL : __real_malloc(n); }
void *__wrap_calloc(size_t n, size_t k) { return fails() ? NULL : __real_calloc(n, k); }
void *__wrap_realloc(void *p, size_t n) { return fails() ? NULL : __real_realloc(p, n); }

/* Fail the 1st, 2nd, ... allocation (every `stride`-th) until the call succeeds. */
static void run(const char *file, double rel, size_t stride)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, file);
    bs_model *m = NULL;
    bs_status st = strstr(file, ".step") ? bs_model_read_step_file(path, NULL, &m) : bs_model_read_iges_file(path, NULL, &m);
    CHECKF(st == BS_OK, "%s not read", file);
    if (st != BS_OK)
        return;
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.flags = BS_TESS_RELATIVE;
    o.tolerance = rel;
    bs_mesh *whole = NULL;
    CHECK(bs_model_tessellate(m, &o, &whole) == BS_OK);
    size_t failures = 0;
    for (size_t k = 1;; k += stride) {
        bs_mesh *mesh = NULL;
        fail_in = k;
        st = bs_model_tessellate(m, &o, &mesh);
        int hit = fail_in == 0;
        fail_in = 0;
        if (!hit) {
            CHECKF(st == BS_OK && mesh != NULL, "%s: status %d with no allocation failed", file, st);
            CHECK(bs_mesh_triangle_count(mesh) == bs_mesh_triangle_count(whole) &&
                  bs_mesh_vertex_count(mesh) == bs_mesh_vertex_count(whole));
            bs_mesh_destroy(mesh);
            break;
        }
        failures++;
        CHECKF(st == BS_ERR_NO_MEMORY && mesh == NULL, "%s: allocation %zu failed: status %d", file, k, st);
        bs_mesh_destroy(mesh);
    }
    size_t nv = 7, nt = 7;
    for (size_t k = 1; k < 40; k += 3) {
        fail_in = k;
        st = bs_model_tessellate_count(m, &o, &nv, &nt);
        int hit = fail_in == 0;
        fail_in = 0;
        if (hit)
            CHECKF(st == BS_ERR_NO_MEMORY && nv == 7 && nt == 7, "%s: count, allocation %zu failed: status %d", file, k, st);
    }
    printf("%s at %g D: %zu allocation failures, each BS_ERR_NO_MEMORY\n", file, rel, failures);
    CHECK(failures > 0);
    bs_mesh_destroy(whole);
    bs_model_destroy(m);
}
#endif

int main(void)
{
#ifdef BS_WRAP_MALLOC
    size_t stride = bs_test_quick() ? 13 : 1;
    run("cone.step", 1e-2, stride);
    run("sphere.step", 1e-2, stride);
    run("torus.igs", 1e-2, stride);
    run("block-brep.igs", 1e-2, stride * 3);
#else
    printf("test_tessellate_alloc: needs the linker's --wrap (GNU or Clang on ELF)\n");
#endif
    return bs_test_exit("test_tessellate_alloc");
}
