#include <algorithm>
#include <cstddef>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "../../../core/cdt/src/box_grid.h"
#include "cavity/core/base/random.h"

namespace cavity::core {
namespace {

Box box_of(double x0, double y0, double z0, double x1, double y1, double z1) {
    Box b;
    b.add(Point3{x0, y0, z0});
    b.add(Point3{x1, y1, z1});
    return b;
}

double uniform(Random& random) {
    return static_cast<double>(random.below(1u << 20)) / (1u << 20);
}

Box random_box(Random& random, double size) {
    const double x = uniform(random);
    const double y = uniform(random);
    const double z = uniform(random);
    return box_of(x,
                  y,
                  z,
                  x + size * uniform(random),
                  y + size * uniform(random),
                  z + size * uniform(random));
}

// Every item whose closed box meets the query's is returned, once: small and long items mixed
// (long ones land on coarse levels), queries of every size, and boxes meeting at a corner only.
TEST(BoxGrid, ReturnsEveryItemItsQueryMeetsOnce) {
    Random random(5);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Box> boxes;
        const std::size_t n = 1 + random.below(3000);
        for (std::size_t i = 0; i < n; ++i) {
            boxes.push_back(random_box(random, i % 10 == 0 ? 1.0 : 0.02));
        }
        boxes.push_back(box_of(0.5, 0.5, 0.5, 0.6, 0.6, 0.6));
        Box bounds;
        for (const Box& b : boxes) {
            bounds.add(Point3{b.lo[0], b.lo[1], b.lo[2]});
            bounds.add(Point3{b.hi[0], b.hi[1], b.hi[2]});
        }
        BoxGrid grid(bounds, boxes);
        std::vector<std::size_t> near;
        for (std::size_t q = 0; q < 200; ++q) {
            const Box query = q == 0 ? box_of(0.6, 0.6, 0.6, 0.7, 0.7, 0.7)
                                     : random_box(random, q % 4 == 0 ? 0.5 : 0.01);
            grid.near(query, q, near);
            const std::set<std::size_t> unique(near.begin(), near.end());
            ASSERT_EQ(unique.size(), near.size()) << "an item returned twice, query " << q;
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                if (query.meets(boxes[i])) {
                    ASSERT_TRUE(unique.contains(i)) << "item " << i << " missed by query " << q;
                }
            }
        }
    }
}

// Long items in one corner of the bounds are not returned to a query in the opposite corner: a
// single grid handed every item over 64 cells to every query, which made checking the CDT of a
// surface mesh (slivers spanning its interior) quadratic.
TEST(BoxGrid, KeepsLongItemsAwayFromFarQueries) {
    Random random(6);
    std::vector<Box> boxes;
    for (int i = 0; i < 4000; ++i) {
        boxes.push_back(random_box(random, 0.01));
    }
    for (int i = 0; i < 500; ++i) {
        const double d = 0.01 * uniform(random);
        boxes.push_back(box_of(d, d, d, 0.3 + d, 0.3 + d, 0.3 + d));
    }
    Box bounds = box_of(0, 0, 0, 1.01, 1.01, 1.01);
    BoxGrid grid(bounds, boxes);
    const std::vector<std::size_t> near = grid.near(box_of(0.9, 0.9, 0.9, 0.91, 0.91, 0.91), 0);
    EXPECT_LT(near.size(), 100u);
    EXPECT_TRUE(std::none_of(near.begin(), near.end(), [](std::size_t i) { return i >= 4000; }));
}

}  // namespace
}  // namespace cavity::core
