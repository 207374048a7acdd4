// cavity against CGAL's Delaunay_triangulation_3 (Epick, range insertion with its spatial sort)
// on the same points in the same process, cavity's parallel construction (--threads T) and its
// instrumented (counting) engine beside its sequential engine, and the optional engines of
// peer_engines.h (HXT) when the build has them. The points are generated (--dist, --n) or read from
// a file (--points: .node, .xyz, .ply, as `cavity triangulate` reads them). Prints one CSV row per
// (input, n, engine, run): the CPU and wall seconds for order + triangulation, the tetrahedra, and
// peak memory when one engine runs alone (--only). The ratios are made by bench/peers_report.py.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <sys/resource.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/io/point_io.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "peer_engines.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<Kernel>;

// Process CPU time compares the single-threaded engines: on a shared machine a descheduled engine
// would otherwise be charged for other processes' work. The parallel construction is judged by
// wall time, which is what threads shorten.
double clock_seconds(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Stamp {
    double cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    double wall = clock_seconds(CLOCK_MONOTONIC);
};

std::uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024u;
}

struct Run {
    double seconds;
    double wall_seconds;
    std::size_t tets;
};

Run since(const Stamp& start, std::size_t tets) {
    const Stamp end;
    return {end.cpu - start.cpu, end.wall - start.wall, tets};
}

/// threads 0: the sequential engine; else the parallel construction on that many threads. The
/// engine borrows the points, as the CLI lets it (they are back, unchanged, when it returns), and
/// keeps the sequence: the peak holds one copy of each. `count`: the instrumented engine that
/// `--stats` and the experiments run (stage, walk and tetrahedron counters; no conflict counting).
Run run_cavity(cavity::core::PointSet& points, unsigned threads, bool count = false) {
    const Stamp start;
    cavity::core::OrderOptions order;  // the defaults: BRIO, ratio 1/8, Hilbert within rounds
    order.threads = std::max(1u, threads);
    auto sequence = cavity::core::make_insertion_order(points.points, order).sequence;
    cavity::core::TriangulateOptions options;
    options.threads = threads;
    options.count = count;
    const auto tri = cavity::core::triangulate_in_place(points, std::move(sequence), options);
    return since(start, tri.tets.size());
}

Run run_prepared(const peers::PreparedRun& run) {
    const Stamp start;
    const std::size_t tets = run();
    return since(start, tets);
}

Run run_cgal(const cavity::core::PointSet& points) {
    std::vector<Kernel::Point_3> cgal_points;
    cgal_points.reserve(points.size());
    for (const auto& p : points.points) {
        cgal_points.emplace_back(p.x, p.y, p.z);
    }
    const Stamp start;
    CgalDelaunay dt(cgal_points.begin(), cgal_points.end());
    return since(start, dt.number_of_finite_cells());
}

}  // namespace

int main(int argc, char** argv) {
    std::string distribution = "cube";
    std::string points_file;  // when given, the input instead of a generated distribution
    std::size_t n = 100000;
    int repeats = 3;
    unsigned threads = 2;  // of the engines "cavity-threads" and "hxt-threads"
    std::string only;      // one engine alone, for its memory
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--dist") {
            distribution = argv[i + 1];
        } else if (flag == "--points") {
            points_file = argv[i + 1];
        } else if (flag == "--n") {
            n = std::strtoull(argv[i + 1], nullptr, 10);
        } else if (flag == "--repeats") {
            repeats = std::atoi(argv[i + 1]);
        } else if (flag == "--only") {
            only = argv[i + 1];
        } else if (flag == "--threads") {
            threads = static_cast<unsigned>(std::strtoul(argv[i + 1], nullptr, 10));
        } else {
            std::fprintf(stderr,
                         "usage: %s [--dist D --n N | --points FILE] [--repeats R] [--threads T] "
                         "[--only ENGINE]\n",
                         argv[0]);
            return 2;
        }
    }
    auto points = points_file.empty() ? cavity::core::generate_points(
                                            distribution, n, 1, cavity::core::WeightSpec{})
                                      : cavity::core::read_points(points_file, false);
    const std::string input = points_file.empty() ? distribution : points_file;
    const std::vector<peers::PeerEngine> optional = peers::optional_engines(threads);
    std::vector<std::string> engines{"cavity", "cgal", "cavity-threads", "cavity-counting"};
    for (const auto& e : optional) {
        engines.push_back(e.name);
    }
    const std::uint64_t baseline_rss = peak_rss_bytes();
    for (int r = 0; r < repeats; ++r) {
        // Rotate which engine goes first so none always meets a cold cache.
        for (std::size_t k = 0; k < engines.size(); ++k) {
            const std::string& engine = engines[(k + static_cast<std::size_t>(r)) % engines.size()];
            if (!only.empty() && only != engine) {
                continue;
            }
            unsigned engine_threads = engine == "cavity-threads" ? threads : 1u;
            Run run{};
            if (engine == "cgal") {
                run = run_cgal(points);
            } else if (engine == "cavity") {
                run = run_cavity(points, 0);
            } else if (engine == "cavity-threads") {
                run = run_cavity(points, threads);
            } else if (engine == "cavity-counting") {
                run = run_cavity(points, 0, true);
            } else {
                const auto& peer = *std::find_if(optional.begin(),
                                                 optional.end(),
                                                 [&](const auto& e) { return e.name == engine; });
                engine_threads = peer.threads;
                run = run_prepared(peer.prepare(points));
            }
            std::printf("%s,%zu,%s,%u,%d,%.6f,%.6f,%zu,%llu,%llu\n",
                        input.c_str(),
                        points.size(),
                        engine.c_str(),
                        engine_threads,
                        r,
                        run.seconds,
                        run.wall_seconds,
                        run.tets,
                        static_cast<unsigned long long>(only.empty() ? 0 : peak_rss_bytes()),
                        static_cast<unsigned long long>(baseline_rss));
            std::fflush(stdout);
        }
    }
    return 0;
}
