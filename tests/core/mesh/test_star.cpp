// The star of a vertex by breadth-first search across the facets around it (star.h): the early
// stop that edge protection's "is pq an edge?" uses must see the tetrahedra in the plain search's
// order and give up exactly when some tetrahedron of the star answers.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {
namespace {

TEST(VertexStar, StopsAtTheFirstTetrahedronThatAnswersInSearchOrder) {
    for (const char* distribution : {"cube", "grid"}) {
        const PointSet ps = generate_points(distribution, 60, 5);
        const ArrayStorage storage = complex_from_tets(test::triangulate_in_input_order(ps).tets);
        const auto by_list = [](const std::vector<TetId>& star, TetId t) {
            return std::find(star.begin(), star.end(), t) == star.end();
        };
        for (VertexId v = 0; v < ps.size(); ++v) {
            const std::vector<TetId> star = vertex_star(storage, v);
            ASSERT_FALSE(star.empty());
            std::vector<TetId> found;
            for (VertexId w = 0; w < ps.size(); ++w) {
                std::vector<TetId> asked;
                const auto holds_w = [&](TetId t) {
                    asked.push_back(t);
                    const TetVertices& x = storage.vertices(t);
                    return std::find(x.begin(), x.end(), w) != x.end();
                };
                const bool whole = vertex_star_into(storage, v, by_list, holds_w, found);
                const auto first = std::find_if(star.begin(), star.end(), [&](TetId t) {
                    const TetVertices& x = storage.vertices(t);
                    return std::find(x.begin(), x.end(), w) != x.end();
                });
                if (first == star.end()) {
                    ASSERT_TRUE(whole) << v << " " << w;
                    EXPECT_EQ(found, star);
                    EXPECT_EQ(asked, star);
                } else {
                    EXPECT_FALSE(whole) << v << " " << w;
                    EXPECT_EQ(asked, std::vector<TetId>(star.begin(), first + 1));
                }
            }
        }
    }
}

}  // namespace
}  // namespace cavity::core
