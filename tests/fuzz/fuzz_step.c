/* libFuzzer target for the STEP reader: any byte string must read or fail cleanly (no model, a
 * position with every parse error); a model read must answer for each face its info and the point
 * at the middle of its parameter box (finite, or NaN outside its patches). */
#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bs_model *m = NULL;
    bs_parse_error err;
    bs_status st = bs_model_read_step((const char *)data, size, &err, &m);
    if (st != BS_OK) {
        if (m != NULL || ((st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED) && (err.line == 0 || err.column == 0)))
            abort();
        return 0;
    }
    for (size_t f = 0; f < bs_model_face_count(m); f++) {
        bs_face_info fi;
        memset(&fi, 0, sizeof fi);
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK || !(fi.u0 < fi.u1) || !(fi.v0 < fi.v1))
            abort();
        double u = 0.5 * (fi.u0 + fi.u1), v = 0.5 * (fi.v0 + fi.v1), p[3];
        uint32_t face = (uint32_t)f;
        bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
        bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
        if (bs_model_face_eval(m, 1, &face, &cu, &cv, pos, NULL, NULL) != BS_OK)
            abort();
        for (int c = 0; c < 3; c++)
            if (isinf(p[c]))
                abort();
    }
    bs_model_destroy(m);
    return 0;
}
