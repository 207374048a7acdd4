// Compiled only when CGAL's headers are found (experiments/CMakeLists.txt); otherwise
// peer_cgal_absent.cpp reports the peer as unavailable.
#include <vector>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "peer_engines.h"

namespace cavity::experiments::detail {

bool cgal_available() {
    return true;
}

EngineReport cgal_delaunay(core::PointSet points) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> input;
    input.reserve(points.size());
    for (const auto& p : points.points) {
        input.emplace_back(p.x, p.y, p.z);
    }
    points = core::PointSet{};
    const double start = process_cpu_seconds();
    const CGAL::Delaunay_triangulation_3<Kernel> triangulation(input.begin(), input.end());
    const double seconds = process_cpu_seconds() - start;
    return {seconds, static_cast<std::uint64_t>(triangulation.number_of_finite_cells())};
}

}  // namespace cavity::experiments::detail
