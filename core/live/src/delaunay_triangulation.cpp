#include "cavity/core/live/delaunay_triangulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/delaunay/seek_conflict.h"
#include "cavity/core/edit/flips.h"
#include "cavity/core/edit/vertex_deletion.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/geometry/duplicates.h"
#include "cavity/core/mesh/star.h"
#include "cavity/core/parallel/parallel_build.h"

namespace cavity::core {

namespace {

/// API slot i of a tetrahedron is storage slot kMirror[i]: the API lists the stored (orient3d
/// > 0) order with its first two vertices swapped (handedness.h). The map is its own inverse.
constexpr std::array<int, 4> kMirror{1, 0, 2, 3};

std::array<std::uint32_t, 4> api_tet(const Geometry& geometry, const TetVertices& v) {
    return {geometry.key(v[1]), geometry.key(v[0]), geometry.key(v[2]), geometry.key(v[3])};
}

}  // namespace

DelaunayTriangulation::State::State(Geometry points, const PointSet& input, std::uint64_t seed)
    : geometry(std::move(points))
    , walk(seed)
    , next_key(static_cast<std::uint32_t>(input.size()))
    , index_base(input.index_base)
    , removed(input.size(), false) {}

DelaunayTriangulation::DelaunayTriangulation(const PointSet& points,
                                             std::span<const std::uint32_t> sequence,
                                             const TriangulateOptions& options) {
    detail::with_observer(options, [&](auto& observer) {
        *this = DelaunayTriangulation(points, sequence, options, observer);
    });
}

DelaunayTriangulation::DelaunayTriangulation(DelaunayTriangulation&&) noexcept = default;
DelaunayTriangulation& DelaunayTriangulation::operator=(DelaunayTriangulation&&) noexcept = default;
DelaunayTriangulation::~DelaunayTriangulation() = default;

void DelaunayTriangulation::require_supported(const TriangulateOptions& options, bool counting) {
    if (options.storage != StorageKind::kArray) {
        throw Error(options.threads > 0
                        ? "the parallel construction uses the array storage, not the hash storage"
                        : "the live triangulation keeps the array storage (the hash storage is for "
                          "triangulate())");
    }
    if (options.threads == 0) {
        return;
    }
    if (counting) {
        throw Error(
            "the parallel construction runs the plain engine: its counters are defined for one "
            "insertion order (run without threads to count)");
    }
    if (options.locate != LocateKind::kWalk) {
        throw Error("the parallel construction locates points by the walk only");
    }
    if (options.prefix != 0) {
        throw Error("the parallel construction inserts every point (no prefix)");
    }
}

detail::RunEnd DelaunayTriangulation::build_in_threads(const TriangulateOptions& options,
                                                       Triangulation& built) {
    State& s = *state_;
    ParallelOptions parallel;
    parallel.threads = options.threads;
    parallel.seed = options.seed;
    ParallelBuild build = build_in_parallel(s.geometry, parallel, s.storage);
    for (VertexId v : build.redundant) {
        built.redundant.push_back(s.geometry.key(v));
    }
    std::sort(built.redundant.begin(), built.redundant.end());
    if (options.progress) {
        options.progress(s.geometry.size(), s.geometry.size());
    }
    return {build.interior, build.last_solid};
}

void DelaunayTriangulation::adopt(const detail::RunEnd& end, Triangulation& built) {
    State& s = *state_;
    s.interior = end.interior;
    s.last_solid = end.last_solid;
    s.duplicates = std::move(built.duplicates);
    s.counters = built.counters;
    if (built.redundant.empty()) {
        return;
    }
    // built.redundant holds input indices; the engine's vertex ids are ranks.
    std::vector<VertexId> rank_of(s.next_key, kNoVertex);
    for (VertexId v = 0; v < s.geometry.size(); ++v) {
        rank_of[s.geometry.key(v)] = v;
    }
    for (std::uint32_t key : built.redundant) {
        s.submerged.push_back(rank_of[key]);
    }
}

std::size_t DelaunayTriangulation::point_count() const {
    return state_->next_key;
}

std::size_t DelaunayTriangulation::tet_count() const {
    return state_->storage.live_count() - hull_triangle_count();
}

std::size_t DelaunayTriangulation::hull_triangle_count() const {
    const ArrayStorage& storage = state_->storage;
    std::size_t ghosts = 0;
    for (TetId t = 0; t < storage.capacity(); ++t) {
        ghosts += storage.alive(t) && is_ghost(storage.vertices(t)) ? 1 : 0;
    }
    return ghosts;
}

bool DelaunayTriangulation::weighted() const {
    return state_->geometry.weighted();
}

BowyerWatson<ArrayStorage, NullObserver>& DelaunayTriangulation::engine(State& s) {
    if (!s.engine) {
        s.engine.emplace(s.geometry, s.storage, s.observer);
        s.engine->resume(s.interior, s.last_solid);
    }
    return *s.engine;
}

void DelaunayTriangulation::hand_out_index() {
    State& s = *state_;
    ++s.next_key;
    s.removed.push_back(false);
    if (!s.vertex_of.empty()) {
        s.vertex_of.push_back(kNoVertex);
    }
}

TetId DelaunayTriangulation::start_near(TetId near) const {
    const ArrayStorage& storage = state_->storage;
    if (near != kNoTet && near < storage.capacity() && storage.alive(near) &&
        !is_ghost(storage.vertices(near))) {
        return near;
    }
    return start_tet();
}

TetId DelaunayTriangulation::start_tet() const {
    const State& s = *state_;
    const TetId hint = s.engine ? s.engine->last_solid() : s.last_solid;
    if (hint != kNoTet && s.storage.alive(hint) && !is_ghost(s.storage.vertices(hint))) {
        return hint;
    }
    // Flips may have deleted it; any live solid tetrahedron will do.
    for (TetId t = 0; t < s.storage.capacity(); ++t) {
        if (s.storage.alive(t) && !is_ghost(s.storage.vertices(t))) {
            return t;
        }
    }
    throw InternalError("internal error: the live triangulation has no solid tetrahedron");
}

std::vector<bool> DelaunayTriangulation::vertex_flags() const {
    const State& s = *state_;
    std::vector<bool> flags(s.geometry.size(), false);
    for (TetId t = 0; t < s.storage.capacity(); ++t) {
        if (s.storage.alive(t)) {
            for (VertexId v : s.storage.vertices(t)) {
                if (v != kGhostVertex) {
                    flags[v] = true;
                }
            }
        }
    }
    return flags;
}

std::uint32_t DelaunayTriangulation::insert(const Point3& p, double weight) {
    State& s = *state_;
    const std::uint32_t key = s.next_key;
    const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                        (!weighted() || std::isfinite(weight));
    if (!finite) {
        throw Error("point " + std::to_string(std::int64_t{key} + s.index_base) +
                    " has a non-finite coordinate or weight");
    }
    hand_out_index();
    insert_keyed(p, weight, key, kNoTet);
    return key;
}

std::uint32_t DelaunayTriangulation::insert(const PointSet& batch,
                                            std::span<const std::uint32_t> sequence) {
    State& s = *state_;
    const std::size_t n = batch.size();
    const bool weights = weighted() && batch.weighted();
    if (weighted() && !batch.weighted()) {
        throw Error("the triangulation is weighted: the points to insert need weights");
    }
    std::vector<bool> listed(n, false);
    for (std::uint32_t row : sequence) {
        if (row >= n || listed[row]) {
            throw Error("the insertion sequence is not a permutation of the batch's rows");
        }
        listed[row] = true;
    }
    if (sequence.size() != n) {
        throw Error("the insertion sequence is not a permutation of the batch's rows");
    }
    for (std::size_t row = 0; row < n; ++row) {
        const Point3& p = batch.points[row];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            (weights && !std::isfinite(batch.weights[row]))) {
            throw Error("point " +
                        std::to_string(static_cast<std::int64_t>(s.next_key + row) + s.index_base) +
                        " has a non-finite coordinate or weight");
        }
    }
    const std::uint32_t base = s.next_key;
    s.next_key += static_cast<std::uint32_t>(n);
    s.removed.resize(s.next_key, false);
    if (!s.vertex_of.empty()) {
        s.vertex_of.resize(s.next_key, kNoVertex);
    }
    // A repeat inside the batch is never inserted: as in triangulate(), the lowest row of equal
    // points is the one kept, whatever the order, and the others repeat what it repeats.
    const std::vector<std::uint32_t> first = first_occurrences(
        batch.points, weights ? std::span<const double>(batch.weights) : std::span<const double>());
    std::vector<std::uint32_t> kept(n);
    for (std::uint32_t row : sequence) {
        if (first[row] == row) {
            kept[row] = insert_keyed(
                batch.points[row], weights ? batch.weights[row] : 0.0, base + row, kNoTet);
        }
    }
    const std::size_t listed_before = s.duplicates.size();
    for (std::uint32_t row = 0; row < n; ++row) {
        if (first[row] != row) {
            s.duplicates.push_back({base + row, kept[first[row]]});
        }
    }
    // By point, as triangulate() lists them.
    std::sort(s.duplicates.begin() + static_cast<std::ptrdiff_t>(listed_before),
              s.duplicates.end());
    return base;
}

