#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/delaunay/insertion_driver.h"
#include "cavity/core/delaunay/triangulate.h"
#include "cavity/core/delaunay/walk.h"
#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/mesh/array_storage.h"

/// The live (weighted) Delaunay triangulation: one object that owns the points, with their input
/// indices (the perturbation keys), and the tetrahedra with their adjacency, and keeps them
/// between operations, as CGAL's Delaunay_triangulation_3 and HXT's mesh do. It is built by the
/// same driver loop as triangulate() (delaunay/insertion_driver.h); afterwards points can be
/// inserted (Bowyer–Watson, §5.2) and removed (gift-wrapping, §5.6), located by the walk (§5.5),
/// flipped, checked and read without rebuilding anything.
namespace cavity::core {

/// How much DelaunayTriangulation::check verifies.
enum class CheckLevel {
    /// The stored complex (check_complex): adjacency symmetric, every facet glued, solid
    /// tetrahedra positively oriented, the hull locally convex. Linear time.
    kComplex,
    /// kComplex, then the independent validator (validate.h) on the solid tetrahedra: the exact
    /// perturbed Delaunay property of every facet and the account of every point.
    kDelaunay,
};

class DelaunayTriangulation {
public:
    /// Triangulates `points` in the order `sequence` exactly as triangulate() does (same checks,
    /// same errors, same tetrahedra), and keeps the result live. options.storage must be kArray
    /// (the hash storage is for the batch triangulate()); with options.prefix only the first
    /// points are vertices. With options.threads, the parallel construction builds it
    /// (parallel/parallel_build.h): the same tetrahedra, in a canonical order.
    DelaunayTriangulation(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options);

    /// As above, reporting the build to `observer` (delaunay/observer.h). Counters are read from
    /// the observer when Observer::kCounting.
    template <class Observer>
    DelaunayTriangulation(const PointSet& points,
                          std::span<const std::uint32_t> sequence,
                          const TriangulateOptions& options,
                          Observer& observer);

    DelaunayTriangulation(DelaunayTriangulation&&) noexcept;
    DelaunayTriangulation& operator=(DelaunayTriangulation&&) noexcept;
    ~DelaunayTriangulation();

    /// Input indices handed out so far: the input points, then one per insert().
    std::size_t point_count() const;
    std::size_t tet_count() const;  ///< solid tetrahedra
    std::size_t hull_triangle_count() const;
    bool weighted() const;

    /// Inserts a new point (with `weight` when weighted; ignored otherwise) and returns its input
    /// index, point_count() before the call. A repeat of a vertex becomes a duplicate and a
    /// submerged weighted point is redundant, as in triangulate(). Insertion assumes the
    /// triangulation is Delaunay: after flips, check(CheckLevel::kDelaunay) first.
    /// \throws Error for a non-finite coordinate or weight (nothing changes).
    std::uint32_t insert(const Point3& p, double weight = 0.0);

    /// Inserts a point given exactly by its definition (generic_point.h: an implicit point, as the
    /// CDT's edge protection makes; unweighted triangulations only) and returns its input index,
    /// point_count() before the call. `rounded` is its coordinates rounded to doubles, where the
    /// walk looks for it; every exact decision reads the definition. The first implicit point
    /// turns the triangulation's tests to the generic predicates. An implicit point never repeats
    /// a vertex (as in triangulate()). `near`, as CGAL's hint cell: a live tetrahedron near p
    /// where the walk that locates p starts (a point far from the last insertion is otherwise
    /// walked to across the mesh); kNoTet, a dead or a ghost tetrahedron start it at the last
    /// tetrahedron made. It changes no tetrahedron of the result. \throws Error for a weighted
    /// triangulation or a non-finite rounding (nothing changes).
    std::uint32_t insert(const predicates::GenericPoint3& p,
                         const Point3& rounded,
                         TetId near = kNoTet);

    /// Inserts every point of `batch` (with its weight when weighted), giving row r the input
    /// index point_count() + r, in the order `sequence` (a permutation of the rows: a
    /// space-filling curve keeps the walks short). The result is the one of inserting the rows
    /// one by one in row order: a repeat inside the batch is never inserted and lists the lowest
    /// equal row's fate as what it repeats. Returns the first new index. \throws Error, before
    /// anything changes, for a non-finite coordinate or weight (naming the point as its new
    /// index), a sequence that is not a permutation, or missing weights.
    std::uint32_t insert(const PointSet& batch, std::span<const std::uint32_t> sequence);

    /// A solid tetrahedron whose closure contains p, or a ghost whose hull triangle has p strictly
    /// in front of it (p outside the hull): by the exact visibility walk from the last tetrahedron
    /// created.
    TetId locate(const Point3& p) const;

    /// Removes the points `ids` (input indices), one by one, by gift-wrapping their cavities
    /// (edit/vertex_deletion.h); deleting a duplicate or redundant point only updates those lists.
    /// The result is the Delaunay triangulation of the remaining points. Every id is checked
    /// before anything changes. \throws Error for an index out of range, repeated, already
    /// removed or never inserted, for a vertex whose exact duplicate is kept (its copy would need
    /// inserting: remove the copies too), and when the rest would not span 3D.
    void remove(std::span<const std::uint32_t> ids);

