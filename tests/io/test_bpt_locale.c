/* The .bpt reader and writer under a locale whose decimal point is a comma (German): numbers are
 * still read and written with '.', and round trips stay exact. Skipped (exit 77) when no such
 * locale is installed. */
#include "harness.h"
#include "surface_check.h"

#include <bezsurf.h>

#include <locale.h>
#include <stdlib.h>
#include <string.h>

int main(void)
{
    const char *found = switch_to_comma_locale();
    if (found == NULL) {
        printf("test_bpt_locale: skipped, no locale with a decimal comma is installed\n");
        return 77;
    }
    printf("test_bpt_locale: running under %s\n", found);
    char probe[32];
    snprintf(probe, sizeof probe, "%.1f", 1.5);
    CHECKF(strcmp(probe, "1,5") == 0, "the C library prints %s", probe); /* the locale is in effect */

    bs_surface *s = NULL;
    CHECK_STATUS(bs_surface_read_bpt("1\n0 0\n1.5 -0.784 2.4e1\n", 23, NULL, &s), BS_OK);
    double c[3] = {0, 0, 0};
    if (s)
        bs_patch_get_ctrl(bs_surface_get(s, 0), c, 3, NULL, 0);
    CHECK(c[0] == 1.5 && c[1] == -0.784 && c[2] == 24.0);
    char text[64];
    size_t size;
    CHECK_STATUS(bs_surface_write_bpt(s, text, sizeof text, &size), BS_OK);
    CHECKF(strcmp(text, "1\n0 0\n1.5 -0.784 24\n") == 0, "wrote '%s'", text);
    bs_surface_destroy(s);
    bs_parse_error err;
    CHECK_STATUS(bs_surface_read_bpt("1\n0 0\n1,5 0 0\n", 15, &err, &s), BS_ERR_PARSE);
    CHECK(err.line == 3 && err.column == 1);

    /* The tea set round-trips bit for bit, and the text has no comma. */
    for (size_t k = 0; bs_builtin_name(k) != NULL; k++) {
        bs_surface *a = NULL, *b = NULL;
        CHECK_STATUS(bs_surface_create_builtin(bs_builtin_name(k), &a), BS_OK);
        CHECK_STATUS(bs_surface_write_bpt(a, NULL, 0, &size), BS_OK);
        char *buf = malloc(size);
        CHECK_STATUS(bs_surface_write_bpt(a, buf, size, &size), BS_OK);
        CHECK(strchr(buf, ',') == NULL);
        CHECK_STATUS(bs_surface_read_bpt(buf, size - 1, NULL, &b), BS_OK);
        int same = bs_surface_count(a) == bs_surface_count(b);
        for (size_t i = 0; same && i < bs_surface_count(a); i++) {
            double ca[48], cb[48];
            bs_patch_get_ctrl(bs_surface_get(a, i), ca, 48, NULL, 0);
            bs_patch_get_ctrl(bs_surface_get(b, i), cb, 48, NULL, 0);
            same = memcmp(ca, cb, sizeof ca) == 0;
        }
        CHECKF(same, "%s", bs_builtin_name(k));
        free(buf);
        bs_surface_destroy(a);
        bs_surface_destroy(b);
    }
    return bs_test_exit("test_bpt_locale");
}