std::uint32_t DelaunayTriangulation::insert(const predicates::GenericPoint3& p,
                                            const Point3& rounded,
                                            TetId near) {
    State& s = *state_;
    const auto* explicit_point = std::get_if<Point3>(&p);
    if (weighted() && explicit_point == nullptr) {
        throw Error("implicit points are unweighted: the triangulation is weighted");
    }
    const Point3& located = explicit_point != nullptr ? *explicit_point : rounded;
    const std::uint32_t key = s.next_key;
    if (!std::isfinite(located.x) || !std::isfinite(located.y) || !std::isfinite(located.z)) {
        throw Error("point " + std::to_string(std::int64_t{key} + s.index_base) +
                    " has a non-finite coordinate");
    }
    hand_out_index();
    if (explicit_point != nullptr) {
        insert_keyed(*explicit_point, 0.0, key, near);
        return key;
    }
    return insert_appended(s.geometry.append_implicit(p, rounded, key), key, near);
}

std::uint32_t DelaunayTriangulation::insert_keyed(const Point3& p,
                                                  double weight,
                                                  std::uint32_t key,
                                                  TetId near) {
    return insert_appended(state_->geometry.append(p, key, weight), key, near);
}

std::uint32_t DelaunayTriangulation::insert_appended(VertexId u, std::uint32_t key, TetId near) {
    State& s = *state_;
    BowyerWatson<ArrayStorage, NullObserver>& bw = engine(s);
    const TetId start = start_near(near);
    if (!s.vertex_of.empty()) {
        s.vertex_of[key] = u;
    }
    const TetId located = s.walk.locate(bw, s.geometry.point(u), start);
    const ConflictSeed seed = seek_conflict(bw, u, located, s.scratch);
    if (seed.duplicate != kNoVertex) {
        const std::uint32_t repeated = s.geometry.key(seed.duplicate);
        s.duplicates.push_back({key, repeated});
        if (!s.vertex_of.empty()) {
            s.vertex_of[key] = kNoVertex;
        }
        return repeated;
    }
    if (seed.tet == kNoTet) {
        s.submerged.push_back(u);
    } else {
        bw.insert_vertex(u, seed.tet, u);
        s.submerged.insert(s.submerged.end(), bw.vanished().begin(), bw.vanished().end());
        if ((u & (u - 1)) == 0) {
            CAVITY_EXPENSIVE_CHECK(
                check_complex(s.storage, s.geometry),
                "the live triangulation after inserting point " + std::to_string(key));
        }
    }
    return key;
}

