#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/order/insertion_order.h"

namespace cavity::core {
namespace {

using Tet = std::array<std::uint32_t, 4>;

// The complex rebuilt from a bare list (the validators' and the files' path) has the engine's
// own adjacency: every facet glued to the same neighbour, and a valid complex with ghosts.
TEST(ComplexFromTets, GluesAsTheEngineDid) {
    for (const char* dist : {"cube", "grid", "sphere"}) {
        const PointSet points = generate_points(dist, 300, 5);
        const InsertionOrder order = make_insertion_order(points.points, {});
        DelaunayTriangulation dt(points, order.sequence, {});
        const std::vector<Tet> tets = dt.tets();
        const ArrayStorage rebuilt = complex_from_tets(tets);
        EXPECT_TRUE(check_complex(rebuilt, geometry_by_index(points)).empty()) << dist;
        // Neighbours by vertex sets, both ways.
        const auto neighbours = [](const ArrayStorage& s, auto key_of) {
            std::vector<std::pair<std::array<std::uint32_t, 4>, std::array<std::uint32_t, 4>>> out;
            for (TetId t = 0; t < s.capacity(); ++t) {
                if (!s.alive(t) || is_ghost(s.vertices(t))) {
                    continue;
                }
                for (int f = 0; f < 4; ++f) {
                    const TetVertices& w = s.vertices(tet_of(s.adjacent(t, f)));
                    out.emplace_back(key_of(s.vertices(t)), key_of(w));
                }
            }
            std::sort(out.begin(), out.end());
            return out;
        };
        const Geometry& g = dt.geometry();
        const auto by_key = [&](const TetVertices& v) {
            std::array<std::uint32_t, 4> k{};
            for (std::size_t i = 0; i < 4; ++i) {
                k[i] = v[i] == kGhostVertex ? kGhostVertex : g.key(v[i]);
            }
            std::sort(k.begin(), k.end());
            return k;
        };
        const auto as_is = [](const TetVertices& v) {
            std::array<std::uint32_t, 4> k = v;
            std::sort(k.begin(), k.end());
            return k;
        };
        EXPECT_EQ(neighbours(rebuilt, as_is), neighbours(dt.storage(), by_key)) << dist;
    }
}

TEST(ComplexFromTets, RefusesATriangleOfThreeTetrahedraAndARepeatedOne) {
    // Three tetrahedra on triangle 0 1 2.
    const std::vector<Tet> three{{0, 1, 2, 3}, {1, 0, 2, 4}, {1, 0, 2, 5}};
    EXPECT_THROW(complex_from_tets(three), Error);
    const std::vector<Tet> repeated{{0, 1, 2, 3}, {0, 1, 2, 3}};
    EXPECT_THROW(complex_from_tets(repeated), Error);
}

}  // namespace
}  // namespace cavity::core
