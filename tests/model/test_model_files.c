/* The same geometry from every file of a part: each CAD part of data/cad/ is read from all of its
 * files (NAME.step, NAME-3d-edges.step, NAME.igs, NAME-brep.igs), and for every ordered pair (A, B)
 * of its models, points sampled inside the faces of A lie on the patches of B within 1e-9 of the
 * part's size. Each model also gives the .ref's face count, closed shells (STEP and B-rep files),
 * and the .ref's area and volume.
 *
 * The closest point on B's patches must also lie on the face of B holding its patch: the public
 * API maps native parameters to patches (bs_model_face_to_patch) but not back, so its native
 * parameters are found here (nearest point of a grid over the face's box, then Gauss-Newton steps
 * on bs_model_face_eval) and classified by bs_model_classify: INSIDE or ON, within 1e-7 D.
 *
 * STEP files count only once the STEP reader reads the cone (before that, every STEP file is
 * refused as BS_ERR_UNSUPPORTED and is reported, not failed). */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FILES = 4, MAX_SAMPLES = 16 * 16 };

typedef struct part_ref {
    size_t faces;
    double area, volume, diag;
} part_ref;

typedef struct loaded {
    const char *suffix;
    int step;      /* a STEP file */
    int topology;  /* a file whose shells must close: STEP and IGES 186 */
    bs_model *m;
} loaded;

/* Face count, area, volume and the box's diagonal from NAME.ref. */
static int read_ref(const char *part, part_ref *r)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s.ref", BS_CAD_DIR, part);
    FILE *f = fopen(path, "r");
    double b[6];
    int ok = f != NULL &&
             fscanf(f, "%*[^\n]\nfaces %zu area %lf volume %lf box %lf %lf %lf %lf %lf %lf", &r->faces, &r->area,
                    &r->volume, &b[0], &b[1], &b[2], &b[3], &b[4], &b[5]) == 9;
    if (f != NULL)
        fclose(f);
    if (ok)
        r->diag = sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) + (b[5] - b[2]) * (b[5] - b[2]));
    return ok;
}

/* The STEP reader reads the parts once it no longer refuses the cone as unsupported. */
static int step_reads(void)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/cone.step", BS_CAD_DIR);
    bs_model *m = NULL;
    bs_status st = bs_model_read_step_file(path, NULL, &m);
    bs_model_destroy(m);
    return st != BS_ERR_UNSUPPORTED;
}

/* The points of face `face` of m on an n x n grid of its native box that classify INSIDE:
 * their native parameters and positions. Returns the number kept. */
static size_t face_samples(const bs_model *m, size_t face, size_t n, double tol, double *u, double *v,
                           double pos[3][MAX_SAMPLES])
{
    bs_face_info fi;
    memset(&fi, 0, sizeof fi);
    fi.size = sizeof fi;
    if (bs_model_face_info(m, face, &fi) != BS_OK)
        return 0;
    uint32_t faces[MAX_SAMPLES];
    unsigned char where[MAX_SAMPLES];
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++, k++) {
            /* cell centres, nudged off a regular lattice so no sample sits on a seam or a symmetry */
            u[k] = fi.u0 + (fi.u1 - fi.u0) * ((double)i + 0.5 + 0.01 * (double)j / (double)n) / (double)n;
            v[k] = fi.v0 + (fi.v1 - fi.v0) * ((double)j + 0.5 + 0.013 * (double)i / (double)n) / (double)n;
            faces[k] = (uint32_t)face;
        }
    bs_cview cu = {u, k, 0}, cv = {v, k, 0};
    if (bs_model_classify(m, k, faces, &cu, &cv, tol, where) != BS_OK)
        return 0;
    size_t kept = 0;
    for (size_t i = 0; i < k; i++)
        if (where[i] == BS_TRIM_INSIDE) {
            u[kept] = u[i];
            v[kept] = v[i];
            kept++;
        }
    bs_view p[3] = {{pos[0], kept, 0}, {pos[1], kept, 0}, {pos[2], kept, 0}};
    bs_cview ku = {u, kept, 0}, kv = {v, kept, 0};
    if (kept > 0 && bs_model_face_eval(m, kept, faces, &ku, &kv, p, NULL, NULL) != BS_OK)
        return 0;
    return kept;
}

/* Where a point of B's surface lies on one of its faces, in native parameters: B's faces with the
 * patches each holds, and per face a grid of native parameters and their points to start from. */
enum { SEED = 16 };