TetId DelaunayTriangulation::locate(const Point3& p) const {
    return state_->walk.locate(engine(*state_), p, start_tet());
}

void DelaunayTriangulation::remove(std::span<const std::uint32_t> ids) {
    State& s = *state_;
    const auto numbered = [&](std::uint32_t id) {
        return std::to_string(std::int64_t{id} + s.index_base);
    };
    if (s.vertex_of.empty()) {
        s.vertex_of.assign(s.next_key, kNoVertex);
        for (VertexId v = 0; v < s.geometry.size(); ++v) {
            s.vertex_of[s.geometry.key(v)] = v;
        }
    }
    std::vector<bool> is_duplicate(s.next_key, false);
    for (const auto& d : s.duplicates) {
        is_duplicate[d[0]] = true;
    }
    std::vector<bool> is_submerged(s.geometry.size(), false);
    for (VertexId v : s.submerged) {
        is_submerged[v] = true;
    }
    const std::vector<bool> is_vertex = vertex_flags();
    std::vector<bool> gone(s.next_key, false);
    for (std::uint32_t id : ids) {
        if (id >= s.next_key) {
            throw Error("cannot delete point " + numbered(id) + ": there are only " +
                        std::to_string(s.next_key) + " points");
        }
        if (gone[id]) {
            throw Error("point " + numbered(id) + " is listed twice for deletion");
        }
        if (s.removed[id]) {
            throw Error("point " + numbered(id) + " has been deleted already");
        }
        const VertexId v = s.vertex_of[id];
        if (!is_duplicate[id] && !is_submerged[v] && !is_vertex[v]) {
            throw Error("cannot delete point " + numbered(id) + ": it was never inserted");
        }
        gone[id] = true;
    }
    for (const auto& d : s.duplicates) {
        if (!gone[d[0]] && gone[d[1]]) {
            throw Error("cannot delete point " + numbered(d[1]) + ": point " + numbered(d[0]) +
                        " repeats it and is kept (delete the repeats too, or keep both)");
        }
    }
    // The remaining vertices and submerged points must still span 3D.
    std::vector<Point3> remaining;
    for (VertexId v = 0; v < s.geometry.size(); ++v) {
        const std::uint32_t key = s.geometry.key(v);
        if (!gone[key] && !s.removed[key] && (is_submerged[v] || is_vertex[v])) {
            remaining.push_back(s.geometry.point(v));
        }
    }
    std::vector<std::uint32_t> all(remaining.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) {
        all[i] = i;
    }
    find_bootstrap(remaining, all);

    for (std::uint32_t id : ids) {
        s.removed[id] = true;
        const VertexId v = s.vertex_of[id];
        if (is_duplicate[id]) {
            std::erase_if(s.duplicates, [&](const auto& d) { return d[0] == id; });
            continue;
        }
        // Not the flags: an earlier deletion of this call may have uncovered v.
        if (std::find(s.submerged.begin(), s.submerged.end(), v) != s.submerged.end()) {
            std::erase(s.submerged, v);
            continue;
        }
        const std::vector<TetId> fresh =
            delete_vertex(s.storage, s.geometry, v, s.submerged, s.edits);
        // Submerged points that the deletion uncovered are vertices now.
        std::erase_if(s.submerged, [&](VertexId w) {
            return std::any_of(fresh.begin(), fresh.end(), [&](TetId t) {
                return slot_of(s.storage.vertices(t), w) >= 0;
            });
        });
    }
    restart_after_edit();
}

