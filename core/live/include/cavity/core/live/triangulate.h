#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/delaunay/insertion_driver.h"
#include "cavity/core/delaunay/triangulate.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/mesh/face_hash_storage.h"

/// The batch entry point: a triangulation built and handed out as a list of tetrahedra. With the
/// array storage it is the live triangulation built and released (release() empties the storage
/// as it copies, so the list costs no second copy at the peak); the book's face hash table, which
/// cannot be kept live for flips and deletion, runs the same driver loop directly.
namespace cavity::core {

namespace detail {

/// triangulate() by the parallel construction (options.threads, checked by the caller): the list
/// of tetrahedra in the canonical order, without building the live storage.
Triangulation triangulate_in_parallel(const PointSet& points,
                                      std::span<const std::uint32_t> sequence,
                                      const TriangulateOptions& options);

}  // namespace detail

/// Triangulates `points` inserting them in `sequence` (a permutation of all input indices, e.g.
/// from make_insertion_order). Exact for every finite double input.
/// Throws Error, before building anything, for a non-finite coordinate or weight (naming the
/// point), weights not one per point, or a sequence that is not a permutation; and when the points
/// have no 3D triangulation (fewer than 4 distinct points, or all coplanar or collinear: the
/// message names the affine dimension). An exception thrown by `options.progress` propagates
/// unchanged and leaves nothing behind.
Triangulation triangulate(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options);

/// As triangulate(), for a caller that lends its points and gives up its sequence: the engine
/// lays the coordinates out in insertion order in `points.points`' own array and makes its keys in
/// `sequence`'s, instead of copying both (28 bytes per point less at the peak: 24 for a point,
/// 4 for its key), and puts the points back in input order, bit for bit, before it returns, also
/// when it throws. Only `points.points` moves meanwhile; the same checks, errors and tetrahedra
/// as triangulate().
Triangulation triangulate_in_place(PointSet& points,
                                   std::vector<std::uint32_t>&& sequence,
                                   const TriangulateOptions& options);

/// As triangulate(), reporting to `observer` (a NullObserver or CountingObserver, or a type
/// derived from one): the engine is instantiated for it, so its hooks (observer.h) are called
/// directly and cost nothing when empty. Triangulation::counters is filled when
/// Observer::kCounting. The experiments layer uses this to log every tetrahedron's life.
template <class Observer>
Triangulation triangulate_observed(const PointSet& points,
                                   std::span<const std::uint32_t> sequence,
                                   const TriangulateOptions& options,
                                   Observer& observer) {
    if (options.threads > 0) {
        DelaunayTriangulation::require_supported(options, Observer::kCounting);
        return detail::triangulate_in_parallel(points, sequence, options);
    }
    if (options.storage == StorageKind::kArray) {
        return DelaunayTriangulation(points, sequence, options, observer).release();
    }
    Triangulation out;
    const detail::Prepared prep = detail::prepare(points, sequence, options.bootstrap, out);
    FaceHashStorage storage;
    detail::run_located(prep.geometry, options, storage, observer, out);
    detail::drain_into(storage, prep.geometry, out);
    return out;
}

}  // namespace cavity::core
