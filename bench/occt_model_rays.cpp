// OpenCASCADE's ray casting on a CAD part as the peer of bs_locator_create_model: the same STEP
// file read by both (STEPControl_Reader; bs_model_read_step_file), the 400 rays of the part's
// .ref file cast ROUNDS times by IntCurvesFace_ShapeIntersector (Load with tolerance 1e-7, then
// PerformNearest over [0, +inf)) and by bs_locator_intersect, one thread each, in CPU seconds in
// the same run. Counts the rays where the two first hits differ by more than 1e-6 of the part's
// diagonal. Built only when OpenCASCADE is found (bench/CMakeLists.txt):
//   build/bench/occt_model_rays [data/cad/PART.step] [ROUNDS]
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt.hxx>

#include <bezsurf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
    int rounds = argc > 2 ? std::atoi(argv[2]) : 10;
    std::string ref = path.substr(0, path.find_first_of(".-", path.find_last_of('/') + 1)) + ".ref";
    std::FILE *f = std::fopen(ref.c_str(), "r");
    if (f == nullptr || rounds < 1) {
        std::fprintf(stderr, "usage: occt_model_rays [data/cad/PART.step] [ROUNDS] (needs PART.ref)\n");
        return 2;
    }
    std::vector<double> o, d;
    double box[6] = {0, 0, 0, 0, 0, 0};
    char line[512];
    while (std::fgets(line, sizeof line, f)) {
        double r[6];
        if (std::sscanf(line, "ray %lf %lf %lf %lf %lf %lf", &r[0], &r[1], &r[2], &r[3], &r[4], &r[5]) == 6) {
            o.insert(o.end(), r, r + 3);
            d.insert(d.end(), r + 3, r + 6);
        }
        (void)std::sscanf(line, "box %lf %lf %lf %lf %lf %lf", &box[0], &box[1], &box[2], &box[3], &box[4], &box[5]);
    }
    std::fclose(f);
    size_t n = o.size() / 3;
    double diag = std::sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                            (box[5] - box[2]) * (box[5] - box[2]));

    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) {
        std::fprintf(stderr, "%s: OpenCASCADE did not read it\n", path.c_str());
        return 1;
    }
    TopoDS_Shape shape = reader.OneShape();
    double c0 = seconds();
    IntCurvesFace_ShapeIntersector inter;
    inter.Load(shape, 1e-7);
    double c1 = seconds();
    std::vector<double> t_occt(n, INFINITY), t_ours(n, INFINITY);
    for (int r = 0; r < rounds; r++)
        for (size_t k = 0; k < n; k++) {
            gp_Lin ray(gp_Pnt(o[3 * k], o[3 * k + 1], o[3 * k + 2]), gp_Dir(d[3 * k], d[3 * k + 1], d[3 * k + 2]));
            inter.PerformNearest(ray, 0.0, RealLast());
            t_occt[k] = inter.IsDone() && inter.NbPnt() > 0 ? inter.WParameter(1) : INFINITY;
        }
    double c2 = seconds();

    bs_model *m = nullptr;
    bs_locator *L = nullptr;
    if (bs_model_read_step_file(path.c_str(), nullptr, &m) != BS_OK)
        return 1;
    double c3 = seconds();
    if (bs_locator_create_model(m, &L) != BS_OK)
        return 1;
    double c4 = seconds();
    const ptrdiff_t s3 = 3 * sizeof(double);
    bs_cview ov[3] = {{o.data(), n, s3}, {o.data() + 1, n, s3}, {o.data() + 2, n, s3}};
    bs_cview dv[3] = {{d.data(), n, s3}, {d.data() + 1, n, s3}, {d.data() + 2, n, s3}};
    bs_view tv = {t_ours.data(), n, sizeof(double)};
    std::vector<uint32_t> face(n);
    for (int r = 0; r < rounds; r++)
        if (bs_locator_intersect(L, n, ov, dv, nullptr, face.data(), nullptr, &tv, nullptr) != BS_OK)
            return 1;
    double c5 = seconds();

    size_t differ = 0, hits = 0;
    for (size_t k = 0; k < n; k++) {
        double a = face[k] == UINT32_MAX ? INFINITY : t_ours[k], b = t_occt[k];
        hits += std::isfinite(a);
        differ += !((std::isinf(a) && std::isinf(b)) || std::fabs(a - b) <= 1e-6 * diag);
    }
    double total = static_cast<double>(n) * rounds;
    double us_occt = 1e6 * (c2 - c1) / total, us_ours = 1e6 * (c5 - c4) / total;
    std::printf("%s: %zu rays x %d, %zu hit; first hits differing by more than 1e-6 D: %zu\n", path.c_str(), n,
                rounds, hits, differ);
    std::printf("OpenCASCADE IntCurvesFace_ShapeIntersector: load %.1f ms, %.2f us per ray\n", 1e3 * (c1 - c0), us_occt);
    std::printf("libbezsurf bs_locator_create_model: build %.1f ms, %.2f us per ray; %.1fx faster per ray\n",
                1e3 * (c4 - c3), us_ours, us_occt / us_ours);
    bs_locator_destroy(L);
    bs_model_destroy(m);
    return 0;
}
