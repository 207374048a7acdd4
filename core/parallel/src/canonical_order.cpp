#include "canonical_order.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
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

void store_canonically(ConcurrentMesh& mesh, ArrayStorage& storage, std::size_t vertices) {
    const std::size_t used = mesh.used();
    // One pass over the slots: each live tetrahedron's highest rank (its bucket; 0 marks a dead
    // slot, as no live tetrahedron has only the ghost) and its rotation, stored inverted (old facet
    // g becomes new facet (packed >> 2g) & 3).
    std::vector<std::uint32_t> top(used, 0);
    std::vector<std::uint8_t> new_facet(used, 0);
    std::vector<std::uint32_t> start(vertices + 2, 0);
    for (TetId t = 0; t < used; ++t) {
        if (!mesh.alive(t)) {
            continue;
        }
        const TetVertices& v = mesh.record(t).v;
        top[t] = top_rank(v);
        ++start[top[t] + 1];
        const Perm p = canonical_perm(v);
        new_facet[t] = static_cast<std::uint8_t>((0 << (2 * p[0])) | (1 << (2 * p[1])) |
                                                 (2 << (2 * p[2])) | (3 << (2 * p[3])));
    }
    for (std::size_t b = 1; b < start.size(); ++b) {
        start[b] += start[b - 1];
    }
    const std::size_t live = start.back();
    // Counting sort on the highest rank, then the few tetrahedra sharing one by their other ranks.
    std::vector<TetId> order(live);
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        for (TetId t = 0; t < used; ++t) {
            if (top[t] != 0) {
                order[next[top[t]]++] = t;
            }
        }
    }
    std::vector<std::pair<std::array<std::uint32_t, 3>, TetId>> bucket;
    for (std::size_t b = 1; b + 1 < start.size(); ++b) {
        if (start[b + 1] - start[b] < 2) {
            continue;
        }
        bucket.clear();
        for (std::size_t i = start[b]; i < start[b + 1]; ++i) {
            bucket.emplace_back(lower_key(mesh.record(order[i]).v, static_cast<std::uint32_t>(b)),
                                order[i]);
        }
        std::sort(bucket.begin(), bucket.end());
        for (std::size_t i = 0; i < bucket.size(); ++i) {
            order[start[b] + i] = bucket[i].second;
        }
    }
    std::vector<std::uint32_t>().swap(start);
    // Old slot -> new slot; dead slots go after the live ones, in any order.
    std::vector<TetId>& new_slot = top;  // reused
    {
        std::size_t dead = live;
        for (TetId t = 0; t < used; ++t) {
            if (top[t] == 0) {
                new_slot[t] = static_cast<TetId>(dead++);
            }
        }
    }
    for (std::size_t i = 0; i < live; ++i) {
        new_slot[order[i]] = static_cast<TetId>(i);
    }
    std::vector<TetId>().swap(order);
    // Rotate every live record and renumber its neighbours in place, then move the records to their
    // new slots by following the permutation's cycles: no second copy of the mesh at the peak.
    std::vector<ArrayRecord> records = mesh.take_records();
    records.resize(used);
    for (TetId t = 0; t < used; ++t) {
        if (!mesh.alive(t)) {
            continue;
        }
        const ArrayRecord old = records[t];
        const std::uint8_t inverse = new_facet[t];
        ArrayRecord& r = records[t];
        for (std::size_t g = 0; g < 4; ++g) {
            const std::size_t s = (inverse >> (2 * g)) & 3u;
            r.v[s] = old.v[g];
            const HalfFacet h = old.n[g];
            const TetId far = tet_of(h);
            r.n[s] = half_facet(new_slot[far], (new_facet[far] >> (2 * facet_of(h))) & 3);
        }
    }
    mesh.clear();
    for (TetId t = 0; t < used; ++t) {
        while (new_slot[t] != t) {
            const TetId to = new_slot[t];
            std::swap(records[t], records[to]);
            std::swap(new_slot[t], new_slot[to]);
        }
    }
    records.resize(live);
    storage.assign(std::move(records), vertices);
}

}  // namespace cavity::core
