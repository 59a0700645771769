// OpenCASCADE's BRepGProp as the peer of bs_model_properties: the same STEP file read by both,
// area (SurfaceProperties) and volume (VolumeProperties) at relative tolerance 1e-9, one thread,
// CPU time in the same run (ROUNDS times each). Where the part has a closed form (the sphere of
// radius 5, the torus of radii 6 and 1.5, the cone frustum of radii 4 and 1 and height 7, as
// data/cad/README.md describes them), both answers' errors against it.
// Built only when OpenCASCADE is found (bench/CMakeLists.txt):
//   build/bench/occt_model_props [data/cad/PART.step] [ROUNDS]
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>

#include <bezsurf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

static double seconds() // CPU time: steadier on a loaded machine
{
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

// The closed-form area and volume of the parts that have one (0 when none).
static void exact(const std::string &path, double *area, double *volume)
{
    const double pi = 3.14159265358979323846;
    *area = *volume = 0.0;
    std::string name = path.substr(path.find_last_of('/') + 1);
    if (name == "sphere.step") {
        *area = 4.0 * pi * 25.0;
        *volume = 4.0 / 3.0 * pi * 125.0;
    } else if (name == "torus.step") {
        *area = 4.0 * pi * pi * 6.0 * 1.5;
        *volume = 2.0 * pi * pi * 6.0 * 1.5 * 1.5;
    } else if (name == "cone.step") {
        *area = pi * (5.0 * std::sqrt(58.0) + 17.0);
        *volume = pi * 7.0 / 3.0 * (16.0 + 4.0 + 1.0);
    }
}

int main(int argc, char **argv)
{
    std::string path = argc > 1 ? argv[1] : "data/cad/bottle.step";
    int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
    if (rounds < 1) {
        std::fprintf(stderr, "usage: occt_model_props [data/cad/PART.step] [ROUNDS]\n");
        return 2;
    }
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) {
        std::fprintf(stderr, "%s: OpenCASCADE did not read it\n", path.c_str());
        return 1;
    }
    TopoDS_Shape shape = reader.OneShape();
    double occt_area = 0.0, occt_volume = 0.0;
    double c0 = seconds();
    for (int r = 0; r < rounds; r++) {
        GProp_GProps surface, volume;
        BRepGProp::SurfaceProperties(shape, surface, 1e-9);
        BRepGProp::VolumeProperties(shape, volume, 1e-9);
        occt_area = surface.Mass();
        occt_volume = volume.Mass();
    }
    double occt_s = (seconds() - c0) / rounds;

    bs_model *m = nullptr;
    if (bs_model_read_step_file(path.c_str(), nullptr, &m) != BS_OK)
        return 1;
    double area = 0.0, volume = 0.0, centroid[3];
    double c1 = seconds();
    for (int r = 0; r < rounds; r++)
        if (bs_model_properties(m, 1e-9, &area, &volume, centroid) != BS_OK)
            return 1;
    double ours_s = (seconds() - c1) / rounds;
    bs_model_destroy(m);

    double ea, ev;
    exact(path, &ea, &ev);
    std::printf("%s at relative tolerance 1e-9, one thread\n", path.c_str());
    std::printf("OpenCASCADE BRepGProp:  %9.2f ms  area %.15g  volume %.15g\n", 1e3 * occt_s, occt_area, occt_volume);
    std::printf("bs_model_properties:    %9.2f ms  area %.15g  volume %.15g\n", 1e3 * ours_s, area, volume);
    if (ea > 0.0)
        std::printf("closed form:                         area %.15g  volume %.15g\n"
                    "relative errors: OpenCASCADE area %.2e volume %.2e; ours area %.2e volume %.2e\n",
                    ea, ev, std::fabs(occt_area - ea) / ea, std::fabs(occt_volume - ev) / ev, std::fabs(area - ea) / ea,
                    std::fabs(volume - ev) / ev);
    std::printf("ratio: %.1fx faster\n", occt_s / ours_s);
    return 0;
}
