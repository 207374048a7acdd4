#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "cavity/core/base/error.h"
#include "cavity/core/delaunay/bowyer_watson.h"
#include "cavity/core/delaunay/stochastic_walk.h"

namespace cavity::core {

/// Point location by a conflict graph (Cheng, Dey & Shewchuk §5.4, §3.6). Every uninserted point
/// records one cell that contains it; every cell lists the uninserted points that chose it. Cells
/// are the solid tetrahedra and, outside the hull, ghost regions: the unbounded convex region over
/// a hull triangle bounded by the rays from a fixed interior point O through the triangle's
/// vertices. When a vertex is inserted, the points of the cells it deleted are redistributed to the
/// new cells, each by a walk that starts at a new cell built on a face of its old cell (the
/// "CG-1" variant: one containing cell per point).
///
/// The ghost region of ghost tetrahedron (v0, v1, v2, g) is the tetrahedron (v0, v1, v2, O) with
/// its facets through O extended to infinity: p is inside when it is on or in front of the hull
/// triangle and on the inner side of the three planes through O and a hull edge. O is inside the
/// bootstrap tetrahedron, so inside every later hull, and the regions and solid tetrahedra always
/// partition space; a cavity's cells and the new cells cover the same region.
class ConflictGraph {
public:
    /// Locates every point after the bootstrap four in the first five cells.
    template <class Storage, class Observer>
    void start(BowyerWatson<Storage, Observer>& engine) {
        engine.record_cavity_faces();
        const Geometry& geometry = engine.geometry();
        choose_interior_point(engine);
        const std::size_t n = geometry.size();
        cell_of_.assign(n, kNoTet);
        next_.assign(n, kNoVertex);
        head_.assign(engine.storage().capacity(), kNoVertex);
        for (VertexId p = 4; p < n; ++p) {
            Uncounted initial;  // the initial attachment is not a redistribution
            attach(p, walk_cells(engine, p, engine.last_solid(), initial));
        }
    }

    /// The cell holding u: its closure contains u.
    template <class Engine>
    TetId locate(Engine&, VertexId u) const {
        return cell_of_[u];
    }

    /// u was not inserted (redundant): it no longer takes part. Its list entry is dropped lazily.
    template <class Engine>
    void skip(Engine&, VertexId u) {
        cell_of_[u] = kNoTet;
    }

    /// Redistributes the points of the cells the insertion of u deleted.
    template <class Storage, class Observer>
    void after_insertion(BowyerWatson<Storage, Observer>& engine, VertexId u) {
        cell_of_[u] = kNoTet;
        if (head_.size() < engine.storage().capacity()) {
            head_.resize(engine.storage().capacity(), kNoVertex);
        }
        // Where to start each walk: a new cell built on a face of the old cell, when there is one.
        start_of_old_.clear();
        for (const CavityFace& face : engine.cavity_faces()) {
            start_of_old_.emplace_back(face.inner, face.created);
        }
        std::sort(start_of_old_.begin(), start_of_old_.end());
        const TetId fallback = engine.created().front();
        for (TetId old_cell : engine.deleted()) {
            const auto hit = std::lower_bound(
                start_of_old_.begin(), start_of_old_.end(), std::pair<TetId, TetId>{old_cell, 0});
            const TetId start =
                hit != start_of_old_.end() && hit->first == old_cell ? hit->second : fallback;
            VertexId p = head_[old_cell];
            head_[old_cell] = kNoVertex;
            while (p != kNoVertex) {
                const VertexId following = next_[p];
                if (cell_of_[p] == old_cell) {  // skips inserted and redundant points
                    if constexpr (Observer::kCounting) {
                        ++engine.tally().points_redistributed;
                    }
                    attach(p, walk_cells(engine, p, start, engine.tally()));
                }
                p = following;
            }
        }
    }

private:
    void attach(VertexId p, TetId cell) {
        cell_of_[p] = cell;
        next_[p] = head_[cell];
        head_[cell] = p;
    }

