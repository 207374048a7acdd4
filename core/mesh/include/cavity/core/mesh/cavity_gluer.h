#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/base/error.h"
#include "cavity/core/base/pod_stack.h"
#include "cavity/core/mesh/facet_gluer.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// Glues the new tetrahedra that fill one cavity to each other. Each new tetrahedron has the apex
/// (the inserted vertex) and three faces through it; the face rotated to (apex, p, q) meets the
/// one rotated to (apex, q, p), across the directed boundary edge (p, q). The cavity's boundary is
/// a sphere, so each directed edge belongs to exactly one face.
///
/// Small cavities (at most kMatrixSide boundary vertices, all but a few) take two passes over the
/// new tetrahedra (after the matrix scheme of HXT's computeAdjacenciesFast): number the boundary
/// vertices and write each face into a matrix cell indexed by its directed edge, then read each
/// face's partner from the cell of the reversed edge. Every cell read was written by this cavity
/// (the reversed edge is some face's edge), so stale cells from earlier cavities are never seen.
/// Each face records only its own side; its partner does the same in its turn. Larger cavities
/// (quadratic-size triangulations) pair faces through FacetGluer's hash table.
///
/// The local numbers come from a small open-addressing table keyed by vertex id, emptied after
/// each cavity by undoing its own writes, rather than from a byte per vertex as in HXT: that byte
/// array was 1 byte per point of the peak memory (issue 13), and per thread in the parallel
/// construction. The first pass keeps each tetrahedron's numbers, so the second pass needs no
/// lookup.
class CavityGluer {
public:
    /// Glues the faces through `apex` of the tetrahedra `created`, each of which has `apex` as a
    /// vertex (any ids but kNoVertex).
    template <class Storage>
    void glue(Storage& storage, std::span<const TetId> created, VertexId apex) {
        // A sphere with F triangles has F/2 + 2 vertices; the apex takes a number too.
        if (created.size() / 2 + 3 > kMatrixSide) {
            glue_hashed(storage, created, apex);
            return;
        }
        numbers_.clear();
        // The next number to give, in a register: as a member it was reloaded after every store
        // to the table (the same type, so possibly the same memory to the compiler).
        std::uint32_t next = 1;
        for (TetId t : created) {
            const TetVertices v = storage.vertices(t);
            // The apex is in slot 3 but in ghosts (cone() in tetrahedron.h): the tests go in that
            // order, and each case is compiled with its faces' slots as constants.
            if (v[3] == apex) [[likely]] {
                number_faces<3>(t, v, next);
            } else if (v[0] == apex) {
                number_faces<0>(t, v, next);
            } else if (v[1] == apex) {
                number_faces<1>(t, v, next);
            } else {
                number_faces<2>(t, v, next);
            }
        }
        for (std::size_t k = 0; k < created.size(); ++k) {
            const std::uint32_t packed = numbers_[k];
            switch (packed >> kApexShift) {
                case 3:
                    glue_faces<3>(storage, created[k], packed);
                    break;
                case 0:
                    glue_faces<0>(storage, created[k], packed);
                    break;
                case 1:
                    glue_faces<1>(storage, created[k], packed);
                    break;
                default:
                    glue_faces<2>(storage, created[k], packed);
                    break;
            }
        }
        forget_numbers(next);
    }

private:
    static constexpr std::size_t kMatrixSide = 64;
    // A word of numbers_: a number (below kMatrixSide) per slot, a byte each, and the apex's slot
    // in the top two bits, which the number in slot 3 leaves free.
    static constexpr std::uint32_t kNumberMask = kMatrixSide - 1;
    static constexpr std::uint32_t kApexShift = 30;
    // Twice the most numbers a cavity takes, so that a probe meets an empty slot within a few
    // steps; a power of two, indexed by the top bits of a product.
    static constexpr std::uint32_t kTableBits = 7;
    static constexpr std::size_t kTableSize = std::size_t{1} << kTableBits;
    static_assert(kTableSize >= 2 * kMatrixSide);