void DelaunayTriangulation::restart_after_edit() {
    // The bootstrap vertices may be gone: any solid tetrahedron's four vertices are affinely
    // independent, which is all the ghost test asks of its reference.
    State& s = *state_;
    s.last_solid = kNoTet;
    s.last_solid = start_tet();
    s.interior = s.storage.vertices(s.last_solid);
    if (s.engine) {
        s.engine->resume(s.interior, s.last_solid);
    }
}

std::vector<TetId> DelaunayTriangulation::flip23(HalfFacet h) {
    std::vector<TetId> fresh = core::flip23(state_->storage, state_->geometry, h, state_->edits);
    if (!fresh.empty()) {
        restart_after_edit();
    }
    return fresh;
}

std::vector<TetId> DelaunayTriangulation::flip32(TetId t, int i, int j) {
    std::vector<TetId> fresh =
        core::flip32(state_->storage, state_->geometry, t, i, j, state_->edits);
    if (!fresh.empty()) {
        restart_after_edit();
    }
    return fresh;
}

std::vector<std::string> DelaunayTriangulation::check(CheckLevel level) const {
    const State& s = *state_;
    std::vector<std::string> problems = check_complex(s.storage, s.geometry);
    if (level == CheckLevel::kComplex || !problems.empty()) {
        return problems;
    }
    // The validator reads points by input index; points never inserted (a prefix build) and
    // removed ones are declared absent.
    PointSet by_key;
    by_key.index_base = s.index_base;
    by_key.points.assign(s.next_key, Point3{});
    if (weighted()) {
        by_key.weights.assign(s.next_key, 0.0);
    }
    std::vector<bool> present(s.next_key, false);
    std::vector<bool> is_present = vertex_flags();
    for (VertexId v : s.submerged) {
        is_present[v] = true;
    }
    for (VertexId v = 0; v < s.geometry.size(); ++v) {
        const std::uint32_t key = s.geometry.key(v);
        by_key.points[key] = s.geometry.point(v);
        if (weighted()) {
            by_key.weights[key] = s.geometry.weighted_point(v).w;
        }
        present[key] = !s.removed[key] && is_present[v];
    }
    for (const auto& d : s.duplicates) {
        by_key.points[d[0]] = by_key.points[d[1]];
        if (weighted()) {
            by_key.weights[d[0]] = by_key.weights[d[1]];
        }
        present[d[0]] = !s.removed[d[0]];
    }
    std::vector<std::uint32_t> absent;
    for (std::uint32_t key = 0; key < s.next_key; ++key) {
        if (!present[key]) {
            absent.push_back(key);
        }
    }
    const std::vector<std::array<std::uint32_t, 4>> solid = tets();
    ValidationReport report = validate(by_key, solid, absent);
    return std::move(report.problems);
}

