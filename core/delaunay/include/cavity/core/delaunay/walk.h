#pragma once

#include <cstdint>

#include "cavity/core/delaunay/bowyer_watson.h"

namespace cavity::core {

/// Walking point location (Cheng, Dey & Shewchuk §5.5): from a start tetrahedron, repeatedly step
/// into the neighbour across a facet that separates the current tetrahedron from the query point.
/// This is the visibility walk with two safeguards that make it terminate on every triangulation,
/// degenerate input included (Devillers, Pion & Teillaud, "Walking in a triangulation"): it never
/// re-tests the facet it came through ("remembering"), and it tests the other facets starting at a
/// pseudo-random one ("stochastic"), from a generator with explicit state so runs are repeatable.
/// The exact, unperturbed orient3d decides; a point on a facet counts as inside (closed cells).
class Walk {
public:
    explicit Walk(std::uint64_t seed) : state_(seed | 1u) {}

    /// Returns a solid tetrahedron whose closure contains the point, or a ghost tetrahedron whose
    /// hull triangle has the point strictly in front of it.
    template <class Storage, class Observer>
    TetId locate(BowyerWatson<Storage, Observer>& engine, const Point3& p, TetId start) {
        Storage& storage = engine.storage();
        const Geometry& geometry = engine.geometry();
        Counters* counters = engine.counters();
        TetId t = start;
        int entered = -1;  // the facet we came in through
        for (;;) {
            if constexpr (Observer::kCounting) {
                ++counters->walk_steps;
            }
            const TetVertices& v = storage.vertices(t);
            if (is_ghost(v)) {
                return t;  // entered through the hull triangle with p strictly in front
            }
            const int first = next_random();
            int exit = -1;
            for (int k = 0; k < 4; ++k) {
                const int f = (first + k) & 3;
                if (f == entered) {
                    continue;
                }
                const auto tri = facet_vertices(v, f);
                if constexpr (Observer::kCounting) {
                    ++counters->walk_orient_calls;
                }
                if (Geometry::orient3d(geometry.point(tri[0]),
                                       geometry.point(tri[1]),
                                       geometry.point(tri[2]),
                                       p,
                                       counters) == Sign::kNeg) {
                    exit = f;
                    break;
                }
            }
            if (exit < 0) {
                return t;
            }
            const HalfFacet across = storage.adjacent(t, exit);
            t = tet_of(across);
            entered = facet_of(across);
        }
    }

private:
    int next_random() {
        // xorshift64: cheap, and good enough to break the cycles a deterministic visiting order
        // can fall into.
        state_ ^= state_ << 13;
        state_ ^= state_ >> 7;
        state_ ^= state_ << 17;
        return static_cast<int>(state_ & 3u);
    }

    std::uint64_t state_;
};

}  // namespace cavity::core
