#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/base/error.h"
#include "cavity/core/mesh/facet_gluer.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// Glues the new tetrahedra that fill one cavity to each other. Each new tetrahedron has the apex
/// (the inserted vertex) and three faces through it; the face rotated to (apex, p, q) meets the
/// one rotated to (apex, q, p), across the directed boundary edge (p, q). The cavity's boundary is
/// a sphere, so each directed edge belongs to exactly one face.
///
/// Small cavities (at most kMatrixSide boundary vertices, all but a few) take three passes over
/// the new tetrahedra with nothing cleared between cavities (the scheme of HXT's
/// computeAdjacenciesFast): mark every boundary vertex unnumbered in a per-vertex byte array,
/// number them and write each face into a matrix cell indexed by its directed edge, then read
/// each face's partner from the cell of the reversed edge. Every cell read was written by this
/// cavity (the reversed edge is some face's edge), so stale cells from earlier cavities are never
/// seen. Each face records only its own side; its partner does the same in its turn. Larger
/// cavities (quadratic-size triangulations) pair faces through FacetGluer's hash table.
class CavityGluer {
public:
    /// Makes room for vertex ids below `vertices` (the ghost vertex has a slot of its own).
    void reserve(std::size_t vertices) {
        if (local_.size() <= vertices) {
            local_.resize(vertices + 1);
        }
    }

    /// Glues the faces through `apex` of the tetrahedra `created`, each of which has `apex` as a
    /// vertex and whose other vertices are below the reserved count or the ghost vertex.
    template <class Storage>
    void glue(Storage& storage, std::span<const TetId> created, VertexId apex) {
        // A sphere with F triangles has F/2 + 2 vertices; the apex takes a number too.
        if (created.size() / 2 + 3 > kMatrixSide) {
            glue_hashed(storage, created, apex);
            return;
        }
        // Byte stores may alias anything, so the arrays and each record's vertices are read into
        // locals once: otherwise the compiler reloads them after every mark.
        std::uint8_t* const local = local_.data();
        HalfFacet* const matrix = matrix_.data();
        const std::size_t ghost = local_.size() - 1;
        const auto slot = [ghost](VertexId w) { return std::min<std::size_t>(w, ghost); };
        for (TetId t : created) {
            const TetVertices v = storage.vertices(t);
            for (VertexId w : v) {
                local[slot(w)] = kUnnumbered;
            }
        }
        std::uint8_t next = 0;
        for (TetId t : created) {
            const TetVertices v = storage.vertices(t);
            std::array<std::uint32_t, 4> number{};
            for (std::size_t s = 0; s < 4; ++s) {
                std::uint8_t& l = local[slot(v[s])];
                if (l == kUnnumbered) {
                    // Euler's count bounds the numbers for a sphere, which the size check above
                    // relied on; more would mean a corrupt cavity, never a memory overrun.
                    if (std::size_t{next} == kMatrixSide) [[unlikely]] {
                        throw_too_many_vertices();
                    }
                    l = next++;
                }
                number[s] = l;
            }
            for (const ApexFace& face : kApexFaces[apex_slot(v, apex)]) {
                matrix[number[face.from] * kMatrixSide + number[face.to]] = half_facet(t, face.s);
            }
        }
        for (TetId t : created) {
            const TetVertices v = storage.vertices(t);
            std::array<std::uint32_t, 4> number{};
            for (std::size_t s = 0; s < 4; ++s) {
                number[s] = local[slot(v[s])];
            }
            for (const ApexFace& face : kApexFaces[apex_slot(v, apex)]) {
                storage.set_adjacent(half_facet(t, face.s),
                                     matrix[number[face.to] * kMatrixSide + number[face.from]]);
            }
        }
    }

private:
    static constexpr std::size_t kMatrixSide = 64;
    static constexpr std::uint8_t kUnnumbered = 0xFF;

    [[noreturn]] static void throw_too_many_vertices() {
        throw InternalError(
            "internal error: a cavity boundary has more vertices than its faces allow");
    }

    static std::size_t apex_slot(const TetVertices& v, VertexId apex) {
        return v[3] == apex ? 3 : v[0] == apex ? 0 : v[1] == apex ? 1 : 2;
    }

    /// A face s through the apex and its directed edge (from, to): the face is facet s rotated to
    /// (apex, from, to), with from and to as vertex slots (kApexFaceEdge without the apex's row).
    struct ApexFace {
        int s;
        std::size_t from;
        std::size_t to;
    };

    /// kApexFaces[a]: the three faces through the apex in slot a.
    static constexpr auto kApexFaces = [] {
        std::array<std::array<ApexFace, 3>, 4> table{};
        for (std::size_t a = 0; a < 4; ++a) {
            std::size_t k = 0;
            for (std::size_t s = 0; s < 4; ++s) {
                if (s != a) {
                    table[a][k++] = {static_cast<int>(s),
                                     static_cast<std::size_t>(kApexFaceEdge[a][s][0]),
                                     static_cast<std::size_t>(kApexFaceEdge[a][s][1])};
                }
            }
        }
        return table;
    }();

    template <class Storage>
    void glue_hashed(Storage& storage, std::span<const TetId> created, VertexId apex) {
        for (TetId t : created) {
            const TetVertices& v = storage.vertices(t);
            const std::size_t a = apex_slot(v, apex);
            const auto& edges = kApexFaceEdge[a];
            for (std::size_t s = 0; s < 4; ++s) {
                if (s == a) {
                    continue;
                }
                const HalfFacet h = half_facet(t, static_cast<int>(s));
                const HalfFacet partner =
                    hashed_.match_hashed(v[static_cast<std::size_t>(edges[s][0])],
                                         v[static_cast<std::size_t>(edges[s][1])],
                                         h);
                if (partner != kNoHalfFacet) {
                    storage.glue(h, partner);
                }
            }
        }
        hashed_.end();
    }

    // One byte per vertex id, then one for the ghost vertex (above every id): local numbers.
    std::vector<std::uint8_t> local_ = std::vector<std::uint8_t>(1);
    std::vector<HalfFacet> matrix_ = std::vector<HalfFacet>(kMatrixSide * kMatrixSide);
    FacetGluer hashed_;
};

}  // namespace cavity::core
