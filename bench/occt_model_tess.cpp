// OpenCASCADE's mesher as the peer of bs_model_tessellate on a CAD part: the same STEP file read
// by both (STEPControl_Reader; bs_model_read_step_file), meshed at the same absolute deflection
// (REL times the diagonal of the part's box in its .ref; OCCT's angular deflection 0.5, its
// default), one thread each, CPU time in the same run (OCCT's mesh is made once: it keeps its
// triangulation on the shape; ours ROUNDS times). For both: triangles, the smallest corner angle
// in 3-D, and the worst error over the deflection by one metric (15 barycentric points per
// triangle: distance from the triangle's point to the face at the interpolated parameters).
// Built only when OpenCASCADE is found (bench/CMakeLists.txt):
//   build/bench/occt_model_tess [data/cad/PART.step] [REL] [ROUNDS]
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <bezsurf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

static double seconds() // CPU time: steadier on a loaded machine
{
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

static double angle_at(const double *a, const double *b, const double *c)
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) *
           180.0 / 3.14159265358979323846;
}

static double smallest_angle(const double P[3][3])
{
    double a = 180.0;
    for (int k = 0; k < 3; k++)
        a = std::fmin(a, angle_at(P[k], P[(k + 1) % 3], P[(k + 2) % 3]));
    return a;
}

static const int ORDER = 4; // 15 barycentric points per triangle

