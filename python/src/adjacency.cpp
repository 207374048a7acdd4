#include "adjacency.h"

#include <algorithm>
#include <string>

#include "cavity/core/error.h"
#include "cavity/core/tetrahedron.h"

namespace cavity::python {

namespace {

using core::kFacetVertices;

/// The facet opposite slot f, sorted: {smallest vertex, the other two packed into a 64-bit key}.
struct SortedFacet {
    std::uint32_t lowest;
    std::uint64_t rest;
};

SortedFacet sorted_facet(const std::array<std::uint32_t, 4>& tet, int f) {
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

}  // namespace

Adjacency build_adjacency(std::span<const std::array<std::uint32_t, 4>> tets,
                          std::span<const std::uint32_t> rank) {
    const std::size_t m = tets.size();
    const std::size_t point_count = rank.size();
    Adjacency out;
    out.neighbors.assign(4 * m, -1);
    out.vertex_to_simplex.assign(point_count, -1);
    const auto ranked = [&](std::size_t t) {
        const auto& v = tets[t];
        return std::array<std::uint32_t, 4>{rank[v[0]], rank[v[1]], rank[v[2]], rank[v[3]]};
    };

    // Counting sort of the half-facets by their lowest-ranked vertex. Each entry carries its key
    // (the two other ranks) so that pairing reads the buckets sequentially, never the tetrahedra.
    std::vector<std::uint32_t> begin(point_count + 1, 0);
    for (std::size_t t = 0; t < m; ++t) {
        const auto tet = ranked(t);
        for (int f = 0; f < 4; ++f) {
            ++begin[sorted_facet(tet, f).lowest + 1];
        }
    }
    for (std::size_t v = 0; v < point_count; ++v) {
        begin[v + 1] += begin[v];
    }
    std::vector<std::uint64_t> keys(4 * m);
    std::vector<std::uint32_t> halves(4 * m);
    {
        std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
        for (std::size_t t = 0; t < m; ++t) {
            const auto tet = ranked(t);
            for (int f = 0; f < 4; ++f) {
                const SortedFacet facet = sorted_facet(tet, f);
                const std::uint32_t slot = fill[facet.lowest]++;
                keys[slot] = facet.rest;
                halves[slot] = static_cast<std::uint32_t>(4 * t) + static_cast<std::uint32_t>(f);
            }
        }
    }

    // Inside a bucket (about 27 half-facets for uniform points), equal keys are the two sides of
    // one triangle.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> bucket;
    for (std::size_t v = 0; v < point_count; ++v) {
        bucket.clear();
        for (std::uint32_t k = begin[v]; k < begin[v + 1]; ++k) {
            bucket.emplace_back(keys[k], halves[k]);
        }
        std::sort(bucket.begin(), bucket.end());
        for (std::size_t k = 0; k < bucket.size();) {
            std::size_t same = k + 1;
            while (same < bucket.size() && bucket[same].first == bucket[k].first) {
                ++same;
            }
            if (same - k > 2) {
                const auto& tet = tets[bucket[k].second >> 2];
                throw core::Error("not a manifold: a triangle of tetrahedron (" +
                                  std::to_string(tet[0]) + ", " + std::to_string(tet[1]) + ", " +
                                  std::to_string(tet[2]) + ", " + std::to_string(tet[3]) +
                                  ") has " + std::to_string(same - k) + " tetrahedra");
            }
            if (same - k == 2) {
                const std::uint32_t h0 = bucket[k].second;
                const std::uint32_t h1 = bucket[k + 1].second;
                out.neighbors[h0] = static_cast<std::int32_t>(h1 >> 2);
                out.neighbors[h1] = static_cast<std::int32_t>(h0 >> 2);
            }
            k = same;
        }
    }

    for (std::size_t t = 0; t < m; ++t) {
        const auto& tet = tets[t];
        for (int f = 0; f < 4; ++f) {
            out.vertex_to_simplex[tet[static_cast<std::size_t>(f)]] = static_cast<std::int32_t>(t);
            if (out.neighbors[4 * t + static_cast<std::size_t>(f)] >= 0) {
                continue;
            }
            // kFacetVertices lists the facet with the opposite vertex on its positive side: seen
            // from outside, the hull triangle is counter-clockwise.
            const auto& s = kFacetVertices[static_cast<std::size_t>(f)];
            out.hull.push_back({static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[0])]),
                                static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[1])]),
                                static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[2])])});
        }
    }
    return out;
}

}  // namespace cavity::python
