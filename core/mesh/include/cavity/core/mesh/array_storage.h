#pragma once

#include <array>

#include "cavity/core/mesh/tet_pool.h"
#include "cavity/core/mesh/tet_storage.h"

namespace cavity::core {

/// One tetrahedron of the array storage: its vertices and, for each facet f, the half-facet
/// 4 t' + f' on the other side (so a walk learns the mirror facet for free), in 32 bytes aligned to
/// 32, so one record never straddles two cache lines.
struct alignas(32) ArrayRecord {
    TetVertices v;
    std::array<HalfFacet, 4> n{kNoHalfFacet, kNoHalfFacet, kNoHalfFacet, kNoHalfFacet};
};

/// The compact storage: explicit adjacency, so the insertion code glues new tetrahedra to their
/// neighbours.
class ArrayStorage : public TetPool<ArrayRecord> {
public:
    static constexpr bool kExplicitAdjacency = true;

    /// AddTetrahedron: v must be positively oriented (ghost vertex, if any, in slot 3). The new
    /// tetrahedron's facets are unglued until glue() is called for them. Inlined: the cavity
    /// fill calls it 27 times per point, and out of line it was a call around a few stores.
    [[gnu::always_inline]] TetId add_tetrahedron(const TetVertices& v) { return allocate(v); }

    /// DeleteTetrahedron. Its data stays readable until end_operation().
    [[gnu::always_inline]] void delete_tetrahedron(TetId t) { release(t); }

    /// Adjacent: the half-facet on the other side of facet f of t, or kNoHalfFacet when the
    /// tetrahedron there has been deleted.
    HalfFacet adjacent(TetId t, int f) const {
        const HalfFacet h = record(t).n[static_cast<std::size_t>(f)];
        return alive(tet_of(h)) ? h : kNoHalfFacet;
    }

    /// Records that half-facets a and b are the two sides of one triangle.
    void glue(HalfFacet a, HalfFacet b) {
        record(tet_of(a)).n[static_cast<std::size_t>(facet_of(a))] = b;
        record(tet_of(b)).n[static_cast<std::size_t>(facet_of(b))] = a;
    }

    /// Records b as the other side of half-facet a, on a's side only: for gluing that visits both
    /// sides of every face (cavity_gluer.h).
    void set_adjacent(HalfFacet a, HalfFacet b) {
        record(tet_of(a)).n[static_cast<std::size_t>(facet_of(a))] = b;
    }

    void end_operation() { recycle_released(); }

    /// Starts loading the records of t's neighbours. The cavity search and the walk read them
    /// next, and at 10^6 points most of those first reads missed every cache (about 150 ns each on
    /// the project's machine; issue 13): issued early, the loads overlap with t's own tests. A
    /// hint, with no effect on any result.
    void prefetch_neighbours(TetId t) const {
        for (HalfFacet h : record(t).n) {
            if (h != kNoHalfFacet) {
                __builtin_prefetch(&record(tet_of(h)));
            }
        }
    }
};

static_assert(TetStorage<ArrayStorage>);

}  // namespace cavity::core
