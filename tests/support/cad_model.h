/* The CAD parts of data/cad/ read as models, and their .ref files, shared by the model tests (BS_CAD_DIR set by
 * tests/model/CMakeLists.txt; harness.h included before). */
#ifndef BS_TEST_CAD_MODEL_H
#define BS_TEST_CAD_MODEL_H

#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* data/cad/FILE as a model (STEP or IGES by its name); NULL, after a failed check, if not read. */
static inline bs_model *read_model(const char *file)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", BS_CAD_DIR, file);
    bs_model *m = NULL;
    bs_status st = strstr(file, ".step") ? bs_model_read_step_file(path, NULL, &m)
                                          : bs_model_read_iges_file(path, NULL, &m);
    CHECKF(st == BS_OK, "%s: %s", file, bs_status_string(st));
    return m;
}

/* data/cad/PART.ref (the kernel's answers) opened for reading; NULL, after a failed check, if
 * not found. */
static inline FILE *open_ref(const char *part)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s.ref", BS_CAD_DIR, part);
    FILE *f = fopen(path, "r");
    CHECKF(f != NULL, "%s not found", path);
    return f;
}

/* 1 when line is the .ref's "box x0 y0 z0 x1 y1 z1" line; *diag receives its diagonal. */
static inline int ref_box_diagonal(const char *line, double *diag)
{
    double b[6];
    if (sscanf(line, "box %lf %lf %lf %lf %lf %lf", &b[0], &b[1], &b[2], &b[3], &b[4], &b[5]) != 6)
        return 0;
    *diag = sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) + (b[5] - b[2]) * (b[5] - b[2]));
    return 1;
}

#endif
