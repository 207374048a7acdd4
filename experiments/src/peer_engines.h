#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "cavity/core/input/point_set.h"
#include "child_process.h"

/// The engines of the peers suite, each meant to run in a child process of its own
/// (run_in_child), where its peak memory is its own. Private to the experiments layer.
namespace cavity::experiments::detail {

/// Whether this build has the CGAL runner (CGAL's headers were found at configure time).
bool cgal_available();

/// CGAL's Delaunay_triangulation_3 over Epick, built from the whole range (its own spatial sort):
/// CPU seconds of the construction and its finite cells. The points are copied into CGAL's type
/// and `points` is released before the clock starts, so the peak holds one copy of the input.
/// \throws Error when the build has no CGAL.
EngineReport cgal_delaunay(core::PointSet points);

/// What one TetGen run measured.
struct TetgenRun {
    bool ok = false;
    std::string failure;     ///< why not, when !ok
    double cpu_seconds = 0;  ///< the whole process (reading .node, writing .ele included)
    std::optional<double> delaunay_seconds;  ///< TetGen's own "Delaunay seconds" (clock())
    std::uint64_t tets = 0;                  ///< from the .ele header
    std::uint64_t peak_bytes = 0;            ///< the process's peak resident set size
};

/// Runs `tetgen -NF PREFIX.node` (a plain Delaunay tetrahedralization of the points: no
/// -p, -q or -a, so no Steiner points; .node and .face output suppressed) and reads the
/// tetrahedra count from PREFIX.1.ele. A TetGen that fails is reported, not thrown.
TetgenRun run_tetgen(const std::filesystem::path& tetgen, const std::filesystem::path& prefix);

}  // namespace cavity::experiments::detail
