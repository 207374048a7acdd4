#include "canonical_order.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace cavity::core {

namespace {

/// New slot s of a record holds old slot perm[s].
using Perm = std::array<std::uint8_t, 4>;

/// The order of ids the canonical order sorts by: the ghost vertex below every vertex.
constexpr std::uint32_t rank_of(VertexId v) {
    return v == kGhostVertex ? 0 : v + 1;
}

Perm canonical_perm(const TetVertices& v) {
    const auto lowest = [&](std::initializer_list<std::uint8_t> slots) {
        std::uint8_t best = *slots.begin();
        for (std::uint8_t s : slots) {
            if (rank_of(v[s]) < rank_of(v[best])) {
                best = s;
            }
        }
        return best;
    };
    if (is_ghost(v)) {
        const std::uint8_t m = lowest({0, 1, 2});
        return {
            m, static_cast<std::uint8_t>((m + 1) % 3), static_cast<std::uint8_t>((m + 2) % 3), 3};
    }
    // The even permutations that bring each slot first (double transpositions), then a 3-cycle of
    // the last three: both keep the orientation.
    constexpr std::array<Perm, 4> kFirst{{{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}};
    Perm p = kFirst[lowest({0, 1, 2, 3})];
    const std::uint8_t k = rank_of(v[p[2]]) < rank_of(v[p[1]])
                               ? (rank_of(v[p[3]]) < rank_of(v[p[2]]) ? 3 : 2)
                               : (rank_of(v[p[3]]) < rank_of(v[p[1]]) ? 3 : 1);
    if (k == 2) {
        p = {p[0], p[2], p[3], p[1]};
    } else if (k == 3) {
        p = {p[0], p[3], p[1], p[2]};
    }
    return p;
}

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

/// Runs body(k, begin, end) on the `threads` consecutive pieces k of [0, count) at once; rethrows
/// the first exception a piece threw.
template <class Body>
void in_pieces(std::size_t count, unsigned threads, Body&& body) {
    std::vector<std::exception_ptr> errors(threads);
    const auto piece = [&](unsigned k) {
        try {
            body(k, count * k / threads, count * (k + 1) / threads);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> helpers;
        for (unsigned k = 1; k < threads; ++k) {
            helpers.emplace_back(piece, k);
        }
        piece(0);
    }
    for (const std::exception_ptr& e : errors) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
}

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

std::size_t list_canonically(ConcurrentMesh& mesh,
                             const Geometry& geometry,
                             unsigned threads,
                             std::vector<std::array<std::uint32_t, 4>>& tets) {
    const CanonicalOrder canonical = canonical_order(mesh, geometry.size(), threads);
    const std::vector<TetId>& order = canonical.order;
    // Each piece's solid tetrahedra are counted first, to know where its part of the list starts.
    std::vector<std::size_t> solid_before(threads + 1, 0);
    in_pieces(order.size(), threads, [&](unsigned k, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            solid_before[k + 1] += is_ghost(mesh.record(order[i]).v) ? 0 : 1;
        }
    });
    for (unsigned k = 0; k < threads; ++k) {
        solid_before[k + 1] += solid_before[k];
    }
    tets.resize(solid_before[threads]);
    in_pieces(order.size(), threads, [&](unsigned k, std::size_t begin, std::size_t end) {
        std::size_t at = solid_before[k];
        for (std::size_t i = begin; i < end; ++i) {
            const TetVertices& from = mesh.record(order[i]).v;
            if (is_ghost(from)) {
                continue;
            }
            const std::uint64_t own = canonical.renumber[order[i]];
            TetVertices v{};
            for (std::size_t g = 0; g < 4; ++g) {
                v[(own >> (2 * g)) & 3u] = from[g];
            }
            // The stored orientation mirrored, as every list of tetrahedra is handed out
            // (detail::drain_into, handedness.h).
            tets[at++] = {
                geometry.key(v[1]), geometry.key(v[0]), geometry.key(v[2]), geometry.key(v[3])};
        }
    });
    mesh.clear();
    return order.size() - tets.size();
}

}  // namespace cavity::core
