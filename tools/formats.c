/* The surface file formats the tool reads and writes, by name and by file extension. */
#include "cmds.h"

#include <ctype.h>
#include <string.h>

/* STEP and IGES files hold trimmed models: as surfaces, their faces' patches. (The model is
 * passed by address: it is set by the read, which must happen before it is looked at.) */
static bs_status surface_of_model(bs_status st, bs_model **m, bs_surface **out)
{
    if (st == BS_OK)
        st = bs_surface_clone(bs_model_surface(*m), out);
    bs_model_destroy(*m);
    return st;
}

static bs_status step_read(const char *text, size_t len, bs_parse_error *err, bs_surface **out)
{
    bs_model *m = NULL;
    *out = NULL;
    return surface_of_model(bs_model_read_step(text, len, err, &m), &m, out);
}

static bs_status step_read_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    bs_model *m = NULL;
    *out = NULL;
    return surface_of_model(bs_model_read_step_file(path, err, &m), &m, out);
}

/* IGES through the model reader (trimmed surfaces, B-reps, B-splines), the 1.1 surface reader
 * when the model reader refuses the file (its error is the one reported if both do). */
static bs_status iges_read(const char *text, size_t len, bs_parse_error *err, bs_surface **out)
{
    bs_model *m = NULL;
    *out = NULL;
    bs_status st = surface_of_model(bs_model_read_iges(text, len, err, &m), &m, out);
    if (st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED) {
        bs_parse_error second;
        if (bs_surface_read_iges(text, len, &second, out) == BS_OK)
            return BS_OK;
    }
    return st;
}

static bs_status iges_read_file(const char *path, bs_parse_error *err, bs_surface **out)
{
    bs_model *m = NULL;
    *out = NULL;
    bs_status st = surface_of_model(bs_model_read_iges_file(path, err, &m), &m, out);
    if (st == BS_ERR_PARSE || st == BS_ERR_UNSUPPORTED) {
        bs_parse_error second;
        if (bs_surface_read_iges_file(path, &second, out) == BS_OK)
            return BS_OK;
    }
    return st;
}

static const cli_format formats[] = {
    {"bpt", ".bpt", bs_surface_read_bpt, bs_surface_read_bpt_file, bs_surface_write_bpt_file, NULL, NULL},
    {"obj", ".obj", bs_surface_read_obj, bs_surface_read_obj_file, bs_surface_write_obj_file,
     bs_model_read_obj, bs_model_read_obj_file},
    {"iges", ".igs .iges", iges_read, iges_read_file, NULL, bs_model_read_iges, bs_model_read_iges_file},
    {"step", ".step .stp", step_read, step_read_file, NULL, bs_model_read_step, bs_model_read_step_file},
};

const cli_format *cli_format_named(const char *name)
{
    for (size_t k = 0; k < sizeof formats / sizeof formats[0]; k++)
        if (strcmp(name, formats[k].name) == 0)
            return &formats[k];
    if (strcmp(name, "igs") == 0)
        return cli_format_named("iges");
    return strcmp(name, "stp") == 0 ? cli_format_named("step") : NULL;
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
