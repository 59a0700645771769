/* The surface file formats the tool reads and writes, by name and by file extension. */
#include "cmds.h"

#include <ctype.h>
#include <string.h>

static const cli_format formats[] = {
    {"bpt", ".bpt", bs_surface_read_bpt, bs_surface_read_bpt_file, bs_surface_write_bpt_file},
    {"obj", ".obj", bs_surface_read_obj, bs_surface_read_obj_file, bs_surface_write_obj_file},
    {"iges", ".igs .iges", bs_surface_read_iges, bs_surface_read_iges_file, NULL},
};

const cli_format *cli_format_named(const char *name)
{
    for (size_t k = 0; k < sizeof formats / sizeof formats[0]; k++)
        if (strcmp(name, formats[k].name) == 0)
            return &formats[k];
    return strcmp(name, "igs") == 0 ? cli_format_named("iges") : NULL;
}

const cli_format *cli_format_of_path(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (dot == NULL || (slash != NULL && dot < slash) || strlen(dot) > 8)
        return NULL;
    char ext[10];
    size_t n = 0;
    for (const char *c = dot; *c; c++)
        ext[n++] = (char)tolower((unsigned char)*c);
    ext[n] = '\0';
    for (size_t k = 0; k < sizeof formats / sizeof formats[0]; k++) {
        const char *list = formats[k].exts; /* space-separated */
        for (const char *e = list; *e;) {
            size_t len = strcspn(e, " ");
            if (len == n && strncmp(e, ext, n) == 0)
                return &formats[k];
            e += len + (e[len] == ' ');
        }
    }
    return NULL;
}
