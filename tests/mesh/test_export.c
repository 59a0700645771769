/* Mesh export: OBJ, PLY (binary and ASCII) and binary STL, read back by strict readers written
 * here (exact headers, exact sizes, every number parsed in full) and compared with the mesh;
 * memory output equal to file output; the size query; every error path. */
#include "harness.h"
#include "bpt_reader.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct mesh_copy {
    size_t nv, nt;
    double *pos, *nrm, *uv;
    uint32_t *tri, *vpatch;
} mesh_copy;

static void copy_mesh(const bs_mesh *m, mesh_copy *c)
{
    c->nv = bs_mesh_vertex_count(m);
    c->nt = bs_mesh_triangle_count(m);
    c->pos = malloc(3 * c->nv * sizeof(double) + 1);
    c->nrm = malloc(3 * c->nv * sizeof(double) + 1);
    c->uv = malloc(2 * c->nv * sizeof(double) + 1);
    c->tri = malloc(3 * c->nt * sizeof(uint32_t) + 1);
    c->vpatch = malloc(c->nv * sizeof(uint32_t) + 1);
    ptrdiff_t s3 = 3 * sizeof(double), s2 = 2 * sizeof(double);
    bs_view p[3] = {{c->pos, c->nv, s3}, {c->pos + 1, c->nv, s3}, {c->pos + 2, c->nv, s3}};
    bs_view n[3] = {{c->nrm, c->nv, s3}, {c->nrm + 1, c->nv, s3}, {c->nrm + 2, c->nv, s3}};
    bs_view uv[2] = {{c->uv, c->nv, s2}, {c->uv + 1, c->nv, s2}};
    CHECK_STATUS(bs_mesh_copy_positions(m, p), BS_OK);
    CHECK_STATUS(bs_mesh_copy_normals(m, n), BS_OK);
    CHECK_STATUS(bs_mesh_copy_uv(m, uv), BS_OK);
    CHECK_STATUS(bs_mesh_copy_triangles(m, c->tri, 3 * c->nt), BS_OK);
    CHECK_STATUS(bs_mesh_copy_patch_ids(m, c->vpatch, c->nv), BS_OK);
}

static void free_copy(mesh_copy *c)
{
    free(c->pos); free(c->nrm); free(c->uv); free(c->tri); free(c->vpatch);
}

/* The bytes of a format, through the memory interface (asking for the size first). */
static unsigned char *to_memory(const bs_mesh *m, int format, size_t *size)
{
    *size = 0;
    CHECK_STATUS(bs_mesh_write_memory(m, format, NULL, 0, size), BS_OK);
    unsigned char *buf = malloc(*size + 1);
    size_t got = 0;
    CHECK_STATUS(bs_mesh_write_memory(m, format, buf, *size, &got), BS_OK);
    CHECK(got == *size);
    return buf;
}

static unsigned char *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    *size = 0;
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = malloc((size_t)n + 1);
    *size = fread(buf, 1, (size_t)n, f);
    fclose(f);
    return buf;
}

/* Strict number parsing: the whole token must be a number. */
static int parse_double(const char *tok, double *x)
{
    char *end;
    *x = strtod(tok, &end);
    return end != tok && *end == '\0';
}

static int parse_index(const char *tok, size_t *x)
{
    char *end;
    if (*tok < '0' || *tok > '9')
        return 0;
    unsigned long long v = strtoull(tok, &end, 10);
    *x = (size_t)v;
    return *end == '\0';
}

/* Next space-separated token of *p (modified), or NULL. Two spaces in a row are malformed: they
 * give an empty token. */
static char *next_tok(char **p)
{
    if (*p == NULL)
        return NULL;
    char *tok = *p, *sp = strchr(tok, ' ');
    if (sp != NULL) {
        *sp = '\0';
        *p = sp + 1;
    } else {
        *p = NULL;
    }
    return tok;
}

/* Split buf (NUL-terminated, modified) into lines; returns the count. */
static size_t split_lines(char *buf, char **lines, size_t max)
{
    size_t n = 0;
    char *p = buf;
    while (*p && n < max) {
        lines[n++] = p;
        char *e = strchr(p, '\n');
        if (e == NULL)
            break;
        *e = '\0';
        p = e + 1;
    }
    return n;
}

