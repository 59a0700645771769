// Writes the IGES fixtures of tests/io/data/iges/ with OpenCASCADE's IGES writer, and beside each
// file.igs a file.txt of reference points the reader's patches must reproduce:
//   surface NU NV          the breakpoints of one entity 128 as read (its parameter range cut at
//   u-breaks...            the distinct knots), in the order of the file's entities
//   v-breaks...
//   bspline DU DV CU CV    the B-spline at full precision: degrees, pole counts,
//   knots-u... knots-v...  flat knot vectors,
//   pole X Y Z W           poles (transformed where the surface is) and weights, i along u outer
//   point U V X Y Z        the surface (transformed where it is) at parameter (U,V), per OCCT
// Build: only when OpenCASCADE is found (tests/io/CMakeLists.txt); run by hand:
//   build/tests/occt_iges_gen tests/io/data/iges
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <GCE2d_MakeCircle.hxx>
#include <Geom2d_Circle.hxx>
#include <GeomToIGES_GeomSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESGeom_TransformationMatrix.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColStd_HArray2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2d.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Spec {
    Handle(Geom_BSplineSurface) surf;
    double u0, u1, v0, v1;  // parameter range written
    gp_Trsf trsf;           // applied to the reference points
};

// A surface from flat knot data: degrees, distinct knots and multiplicities, poles (i along u).
Handle(Geom_BSplineSurface) make(int pu, int pv, const std::vector<double> &ku, const std::vector<int> &mu,
                                 const std::vector<double> &kv, const std::vector<int> &mv, int nu, int nv,
                                 double (*pole)(int, int, int), double (*weight)(int, int))
{
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal w(1, nu, 1, nv);
    for (int i = 1; i <= nu; i++)
        for (int j = 1; j <= nv; j++) {
            poles(i, j) = gp_Pnt(pole(i, j, 0), pole(i, j, 1), pole(i, j, 2));
            w(i, j) = weight(i, j);
        }
    TColStd_Array1OfReal aku(1, (int)ku.size()), akv(1, (int)kv.size());
    TColStd_Array1OfInteger amu(1, (int)mu.size()), amv(1, (int)mv.size());
    for (size_t k = 0; k < ku.size(); k++)
        aku((int)k + 1) = ku[k], amu((int)k + 1) = mu[k];
    for (size_t k = 0; k < kv.size(); k++)
        akv((int)k + 1) = kv[k], amv((int)k + 1) = mv[k];
    return new Geom_BSplineSurface(poles, w, aku, akv, amu, amv, pu, pv);
}

// Quarter cylinder of radius 2 and height 3: rational quadratic in u, linear in v.
double cyl_pole(int i, int j, int c)
{
    static const double xy[3][2] = {{2, 0}, {2, 2}, {0, 2}};
    return c < 2 ? xy[i - 1][c] : 3.0 * (j - 1);
}
double cyl_weight(int i, int) { return i == 2 ? std::sqrt(0.5) : 1.0; }

// A wavy net of up to 7 x 5 points.
double wave_pole(int i, int j, int c)
{
    return c == 0 ? 1.5 * i : c == 1 ? 1.25 * j : 0.3 * std::sin(1.7 * i + 0.9 * j) + 0.05 * i * j;
}
double unit_weight(int, int) { return 1.0; }
double wave_weight(int i, int j) { return 0.6 + 0.15 * ((i * 7 + j * 3) % 5); }

void write_points(FILE *f, const Spec &s)
{
    std::vector<double> bu, bv;
    const TColStd_Array1OfReal &ku = s.surf->UKnots(), &kv = s.surf->VKnots();
    bu.push_back(s.u0);
    for (int k = ku.Lower(); k <= ku.Upper(); k++)
        if (ku(k) > s.u0 && ku(k) < s.u1)
            bu.push_back(ku(k));
    bu.push_back(s.u1);
    bv.push_back(s.v0);
    for (int k = kv.Lower(); k <= kv.Upper(); k++)
        if (kv(k) > s.v0 && kv(k) < s.v1)
            bv.push_back(kv(k));
    bv.push_back(s.v1);
    std::fprintf(f, "surface %zu %zu\n", bu.size(), bv.size());
    for (double x : bu)
        std::fprintf(f, "%.17g ", x);
    std::fprintf(f, "\n");
    for (double x : bv)
        std::fprintf(f, "%.17g ", x);
    std::fprintf(f, "\n");
    // The B-spline itself at full precision (the file holds 9 digits): degrees, counts, flat
    // knots, then the poles (transformed) and weights, i along u outer.
    const Handle(Geom_BSplineSurface) &g = s.surf;
    std::fprintf(f, "bspline %d %d %d %d\n", g->UDegree(), g->VDegree(), g->NbUPoles(), g->NbVPoles());
    const TColStd_Array1OfReal &fu = g->UKnotSequence(), &fv = g->VKnotSequence();
    for (int k = fu.Lower(); k <= fu.Upper(); k++)
        std::fprintf(f, "%.17g ", fu(k));
    std::fprintf(f, "\n");
    for (int k = fv.Lower(); k <= fv.Upper(); k++)
        std::fprintf(f, "%.17g ", fv(k));
    std::fprintf(f, "\n");
    for (int i = 1; i <= g->NbUPoles(); i++)
        for (int j = 1; j <= g->NbVPoles(); j++) {
            gp_Pnt p = g->Pole(i, j).Transformed(s.trsf);
            std::fprintf(f, "pole %.17g %.17g %.17g %.17g\n", p.X(), p.Y(), p.Z(), g->Weight(i, j));
        }
    for (int a = 0; a <= 6; a++)
        for (int b = 0; b <= 6; b++) {
            double u = s.u0 + (s.u1 - s.u0) * a / 6.0, v = s.v0 + (s.v1 - s.v0) * b / 6.0;
            gp_Pnt p = s.surf->Value(u, v).Transformed(s.trsf);
            std::fprintf(f, "point %.17g %.17g %.17g %.17g %.17g\n", u, v, p.X(), p.Y(), p.Z());
        }
}