    /// Bistellar flips (edit/flips.h) on the live complex; empty and unchanged when refused. The
    /// result is a triangulation, not necessarily Delaunay.
    std::vector<TetId> flip23(HalfFacet h);
    std::vector<TetId> flip32(TetId t, int i, int j);

    /// The problems found at `level` (empty: valid).
    std::vector<std::string> check(CheckLevel level) const;

    /// \throws Error for options the live triangulation cannot build with: the hash storage, or
    /// threads with counters (`counting`), a locator other than the walk, or a prefix.
    static void require_supported(const TriangulateOptions& options, bool counting);

    /// Solid tetrahedra as input indices with positive right-hand volume, in storage order.
    std::vector<std::array<std::uint32_t, 4>> tets() const;

    /// scipy's and TetGen's views (io/tet_adjacency.h), read off the live adjacency in linear time
    /// (no facet matching): simplices in storage order, which the space-filling insertion order
    /// makes mostly local (tetrahedra near in space near in the array).
    Adjacency adjacency() const;

    /// {point, the vertex it repeats}, input indices.
    const std::vector<std::array<std::uint32_t, 2>>& duplicates() const;
    /// Weighted: submerged points, input indices, increasing.
    std::vector<std::uint32_t> redundant() const;
    /// The build's counters (TriangulateOptions::count); later operations are not counted here.
    const Counters& counters() const;
    /// The work of every removal and flip since the build (edit/retriangulation_counters.h).
    const RetriangulationCounters& edit_counters() const;

    /// The engine's view: vertex ids are insertion ranks, geometry().key(v) the input index.
    const Geometry& geometry() const;
    const ArrayStorage& storage() const;

    /// Hands out the tetrahedra as triangulate() does, emptying the storage as it copies (no
    /// second copy at the peak).
    Triangulation release() &&;

    /// The storage with every vertex renamed to its input index (ids of points inserted later
    /// follow the input's): the form of complexes on a geometry by index (complex_from_tets,
    /// the CDT), without matching a facet.
    ArrayStorage release_by_index() &&;

private:
    /// Everything on the heap, so that the engine's references into it survive moves.
    struct State {
        State(Geometry points, const PointSet& input, std::uint64_t seed);

        Geometry geometry;
        ArrayStorage storage;
        NullObserver observer;
        /// The engine of insert(), made at the first insertion (the build's engine was the
        /// driver's, typed on its observer).
        std::optional<BowyerWatson<ArrayStorage, NullObserver>> engine;
        std::array<VertexId, 4> interior{};  ///< four affinely independent vertices
        TetId last_solid = kNoTet;           ///< where walks start
        mutable Walk walk;                   // its random stream is not observable state
        std::uint32_t next_key;
        int index_base;  ///< how messages number points, as the input did
        std::vector<std::array<std::uint32_t, 2>> duplicates;
        std::vector<VertexId> submerged;
        std::vector<bool> removed;  ///< by input index
        /// By input index: its vertex id, or kNoVertex (a repeat). Made by the first removal.
        std::vector<VertexId> vertex_of;
        Counters counters;
        RetriangulationCounters edits;
        std::vector<TetId> scratch;
    };

    void adopt(const detail::RunEnd& end, Triangulation& built);
    /// The parallel construction (options.threads) into the state's storage.
    detail::RunEnd build_in_threads(const TriangulateOptions& options, Triangulation& built);
    static BowyerWatson<ArrayStorage, NullObserver>& engine(State& s);
    /// A live solid tetrahedron: the last one created when it still is.
    TetId start_tet() const;
    /// By vertex id: whether it is a vertex of a live tetrahedron (one pass over the storage).
    std::vector<bool> vertex_flags() const;
    void restart_after_edit();
    /// Inserts p as input index `key` (already handed out), located from start_near(near);
    /// returns `key`, or the index of the vertex it repeats.
    std::uint32_t insert_keyed(const Point3& p, double weight, std::uint32_t key, TetId near);
    /// Inserts vertex u, already appended to the geometry with key `key`, located from
    /// start_near(near); returns as insert_keyed.
    std::uint32_t insert_appended(VertexId u, std::uint32_t key, TetId near);
    /// near when it is a live solid tetrahedron, else start_tet().
    TetId start_near(TetId near) const;
    /// Hands out the next input index (next_key) to a single inserted point: not removed, and
    /// no vertex yet in the key-to-vertex map when there is one.
    void hand_out_index();

    std::unique_ptr<State> state_;
};

template <class Observer>
DelaunayTriangulation::DelaunayTriangulation(const PointSet& points,
                                             std::span<const std::uint32_t> sequence,
                                             const TriangulateOptions& options,
                                             Observer& observer) {
    require_supported(options, Observer::kCounting);
    Triangulation built;
    detail::Prepared prep =
        detail::prepare(points, sequence, options.bootstrap, built, options.threads);
    state_ = std::make_unique<State>(std::move(prep.geometry), points, options.seed);
    const detail::RunEnd end =
        options.threads > 0
            ? build_in_threads(options, built)
            : detail::run_located(state_->geometry, options, state_->storage, observer, built);
    adopt(end, built);
}

}  // namespace cavity::core
