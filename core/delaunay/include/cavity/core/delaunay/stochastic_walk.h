#pragma once

#include <cstdint>

#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// The xorshift64 stream a walk draws the first facet to test from: cheap, with explicit state so
/// that runs repeat, and good enough to break the cycles a fixed visiting order can fall into.
class WalkRandom {
public:
    explicit WalkRandom(std::uint64_t state) : state_(state) {}

    int first_facet() {
        state_ ^= state_ << 13;
        state_ ^= state_ >> 7;
        state_ ^= state_ << 17;
        return static_cast<int>(state_ & 3u);
    }

private:
    std::uint64_t state_;
};

/// The remembering stochastic walk of Devillers, Pion & Teillaud ("Walking in a triangulation"),
/// the one loop behind every walk of cavity (§5.5's point location, the conflict graph's moves of
/// uninserted points, the CDT's location of a new vertex). From `start`, at each tetrahedron t:
/// `stop(t, vertices)` may end the walk at t before any facet is tested; otherwise the facets are
/// offered to `leaves(t, vertices, f, entered)` from a random one on, until one answers that the
/// walk leaves t through f. `entered` is the facet the walk came in through (-1 at the start):
/// `leaves` must not leave through it (that memory is what makes the walk terminate on every
/// triangulation, degenerate or constrained), though it may look at it. The walk ends at the
/// tetrahedron no facet leaves.
///
/// Inlined into its caller, whose tests (`stop`, `leaves`) then inline into the loop: left out of
/// line (as GCC left the counting engine's walk and the conflict graph's moves), each step
/// reloaded the tests' captures and counters from memory (callgrind: 0.9% of the counting
/// engine's instructions on a 50^3 grid, 9.5% of the conflict graph's on a 2*10^5 cube).
template <class Storage, class Stop, class Leaves>
[[gnu::always_inline]] inline TetId stochastic_walk(
    const Storage& storage, TetId start, WalkRandom& random, Stop&& stop, Leaves&& leaves) {
    TetId t = start;
    int entered = -1;
    for (;;) {
        const TetVertices& v = storage.vertices(t);
        // The walk continues into one of them; their loads overlap with t's orientation tests.
        storage.prefetch_neighbours(t);
        if (stop(t, v)) {
            return t;
        }
        const int first = random.first_facet();
        int exit = -1;
        for (int k = 0; k < 4; ++k) {
            const int f = (first + k) & 3;
            if (leaves(t, v, f, entered)) {
                exit = f;
                break;
            }
        }
        if (exit < 0) {
            return t;
        }
        const HalfFacet across = storage.adjacent(t, exit);
        t = tet_of(across);
        entered = facet_of(across);
    }
}

}  // namespace cavity::core
