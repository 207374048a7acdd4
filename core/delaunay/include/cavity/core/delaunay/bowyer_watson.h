#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/delaunay/observer.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/cavity_gluer.h"
#include "cavity/core/mesh/dig_cavity.h"
#include "cavity/core/mesh/tet_storage.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// A new tetrahedron and the deleted one whose face it was built on.
struct CavityFace {
    TetId inner;
    TetId created;
};

/// Bowyer–Watson vertex insertion with ghost tetrahedra (Cheng, Dey & Shewchuk §5.2:
/// InsertVertex3D and DigCavity3D), written once against the storage interface of Figure 5.1 so
/// that the compact array storage and the book's face hash table run the same code. Delaunay or
/// weighted Delaunay, as the Geometry says; every conflict test is exact and perturbed.
template <class Storage, class Observer = NullObserver>
class BowyerWatson {
    static_assert(TetStorage<Storage>, "the storage must model TetStorage (mesh/tet_storage.h)");
    static_assert(EngineObserver<Observer>,
                  "the observer must model EngineObserver (delaunay/observer.h)");

public:
    BowyerWatson(const Geometry& geometry, Storage& storage, Observer& observer)
        : geometry_(geometry), storage_(storage), observer_(observer) {
        if (geometry_.weighted()) {
            deleted_stamp_.assign(geometry_.size(), kNoStamp);
            created_stamp_.assign(geometry_.size(), kNoStamp);
        }
    }

    /// Builds the triangulation of four affinely independent vertices: one solid tetrahedron and
    /// the four ghosts on its faces.
    void bootstrap(VertexId a, VertexId b, VertexId c, VertexId d) {
        if (geometry_.orient3d(a, b, c, d, tally()) == Sign::kNeg) {
            std::swap(a, b);
        }
        bootstrap_ = {a, b, c, d};
        const TetId solid = add({a, b, c, d}, 0);
        last_solid_ = solid;
        std::array<TetId, 4> ghosts{};
        for (int f = 0; f < 4; ++f) {
            const auto tri = facet_vertices(bootstrap_, f);
            ghosts[static_cast<std::size_t>(f)] = add({tri[0], tri[2], tri[1], kGhostVertex}, 0);
            storage_.glue(half_facet(solid, f), half_facet(ghosts[static_cast<std::size_t>(f)], 3));
        }
        if constexpr (Observer::kCounting) {
            ++tally().tets_created;
            tally().ghosts_created += 4;
        }
        if constexpr (Storage::kExplicitAdjacency) {
            // Ghost faces pair up around the ghost vertex exactly as new faces pair up around a
            // new vertex.
            gluer_.glue(storage_, ghosts, kGhostVertex);
        }
        storage_.end_operation();
    }

    /// Takes over a triangulation another engine built in the same storage (the live
    /// triangulation keeps one engine for the insertions after its build): `interior` are four
    /// affinely independent vertices (the ghost test's reference, see conflicts_ghost),
    /// `last_solid` a live solid tetrahedron where the next walk starts.
    void resume(const std::array<VertexId, 4>& interior, TetId last_solid) {
        bootstrap_ = interior;
        last_solid_ = last_solid;
    }

    /// True when u conflicts with tetrahedron t (is in its perturbed open circumball, or for a
    /// ghost, in the outer halfspace of its hull triangle).
    /// Inlined, with Digger::conflicts, into the cavity search: GCC kept the test out of line, and
    /// a call per test (46 per point on a uniform cube) spilled and reloaded the search's state;
    /// inlining it and add() cut the triangulation by 5% (callgrind, cube 10^5).
    [[gnu::always_inline]] bool conflicts(TetId t, VertexId u) {
        const TetVertices& v = storage_.vertices(t);
        return is_ghost(v) ? geometry_.conflicts_ghost(v, u, bootstrap_, tally())
                           : geometry_.conflicts_solid(v, u, tally());
    }

