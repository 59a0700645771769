/* Faces written by OpenCASCADE (data/faces/, occt_faces_gen.cpp). Sweeps of a closed curve: a
 * circle revolved (a torus written as its tube revolved) and extruded, the faces' ranges along the
 * circle crossing its start. Along the circle the surface is periodic, as the angle of a torus is:
 * from STEP, IGES 144 and IGES B-rep entities, the area is the kernel's, the whole tube's volume
 * the torus's closed form, and a parameter moved by whole periods along the circle is the same
 * point and classifies alike (inside where the face's range, taken round the circle, holds it).
 * IGES B-rep entities without a solid: the lone 510 faces of the sweeps, and an open box as a 514
 * shell no 186 holds. */
#include "harness.h"

#include <bezsurf.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

static bs_model *read_sweep(const char *file)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/data/faces/%s", BS_TEST_SOURCE_DIR, file);
    bs_model *m = NULL;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_status st = strstr(file, ".step") ? bs_model_read_step_file(path, &err, &m) : bs_model_read_iges_file(path, &err, &m);
    CHECKF(st == BS_OK && m != NULL && bs_model_face_count(m) == 1, "%s: status %d (%s)", file, st, err.message);
    return st == BS_OK ? m : NULL;
}

static double ref_value(const char *name, const char *key)
{
    char path[512], line[256], k[32];
    double x = NAN;
    (void)snprintf(path, sizeof path, "%s/data/faces/%s.ref", BS_TEST_SOURCE_DIR, name);
    FILE *f = fopen(path, "r");
    CHECKF(f != NULL, "%s not found", path);
    while (f != NULL && fgets(line, sizeof line, f) != NULL)
        if (sscanf(line, "%31s %lf", k, &x) == 2 && strcmp(k, key) == 0)
            break;
    if (f != NULL)
        fclose(f);
    return strcmp(k, key) == 0 ? x : NAN;
}

/* Grid points of the face's box, each also moved by -2, -1, 1 and 2 periods along direction d:
 * the same point, classified alike. */
static void periodic(const char *file, const bs_model *m, int d, double period)
{
    enum { G = 9, N = G * G, SHIFTS = 5 };
    bs_face_info fi;
    fi.size = sizeof fi;
    CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_OK);
    uint32_t face[N] = {0};
    double uv[SHIFTS][2][N], xyz[SHIFTS][3][N];
    unsigned char where[SHIFTS][N];
    for (int k = 0; k < SHIFTS; k++) {
        for (int i = 0; i < N; i++) {
            uv[k][0][i] = fi.u0 + (fi.u1 - fi.u0) * (i / G + 0.5) / G;
            uv[k][1][i] = fi.v0 + (fi.v1 - fi.v0) * (i % G + 0.5) / G;
            uv[k][d][i] += (k - 2) * period;
        }
        bs_cview u = {uv[k][0], N, sizeof(double)}, v = {uv[k][1], N, sizeof(double)};
        bs_view pos[3] = {{xyz[k][0], N, sizeof(double)}, {xyz[k][1], N, sizeof(double)}, {xyz[k][2], N, sizeof(double)}};
        CHECK_STATUS(bs_model_face_eval(m, N, face, &u, &v, pos, NULL, NULL), BS_OK);
        CHECK_STATUS(bs_model_classify(m, N, face, &u, &v, 1e-9, where[k]), BS_OK);
    }
    int inside = 0;
    for (int i = 0; i < N; i++) {
        inside += where[2][i] == BS_TRIM_INSIDE;
        for (int k = 0; k < SHIFTS; k++) {
            double dist = 0.0;
            for (int c = 0; c < 3; c++)
                dist = hypot(dist, xyz[k][c][i] - xyz[2][c][i]);
            CHECKF(dist <= 1e-12 * 10.0 && where[k][i] == where[2][i],
                   "%s: (%.6g, %.6g) moved by %d periods: %.3g away, class %d, not %d", file, uv[2][0][i], uv[2][1][i],
                   k - 2, dist, where[k][i], where[2][i]);
        }
    }
    CHECKF(inside > N / 2, "%s: %d of %d points of the face's box inside", file, inside, N);
}

