/* libFuzzer target for the IGES reader: any byte string must parse or fail cleanly (a position with
 * every parse error); whatever parses must give finite patches that survive an OBJ round trip bit
 * for bit. */
#include "obj_round_trip.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bs_surface *s = NULL;
    bs_parse_error err;
    bs_status st = bs_surface_read_iges((const char *)data, size, &err, &s);
    if (st != BS_OK) {
        if (s != NULL || (st == BS_ERR_PARSE && (err.line == 0 || err.column == 0)))
            abort();
        return 0;
    }
    for (size_t k = 0; k < bs_surface_count(s); k++) {
        double lo[3], hi[3];
        if (bs_patch_bounds(bs_surface_get(s, k), lo, hi) != BS_OK)
            abort();
        for (int c = 0; c < 3; c++)
            if (!isfinite(lo[c]) || !isfinite(hi[c]))
                abort();
    }
    obj_round_trip(s);
    bs_surface_destroy(s);
    return 0;
}
