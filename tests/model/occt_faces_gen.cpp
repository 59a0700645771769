// Writes faces with OpenCASCADE's STEP and IGES writers for the model readers' tests, each with
// the kernel's own area (BRepGProp, 1e-10).
// Faces on sweeps of a closed curve: a circle of radius 1.5 about (6, 0, 0) in the xz-plane
// revolved about z (a torus written as its tube revolved: SURFACE_OF_REVOLUTION, IGES 120) and the
// same circle extruded along y (SURFACE_OF_LINEAR_EXTRUSION, IGES 122). The faces' ranges along
// the circle cross its start, so their trims run across the seam of the circle's parameter:
//   tube-band   revolution, the whole turn, circle parameter -1 .. 1
//   tube-shift  revolution, angle 1 .. 4, circle parameter 5 .. 7.5 (past 2 pi)
//   tube-full   revolution, the whole torus (a closed shell of one face, both directions seams)
//   pipe-shift  extrusion, circle parameter 5 .. 7.5, length 0 .. 3
// each as NAME.step, NAME.igs (144 trimmed surface) and NAME-brep.igs (the IGES B-rep form of a
// lone face: a 510 that no 514 shell or 186 solid holds).
//   open-box    a box of 4 x 3 x 2 without its top, five faces sewn into an open shell: as
//               open-box-brep.igs, a 514 shell that no 186 solid holds
// Build: only when OpenCASCADE is found (tests/model/CMakeLists.txt); run:
//   build/tests/occt_faces_gen tests/model/data/faces
// writes DIR/NAME.* and DIR/NAME.ref for each.
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Circle.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax2.hxx>

#include <cstdio>
#include <string>

static bool write_brep_iges(const std::string &base, const TopoDS_Shape &shape)
{
    IGESControl_Writer iges("MM", 1);
    iges.AddShape(shape);
    iges.ComputeModel();
    return iges.Write((base + "-brep.igs").c_str());
}

static bool write_area(const std::string &base, const TopoDS_Shape &shape)
{
    GProp_GProps area;
    BRepGProp::SurfaceProperties(shape, area, 1e-10);
    FILE *f = std::fopen((base + ".ref").c_str(), "w");
    if (f == nullptr)
        return false;
    std::fprintf(f, "# OpenCASCADE reference: BRepGProp area (1e-10)\narea %.17g\n", area.Mass());
    return std::fclose(f) == 0;
}

static bool write(const std::string &dir, const char *name, const Handle(Geom_Surface) & s, double u0, double u1,
                  double v0, double v1, bool closed)
{
    TopoDS_Face face = BRepBuilderAPI_MakeFace(s, u0, u1, v0, v1, 1e-7);
    std::string base = dir + "/" + name;
    if (!write_brep_iges(base, face))
        return false;
    STEPControl_Writer step;
    if (step.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone || step.Write((base + ".step").c_str()) != IFSelect_RetDone)
        return false;
    IGESControl_Writer iges("MM", 0);
    iges.AddShape(face);
    iges.ComputeModel();
    if (!iges.Write((base + ".igs").c_str()))
        return false;
    GProp_GProps area, volume;
    BRepGProp::SurfaceProperties(face, area, 1e-10);
    FILE *f = std::fopen((base + ".ref").c_str(), "w");
    if (f == nullptr)
        return false;
    std::fprintf(f, "# OpenCASCADE reference: BRepGProp area (1e-10)%s\narea %.17g\n", closed ? " and volume" : "",
                 area.Mass());
    if (closed) {
        BRepGProp::VolumeProperties(face, volume, 1e-10);
        std::fprintf(f, "volume %.17g\n", volume.Mass());
    }
    return std::fclose(f) == 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: occt_faces_gen DIR\n");
        return 1;
    }
    IGESControl_Controller::Init();
    const double turn = 2.0 * M_PI;
    Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(gp_Pnt(6, 0, 0), gp::DY()), 1.5);
    Handle(Geom_Surface) tube = new Geom_SurfaceOfRevolution(circle, gp::OZ());
    Handle(Geom_Surface) pipe = new Geom_SurfaceOfLinearExtrusion(circle, gp::DY());
    bool ok = write(argv[1], "tube-band", tube, 0, turn, -1, 1, false) &&
              write(argv[1], "tube-shift", tube, 1, 4, 5, 7.5, false) &&
              write(argv[1], "tube-full", tube, 0, turn, 0, turn, true) &&
              write(argv[1], "pipe-shift", pipe, 5, 7.5, 0, 3, false);
    BRepBuilderAPI_Sewing sewing;
    int k = 0;
    for (TopExp_Explorer e(BRepPrimAPI_MakeBox(4, 3, 2).Shape(), TopAbs_FACE); e.More(); e.Next(), k++)
        if (k != 5) /* the sixth face of OpenCASCADE's box is its top */
            sewing.Add(e.Current());
    sewing.Perform();
    TopoDS_Shape open_box = sewing.SewedShape();
    std::string base = std::string(argv[1]) + "/open-box";
    ok = ok && open_box.ShapeType() == TopAbs_SHELL && write_brep_iges(base, open_box) && write_area(base, open_box);
    return ok ? 0 : 1;
}
