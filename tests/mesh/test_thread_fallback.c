/* When no thread can be created, the multi-threaded calls do the work on the calling thread: this
 * program's pthread_create, which the library binds to, always fails with EAGAIN. The mesh and the
 * grid are those of one thread, and the failing creations are counted to show they were tried. */
#include "harness.h"
#include "mesh_data.h"

#include <errno.h>
#include <pthread.h>
#include <string.h>

static int attempts; /* the library only calls it from the calling thread */

int pthread_create(pthread_t *thread, const pthread_attr_t *attr, void *(*start)(void *), void *arg)
{
    (void)thread;
    (void)attr;
    (void)start;
    (void)arg;
    attempts++;
    return EAGAIN;
}

int main(void)
{
    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &s), BS_OK);
    bs_surface *bumps = bumpy_grid(3, 4, 5);
    bs_tess_options o;
    bs_tess_options_init(&o);
    bs_mesh *one = NULL, *four = NULL;
    CHECK_STATUS(bs_surface_tessellate(bumps, &o, &one), BS_OK);
    CHECK(attempts == 0);
    o.threads = 4;
    CHECK_STATUS(bs_surface_tessellate(bumps, &o, &four), BS_OK);
    CHECK(attempts > 0 && one != NULL && four != NULL && same_mesh(one, four));
    bs_mesh_destroy(one);
    bs_mesh_destroy(four);
    bs_surface_destroy(bumps);

    enum { G = 17, N = 32 * G * G };
    double t[G], *a = malloc(2 * 3 * N * sizeof(double));
    for (int k = 0; k < G; k++)
        t[k] = k / (double)(G - 1);
    bs_cview ct = {t, G, 0};
    bs_view pa[3], pb[3];
    for (size_t c = 0; c < 3; c++) {
        pa[c] = (bs_view){a + c * N, N, 0};
        pb[c] = (bs_view){a + (3 + c) * N, N, 0};
    }
    int before = attempts;
    CHECK_STATUS(bs_surface_eval_grid(s, G, &ct, G, &ct, pa, NULL, NULL, NULL, NULL, 1), BS_OK);
    CHECK_STATUS(bs_surface_eval_grid(s, G, &ct, G, &ct, pb, NULL, NULL, NULL, NULL, 0), BS_OK);
    CHECK(memcmp(a, a + 3 * N, 3 * N * sizeof(double)) == 0);
    CHECK(attempts >= before); /* 0 threads on a one-CPU machine starts none */
    free(a);
    bs_surface_destroy(s);
    return bs_test_exit("test_thread_fallback");
}
