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
    : id_(id), geometry_(geometry), mesh_(mesh), interior_(interior), random_(seed | 1u) {
    gluer_.reserve(geometry.size());
}

InsertionWorker::Outcome InsertionWorker::insert(VertexId u) {
    const Outcome outcome = attempt(u);
    for (TetId t : held_) {
        // The cavity of an insertion is dead now (fill), and stays out of every other thread's
        // reach until this worker hands its slot out again.
        if (mesh_.owner(t) != ConcurrentMesh::kDead) {
            mesh_.unlock(t);
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

bool InsertionWorker::lock(TetId t) {
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
    TetId t = start;
    int entered = -1;
    for (std::size_t step = 0; !bounded_walks_ || step < kMaxWalkSteps; ++step) {
        const ArrayRecord& r = mesh_.record(t);
        mesh_.prefetch_neighbours(t);
        int exit = -1;
        if (!is_ghost(r.v)) {
            const int first = random_.first_facet();
            for (int k = 0; k < 4 && exit < 0; ++k) {
                const int f = (first + k) & 3;
                if (f == entered) {
                    continue;
                }
                const auto tri = facet_vertices(r.v, f);
                if (Geometry::orient3d(geometry_.point(tri[0]),
                                       geometry_.point(tri[1]),
                                       geometry_.point(tri[2]),
                                       p) == Sign::kNeg) {
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
        const bool locked = mesh_.try_lock(next, id_);
        mesh_.unlock(t);
        if (!locked) {
            return kNoTet;
        }
        t = next;
        entered = facet_of(across);
    }
    mesh_.unlock(t);
    return kNoTet;
}

bool InsertionWorker::conflicts(TetId t, VertexId u) const {
    const TetVertices& v = mesh_.record(t).v;
    return is_ghost(v) ? geometry_.conflicts_ghost(v, u, interior_)
                       : geometry_.conflicts_solid(v, u);
}

TetId InsertionWorker::seek(TetId located, VertexId u, bool& contended) {
    if (conflicts(located, u)) {
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
            if (conflicts(next, u)) {
                return next;
            }
            scratch_.push_back(next);
        }
    }
    return kNoTet;
}

bool InsertionWorker::dig(TetId t0, VertexId u) {
    const auto in_cavity = static_cast<std::uint8_t>(id_ | ConcurrentMesh::kCavityBit);
    stack_.clear();
    mesh_.set_owner(t0, in_cavity);
    cavity_.push_back(t0);
    for (int f = 0; f < 4; ++f) {
        stack_.push_back(half_facet(t0, f));
    }
    while (!stack_.empty()) {
        const HalfFacet top = stack_.pop_back();
        const TetId t = tet_of(top);
        const int f = facet_of(top);
        const HalfFacet across = mesh_.record(t).n[static_cast<std::size_t>(f)];
        const TetId far = tet_of(across);
        const std::uint8_t owner = mesh_.owner(far);
        if (owner == in_cavity) {
            continue;
        }
        if (owner != id_ && !lock(far)) {
            return false;
        }
        if (conflicts(far, u)) {
            mesh_.set_owner(far, in_cavity);
            cavity_.push_back(far);
            mesh_.prefetch_neighbours(far);
            for (int g = 0; g < 4; ++g) {
                if (g != facet_of(across)) {
                    stack_.push_back(half_facet(far, g));
                }
            }
        } else {
            boundary_.push_back({t, f, across});
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
    const TetId t = free_.empty() ? block_.first++ : free_.pop_back();
    mesh_.set_owner(t, id_);
    held_.push_back(t);
    return t;
}

void InsertionWorker::fill(VertexId u) {
    created_.clear();
    for (const BoundaryFace& b : boundary_) {
        const auto [v, u_slot] = cone(facet_vertices(mesh_.record(b.inner).v, b.facet), u);
        const TetId t = new_slot();
        ArrayRecord& r = mesh_.record(t);
        r.v = v;
        r.n[static_cast<std::size_t>(u_slot)] = b.across;
        mesh_.record(tet_of(b.across)).n[static_cast<std::size_t>(facet_of(b.across))] =
            half_facet(t, u_slot);
        created_.push_back(t);
        if (!is_ghost(v)) {
            last_ = t;
        }
    }
    ConcurrentMesh::OwnedRecords view{mesh_};
    gluer_.glue(view, std::span<const TetId>(created_.begin(), created_.size()), u);
    for (TetId t : cavity_) {
        mesh_.set_owner(t, ConcurrentMesh::kDead);
        free_.push_back(t);
    }
}

}  // namespace cavity::core
