// The bootstrap rules: kFirst takes the first four affinely independent points of the sequence, so
// that a uniform order stays uniform (the identities of §5.3 need it); kWidest may reach further.

#include <numeric>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"

namespace cavity::core {
namespace {

std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> s(n);
    std::iota(s.begin(), s.end(), 0u);
    return s;
}

TEST(Bootstrap, FirstSkipsRepeatsCollinearAndCoplanarPointsInOrder) {
    // A repeat of point 0, a point on the line of 0 and 2, a point in the plane of 0, 2 and 4.
    const std::vector<Point3> points = {
        {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {5, 5, 5}};
    const auto boot = find_bootstrap(points, identity(points.size()), BootstrapRule::kFirst);
    EXPECT_EQ(boot, (std::array<std::size_t, 4>{0, 2, 4, 6}));
}

TEST(Bootstrap, RulesParseByName) {
    EXPECT_EQ(parse_bootstrap_rule("first"), BootstrapRule::kFirst);
    EXPECT_EQ(parse_bootstrap_rule("widest"), BootstrapRule::kWidest);
    EXPECT_THROW(parse_bootstrap_rule("random"), Error);
}

/// The input indices in the order the engine inserted them, the bootstrap four first.
struct InsertedOrder : CountingObserver {
    void on_start(const Geometry& g) {
        for (VertexId v = 0; v < 4; ++v) {
            order.push_back(g.key(v));
        }
    }

    void on_insertion(const InsertionRecord& r) { order.push_back(r.vertex); }

    std::vector<std::uint32_t> order;
};

std::vector<std::uint32_t> inserted(const PointSet& points,
                                    std::span<const std::uint32_t> sequence,
                                    BootstrapRule rule) {
    TriangulateOptions options;
    options.bootstrap = rule;
    InsertedOrder observer;
    triangulate_observed(points, sequence, options, observer);
    return observer.order;
}

// In general position the engine inserts exactly the permutation under kFirst; kWidest moves a
// wider triangle and a higher fourth point to the front.
TEST(Bootstrap, FirstKeepsAUniformOrderAsItIs) {
    const PointSet points = generate_points("cube", 500, 4);
    OrderOptions order;
    order.kind = OrderKind::kRandom;
    std::size_t moved = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        order.seed = seed;
        const InsertionOrder sequence = make_insertion_order(points.points, order);
        EXPECT_EQ(inserted(points, sequence.sequence, BootstrapRule::kFirst), sequence.sequence);
        moved += inserted(points, sequence.sequence, BootstrapRule::kWidest) != sequence.sequence;
    }
    EXPECT_GT(moved, 15u);
}

}  // namespace
}  // namespace cavity::core
