/* Small STEP texts for the model tests: the frame of a file, a cube, and reading a text that must
 * read or must be refused (harness.h included before). */
#ifndef BS_TEST_STEP_TEXT_H
#define BS_TEST_STEP_TEXT_H

#include <bezsurf.h>

#include <stdio.h>
#include <string.h>

#define HEAD "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\nENDSEC;\nDATA;\n"
#define TAIL "ENDSEC;\nEND-ISO-10303-21;\n"

/* The model of a text that must read (NULL and a failure otherwise). */
static inline bs_model *must_read(const char *what, const char *text)
{
    bs_parse_error err;
    bs_model *m = NULL;
    memset(&err, 0, sizeof err);
    bs_status st = text != NULL ? bs_model_read_step(text, strlen(text), &err, &m) : BS_ERR_INVALID_ARG;
    CHECKF(st == BS_OK && m != NULL, "%s: status %d at %zu:%zu %s", what, st, err.line, err.column, err.message);
    return st == BS_OK ? m : NULL;
}

/* A text that must be refused with status, at line (0: not checked), its message naming `names`. */
static inline void must_refuse(const char *what, const char *text, bs_status status, size_t line, const char *names)
{
    bs_parse_error err;
    bs_model *m = (bs_model *)&err; /* must come back NULL */
    memset(&err, 0, sizeof err);
    if (text == NULL)
        return;
    bs_status st = bs_model_read_step(text, strlen(text), &err, &m);
    CHECKF(st == status, "%s: status %d, wanted %d (%zu:%zu %s)", what, st, status, err.line, err.column, err.message);
    CHECKF(m == NULL, "%s: a model with a failure", what);
    if (st == BS_OK)
        bs_model_destroy(m);
    CHECKF(err.line >= 1 && err.column >= 1, "%s: no position (%s)", what, err.message);
    CHECKF(line == 0 || err.line == line, "%s: line %zu, wanted %zu (%s)", what, err.line, line, err.message);
    CHECKF(strstr(err.message, names) != NULL, "%s: '%s' does not name '%s'", what, err.message, names);
}


/* A cube [lo, hi]^3 as a CLOSED_SHELL numbered from base (its id is base), faces outward. */
static inline size_t cube(char *buf, size_t cap, int base, double lo, double hi)
{
    static const int face[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    size_t n = 0;
#define PUT(...) (n += (size_t)snprintf(buf + n, cap > n ? cap - n : 0, __VA_ARGS__))
    PUT("#%d = CLOSED_SHELL('',(#%d,#%d,#%d,#%d,#%d,#%d));\n", base, base + 1, base + 2, base + 3, base + 4, base + 5,
        base + 6);
    for (int v = 0; v < 8; v++) {
        PUT("#%d = CARTESIAN_POINT('',(%.17g,%.17g,%.17g));\n", base + 10 + v, v & 1 ? hi : lo, v & 2 ? hi : lo,
            v & 4 ? hi : lo);
        PUT("#%d = VERTEX_POINT('',#%d);\n", base + 20 + v, base + 10 + v);
    }
    for (int a = 0; a < 3; a++)
        PUT("#%d = DIRECTION('',(%d.,%d.,%d.));\n#%d = DIRECTION('',(%d.,%d.,%d.));\n", base + 30 + a, a == 0, a == 1,
            a == 2, base + 33 + a, -(a == 0), -(a == 1), -(a == 2));
    /* edge from vertex v along bit b: id base + 40 + 3 v + b */
    for (int v = 0; v < 8; v++)
        for (int b = 0; b < 3; b++) {
            if (v & (1 << b))
                continue;
            int e = base + 40 + 3 * v + b, l = base + 70 + 3 * v + b, vec = base + 100 + 3 * v + b;
            PUT("#%d = EDGE_CURVE('',#%d,#%d,#%d,.T.);\n#%d = LINE('',#%d,#%d);\n#%d = VECTOR('',#%d,%.17g);\n", e,
                base + 20 + v, base + 20 + (v | (1 << b)), l, l, base + 10 + v, vec, vec, base + 30 + b, hi - lo);
        }
    for (int f = 0; f < 6; f++) {
        int id = base + 1 + f, axis = f / 2, out = base + 30 + axis + (f % 2 ? 0 : 3);
        PUT("#%d = ADVANCED_FACE('',(#%d),#%d,.T.);\n#%d = FACE_OUTER_BOUND('',#%d,.T.);\n", id, id + 200, id + 210,
            id + 200, id + 220);
        PUT("#%d = PLANE('',#%d);\n#%d = AXIS2_PLACEMENT_3D('',#%d,#%d,$);\n", id + 210, id + 230, id + 230,
            base + 10 + face[f][0], out);
        PUT("#%d = EDGE_LOOP('',(", id + 220);
        for (int k = 0; k < 4; k++) {
            int a = face[f][k], b = face[f][(k + 1) % 4], lo_v = a < b ? a : b, bit = (a ^ b) == 1 ? 0 : (a ^ b) == 2 ? 1 : 2;
            PUT("%s#%d", k ? "," : "", base + 300 + 10 * f + k);
            (void)lo_v;
            (void)bit;
        }
        PUT("));\n");
        for (int k = 0; k < 4; k++) {
            int a = face[f][k], b = face[f][(k + 1) % 4], from = a < b ? a : b, bit = (a ^ b) == 1 ? 0 : (a ^ b) == 2 ? 1 : 2;
            PUT("#%d = ORIENTED_EDGE('',*,*,#%d,%s);\n", base + 300 + 10 * f + k, base + 40 + 3 * from + bit,
                a < b ? ".T." : ".F.");
        }
    }
#undef PUT
    return n;
}

#endif
