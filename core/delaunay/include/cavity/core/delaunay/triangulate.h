#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "cavity/core/base/names.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/geometry/counters.h"
#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// Point location (§5.4 conflict graph, §5.5 walking).
/// kFullConflictGraph keeps every conflict of every tetrahedron (Clarkson–Shor), the algorithm
/// Theorem 5.4 analyses; it counts the conflicts as it goes.
/// kStraightWalk is the book's straight-line walk (straight_walk.h), kWalk the visibility walk.
enum class LocateKind { kWalk, kConflictGraph, kFullConflictGraph, kStraightWalk };
/// Storage (§5.1 face hash table, or the compact array layout).
enum class StorageKind { kArray, kHash };

/// The locators' and storages' names (`--locate`, `--storage`, Python, suite files), one row per
/// value: tests run every row.
inline constexpr std::array<NamedKind<LocateKind>, 4> kLocateKinds{{
    {"walk", LocateKind::kWalk, "the visibility walk (§5.5)"},
    {"conflict-graph",
     LocateKind::kConflictGraph,
     "the book's conflict graph, one cell per point (§5.4)"},
    {"conflict-graph-all",
     LocateKind::kFullConflictGraph,
     "every conflict kept (Clarkson-Shor; counts Theorem 5.4's conflicts)"},
    {"straight-walk", LocateKind::kStraightWalk, "the book's straight-line walk (§5.5)"},
}};
inline constexpr std::array<NamedKind<StorageKind>, 2> kStorageKinds{{
    {"array", StorageKind::kArray, "four neighbours per tetrahedron in flat arrays"},
    {"hash", StorageKind::kHash, "the book's face hash table (Figure 5.1)"},
}};

/// A name of kLocateKinds or kStorageKinds. \throws Error for any other name.
LocateKind parse_locate_kind(std::string_view name);
StorageKind parse_storage_kind(std::string_view name);

struct TriangulateOptions {
    LocateKind locate = LocateKind::kWalk;
    StorageKind storage = StorageKind::kArray;
    bool count = false;  ///< fill Triangulation::counters (instrumented engine)
    /// Also count every created tetrahedron's conflicts (Σj, Theorem 5.4) exactly, by
    /// ConflictCountingObserver (conflict_counter.h); implies `count`. Costs about one exact test
    /// per conflict: Σj ≈ 81 n ln n in a uniform cube.
    bool count_conflicts = false;
    std::uint64_t seed = 0;  ///< the walk's stochastic choices
    /// How the first tetrahedron is taken from the sequence (bootstrap.h): kFirst keeps the
    /// sequence as it is for points in general position, as exact identities need.
    BootstrapRule bootstrap = BootstrapRule::kWidest;
    /// Insert only the first `prefix` points of the sequence (after the bootstrap four are put
    /// first and repeats removed); 0 inserts all. The rest stay uninserted but are still counted
    /// as conflicts, so a prefix run gives the conflicts a full run creates in its first `prefix`
    /// insertions, exactly, at a small part of its cost: Σj/n varies between seeds mostly through
    /// the first insertions (their circumballs hold about n/i points), so more seeds of the
    /// prefix narrow Theorem 5.4's interval where full runs are too costly (experiments' prefix).
    std::size_t prefix = 0;
    /// 0: the sequential engine. N >= 1: the parallel construction on N threads
    /// (parallel/parallel_build.h): the plain engine (no counters), the visibility walk and the
    /// array storage only; the same tetrahedra as the sequential engine, stored in a canonical
    /// order that is the same for every N.
    unsigned threads = 0;
    /// Called now and then with (points processed, total); may be empty.
    std::function<void(std::size_t, std::size_t)> progress;
};

/// A (weighted) Delaunay triangulation of a point set under the symbolic perturbation, in the
/// input's own indices.
struct Triangulation {
    /// Solid tetrahedra as input indices (0-based), each with positive volume by the right-hand
    /// rule as TetGen and VTK list them: the engine's orient3d > 0 order mirrored (handedness.h).
    std::vector<std::array<std::uint32_t, 4>> tets;
    /// {point, its first occurrence}: exact repeats, not inserted.
    std::vector<std::array<std::uint32_t, 2>> duplicates;
    /// Weighted only: points that are not vertices because their lifted point lies above the lower
    /// hull (submerged), in increasing order.
    std::vector<std::uint32_t> redundant;
    std::size_t hull_triangles = 0;
    std::size_t storage_bytes = 0;  ///< capacity of the storage at the end
    Counters counters;              ///< when TriangulateOptions::count
};

/// triangulate() itself is in live/triangulate.h: with the array storage it builds the live
/// triangulation and releases it.

}  // namespace cavity::core
