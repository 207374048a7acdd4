#pragma once

// Engines the peer benchmark times beside cavity and CGAL when their builds are given at
// configure time (bench/CMakeLists.txt). Each is prepared outside the timed region (the input
// copied into its own structures, as CGAL's points are) and then run once, timed.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace peers {

/// Triangulates the prepared input; returns the number of finite tetrahedra.
using PreparedRun = std::function<std::size_t()>;

struct PeerEngine {
    std::string name;
    unsigned threads = 1;
    std::function<PreparedRun(const cavity::core::PointSet&)> prepare;
};

/// The engines this build has, each on one thread and, where it has threads, on `threads`.
std::vector<PeerEngine> optional_engines(unsigned threads);

}  // namespace peers
