#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "cavity/core/delaunay/observer.h"

/// The life of every tetrahedron one run creates (experiments.md §2.2): which vertices, when it
/// was created, when deleted. For generic input the chapter's analysis predicts both exactly: a
/// tetrahedron is created at the insertion of its last vertex iff all four vertices precede all
/// of its stoppers (the points in its open circumball), and deleted at the insertion of its first
/// stopper.
namespace cavity::experiments {

inline constexpr std::uint64_t kNeverDeleted = std::numeric_limits<std::uint64_t>::max();

struct TetLife {
    std::array<std::uint32_t, 4> vertices;  ///< input indices, ascending (ghost: 3 and a marker)
    bool ghost;
    std::uint64_t created;  ///< insertion step (= insertion rank of the inserted vertex)
    std::uint64_t deleted;  ///< insertion step, or kNeverDeleted
};

/// Counts like CountingObserver and logs every tetrahedron's life. Ghost tetrahedra are logged
/// with ghost = true and the ghost vertex dropped (vertices[3] = UINT32_MAX).
class LifeCycleObserver : public core::CountingObserver {
public:
    void on_start(const core::Geometry& geometry) {
        geometry_ = &geometry;
        lives_.clear();
        record_of_slot_.clear();
        rank_of_input_.clear();
        for (core::VertexId v = 0; v < geometry.size(); ++v) {
            const std::uint32_t key = geometry.key(v);
            if (key >= rank_of_input_.size()) {
                rank_of_input_.resize(key + 1, kNotInserted);
            }
            rank_of_input_[key] = v;
        }
    }

    void on_tet_created(core::TetId t, const core::TetVertices& v, std::uint64_t step) {
        core::CountingObserver::on_tet_created(t, v, step);
        TetLife life{{0, 0, 0, 0}, core::is_ghost(v), step, kNeverDeleted};
        for (std::size_t i = 0; i < 4; ++i) {
            life.vertices[i] = v[i] == core::kGhostVertex
                                   ? std::numeric_limits<std::uint32_t>::max()
                                   : geometry_->key(v[i]);
        }
        std::sort(life.vertices.begin(), life.vertices.end());
        if (t >= record_of_slot_.size()) {
            record_of_slot_.resize(std::max<std::size_t>(t + 1, 2 * record_of_slot_.size()));
        }
        record_of_slot_[t] = lives_.size();
        lives_.push_back(life);
    }

    void on_tet_deleted(core::TetId t, std::uint64_t step) {
        core::CountingObserver::on_tet_deleted(t, step);
        lives_[record_of_slot_[t]].deleted = step;
    }

    /// One entry per tetrahedron created, in creation order.
    const std::vector<TetLife>& lives() const { return lives_; }

    /// The insertion rank (= step) of an input point, or kNotInserted for a repeat.
    std::uint32_t rank_of_input(std::uint32_t input) const {
        return input < rank_of_input_.size() ? rank_of_input_[input] : kNotInserted;
    }

    static constexpr std::uint32_t kNotInserted = std::numeric_limits<std::uint32_t>::max();

private:
    const core::Geometry* geometry_ = nullptr;
    std::vector<TetLife> lives_;
    std::vector<std::size_t> record_of_slot_;  ///< storage slot -> its current life in lives_
    std::vector<std::uint32_t> rank_of_input_;
};

}  // namespace cavity::experiments
