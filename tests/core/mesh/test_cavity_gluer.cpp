// CavityGluer: the faces through a new vertex paired across the cavity boundary's edges, checked
// against a brute-force match of shared triangles.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/cavity_gluer.h"

namespace cavity::test {
namespace {

using core::ArrayStorage;
using core::HalfFacet;
using core::TetId;
using core::TetVertices;
using core::VertexId;

/// The cone from `apex` over a bipyramid (a ring of ring.size() vertices and two poles, its
/// triangles all turning the same way), one tetrahedron per triangle, the apex in slot `apex_slot`
/// (an even rotation of (p, q, r, apex), so every tetrahedron has the same orientation).
std::vector<TetId> cone_over_bipyramid(ArrayStorage& storage,
                                       VertexId apex,
                                       std::size_t apex_slot,
                                       VertexId north,
                                       VertexId south,
                                       const std::vector<VertexId>& ring) {
    std::vector<TetId> created;
    const auto add = [&](VertexId p, VertexId q, VertexId r) {
        TetVertices v{p, q, r, apex};
        // Rotating (p, q, r) and swapping slot 3 into place by two transpositions keeps parity.
        if (apex_slot != 3) {
            std::swap(v[apex_slot], v[3]);
            std::swap(v[(apex_slot + 1) % 3], v[(apex_slot + 2) % 3]);
        }
        created.push_back(storage.add_tetrahedron(v));
    };
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const VertexId a = ring[i];
        const VertexId b = ring[(i + 1) % ring.size()];
        add(north, a, b);
        add(south, b, a);
    }
    return created;
}

/// The facet of t whose three vertices are `face` (any order), or -1.
int facet_with(const ArrayStorage& storage, TetId t, std::array<VertexId, 3> face) {
    std::sort(face.begin(), face.end());
    for (int f = 0; f < 4; ++f) {
        auto tri = core::facet_vertices(storage.vertices(t), f);
        std::sort(tri.begin(), tri.end());
        if (tri == face) {
            return f;
        }
    }
    return -1;
}

/// Every face through `apex` of every created tetrahedron is glued to the one other created
/// tetrahedron that shares it, on both sides.
void expect_glued_like_brute_force(const ArrayStorage& storage,
                                   const std::vector<TetId>& created,
                                   VertexId apex) {
    for (TetId t : created) {
        const TetVertices& v = storage.vertices(t);
        for (int f = 0; f < 4; ++f) {
            const auto tri = core::facet_vertices(v, f);
            if (std::find(tri.begin(), tri.end(), apex) == tri.end()) {
                continue;  // the boundary face: glued to the outside, not by the gluer
            }
            HalfFacet expected = core::kNoHalfFacet;
            for (TetId other : created) {
                const int g = other == t ? -1 : facet_with(storage, other, tri);
                if (g >= 0) {
                    EXPECT_EQ(expected, core::kNoHalfFacet) << "a face shared three times";
                    expected = core::half_facet(other, g);
                }
            }
            ASSERT_NE(expected, core::kNoHalfFacet);
            EXPECT_EQ(storage.adjacent(t, f), expected) << "tetrahedron " << t << " facet " << f;
        }
    }
}

TEST(CavityGluer, PairsTheFacesOfTheLargestMatrixCavity) {
    // 60 ring vertices and 2 poles: 120 faces, 62 boundary vertices and the apex, the most the
    // matrix takes. Ids near the top of the range and spaced by a prime: no reservation needed,
    // and the lookup table sees long probe runs.
    ArrayStorage storage;
    core::CavityGluer gluer;
    std::vector<VertexId> ring;
    for (VertexId i = 0; i < 60; ++i) {
        ring.push_back(4'000'000'000u + 7919u * i);
    }
    const VertexId apex = 4'200'000'000u;
    for (std::size_t slot = 0; slot < 4; ++slot) {
        const auto created = cone_over_bipyramid(storage, apex, slot, 17, 4'100'000'000u, ring);
        gluer.glue(storage, created, apex);
        expect_glued_like_brute_force(storage, created, apex);
    }
}

TEST(CavityGluer, ForgetsEachCavityBeforeTheNext) {
    // Cavities one after another sharing vertex ids in other roles, and the ghost vertex as an
    // apex (the bootstrap's ghosts) and as a boundary vertex (a cavity on the hull).
    ArrayStorage storage;
    core::CavityGluer gluer;
    const std::vector<VertexId> small{1, 2, 3, 4, 5};
    const std::vector<VertexId> shifted{2, 3, 4, 5, 6, 7, 8};

    struct Cavity {
        VertexId apex, north, south;
        const std::vector<VertexId>& ring;
    };

    const std::array<Cavity, 4> cavities{{{9, 0, 6, small},
                                          {core::kGhostVertex, 0, 9, small},
                                          {1, core::kGhostVertex, 9, shifted},
                                          {0, 1, 9, shifted}}};
    for (const Cavity& c : cavities) {
        const auto created = cone_over_bipyramid(storage, c.apex, 3, c.north, c.south, c.ring);
        gluer.glue(storage, created, c.apex);
        expect_glued_like_brute_force(storage, created, c.apex);
    }
}

}  // namespace
}  // namespace cavity::test
