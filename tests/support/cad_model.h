/* The CAD parts of data/cad/ read as models, shared by the model tests (BS_CAD_DIR set by
 * tests/model/CMakeLists.txt; harness.h included before). */
#ifndef BS_TEST_CAD_MODEL_H
#define BS_TEST_CAD_MODEL_H

#include <bezsurf.h>

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

#endif
