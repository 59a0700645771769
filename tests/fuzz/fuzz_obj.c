/* libFuzzer target for the OBJ reader: any byte string must parse or fail cleanly (a position with
 * every parse error); whatever parses must write and read back to the same text. */
#include "obj_round_trip.h"

#include <bezsurf.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bs_surface *s = NULL;
    bs_parse_error err;
    bs_status st = bs_surface_read_obj((const char *)data, size, &err, &s);
    if (st != BS_OK) {
        if (s != NULL || ((st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED) && (err.line == 0 || err.column == 0)))
            abort();
        return 0;
    }
    obj_round_trip(s);
    bs_surface_destroy(s);
    return 0;
}
