#include "cavity/core/io/tet_adjacency.h"

#include <algorithm>
#include <limits>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

namespace {

/// The facet opposite slot f, sorted: {smallest vertex, the other two packed into a 64-bit key}.
struct SortedFacet {
    std::uint32_t lowest;
    std::uint64_t rest;
};

SortedFacet sorted_facet(const Tet& tet, int f) {
    const auto& s = kFacetVertices[static_cast<std::size_t>(f)];
    std::uint32_t a = tet[static_cast<std::size_t>(s[0])];
    std::uint32_t b = tet[static_cast<std::size_t>(s[1])];
    std::uint32_t c = tet[static_cast<std::size_t>(s[2])];
    if (a > b) {
        std::swap(a, b);
    }
    if (b > c) {
        std::swap(b, c);
    }
    if (a > b) {
        std::swap(a, b);
    }
    return {a, (std::uint64_t{b} << 32) | c};
}

/// Turns counts (in [1, n]) into bucket starts: begin[v] = sum of the counts below v.
void prefix_sums(std::vector<std::uint32_t>& begin) {
    for (std::size_t v = 1; v < begin.size(); ++v) {
        begin[v] += begin[v - 1];
    }
}

/// The tetrahedra in rank space, sorted by lowest rank (a counting sort), with their input ids.
void sort_by_rank(std::span<const Tet> tets,
                  std::span<const std::uint32_t> rank,
                  std::vector<Tet>& ranked,
                  std::vector<Tet>& simplices) {
    std::vector<std::uint32_t> begin(rank.size() + 1, 0);
    for (const Tet& t : tets) {
        ++begin[std::min({rank[t[0]], rank[t[1]], rank[t[2]], rank[t[3]]}) + 1];
    }
    prefix_sums(begin);
    ranked.resize(tets.size());
    simplices.resize(tets.size());
    for (const Tet& t : tets) {
        const Tet r{rank[t[0]], rank[t[1]], rank[t[2]], rank[t[3]]};
        const std::uint32_t slot = begin[std::min({r[0], r[1], r[2], r[3]})]++;
        ranked[slot] = r;
        simplices[slot] = t;
    }
}

}  // namespace

