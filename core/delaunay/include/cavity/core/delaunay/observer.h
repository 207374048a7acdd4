#pragma once

#include <concepts>
#include <cstdint>
#include <type_traits>

#include "cavity/core/geometry/counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// The engine's instrumentation hooks. The engine is a template on its observer; with
/// NullObserver every hook is an empty inline function and `kCounting` is false, so counting code
/// is compiled out and the uninstrumented engine pays nothing. An observer that counts derives
/// from CountingObserver; the experiments layer adds per-tetrahedron hooks (life-cycle logs) by
/// overriding the hooks below in a derived class (they are called non-virtually, by name, so the
/// engine must be instantiated with the derived type: see live/triangulate.h).
struct NullObserver {
    static constexpr bool kCounting = false;
    /// True for ConflictCountingObserver, which fills the conflict fields of Counters.
    static constexpr bool kCountsConflicts = false;

    /// Where the engine, its walks and its tests count: nowhere.
    Uncounted& tally() { return uncounted; }

    [[no_unique_address]] Uncounted uncounted;

    /// Called once before the first insertion, with the engine's points: vertex ids in the other
    /// hooks are insertion ranks, and geometry.key(v) is the input index of vertex v.
    void on_start(const Geometry&) {}

    void on_tet_created(TetId, const TetVertices&, std::uint64_t /*step*/) {}

    void on_tet_deleted(TetId, std::uint64_t /*step*/) {}

    void on_insertion(const InsertionRecord&) {}

    /// Called once after the last insertion, before the counters are read: an observer that
    /// defers work (the conflict counter counts in batches) completes it here.
    void on_finish() {}
};

/// What the engine asks of an observer: NullObserver's members, with the same meaning.
template <class O>
concept EngineObserver = requires(O observer,
                                  const Geometry& geometry,
                                  TetId t,
                                  const TetVertices& vertices,
                                  std::uint64_t step,
                                  const InsertionRecord& record) {
    { O::kCounting } -> std::convertible_to<bool>;
    { O::kCountsConflicts } -> std::convertible_to<bool>;
    requires Tally<std::remove_reference_t<decltype(observer.tally())>>;
    requires std::remove_reference_t<decltype(observer.tally())>::kCounting == O::kCounting;
    observer.on_start(geometry);
    observer.on_tet_created(t, vertices, step);
    observer.on_tet_deleted(t, step);
    observer.on_insertion(record);
    observer.on_finish();
};

/// Counts everything in Counters.
struct CountingObserver : NullObserver {
    static constexpr bool kCounting = true;

    Counters& tally() { return totals; }

    Counters totals;
};

}  // namespace cavity::core