std::vector<std::array<std::uint32_t, 4>> DelaunayTriangulation::tets() const {
    const State& s = *state_;
    std::vector<std::array<std::uint32_t, 4>> out;
    out.reserve(s.storage.live_count());
    for (TetId t = 0; t < s.storage.capacity(); ++t) {
        if (s.storage.alive(t) && !is_ghost(s.storage.vertices(t))) {
            out.push_back(api_tet(s.geometry, s.storage.vertices(t)));
        }
    }
    return out;
}

Adjacency DelaunayTriangulation::adjacency() const {
    const State& s = *state_;
    const ArrayStorage& storage = s.storage;
    const std::size_t slots = storage.capacity();
    // Storage order, read sequentially. The slots are reused by insertions that follow a
    // space-filling curve, so tetrahedra near in space are mostly near in the storage already;
    // sorting them by their lowest vertex instead cost random reads of every record (0.95 s of
    // the 5.2 s of a 10^6-point build from Python).
    std::vector<std::int32_t> index(slots, -1);
    std::int32_t m = 0;
    for (TetId t = 0; t < slots; ++t) {
        if (storage.alive(t) && !is_ghost(storage.vertices(t))) {
            index[t] = m++;
        }
    }
    Adjacency out;
    out.simplices.resize(static_cast<std::size_t>(m));
    out.neighbors.resize(4 * static_cast<std::size_t>(m));
    // By vertex id (insertion rank), which is local along the storage, then permuted to input
    // indices once per vertex: writing by input index directly scattered four writes per
    // tetrahedron over the whole array (half of this function's time at 10^6 points).
    std::vector<std::int32_t> by_vertex(s.geometry.size(), -1);
    for (TetId t = 0; t < slots; ++t) {
        const std::int32_t o = index[t];
        if (o < 0) {
            continue;
        }
        const TetVertices& v = storage.vertices(t);
        const Tet tet = api_tet(s.geometry, v);
        const auto at = static_cast<std::size_t>(o);
        out.simplices[at] = tet;
        for (std::size_t i = 0; i < 4; ++i) {
            by_vertex[v[i]] = o;
            const HalfFacet across = storage.adjacent(t, kMirror[i]);
            const std::int32_t neighbour = index[tet_of(across)];
            out.neighbors[4 * at + i] = neighbour;
            if (neighbour < 0) {
                out.hull.push_back(hull_triangle(tet, i));
            }
        }
    }
    out.vertex_to_simplex.assign(s.next_key, -1);
    for (VertexId v = 0; v < by_vertex.size(); ++v) {
        out.vertex_to_simplex[s.geometry.key(v)] = by_vertex[v];
    }
    return out;
}

const std::vector<std::array<std::uint32_t, 2>>& DelaunayTriangulation::duplicates() const {
    return state_->duplicates;
}

std::vector<std::uint32_t> DelaunayTriangulation::redundant() const {
    std::vector<std::uint32_t> keys;
    for (VertexId v : state_->submerged) {
        keys.push_back(state_->geometry.key(v));
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

const Counters& DelaunayTriangulation::counters() const {
    return state_->counters;
}

const RetriangulationCounters& DelaunayTriangulation::edit_counters() const {
    return state_->edits;
}

const Geometry& DelaunayTriangulation::geometry() const {
    return state_->geometry;
}

const ArrayStorage& DelaunayTriangulation::storage() const {
    return state_->storage;
}

Triangulation DelaunayTriangulation::release() && {
    Triangulation out;
    out.duplicates = std::move(state_->duplicates);
    out.redundant = redundant();
    out.counters = state_->counters;
    detail::drain_into(state_->storage, state_->geometry, out);
    state_.reset();
    return out;
}

ArrayStorage DelaunayTriangulation::release_by_index() && {
    State& s = *state_;
    std::vector<VertexId> rename(s.geometry.size());
    for (VertexId v = 0; v < rename.size(); ++v) {
        rename[v] = s.geometry.key(v);
    }
    s.storage.rename_vertices(rename);
    ArrayStorage out = std::move(s.storage);
    state_.reset();
    return out;
}

}  // namespace cavity::core
