#include "insertion_worker.h"

#include <algorithm>

namespace cavity::core {

namespace {

/// Slots a worker claims at once: enough that the shared counter is touched once per hundreds
/// of insertions, few enough that the unused tails of the blocks stay negligible.
constexpr std::size_t kBlockSlots = 4096;

/// A walk in a mesh that other threads change under it is not guaranteed to end (the remembering
/// walk's proof assumes a fixed triangulation); one this long is given up as contended, and the
/// point is inserted later, when fewer threads run.
constexpr std::size_t kMaxWalkSteps = 1u << 16;

}  // namespace

InsertionWorker::InsertionWorker(std::uint8_t id,
                                 const Geometry& geometry,
                                 ConcurrentMesh& mesh,
                                 const std::array<VertexId, 4>& interior,
                                 std::uint64_t seed)
    : id_(id), geometry_(geometry), mesh_(mesh), interior_(interior), random_(seed | 1u) {}

InsertionWorker::Outcome InsertionWorker::insert(VertexId u) {
    const Outcome outcome = attempt(u);
    const ConcurrentMesh::Slots mesh = mesh_.slots();
    for (TetId t : held_) {
        mesh.unlock(t);
    }
    if (outcome == Outcome::kInserted) {
        // The cavity is dead (fill), and stays out of every other thread's reach until this
        // worker hands its slots out again; the new tetrahedra are published.
        for (TetId t : created_) {
            mesh.unlock(t);
        }
    } else {
        // Given up: the cavity found so far stays as it was.
        for (TetId t : cavity_) {
            mesh.unlock(t);
        }
    }
    held_.clear();
    cavity_.clear();
    boundary_.clear();
    return outcome;
}

InsertionWorker::Outcome InsertionWorker::attempt(VertexId u) {
    const TetId start = start_tet();
    if (start == kNoTet) {
        return Outcome::kContended;
    }
    const TetId located = walk(start, geometry_.point(u));
    if (located == kNoTet) {
        return Outcome::kContended;
    }
    bool contended = false;
    const TetId seed = seek(located, u, contended);
    if (contended) {
        return Outcome::kContended;
    }
    if (seed == kNoTet) {
        return Outcome::kRedundant;
    }
    if (!dig(seed, u)) {
        return Outcome::kContended;
    }
    if (!reserve_slots(boundary_.size())) {
        return Outcome::kNoRoom;
    }
    fill(u);
    last_vertex_ = u;
    return Outcome::kInserted;
}

inline bool InsertionWorker::lock(TetId t) {
    if (!mesh_.try_lock(t, id_)) {
        return false;
    }
    held_.push_back(t);
    return true;
}

TetId InsertionWorker::start_tet() {
    if (last_ != kNoTet) {
        // Another thread may have deleted it since (then it is dead, and any other start will
        // do), and may even have reused the slot for a ghost, where a walk cannot start (it
        // would stop at once).
        if (mesh_.try_lock(last_, id_)) {
            if (!is_ghost(mesh_.record(last_).v)) {
                return last_;
            }
            mesh_.unlock(last_);
        } else if (mesh_.owner(last_) != ConcurrentMesh::kDead) {
            return kNoTet;
        }
    }
    // Any live solid tetrahedron will do, and the slots after the hint were mostly handed out
    // near it.
    const std::size_t used = mesh_.used();
    const std::size_t from = last_ == kNoTet ? 0 : last_;
    for (std::size_t k = 0; k < used; ++k) {
        const auto t = static_cast<TetId>((from + k) % used);
        if (mesh_.try_lock(t, id_)) {
            if (!is_ghost(mesh_.record(t).v)) {
                last_ = t;
                return t;
            }
            mesh_.unlock(t);
        }
    }
    return kNoTet;
}

TetId InsertionWorker::walk(TetId start, const Point3& p) {
    Uncounted none;
    const ConcurrentMesh::Slots mesh = mesh_.slots();
    TetId t = start;
    int entered = -1;
    for (std::size_t step = 0; !bounded_walks_ || step < kMaxWalkSteps; ++step) {
        const ArrayRecord& r = mesh.record(t);
        mesh.prefetch_neighbours(t);
        int exit = -1;
        if (!is_ghost(r.v)) {
            const int first = random_.first_facet();
            for (int k = 0; k < 4 && exit < 0; ++k) {
                const int f = (first + k) & 3;
                if (f == entered) {
                    continue;
                }
                const auto tri = facet_vertices(r.v, f);
                // The points inserted in parallel are explicit input points, all in the box, so
                // the static filter holds (the sequential walk's test).
                if (geometry_.orient3d_in_box(geometry_.point(tri[0]),
                                              geometry_.point(tri[1]),
                                              geometry_.point(tri[2]),
                                              p,
                                              none) == Sign::kNeg) {
                    exit = f;
                }
            }
        }
        if (exit < 0) {
            // Inside the closed tetrahedron, or entered a ghost through its hull triangle with p
            // strictly in front (walk.h).
            held_.push_back(t);
            return t;
        }
        const HalfFacet across = r.n[static_cast<std::size_t>(exit)];
        const TetId next = tet_of(across);
        const bool locked = mesh.try_lock(next, id_);
        mesh.unlock(t);
        if (!locked) {
            return kNoTet;
        }
        t = next;
        entered = facet_of(across);
    }
    mesh.unlock(t);
    return kNoTet;
}

inline bool InsertionWorker::conflicts(const TetVertices& v, VertexId u) const {
    return is_ghost(v) ? geometry_.conflicts_ghost(v, u, interior_)
                       : geometry_.conflicts_solid(v, u);
}

TetId InsertionWorker::seek(TetId located, VertexId u, bool& contended) {
    if (conflicts(mesh_.record(located).v, u)) {
        return located;
    }
    // Weighted only (unweighted, the closed cell holding a new point always conflicts): the cells
    // around a face through u may conflict instead (seek_conflict.h).
    scratch_.clear();
    scratch_.push_back(located);
    for (std::size_t i = 0; i < scratch_.size(); ++i) {
        const TetId t = scratch_[i];
        const TetVertices v = mesh_.record(t).v;
        for (int f = 0; f < 4; ++f) {
            if (is_ghost(v) && f != 3) {
                continue;
            }
            const auto tri = facet_vertices(v, f);
            if (geometry_.orient3d(tri[0], tri[1], tri[2], u) != Sign::kZero) {
                continue;
            }
            const TetId next = tet_of(mesh_.record(t).n[static_cast<std::size_t>(f)]);
            if (std::find(scratch_.begin(), scratch_.end(), next) != scratch_.end()) {
                continue;
            }
            if (!lock(next)) {
                contended = true;
                return kNoTet;
            }
            if (conflicts(mesh_.record(next).v, u)) {
                return next;
            }
            scratch_.push_back(next);
        }
    }
    return kNoTet;
}

bool InsertionWorker::dig(TetId t0, VertexId u) {
    const auto in_cavity = static_cast<std::uint8_t>(id_ | ConcurrentMesh::kCavityBit);
    const ConcurrentMesh::Slots mesh = mesh_.slots();
    // Breadth-first, as the sequential DigCavity3D (dig_cavity.h): a cavity tetrahedron's faces
    // are looked across only after those of every tetrahedron taken before it, so the prefetch of
    // its neighbours' records has a level of tests to land. `stack_` is the queue: each taken
    // tetrahedron with the face it was entered through.
    const auto look_across = [&](TetId t, int f) __attribute__((always_inline)) {
        const HalfFacet across = mesh.record(t).n[static_cast<std::size_t>(f)];
        const TetId far = tet_of(across);
        const std::uint8_t owner = mesh.owner(far);
        if (owner == in_cavity) {
            return true;
        }
        // A tetrahedron this attempt locked before (walk, seek, or an earlier cavity face) was
        // found not in conflict, and is not tested into the cavity now: the tests are exact.
        const bool fresh = owner != id_;
        if (fresh && !mesh.try_lock(far, id_)) {
            return false;
        }
        if (conflicts(mesh.record(far).v, u)) {
            mesh.set_owner(far, in_cavity);
            cavity_.push_back(far);
            mesh.prefetch_neighbours(far);
            stack_.push_back(across);
        } else {
            if (fresh) {
                held_.push_back(far);
            }
            boundary_.push_back({t, f, across});
        }
        return true;
    };
    stack_.clear();
    // t0 was the last tetrahedron locked (the walk's or the seek's): from held_ into the cavity.
    held_.pop_back();
    mesh.set_owner(t0, in_cavity);
    cavity_.push_back(t0);
    mesh.prefetch_neighbours(t0);
    for (int f = 0; f < 4; ++f) {
        if (!look_across(t0, f)) {
            return false;
        }
    }
    for (std::size_t next = 0; next < stack_.size(); ++next) {
        const HalfFacet entered = stack_[next];
        const TetId t = tet_of(entered);
        for (int g = 0; g < 4; ++g) {
            if (g != facet_of(entered) && !look_across(t, g)) {
                return false;
            }
        }
    }
    return true;
}

bool InsertionWorker::reserve_slots(std::size_t count) {
    while (free_.size() + (block_.end - block_.first) < count) {
        // The rest of the current block stays unused (dead, never handed out).
        block_ = mesh_.claim_block(kBlockSlots);
        if (block_.first == block_.end) {
            return false;
        }
    }
    return true;
}

TetId InsertionWorker::new_slot() {
    // A dead slot of this worker's: no other thread can lock it (try_lock takes live ones only).
    // It stays dead until insert() publishes it (unlock's release store, after every write).
    return free_.empty() ? block_.first++ : free_.pop_back();
}

void InsertionWorker::fill(VertexId u) {
    const ConcurrentMesh::Slots mesh = mesh_.slots();
    created_.clear();
    for (const BoundaryFace& b : boundary_) {
        const auto [v, u_slot] = cone(facet_vertices(mesh.record(b.inner).v, b.facet), u);
        const TetId t = new_slot();
        ArrayRecord& r = mesh.record(t);
        r.v = v;
        r.n[static_cast<std::size_t>(u_slot)] = b.across;
        mesh.record(tet_of(b.across)).n[static_cast<std::size_t>(facet_of(b.across))] =
            half_facet(t, u_slot);
        created_.push_back(t);
        if (!is_ghost(v)) {
            last_ = t;
        }
    }
    ConcurrentMesh::OwnedRecords view{mesh};
    gluer_.glue(view, std::span<const TetId>(created_.begin(), created_.size()), u);
    for (TetId t : cavity_) {
        mesh.set_owner(t, ConcurrentMesh::kDead);
        free_.push_back(t);
    }
}

}  // namespace cavity::core