std::vector<std::int32_t> match_facets(std::span<const Tet> tets,
                                       std::size_t point_count,
                                       std::span<const Tet> names) {
    const std::size_t m = tets.size();
    std::vector<std::int32_t> neighbors(4 * m, -1);

    // Counting sort of the half-facets by their lowest vertex. Each entry carries its key (the
    // two other vertices) so that pairing reads the buckets sequentially, never the tetrahedra.
    std::vector<std::uint32_t> begin(point_count + 1, 0);
    for (const Tet& t : tets) {
        for (int f = 0; f < 4; ++f) {
            ++begin[sorted_facet(t, f).lowest + 1];
        }
    }
    prefix_sums(begin);
    std::vector<std::uint64_t> keys(4 * m);
    std::vector<std::uint32_t> halves(4 * m);
    {
        std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
        for (std::size_t t = 0; t < m; ++t) {
            for (int f = 0; f < 4; ++f) {
                const SortedFacet facet = sorted_facet(tets[t], f);
                const std::uint32_t slot = fill[facet.lowest]++;
                keys[slot] = facet.rest;
                halves[slot] = static_cast<std::uint32_t>(4 * t) + static_cast<std::uint32_t>(f);
            }
        }
    }

    // Inside a bucket (about 27 half-facets for uniform points; thousands around the centre of
    // cospherical input), equal keys are the two sides of one triangle. They are paired through a
    // small open-addressing table, cheaper than sorting the bucket; a slot belongs to the current
    // bucket when its stamp is the bucket's, so the table is never cleared.
    constexpr std::uint32_t kPaired = 0xFFFF'FFFFu;

    struct Slot {
        std::uint64_t key = 0;
        std::uint32_t half = 0;
        std::uint32_t stamp = 0;  // bucket v + 1; 0: never used
    };

    std::vector<Slot> table(64);
    for (std::size_t v = 0; v < point_count; ++v) {
        const std::uint32_t size = begin[v + 1] - begin[v];
        std::size_t capacity = 16;
        while (capacity < 2 * static_cast<std::size_t>(size)) {
            capacity *= 2;
        }
        if (table.size() < capacity) {
            table.assign(capacity, Slot{});
        }
        const std::size_t mask = capacity - 1;
        const auto stamp = static_cast<std::uint32_t>(v + 1);
        for (std::uint32_t k = begin[v]; k < begin[v + 1]; ++k) {
            const std::uint64_t key = keys[k];
            const std::uint32_t h = halves[k];
            std::size_t i = static_cast<std::size_t>((key * 0x9E37'79B9'7F4A'7C15ull) >> 40) & mask;
            while (table[i].stamp == stamp && table[i].key != key) {
                i = (i + 1) & mask;
            }
            Slot& slot = table[i];
            if (slot.stamp != stamp) {
                slot = {key, h, stamp};
                continue;
            }
            if (slot.half == kPaired) {
                const Tet& t = (names.empty() ? tets : names)[h >> 2];
                throw Error("not a manifold: a triangle of tetrahedron (" + std::to_string(t[0]) +
                            ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ", " +
                            std::to_string(t[3]) + ") has more than two tetrahedra");
            }
            neighbors[slot.half] = static_cast<std::int32_t>(h >> 2);
            neighbors[h] = static_cast<std::int32_t>(slot.half >> 2);
            slot.half = kPaired;
        }
    }
    return neighbors;
}

Adjacency build_adjacency(std::span<const Tet> tets, std::span<const std::uint32_t> rank) {
    const std::size_t m = tets.size();
    const std::size_t point_count = rank.size();
    Adjacency out;
    std::vector<Tet> ranked;
    sort_by_rank(tets, rank, ranked, out.simplices);
    out.neighbors = match_facets(ranked, point_count, out.simplices);
    out.vertex_to_simplex.assign(point_count, -1);

    for (std::size_t t = 0; t < m; ++t) {
        const Tet& tet = out.simplices[t];
        for (std::size_t f = 0; f < 4; ++f) {
            out.vertex_to_simplex[tet[f]] = static_cast<std::int32_t>(t);
            if (out.neighbors[4 * t + f] >= 0) {
                continue;
            }
            out.hull.push_back(hull_triangle(tet, f));
        }
    }
    return out;
}

VertexNeighbors vertex_neighbors(std::span<const Tet> tets, std::size_t point_count) {
    // incident[begin[v] .. begin[v + 1]): the tetrahedra having v as a vertex.
    std::vector<std::size_t> begin(point_count + 1, 0);
    for (const Tet& t : tets) {
        for (std::uint32_t v : t) {
            ++begin[v + 1];
        }
    }
    for (std::size_t v = 1; v <= point_count; ++v) {
        begin[v] += begin[v - 1];
    }
    std::vector<std::uint32_t> incident(begin.back());
    {
        std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
        for (std::size_t t = 0; t < tets.size(); ++t) {
            for (std::uint32_t v : tets[t]) {
                incident[fill[v]++] = static_cast<std::uint32_t>(t);
            }
        }
    }
    VertexNeighbors out;
    out.indptr.reserve(point_count + 1);
    out.indptr.push_back(0);
    std::vector<std::int32_t> around;
    for (std::size_t v = 0; v < point_count; ++v) {
        around.clear();
        for (std::size_t k = begin[v]; k < begin[v + 1]; ++k) {
            for (std::uint32_t u : tets[incident[k]]) {
                if (u != v) {
                    around.push_back(static_cast<std::int32_t>(u));
                }
            }
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        out.indices.insert(out.indices.end(), around.begin(), around.end());
        if (out.indices.size() >
            static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
            throw Error("vertex_neighbors: more than 2^31 - 1 vertex-edge incidences");
        }
        out.indptr.push_back(static_cast<std::int32_t>(out.indices.size()));
    }
    return out;
}

}  // namespace cavity::core
