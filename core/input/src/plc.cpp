#include "cavity/core/input/plc.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "cavity/core/base/bucket_sort.h"

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
    std::vector<std::array<std::uint32_t, 2>> edges;
    const auto add = [&](std::uint32_t a, std::uint32_t b) {
        edges.push_back({std::min(a, b), std::max(a, b)});
    };
    for (const auto& s : plc.segments) {
        add(s[0], s[1]);
    }
    for (const auto& facet : plc.facets) {
        for (const auto& loop : facet.loops) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                add(loop[i], loop[(i + 1) % loop.size()]);
            }
        }
    }
    bucket_sort(edges, [](const std::array<std::uint32_t, 2>& e) { return std::size_t{e[0]}; });
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

}  // namespace cavity::core