typedef struct inverse {
    const bs_model *m;
    size_t faces;
    uint32_t *face_of;   /* per patch of bs_model_surface(m) */
    double *box;         /* per face: u0 u1 v0 v1 */
    double *seed;        /* per face: SEED^2 x (u, v, x, y, z) */
} inverse;

static int eval1(const bs_model *m, uint32_t face, double u, double v, double *p)
{
    bs_cview cu = {&u, 1, 0}, cv = {&v, 1, 0};
    bs_view pos[3] = {{&p[0], 1, 0}, {&p[1], 1, 0}, {&p[2], 1, 0}};
    return bs_model_face_eval(m, 1, &face, &cu, &cv, pos, NULL, NULL) == BS_OK && !isnan(p[0]);
}

static int inverse_make(const bs_model *m, inverse *inv)
{
    size_t np = bs_surface_count(bs_model_surface(m));
    inv->m = m;
    inv->faces = bs_model_face_count(m);
    inv->face_of = malloc((np + 1) * sizeof *inv->face_of);
    inv->box = malloc((inv->faces + 1) * 4 * sizeof *inv->box);
    inv->seed = malloc((inv->faces + 1) * SEED * SEED * 5 * sizeof *inv->seed);
    if (inv->face_of == NULL || inv->box == NULL || inv->seed == NULL)
        return 0;
    for (size_t f = 0; f < inv->faces; f++) {
        bs_face_info fi;
        memset(&fi, 0, sizeof fi);
        fi.size = sizeof fi;
        if (bs_model_face_info(m, f, &fi) != BS_OK || fi.first_patch + fi.patch_count > np)
            return 0;
        for (size_t k = 0; k < fi.patch_count; k++)
            inv->face_of[fi.first_patch + k] = (uint32_t)f;
        double *b = &inv->box[4 * f];
        b[0] = fi.u0, b[1] = fi.u1, b[2] = fi.v0, b[3] = fi.v1;
        for (size_t i = 0; i < SEED; i++)
            for (size_t j = 0; j < SEED; j++) {
                double *e = &inv->seed[((f * SEED + i) * SEED + j) * 5];
                e[0] = b[0] + (b[1] - b[0]) * ((double)i + 0.5) / SEED;
                e[1] = b[2] + (b[3] - b[2]) * ((double)j + 0.5) / SEED;
                if (!eval1(m, (uint32_t)f, e[0], e[1], &e[2]))
                    e[2] = e[3] = e[4] = INFINITY;
            }
    }
    return 1;
}

