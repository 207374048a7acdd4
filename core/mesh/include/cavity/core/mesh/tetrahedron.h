#pragma once

#include <array>
#include <cstdint>

/// Vocabulary of the tetrahedral complex: vertex and tetrahedron ids, half-facets, and the local
/// tables every part of core agrees on.
///
/// A tetrahedron t is four vertex ids (v0, v1, v2, v3) listed with positive orientation:
/// orient3d(v0, v1, v2, v3) > 0. Facet f of t is the triangle opposite vertex f, listed in
/// kFacetVertices[f] so that (facet, v_f) is again positively oriented: v_f lies on the positive
/// side of its facet. A ghost tetrahedron holds the ghost vertex, always in slot 3, so its facet 3
/// is the convex-hull triangle and the ghost lies in front of it (Cheng, Dey & Shewchuk §5.2).
/// With ghosts, every triangle of the complex has exactly two sides, like a triangulation of the
/// 3-sphere.
namespace cavity::core {

/// A vertex of the triangulation. Inside the engine, vertices are numbered in insertion order;
/// the input index (the perturbation key and the output id) is kept beside it.
using VertexId = std::uint32_t;
/// A tetrahedron slot in the storage.
using TetId = std::uint32_t;
/// 4 * tet + facet: one side of a triangle.
using HalfFacet = std::uint32_t;

/// The ghost vertex g (the point at infinity); distinct from "no tetrahedron" (kNoHalfFacet).
inline constexpr VertexId kGhostVertex = 0xFFFF'FFFEu;
inline constexpr VertexId kNoVertex = 0xFFFF'FFFFu;
inline constexpr TetId kNoTet = 0xFFFF'FFFFu;
inline constexpr HalfFacet kNoHalfFacet = 0xFFFF'FFFFu;

using TetVertices = std::array<VertexId, 4>;

/// kFacetVertices[f]: the slots of facet f, ordered so that (facet, slot f) is an even
/// permutation of (0, 1, 2, 3).
inline constexpr std::array<std::array<int, 3>, 4> kFacetVertices{{
    {1, 3, 2},
    {0, 2, 3},
    {0, 3, 1},
    {0, 1, 2},
}};

/// kApexFaceEdge[a][s] = {i, j}: facet s of a tetrahedron, rotated to start at slot a (a != s), is
/// (slot a, slot i, slot j). Around a new vertex in slot a, faces pair up across the edge (i, j).
inline constexpr auto kApexFaceEdge = [] {
    std::array<std::array<std::array<int, 2>, 4>, 4> table{};
    for (std::size_t a = 0; a < 4; ++a) {
        for (std::size_t s = 0; s < 4; ++s) {
            if (a == s) {
                continue;
            }
            const auto& tri = kFacetVertices[s];
            std::size_t k = 0;
            while (static_cast<std::size_t>(tri[k]) != a) {
                ++k;
            }
            table[a][s] = {tri[(k + 1) % 3], tri[(k + 2) % 3]};
        }
    }
    return table;
}();

constexpr HalfFacet half_facet(TetId t, int f) {
    return 4 * t + static_cast<HalfFacet>(f);
}

constexpr TetId tet_of(HalfFacet h) {
    return h >> 2;
}

constexpr int facet_of(HalfFacet h) {
    return static_cast<int>(h & 3u);
}

constexpr bool is_ghost(const TetVertices& v) {
    return v[3] == kGhostVertex;
}

/// The facet f of a tetrahedron as three vertex ids, oriented with v_f on its positive side.
constexpr std::array<VertexId, 3> facet_vertices(const TetVertices& v, int f) {
    const auto& s = kFacetVertices[static_cast<std::size_t>(f)];
    return {v[static_cast<std::size_t>(s[0])],
            v[static_cast<std::size_t>(s[1])],
            v[static_cast<std::size_t>(s[2])]};
}

/// The same tetrahedron with slot i moved to slot 3 by an even permutation (orientation kept):
/// used to put the ghost vertex in slot 3.
constexpr TetVertices rotate_to_last(const TetVertices& v, int i) {
    if (i == 3) {
        return v;
    }
    const auto f = facet_vertices(v, i);
    return {f[0], f[1], f[2], v[static_cast<std::size_t>(i)]};
}

/// A new tetrahedron of a cavity retriangulation (§5.2, §5.7): a boundary face joined to the new
/// vertex u, and the slot of u, whose facet is that face.
struct Cone {
    TetVertices v;
    int u_slot;
};

/// Joins the cavity face `tri` (as facet_vertices lists a facet of the deleted tetrahedron inside,
/// so that u is on its positive side) to u, stored as every tetrahedron is: a ghost keeps its
/// ghost vertex in slot 3. Bowyer-Watson and the CDT's vertex insertion both build their new
/// tetrahedra with it.
constexpr Cone cone(const std::array<VertexId, 3>& tri, VertexId u) {
    TetVertices v{tri[0], tri[1], tri[2], u};
    for (int i = 0; i < 3; ++i) {
        if (v[static_cast<std::size_t>(i)] == kGhostVertex) {
            v = rotate_to_last(v, i);
            int u_slot = 0;
            while (v[static_cast<std::size_t>(u_slot)] != u) {
                ++u_slot;
            }
            return {v, u_slot};
        }
    }
    return {v, 3};
}

}  // namespace cavity::core
