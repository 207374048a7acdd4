#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cavity/core/delaunay/bowyer_watson.h"
#include "cavity/core/delaunay/walk.h"

namespace cavity::core {

/// What a full conflict graph created and freed: Theorem 5.4's conflicts, counted by the
/// algorithm whose running time the theorem bounds.
struct ConflictTally {
    std::uint64_t created = 0;  ///< solid tetrahedra: Σj
    std::uint64_t ghost_created = 0;
    std::uint64_t deleted = 0;
    std::uint64_t ghost_deleted = 0;
    std::uint64_t live = 0;
    std::uint64_t live_max = 0;  ///< after an insertion
};

/// Point location by the Clarkson–Shor conflict graph (Cheng, Dey & Shewchuk §5.4's analysis;
/// Boissonnat & Teillaud): every live tetrahedron keeps *all* its conflicts, the uninserted points
/// in its open perturbed circumball (for a ghost, in front of its hull triangle). A tetrahedron
/// created on the cavity face between a deleted tetrahedron and a surviving one can only conflict
/// with points of theirs (its ball lies in the union of their balls: the pencil through the face),
/// so its list is those two lists filtered by the exact test. The lists' total length created over
/// the run is Σj exactly, and the work is Theorem 5.4's: O(1) tests per conflict.
///
/// Each point remembers the last tetrahedron whose list took it. When that one has died without
/// any new tetrahedron taking the point (the point was in the dead tetrahedron's ball but outside
/// the cavity), the point is found by the visibility walk instead, from the last solid tetrahedron;
/// those walks are the engine's walk_steps under this locator. Memory: the live lists, at most
/// live_max entries of 4 bytes (about 20 n for uniform points), and 16 bytes per point.
class FullConflictGraph {
public:
    explicit FullConflictGraph(std::uint64_t seed) : walk_(seed) {}

    template <class Storage, class Observer>
    void start(BowyerWatson<Storage, Observer>& engine) {
        engine.record_cavity_faces();
        const std::size_t n = engine.geometry().size();
        home_.assign(n, kNoTet);
        seen_.assign(n, 0);
        conflicts_of_.assign(n, 0);
        grow(engine.storage().capacity());
        const TetId solid = engine.last_solid();
        std::array<TetId, 5> first{solid};
        for (int f = 0; f < 4; ++f) {
            first[static_cast<std::size_t>(f) + 1] = tet_of(engine.storage().adjacent(solid, f));
        }
        for (TetId t : first) {
            std::vector<VertexId> list;
            for (VertexId p = 4; p < n; ++p) {
                if (engine.conflicts(t, p)) {
                    list.push_back(p);
                }
            }
            adopt(t, is_ghost(engine.storage().vertices(t)), std::move(list));
        }
        tally_.live_max = tally_.live;
    }

    /// A live tetrahedron in conflict with u (its recorded one), or the cell holding u.
    template <class Storage, class Observer>
    TetId locate(BowyerWatson<Storage, Observer>& engine, VertexId u) {
        const TetId h = home_[u];
        if (h != kNoTet && alive_[h] != 0 && engine.conflicts(h, u)) {
            return h;
        }
        return walk_.locate(engine, engine.geometry().point(u), engine.last_solid());
    }

    /// u is redundant: no tetrahedron conflicts with it, so no list holds it.
    template <class Engine>
    void skip(Engine&, VertexId) {}

    template <class Storage, class Observer>
    void after_insertion(BowyerWatson<Storage, Observer>& engine, VertexId u) {
        Storage& storage = engine.storage();
        // The dead tetrahedra's lists leave their slots first: new tetrahedra may reuse them.
        dead_lists_.clear();
        for (TetId d : engine.deleted()) {
            const std::uint64_t size = lists_[d].size();
            for (VertexId q : lists_[d]) {
                --conflicts_of_[q];
            }
            (ghost_[d] != 0 ? tally_.ghost_deleted : tally_.deleted) += size;
            tally_.live -= size;
            alive_[d] = 0;
            dead_index_[d] = static_cast<std::uint32_t>(dead_lists_.size());
            dead_lists_.push_back(std::move(lists_[d]));
            lists_[d].clear();
        }
        grow(storage.capacity());
        for (const CavityFace& face : engine.cavity_faces()) {
            const TetId t = face.created;
            const TetVertices& v = storage.vertices(t);
            const int u_slot = static_cast<int>(std::find(v.begin(), v.end(), u) - v.begin());
            const TetId outer = tet_of(storage.adjacent(t, u_slot));
            if (++stamp_ == 0) {  // after 2^32 - 1 tetrahedra: start the stamps afresh
                std::fill(seen_.begin(), seen_.end(), 0);
                stamp_ = 1;
            }
            std::vector<VertexId> list;
            for (VertexId q : dead_lists_[dead_index_[face.inner]]) {
                seen_[q] = stamp_;
                if (q != u && engine.conflicts(t, q)) {
                    list.push_back(q);
                }
            }
            for (VertexId q : lists_[outer]) {
                if (seen_[q] != stamp_ && engine.conflicts(t, q)) {
                    list.push_back(q);
                }
            }
            adopt(t, is_ghost(v), std::move(list));
        }
        tally_.live_max = std::max(tally_.live_max, tally_.live);
    }

    const ConflictTally& tally() const { return tally_; }

    /// The uninserted points in conflict with live tetrahedron t.
    const std::vector<VertexId>& conflicts_of_tet(TetId t) const { return lists_[t]; }

    /// How many live tetrahedra uninserted point q conflicts with: the cavity its insertion would
    /// dig now (the greedy adversary of Exercise 1 inserts the largest first).
    std::uint32_t conflicts_of(VertexId q) const { return conflicts_of_[q]; }

private:
    void grow(std::size_t capacity) {
        if (lists_.size() < capacity) {
            lists_.resize(capacity);
            alive_.resize(capacity, 0);
            ghost_.resize(capacity, 0);
            dead_index_.resize(capacity, 0);
        }
    }

    void adopt(TetId t, bool ghost, std::vector<VertexId> list) {
        for (VertexId q : list) {
            home_[q] = t;
            ++conflicts_of_[q];
        }
        (ghost ? tally_.ghost_created : tally_.created) += list.size();
        tally_.live += list.size();
        alive_[t] = 1;
        ghost_[t] = ghost ? 1 : 0;
        lists_[t] = std::move(list);
    }

    Walk walk_;
    std::vector<std::vector<VertexId>> lists_;  ///< by storage slot
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint8_t> ghost_;
    std::vector<std::uint32_t> dead_index_;  ///< slot -> dead_lists_ entry, last insertion only
    std::vector<std::vector<VertexId>> dead_lists_;
    std::vector<TetId> home_;                  ///< by point: the last tetrahedron that took it
    std::vector<std::uint32_t> seen_;          ///< by point: the stamp of the last filtering
    std::vector<std::uint32_t> conflicts_of_;  ///< by point: live tetrahedra it conflicts with
    std::uint32_t stamp_ = 0;
    ConflictTally tally_;
};

}  // namespace cavity::core
