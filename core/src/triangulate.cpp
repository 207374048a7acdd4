#include "cavity/core/triangulate.h"

#include <algorithm>
#include <string>

#include "cavity/core/array_storage.h"
#include "cavity/core/bootstrap.h"
#include "cavity/core/conflict_graph.h"
#include "cavity/core/duplicates.h"
#include "cavity/core/error.h"
#include "cavity/core/face_hash_storage.h"
#include "cavity/core/seek_conflict.h"
#include "cavity/core/walk.h"

namespace cavity::core {

LocateKind parse_locate_kind(std::string_view name) {
    if (name == "walk") {
        return LocateKind::kWalk;
    }
    if (name == "conflict-graph") {
        return LocateKind::kConflictGraph;
    }
    throw Error("unknown point location '" + std::string(name) + "' (walk, conflict-graph)");
}

StorageKind parse_storage_kind(std::string_view name) {
    if (name == "array") {
        return StorageKind::kArray;
    }
    if (name == "hash") {
        return StorageKind::kHash;
    }
    throw Error("unknown storage '" + std::string(name) + "' (array, hash)");
}

namespace {

/// The insertion sequence without repeats, the bootstrap four first, and the engine's view of the
/// points in that order.
struct Prepared {
    std::vector<std::uint32_t> sequence;
    Geometry geometry;
};

Prepared prepare(const PointSet& input,
                 std::span<const std::uint32_t> sequence,
                 Triangulation& out) {
    const auto first = first_occurrences(input.points, input.weights);
    std::vector<std::uint32_t> order;
    order.reserve(sequence.size());
    for (std::uint32_t i : sequence) {
        if (first[i] == i) {
            order.push_back(i);
        }
    }
    for (std::uint32_t i = 0; i < first.size(); ++i) {
        if (first[i] != i) {
            out.duplicates.push_back({i, first[i]});
        }
    }
    const auto boot = find_bootstrap(input.points, order);
    // Move the bootstrap four to the front, keeping the relative order of the rest.
    std::vector<std::uint32_t> seq;
    seq.reserve(order.size());
    for (std::size_t k : boot) {
        seq.push_back(order[k]);
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (std::find(boot.begin(), boot.end(), k) == boot.end()) {
            seq.push_back(order[k]);
        }
    }
    std::vector<Point3> points(seq.size());
    std::vector<double> weights(input.weighted() ? seq.size() : 0);
    for (std::size_t r = 0; r < seq.size(); ++r) {
        points[r] = input.points[seq[r]];
        if (input.weighted()) {
            weights[r] = input.weights[seq[r]];
        }
    }
    Geometry geometry(std::move(points), seq, std::move(weights));
    return {std::move(seq), std::move(geometry)};
}

template <class Storage, class Observer, class Locator>
void run(const Prepared& prep,
         const TriangulateOptions& options,
         Locator& locator,
         Storage& storage,
         Observer& observer,
         Triangulation& out) {
    const Geometry& geometry = prep.geometry;
    const std::size_t n = geometry.size();
    storage.reserve(7 * n + 64, n);
    BowyerWatson<Storage, Observer> engine(geometry, storage, observer);
    engine.bootstrap(0, 1, 2, 3);
    locator.start(engine);
    std::vector<TetId> scratch;
    std::vector<VertexId> redundant;
    const std::size_t report_every = std::max<std::size_t>(n / 200, 1024);
    for (VertexId u = 4; u < n; ++u) {
        std::uint64_t steps_before = 0;
        if constexpr (Observer::kCounting) {
            steps_before = observer.counters()->walk_steps;
        }
        const TetId located = locator.locate(engine, u);
        const ConflictSeed seed = seek_conflict(engine, u, located, scratch);
        if (seed.duplicate != kNoVertex) {
            // first_occurrences removed every repeat; reaching here would be an engine bug.
            throw Error("internal error: point " + std::to_string(geometry.key(u)) +
                        " repeats point " + std::to_string(geometry.key(seed.duplicate)) +
                        " after duplicate removal");
        }
        if (seed.tet == kNoTet) {
            redundant.push_back(u);
            locator.skip(engine, u);
        } else {
            engine.insert_vertex(u, seed.tet, u);
            locator.after_insertion(engine, u);
            redundant.insert(redundant.end(), engine.vanished().begin(), engine.vanished().end());
        }
        if constexpr (Observer::kCounting) {
            const bool inserted = seed.tet != kNoTet;
            observer.on_insertion(InsertionRecord{
                geometry.key(u), u,
                inserted ? static_cast<std::uint32_t>(engine.created().size()) : 0u,
                inserted ? static_cast<std::uint32_t>(engine.deleted().size()) : 0u,
                static_cast<std::uint32_t>(observer.counters()->walk_steps - steps_before)});
        }
        if (options.progress && u % report_every == 0) {
            options.progress(u, n);
        }
    }
    for (VertexId v : redundant) {
        out.redundant.push_back(geometry.key(v));
    }
    std::sort(out.redundant.begin(), out.redundant.end());
    out.tets.reserve(storage.live_count());
    for (TetId t = 0; t < storage.capacity(); ++t) {
        if (!storage.alive(t)) {
            continue;
        }
        const TetVertices& v = storage.vertices(t);
        if (is_ghost(v)) {
            ++out.hull_triangles;
            continue;
        }
        out.tets.push_back({geometry.key(v[0]), geometry.key(v[1]), geometry.key(v[2]), geometry.key(v[3])});
    }
    out.storage_bytes = storage.bytes();
    if constexpr (Observer::kCounting) {
        out.counters = *observer.counters();
        if constexpr (requires { storage.probes(); }) {
            out.counters.hash_probes = storage.probes();
        }
    }
    if (options.progress) {
        options.progress(n, n);
    }
}

/// Walking from the most recently created solid tetrahedron (§5.5).
class WalkLocator {
public:
    explicit WalkLocator(std::uint64_t seed) : walk_(seed) {}

