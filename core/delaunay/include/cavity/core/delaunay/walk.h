#pragma once

#include <cstdint>

#include "cavity/core/delaunay/bowyer_watson.h"
#include "cavity/core/delaunay/stochastic_walk.h"

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
    explicit Walk(std::uint64_t seed) : random_(seed | 1u) {}

    /// Returns a solid tetrahedron whose closure contains the point, or a ghost tetrahedron whose
    /// hull triangle has the point strictly in front of it.
    /// Inlined into the insertion loop with the walk (stochastic_walk.h): GCC's choice depends on
    /// what else the translation unit instantiates, and it left the counting engine's out of line
    /// (1.3% of its instructions on a 2*10^5 cube).
    template <class Storage, class Observer>
    [[gnu::always_inline]] TetId locate(BowyerWatson<Storage, Observer>& engine,
                                        const Point3& p,
                                        TetId start) {
        const Geometry& geometry = engine.geometry();
        auto& tally = engine.tally();
        // Inserted points are in the box; a query of the live triangulation may not be.
        const bool in_box = geometry.in_box(p);
        // The counting engine counts steps and tests here and adds them to the totals once per
        // walk: the totals are behind a reference the tests' stage counts also write, so an
        // increment there was a load and a store per step.
        std::uint64_t steps = 0;
        std::uint64_t orient_calls = 0;
        const TetId found = stochastic_walk(
            engine.storage(),
            start,
            random_,
            [&](TetId, const TetVertices& v) {
                if constexpr (Observer::kCounting) {
                    ++steps;
                }
                return is_ghost(v);  // entered through the hull triangle with p strictly in front
            },
            [&](TetId, const TetVertices& v, int f, int entered) {
                if (f == entered) {
                    return false;
                }
                if constexpr (Observer::kCounting) {
                    ++orient_calls;
                }
                const auto tri = facet_vertices(v, f);
                const Point3& a = geometry.point(tri[0]);
                const Point3& b = geometry.point(tri[1]);
                const Point3& c = geometry.point(tri[2]);
                return (in_box ? geometry.orient3d_in_box(a, b, c, p, tally)
                               : Geometry::orient3d(a, b, c, p, tally)) == Sign::kNeg;
            });
        if constexpr (Observer::kCounting) {
            tally.walk_steps += steps;
            tally.walk_orient_calls += orient_calls;
        }
        return found;
    }

private:
    WalkRandom random_;
};

}  // namespace cavity::core
