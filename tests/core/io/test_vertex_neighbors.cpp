// scipy's vertex_neighbor_vertices from a list of tetrahedra: each vertex's neighbours are the
// vertices it shares an edge with, increasing, and points in no tetrahedron have none.
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/io/tet_adjacency.h"

namespace cavity::core {
namespace {

TEST(VertexNeighbors, TwoTetrahedraSharingAFacet) {
    // Points 0..4, point 5 unused; tetrahedra 0123 and 1234 share the triangle 123.
    const std::vector<Tet> tets{{0, 1, 2, 3}, {1, 2, 3, 4}};
    const VertexNeighbors vn = vertex_neighbors(tets, 6);
    const std::vector<std::int32_t> indptr{0, 3, 7, 11, 15, 18, 18};
    const std::vector<std::int32_t> indices{1, 2, 3, 0, 2, 3, 4, 0, 1, 3, 4, 0, 1, 2, 4, 1, 2, 3};
    EXPECT_EQ(vn.indptr, indptr);
    EXPECT_EQ(vn.indices, indices);
}

TEST(VertexNeighbors, EveryEdgeTwiceOnAFan) {
    // A fan of tetrahedra around the edge 0-1: the ring 2..7 closes up.
    std::vector<Tet> tets;
    for (std::uint32_t k = 0; k < 6; ++k) {
        tets.push_back({0, 1, 2 + k, 2 + (k + 1) % 6});
    }
    const VertexNeighbors vn = vertex_neighbors(tets, 8);
    std::set<std::pair<std::int32_t, std::int32_t>> edges;
    for (std::int32_t v = 0; v < 8; ++v) {
        for (std::int32_t k = vn.indptr[static_cast<std::size_t>(v)];
             k < vn.indptr[static_cast<std::size_t>(v) + 1];
             ++k) {
            edges.insert({v, vn.indices[static_cast<std::size_t>(k)]});
        }
    }
    EXPECT_EQ(edges.size(), vn.indices.size());       // no repeats
    EXPECT_EQ(vn.indices.size(), 2u * (1 + 12 + 6));  // 0-1, the 12 spokes, the 6 ring edges
    for (const auto& [a, b] : edges) {
        EXPECT_TRUE(edges.count({b, a})) << a << "-" << b;
    }
}

}  // namespace
}  // namespace cavity::core