static void check_obj(const mesh_copy *c, unsigned char *bytes, size_t size)
{
    char *text = malloc(size + 1);
    memcpy(text, bytes, size);
    text[size] = '\0';
    CHECK(size > 0 && text[size - 1] == '\n');
    size_t maxl = 4 * c->nv + c->nt + 8;
    char **lines = malloc(maxl * sizeof(char *));
    size_t nl = split_lines(text, lines, maxl);
    size_t nv = 0, nvt = 0, nvn = 0, nf = 0, bad = 0, mismatch = 0;
    for (size_t l = 0; l < nl; l++) {
        char *save = lines[l], *tag = next_tok(&save);
        if (tag == NULL || tag[0] == '#')
            continue;
        char *tok[4];
        size_t nt = 0;
        while (nt < 4 && (tok[nt] = next_tok(&save)) != NULL)
            nt++;
        if (strcmp(tag, "v") == 0 || strcmp(tag, "vn") == 0 || strcmp(tag, "vt") == 0) {
            size_t want = strcmp(tag, "vt") == 0 ? 2 : 3;
            size_t *cnt = tag[1] == '\0' ? &nv : tag[1] == 't' ? &nvt : &nvn;
            const double *ref = tag[1] == '\0' ? c->pos : tag[1] == 't' ? c->uv : c->nrm;
            if (nt != want || *cnt >= c->nv) {
                bad++;
                continue;
            }
            for (size_t k = 0; k < want; k++) {
                double x;
                if (!parse_double(tok[k], &x))
                    bad++;
                else if (x != ref[want * *cnt + k]) /* 17 digits: exact round trip */
                    mismatch++;
            }
            (*cnt)++;
        } else if (strcmp(tag, "f") == 0) {
            if (nt != 3 || nf >= c->nt) {
                bad++;
                continue;
            }
            for (size_t k = 0; k < 3; k++) {
                char *s1 = strchr(tok[k], '/'), *s2 = s1 ? strchr(s1 + 1, '/') : NULL;
                if (s1 == NULL || s2 == NULL) {
                    bad++;
                    continue;
                }
                *s1 = *s2 = '\0';
                size_t a, b, d;
                if (!parse_index(tok[k], &a) || !parse_index(s1 + 1, &b) || !parse_index(s2 + 1, &d) || a != b ||
                    a != d || a < 1 || a > c->nv)
                    bad++;
                else if (a - 1 != c->tri[3 * nf + k])
                    mismatch++;
            }
            nf++;
        } else {
            bad++;
        }
    }
    CHECKF(bad == 0 && mismatch == 0, "OBJ: %zu malformed, %zu mismatched", bad, mismatch);
    CHECK(nv == c->nv && nvt == c->nv && nvn == c->nv && nf == c->nt);
    free(lines);
    free(text);
}

