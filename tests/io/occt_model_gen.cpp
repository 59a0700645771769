// Writes a NURBS model with OpenCASCADE's IGES writer: a vase, a B-spline profile revolved about
// the z axis and converted to one rational B-spline surface (entity 128). It is the IGES model of
// docs/formats.md's picture. Build: only when OpenCASCADE is found (tests/io/CMakeLists.txt); run:
//   build/tests/occt_model_gen tests/io/data/iges/vase.igs
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomConvert.hxx>
#include <GeomToIGES_GeomSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESEntity.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp.hxx>

#include <cstdio>

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: occt_model_gen OUT.igs\n");
        return 1;
    }
    // (radius, height) of the profile, in the xz-plane
    const double profile[][2] = {{1.0, 0.0}, {1.35, 0.45}, {1.6, 1.1}, {1.3, 1.9}, {0.75, 2.5},
                                 {0.7, 2.9}, {0.95, 3.3}, {1.15, 3.45}};
    const int n = sizeof profile / sizeof profile[0];
    TColgp_Array1OfPnt pts(1, n);
    for (int k = 0; k < n; k++)
        pts.SetValue(k + 1, gp_Pnt(profile[k][0], 0.0, profile[k][1]));
    Handle(Geom_BSplineCurve) curve = GeomAPI_PointsToBSpline(pts, 3, 3).Curve();
    Handle(Geom_SurfaceOfRevolution) rev = new Geom_SurfaceOfRevolution(curve, gp::OZ());
    Handle(Geom_BSplineSurface) nurbs = GeomConvert::SurfaceToBSplineSurface(rev);
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", 0);
    GeomToIGES_GeomSurface gs;
    gs.SetModel(writer.Model());
    gs.SetUnit(1.0);
    double u0, u1, v0, v1;
    nurbs->Bounds(u0, u1, v0, v1);
    writer.AddEntity(gs.TransferSurface(nurbs, u0, u1, v0, v1));
    writer.ComputeModel();
    if (!writer.Write(argv[1]))
        return 1;
    std::printf("%s: NURBS of degree %d x %d, %d x %d poles, %d x %d knots\n", argv[1], nurbs->UDegree(),
                nurbs->VDegree(), nurbs->NbUPoles(), nurbs->NbVPoles(), nurbs->NbUKnots(), nurbs->NbVKnots());
    return 0;
}
