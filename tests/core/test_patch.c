/* The patch object, status texts and versions: creation rules, accessors, copies, every error path. */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <string.h>

static const double net3[27] = { /* MATH.md's first worked net, (2,2) in 3-D */
    1, 0, 2, 1, 2, 4, 1, 3, 2, 2, 1, 0, 2, 2, 2, 2, 4, 0, 4, 1, 0, 3, 3, 2, 4, 4, 2};

static void test_version(void)
{
    CHECK(bs_version_number() == BS_VERSION_NUMBER);
    CHECK(strcmp(bs_version_string(), BS_VERSION_STRING) == 0);
    CHECK(BS_VERSION_NUMBER == BS_VERSION_MAJOR * 10000 + BS_VERSION_MINOR * 100 + BS_VERSION_PATCH);
}

static void test_status_strings(void)
{
    for (int s = -20; s <= 5; s++)
        CHECK(bs_status_string(s) != NULL && bs_status_string(s)[0] != '\0');
    for (int s = BS_ERR_PRECISION; s <= BS_OK; s++)
        CHECKF(strcmp(bs_status_string(s), "unknown status") != 0, "code %d has no text", s);
    CHECK(strcmp(bs_status_string(-13), "unknown status") == 0);
    CHECK(strcmp(bs_status_string(1), "unknown status") == 0);
}

static void test_create_and_accessors(void)
{
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &p), BS_OK);
    CHECK(p != NULL);
    CHECK(bs_patch_degree_u(p) == 2 && bs_patch_degree_v(p) == 2 && bs_patch_dim(p) == 3);
    CHECK(bs_patch_is_rational(p) == 0);
    double ctrl[27], w[9];
    CHECK_STATUS(bs_patch_get_ctrl(p, ctrl, 27, w, 9), BS_OK);
    CHECK(memcmp(ctrl, net3, sizeof ctrl) == 0);
    for (int k = 0; k < 9; k++)
        CHECK(w[k] == 1.0);
    bs_patch *q = NULL;
    CHECK_STATUS(bs_patch_clone(p, &q), BS_OK);
    bs_patch_destroy(p); /* the clone is independent */
    double ctrl2[27];
    CHECK_STATUS(bs_patch_get_ctrl(q, ctrl2, 27, NULL, 0), BS_OK);
    CHECK(memcmp(ctrl2, net3, sizeof ctrl2) == 0);
    bs_patch_destroy(q);
    bs_patch_destroy(NULL);
}

static void test_mixed_degrees_and_rational(void)
{
    /* degree (3,1) in 2-D with weights; degree (0,0) in 1-D */
    double ctrl[8 * 2], w[8];
    for (int k = 0; k < 16; k++)
        ctrl[k] = k * 0.5 - 3.0;
    for (int k = 0; k < 8; k++)
        w[k] = 0.5 + k;
    bs_patch *p = NULL;
    CHECK_STATUS(bs_patch_create(3, 1, 2, ctrl, w, &p), BS_OK);
    CHECK(bs_patch_degree_u(p) == 3 && bs_patch_degree_v(p) == 1 && bs_patch_dim(p) == 2);
    CHECK(bs_patch_is_rational(p) == 1);
    double c2[16], w2[8];
    CHECK_STATUS(bs_patch_get_ctrl(p, c2, 16, w2, 8), BS_OK);
    CHECK(memcmp(c2, ctrl, sizeof c2) == 0 && memcmp(w2, w, sizeof w2) == 0);
    bs_patch_destroy(p);

    double one = 7.0;
    CHECK_STATUS(bs_patch_create(0, 0, 1, &one, NULL, &p), BS_OK);
    CHECK(bs_patch_degree_u(p) == 0 && bs_patch_dim(p) == 1);
    bs_patch_destroy(p);

    static double big[(BS_MAX_DEGREE + 1) * (BS_MAX_DEGREE + 1) * BS_MAX_DIM];
    CHECK_STATUS(bs_patch_create(BS_MAX_DEGREE, BS_MAX_DEGREE, BS_MAX_DIM, big, NULL, &p), BS_OK);
    CHECK(bs_patch_degree_v(p) == BS_MAX_DEGREE && bs_patch_dim(p) == BS_MAX_DIM);
    bs_patch_destroy(p);
}

