#include "canonical_order.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "canonical_rotation.h"
#include "in_pieces.h"

namespace cavity::core {

namespace {

/// The three lower ranks of a tetrahedron, highest first: how tetrahedra with the same highest
/// vertex are ordered.
std::array<std::uint32_t, 3> lower_key(const TetVertices& v, std::uint32_t top) {
    std::array<std::uint32_t, 4> r{rank_of(v[0]), rank_of(v[1]), rank_of(v[2]), rank_of(v[3])};
    // Drop the top (ranks are distinct in a tetrahedron), then order the other three.
    std::size_t k = 0;
    std::array<std::uint32_t, 3> low{};
    for (std::uint32_t x : r) {
        if (x != top) {
            low[k++] = x;
        }
    }
    if (low[0] < low[1]) {
        std::swap(low[0], low[1]);
    }
    if (low[1] < low[2]) {
        std::swap(low[1], low[2]);
    }
    if (low[0] < low[1]) {
        std::swap(low[0], low[1]);
    }
    return low;
}

std::uint32_t top_rank(const TetVertices& v) {
    return std::max(std::max(rank_of(v[0]), rank_of(v[1])), std::max(rank_of(v[2]), rank_of(v[3])));
}

}  // namespace

CanonicalOrder canonical_order(ConcurrentMesh& mesh, std::size_t vertices, unsigned threads) {
    const std::size_t used = mesh.used();
    // Each live slot's highest rank (its bucket; 0 marks a dead slot, as no live tetrahedron has
    // only the ghost) and, in `renumber`, its rotation stored inverted (old facet g becomes new
    // facet (renumber >> 2g) & 3), to which its new slot is added above bit 8 once known: one
    // load per neighbour when the records are renumbered.
    std::vector<std::uint32_t> top(used, 0);
    std::vector<std::uint64_t> renumber(used, 0);
    // Counting sort on the highest rank, then the few tetrahedra sharing one by their other
    // ranks. The threads count and place with atomic increments: the order within a bucket then
    // depends on the interleaving, but each bucket is sorted by its keys afterwards.
    std::vector<std::uint32_t> start(vertices + 2, 0);
    in_pieces(used, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            if (!mesh.alive(static_cast<TetId>(t))) {
                continue;
            }
            const TetVertices& v = mesh.record(static_cast<TetId>(t)).v;
            top[t] = top_rank(v);
            std::atomic_ref<std::uint32_t>(start[top[t] + 1])
                .fetch_add(1, std::memory_order_relaxed);
            const Perm p = canonical_perm(v);
            renumber[t] =
                (0u << (2 * p[0])) | (1u << (2 * p[1])) | (2u << (2 * p[2])) | (3u << (2 * p[3]));
        }
    });
    for (std::size_t b = 1; b < start.size(); ++b) {
        start[b] += start[b - 1];
    }
    const std::size_t live = start.back();

    // Placed with their sort keys, so that each bucket is sorted where it lies (reading the keys
    // off the records in bucket order instead was measured at 0.4 s of cache misses at 10^6).
    struct Entry {
        std::array<std::uint32_t, 3> key;
        TetId slot;
    };

    std::vector<Entry> entries(live);
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        in_pieces(used, threads, [&](unsigned, std::size_t begin, std::size_t end) {
            for (std::size_t t = begin; t < end; ++t) {
                if (top[t] != 0) {
                    const std::uint32_t at = std::atomic_ref<std::uint32_t>(next[top[t]])
                                                 .fetch_add(1, std::memory_order_relaxed);
                    entries[at] = {lower_key(mesh.record(static_cast<TetId>(t)).v, top[t]),
                                   static_cast<TetId>(t)};
                }
            }
        });
    }
    std::vector<std::uint32_t>().swap(top);
    in_pieces(vertices + 1, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        for (std::size_t b = std::max<std::size_t>(begin, 1); b < end; ++b) {
            if (start[b + 1] - start[b] > 1) {
                std::sort(entries.begin() + start[b],
                          entries.begin() + start[b + 1],
                          [](const Entry& x, const Entry& y) { return x.key < y.key; });
            }
        }
    });
    std::vector<std::uint32_t>().swap(start);
    // The keys are done with: keep the old slots alone (4 bytes instead of 16 at the peak).
    CanonicalOrder out;
    out.order.resize(live);
    in_pieces(live, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            out.order[i] = entries[i].slot;
            renumber[out.order[i]] |= std::uint64_t{i} << 8;
        }
    });
    out.renumber = std::move(renumber);
    return out;
}

void store_canonically(ConcurrentMesh& mesh,
                       ArrayStorage& storage,
                       std::size_t vertices,
                       unsigned threads) {
    const CanonicalOrder canonical = canonical_order(mesh, vertices, threads);
    const std::vector<TetId>& order = canonical.order;
    const std::vector<std::uint64_t>& renumber = canonical.renumber;
    const std::size_t live = order.size();
    // Gather the records in their new order, rotated, with renumbered neighbours. (Moving them in
    // place along the permutation's cycles saves the second copy, but was measured 2x slower:
    // slots freed by a cavity are reused by later insertions, so the cycles jump across the
    // whole array.)
    std::vector<ArrayRecord> records(live);
    in_pieces(live, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const ArrayRecord& from = mesh.record(order[i]);
            const std::uint64_t own = renumber[order[i]];
            ArrayRecord& r = records[i];
            for (std::size_t g = 0; g < 4; ++g) {
                const std::size_t s = (own >> (2 * g)) & 3u;
                r.v[s] = from.v[g];
                const HalfFacet h = from.n[g];
                const std::uint64_t far = renumber[tet_of(h)];
                r.n[s] = half_facet(static_cast<TetId>(far >> 8),
                                    static_cast<int>((far >> (2 * facet_of(h))) & 3u));
            }
        }
    });
    mesh.clear();
    storage.assign(std::move(records), vertices);
}

}  // namespace cavity::core
