#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "cavity/core/delaunay/observer.h"
#include "cavity/core/delaunay/point_kd_tree.h"

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
/// A created tetrahedron's conflicts do not depend on when they are counted: no inserted point
/// can conflict with a tetrahedron of the current (perturbed) Delaunay triangulation, so its
/// conflicts with the uninserted points are its conflicts with all points. The counter therefore
/// defers the counting: it collects created tetrahedra in batches and counts each batch in the
/// order of a space-filling curve through their centroids, so consecutive queries walk the same
/// part of the tree and of memory (10^6 uniform points in a uniform order: 88 s in all, against
/// 115 s counting each tetrahedron at its creation). Deletions of tetrahedra whose batch is still
/// pending are recorded with them; the per-insertion tallies are assembled in on_finish().
///
/// Cost: a few exact tests per tetrahedron (points strictly inside a certified inner ball, and
/// whole boxes inside it, are counted without one) plus the boxes along the sphere; memory 36
/// bytes per point for the tree, 9 bytes per storage slot, 16 bytes per insertion (40 with
/// keep_steps) and one batch.
/// Fills the conflict fields of Counters and, per insertion, `steps()` (when asked) and the
/// histogram of j over created solid tetrahedra; all are complete after on_finish().
class ConflictCountingObserver : public CountingObserver {
public:
    static constexpr bool kCountsConflicts = true;

    /// Exact bins of the j histogram; larger j are summed into the last bin.
    static constexpr std::size_t kHistogramBins = 4097;

    /// Created tetrahedra counted together (a batch of 2^20 takes about 45 MB with its sort keys).
    static constexpr std::size_t kDefaultBatch = std::size_t{1} << 20;

    /// `batch`: how many created tetrahedra wait to be counted together; the counts do not depend
    /// on it (tests make it small to cross batch boundaries often).
    explicit ConflictCountingObserver(bool keep_steps = false, std::size_t batch = kDefaultBatch)
        : keep_steps_(keep_steps), batch_(std::max<std::size_t>(batch, 1)) {}

    void on_start(const Geometry& geometry);
    void on_tet_created(TetId t, const TetVertices& v, std::uint64_t step);
    void on_tet_deleted(TetId t, std::uint64_t step);
    void on_insertion(const InsertionRecord& record);
    void on_finish();

    /// Created solid tetrahedra by j: histogram()[j] for j < kHistogramBins - 1, the rest in the
    /// last bin.
    const std::vector<std::uint64_t>& histogram() const { return histogram_; }

    /// One entry per insertion (the bootstrap tetrahedron's conflicts go to the first), when the
    /// observer was made with keep_steps.
    const std::vector<ConflictStep>& steps() const { return steps_; }

private:
    /// A created tetrahedron waiting for its count.
    struct Pending {
        TetVertices v;
        TetId slot;
        std::uint32_t created_step;
        std::uint32_t deleted_step;  ///< kAlive while it lives
    };

    static constexpr std::uint32_t kAlive = 0xFFFF'FFFFu;

    std::uint64_t count_solid(const TetVertices& v);
    std::uint64_t count_ghost(const TetVertices& v);
    void count_batch();
    void add_at(std::vector<std::uint64_t>& per_step, std::uint64_t step, std::uint64_t j);
    std::uint64_t curve_key(const TetVertices& v) const;

    bool keep_steps_;
    std::size_t batch_;
    const Geometry* geometry_ = nullptr;
    std::unique_ptr<PointKdTree> tree_;
    double max_weight_ = 0;
    Point3 lo_{};  ///< the points' bounding box, for the curve keys
    double scale_ = 0;
    std::vector<Pending> pending_;
    std::vector<std::uint32_t> pending_of_;  ///< by storage slot: 1 + its pending index, or 0
    std::vector<std::uint32_t> j_of_;        ///< by storage slot: the counted live tetrahedron's j
    std::vector<std::uint8_t> ghost_of_;
    std::vector<std::uint64_t> created_at_;  ///< conflicts created and deleted, by step
    std::vector<std::uint64_t> deleted_at_;
    std::uint64_t insertions_ = 0;
    std::vector<ConflictStep> steps_;
    std::vector<std::uint64_t> histogram_;
};

}  // namespace cavity::core
