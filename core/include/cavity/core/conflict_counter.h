#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cavity/core/observer.h"
#include "cavity/core/point_kd_tree.h"

namespace cavity::core {

/// Conflicts of one insertion (Theorem 5.4's charge): what a conflict graph keeping every conflict
/// of every tetrahedron would add and free.
struct ConflictStep {
    std::uint64_t created = 0;  ///< solid and ghost
    std::uint64_t deleted = 0;  ///< solid and ghost
    std::uint64_t live = 0;     ///< after the insertion
};

/// Counts, for every tetrahedron the engine creates, its conflicts: the input points in its open
/// circumball under the engine's perturbation (weighted: in conflict with its orthoball), or for a
/// ghost the points in the perturbed outer halfspace of its hull triangle. Every point counted or
/// not is decided by the engine's own exact test (Geometry::conflicts_solid / conflicts_ghost);
/// a kd-tree over all n points only skips boxes that provably hold no conflict: for a ball, by a
/// floating-point circumcentre with a forward error bound from Cramer's rule (no pruning when the
/// bound is not finite or the tetrahedron is too flat for it); for a halfspace, by the exact
/// orientation of the box's eight corners. So the counts are exact, independently of the
/// triangulation's own point location.
///
/// Cost: about one exact test per conflict plus O(log n) boxes per tetrahedron; memory 36 bytes
/// per point for the tree and 5 bytes per storage slot. Fills the conflict fields of Counters and,
/// per insertion, `steps()` (when asked) and the histogram of j over created solid tetrahedra.
class ConflictCountingObserver : public CountingObserver {
public:
    static constexpr bool kCountsConflicts = true;

    /// Exact bins of the j histogram; larger j are summed into the last bin.
    static constexpr std::size_t kHistogramBins = 4097;

    explicit ConflictCountingObserver(bool keep_steps = false) : keep_steps_(keep_steps) {}

    void on_start(const Geometry& geometry);
    void on_tet_created(TetId t, const TetVertices& v, std::uint64_t step);
    void on_tet_deleted(TetId t, std::uint64_t step);
    void on_insertion(const InsertionRecord& record);

    /// Created solid tetrahedra by j: histogram()[j] for j < kHistogramBins - 1, the rest in the
    /// last bin.
    const std::vector<std::uint64_t>& histogram() const { return histogram_; }

    /// One entry per insertion (the bootstrap tetrahedron's conflicts go to the first), when the
    /// observer was made with keep_steps.
    const std::vector<ConflictStep>& steps() const { return steps_; }

private:
    std::uint64_t count_solid(const TetVertices& v);
    std::uint64_t count_ghost(const TetVertices& v);

    bool keep_steps_;
    const Geometry* geometry_ = nullptr;
    std::unique_ptr<PointKdTree> tree_;
    double max_weight_ = 0;
    std::vector<std::uint32_t> j_of_;  ///< by storage slot: the live tetrahedron's conflicts
    std::vector<std::uint8_t> ghost_of_;
    std::uint64_t live_ = 0;
    ConflictStep step_;
    std::vector<ConflictStep> steps_;
    std::vector<std::uint64_t> histogram_;
};

}  // namespace cavity::core
