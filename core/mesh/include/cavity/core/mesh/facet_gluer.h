#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// Pairs up the new faces around a freshly inserted vertex u. Every new tetrahedron's face through
/// u, rotated to (u, p, q), meets another new tetrahedron's face (u, q, p) across the directed
/// edge (p, q). The cavity's boundary vertices get small local numbers (a per-vertex stamp tells
/// which are current), and a local-number matrix finds each partner in two array reads; a cavity
/// with more boundary vertices than the matrix holds (quadratic-size triangulations) uses a hash
/// table on the directed edge instead. Either way the state is cleared by undoing its own writes.
class FacetGluer {
public:
    /// Starts a cavity of `faces` new faces through u (a cavity with F boundary triangles has
    /// F/2 + 2 boundary vertices).
    void begin(std::size_t faces);

    /// The local number of a boundary vertex of the current cavity (matrix mode only).
    [[gnu::always_inline]] std::uint32_t local(VertexId v) {
        // At most kMatrixSide vertices in kLocalSlots slots: the table is at most a quarter full.
        std::size_t i = ((v * 0x9E37'79B9u) >> 24) & (kLocalSlots - 1);
        while (local_table_[i].vertex != v) {
            if (local_table_[i].vertex == kNoVertex) {
                // A cavity boundary is a sphere with F/2 + 2 vertices, which begin() checked
                // against the matrix; more would mean a corrupt cavity, never a memory overrun.
                if (locals_ == kMatrixSide) [[unlikely]] {
                    throw_too_many_vertices();
                }
                local_table_[i] = Local{v, locals_++};
                local_touched_.push_back(static_cast<std::uint32_t>(i));
                break;
            }
            i = (i + 1) & (kLocalSlots - 1);
        }
        return local_table_[i].number;
    }

    /// True when this cavity is small enough for the local-number matrix.
    bool use_matrix() const { return use_matrix_; }

    /// Registers half-facet h whose face, rotated to start at u, is (u, p, q), p and q given by
    /// their local numbers. Returns the partner's half-facet if (u, q, p) was registered before,
    /// else kNoHalfFacet.
    [[gnu::always_inline]] HalfFacet match_local(std::uint32_t lp, std::uint32_t lq, HalfFacet h) {
        HalfFacet& partner = matrix_[lq * kMatrixSide + lp];
        if (partner != kNoHalfFacet) {
            const HalfFacet found = partner;
            partner = kNoHalfFacet;
            return found;
        }
        const std::size_t own = lp * kMatrixSide + lq;
        matrix_[own] = h;
        matrix_touched_.push_back(static_cast<std::uint32_t>(own));
        return kNoHalfFacet;
    }

    /// The same for cavities too large for the matrix, keyed on the vertex ids.
    HalfFacet match_hashed(VertexId p, VertexId q, HalfFacet h);

    void end();

private:
    static constexpr std::size_t kMatrixSide = 64;
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    struct Entry {
        std::uint64_t edge;
        HalfFacet value;
    };

    [[noreturn]] static void throw_too_many_vertices();
    std::size_t slot(std::uint64_t edge) const;
    void grow();

    static constexpr std::size_t kLocalSlots = 4 * kMatrixSide;

    struct Local {
        VertexId vertex;
        std::uint32_t number;
    };

    bool use_matrix_ = true;
    std::uint32_t locals_ = 0;
    std::vector<Local> local_table_ = std::vector<Local>(kLocalSlots, Local{kNoVertex, 0});
    PodStack<std::uint32_t> local_touched_;
    std::vector<HalfFacet> matrix_ =
        std::vector<HalfFacet>(kMatrixSide * kMatrixSide, kNoHalfFacet);
    PodStack<std::uint32_t> matrix_touched_;
    std::vector<Entry> table_ = std::vector<Entry>(64, Entry{kEmpty, kNoHalfFacet});
    PodStack<std::size_t> table_touched_;
};

}  // namespace cavity::core