    template <class Engine>
    void start(Engine&) {}

    template <class Engine>
    TetId locate(Engine& engine, VertexId u) {
        return walk_.locate(engine, engine.geometry().point(u), engine.last_solid());
    }

    template <class Engine>
    void skip(Engine&, VertexId) {}

    template <class Engine>
    void after_insertion(Engine&, VertexId) {}

private:
    Walk walk_;
};

template <class Storage, class Observer>
void dispatch_locator(const Prepared& prep,
                      const TriangulateOptions& options,
                      Observer& observer,
                      Triangulation& out) {
    Storage storage;
    if (options.locate == LocateKind::kWalk) {
        WalkLocator locator(options.seed);
        run(prep, options, locator, storage, observer, out);
    } else {
        ConflictGraph locator;
        run(prep, options, locator, storage, observer, out);
    }
}

template <class Observer>
void dispatch_storage(const Prepared& prep,
                      const TriangulateOptions& options,
                      Observer& observer,
                      Triangulation& out) {
    if (options.storage == StorageKind::kArray) {
        dispatch_locator<ArrayStorage>(prep, options, observer, out);
    } else {
        dispatch_locator<FaceHashStorage>(prep, options, observer, out);
    }
}

}  // namespace

Triangulation triangulate(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options) {
    if (sequence.size() != points.size()) {
        throw Error("the insertion sequence has " + std::to_string(sequence.size()) +
                    " entries for " + std::to_string(points.size()) + " points");
    }
    Triangulation out;
    const Prepared prep = prepare(points, sequence, out);
    if (options.count) {
        CountingObserver observer;
        dispatch_storage(prep, options, observer, out);
    } else {
        NullObserver observer;
        dispatch_storage(prep, options, observer, out);
    }
    return out;
}

}  // namespace cavity::core
