/* An out-of-tree program built against the installed library, by pkg-config and by CMake. */
#include <bezsurf.h>

#include <stdio.h>

int main(void)
{
    if (bs_version_number() / 10000 != BS_VERSION_MAJOR) {
        fprintf(stderr, "header %s, library %s: major versions differ\n", BS_VERSION_STRING, bs_version_string());
        return 1;
    }
    const double net[4 * 3] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    bs_patch *p;
    if (bs_patch_create(1, 1, 3, net, NULL, &p) != BS_OK)
        return 1;
    double back[12];
    bs_status st = bs_patch_get_ctrl(p, back, 12, NULL, 0);
    bs_patch_destroy(p);
    if (st != BS_OK || back[11] != 1.0)
        return 1;
    printf("consumer: linked libbezsurf %s\n", bs_version_string());
    return 0;
}
