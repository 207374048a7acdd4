// Exact point location in the exported adjacency (scipy's find_simplex): the answer is the
// lowest-numbered simplex whose closure holds the point, as a scan of every simplex with exact
// orientation tests finds it, from whatever simplex the walk starts.
#include <array>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/random.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/io/tet_adjacency.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/live/simplex_location.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {
namespace {

using predicates::Sign;

/// The oracle: a scan of every simplex.
std::int32_t lowest_by_scan(const PointSet& ps, const Adjacency& a, const Point3& p) {
    for (std::size_t t = 0; t < a.simplices.size(); ++t) {
        bool holds = true;
        for (std::size_t i = 0; i < 4 && holds; ++i) {
            std::array<Point3, 4> q{};
            for (std::size_t k = 0; k < 4; ++k) {
                q[k] = k == i ? p : ps.points[a.simplices[t][k]];
            }
            holds = predicates::orient3d(q[0], q[1], q[2], q[3]) != Sign::kPos;
        }
        if (holds) {
            return static_cast<std::int32_t>(t);
        }
    }
    return -1;
}

Adjacency built(const PointSet& ps) {
    const InsertionOrder order = make_insertion_order(ps.points, OrderOptions{});
    return DelaunayTriangulation(ps, order.sequence, TriangulateOptions{}).adjacency();
}

/// Queries inside and outside the hull, on vertices, and, on the lattice, on shared edges and
/// facets (midpoints and centres of lattice points are exact doubles).
std::vector<Point3> queries(const PointSet& ps, std::uint64_t seed) {
    Random rng(seed);
    std::vector<Point3> out(ps.points.begin(), ps.points.begin() + 40);
    for (int i = 0; i < 300; ++i) {
        const Point3& a = ps.points[rng.below(ps.size())];
        const Point3& b = ps.points[rng.below(ps.size())];
        out.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2});
        out.push_back({a.x * 1.3 - 0.1, b.y * 1.2, (a.z + b.z) * 0.7});
    }
    return out;
}

TEST(SimplexLocator, FindsTheLowestSimplexHoldingThePointFromAnyStart) {
    for (const char* dist : {"cube", "grid", "sphere"}) {
        const PointSet ps = generate_points(dist, 343, 5);
        const Adjacency a = built(ps);
        const SimplexLocator locator(ps.points, a.simplices, a.neighbors);
        int outside = 0;
        for (const Point3& p : queries(ps, 9)) {
            const std::int32_t expected = lowest_by_scan(ps, a, p);
            outside += expected < 0;
            for (std::int32_t start :
                 {0, 17, static_cast<std::int32_t>(a.simplices.size()) - 1, -5}) {
                EXPECT_EQ(locator.find(p, start), expected)
                    << dist << " (" << p.x << ", " << p.y << ", " << p.z << ") from " << start;
            }
        }
        EXPECT_GT(outside, 0) << dist;
    }
}

TEST(SimplexLocator, NothingToFindInAnEmptyTriangulation) {
    const std::vector<Point3> points{{0, 0, 0}};
    const SimplexLocator locator(points, {}, {});
    EXPECT_EQ(locator.find({0, 0, 0}, 0), -1);
}

}  // namespace
}  // namespace cavity::core
