/* What the locator benchmarks share: CPU time, and the camera's primary rays at the teapot. */
#ifndef BS_BENCH_RAYS_CAMERA_H
#define BS_BENCH_RAYS_CAMERA_H

#include <math.h>
#include <stddef.h>
#include <time.h>

/* Seconds of the calling thread's CPU time: less noisy than wall time on a shared machine. */
static inline double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* N x N primary rays from a pinhole camera at eye looking at the teapot's middle, 40 degrees
 * across: ray y*N + x from o, direction d (not unit). */
static inline void camera_rays(size_t N, double *o[3], double *d[3])
{
    const double eye[3] = {6.0, -8.0, 5.5}, at[3] = {0.2, 0.0, 1.4}, up[3] = {0, 0, 1};
    double f[3], rgt[3], u[3], fl = 0, rl = 0, half = tan(20.0 * 3.14159265358979 / 180.0);
    for (int c = 0; c < 3; c++) {
        f[c] = at[c] - eye[c];
        fl += f[c] * f[c];
    }
    for (int c = 0; c < 3; c++)
        f[c] /= sqrt(fl);
    rgt[0] = f[1] * up[2] - f[2] * up[1];
    rgt[1] = f[2] * up[0] - f[0] * up[2];
    rgt[2] = f[0] * up[1] - f[1] * up[0];
    for (int c = 0; c < 3; c++)
        rl += rgt[c] * rgt[c];
    for (int c = 0; c < 3; c++)
        rgt[c] /= sqrt(rl);
    u[0] = rgt[1] * f[2] - rgt[2] * f[1];
    u[1] = rgt[2] * f[0] - rgt[0] * f[2];
    u[2] = rgt[0] * f[1] - rgt[1] * f[0];
    for (size_t y = 0; y < N; y++)
        for (size_t x = 0; x < N; x++) {
            size_t k = y * N + x;
            double px = (2.0 * ((double)x + 0.5) / (double)N - 1.0) * half;
            double py = (1.0 - 2.0 * ((double)y + 0.5) / (double)N) * half;
            for (int c = 0; c < 3; c++) {
                o[c][k] = eye[c];
                d[c][k] = f[c] + px * rgt[c] + py * u[c];
            }
        }
}

#endif