/* Native (u, v) that must classify as `want`. */
static void classify_at(const char *file, const bs_model *m, double u, double v, unsigned char want)
{
    uint32_t face = 0;
    unsigned char where = 255;
    bs_cview cu = {&u, 1, sizeof u}, cv = {&v, 1, sizeof v};
    CHECK_STATUS(bs_model_classify(m, 1, &face, &cu, &cv, 1e-9, &where), BS_OK);
    CHECKF(where == want, "%s: (%g, %g) classified %d, not %d", file, u, v, where, want);
}

/* A 514 shell that no 186 holds: the box of 4 x 3 x 2 without its top, five faces, 12 edges (the
 * top's four used once). */
static void test_open_box(void)
{
    bs_model *m = NULL;
    bs_parse_error err;
    memset(&err, 0, sizeof err);
    bs_status st = bs_model_read_iges_file(BS_TEST_SOURCE_DIR "/data/faces/open-box-brep.igs", &err, &m);
    CHECKF(st == BS_OK, "open-box-brep.igs: status %d (%s)", st, err.message);
    if (m == NULL)
        return;
    double area = NAN;
    CHECK_STATUS(bs_model_properties(m, 1e-10, &area, NULL, NULL), BS_OK);
    CHECKF(bs_model_face_count(m) == 5 && bs_model_edge_count(m) == 12 && bs_model_shell_count(m) == 1 &&
               bs_model_shell_closed(m, 0) == 0 && fabs(area - ref_value("open-box", "area")) <= 1e-12 * area,
           "open-box-brep.igs: %zu faces, %zu edges, %zu shells (closed %d), area %.15g", bs_model_face_count(m),
           bs_model_edge_count(m), bs_model_shell_count(m), bs_model_shell_closed(m, 0), area);
    bs_model_destroy(m);
}

int main(void)
{
    static const char *const names[] = {"tube-band", "tube-shift", "tube-full", "pipe-shift"};
    static const char *const ext[] = {".step", ".igs", "-brep.igs"};
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++)
        for (size_t e = 0; e < 3; e++) {
            char file[64];
            (void)snprintf(file, sizeof file, "%s%s", names[n], ext[e]);
            bs_model *m = read_sweep(file);
            if (m == NULL)
                continue;
            /* IGES writes 9 significant digits: its trims carry 1e-9 relative */
            double area = NAN, volume = NAN, rel = e == 0 ? 1e-9 : 1e-8, want = ref_value(names[n], "area");
            CHECK_STATUS(bs_model_properties(m, 1e-10, &area, &volume, NULL), BS_OK);
            CHECKF(fabs(area - want) <= rel * want, "%s: area %.15g, the kernel's %.15g", file, area, want);
            bs_face_info fi;
            fi.size = sizeof fi;
            CHECK_STATUS(bs_model_face_info(m, 0, &fi), BS_OK);
            /* the circle's parameter: native v of a STEP revolution, u of the others (IGES 120
             * is (curve, angle)). IGES writes the tube's band and shifted face on an arc of the
             * circle, not the whole circle: their surfaces end where the arc does. */
            int d = fi.kind == BS_FACE_REVOLUTION && e == 0 ? 1 : 0, whole = e == 0 || n >= 2;
            CHECKF(bs_model_shell_count(m) == 1 && bs_model_shell_closed(m, 0) == (n == 2), "%s: %zu shells, closed %d",
                   file, bs_model_shell_count(m), bs_model_shell_closed(m, 0));
            if (whole)
                periodic(file, m, d, 2.0 * pi);
            if (n == 1 && e == 0) { /* 5 .. 7.5 along the circle holds 0.5 (= 6.78) and 6, not 4 nor 1.5 */
                double other = 0.5 * ((d ? fi.u0 : fi.v0) + (d ? fi.u1 : fi.v1));
                double at[4] = {0.5, 6.0, 4.0, 1.5};
                for (int k = 0; k < 4; k++)
                    classify_at(file, m, d ? other : at[k], d ? at[k] : other, k < 2 ? BS_TRIM_INSIDE : BS_TRIM_OUTSIDE);
            }
            if (n == 2) { /* the whole torus of radii 6 and 1.5: one closed shell */
                double exact = 2.0 * pi * pi * 6.0 * 1.5 * 1.5;
                CHECKF(bs_model_shell_closed(m, 0) == 1 && fabs(fabs(volume) - exact) <= 1e-9 * exact,
                       "%s: closed %d, volume %.15g, the torus's %.15g", file, bs_model_shell_closed(m, 0), volume, exact);
            }
            bs_model_destroy(m);
        }
    test_open_box();
    return bs_test_exit("test_occt_faces");
}
