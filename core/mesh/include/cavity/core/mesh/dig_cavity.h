#pragma once

#include <concepts>
#include <cstddef>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// What dig_cavity asks of its caller: the geometry (which tetrahedra conflict), the constraints
/// (which faces the search may not cross) and what becomes of the cavity. Unconstrained
/// Bowyer–Watson answers `blocked` with a constant false, and the compiler drops the branch.
template <class R>
concept DigRules = requires(R rules, TetId t, int f, HalfFacet across) {
    { rules.blocked(t, f) } -> std::same_as<bool>;
    { rules.in_cavity(t) } -> std::same_as<bool>;
    { rules.conflicts(t) } -> std::same_as<bool>;
    rules.take(t);
    rules.blocked_inside(t, f);
    rules.cavity_face(t, f, across);
};

/// DigCavity3D (Cheng, Dey & Shewchuk §5.2) and its constrained form (§5.7), one loop: from t0,
/// which the caller knows to conflict, the search takes every tetrahedron reachable through faces
/// that are not blocked and whose far side conflicts. Each face of a taken tetrahedron is looked at
/// once from inside (the face it was entered through excepted):
///  - its far side already in the cavity (taken, or deleted so that storage.adjacent says
///    kNoHalfFacet): an inner face; if it is blocked too, `blocked_inside` hears of it (a
///    constraint with the cavity on both sides);
///  - blocked, or the far side does not conflict: a cavity face, `cavity_face(t, f, across)`;
///  - else the far side is taken, and queued with the face it was entered through.
/// As in the book, a tetrahedron outside the cavity is tested once per cavity face it borders.
///
/// The search is breadth-first (the order of HXT's diggingACavity): a taken tetrahedron's faces are
/// looked at only after those of every tetrahedron queued before it, so the prefetch of its
/// neighbours' records, issued when it is taken, has a whole level of tests to land. Depth-first,
/// the next test read the prefetched record at once and the prefetch saved little (perf playbook
/// §3: −5.6% alone, −16% with this order, cube 10^6).
/// Inlined into its caller: the insertion loop is the engine's hottest code, and a call here
/// measured 1.3% more instructions on a 2·10^5-point cube (callgrind).
template <class Storage, class Rules>
requires DigRules<Rules>

[[gnu::always_inline]] inline void dig_cavity(const Storage& storage,
                                              TetId t0,
                                              PodStack<HalfFacet>& queue,
                                              Rules& rules) {
    queue.clear();
    const auto look_across = [&](TetId t, int f) __attribute__((always_inline)) {
        const bool blocked = rules.blocked(t, f);
        const HalfFacet across = storage.adjacent(t, f);
        if (across == kNoHalfFacet || rules.in_cavity(tet_of(across))) {
            if (blocked) {
                rules.blocked_inside(t, f);
            }
            return;
        }
        const TetId far = tet_of(across);
        if (!blocked && rules.conflicts(far)) {
            rules.take(far);
            storage.prefetch_neighbours(far);
            queue.push_back(across);  // far, with the face it was entered through
        } else {
            rules.cavity_face(t, f, across);
        }
    };
    rules.take(t0);
    storage.prefetch_neighbours(t0);
    for (int f = 0; f < 4; ++f) {
        look_across(t0, f);
    }
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const HalfFacet entered = queue[next];
        const TetId t = tet_of(entered);
        for (int g = 0; g < 4; ++g) {
            if (g != facet_of(entered)) {
                look_across(t, g);
            }
        }
    }
}

}  // namespace cavity::core