static uint32_t get_u32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static float get_f32(const unsigned char *b)
{
    uint32_t u = get_u32(b);
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static const char *ply_header(const mesh_copy *c, int binary, char *out, size_t cap)
{
    snprintf(out, cap,
             "ply\nformat %s 1.0\ncomment libbezsurf mesh\nelement vertex %zu\n"
             "property float x\nproperty float y\nproperty float z\n"
             "property float nx\nproperty float ny\nproperty float nz\n"
             "property float u\nproperty float v\nproperty uint patch\nelement face %zu\n"
             "property list uchar uint vertex_indices\nend_header\n",
             binary ? "binary_little_endian" : "ascii", c->nv, c->nt);
    return out;
}

static double vertex_prop(const mesh_copy *c, size_t k, size_t p)
{
    return p < 3 ? c->pos[3 * k + p] : p < 6 ? c->nrm[3 * k + p - 3] : c->uv[2 * k + p - 6];
}

static void check_ply_binary(const mesh_copy *c, const unsigned char *b, size_t size)
{
    char head[1024];
    ply_header(c, 1, head, sizeof head);
    size_t hl = strlen(head);
    CHECK(size >= hl && memcmp(b, head, hl) == 0);
    CHECKF(size == hl + 36 * c->nv + 13 * c->nt, "PLY size %zu", size);
    if (size != hl + 36 * c->nv + 13 * c->nt)
        return;
    const unsigned char *p = b + hl;
    size_t mismatch = 0;
    for (size_t k = 0; k < c->nv; k++, p += 36) {
        for (size_t q = 0; q < 8; q++)
            mismatch += get_f32(p + 4 * q) != (float)vertex_prop(c, k, q);
        mismatch += get_u32(p + 32) != c->vpatch[k];
    }
    for (size_t t = 0; t < c->nt; t++, p += 13) {
        mismatch += p[0] != 3;
        for (size_t q = 0; q < 3; q++)
            mismatch += get_u32(p + 1 + 4 * q) != c->tri[3 * t + q];
    }
    CHECKF(mismatch == 0, "PLY binary: %zu mismatches", mismatch);
}

static void check_ply_ascii(const mesh_copy *c, const unsigned char *b, size_t size)
{
    char head[1024];
    ply_header(c, 0, head, sizeof head);
    size_t hl = strlen(head);
    CHECK(size >= hl && memcmp(b, head, hl) == 0);
    char *text = malloc(size + 1);
    memcpy(text, b, size);
    text[size] = '\0';
    size_t maxl = c->nv + c->nt + 2;
    char **lines = malloc(maxl * sizeof(char *));
    size_t nl = split_lines(text + hl, lines, maxl);
    CHECKF(nl == c->nv + c->nt, "PLY ASCII: %zu lines", nl);
    size_t bad = 0, mismatch = 0;
    for (size_t l = 0; l < nl && l < c->nv + c->nt; l++) {
        char *save = lines[l], *tok[10];
        size_t nt = 0;
        for (char *x = next_tok(&save); x != NULL && nt < 10; x = next_tok(&save))
            tok[nt++] = x;
        if (l < c->nv) {
            if (nt != 9) {
                bad++;
                continue;
            }
            for (size_t q = 0; q < 8; q++) {
                double x, want = vertex_prop(c, l, q);
                if (!parse_double(tok[q], &x))
                    bad++;
                else if (fabs(x - want) > 1e-8 * fmax(fabs(want), 1e-30))
                    mismatch++;
            }
            size_t id;
            if (!parse_index(tok[8], &id) || id != c->vpatch[l])
                bad++;
        } else {
            size_t t = l - c->nv, x;
            if (nt != 4 || strcmp(tok[0], "3") != 0) {
                bad++;
                continue;
            }
            for (size_t q = 0; q < 3; q++)
                if (!parse_index(tok[q + 1], &x) || x != c->tri[3 * t + q])
                    mismatch++;
        }
    }
    CHECKF(bad == 0 && mismatch == 0, "PLY ASCII: %zu malformed, %zu mismatched", bad, mismatch);
    free(lines);
    free(text);
}

static void check_stl(const mesh_copy *c, const unsigned char *b, size_t size)
{
    CHECKF(size == 84 + 50 * c->nt, "STL size %zu", size);
    if (size != 84 + 50 * c->nt)
        return;
    CHECK(get_u32(b + 80) == c->nt);
    size_t mismatch = 0, badnormal = 0, against = 0;
    for (size_t t = 0; t < c->nt; t++) {
        const unsigned char *p = b + 84 + 50 * t;
        double n[3] = {get_f32(p), get_f32(p + 4), get_f32(p + 8)}, len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        badnormal += !(fabs(len - 1.0) < 1e-6);
        for (size_t k = 0; k < 3; k++)
            for (size_t q = 0; q < 3; q++)
                mismatch += get_f32(p + 12 + 12 * k + 4 * q) != (float)c->pos[3 * (size_t)c->tri[3 * t + k] + q];
        /* The facet normal agrees in direction with the vertex normals (counter-clockwise winding). */
        double avg = 0.0;
        for (size_t k = 0; k < 3; k++)
            for (size_t q = 0; q < 3; q++)
                avg += n[q] * c->nrm[3 * (size_t)c->tri[3 * t + k] + q];
        against += avg < 0.0;
        mismatch += p[48] != 0 || p[49] != 0;
    }
    CHECKF(mismatch == 0 && badnormal == 0, "STL: %zu mismatches, %zu bad normals", mismatch, badnormal);
    CHECKF(against * 100 <= c->nt, "STL: %zu of %zu facets against the vertex normals", against, c->nt);
}

static void round_trip(const bs_mesh *m, const char *dir)
{
    mesh_copy c;
    copy_mesh(m, &c);
    static const int formats[4] = {BS_MESH_OBJ, BS_MESH_PLY, BS_MESH_PLY_ASCII, BS_MESH_STL};
    static const char *names[4] = {"mesh.obj", "mesh.ply", "mesh_ascii.ply", "mesh.stl"};
    for (int f = 0; f < 4; f++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[f]);
        CHECK_STATUS(bs_mesh_write(m, formats[f], path), BS_OK);
        size_t fsize, msize;
        unsigned char *fb = read_file(path, &fsize), *mb = to_memory(m, formats[f], &msize);
        CHECK(fb != NULL && fsize == msize && memcmp(fb, mb, fsize) == 0);
        switch (formats[f]) {
        case BS_MESH_OBJ: check_obj(&c, mb, msize); break;
        case BS_MESH_PLY: check_ply_binary(&c, mb, msize); break;
        case BS_MESH_PLY_ASCII: check_ply_ascii(&c, mb, msize); break;
        default: check_stl(&c, mb, msize); break;
        }
        printf("%s: %zu bytes\n", names[f], msize);
        free(fb);
        free(mb);
        remove(path);
    }
    free_copy(&c);
}

