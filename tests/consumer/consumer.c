/* An out-of-tree program built against the installed library, by pkg-config and by CMake. */
#include <bezsurf.h>

#include <stdio.h>

int main(void)
{
    if (bs_version_number() / 10000 != BS_VERSION_MAJOR) {
        fprintf(stderr, "header %s, library %s: major versions differ\n", BS_VERSION_STRING, bs_version_string());
        return 1;
    }
    /* The bilinear patch z = u v: at (1/2, 1/4) the point is (1/2, 1/4, 1/8) exactly. */
    const double net[4 * 3] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    const double u = 0.5, v = 0.25;
    double x, y, z;
    bs_cview uv = {&u, 1, 0}, vv = {&v, 1, 0};
    bs_view pos[3] = {{&x, 1, 0}, {&y, 1, 0}, {&z, 1, 0}};
    bs_patch *p;
    if (bs_patch_create(1, 1, 3, net, NULL, &p) != BS_OK)
        return 1;
    bs_status st = bs_patch_eval(p, 1, &uv, &vv, pos, NULL, NULL);
    bs_patch_destroy(p);
    if (st != BS_OK || x != 0.5 || y != 0.25 || z != 0.125)
        return 1;
    printf("consumer: linked libbezsurf %s\n", bs_version_string());
    return 0;
}
