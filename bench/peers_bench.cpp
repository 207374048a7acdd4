// cavity against CGAL's Delaunay_triangulation_3 (Epick, range insertion with its spatial sort)
// on the same points in the same process. Prints one CSV row per (distribution, n, engine, run):
// the CPU seconds for order + triangulation, the tetrahedra, and peak memory when one engine runs
// alone (--only). The ratios are made by bench/run_peers_bench.sh.

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <sys/resource.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<Kernel>;

// Process CPU time rather than wall-clock time: on a shared machine a descheduled engine would
// otherwise be charged for other processes' work. Both engines are single-threaded.
double now() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024u;
}

struct Run {
    double seconds;
    std::size_t tets;
};

Run run_cavity(const cavity::core::PointSet& points) {
    const double start = now();
    cavity::core::OrderOptions order;  // the defaults: BRIO, ratio 1/2, Hilbert within rounds
    const auto sequence = cavity::core::make_insertion_order(points.points, order).sequence;
    const auto tri =
        cavity::core::triangulate(points, sequence, cavity::core::TriangulateOptions{});
    return {now() - start, tri.tets.size()};
}

Run run_cgal(const cavity::core::PointSet& points) {
    std::vector<Kernel::Point_3> cgal_points;
    cgal_points.reserve(points.size());
    for (const auto& p : points.points) {
        cgal_points.emplace_back(p.x, p.y, p.z);
    }
    const double start = now();
    CgalDelaunay dt(cgal_points.begin(), cgal_points.end());
    const double seconds = now() - start;
    return {seconds, dt.number_of_finite_cells()};
}

}  // namespace

int main(int argc, char** argv) {
    std::string distribution = "cube";
    std::size_t n = 100000;
    int repeats = 3;
    std::string only;  // "cavity" or "cgal": one engine alone, for its peak memory
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--dist") {
            distribution = argv[i + 1];
        } else if (flag == "--n") {
            n = std::strtoull(argv[i + 1], nullptr, 10);
        } else if (flag == "--repeats") {
            repeats = std::atoi(argv[i + 1]);
        } else if (flag == "--only") {
            only = argv[i + 1];
        } else {
            std::fprintf(stderr,
                         "usage: %s [--dist D] [--n N] [--repeats R] [--only cavity|cgal]\n",
                         argv[0]);
            return 2;
        }
    }
    const auto points =
        cavity::core::generate_points(distribution, n, 1, cavity::core::WeightSpec{});
    const std::uint64_t baseline_rss = peak_rss_bytes();
    for (int r = 0; r < repeats; ++r) {
        // Alternate which engine goes first so neither always meets a cold cache.
        for (int k = 0; k < 2; ++k) {
            const bool cavity_turn = (k + r) % 2 == 0;
            const char* engine = cavity_turn ? "cavity" : "cgal";
            if (!only.empty() && only != engine) {
                continue;
            }
            const Run run = cavity_turn ? run_cavity(points) : run_cgal(points);
            std::printf("%s,%zu,%s,%d,%.6f,%zu,%llu,%llu\n",
                        distribution.c_str(),
                        points.size(),
                        engine,
                        r,
                        run.seconds,
                        run.tets,
                        static_cast<unsigned long long>(only.empty() ? 0 : peak_rss_bytes()),
                        static_cast<unsigned long long>(baseline_rss));
            std::fflush(stdout);
        }
    }
    return 0;
}
