#pragma once

#include <array>
#include <cstdint>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/delaunay/stochastic_walk.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/cavity_gluer.h"
#include "cavity/core/mesh/tetrahedron.h"
#include "concurrent_mesh.h"

namespace cavity::core {

/// One thread's Bowyer–Watson insertion (§5.2) into the shared ConcurrentMesh. An insertion takes
/// the lock of every tetrahedron it reads before reading it: hand over hand along the walk (§5.5),
/// then the cavity and the tetrahedra around it. Only when every lock is held does it change
/// anything, so a lock held by another thread costs nothing but the attempt: the locks are
/// dropped and the point is handed back (kContended) to be inserted in a later pass. Without
/// contention the result is the sequential engine's: the same exact, perturbed tests decide the
/// same cavity, and the Delaunay triangulation of the perturbed points is unique, so the order in
/// which the threads insert does not change the tetrahedra.
class InsertionWorker {
public:
    enum class Outcome {
        kInserted,
        kRedundant,  ///< weighted: u conflicts with nothing (it is submerged)
        kContended,  ///< another thread held a tetrahedron the insertion needed
        kNoRoom,     ///< the mesh has no free slot left for the new tetrahedra
    };

    /// `id` (1 to 127) is the owner byte the worker locks with; `interior` the bootstrap vertices
    /// (the ghost test's reference).
    InsertionWorker(std::uint8_t id,
                    const Geometry& geometry,
                    ConcurrentMesh& mesh,
                    const std::array<VertexId, 4>& interior,
                    std::uint64_t seed);

    /// Inserts vertex u, or leaves the mesh as it was; returns no lock held.
    Outcome insert(VertexId u);

    /// Where the next walk starts: a tetrahedron (live or not; checked under its lock), and the
    /// vertex last inserted near it.
    void restart_at(TetId t, VertexId near) {
        last_ = t;
        last_vertex_ = near;
    }

    TetId last_solid() const { return last_; }

    /// Whether walks are cut short (kMaxWalkSteps): only while other threads change the mesh; a
    /// lone thread's walk always ends.
    void bound_walks(bool bounded) { bounded_walks_ = bounded; }

    /// The vertex this worker inserted last (kNoVertex before any).
    VertexId last_vertex() const { return last_vertex_; }

private:
    struct BoundaryFace {
        TetId inner;
        int facet;
        HalfFacet across;
    };

    Outcome attempt(VertexId u);
    /// A live tetrahedron to walk from, locked (not in held_), or kNoTet when every candidate is
    /// held by another thread.
    TetId start_tet();
    /// The visibility walk towards u, hand over hand; the cell it ends in is locked and in held_.
    /// kNoTet (nothing locked) when another thread holds a cell on the way.
    TetId walk(TetId start, const Point3& p);
    /// A tetrahedron in conflict with u around `located` (seek_conflict's search, locking what it
    /// reads). Sets `contended` when a lock was refused.
    TetId seek(TetId located, VertexId u, bool& contended);
    /// DigCavity3D without changing anything: the cavity and its boundary faces, all locked.
    /// False when a lock was refused.
    bool dig(TetId t0, VertexId u);
    bool reserve_slots(std::size_t count);
    TetId new_slot();
    void fill(VertexId u);
    [[gnu::always_inline]] bool lock(TetId t);
    /// Inlined into the cavity search, as the sequential engine's test (bowyer_watson.h).
    [[gnu::always_inline]] bool conflicts(const TetVertices& v, VertexId u) const;

    std::uint8_t id_;
    const Geometry& geometry_;
    ConcurrentMesh& mesh_;
    std::array<VertexId, 4> interior_;
    WalkRandom random_;
    TetId last_ = kNoTet;
    bool bounded_walks_ = true;
    VertexId last_vertex_ = kNoVertex;
    /// The live slots this attempt locked and kept out of its cavity (the cavity's are in cavity_,
    /// the new ones in created_).
    PodStack<TetId> held_;
    PodStack<TetId> cavity_;
    PodStack<BoundaryFace> boundary_;
    PodStack<HalfFacet> stack_;
    PodStack<TetId> created_;
    PodStack<TetId> scratch_;
    PodStack<TetId> free_;  ///< dead slots this worker freed, to reuse
    ConcurrentMesh::Block block_{0, 0};
    CavityGluer gluer_;
};

}  // namespace cavity::core
