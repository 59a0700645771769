// The peer of bench_tess_adaptive: OpenCASCADE's BRepMesh_IncrementalMesh on the tea set, each
// patch a face on a Geom_BezierSurface with the same control points (and the same (u,v)), at the
// same absolute tolerances as linear deflection (angular deflection 0.5, OCCT's default):
// triangles, the worst error over the tolerance by the same metric (21 barycentric points per
// triangle, distance to the surface at the interpolated (u,v) of the triangulation's UV nodes), and
// the wall-clock time of one meshing. Built only when OpenCASCADE is found (bench/CMakeLists.txt).
// Usage: bench_tess_occt [SMALLEST_TOLERANCE] (default 1e-4).
#include <bezsurf.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BezierSurface.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

// The surface's patches as faces of one compound (not sewn: each face is meshed on its own).
static TopoDS_Compound faces_of(const bs_surface *s)
{
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    for (size_t i = 0; i < bs_surface_count(s); i++) {
        const bs_patch *p = bs_surface_get(s, i);
        int m = (int)bs_patch_degree_u(p), n = (int)bs_patch_degree_v(p);
        std::vector<double> net(3 * (m + 1) * (n + 1)), w((m + 1) * (n + 1));
        bs_patch_get_ctrl(p, net.data(), net.size(), w.data(), w.size());
        TColgp_Array2OfPnt poles(1, m + 1, 1, n + 1);
        TColStd_Array2OfReal weights(1, m + 1, 1, n + 1);
        for (int a = 0; a <= m; a++)
            for (int k = 0; k <= n; k++) {
                const double *x = &net[3 * (a * (n + 1) + k)];
                poles.SetValue(a + 1, k + 1, gp_Pnt(x[0], x[1], x[2]));
                weights.SetValue(a + 1, k + 1, bs_patch_is_rational(p) ? w[a * (n + 1) + k] : 1.0);
            }
        Handle(Geom_BezierSurface) g = bs_patch_is_rational(p) ? new Geom_BezierSurface(poles, weights)
                                                                : new Geom_BezierSurface(poles);
        b.Add(c, BRepBuilderAPI_MakeFace(g, Precision::Confusion()).Face());
    }
    return c;
}

int main(int argc, char **argv)
{
    double smallest = argc > 1 ? std::atof(argv[1]) : 1e-4;
    std::printf("%-9s %-9s | %10s %9s %10s\n", "surface", "tolerance", "triangles", "error/tol", "ms");
    const char *name;
    for (size_t k = 0; (name = bs_builtin_name(k)) != NULL; k++) {
        bs_surface *s = NULL;
        if (bs_surface_create_builtin(name, &s) != BS_OK)
            return 1;
        for (double tol = 1e-2; tol >= 0.9 * smallest; tol /= 10.0) {
            TopoDS_Compound shape = faces_of(s);
            auto t0 = std::chrono::steady_clock::now();
            BRepMesh_IncrementalMesh mesher(shape, tol, Standard_False, 0.5, Standard_False);
            double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            size_t ntri = 0;
            double worst = 0.0;
            for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
                const TopoDS_Face &f = TopoDS::Face(ex.Current());
                TopLoc_Location loc;
                Handle(Poly_Triangulation) tr = BRep_Tool::Triangulation(f, loc);
                Handle(Geom_Surface) g = BRep_Tool::Surface(f);
                if (tr.IsNull() || !tr->HasUVNodes())
                    continue;
                ntri += (size_t)tr->NbTriangles();
                for (int t = 1; t <= tr->NbTriangles(); t++) {
                    int v[3];
                    tr->Triangle(t).Get(v[0], v[1], v[2]);
                    for (int i = 0; i <= 5; i++)
                        for (int j = 0; i + j <= 5; j++) {
                            double l[3] = {i / 5.0, j / 5.0, (5 - i - j) / 5.0}, u = 0, w = 0, x[3] = {0, 0, 0};
                            for (int c = 0; c < 3; c++) {
                                gp_Pnt2d q = tr->UVNode(v[c]);
                                gp_Pnt P = tr->Node(v[c]);
                                u += l[c] * q.X();
                                w += l[c] * q.Y();
                                x[0] += l[c] * P.X();
                                x[1] += l[c] * P.Y();
                                x[2] += l[c] * P.Z();
                            }
                            gp_Pnt S = g->Value(u, w);
                            worst = std::fmax(worst, std::sqrt((S.X() - x[0]) * (S.X() - x[0]) + (S.Y() - x[1]) * (S.Y() - x[1]) +
                                                               (S.Z() - x[2]) * (S.Z() - x[2])));
                        }
                }
            }
            std::printf("%-9s %-9g | %10zu %9.3f %10.1f\n", name, tol, ntri, worst / tol, ms);
        }
        bs_surface_destroy(s);
    }
    return 0;
}
