/* Mesh export under a locale whose decimal point is a comma: the OBJ and ASCII PLY bytes are the
 * same as under the "C" locale. Skipped (exit 77) when no such locale is installed. */
#include "harness.h"

#include <bezsurf.h>

#include <locale.h>
#include <stdlib.h>
#include <string.h>

static unsigned char *export(const bs_mesh *m, int format, size_t *size)
{
    CHECK_STATUS(bs_mesh_write_memory(m, format, NULL, 0, size), BS_OK);
    unsigned char *buf = malloc(*size + 1);
    CHECK_STATUS(bs_mesh_write_memory(m, format, buf, *size, size), BS_OK);
    return buf;
}

int main(void)
{
    double net[4 * 3] = {0, 0, 0.125, 0, 1.5, 0, 1.25, 0, 0, 1, 1, 1.75};
    bs_patch *p = NULL;
    bs_surface *s = NULL;
    bs_mesh *m = NULL;
    bs_patch_create(1, 1, 3, net, NULL, &p);
    bs_surface_create(&s);
    bs_surface_add(s, p, NULL);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 3, 3, 0, &m), BS_OK);
    size_t n_obj, n_ply;
    unsigned char *obj = export(m, BS_MESH_OBJ, &n_obj), *ply = export(m, BS_MESH_PLY_ASCII, &n_ply);
    static const char *const names[] = {"de_DE.UTF-8", "de_DE.utf8", "de_DE", "fr_FR.UTF-8", "fr_FR.utf8"};
    const char *found = NULL;
    for (size_t k = 0; k < sizeof names / sizeof names[0] && !found; k++)
        if (setlocale(LC_ALL, names[k]) != NULL && strcmp(localeconv()->decimal_point, ",") == 0)
            found = names[k];
    int rc = 77;
    if (found == NULL) {
        printf("test_export_locale: skipped, no locale with a decimal comma is installed\n");
    } else {
        size_t n2_obj, n2_ply;
        unsigned char *obj2 = export(m, BS_MESH_OBJ, &n2_obj), *ply2 = export(m, BS_MESH_PLY_ASCII, &n2_ply);
        CHECK(n2_obj == n_obj && memcmp(obj, obj2, n_obj) == 0);
        CHECK(n2_ply == n_ply && memcmp(ply, ply2, n_ply) == 0);
        free(obj2);
        free(ply2);
        rc = bs_test_exit("test_export_locale");
    }
    free(obj);
    free(ply);
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
    return rc;
}
