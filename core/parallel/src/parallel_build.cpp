#include "cavity/core/parallel/parallel_build.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <thread>
#include <utility>

#include "canonical_list.h"
#include "canonical_order.h"
#include "cavity/core/base/error.h"
#include "concurrent_mesh.h"
#include "insertion_worker.h"

namespace cavity::core {

namespace {

/// Free slots to have before a pass: tetrahedra (ghosts included) per point of a Delaunay
/// triangulation of well-spread points are about 6.5; each thread also holds a block and the
/// slots of its last cavities.
constexpr std::size_t kSlotsPerPoint = 7;
constexpr std::size_t kSlotsPerThread = 2 * 4096;

using Workers = std::vector<std::unique_ptr<InsertionWorker>>;

/// The first tetrahedron and the four ghosts on its faces (BowyerWatson::bootstrap), in slots 0
/// to 4. Returns the bootstrap vertices as stored.
std::array<VertexId, 4> bootstrap(const Geometry& geometry, ConcurrentMesh& mesh) {
    VertexId a = 0;
    VertexId b = 1;
    if (geometry.orient3d(a, b, 2, 3) == Sign::kNeg) {
        std::swap(a, b);
    }
    const TetVertices solid{a, b, 2, 3};
    mesh.claim_block(5);
    mesh.record(0).v = solid;
    mesh.set_owner(0, ConcurrentMesh::kFree);
    std::array<TetId, 4> ghosts{};
    for (int f = 0; f < 4; ++f) {
        const auto tri = facet_vertices(solid, f);
        const auto g = static_cast<TetId>(1 + f);
        ghosts[static_cast<std::size_t>(f)] = g;
        mesh.record(g).v = {tri[0], tri[2], tri[1], kGhostVertex};
        mesh.record(0).n[static_cast<std::size_t>(f)] = half_facet(g, 3);
        mesh.record(g).n[3] = half_facet(0, f);
        mesh.set_owner(g, ConcurrentMesh::kFree);
    }
    // Each ghost's three faces through the ghost vertex meet the other ghosts' across the edges of
    // the solid tetrahedron: twelve faces, paired by their vertex sets.
    const auto sorted_face = [&](TetId t, int f) {
        auto tri = facet_vertices(mesh.record(t).v, f);
        std::sort(tri.begin(), tri.end());
        return tri;
    };
    for (TetId g : ghosts) {
        for (int f = 0; f < 3; ++f) {
            for (TetId h : ghosts) {
                for (int e = 0; e < 3; ++e) {
                    if (g != h && sorted_face(g, f) == sorted_face(h, e)) {
                        mesh.record(g).n[static_cast<std::size_t>(f)] = half_facet(h, e);
                    }
                }
            }
        }
    }
    return solid;
}

void make_room(ConcurrentMesh& mesh, std::size_t points, unsigned threads, bool short_of_room) {
    std::size_t want = mesh.used() + kSlotsPerPoint * points + kSlotsPerThread * (threads + 1);
    if (short_of_room) {
        // A pass ran out with that much: cavities are larger than estimated (degenerate input).
        want = std::max(want, 2 * mesh.capacity());
    }
    if (want > mesh.capacity()) {
        mesh.grow(std::max(want, mesh.capacity() + mesh.capacity() / 2));
    }
}

/// Squared distance in doubles: only to choose where a walk starts, never a result.
double distance2(const Point3& p, const Point3& q) {
    const double dx = p.x - q.x;
    const double dy = p.y - q.y;
    const double dz = p.z - q.z;
    return dx * dx + dy * dy + dz * dz;
}

/// Each active worker starts its piece from the tetrahedron of whichever worker inserted nearest
/// to the piece's first point (rounds of a biased order run the curve in alternate directions,
/// so a thread's next piece is often where another thread ended).
void choose_starts(const Geometry& geometry,
                   Workers& workers,
                   unsigned active,
                   std::span<const VertexId> points) {
    std::vector<std::pair<TetId, VertexId>> starts(active);
    for (unsigned i = 0; i < active; ++i) {
        const Point3& first = geometry.point(points[i * points.size() / active]);
        double best = -1;
        for (const auto& w : workers) {
            if (w->last_vertex() == kNoVertex) {
                continue;
            }
            const double d = distance2(first, geometry.point(w->last_vertex()));
            if (best < 0 || d < best) {
                best = d;
                starts[i] = {w->last_solid(), w->last_vertex()};
            }
        }
    }
    for (unsigned i = 0; i < active; ++i) {
        if (starts[i].second != kNoVertex) {
            workers[i]->restart_at(starts[i].first, starts[i].second);
        }
    }
}

struct PassResult {
    std::vector<VertexId> handed_back;
    bool short_of_room = false;
};

/// Inserts `points` with `active` workers, one contiguous piece each.
PassResult run_pass(const Geometry& geometry,
                    Workers& workers,
                    unsigned active,
                    std::span<const VertexId> points) {
    choose_starts(geometry, workers, active, points);
    std::atomic<bool> no_room{false};
    std::atomic<bool> failed{false};
    std::vector<std::vector<VertexId>> back(active);
    std::vector<std::exception_ptr> errors(active);
    const auto work = [&](unsigned i) {
        InsertionWorker& worker = *workers[i];
        worker.bound_walks(active > 1);
        const std::span<const VertexId> piece =
            points.subspan(i * points.size() / active,
                           (i + 1) * points.size() / active - i * points.size() / active);
        try {
            for (VertexId u : piece) {
                if (no_room.load(std::memory_order_relaxed) ||
                    failed.load(std::memory_order_relaxed)) {
                    back[i].push_back(u);
                    continue;
                }
                switch (worker.insert(u)) {
                    case InsertionWorker::Outcome::kInserted:
                    case InsertionWorker::Outcome::kRedundant:
                        break;
                    case InsertionWorker::Outcome::kNoRoom:
                        no_room.store(true, std::memory_order_relaxed);
                        back[i].push_back(u);
                        break;
                    case InsertionWorker::Outcome::kContended:
                        back[i].push_back(u);
                        break;
                }
            }
        } catch (...) {
            errors[i] = std::current_exception();
            failed.store(true);
        }
    };
    {
        std::vector<std::jthread> threads;
        threads.reserve(active - 1);
        for (unsigned i = 1; i < active; ++i) {
            threads.emplace_back(work, i);
        }
        work(0);
    }
    for (const std::exception_ptr& e : errors) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
    PassResult result;
    result.short_of_room = no_room.load();
    for (const auto& b : back) {
        result.handed_back.insert(result.handed_back.end(), b.begin(), b.end());
    }
    return result;
}

/// Inserts every point of `geometry` into `mesh`; returns the bootstrap vertices.
std::array<VertexId, 4> construct(const Geometry& geometry,
                                  const ParallelOptions& options,
                                  ConcurrentMesh& mesh) {
    const unsigned threads = options.threads;
    if (threads < 1 || threads > 127) {
        throw Error("the number of threads must be between 1 and 127, not " +
                    std::to_string(threads));
    }
    if (geometry.has_implicit()) {
        // The workers' seek for a conflicting cell trusts rounded coordinates near the located
        // cell; an implicit point needs the sequential engine's search across every face.
        throw Error(
            "the parallel construction takes explicit points only (a CDT's implicit "
            "Steiner points are inserted by the sequential engine)");
    }
    const std::size_t n = geometry.size();
    mesh.grow(kSlotsPerPoint * n + kSlotsPerThread * (threads + 1));
    const std::array<VertexId, 4> interior = bootstrap(geometry, mesh);
    Workers workers;
    for (unsigned i = 0; i < threads; ++i) {
        // Distinct walk streams; the walks' choices never change the result.
        workers.push_back(
            std::make_unique<InsertionWorker>(static_cast<std::uint8_t>(i + 1),
                                              geometry,
                                              mesh,
                                              interior,
                                              options.seed + 0x9E37'79B9'7F4A'7C15ull * i));
    }
    workers[0]->restart_at(0, 3);
    std::vector<VertexId> pending;
    bool short_of_room = false;
    for (std::size_t begin = 4; begin < n;) {
        const std::size_t end = std::min(n, 2 * begin);
        pending.resize(end - begin);
        std::iota(pending.begin(), pending.end(), static_cast<VertexId>(begin));
        unsigned active = pending.size() >= options.min_points_per_thread * threads ? threads : 1;
        while (!pending.empty()) {
            make_room(mesh, pending.size(), threads, short_of_room);
            PassResult pass = run_pass(geometry, workers, active, pending);
            if (active == 1 && !pass.short_of_room && !pass.handed_back.empty()) {
                throw InternalError(
                    "internal error: a parallel construction's lone thread handed points back");
            }
            short_of_room = pass.short_of_room;
            pending = std::move(pass.handed_back);
            if (pending.size() < options.lone_retry_below) {
                active = 1;
            }
        }
        begin = end;
    }
    return interior;
}

/// Weighted: the vertices no live tetrahedron of `mesh` has (submerged), increasing. Unweighted
/// every point is a vertex (detail::prepare removed the repeats), and nothing is scanned.
std::vector<VertexId> redundant_vertices(const Geometry& geometry, ConcurrentMesh& mesh) {
    std::vector<VertexId> redundant;
    if (!geometry.weighted()) {
        return redundant;
    }
    std::vector<bool> vertex(geometry.size(), false);
    for (TetId t = 0; t < mesh.used(); ++t) {
        if (mesh.alive(t)) {
            for (VertexId w : mesh.record(t).v) {
                if (w != kGhostVertex) {
                    vertex[w] = true;
                }
            }
        }
    }
    for (VertexId v = 0; v < geometry.size(); ++v) {
        if (!vertex[v]) {
            redundant.push_back(v);
        }
    }
    return redundant;
}

}  // namespace

ParallelBuild build_in_parallel(const Geometry& geometry,
                                const ParallelOptions& options,
                                ArrayStorage& storage) {
    ConcurrentMesh mesh;
    ParallelBuild out{construct(geometry, options, mesh), kNoTet, {}};
    out.redundant = redundant_vertices(geometry, mesh);
    store_canonically(mesh, storage, geometry.size(), options.threads);
    for (TetId t = static_cast<TetId>(storage.capacity()); t-- > 0;) {
        if (!is_ghost(storage.vertices(t))) {
            out.last_solid = t;
            break;
        }
    }
    return out;
}

ParallelList list_in_parallel(const Geometry& geometry,
                              const ParallelOptions& options,
                              std::vector<std::array<std::uint32_t, 4>>& tets) {
    ConcurrentMesh mesh;
    construct(geometry, options, mesh);
    ParallelList out;
    out.redundant = redundant_vertices(geometry, mesh);
    out.storage_bytes = mesh.bytes();
    out.hull_triangles = list_canonically(mesh, geometry, options.threads, tets);
    return out;
}

}  // namespace cavity::core