    struct Entry {
        VertexId vertex;  // kNoVertex: empty
        std::uint32_t number;
    };

    [[noreturn]] static void throw_too_many_vertices() {
        throw InternalError(
            "internal error: a cavity boundary has more vertices than its faces allow");
    }

    /// The number of boundary vertex w in this cavity, given on its first lookup (1, 2, ...).
    [[gnu::always_inline]] std::uint32_t local_number(VertexId w, std::uint32_t& next) {
        // Fibonacci hashing: the top bits of the product depend on every bit of the id.
        std::size_t i = (w * 0x9E37'79B1u) >> (32 - kTableBits);
        for (;;) {
            Entry& e = table_[i];
            if (e.vertex == w) {
                return e.number;
            }
            if (e.vertex == kNoVertex) {
                // Euler's count bounds the numbers for a sphere, which the size check in glue()
                // relied on; more would mean a corrupt cavity, never a memory overrun.
                if (next == kMatrixSide) [[unlikely]] {
                    forget_numbers(next);
                    throw_too_many_vertices();
                }
                e = {w, next};
                slot_of_[next] = static_cast<std::uint32_t>(i);
                return next++;
            }
            i = (i + 1) & (kTableSize - 1);
        }
    }

    /// Empties the table by undoing this cavity's writes (numbers 1 to next - 1), ready for the
    /// next cavity.
    void forget_numbers(std::uint32_t next) {
        for (std::uint32_t k = 1; k < next; ++k) {
            table_[slot_of_[k]].vertex = kNoVertex;
        }
    }

    /// First pass for a new tetrahedron t (vertices v) with the apex in slot A: numbers its other
    /// vertices, keeps the numbers (a byte each, the apex's 0) and A in its word of numbers_, and
    /// writes each face through the apex into the cell of its directed edge.
    template <std::size_t A>
    [[gnu::always_inline]] void number_faces(TetId t, const TetVertices& v, std::uint32_t& next) {
        // The three other slots as constants (GCC kept the loop over the four slots rolled, with
        // the vertices and numbers on the stack and indexed at run time).
        constexpr std::size_t kS0 = A == 0 ? 1 : 0;
        constexpr std::size_t kS1 = A <= 1 ? 2 : 1;
        constexpr std::size_t kS2 = A <= 2 ? 3 : 2;
        std::array<std::uint32_t, 4> number{};
        number[kS0] = local_number(v[kS0], next);
        number[kS1] = local_number(v[kS1], next);
        number[kS2] = local_number(v[kS2], next);
        const std::uint32_t packed = (std::uint32_t{A} << kApexShift) | (number[kS0] << (8 * kS0)) |
                                     (number[kS1] << (8 * kS1)) | (number[kS2] << (8 * kS2));
        numbers_.push_back(packed);
        for (const ApexFace& face : kApexFaces[A]) {
            matrix_[number[face.from] * kMatrixSide + number[face.to]] = half_facet(t, face.s);
        }
    }

    /// Second pass: each face through the apex of t takes its partner from the reversed edge.
    template <std::size_t A, class Storage>
    [[gnu::always_inline]] void glue_faces(Storage& storage, TetId t, std::uint32_t packed) {
        for (const ApexFace& face : kApexFaces[A]) {
            const std::uint32_t from = (packed >> (8 * face.from)) & kNumberMask;
            const std::uint32_t to = (packed >> (8 * face.to)) & kNumberMask;
            storage.set_adjacent(half_facet(t, face.s), matrix_[to * kMatrixSide + from]);
        }
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

    std::array<Entry, kTableSize> table_ = [] {
        std::array<Entry, kTableSize> empty{};
        empty.fill({kNoVertex, 0});
        return empty;
    }();
    std::array<std::uint32_t, kMatrixSide> slot_of_{};  // the table slot of each number
    PodStack<std::uint32_t> numbers_;  // per new tetrahedron, its four numbers, a byte each
    std::array<HalfFacet, kMatrixSide * kMatrixSide> matrix_{};
    FacetGluer hashed_;
};

}  // namespace cavity::core
