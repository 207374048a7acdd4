#include "cavity/core/live/triangulate.h"

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "cavity/core/parallel/parallel_build.h"

namespace cavity::core {

namespace detail {

namespace {

/// The parallel construction on prepared points (of `n` input points) into `out`.
void list_prepared_in_parallel(const Prepared& prep,
                               std::size_t n,
                               const TriangulateOptions& options,
                               Triangulation& out) {
    ParallelOptions parallel;
    parallel.threads = options.threads;
    parallel.seed = options.seed;
    const ParallelList list = list_in_parallel(prep.geometry, parallel, out.tets);
    out.hull_triangles = list.hull_triangles;
    out.storage_bytes = list.storage_bytes;
    for (VertexId v : list.redundant) {
        out.redundant.push_back(prep.geometry.key(v));
    }
    std::sort(out.redundant.begin(), out.redundant.end());
    if (options.progress) {
        options.progress(n, n);
    }
}

/// The sequential driver on prepared points, in `Storage`, drained into `out`.
template <class Storage, class Observer>
void list_prepared(const Prepared& prep,
                   const TriangulateOptions& options,
                   Observer& observer,
                   Triangulation& out) {
    Storage storage;
    run_located(prep.geometry, options, storage, observer, out);
    drain_into(storage, prep.geometry, out);
}

/// Gives lent points back when it goes out of scope, however the run ends.
class GiveBack {
public:
    GiveBack(Prepared& prep, const Triangulation& out, PointSet& points)
        : prep_(prep), out_(out), points_(points) {}

    GiveBack(const GiveBack&) = delete;
    GiveBack& operator=(const GiveBack&) = delete;

    ~GiveBack() { give_back(prep_, out_, points_); }

private:
    Prepared& prep_;
    const Triangulation& out_;
    PointSet& points_;
};

}  // namespace

Triangulation triangulate_in_parallel(const PointSet& points,
                                      std::span<const std::uint32_t> sequence,
                                      const TriangulateOptions& options) {
    Triangulation out;
    const Prepared prep = prepare(points, sequence, options.bootstrap, out, options.threads);
    list_prepared_in_parallel(prep, points.size(), options, out);
    return out;
}

}  // namespace detail

Triangulation triangulate_in_place(PointSet& points,
                                   std::vector<std::uint32_t>&& sequence,
                                   const TriangulateOptions& options) {
    Triangulation out;
    detail::with_observer(options, [&](auto& observer) {
        using Observer = std::remove_reference_t<decltype(observer)>;
        if (options.threads > 0) {
            DelaunayTriangulation::require_supported(options, Observer::kCounting);
        }
        const std::size_t n = points.size();
        detail::Prepared prep = detail::prepare_in_place(
            points, std::move(sequence), options.bootstrap, out, std::max(1u, options.threads));
        const detail::GiveBack guard(prep, out, points);
        if (options.threads > 0) {
            detail::list_prepared_in_parallel(prep, n, options, out);
        } else if (options.storage == StorageKind::kArray) {
            // The live triangulation's build and release(), without keeping it live.
            detail::list_prepared<ArrayStorage>(prep, options, observer, out);
        } else {
            detail::list_prepared<FaceHashStorage>(prep, options, observer, out);
        }
    });
    return out;
}

Triangulation triangulate(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options) {
    Triangulation out;
    detail::with_observer(options, [&](auto& observer) {
        out = triangulate_observed(points, sequence, options, observer);
    });
    return out;
}

}  // namespace cavity::core
