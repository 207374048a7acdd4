#pragma once

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/delaunay/conflict_counter.h"
#include "cavity/core/delaunay/conflict_graph.h"
#include "cavity/core/delaunay/full_conflict_graph.h"
#include "cavity/core/delaunay/locator.h"
#include "cavity/core/delaunay/seek_conflict.h"
#include "cavity/core/delaunay/straight_walk.h"
#include "cavity/core/delaunay/triangulate.h"
#include "cavity/core/delaunay/walk.h"
#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/face_hash_storage.h"

/// The driver loop of Bowyer–Watson (§5.2–5.5): the input checked and laid out in insertion
/// order, the bootstrap tetrahedron, then every point located and inserted, for any storage,
/// locator and observer. The live triangulation (live/delaunay_triangulation.h) and the batch
/// triangulate() (live/triangulate.h) are both this loop and what they do with the storage after.
namespace cavity::core {

namespace detail {

/// The engine's view of the points in insertion order, without repeats, the bootstrap four first
/// (its keys are that sequence: no second copy of it lives through the build).
struct Prepared {
    Geometry geometry;
    /// prepare_in_place only: what give_back needs besides the geometry, the repeats'
    /// coordinates (in increasing index) and one mark bit per input point.
    std::vector<Point3> repeats;
    std::vector<std::uint64_t> marks;
};

/// Checks the input (finite coordinates and weights, one weight per point, the sequence a
/// permutation), removes repeats (keeping the lowest index), puts the bootstrap four (by `rule`)
/// first and lays the points out in insertion order. Throws Error naming the problem, or when there
/// is no 3D triangulation. Up to `threads` threads look for the repeats (the same result for
/// every count).
Prepared prepare(const PointSet& input,
                 std::span<const std::uint32_t> sequence,
                 BootstrapRule rule,
                 Triangulation& out,
                 unsigned threads = 1);

/// prepare() on points the caller lends and a sequence it gives up: the points move to the
/// geometry in insertion order (gathered by up to `threads` threads into a new array, the lent one
/// freed at once) and its keys are made in `sequence`'s array, so neither is held twice while the
/// engine runs (28 bytes per point less). Checks and throws as prepare() does, before anything
/// moves; afterwards `input.points` is empty until give_back.
Prepared prepare_in_place(PointSet& input,
                          std::vector<std::uint32_t>&& sequence,
                          BootstrapRule rule,
                          Triangulation& out,
                          unsigned threads = 1);

/// Puts the points prepare_in_place took back into `input.points`, in input order, bit for bit
/// (repeats included); `out` is the Triangulation prepare_in_place filled (its duplicates). Needs
/// no allocation, so it cannot fail; the geometry has no points afterwards.
void give_back(Prepared& prep, const Triangulation& out, PointSet& input) noexcept;

/// The full conflict graph's own count of the conflicts goes into the counters; when the
/// conflict-counting observer has counted them too, the two independent counts must agree to the
/// unit. \throws InternalError when they do not.
void merge_conflict_tally(const ConflictTally& tally, Counters& counters, bool counted);

/// Where a run left the engine, for an engine that continues in the same storage.
struct RunEnd {
    std::array<VertexId, 4> interior;  ///< the bootstrap vertices
    TetId last_solid;
};

/// Inserts the prepared points (`geometry`, Prepared::geometry) (the first options.prefix, when
/// set) into the empty `storage`. Fills out.redundant and, when Observer::kCounting, out.counters;
/// the tetrahedra stay in the storage.
template <class Storage, class Observer, class PointLocator>
RunEnd run(const Geometry& geometry,
           const TriangulateOptions& options,
           PointLocator& locator,
           Storage& storage,
           Observer& observer,
           Triangulation& out) {
    static_assert(Locator<PointLocator, BowyerWatson<Storage, Observer>>,
                  "the locator must model Locator (delaunay/locator.h)");
    const std::size_t n = geometry.size();
    // A prefix run inserts the first `last` points; the others are only counted as conflicts.
    const std::size_t last =
        options.prefix == 0 ? n : std::clamp<std::size_t>(options.prefix, 4, n);
    storage.reserve(7 * last + 64);
    BowyerWatson<Storage, Observer> engine(geometry, storage, observer);
    observer.on_start(geometry);
    engine.bootstrap(0, 1, 2, 3);
    locator.start(engine);
    std::vector<TetId> scratch;
    std::vector<VertexId> redundant;
    const std::size_t report_every = std::max<std::size_t>(n / 200, 1024);
    for (VertexId u = 4; u < last; ++u) {
        std::uint64_t steps_before = 0;
        if constexpr (Observer::kCounting) {
            steps_before = observer.tally().walk_steps;
        }
        const TetId located = locator.locate(engine, u);
        const ConflictSeed seed = seek_conflict(engine, u, located, scratch);
        if (seed.duplicate != kNoVertex) {
            // first_occurrences removed every repeat; reaching here would be an engine bug.
            throw InternalError("internal error: point " + std::to_string(geometry.key(u)) +
                                " repeats point " + std::to_string(geometry.key(seed.duplicate)) +
                                " after duplicate removal");
        }
        if (seed.tet == kNoTet) {
            redundant.push_back(u);
            locator.skip(engine, u);
        } else {
            engine.insert_vertex(u, seed.tet, u);
            locator.after_insertion(engine, u);
            redundant.insert(redundant.end(), engine.vanished().begin(), engine.vanished().end());
        }
        if constexpr (Observer::kCounting) {
            const bool inserted = seed.tet != kNoTet;
            observer.on_insertion(InsertionRecord{
                geometry.key(u),
                u,
                inserted ? static_cast<std::uint32_t>(engine.created().size()) : 0u,
                inserted ? static_cast<std::uint32_t>(engine.deleted().size()) : 0u,
                static_cast<std::uint32_t>(observer.tally().walk_steps - steps_before)});
        }
        // Expensive builds check the whole complex after the 4th, 8th, 16th, ... insertion and
        // the last, so the check costs O(n log n) of complex size, not O(n^2).
        if constexpr (std::is_same_v<Storage, ArrayStorage>) {
            if ((u & (u - 1)) == 0 || u + 1 == last) {
                CAVITY_EXPENSIVE_CHECK(check_complex(storage, geometry),
                                       "the triangulation after insertion " + std::to_string(u));
            }
        }
        if (options.progress && u % report_every == 0) {
            options.progress(u, n);
        }
    }
    for (VertexId v : redundant) {
        out.redundant.push_back(geometry.key(v));
    }
    std::sort(out.redundant.begin(), out.redundant.end());
    observer.on_finish();
    if constexpr (Observer::kCounting) {
        out.counters = observer.tally();
        out.counters.duplicates = out.duplicates.size();
        out.counters.redundant = out.redundant.size();
        if constexpr (requires { storage.probes(); }) {
            out.counters.hash_probes = storage.probes();
        }
    }
    if constexpr (Observer::kCounting && requires { locator.tally(); }) {
        merge_conflict_tally(locator.tally(), out.counters, Observer::kCountsConflicts);
    }
    if (options.progress) {
        options.progress(n, n);
    }
    return {engine.bootstrap_vertices(), engine.last_solid()};
}

/// Moves the tetrahedra out of `storage` into out.tets (solid ones, input indices, positive
/// right-hand volume) and counts the hull triangles, emptying the storage as it goes so that the
/// copy does not double the peak memory.
template <class Storage>
void drain_into(Storage& storage, const Geometry& geometry, Triangulation& out) {
    out.storage_bytes = storage.bytes();
    out.tets.reserve(storage.live_count());
    storage.drain([&](const TetVertices& v) {
        if (is_ghost(v)) {
            ++out.hull_triangles;
        } else {
            // The stored orientation mirrored: the API hands out positive right-hand volume.
            out.tets.push_back(
                {geometry.key(v[1]), geometry.key(v[0]), geometry.key(v[2]), geometry.key(v[3])});
        }
    });
}

/// Point location by a walk from the most recently created solid tetrahedron (§5.5): `Walker` is
/// the visibility walk (walk.h) or the book's straight-line walk (straight_walk.h).
template <class Walker>
class WalkingLocator {
public:
    explicit WalkingLocator(std::uint64_t seed) : walk_(seed) {}

