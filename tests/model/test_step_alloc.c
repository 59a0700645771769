/* The STEP reader when memory runs out: each allocation of a read failing in turn must give
 * BS_ERR_NO_MEMORY and no model (and, under the sanitizers and valgrind, no leak); then the read
 * succeeds. Files: the cone and the sphere of data/cad (PCURVEs, vertex loops), the torus without
 * PCURVEs (projected edges), and a small text with a hole, a void and the lexer's forms. */
#include "harness.h"

#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef BS_WRAP_MALLOC
void *__real_malloc(size_t n);
void *__wrap_malloc(size_t n);
void *__real_calloc(size_t n, size_t k);
void *__wrap_calloc(size_t n, size_t k);
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static size_t fail_in;
static int fails(void) { return fail_in != 0 && --fail_in == 0; }
void *__wrap_malloc(size_t n) { return fails() ? NULL : __real_malloc(n); }
void *__wrap_calloc(size_t n, size_t k) { return fails() ? NULL : __real_calloc(n, k); }
void *__wrap_realloc(void *p, size_t n) { return fails() ? NULL : __real_realloc(p, n); }

/* data/cad/NAME, or tests/model/NAME when it names a folder. */
static char *read_text(const char *name, size_t *len)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", strchr(name, '/') ? BS_TEST_SOURCE_DIR : BS_CAD_DIR, name);
    FILE *f = fopen(path, "rb");
    static char buf[1 << 16];
    *len = f != NULL ? fread(buf, 1, sizeof buf - 1, f) : 0;
    if (f != NULL)
        fclose(f);
    buf[*len] = '\0';
    return *len > 0 ? buf : NULL;
}

/* Fail the 1st, 2nd, ... allocation (every `stride`-th) until the read succeeds. */
static void run(const char *what, const char *text, size_t len, size_t stride)
{
    size_t k = 1, failures = 0;
    for (;; k += stride) {
        bs_model *m = NULL;
        bs_parse_error err;
        fail_in = k;
        bs_status st = bs_model_read_step(text, len, &err, &m);
        int hit = fail_in == 0;
        fail_in = 0;
        if (!hit) {
            CHECKF(st == BS_OK && m != NULL, "%s: status %d with no allocation failed (%s)", what, st, err.message);
            bs_model_destroy(m);
            break;
        }
        if (st == BS_OK) { /* a failure the reader may recover from (none expected) */
            bs_model_destroy(m);
            continue;
        }
        failures++;
        CHECKF(st == BS_ERR_NO_MEMORY && m == NULL, "%s: allocation %zu failed: status %d (%s)", what, k, st,
               st == BS_ERR_PARSE ? err.message : "");
    }
    printf("%s: %zu allocation failures, each BS_ERR_NO_MEMORY\n", what, failures);
    CHECK(failures > 0);
}
#endif

int main(void)
{
#ifdef BS_WRAP_MALLOC
    size_t stride = bs_test_quick() ? 7 : 1, len;
    static const char *const files[] = {"cone.step", "sphere.step", "torus-3d-edges.step",
                                                 "data/step/assembly.step"};
    for (size_t f = 0; f < sizeof files / sizeof files[0]; f++) {
        const char *text = read_text(files[f], &len);
        CHECKF(text != NULL, "%s not read", files[f]);
        if (text != NULL)
            run(files[f], text, len, stride);
    }
    static const char small[] =
        "ISO-10303-21;\nHEADER;\nFILE_NAME('a''b',(''),$,*,.E.,(1,2.5,#3));\nENDSEC;\nDATA(('x'),('y'));\n"
        "#1 = BREP_WITH_VOIDS('',#2,(#90));\n#90 = ORIENTED_CLOSED_SHELL('',*,#2,.F.);\n"
        "#2 = CLOSED_SHELL('',(#3));\n#3 = ADVANCED_FACE('',(#80,#4),#6,.T.);\n#4 = FACE_BOUND('',#5,.T.);\n"
        "#5 = EDGE_LOOP('',(#11,#12,#13,#14));\n#6 = ( PLANE('',#7) SURFACE() );\n#7 = AXIS2_PLACEMENT_3D('',#8,$,$);\n"
        "#8 = CARTESIAN_POINT('',(0.,0.,0.));\n#11 = ORIENTED_EDGE('',*,*,#21,.T.);\n#12 = ORIENTED_EDGE('',*,*,#22,.T.);\n"
        "#13 = ORIENTED_EDGE('',*,*,#23,.T.);\n#14 = ORIENTED_EDGE('',*,*,#24,.T.);\n#21 = EDGE_CURVE('',#31,#32,#41,.T.);\n"
        "#22 = EDGE_CURVE('',#32,#33,#42,.T.);\n#23 = EDGE_CURVE('',#33,#34,#43,.T.);\n#24 = EDGE_CURVE('',#34,#31,#44,.T.);\n"
        "#31 = VERTEX_POINT('',#8);\n#32 = VERTEX_POINT('',#52);\n#33 = VERTEX_POINT('',#53);\n#34 = VERTEX_POINT('',#54);\n"
        "#41 = LINE('',#8,#61);\n#42 = LINE('',#52,#62);\n#43 = LINE('',#53,#63);\n#44 = LINE('',#54,#64);\n"
        "#52 = CARTESIAN_POINT('',(2.,0.,0.));\n#53 = CARTESIAN_POINT('',(2.,2.,0.));\n#54 = CARTESIAN_POINT('',(0.,2.,0.));\n"
        "#61 = VECTOR('',#71,2.);\n#62 = VECTOR('',#72,2.);\n#63 = VECTOR('',#73,2.);\n#64 = VECTOR('',#74,2.);\n"
        "#71 = DIRECTION('',(1.,0.,0.));\n#72 = DIRECTION('',(0.,1.,0.));\n#73 = DIRECTION('',(-1.,0.,0.));\n"
        "#74 = DIRECTION('',(0.,-1.,0.));\n#80 = FACE_BOUND('',#81,.T.);\n#81 = EDGE_LOOP('',(#82));\n"
        "#82 = ORIENTED_EDGE('',*,*,#83,.F.);\n#83 = EDGE_CURVE('',#84,#84,#85,.T.);\n#84 = VERTEX_POINT('',#86);\n"
        "#85 = CIRCLE('',#87,0.5);\n#86 = CARTESIAN_POINT('',(1.5,1.,0.));\n#87 = AXIS2_PLACEMENT_3D('',#88,$,$);\n"
        "#88 = CARTESIAN_POINT('',(1.,1.,0.));\nENDSEC;\nEND-ISO-10303-21;\n";
    run("square with a hole", small, strlen(small), 1);
#endif
    return bs_test_exit("test_step_alloc");
}
