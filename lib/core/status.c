/* Status texts and the run-time version. */
#include "core/internal.h"

unsigned bs_version_number(void) { return BS_VERSION_NUMBER; }

const char *bs_version_string(void) { return BS_VERSION_STRING; }

const char *bs_status_string(bs_status s)
{
    switch (s) {
    case BS_OK:               return "success";
    case BS_ERR_INVALID_ARG:  return "invalid argument";
    case BS_ERR_NO_MEMORY:    return "out of memory";
    case BS_ERR_DEGREE:       return "degree or derivative order out of range";
    case BS_ERR_DIMENSION:    return "dimension out of range";
    case BS_ERR_SIZE:         return "buffer or view too small";
    case BS_ERR_DOMAIN:       return "parameter outside its allowed range";
    case BS_ERR_NONFINITE:    return "non-finite control point or invalid weight";
    case BS_ERR_PARSE:        return "malformed input";
    case BS_ERR_IO:           return "input/output error";
    case BS_ERR_INCOMPATIBLE: return "incompatible objects";
    case BS_ERR_UNSUPPORTED:  return "operation not supported for this input";
    case BS_ERR_PRECISION:    return "result cannot be certified in double precision for this input";
    default:                  return "unknown status";
    }
}
