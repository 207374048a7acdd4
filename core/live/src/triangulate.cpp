#include "cavity/core/live/triangulate.h"

#include <algorithm>

#include "cavity/core/parallel/parallel_build.h"

namespace cavity::core {

namespace detail {

Triangulation triangulate_in_parallel(const PointSet& points,
                                      std::span<const std::uint32_t> sequence,
                                      const TriangulateOptions& options) {
    Triangulation out;
    const Prepared prep = prepare(points, sequence, options.bootstrap, out, options.threads);
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
        options.progress(points.size(), points.size());
    }
    return out;
}

}  // namespace detail

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
