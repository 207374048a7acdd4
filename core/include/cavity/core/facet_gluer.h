#pragma once

#include <cstdint>
#include <vector>

#include "cavity/core/tetrahedron.h"

namespace cavity::core {

/// Pairs up the new faces around a freshly inserted vertex u. Every new tetrahedron's faces through
/// u meet another new tetrahedron's across the directed edge (p, q) of the face rotated to (u, p,
/// q); its partner holds (u, q, p). An open-addressed table keyed on the directed edge finds the
/// partner; the table is cleared by undoing its own writes, so a small cavity costs a small clear.
class FacetGluer {
public:
    /// Registers half-facet h whose face, rotated to start at u, is (u, p, q). Returns the
    /// partner's half-facet if (u, q, p) was registered before (and forgets it), else kNoHalfFacet.
    HalfFacet match(VertexId p, VertexId q, HalfFacet h);

    void clear();

private:
    struct Entry {
        std::uint64_t edge;
        HalfFacet value;
    };

    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    std::size_t slot(std::uint64_t edge) const;
    void grow();

    std::vector<Entry> table_ = std::vector<Entry>(64, Entry{kEmpty, kNoHalfFacet});
    std::vector<std::size_t> touched_;
};

}  // namespace cavity::core
