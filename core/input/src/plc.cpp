#include "cavity/core/input/plc.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cavity::core {

std::string facet_name(const Plc& plc, std::size_t f) {
    const PlcFacet& facet = plc.facets[f];
    if (!facet.number) {
        return "facet " + std::to_string(f + static_cast<std::size_t>(plc.points.index_base));
    }
    if (facet.line == 0) {
        return "facet " + std::to_string(*facet.number);  // a binary file's
    }
    return "facet " + std::to_string(*facet.number) + " (line " + std::to_string(facet.line) + ")";
}

std::vector<std::array<std::uint32_t, 2>> plc_edges(const Plc& plc) {
    // Every edge once per segment or loop side that has it, visited twice: a counting sort by
    // lower end (the ends are point indices) and a sort of each end's few edges replace one
    // comparison sort of them all, which was 4.5% of a large surface mesh's run (perf,
    // refined_elephant.off: 180k sides).
    const auto for_each_side = [&plc](auto&& visit) {
        for (const auto& s : plc.segments) {
            visit(std::min(s[0], s[1]), std::max(s[0], s[1]));
        }
        for (const auto& facet : plc.facets) {
            for (const auto& loop : facet.loops) {
                for (std::size_t i = 0; i < loop.size(); ++i) {
                    const std::uint32_t a = loop[i];
                    const std::uint32_t b = loop[(i + 1) % loop.size()];
                    visit(std::min(a, b), std::max(a, b));
                }
            }
        }
    };
    // Sized by the largest end rather than the point count, so that an index the caller has not
    // yet checked against the points still sorts (and is reported by that caller).
    std::uint32_t top = 0;
    for_each_side([&top](std::uint32_t, std::uint32_t hi) { top = std::max(top, hi); });
    std::vector<std::uint32_t> next(std::size_t{top} + 2, 0);
    for_each_side([&next](std::uint32_t lo, std::uint32_t) { ++next[std::size_t{lo} + 1]; });
    for (std::size_t v = 1; v < next.size(); ++v) {
        next[v] += next[v - 1];
    }
    std::vector<std::array<std::uint32_t, 2>> edges(next.back());
    for_each_side([&](std::uint32_t lo, std::uint32_t hi) { edges[next[lo]++] = {lo, hi}; });
    // next[v] is now where v's bucket ends, and the previous bucket's end where it begins.
    std::size_t begin = 0;
    for (std::size_t v = 0; v + 1 < next.size(); ++v) {
        std::sort(edges.begin() + static_cast<std::ptrdiff_t>(begin),
                  edges.begin() + static_cast<std::ptrdiff_t>(next[v]));
        begin = next[v];
    }
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

}  // namespace cavity::core
