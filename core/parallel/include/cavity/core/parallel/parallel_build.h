#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/tetrahedron.h"

/// The parallel construction: Bowyer–Watson (§5.2) with several threads inserting at once into
/// one mesh, each locking the tetrahedra it reads (HXT's scheme, Marot, Pellerin & Remacle,
/// "One machine, one minute, three billion tetrahedra", 2019).
namespace cavity::core {

/// Where a parallel build left the triangulation.
struct ParallelBuild {
    std::array<VertexId, 4> interior;  ///< the bootstrap vertices
    TetId last_solid;                  ///< a live solid tetrahedron
    std::vector<VertexId> redundant;   ///< weighted: vertex ids in no tetrahedron, increasing
};

struct ParallelOptions {
    unsigned threads = 1;    ///< 1 to 127
    std::uint64_t seed = 0;  ///< the walks' random choices (never the result)
    /// A batch with fewer points than this per thread runs on one thread: in a small
    /// triangulation the threads' regions are a few tetrahedra apart and most attempts would
    /// collide. Tests set it low to make threads collide.
    std::size_t min_points_per_thread = 4096;
    /// Points handed back are inserted on one thread once fewer than this remain: another
    /// parallel pass over a handful of points near the threads' borders would mostly collide
    /// again.
    std::size_t lone_retry_below = 1024;
};

/// Triangulates the points of `geometry` (vertex ids are insertion ranks, the first four affinely
/// independent, no exact repeats: detail::prepare's output) into the empty `storage`.
/// \throws Error for a thread count outside 1 to 127.
///
/// The points go in in batches of doubling size along the insertion order. Each batch is cut
/// into one contiguous piece per thread (a piece of a space-filling curve is a compact region, so
/// threads rarely meet); a thread that finds a tetrahedron locked by another hands its point
/// back, and the points handed back are inserted in a further pass, on one thread once they are
/// few. Batches too small to share run on one thread.
///
/// The result does not depend on `threads`, nor on the interleaving: the symbolic perturbation
/// keyed on input index makes the Delaunay triangulation unique, every test is the sequential
/// engine's exact one, and the tetrahedra are stored in a canonical order (parallel/src/
/// canonical_order.h).
/// They are the sequential engine's tetrahedra, in another order.
ParallelBuild build_in_parallel(const Geometry& geometry,
                                const ParallelOptions& options,
                                ArrayStorage& storage);

/// What list_in_parallel leaves besides the tetrahedra.
struct ParallelList {
    std::vector<VertexId> redundant;  ///< weighted: vertex ids in no tetrahedron, increasing
    std::size_t hull_triangles = 0;
    std::size_t storage_bytes = 0;  ///< of the shared mesh at its largest
};

/// build_in_parallel for a caller that wants only the list of tetrahedra (the batch
/// triangulate()): `tets` gets the solid ones as input indices with positive right-hand volume,
/// exactly as building the storage and draining it would list them, but the storage is never
/// built, so the neighbours are never renumbered (about a third of the canonical order's cost).
ParallelList list_in_parallel(const Geometry& geometry,
                              const ParallelOptions& options,
                              std::vector<std::array<std::uint32_t, 4>>& tets);

}  // namespace cavity::core
