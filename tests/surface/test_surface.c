/* Surfaces as containers: add, count, get, clone, dimension rules and error paths. */
#include "harness.h"

#include <bezsurf.h>

#include <string.h>

int main(void)
{
    double net[4 * 3] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    double net2[4 * 2] = {0, 0, 0, 1, 1, 0, 1, 1};
    bs_patch *p3, *p2;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p3), BS_OK);
    CHECK_STATUS(bs_patch_create(1, 1, 2, net2, NULL, &p2), BS_OK);

    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK(bs_surface_count(s) == 0 && bs_surface_dim(s) == 0 && bs_surface_get(s, 0) == NULL);
    size_t idx = 99;
    /* the second patch already must have the first one's dimension */
    CHECK_STATUS(bs_surface_add(s, p3, &idx), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p2, &idx), BS_ERR_INCOMPATIBLE);
    CHECK(idx == 0 && bs_surface_count(s) == 1 && bs_surface_dim(s) == 3);
    bs_surface_destroy(s);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    for (size_t k = 0; k < 20; k++) {
        CHECK_STATUS(bs_surface_add(s, p3, &idx), BS_OK);
        CHECK(idx == k);
    }
    CHECK(bs_surface_count(s) == 20 && bs_surface_dim(s) == 3);
    idx = 99;
    CHECK_STATUS(bs_surface_add(s, p2, &idx), BS_ERR_INCOMPATIBLE);
    CHECK(idx == 99 && bs_surface_count(s) == 20);
    const bs_patch *g = bs_surface_get(s, 19);
    CHECK(g != NULL && g != p3 && bs_patch_dim(g) == 3);
    double back[12];
    CHECK_STATUS(bs_patch_get_ctrl(g, back, 12, NULL, 0), BS_OK);
    CHECK(memcmp(back, net, sizeof back) == 0);
    CHECK(bs_surface_get(s, 20) == NULL);

    bs_surface *c = NULL;
    CHECK_STATUS(bs_surface_clone(s, &c), BS_OK);
    bs_surface_destroy(s);
    CHECK(bs_surface_count(c) == 20 && bs_surface_dim(c) == 3);

    CHECK_STATUS(bs_surface_create(NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_add(NULL, p3, NULL), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_surface_add(c, NULL, NULL), BS_ERR_INVALID_ARG);
    bs_surface *q = (bs_surface *)&q;
    CHECK_STATUS(bs_surface_clone(NULL, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK(bs_surface_count(NULL) == 0 && bs_surface_dim(NULL) == 0 && bs_surface_get(NULL, 0) == NULL);
    bs_surface_destroy(NULL);
    bs_surface_destroy(c);
    bs_patch_destroy(p3);
    bs_patch_destroy(p2);
    return bs_test_exit("test_surface");
}