    /// InsertVertex3D(u, t0): t0 must conflict with u. Deletes every tetrahedron in conflict with
    /// u (a breadth-first search from t0 through conflicting neighbours: DigCavity3D, dig_cavity.h,
    /// the loop the constrained insertion of the CDT shares) and fills the
    /// cavity with one new tetrahedron per cavity face. As in the book's pseudocode, a tetrahedron
    /// outside the cavity is tested once for every cavity face it borders (remembering the verdicts
    /// was measured to cost more than the tests it saves), so the conflict tests number (deleted -
    /// 1) + (cavity faces).
    void insert_vertex(VertexId u, TetId t0, std::uint64_t step) {
        created_.clear();
        deleted_.clear();
        vanished_.clear();
        cavity_faces_.clear();
        step_ = step;
        if (geometry_.weighted() && deleted_stamp_.size() < geometry_.size()) {
            // A live triangulation's geometry grows as points are added.
            deleted_stamp_.resize(geometry_.size(), kNoStamp);
            created_stamp_.resize(geometry_.size(), kNoStamp);
        }
        Digger digger{*this, u};
        if constexpr (Observer::kCounting) {
            // t0 is taken untested (the caller knows it conflicts).
            digger.ghosts_taken = is_ghost(storage_.vertices(t0)) ? 1u : 0u;
        }
        dig_cavity(storage_, t0, queue_, digger);
        if constexpr (Storage::kExplicitAdjacency) {
            gluer_.glue(storage_, std::span<const TetId>(created_.begin(), created_.size()), u);
        }
        if (geometry_.weighted()) {
            // After the search, not per tetrahedron: the deleted records stay readable until
            // end_operation(), and the unweighted search then tests weighted() once per insertion.
            for (TetId t : deleted_) {
                stamp(deleted_stamp_, storage_.vertices(t));
            }
            for (TetId t : created_) {
                stamp(created_stamp_, storage_.vertices(t));
            }
            collect_vanished(u);
        }
        storage_.end_operation();
        if constexpr (Observer::kCounting) {
            count_insertion(digger);
        }
    }

    /// The tetrahedra the last insertion created and deleted (deleted ids may be reused by later
    /// insertions).
    const PodStack<TetId>& created() const { return created_; }

    const PodStack<TetId>& deleted() const { return deleted_; }

    /// For each tetrahedron the last insertion created: the deleted tetrahedron whose face it was
    /// built on. Recorded only after record_cavity_faces().
    const PodStack<CavityFace>& cavity_faces() const { return cavity_faces_; }

    /// Asks every later insertion to record its cavity faces: only the conflict graphs read them,
    /// and the two stores per new tetrahedron are left out of the walk's insertions.
    void record_cavity_faces() { record_cavity_faces_ = true; }

    /// Weighted only: vertices the last insertion submerged (no longer in the triangulation).
    const std::vector<VertexId>& vanished() const { return vanished_; }

    /// The most recently created solid tetrahedron: where the next walk starts (§5.5).
    TetId last_solid() const { return last_solid_; }

    const std::array<VertexId, 4>& bootstrap_vertices() const { return bootstrap_; }

    Storage& storage() { return storage_; }

    const Geometry& geometry() const { return geometry_; }

    Observer& observer() { return observer_; }

    /// The observer's tally (counters.h): Counters when it counts, else Uncounted.
    auto& tally() { return observer_.tally(); }

private:
    static constexpr std::uint32_t kNoStamp = 0xFFFF'FFFFu;

    /// Unconstrained DigCavity3D: nothing is blocked, and a deleted tetrahedron is in the cavity
    /// (the storage answers kNoHalfFacet across from it), so tetrahedra are deleted as they are
    /// taken and each cavity face gets its new tetrahedron at once.
    /// The counting engine counts what only the search sees in the search's own frame (the ghosts
    /// it takes and makes, the tests the static filter decides) and the rest from the insertion's
    /// lists, and adds it all to the totals once per insertion (count_insertion). The totals are
    /// behind a reference that every predicate stage count also writes: an increment there per
    /// test and per tetrahedron was a reload of their address and a read-modify-write each
    /// (callgrind, 46^3 grid: the counting engine's instructions 2399 M -> 2355 M, the plain
    /// engine's 2323 M; the counts are unchanged).
    struct Digger {
        BowyerWatson& engine;
        VertexId u;
        std::uint32_t ghosts_taken = 0;
        std::uint32_t ghosts_made = 0;
        std::uint64_t decided_static = 0;

        static bool blocked(TetId, int) { return false; }

        static bool in_cavity(TetId) { return false; }

        [[gnu::always_inline]] bool conflicts(TetId t) {
            if constexpr (Observer::kCounting) {
                const TetVertices& v = engine.storage_.vertices(t);
                if (is_ghost(v)) [[unlikely]] {
                    // A ghost is taken only after this test: its count costs nothing on the
                    // solid tests.
                    const bool in =
                        engine.geometry_.conflicts_ghost(v, u, engine.bootstrap_, engine.tally());
                    ghosts_taken += in ? 1u : 0u;
                    return in;
                }
                return engine.geometry_.conflicts_solid(v, u, engine.tally(), decided_static);
            } else {
                return engine.conflicts(t, u);
            }
        }

        [[gnu::always_inline]] void take(TetId t) { engine.remove(t); }

        static void blocked_inside(TetId, int) {}