    template <class Engine>
    void start(Engine&) {}

    template <class Engine>
    TetId locate(Engine& engine, VertexId u) {
        return walk_.locate(engine, engine.geometry().point(u), engine.last_solid());
    }

    template <class Engine>
    void skip(Engine&, VertexId) {}

    template <class Engine>
    void after_insertion(Engine&, VertexId) {}

private:
    Walker walk_;
};

using WalkLocator = WalkingLocator<Walk>;
using StraightWalkLocator = WalkingLocator<StraightWalk>;

/// run() with the locator options.locate names.
template <class Storage, class Observer>
RunEnd run_located(const Geometry& geometry,
                   const TriangulateOptions& options,
                   Storage& storage,
                   Observer& observer,
                   Triangulation& out) {
    switch (options.locate) {
        case LocateKind::kWalk: {
            WalkLocator locator(options.seed);
            return run(geometry, options, locator, storage, observer, out);
        }
        case LocateKind::kStraightWalk: {
            StraightWalkLocator locator(options.seed);
            return run(geometry, options, locator, storage, observer, out);
        }
        case LocateKind::kFullConflictGraph: {
            FullConflictGraph locator(options.seed);
            return run(geometry, options, locator, storage, observer, out);
        }
        case LocateKind::kConflictGraph:
            break;
    }
    ConflictGraph locator;
    return run(geometry, options, locator, storage, observer, out);
}

/// Calls `build(observer)` with the observer the options ask for: ConflictCountingObserver
/// (count_conflicts), CountingObserver (count) or NullObserver.
template <class Build>
void with_observer(const TriangulateOptions& options, Build&& build) {
    if (options.count_conflicts) {
        ConflictCountingObserver observer;
        build(observer);
    } else if (options.count) {
        CountingObserver observer;
        build(observer);
    } else {
        NullObserver observer;
        build(observer);
    }
}

}  // namespace detail

}  // namespace cavity::core
