// OpenCASCADE's distance computation on a CAD part as the peer of closest points on a model's
// locator: the same STEP file read by both (STEPControl_Reader; bs_model_read_step_file), the 200
// points of the part's .ref file measured ROUNDS times against the part's faces by
// BRepExtrema_DistShapeShape (a vertex against the compound of the faces, so that a point inside
// the solid gets its distance to the surface) and by bs_locator_closest_point, one thread each, in
// CPU seconds in the same run. Counts the points where the kernel's answer is not the global one
// (ours nearer by more than 1e-7 D, the kernel's own tolerance) and where ours would be farther
// than the kernel's by more than that (none expected). Built only when OpenCASCADE is found
// (bench/CMakeLists.txt):
//   build/bench/occt_model_closest [data/cad/PART.step] [ROUNDS]
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

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

int main(int argc, char **argv)
{
    std::string path = argc > 1 ? argv[1] : "data/cad/bottle.step";
    int rounds = argc > 2 ? std::atoi(argv[2]) : 1;
    std::string ref = path.substr(0, path.find_first_of(".-", path.find_last_of('/') + 1)) + ".ref";
    std::FILE *f = std::fopen(ref.c_str(), "r");
    if (f == nullptr || rounds < 1) {
        std::fprintf(stderr, "usage: occt_model_closest [data/cad/PART.step] [ROUNDS] (needs PART.ref)\n");
        return 2;
    }
    std::vector<double> q;
    double box[6] = {0, 0, 0, 0, 0, 0};
    char line[512];
    while (std::fgets(line, sizeof line, f)) {
        double r[3];
        if (std::sscanf(line, "closest %lf %lf %lf", &r[0], &r[1], &r[2]) == 3)
            q.insert(q.end(), r, r + 3);
        (void)std::sscanf(line, "box %lf %lf %lf %lf %lf %lf", &box[0], &box[1], &box[2], &box[3], &box[4], &box[5]);
    }
    std::fclose(f);
    size_t n = q.size() / 3;
    double diag = std::sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                            (box[5] - box[2]) * (box[5] - box[2]));

    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) {
        std::fprintf(stderr, "%s: OpenCASCADE did not read it\n", path.c_str());
        return 1;
    }
    TopoDS_Shape shape = reader.OneShape();
    TopoDS_Compound faces;
    BRep_Builder builder;
    builder.MakeCompound(faces);
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
        builder.Add(faces, e.Current());
    std::vector<double> d_occt(n, NAN), d_ours(n, NAN);
    double c0 = seconds();
    for (int r = 0; r < rounds; r++)
        for (size_t k = 0; k < n; k++) {
            TopoDS_Vertex v = BRepBuilderAPI_MakeVertex(gp_Pnt(q[3 * k], q[3 * k + 1], q[3 * k + 2]));
            BRepExtrema_DistShapeShape dss(v, faces);
            d_occt[k] = dss.IsDone() ? dss.Value() : NAN;
        }
    double c1 = seconds();

    bs_model *m = nullptr;
    bs_locator *L = nullptr;
    if (bs_model_read_step_file(path.c_str(), nullptr, &m) != BS_OK)
        return 1;
    double c2 = seconds();
    if (bs_locator_create_model(m, &L) != BS_OK)
        return 1;
    double c3 = seconds();
    const ptrdiff_t s3 = 3 * sizeof(double);
    bs_cview qv[3] = {{q.data(), n, s3}, {q.data() + 1, n, s3}, {q.data() + 2, n, s3}};
    bs_view dv = {d_ours.data(), n, sizeof(double)};
    for (int r = 0; r < rounds; r++) {
        bs_status st = bs_locator_closest_point(L, n, qv, nullptr, nullptr, &dv, nullptr);
        if (st != BS_OK) {
            std::fprintf(stderr, "bs_locator_closest_point: %s\n", bs_status_string(st));
            return 1;
        }
    }
    double c4 = seconds();

    size_t kernel_not_global = 0, ours_farther = 0;
    for (size_t k = 0; k < n; k++) {
        kernel_not_global += d_ours[k] < d_occt[k] - 1e-7 * diag;
        ours_farther += d_ours[k] > d_occt[k] + 1e-7 * diag + 1e-9 * (diag + d_occt[k]);
    }
    double total = static_cast<double>(n) * rounds;
    double us_occt = 1e6 * (c1 - c0) / total, us_ours = 1e6 * (c4 - c3) / total;
    std::printf("%s: %zu points x %d; the kernel's not the closest (ours nearer by > 1e-7 D): %zu; "
                "ours farther than the kernel's: %zu\n", path.c_str(), n, rounds, kernel_not_global, ours_farther);
    std::printf("OpenCASCADE BRepExtrema_DistShapeShape: %.1f us per point\n", us_occt);
    std::printf("libbezsurf bs_locator_closest_point on the model: build %.1f ms, %.1f us per point; "
                "%.1fx faster per point\n", 1e3 * (c3 - c2), us_ours, us_occt / us_ours);
    bs_locator_destroy(L);
    bs_model_destroy(m);
    return 0;
}