        [[gnu::always_inline]] void cavity_face(TetId t, int f, HalfFacet across) {
            const bool ghost = engine.fill_cavity_face(u, t, f, across);
            if constexpr (Observer::kCounting) {
                ghosts_made += ghost ? 1u : 0u;
            }
        }
    };

    /// Adds one insertion's counts to the totals. Nothing blocks the search, so each tetrahedron
    /// it took but t0 was tested and found in conflict, and each cavity face (one new tetrahedron
    /// each) was tested and found not: the tests number (deleted - 1) + created.
    void count_insertion(const Digger& digger) {
        Counters& c = tally();
        ++c.insertions;
        c.max_cavity = std::max<std::uint64_t>(c.max_cavity, deleted_.size());
        c.dig_tests += deleted_.size() - 1 + created_.size();
        c.ghosts_deleted += digger.ghosts_taken;
        c.tets_deleted += deleted_.size() - digger.ghosts_taken;
        c.ghosts_created += digger.ghosts_made;
        c.tets_created += created_.size() - digger.ghosts_made;
        c.count_predicate(
            PredicateKind::kInsphere, predicates::Stage::kStatic, digger.decided_static);
    }

    /// Uncounted: the callers count (bootstrap, count_insertion).
    [[gnu::always_inline]] TetId add(const TetVertices& v, std::uint64_t step) {
        const TetId t = storage_.add_tetrahedron(v);
        observer_.on_tet_created(t, v, step);
        return t;
    }

    [[gnu::always_inline]] void remove(TetId t) {
        storage_.delete_tetrahedron(t);
        observer_.on_tet_deleted(t, step_);
        deleted_.push_back(t);
    }

    /// AddTetrahedron(u, face): the face is facet f of the deleted tetrahedron `inner`, whose
    /// other side (`across`) survives.
    /// Inlined into the cavity search: out of line (27 calls per point on a uniform cube) it was
    /// a call around a few stores, with the callee's registers saved and restored each time.
    /// Returns whether the new tetrahedron is a ghost.
    [[gnu::always_inline]] bool fill_cavity_face(VertexId u, TetId inner, int f, HalfFacet across) {
        const TetVertices& w = storage_.vertices(inner);
        // Only a ghost's facets other than its hull triangle hold the ghost vertex, which cone()
        // must rotate to slot 3; every other face is joined to u in slot 3 as it is.
        const auto [v, u_slot] = is_ghost(w) && f != 3
                                     ? cone(facet_vertices(w, f), u)
                                     : Cone{with_apex(facet_vertices(w, f), u), 3};
        const TetId t = add(v, step_);
        storage_.glue(half_facet(t, u_slot), across);
        created_.push_back(t);
        if (record_cavity_faces_) {
            cavity_faces_.push_back({inner, t});
        }
        const bool ghost = is_ghost(v);
        if (!ghost) {
            last_solid_ = t;
        }
        return ghost;
    }

    static TetVertices with_apex(const std::array<VertexId, 3>& tri, VertexId u) {
        return {tri[0], tri[1], tri[2], u};
    }

    void stamp(std::vector<std::uint32_t>& stamps, const TetVertices& v) {
        for (VertexId w : v) {
            if (w != kGhostVertex) {
                stamps[w] = static_cast<std::uint32_t>(step_);
            }
        }
    }

    /// A vertex of a deleted tetrahedron that no new tetrahedron uses lay strictly inside the
    /// cavity: the new (heavier) vertex has submerged it.
    void collect_vanished(VertexId u) {
        const auto s = static_cast<std::uint32_t>(step_);
        for (TetId t : deleted_) {
            for (VertexId w : storage_.vertices(t)) {
                if (w != kGhostVertex && w != u && deleted_stamp_[w] == s &&
                    created_stamp_[w] != s) {
                    vanished_.push_back(w);
                    created_stamp_[w] = s;  // report once
                }
            }
        }
    }

    const Geometry& geometry_;
    Storage& storage_;
    Observer& observer_;
    std::array<VertexId, 4> bootstrap_{};
    TetId last_solid_ = kNoTet;
    std::uint64_t step_ = 0;
    bool record_cavity_faces_ = false;
    PodStack<HalfFacet> queue_;  // deleted tetrahedra whose faces are still to look across
    PodStack<TetId> created_;
    PodStack<TetId> deleted_;
    std::vector<VertexId> vanished_;
    PodStack<CavityFace> cavity_faces_;
    std::vector<std::uint32_t> deleted_stamp_;
    std::vector<std::uint32_t> created_stamp_;
    CavityGluer gluer_;
};

}  // namespace cavity::core