static void test_create_errors(void)
{
    bs_patch *sentinel = (bs_patch *)&sentinel, *p = sentinel;
    CHECK_STATUS(bs_patch_create(2, 2, 3, NULL, NULL, &p), BS_ERR_INVALID_ARG);
    CHECK(p == NULL);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, NULL), BS_ERR_INVALID_ARG);
    p = sentinel;
    CHECK_STATUS(bs_patch_create(BS_MAX_DEGREE + 1, 2, 3, net3, NULL, &p), BS_ERR_DEGREE);
    CHECK(p == NULL);
    CHECK_STATUS(bs_patch_create(2, (size_t)-1, 3, net3, NULL, &p), BS_ERR_DEGREE);
    CHECK_STATUS(bs_patch_create(2, 2, 0, net3, NULL, &p), BS_ERR_DIMENSION);
    CHECK_STATUS(bs_patch_create(0, 0, BS_MAX_DIM + 1, net3, NULL, &p), BS_ERR_DIMENSION);
    CHECK(p == NULL);

    double bad[27];
    const double specials[3] = {NAN, INFINITY, -INFINITY};
    for (int s = 0; s < 3; s++) {
        memcpy(bad, net3, sizeof bad);
        bad[13] = specials[s];
        p = sentinel;
        CHECK_STATUS(bs_patch_create(2, 2, 3, bad, NULL, &p), BS_ERR_NONFINITE);
        CHECK(p == NULL);
    }
    const double bad_weights[5] = {0.0, -1.0, NAN, INFINITY, -0.0};
    for (int s = 0; s < 5; s++) {
        double w[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
        w[4] = bad_weights[s];
        p = sentinel;
        CHECK_STATUS(bs_patch_create(2, 2, 3, net3, w, &p), BS_ERR_NONFINITE);
        CHECK(p == NULL);
    }
    /* w*P overflows although both are finite */
    double huge[27];
    memcpy(huge, net3, sizeof huge);
    huge[0] = 1e308;
    double w[9] = {10, 1, 1, 1, 1, 1, 1, 1, 1};
    CHECK_STATUS(bs_patch_create(2, 2, 3, huge, w, &p), BS_ERR_NONFINITE);
}

static void test_accessor_errors(void)
{
    CHECK(bs_patch_degree_u(NULL) == 0 && bs_patch_degree_v(NULL) == 0);
    CHECK(bs_patch_dim(NULL) == 0 && bs_patch_is_rational(NULL) == 0);
    double buf[27];
    CHECK_STATUS(bs_patch_get_ctrl(NULL, buf, 27, NULL, 0), BS_ERR_INVALID_ARG);
    bs_patch *p, *q = (bs_patch *)&q;
    CHECK_STATUS(bs_patch_clone(NULL, &q), BS_ERR_INVALID_ARG);
    CHECK(q == NULL);
    CHECK_STATUS(bs_patch_create(2, 2, 3, net3, NULL, &p), BS_OK);
    CHECK_STATUS(bs_patch_clone(p, NULL), BS_ERR_INVALID_ARG);
    for (int k = 0; k < 27; k++)
        buf[k] = -99.0;
    double wbuf[9] = {-99, -99, -99, -99, -99, -99, -99, -99, -99};
    CHECK_STATUS(bs_patch_get_ctrl(p, buf, 26, wbuf, 9), BS_ERR_SIZE);
    CHECK_STATUS(bs_patch_get_ctrl(p, buf, 27, wbuf, 8), BS_ERR_SIZE);
    int untouched = 1;
    for (int k = 0; k < 27; k++)
        untouched &= buf[k] == -99.0;
    for (int k = 0; k < 9; k++)
        untouched &= wbuf[k] == -99.0;
    CHECK(untouched);
    CHECK_STATUS(bs_patch_get_ctrl(p, NULL, 0, NULL, 0), BS_OK);
    bs_patch_destroy(p);
}

int main(void)
{
    test_version();
    test_status_strings();
    test_create_and_accessors();
    test_mixed_degrees_and_rational();
    test_create_errors();
    test_accessor_errors();
    return bs_test_exit("test_patch");
}
