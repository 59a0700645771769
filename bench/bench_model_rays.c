/* Rays on the trimmed faces of a CAD part (bs_locator_create_model): the 400 rays of the part's
 * .ref file (data/cad/NAME.ref, beside the file) cast ROUNDS times, one thread and then all
 * threads, in CPU seconds for one thread (steadier on a loaded machine) and wall seconds for the
 * threaded run; the time to read the file and to build the locator.
 *   build/bench/bench_model_rays [FILE] [ROUNDS]     (default data/cad/bottle.step, 50) */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <bezsurf.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The rays of the .ref beside path (NAME.step, NAME-brep.igs, ... -> NAME.ref): their count. */
static size_t read_rays(const char *path, double *o, double *d, size_t cap)
{
    char ref[1024];
    (void)snprintf(ref, sizeof ref, "%s", path);
    char *base = strrchr(ref, '/') ? strrchr(ref, '/') + 1 : ref, *cut = strpbrk(base, ".-");
    if (cut == NULL || (size_t)(cut - ref) + 5 > sizeof ref)
        return 0;
    strcpy(cut, ".ref");
    FILE *f = fopen(ref, "r");
    if (f == NULL)
        return 0;
    char line[512];
    size_t n = 0;
    while (n < cap && fgets(line, sizeof line, f))
        if (sscanf(line, "ray %lf %lf %lf %lf %lf %lf", &o[3 * n], &o[3 * n + 1], &o[3 * n + 2],
                   &d[3 * n], &d[3 * n + 1], &d[3 * n + 2]) == 6)
            n++;
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "data/cad/bottle.step";
    int rounds = argc > 2 ? atoi(argv[2]) : 50;
    static double o[3 * 512], d[3 * 512], t[512];
    static uint32_t face[512];
    size_t n = read_rays(path, o, d, 512);
    if (n == 0 || rounds < 1) {
        fprintf(stderr, "usage: bench_model_rays [data/cad/PART.step|.igs] [ROUNDS] (needs PART.ref)\n");
        return 2;
    }
    double t0 = wall();
    bs_model *m = NULL;
    bs_status st = strstr(path, ".igs") ? bs_model_read_iges_file(path, NULL, &m)
                                        : bs_model_read_step_file(path, NULL, &m);
    double t1 = wall();
    bs_locator *L = NULL;
    if (st == BS_OK)
        st = bs_locator_create_model(m, &L);
    double t2 = wall();
    if (st != BS_OK) {
        fprintf(stderr, "%s: %s\n", path, bs_status_string(st));
        return 1;
    }
    bs_cview ov[3] = {{o, n, 3 * sizeof(double)}, {o + 1, n, 3 * sizeof(double)}, {o + 2, n, 3 * sizeof(double)}};
    bs_cview dv[3] = {{d, n, 3 * sizeof(double)}, {d + 1, n, 3 * sizeof(double)}, {d + 2, n, 3 * sizeof(double)}};
    bs_view tv = {t, n, sizeof(double)};
    size_t hits = 0;
    double c0 = cpu();
    for (int r = 0; r < rounds && st == BS_OK; r++)
        st = bs_locator_intersect(L, n, ov, dv, NULL, face, NULL, &tv, NULL);
    double c1 = cpu(), w0 = wall();
    for (int r = 0; r < rounds && st == BS_OK; r++)
        st = bs_locator_intersect_mt(L, n, ov, dv, NULL, face, NULL, &tv, NULL, 0);
    double w1 = wall();
    for (size_t k = 0; k < n; k++)
        hits += face[k] != UINT32_MAX;
    double total = (double)n * rounds;
    printf("%s: %zu faces; read %.1f ms, locator %.1f ms\n", path, bs_model_face_count(m),
           1e3 * (t1 - t0), 1e3 * (t2 - t1));
    printf("rays: %zu x %d (%zu hit): one thread %.2f us per ray (%.0f rays/s), all threads %.2f us per ray\n",
           n, rounds, hits, 1e6 * (c1 - c0) / total, total / (c1 - c0), 1e6 * (w1 - w0) / total);
    bs_locator_destroy(L);
    bs_model_destroy(m);
    return st == BS_OK ? 0 : 1;
}
