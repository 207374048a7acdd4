#pragma once

#include <cstdint>

#include "cavity/core/delaunay/bowyer_watson.h"
#include "cavity/core/delaunay/walk.h"

namespace cavity::core {

/// The book's straight-line walk (Cheng, Dey & Shewchuk §5.5): from a point s inside the start
/// tetrahedron, visit the tetrahedra that the segment from s to the query point p crosses, in
/// order, until one holds p. At each tetrahedron the segment leaves through the one facet that p
/// lies strictly beyond and that the line sp passes through (the three orientations of s, an edge
/// of the facet and p agree), all decided by exact orient3d. When the line meets an edge or a
/// vertex exactly (a zero orientation on the way out, common on grids) the straight walk has no
/// unique next tetrahedron; it then finishes with the visibility walk (walk.h) from where it is,
/// and counts a fallback, so §5.5's analysis is measured on the walk it describes and the rare
/// degenerate steps are visible. s is the start tetrahedron's centroid, certified strictly inside
/// by exact orientations (a flat-ish start falls back at once).
class StraightWalk {
public:
    explicit StraightWalk(std::uint64_t seed) : fallback_(seed) {}

    /// As Walk::locate: a solid tetrahedron whose closure contains p, or a ghost whose hull
    /// triangle has p strictly in front of it.
    template <class Storage, class Observer>
    TetId locate(BowyerWatson<Storage, Observer>& engine, const Point3& p, TetId start) {
        Storage& storage = engine.storage();
        const Geometry& g = engine.geometry();
        auto& tally = engine.tally();
        // The static filter needs every point in the box: the vertices are, p and the source s
        // (rounded sums of quarters) are checked.
        bool in_box = g.in_box(p);
        const auto orient =
            [&](const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
                if constexpr (Observer::kCounting) {
                    ++tally.walk_orient_calls;
                }
                return in_box ? g.orient3d_in_box(a, b, c, d, tally)
                              : Geometry::orient3d(a, b, c, d, tally);
            };
        const TetVertices& first = storage.vertices(start);
        if (is_ghost(first)) {
            return fall_back(engine, p, start);
        }
        // Quarters are exact; the sums may round, which is harmless: s only has to be inside.
        const Point3 s{g.point(first[0]).x / 4 + g.point(first[1]).x / 4 + g.point(first[2]).x / 4 +
                           g.point(first[3]).x / 4,
                       g.point(first[0]).y / 4 + g.point(first[1]).y / 4 + g.point(first[2]).y / 4 +
                           g.point(first[3]).y / 4,
                       g.point(first[0]).z / 4 + g.point(first[1]).z / 4 + g.point(first[2]).z / 4 +
                           g.point(first[3]).z / 4};
        in_box = in_box && g.in_box(s);
        for (int f = 0; f < 4; ++f) {
            const auto tri = facet_vertices(first, f);
            if (orient(g.point(tri[0]), g.point(tri[1]), g.point(tri[2]), s) != Sign::kPos) {
                return fall_back(engine, p, start);
            }
        }
        TetId t = start;
        int entered = -1;
        for (;;) {
            if constexpr (Observer::kCounting) {
                ++tally.walk_steps;
            }
            const TetVertices& v = storage.vertices(t);
            if (is_ghost(v)) {
                return t;  // crossed the hull triangle towards p: p is strictly in front of it
            }
            int exit = -1;
            bool beyond_any = false;
            for (int f = 0; f < 4 && exit < 0; ++f) {
                if (f == entered) {
                    continue;
                }
                const auto tri = facet_vertices(v, f);
                const Point3& a = g.point(tri[0]);
                const Point3& b = g.point(tri[1]);
                const Point3& c = g.point(tri[2]);
                if (orient(a, b, c, p) != Sign::kNeg) {
                    continue;
                }
                beyond_any = true;
                const Sign ab = orient(s, a, b, p);
                if (ab == Sign::kZero || orient(s, b, c, p) != ab || orient(s, c, a, p) != ab) {
                    continue;
                }
                exit = f;
            }
            if (exit < 0) {
                // p beyond no facet: t holds it. Beyond one the line does not cleanly cross: the
                // line goes through an edge or a vertex.
                return beyond_any ? fall_back(engine, p, t) : t;
            }
            const HalfFacet across = storage.adjacent(t, exit);
            t = tet_of(across);
            entered = facet_of(across);
        }
    }

private:
    template <class Storage, class Observer>
    TetId fall_back(BowyerWatson<Storage, Observer>& engine, const Point3& p, TetId t) {
        if constexpr (Observer::kCounting) {
            ++engine.tally().walk_fallbacks;
        }
        return fallback_.locate(engine, p, t);
    }

    Walk fallback_;
};

}  // namespace cavity::core