static void errors(const bs_mesh *m)
{
    size_t size = 12345;
    unsigned char small[16];
    memset(small, 0xAB, sizeof small);
    CHECK_STATUS(bs_mesh_write_memory(m, BS_MESH_OBJ, small, sizeof small, &size), BS_ERR_SIZE);
    CHECK(size == 12345 && small[0] == 0xAB && small[15] == 0xAB);
    CHECK_STATUS(bs_mesh_write_memory(m, 7, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_write_memory(m, -1, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_write_memory(NULL, BS_MESH_OBJ, NULL, 0, &size), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_write_memory(m, BS_MESH_OBJ, NULL, 0, NULL), BS_ERR_INVALID_ARG);
    CHECK(size == 12345);
    CHECK_STATUS(bs_mesh_write(m, BS_MESH_STL, "/nonexistent-dir/x/y.stl"), BS_ERR_IO);
    CHECK_STATUS(bs_mesh_write(m, 9, "x.stl"), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_write(NULL, BS_MESH_STL, "x.stl"), BS_ERR_INVALID_ARG);
    CHECK_STATUS(bs_mesh_write(m, BS_MESH_STL, NULL), BS_ERR_INVALID_ARG);
}

/* OBJ numbers in their shortest exact form, as the surface writers print them: 1.4, not
 * 1.3999999999999999; 0.1 + 0.2 needs 17 digits. */
static void shortest_numbers(void)
{
    const double net[12] = {1.4, 0.1 + 0.2, -0.0, 1.4, 2, 0, 2.5, 0.1 + 0.2, 0, 2.5, 2, 0};
    bs_patch *p = NULL;
    bs_surface *s = NULL;
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_patch_create(1, 1, 3, net, NULL, &p), BS_OK);
    CHECK_STATUS(bs_surface_create(&s), BS_OK);
    CHECK_STATUS(bs_surface_add(s, p, NULL), BS_OK);
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 1, 1, 0, &m), BS_OK);
    size_t size = 0;
    CHECK_STATUS(bs_mesh_write_memory(m, BS_MESH_OBJ, NULL, 0, &size), BS_OK);
    char *text = calloc(size + 1, 1);
    CHECK(text != NULL && bs_mesh_write_memory(m, BS_MESH_OBJ, text, size, &size) == BS_OK);
    CHECKF(text && strstr(text, "\nv 1.4 0.30000000000000004 0\n") != NULL && strstr(text, "1.3999") == NULL,
           "%s", text ? text : "");
    free(text);
    bs_mesh_destroy(m);
    bs_surface_destroy(s);
    bs_patch_destroy(p);
}

int main(int argc, char **argv)
{
    shortest_numbers();
    const char *dir = argc > 1 ? argv[1] : ".";
    bs_surface *s = test_load_bpt("teapot.bpt");
    CHECK(s != NULL);
    if (s == NULL)
        return bs_test_exit("test_export");
    bs_mesh *m = NULL;
    CHECK_STATUS(bs_surface_tessellate_uniform(s, 6, 6, 0, &m), BS_OK);
    round_trip(m, dir);
    errors(m);
    bs_mesh_destroy(m);
    /* An empty mesh is a valid file in every format. */
    bs_surface *empty = NULL;
    bs_surface_create(&empty);
    CHECK_STATUS(bs_surface_tessellate_uniform(empty, 2, 2, 0, &m), BS_OK);
    round_trip(m, dir);
    bs_mesh_destroy(m);
    bs_surface_destroy(empty);
    bs_surface_destroy(s);
    return bs_test_exit("test_export");
}