    template <class Storage, class Observer>
    void choose_interior_point(BowyerWatson<Storage, Observer>& engine) {
        const Geometry& g = engine.geometry();
        const auto& b = engine.bootstrap_vertices();
        const Point3& a0 = g.point(b[0]);
        const Point3& a1 = g.point(b[1]);
        const Point3& a2 = g.point(b[2]);
        const Point3& a3 = g.point(b[3]);
        // Candidates: the centroid, then points pulled towards each vertex. Each is computed in
        // floating point and then certified strictly inside by exact orientations; a quarter and an
        // eighth are exact scalings, so no candidate overflows.
        const auto combo = [](const Point3& p,
                              const Point3& q,
                              const Point3& r,
                              const Point3& s,
                              double wp,
                              double wq) {
            const double wr = (1.0 - wp - wq) / 2.0;
            return Point3{wp * p.x + wq * q.x + wr * r.x + wr * s.x,
                          wp * p.y + wq * q.y + wr * r.y + wr * s.y,
                          wp * p.z + wq * q.z + wr * r.z + wr * s.z};
        };
        const std::array<Point3, 5> candidates{combo(a0, a1, a2, a3, 0.25, 0.25),
                                               combo(a0, a1, a2, a3, 0.625, 0.125),
                                               combo(a1, a0, a2, a3, 0.625, 0.125),
                                               combo(a2, a0, a1, a3, 0.625, 0.125),
                                               combo(a3, a0, a1, a2, 0.625, 0.125)};
        for (const Point3& o : candidates) {
            bool inside = true;
            for (int f = 0; f < 4 && inside; ++f) {
                const auto tri = facet_vertices(b, f);
                inside = Geometry::orient3d(g.point(tri[0]), g.point(tri[1]), g.point(tri[2]), o) ==
                         Sign::kPos;
            }
            if (inside) {
                interior_ = o;
                return;
            }
        }
        throw Error(
            "conflict graph: no point strictly inside the bootstrap tetrahedron is representable "
            "(the tetrahedron is too thin); use walking point location");
    }

    /// The remembering stochastic walk over cells (solid tetrahedra and ghost regions).
    template <class Storage, class Observer, Tally T>
    TetId walk_cells(BowyerWatson<Storage, Observer>& engine, VertexId p, TetId t, T& tally) {
        const Geometry& g = engine.geometry();
        const Point3& q = g.point(p);
        return stochastic_walk(
            engine.storage(),
            t,
            random_,
            [&](TetId, const TetVertices&) {
                if constexpr (T::kCounting) {
                    ++tally.redistribution_steps;
                }
                return false;
            },
            [&](TetId, const TetVertices& v, int f, int entered) {
                if (f == entered) {
                    return false;
                }
                const auto tri = facet_vertices(v, f);
                if (!is_ghost(v) || f == 3) {
                    return Geometry::orient3d(
                               g.point(tri[0]), g.point(tri[1]), g.point(tri[2]), q, tally) ==
                           Sign::kNeg;
                }
                // A ghost facet through g: the plane through O and the hull edge. The region lies
                // on the side of that plane where O's tetrahedron (v0, v1, v2, O) has its vertex
                // v_f, which is the negative side because O is behind the hull triangle.
                const auto at = [&](VertexId w) -> const Point3& {
                    return w == kGhostVertex ? interior_ : g.point(w);
                };
                return Geometry::orient3d(at(tri[0]), at(tri[1]), at(tri[2]), q, tally) ==
                       Sign::kPos;
            });
    }

    Point3 interior_{};
    std::vector<TetId> cell_of_;
    std::vector<VertexId> next_;
    std::vector<VertexId> head_;
    std::vector<std::pair<TetId, TetId>> start_of_old_;
    WalkRandom random_{0x2545'F491'4F6C'DD1Dull};
};

}  // namespace cavity::core