static void inverse_free(inverse *inv)
{
    free(inv->face_of);
    free(inv->box);
    free(inv->seed);
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* The native (u, v) of face f whose point is q: the nearest seed, then damped Gauss-Newton steps
 * with difference quotients, kept in the face's box. Returns the distance left. */
static double native_of(const inverse *inv, uint32_t f, const double *q, double *u, double *v)
{
    const double *b = &inv->box[4 * f], *best = NULL;
    for (size_t k = 0; k < SEED * SEED; k++) {
        const double *e = &inv->seed[(f * SEED * SEED + k) * 5];
        if (best == NULL || dist3(&e[2], q) < dist3(&best[2], q))
            best = e;
    }
    double x[2] = {best[0], best[1]}, p[3], left = INFINITY;
    double hu = 1e-7 * (b[1] - b[0]), hv = 1e-7 * (b[3] - b[2]);
    for (int it = 0; it < 40 && eval1(inv->m, f, x[0], x[1], p); it++) {
        left = dist3(p, q);
        double pu[3], pv[3], su = x[0] + hu > b[1] ? -hu : hu, sv = x[1] + hv > b[3] ? -hv : hv;
        if (!eval1(inv->m, f, x[0] + su, x[1], pu) || !eval1(inv->m, f, x[0], x[1] + sv, pv))
            break;
        double a11 = 0, a12 = 0, a22 = 0, g1 = 0, g2 = 0;
        for (int c = 0; c < 3; c++) {
            double du = (pu[c] - p[c]) / su, dv = (pv[c] - p[c]) / sv, r = q[c] - p[c];
            a11 += du * du, a12 += du * dv, a22 += dv * dv, g1 += du * r, g2 += dv * r;
        }
        double lam = 1e-12 * (a11 + a22), det = (a11 + lam) * (a22 + lam) - a12 * a12;
        if (!(det > 0.0))
            break;
        double d1 = ((a22 + lam) * g1 - a12 * g2) / det, d2 = ((a11 + lam) * g2 - a12 * g1) / det;
        double nu = fmin(fmax(x[0] + d1, b[0]), b[1]), nv = fmin(fmax(x[1] + d2, b[2]), b[3]);
        if (nu == x[0] && nv == x[1])
            break;
        x[0] = nu, x[1] = nv;
    }
    *u = x[0];
    *v = x[1];
    return left;
}

/* Points inside every face of A against B: the largest distance to B's patches; each closest
 * point's face of B found from its patch, its native parameters by native_of, and counted in
 * *outside when that face classifies them OUTSIDE (in *lost when they could not be found). */
static double on_other(const bs_model *a, const bs_model *b, size_t n, double diag, size_t *points, size_t *outside,
                       size_t *lost)
{
    bs_locator *L = NULL;
    inverse inv;
    memset(&inv, 0, sizeof inv);
    if (bs_locator_create(bs_model_surface(b), &L) != BS_OK || !inverse_make(b, &inv)) {
        bs_locator_destroy(L);
        inverse_free(&inv);
        return INFINITY;
    }
    double worst = 0.0, u[MAX_SAMPLES], v[MAX_SAMPLES], pos[3][MAX_SAMPLES], dist[MAX_SAMPLES], cp[3][MAX_SAMPLES];
    uint32_t patch[MAX_SAMPLES];
    for (size_t f = 0; f < bs_model_face_count(a); f++) {
        size_t k = face_samples(a, f, n, 1e-7 * diag, u, v, pos);
        CHECKF(k > 0, "face %zu: no sample inside", f);
        bs_cview q[3] = {{pos[0], k, 0}, {pos[1], k, 0}, {pos[2], k, 0}};
        bs_view d = {dist, k, 0}, c[3] = {{cp[0], k, 0}, {cp[1], k, 0}, {cp[2], k, 0}};
        if (k == 0 || bs_locator_closest_point(L, k, q, patch, NULL, &d, c) != BS_OK) {
            worst = INFINITY;
            continue;
        }
        for (size_t i = 0; i < k; i++) {
            worst = isnan(dist[i]) ? INFINITY : fmax(worst, dist[i]);
            if (patch[i] == UINT32_MAX) {
                (*lost)++;
                continue;
            }
            uint32_t g = inv.face_of[patch[i]];
            double x[3] = {cp[0][i], cp[1][i], cp[2][i]}, gu, gv;
            if (native_of(&inv, g, x, &gu, &gv) > 1e-9 * diag) {
                (*lost)++;
                continue;
            }
            unsigned char where = BS_TRIM_OUTSIDE;
            bs_cview cu = {&gu, 1, 0}, cv = {&gv, 1, 0};
            if (bs_model_classify(b, 1, &g, &cu, &cv, 1e-7 * diag, &where) != BS_OK || where == BS_TRIM_OUTSIDE)
                (*outside)++;
        }
        *points += k;
    }
    bs_locator_destroy(L);
    inverse_free(&inv);
    return worst;
}

static double rel(double x, double ref)
{
    return isnan(x) ? INFINITY : fabs(x - ref) / fabs(ref);
}

/* How close a file's area and volume can come to the kernel's (as bindings/python/tests/
 * test_model.py): 1e-9, except the 144 files, whose numbers carry about 10 digits; the files of
 * 3-D edges, whose trims are computed to 1e-7 D of the edges (a trim 1e-7 D off moves the area
 * by up to about 1e-8 of it); and the duct and the bell, whose files' B-spline trims agree with
 * each other to 3e-9 and whose kernel values (the duct's area, the bell's volume) are off by
 * 4e-8 and 2e-8 (ours are stable to 1e-15 between tolerances). */
static void allowed(const char *part, const char *suffix, double *area_tol, double *volume_tol)
{
    int coarse = strcmp(suffix, ".igs") == 0 || strcmp(part, "duct") == 0 || strcmp(part, "bell") == 0;
    int computed = strcmp(suffix, "-3d-edges.step") == 0;
    *area_tol = coarse ? 1e-7 : computed ? 1e-8 : 1e-9;
    *volume_tol = coarse ? 1e-7 : computed ? 1e-8 : 1e-9;
}

static void test_part(const char *part, int step_on, size_t n)
{
    static const char *const suffix[MAX_FILES] = {".step", "-3d-edges.step", ".igs", "-brep.igs"};
    part_ref r;
    CHECKF(read_ref(part, &r), "%s.ref unreadable", part);
    if (r.diag <= 0.0)
        return;
    loaded f[MAX_FILES];
    size_t nf = 0;
    double worst_area = 0.0, worst_volume = 0.0;
    for (size_t k = 0; k < MAX_FILES; k++) {
        char path[512];
        (void)snprintf(path, sizeof path, "%s/%s%s", BS_CAD_DIR, part, suffix[k]);
        int step = k < 2;
        bs_parse_error err;
        memset(&err, 0, sizeof err);
        bs_model *m = NULL;
        bs_status st = step ? bs_model_read_step_file(path, &err, &m) : bs_model_read_iges_file(path, &err, &m);
        if (st != BS_OK) {
            if (step && !step_on)
                printf("  %s%s: not read (status %d, line %zu: %s), not counted\n", part, suffix[k], (int)st, err.line,
                       err.message);
            else
                CHECKF(0, "%s%s: status %d, line %zu column %zu: %s", part, suffix[k], (int)st, err.line, err.column,
                       err.message);
            continue;
        }
        f[nf] = (loaded){suffix[k], step, step || k == 3, m};
        CHECKF(bs_model_face_count(m) == r.faces, "%s%s: %zu faces, %zu in the .ref", part, suffix[k],
               bs_model_face_count(m), r.faces);
        size_t closed = 0, shells = bs_model_shell_count(m);
        for (size_t s = 0; s < shells; s++)
            closed += bs_model_shell_closed(m, s) == 1;
        if (f[nf].topology)
            CHECKF(shells > 0 && closed == shells, "%s%s: %zu of %zu shells closed", part, suffix[k], closed, shells);
        double area = NAN, volume = NAN, at, vt;
        st = bs_model_properties(m, 1e-10, &area, &volume, NULL);
        allowed(part, suffix[k], &at, &vt);
        double ea = rel(area, r.area), ev = closed == shells && shells > 0 ? rel(volume, r.volume) : NAN;
        CHECKF(st == BS_OK && ea <= at, "%s%s: area %.15g, %.15g in the .ref (%.2g off, %.0e allowed)", part,
               suffix[k], area, r.area, ea, at);
        if (!isnan(ev))
            CHECKF(ev <= vt, "%s%s: volume %.15g, %.15g in the .ref (%.2g off, %.0e allowed)", part, suffix[k],
                   volume, r.volume, ev, vt);
        printf("  %-22s %3zu faces, %zu/%zu shells closed, area %.2e off, volume %s%.2e off\n", path + strlen(BS_CAD_DIR) + 1,
               bs_model_face_count(m), closed, shells, ea, isnan(ev) ? "(open) " : "", isnan(ev) ? 0.0 : ev);
        worst_area = fmax(worst_area, ea);
        if (!isnan(ev))
            worst_volume = fmax(worst_volume, ev);
        nf++;
    }
    double worst = 0.0;
    size_t points = 0, outside = 0, lost = 0;
    for (size_t a = 0; a < nf; a++)
        for (size_t b = 0; b < nf; b++)
            if (a != b) {
                size_t pts = 0, out = 0, lo = 0;
                double d = on_other(f[a].m, f[b].m, n, r.diag, &pts, &out, &lo) / r.diag;
                CHECKF(d <= 1e-9, "%s%s on %s%s: a point %.3g D off", part, f[a].suffix, part, f[b].suffix, d);
                CHECKF(out == 0 && lo == 0, "%s%s on %s%s: %zu of %zu points outside the face of their closest point, "
                       "%zu not found on it", part, f[a].suffix, part, f[b].suffix, out, pts, lo);
                worst = fmax(worst, d);
                points += pts;
                outside += out;
                lost += lo;
            }
    printf("%-7s %zu files, %zu pairs, %7zu points, worst distance %.2e D, %zu outside their face, %zu not found; "
           "worst area %.2e, volume %.2e relative\n",
           part, nf, nf * (nf - 1), points, worst, outside, lost, worst_area, worst_volume);
    for (size_t k = 0; k < nf; k++)
        bs_model_destroy(f[k].m);
}

int main(void)
{
    static const char *const parts[] = {"bottle", "block", "sphere", "torus", "cone", "wedge", "bell", "duct"};
    int quick = bs_test_quick(), step_on = step_reads();
    printf("STEP files %s\n", step_on ? "read and counted" : "not read yet (BS_ERR_UNSUPPORTED): reported only");
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        const char *p = parts[k];
        int small = strcmp(p, "sphere") == 0 || strcmp(p, "cone") == 0 || strcmp(p, "wedge") == 0;
        if (quick && !small)
            continue;
        test_part(p, step_on, quick ? 4 : 6);
    }
    return bs_test_exit("test_model_files");
}
