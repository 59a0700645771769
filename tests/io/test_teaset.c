/* The built-in tea set: names, patch counts, and control-point bounds compared with the data files
 * as read independently (strtod in the C locale). */
#include "harness.h"
#include "bpt_oracle.h"

#include <bezsurf.h>

#include <string.h>

int main(void)
{
    static const struct { const char *name; size_t count; } sets[] = {
        {"teapot", 32}, {"teacup", 26}, {"teaspoon", 16}};
    for (size_t f = 0; f < 3; f++) {
        bs_surface *s = NULL;
        CHECK_STATUS(bs_surface_create_builtin(sets[f].name, &s), BS_OK);
        CHECKF(bs_surface_count(s) == sets[f].count, "%s: %zu patches", sets[f].name, bs_surface_count(s));
        CHECK(bs_surface_dim(s) == 3);
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (size_t k = 0; k < bs_surface_count(s); k++) {
            const bs_patch *p = bs_surface_get(s, k);
            double c[48];
            CHECK(bs_patch_degree_u(p) == 3 && bs_patch_degree_v(p) == 3 && !bs_patch_is_rational(p));
            CHECK_STATUS(bs_patch_get_ctrl(p, c, 48, NULL, 0), BS_OK);
            for (size_t i = 0; i < 48; i++) {
                lo[i % 3] = c[i] < lo[i % 3] ? c[i] : lo[i % 3];
                hi[i % 3] = c[i] > hi[i % 3] ? c[i] : hi[i % 3];
            }
        }
        char path[512];
        snprintf(path, sizeof path, "%s/%s.bpt", BS_DATA_DIR, sets[f].name);
        size_t len;
        char *text = oracle_slurp(path, &len);
        static oracle_bpt o;
        CHECK(text != NULL && oracle_parse(text, &o) && o.npatch == sets[f].count);
        double olo[3] = {1e300, 1e300, 1e300}, ohi[3] = {-1e300, -1e300, -1e300};
        for (size_t k = 0; k < o.npatch; k++)
            for (size_t i = 0; i < 48; i++) {
                olo[i % 3] = o.ctrl[k][i] < olo[i % 3] ? o.ctrl[k][i] : olo[i % 3];
                ohi[i % 3] = o.ctrl[k][i] > ohi[i % 3] ? o.ctrl[k][i] : ohi[i % 3];
            }
        CHECKF(memcmp(lo, olo, sizeof lo) == 0 && memcmp(hi, ohi, sizeof hi) == 0,
               "%s: bounds differ", sets[f].name);
        printf("%s: %zu patches, bounds [%g %g %g] .. [%g %g %g]\n", sets[f].name, bs_surface_count(s),
               lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
        free(text);
        bs_surface_destroy(s);
    }
    /* The classic teapot starts with its rim point (1.4, 0, 2.4). */
    bs_surface *t;
    CHECK_STATUS(bs_surface_create_builtin("teapot", &t), BS_OK);
    double c[48];
    bs_patch_get_ctrl(bs_surface_get(t, 0), c, 48, NULL, 0);
    CHECK(c[0] == 1.4 && c[1] == 0.0 && c[2] == 2.4);
    bs_surface_destroy(t);
    return bs_test_exit("test_teaset");
}
