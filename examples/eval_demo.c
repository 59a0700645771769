/* Evaluate a bicubic patch whose u = 0 edge is collapsed to one point (like the top of the Utah
 * teapot's lid): positions, unit normals and their kinds at a few points, scattered and on a grid. */
#include <bezsurf.h>

#include <stdio.h>

static const char *kind_name(unsigned char k)
{
    return k == BS_NORMAL_REGULAR ? "regular" : k == BS_NORMAL_LIMIT ? "limit" : "undefined";
}

int main(void)
{
    /* row i = 0 is the apex (0, 0, 1); the other rows spread out into a dome */
    double ctrl[4 * 4 * 3];
    const double r[4] = {0.0, 0.6, 1.0, 1.2}, z[4] = {1.0, 1.0, 0.6, 0.0};
    const double x[4] = {1.0, 1.0, 0.55, 0.0}, y[4] = {0.0, 0.55, 1.0, 1.0}; /* quarter circle */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *P = ctrl + (i * 4 + j) * 3;
            P[0] = r[i] * x[j];
            P[1] = r[i] * y[j];
            P[2] = z[i];
        }
    bs_patch *p = NULL;
    bs_status st = bs_patch_create(3, 3, 3, ctrl, NULL, &p);
    if (st != BS_OK) {
        fprintf(stderr, "bs_patch_create: %s\n", bs_status_string(st));
        return 1;
    }

    enum { N = 5 };
    double u[N] = {0.0, 0.0, 0.5, 1.0, 0.25}, v[N] = {0.0, 0.5, 0.5, 1.0, 0.75};
    double pos[3][N], nrm[3][N];
    unsigned char kind[N];
    bs_cview cu = {u, N, 0}, cv = {v, N, 0};
    bs_view vp[3], vn[3];
    for (int c = 0; c < 3; c++) {
        vp[c] = (bs_view){pos[c], N, 0};
        vn[c] = (bs_view){nrm[c], N, 0};
    }
    st = bs_patch_eval_normal(p, N, &cu, &cv, vp, vn, kind);
    if (st != BS_OK) {
        fprintf(stderr, "bs_patch_eval_normal: %s\n", bs_status_string(st));
        bs_patch_destroy(p);
        return 1;
    }
    printf("libbezsurf %s: bicubic patch with its u = 0 edge collapsed to a point\n", bs_version_string());
    printf("    u     v   |  position                 |  unit normal                 kind\n");
    for (int k = 0; k < N; k++)
        printf("%5.2f %5.2f | %7.4f %7.4f %7.4f | %8.5f %8.5f %8.5f  %s\n", u[k], v[k], pos[0][k], pos[1][k],
               pos[2][k], nrm[0][k], nrm[1][k], nrm[2][k], kind_name(kind[k]));

    /* a 3 x 3 grid: only the points on u = 0 take the limit rule */
    double g[3] = {0.0, 0.5, 1.0}, gk[3][9];
    unsigned char gkind[9];
    bs_cview cg = {g, 3, 0};
    bs_view vg[3];
    for (int c = 0; c < 3; c++)
        vg[c] = (bs_view){gk[c], 9, 0};
    st = bs_patch_eval_grid(p, 3, &cg, 3, &cg, NULL, NULL, NULL, vg, gkind);
    if (st != BS_OK) {
        fprintf(stderr, "bs_patch_eval_grid: %s\n", bs_status_string(st));
        bs_patch_destroy(p);
        return 1;
    }
    printf("grid normal kinds (rows u = 0, 0.5, 1):\n");
    for (int a = 0; a < 3; a++)
        printf("  %-9s %-9s %-9s\n", kind_name(gkind[a * 3]), kind_name(gkind[a * 3 + 1]), kind_name(gkind[a * 3 + 2]));
    bs_patch_destroy(p);
    return 0;
}
