#include "cavity/core/cdt/edge_protection.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/live/delaunay_triangulation.h"

namespace cavity::core {

DelaunayTriangulation plc_delaunay(const Plc& plc) {
    std::vector<std::uint32_t> sequence(plc.points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    DelaunayTriangulation dt(plc.points, sequence, TriangulateOptions{});
    if (!dt.duplicates().empty()) {
        const auto& d = dt.duplicates().front();
        throw Error(located_message(plc.source,
                                    std::nullopt,
                                    "points " + std::to_string(d[0] + plc.points.index_base) +
                                        " and " + std::to_string(d[1] + plc.points.index_base) +
                                        " coincide"));
    }
    return dt;
}

void split_plc_edge(Plc& plc, const Edge& e, std::uint32_t m) {
    for (auto& s : plc.segments) {
        if (std::min(s[0], s[1]) == e[0] && std::max(s[0], s[1]) == e[1]) {
            const std::uint32_t other = s[1];
            s[1] = m;
            plc.segments.push_back({m, other});
        }
    }
    for (auto& facet : plc.facets) {
        for (auto& loop : facet.loops) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const std::uint32_t p = loop[i];
                const std::uint32_t q = loop[(i + 1) % loop.size()];
                if (std::min(p, q) == e[0] && std::max(p, q) == e[1]) {
                    loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), m);
                    ++i;
                }
            }
        }
    }
}

std::vector<Edge> unprotected_edges(const Plc& plc,
                                    std::span<const std::array<std::uint32_t, 4>> tets) {
    std::vector<Edge> present;
    present.reserve(tets.size() * 6);
    for (const auto& t : tets) {
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = i + 1; j < 4; ++j) {
                present.push_back({std::min(t[i], t[j]), std::max(t[i], t[j])});
            }
        }
    }
    std::sort(present.begin(), present.end());
    std::vector<Edge> missing;
    for (const Edge& e : plc_edges(plc)) {
        if (!std::binary_search(present.begin(), present.end(), e)) {
            missing.push_back(e);
        }
    }
    return missing;
}

std::vector<Edge> unprotected_edges(const Plc& plc) {
    return unprotected_edges(plc, plc_delaunay(plc).tets());
}

Protection protect_edges(Plc& plc, std::size_t max_points) {
    Protection result;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    for (;;) {
        ++result.rounds;
        const std::vector<Edge> missing = unprotected_edges(plc);
        if (missing.empty()) {
            return result;
        }
        if (result.rounds == 1) {
            // Splitting never protects an edge that a point lies on or another edge crosses; later
            // rounds split only pieces of these edges, which inherit the check.
            require_edges_meet_properly(plc, missing);
        }
        for (const Edge& e : missing) {
            const auto& a = plc.points.points[e[0]];
            const auto& b = plc.points.points[e[1]];
            const std::string name =
                "edge " + std::to_string(e[0] + base) + "-" + std::to_string(e[1] + base);
            if (result.inserted.size() >= max_points) {
                throw Error(located_message(plc.source,
                                            std::nullopt,
                                            "still not edge-protected after inserting " +
                                                std::to_string(max_points) + " points (" + name +
                                                ")"));
            }
            const auto m = protection_point(a, b);
            if (!m) {
                throw Error(located_message(
                    plc.source,
                    std::nullopt,
                    name + " needs a split, but no point strictly inside it has coordinates that "
                           "are doubles exactly (snap its endpoints to a binary grid, e.g. "
                           "multiples of 2^-20, to make them)"));
            }
            const auto id = static_cast<std::uint32_t>(plc.points.size());
            plc.points.points.push_back(*m);
            result.inserted.push_back(id);
            split_plc_edge(plc, e, id);
        }
    }
}

}  // namespace cavity::core