int main(int argc, char **argv)
{
    std::string path = argc > 1 ? argv[1] : "data/cad/bottle.step";
    double rel = argc > 2 ? std::atof(argv[2]) : 1e-3;
    int rounds = argc > 3 ? std::atoi(argv[3]) : 5;
    std::string ref = path.substr(0, path.find_first_of(".-", path.find_last_of('/') + 1)) + ".ref";
    std::FILE *f = std::fopen(ref.c_str(), "r");
    if (f == nullptr || rounds < 1 || !(rel > 0.0)) {
        std::fprintf(stderr, "usage: occt_model_tess [data/cad/PART.step] [REL] [ROUNDS] (needs PART.ref)\n");
        return 2;
    }
    double box[6] = {0, 0, 0, 0, 0, 0};
    char line[512];
    while (std::fgets(line, sizeof line, f))
        (void)std::sscanf(line, "box %lf %lf %lf %lf %lf %lf", &box[0], &box[1], &box[2], &box[3], &box[4], &box[5]);
    std::fclose(f);
    double diag = std::sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                            (box[5] - box[2]) * (box[5] - box[2]));
    double tol = rel * diag;

    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) {
        std::fprintf(stderr, "%s: OpenCASCADE did not read it\n", path.c_str());
        return 1;
    }
    TopoDS_Shape shape = reader.OneShape();
    double c0 = seconds();
    BRepMesh_IncrementalMesh mesher(shape, tol, Standard_False, 0.5, Standard_False);
    double occt_s = seconds() - c0;
    size_t occt_tri = 0;
    double occt_err = 0.0, occt_angle = 180.0;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face &face = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        Handle(Poly_Triangulation) tr = BRep_Tool::Triangulation(face, loc);
        Handle(Geom_Surface) g = BRep_Tool::Surface(face);
        if (tr.IsNull() || !tr->HasUVNodes())
            continue;
        occt_tri += (size_t)tr->NbTriangles();
        for (int t = 1; t <= tr->NbTriangles(); t++) {
            int v[3];
            tr->Triangle(t).Get(v[0], v[1], v[2]);
            double P[3][3];
            for (int c = 0; c < 3; c++) {
                gp_Pnt q = tr->Node(v[c]).Transformed(loc.Transformation());
                P[c][0] = q.X();
                P[c][1] = q.Y();
                P[c][2] = q.Z();
            }
            occt_angle = std::fmin(occt_angle, smallest_angle(P));
            for (int i = 0; i <= ORDER; i++)
                for (int j = 0; i + j <= ORDER; j++) {
                    double l[3] = {double(i) / ORDER, double(j) / ORDER, double(ORDER - i - j) / ORDER};
                    double u = 0, w = 0, x[3] = {0, 0, 0};
                    for (int c = 0; c < 3; c++) {
                        gp_Pnt2d q = tr->UVNode(v[c]);
                        u += l[c] * q.X();
                        w += l[c] * q.Y();
                        for (int d = 0; d < 3; d++)
                            x[d] += l[c] * P[c][d];
                    }
                    gp_Pnt S = g->Value(u, w);
                    occt_err = std::fmax(occt_err, std::sqrt((S.X() - x[0]) * (S.X() - x[0]) + (S.Y() - x[1]) * (S.Y() - x[1]) +
                                                             (S.Z() - x[2]) * (S.Z() - x[2])));
                }
        }
    }

    bs_model *m = nullptr;
    if (bs_model_read_step_file(path.c_str(), nullptr, &m) != BS_OK)
        return 1;
    bs_tess_options o;
    bs_tess_options_init(&o);
    o.method = BS_TESS_SUBDIVIDE;
    o.tolerance = tol;
    bs_mesh *mesh = nullptr;
    double c1 = seconds();
    for (int r = 0; r < rounds; r++) {
        bs_mesh_destroy(mesh);
        mesh = nullptr;
        if (bs_model_tessellate(m, &o, &mesh) != BS_OK)
            return 1;
    }
    double ours_s = (seconds() - c1) / rounds;
    size_t nv = bs_mesh_vertex_count(mesh), nt = bs_mesh_triangle_count(mesh);
    std::vector<double> x(nv), y(nv), z(nv), cu(3 * nt), cv(3 * nt);
    std::vector<uint32_t> tri(3 * nt), tf(nt);
    bs_view xyz[3] = {{x.data(), nv, 0}, {y.data(), nv, 0}, {z.data(), nv, 0}};
    bs_view uv[2] = {{cu.data(), 3 * nt, 0}, {cv.data(), 3 * nt, 0}};
    if (bs_mesh_copy_positions(mesh, xyz) != BS_OK || bs_mesh_copy_corner_uv(mesh, uv) != BS_OK ||
        bs_mesh_copy_triangles(mesh, tri.data(), tri.size()) != BS_OK ||
        bs_mesh_copy_triangle_patch_ids(mesh, tf.data(), tf.size()) != BS_OK)
        return 1;
    size_t per = (ORDER + 1) * (ORDER + 2) / 2, n = nt * per;
    std::vector<uint32_t> faces(n);
    std::vector<double> su(n), sv(n), lin(3 * n), pos(3 * n);
    double ours_angle = 180.0;
    size_t k = 0;
    for (size_t t = 0; t < nt; t++) {
        double P[3][3];
        for (int c = 0; c < 3; c++) {
            uint32_t id = tri[3 * t + c];
            P[c][0] = x[id];
            P[c][1] = y[id];
            P[c][2] = z[id];
        }
        ours_angle = std::fmin(ours_angle, smallest_angle(P));
        for (int i = 0; i <= ORDER; i++)
            for (int j = 0; i + j <= ORDER; j++, k++) {
                double l[3] = {double(i) / ORDER, double(j) / ORDER, double(ORDER - i - j) / ORDER};
                faces[k] = tf[t];
                su[k] = l[0] * cu[3 * t] + l[1] * cu[3 * t + 1] + l[2] * cu[3 * t + 2];
                sv[k] = l[0] * cv[3 * t] + l[1] * cv[3 * t + 1] + l[2] * cv[3 * t + 2];
                for (int d = 0; d < 3; d++)
                    lin[3 * k + d] = l[0] * P[0][d] + l[1] * P[1][d] + l[2] * P[2][d];
            }
    }
    bs_cview vu = {su.data(), n, 0}, vv = {sv.data(), n, 0};
    bs_view vp[3] = {{pos.data(), n, 3 * sizeof(double)}, {pos.data() + 1, n, 3 * sizeof(double)},
                     {pos.data() + 2, n, 3 * sizeof(double)}};
    if (bs_model_face_eval(m, n, faces.data(), &vu, &vv, vp, nullptr, nullptr) != BS_OK)
        return 1;
    double ours_err = 0.0;
    for (size_t i = 0; i < n; i++)
        ours_err = std::fmax(ours_err, std::sqrt((pos[3 * i] - lin[3 * i]) * (pos[3 * i] - lin[3 * i]) +
                                                 (pos[3 * i + 1] - lin[3 * i + 1]) * (pos[3 * i + 1] - lin[3 * i + 1]) +
                                                 (pos[3 * i + 2] - lin[3 * i + 2]) * (pos[3 * i + 2] - lin[3 * i + 2])));
    std::printf("%s at %g D (%g): one thread\n", path.c_str(), rel, tol);
    std::printf("OpenCASCADE BRepMesh_IncrementalMesh: %8.2f ms, %7zu triangles, error <= %.2f x tol, smallest angle %.2f deg\n",
                1e3 * occt_s, occt_tri, occt_err / tol, occt_angle);
    std::printf("libbezsurf bs_model_tessellate:       %8.2f ms, %7zu triangles, error <= %.2f x tol, smallest angle %.2f deg\n",
                1e3 * ours_s, nt, ours_err / tol, ours_angle);
    std::printf("ratio: %.1fx faster, %.2f of its triangles\n", occt_s / ours_s, double(nt) / double(occt_tri));
    bs_mesh_destroy(mesh);
    bs_model_destroy(m);
    return 0;
}
