// OpenCASCADE's point projection as a peer of bs_patch_closest_point: the 32 teapot patches as
// Geom_BezierSurface, the same random points around the teapot as bench_closest, and for each
// GeomAPI_ProjectPointOnSurf's nearest answer (LowerDistance) against ours, which is certified
// global to tau = 1e-9 (D + d). Counts the answers farther than ours by more than tau (not the
// global minimum), also among the queries whose minimum is inside the domain (the only ones an
// orthogonal projection can answer), the queries without an answer, and times both.
// Built only when OpenCASCADE is found (bench/CMakeLists.txt):  build/bench/occt_closest [points]
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>

#include <bezsurf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

static double seconds() // CPU time, as bench_closest: steadier on a loaded machine
{
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

int main(int argc, char **argv)
{
    size_t npts = argc > 1 ? static_cast<size_t>(std::atol(argv[1])) : 300;
    bs_surface *s = nullptr;
    if (npts == 0 || bs_surface_create_builtin("teapot", &s) != BS_OK)
        return 1;
    size_t np = bs_surface_count(s);
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    std::vector<Handle(Geom_BezierSurface)> occ;
    std::vector<double> diag;
    for (size_t i = 0; i < np; i++) {
        const bs_patch *p = bs_surface_get(s, i);
        double ctrl[48], b[6];
        if (bs_patch_degree_u(p) != 3 || bs_patch_degree_v(p) != 3 ||
            bs_patch_get_ctrl(p, ctrl, 48, nullptr, 0) != BS_OK)
            return 1;
        TColgp_Array2OfPnt poles(1, 4, 1, 4);
        for (int a = 0; a < 4; a++)
            for (int c = 0; c < 4; c++) {
                const double *x = ctrl + (a * 4 + c) * 3;
                poles.SetValue(a + 1, c + 1, gp_Pnt(x[0], x[1], x[2]));
            }
        occ.push_back(new Geom_BezierSurface(poles));
        bs_patch_bounds(p, b, b + 3);
        diag.push_back(std::sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) +
                                 (b[5] - b[2]) * (b[5] - b[2])));
        for (int c = 0; c < 3; c++) {
            lo[c] = std::fmin(lo[c], b[c]);
            hi[c] = std::fmax(hi[c], b[3 + c]);
        }
    }
    std::vector<double> q(3 * npts), ours(np * npts), u(np * npts), v(np * npts);
    unsigned long long x = 12345; // the LCG of bench_closest: the same points
    for (size_t k = 0; k < npts; k++)
        for (int c = 0; c < 3; c++) {
            x = x * 6364136223846793005ull + 1442695040888963407ull;
            double pad = 0.2 * (hi[c] - lo[c]), t = static_cast<double>(x >> 11) * 0x1.0p-53;
            q[3 * k + c] = lo[c] - pad + (hi[c] - lo[c] + 2 * pad) * t;
        }
    double t0 = seconds();
    for (size_t i = 0; i < np; i++) {
        bs_cview qv[3] = {{q.data(), npts, 24}, {q.data() + 1, npts, 24}, {q.data() + 2, npts, 24}};
        bs_view d = {ours.data() + i * npts, npts, 0};
        bs_view uv[2] = {{u.data() + i * npts, npts, 0}, {v.data() + i * npts, npts, 0}};
        if (bs_patch_closest_point(bs_surface_get(s, i), npts, qv, uv, &d, nullptr) != BS_OK)
            return 1;
    }
    double t1 = seconds();
    size_t farther = 0, none = 0, wrong = 0, inner = 0, inner_farther = 0;
    double worst = 0;
    for (size_t i = 0; i < np; i++) {
        GeomAPI_ProjectPointOnSurf proj; /* set up once per patch, as a caller would */
        proj.Init(occ[i], 0.0, 1.0, 0.0, 1.0);
        for (size_t k = 0; k < npts; k++) {
            proj.Perform(gp_Pnt(q[3 * k], q[3 * k + 1], q[3 * k + 2]));
            double d = ours[i * npts + k], tau = 1e-9 * (diag[i] + d);
            if (proj.NbPoints() == 0) {
                none++;
                continue;
            }
            double theirs = proj.LowerDistance();
            size_t at = i * npts + k;
            bool interior = u[at] > 1e-6 && u[at] < 1 - 1e-6 && v[at] > 1e-6 && v[at] < 1 - 1e-6;
            inner += interior;
            inner_farther += interior && theirs > d + tau;
            farther += theirs > d + tau;
            wrong += theirs > d + 1e-4 * diag[i];
            worst = std::fmax(worst, (theirs - d) / diag[i]);
        }
    }
    double t2 = seconds(), total = static_cast<double>(np * npts);
    std::printf("teapot: %zu patches x %zu random points around it\n", np, npts);
    std::printf("  bs_patch_closest_point      %9.0f queries/s\n", total / (t1 - t0));
    std::printf("  GeomAPI_ProjectPointOnSurf  %9.0f queries/s\n", total / (t2 - t1));
    std::printf("    of %.0f queries: no answer in %zu; of the answers, %zu farther than ours by more "
                "than tau, %zu by more than 1e-4 D (worst %.3g D)\n",
                total, none, farther, wrong, worst);
    std::printf("    where our answer is inside the domain (an orthogonal projection; %zu queries): "
                "%zu farther by more than tau\n", inner, inner_farther);
    bs_surface_destroy(s);
    return 0;
}
