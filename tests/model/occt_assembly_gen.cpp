// Writes a STEP assembly with OpenCASCADE's XCAF writer, and the kernel's own answers for it: a
// plate with a drilled hole, and a sub-assembly of two cone pegs (one upright, one turned on its
// side) placed twice in it, once moved and once turned about a vertical axis: five instances of
// two parts, nested two deep. The .ref gives the faces of all instances, the area and volume
// (BRepGProp, 1e-9) and the box of the placed shapes, in the format of data/cad/*.ref.
// Build: only when OpenCASCADE is found (tests/model/CMakeLists.txt); run:
//   build/tests/occt_assembly_gen tests/model/data/step/assembly
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <cstdio>
#include <string>

static gp_Trsf moved(double x, double y, double z)
{
    gp_Trsf t;
    t.SetTranslation(gp_Vec(x, y, z));
    return t;
}

static gp_Trsf turned(const gp_Ax1 &axis, double angle)
{
    gp_Trsf t;
    t.SetRotation(axis, angle);
    return t;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: occt_assembly_gen OUT (writes OUT.step and OUT.ref)\n");
        return 1;
    }
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TopoDS_Shape plate = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(40, 20, 4).Shape(),
                                         BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(10, 10, -1), gp::DZ()), 3, 6).Shape())
                             .Shape();
    TopoDS_Shape peg = BRepPrimAPI_MakeCone(3, 1.5, 8).Shape();
    TDF_Label plate_label = tool->AddShape(plate, false);
    TDF_Label peg_label = tool->AddShape(peg, false);
    TDF_Label pair = tool->NewShape();
    tool->AddComponent(pair, peg_label, TopLoc_Location(moved(0, 0, 4)));
    tool->AddComponent(pair, peg_label, TopLoc_Location(moved(8, 0, 4) * turned(gp::OX(), M_PI / 2)));
    TDF_Label root = tool->NewShape();
    tool->AddComponent(root, plate_label, TopLoc_Location());
    tool->AddComponent(root, pair, TopLoc_Location(moved(25, 5, 0)));
    tool->AddComponent(root, pair, TopLoc_Location(moved(-10, 3, 0) * turned(gp_Ax1(gp_Pnt(30, 10, 0), gp::DZ()), 2.0)));
    tool->UpdateAssemblies();

    std::string out = argv[1];
    STEPCAFControl_Writer writer;
    if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write((out + ".step").c_str()) != IFSelect_RetDone) {
        std::fprintf(stderr, "%s.step: not written\n", out.c_str());
        return 1;
    }
    TopoDS_Shape all = tool->GetShape(root);
    int faces = 0;
    for (TopExp_Explorer e(all, TopAbs_FACE); e.More(); e.Next())
        faces++;
    GProp_GProps area, volume;
    BRepGProp::SurfaceProperties(all, area, 1e-9);
    BRepGProp::VolumeProperties(all, volume, 1e-9);
    Bnd_Box box;
    BRepBndLib::AddOptimal(all, box, Standard_False);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    FILE *f = std::fopen((out + ".ref").c_str(), "w");
    if (f == nullptr)
        return 1;
    std::fprintf(f, "# OpenCASCADE reference for the assembly: BRepGProp area and volume (1e-9), optimal box\n");
    std::fprintf(f, "faces %d\ninstances 5\narea %.17g\nvolume %.17g\nbox %.17g %.17g %.17g %.17g %.17g %.17g\n", faces,
                 area.Mass(), volume.Mass(), x0, y0, z0, x1, y1, z1);
    return std::fclose(f) == 0 ? 0 : 1;
}
