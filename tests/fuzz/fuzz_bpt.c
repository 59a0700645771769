/* libFuzzer target for the .bpt reader: any byte string must parse or fail cleanly; whatever parses
 * must write and read back to the same text. */
#include <bezsurf.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bs_surface *s = NULL;
    bs_parse_error err;
    bs_status st = bs_surface_read_bpt((const char *)data, size, &err, &s);
    if (st != BS_OK) {
        if (s != NULL || (st == BS_ERR_PARSE && (err.line == 0 || err.column == 0)))
            abort();
        return 0;
    }
    size_t n1 = 0, n2 = 0;
    if (bs_surface_write_bpt(s, NULL, 0, &n1) != BS_OK)
        abort();
    char *a = malloc(n1), *b = malloc(n1);
    bs_surface *t = NULL;
    if (a == NULL || b == NULL || bs_surface_write_bpt(s, a, n1, &n1) != BS_OK ||
        bs_surface_read_bpt(a, n1 - 1, NULL, &t) != BS_OK || bs_surface_write_bpt(t, b, n1, &n2) != BS_OK ||
        n1 != n2 || memcmp(a, b, n1) != 0)
        abort();
    free(a);
    free(b);
    bs_surface_destroy(t);
    bs_surface_destroy(s);
    return 0;
}