bool write_file(const std::string &dir, const char *name, const std::vector<Spec> &specs,
                const TopoDS_Face *face)
{
    IGESControl_Writer writer("MM", 0);
    for (const Spec &s : specs) {
        if (face != nullptr)
            break;
        GeomToIGES_GeomSurface gs;
        gs.SetModel(writer.Model());
        gs.SetUnit(1.0);
        Handle(IGESData_IGESEntity) e = gs.TransferSurface(s.surf, s.u0, s.u1, s.v0, s.v1);
        if (s.trsf.Form() != gp_Identity) {
            Handle(TColStd_HArray2OfReal) m = new TColStd_HArray2OfReal(1, 3, 1, 4);
            for (int r = 1; r <= 3; r++)
                for (int c = 1; c <= 4; c++)
                    m->SetValue(r, c, s.trsf.Value(r, c));
            Handle(IGESGeom_TransformationMatrix) t = new IGESGeom_TransformationMatrix;
            t->Init(m);
            e->InitTransf(t);
        }
        writer.AddEntity(e);
    }
    if (face != nullptr)
        writer.AddShape(*face);
    writer.ComputeModel();
    std::string path = dir + "/" + name;
    if (!writer.Write((path + ".igs").c_str()))
        return false;
    FILE *f = std::fopen((path + ".txt").c_str(), "w");
    if (f == nullptr)
        return false;
    for (const Spec &s : specs)
        write_points(f, s);
    return std::fclose(f) == 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: occt_iges_gen OUTPUT_DIR\n");
        return 2;
    }
    IGESControl_Controller::Init();
    std::string dir = argv[1];
    gp_Trsf id;
    Spec cyl = {make(2, 1, {0, 1}, {3, 3}, {0, 1}, {2, 2}, 3, 2, cyl_pole, cyl_weight), 0, 1, 0, 1, id};
    Spec wave = {make(3, 3, {0, 1, 2.5, 4}, {4, 1, 2, 4}, {0, 0.5, 1}, {4, 1, 4}, 7, 5, wave_pole, unit_weight),
                 0, 4, 0, 1, id};
    Spec rat = {make(3, 2, {0, 1, 2.5, 4}, {4, 1, 2, 4}, {0, 0.5, 1}, {3, 1, 3}, 7, 4, wave_pole, wave_weight),
                0, 4, 0, 1, id};
    gp_Trsf moved;
    moved.SetRotation(gp_Ax1(gp_Pnt(1, 0, 0), gp_Dir(1, 1, 1)), 0.7);
    gp_Trsf shift;
    shift.SetTranslation(gp_Vec(10, -4, 2.5));
    moved = shift * moved;
    Spec cyl_moved = cyl, wave_sub = wave;
    cyl_moved.trsf = moved;
    wave_sub.u0 = 0.5, wave_sub.u1 = 3.0, wave_sub.v0 = 0.25, wave_sub.v1 = 1.0;
    bool ok = write_file(dir, "nurbs_cylinder", {cyl}, nullptr) &&
              write_file(dir, "bicubic_knots", {wave, rat}, nullptr) &&
              write_file(dir, "transformed", {cyl_moved}, nullptr) &&
              write_file(dir, "subrange", {wave_sub}, nullptr);
    // A face of the bicubic surface with a circular hole: the IGES writer puts its surface under a
    // trimmed surface (144); the reader reads the whole surface.
    Handle(Geom2d_Circle) circle = GCE2d_MakeCircle(gp_Ax2d(gp_Pnt2d(2.0, 0.5), gp_Dir2d(1, 0)), 0.2).Value();
    BRepBuilderAPI_MakeFace mf(wave.surf, 1e-7);
    TopoDS_Edge hole = BRepBuilderAPI_MakeEdge(circle, wave.surf);
    mf.Add(BRepBuilderAPI_MakeWire(TopoDS::Edge(hole.Reversed())));
    TopoDS_Face face = mf.Face();
    ok = ok && write_file(dir, "trimmed_face", {wave}, &face);
    if (!ok) {
        std::fprintf(stderr, "occt_iges_gen: writing failed\n");
        return 1;
    }
    return 0;
}
