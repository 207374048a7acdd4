// The two storages behind the chapter's interface (Figure 5.1): AddTetrahedron, DeleteTetrahedron,
// Adjacent, Adjacent2Vertex.

#include <map>

#include <gtest/gtest.h>

#include "cavity/core/base/random.h"
#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/face_hash_storage.h"

namespace cavity::test {
namespace {

using core::FaceHashStorage;
using core::TetVertices;

TEST(FaceHashStorage, AdjacentFindsTheTetrahedronAcrossEachFace) {
    FaceHashStorage s;
    // Two tetrahedra sharing the face (0, 1, 2): 0123 and 0214 (both even orderings around it).
    const auto a = s.add_tetrahedron({0, 1, 2, 3});
    const auto b = s.add_tetrahedron({0, 2, 1, 4});
    const auto across = s.adjacent(a, 3);
    ASSERT_NE(across, core::kNoHalfFacet);
    EXPECT_EQ(core::tet_of(across), b);
    EXPECT_EQ(s.vertices(b)[static_cast<std::size_t>(core::facet_of(across))], 4u);
    EXPECT_EQ(core::tet_of(s.adjacent(b, core::facet_of(across))), a);
    EXPECT_EQ(s.adjacent(a, 0), core::kNoHalfFacet);  // nothing beyond the other faces
    s.delete_tetrahedron(b);
    EXPECT_EQ(s.adjacent(a, 3), core::kNoHalfFacet);  // deleted: the book's "empty"
    s.end_operation();
    EXPECT_EQ(s.tet_at_vertex(3), a);
    EXPECT_EQ(s.tet_at_vertex(4), core::kNoTet);
}

TEST(FaceHashStorage, ManyInsertionsAndDeletionsAgreeWithAMap) {
    // Random tetrahedra with distinct faces; the table must find exactly what a std::map finds,
    // through growth and backward-shift deletions.
    FaceHashStorage s;
    core::Random random(42);
    std::map<std::array<core::VertexId, 4>, core::TetId> live;
    for (int round = 0; round < 20000; ++round) {
        if (!live.empty() && random.below(3) == 0) {
            auto it = live.begin();
            std::advance(it, static_cast<long>(random.below(live.size())));
            s.delete_tetrahedron(it->second);
            live.erase(it);
            s.end_operation();
            continue;
        }
        // Fresh vertex ids make every face unique.
        const auto base = static_cast<core::VertexId>(4 * round);
        const TetVertices v{base, base + 1, base + 2, base + 3};
        live[v] = s.add_tetrahedron(v);
    }
    for (const auto& [v, t] : live) {
        ASSERT_TRUE(s.alive(t));
        EXPECT_EQ(s.vertices(t), v);
        for (int f = 0; f < 4; ++f) {
            EXPECT_EQ(s.adjacent(t, f), core::kNoHalfFacet);  // no tetrahedron shares a face
        }
        EXPECT_EQ(s.tet_at_vertex(v[0]), t);
    }
    EXPECT_EQ(s.live_count(), live.size());
}

TEST(ArrayStorage, GlueIsSymmetricAndDeletionIsVisible) {
    core::ArrayStorage s;
    const auto a = s.add_tetrahedron({0, 1, 2, 3});
    const auto b = s.add_tetrahedron({0, 2, 1, 4});
    s.glue(core::half_facet(a, 3), core::half_facet(b, 3));
    EXPECT_EQ(s.adjacent(a, 3), core::half_facet(b, 3));
    EXPECT_EQ(s.adjacent(b, 3), core::half_facet(a, 3));
    s.delete_tetrahedron(b);
    EXPECT_EQ(s.adjacent(a, 3), core::kNoHalfFacet);
    EXPECT_EQ(s.vertices(b)[3], 4u);  // still readable until the operation ends
    s.end_operation();
    const auto c = s.add_tetrahedron({0, 2, 1, 5});
    EXPECT_EQ(c, b);  // the slot is reused once the operation has ended
}

TEST(Tables, FacetsAreOrientedAndRotationKeepsOrientation) {
    // (facet f, vertex f) must be an even permutation of (0, 1, 2, 3).
    for (int f = 0; f < 4; ++f) {
        const auto& tri = core::kFacetVertices[static_cast<std::size_t>(f)];
        const int p[4] = {tri[0], tri[1], tri[2], f};
        int inversions = 0;
        for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) {
                inversions += p[i] > p[j] ? 1 : 0;
            }
        }
        EXPECT_EQ(inversions % 2, 0) << "facet " << f;
    }
    const TetVertices v{10, 11, 12, 13};
    for (int i = 0; i < 4; ++i) {
        const auto r = core::rotate_to_last(v, i);
        EXPECT_EQ(r[3], v[static_cast<std::size_t>(i)]);
    }
}

}  // namespace
}  // namespace cavity::test
