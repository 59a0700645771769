/* The built-in surfaces: Newell's tea set, parsed from the .bpt texts compiled into the library. */
#include "io/internal.h"

#include <string.h>

bs_status bs_surface_create_builtin(const char *name, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (name == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    for (size_t k = 0; k < bsi_builtin_count; k++)
        if (strcmp(name, bsi_builtins[k].name) == 0) {
            bs_status st = bs_surface_read_bpt(bsi_builtins[k].text, bsi_builtins[k].len, NULL, out);
            /* The embedded texts are valid: only an allocation can fail. */
            return st == BS_OK ? BS_OK : BS_ERR_NO_MEMORY;
        }
    return BS_ERR_INVALID_ARG;
}

const char *bs_builtin_name(size_t i)
{
    return i < bsi_builtin_count ? bsi_builtins[i].name : NULL;
}
