#include "cavity/core/cdt.h"

#include <numeric>
#include <string>

#include "cavity/core/cdt_validate.h"
#include "cavity/core/complex_from_tets.h"
#include "cavity/core/error.h"
#include "cavity/core/triangulate.h"

namespace cavity::core {

namespace {

std::string edge_list(const Plc& plc, const std::vector<Edge>& edges) {
    std::string s;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    for (std::size_t i = 0; i < edges.size() && i < 20; ++i) {
        s += " " + std::to_string(edges[i][0] + base) + "-" + std::to_string(edges[i][1] + base);
    }
    if (edges.size() > 20) {
        s += " ...";
    }
    return s;
}

}  // namespace

Cdt build_cdt(Plc plc, const CdtOptions& options) {
    Cdt cdt;
    if (options.protect) {
        cdt.protection = protect_edges(plc, options.max_protection_points);
    }
    std::vector<std::uint32_t> sequence(plc.points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    const Triangulation dt = triangulate(plc.points, sequence, TriangulateOptions{});
    if (!dt.duplicates.empty()) {
        const auto& d = dt.duplicates.front();
        throw Error(located_message(plc.source, std::nullopt,
                                    "points " + std::to_string(d[0] + plc.points.index_base) +
                                        " and " + std::to_string(d[1] + plc.points.index_base) +
                                        " coincide"));
    }
    const std::vector<Edge> missing = unprotected_edges(plc, dt.tets);
    if (!missing.empty()) {
        throw Error(located_message(
            plc.source, std::nullopt,
            "the PLC is not edge-protected: " + std::to_string(missing.size()) +
                " edge(s) are not Delaunay edges of its vertices:" + edge_list(plc, missing) +
                " (the flip-based CDT needs edge protection; --protect splits them)"));
    }
    ArrayStorage storage = complex_from_tets(dt.tets);
    const Geometry geometry = geometry_by_index(plc.points);
    ConstrainedFaces constrained;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        for (const auto& g : insert_polygon(storage, geometry, plc, f, constrained, cdt.counters)) {
            cdt.faces.push_back({{g[0], g[1], g[2]}, plc.facets[f].marker});
        }
    }
    cdt.tets = solid_tets(storage);
    const CdtValidation check = validate_cdt(plc, cdt.tets);
    if (!check.ok()) {
        std::string message = "internal error: the constructed mesh is not a CDT (" +
                              std::to_string(check.problem_count) + " problem(s)):";
        for (const auto& p : check.problems) {
            message += "\n  " + p;
        }
        throw Error(located_message(plc.source, std::nullopt, message));
    }
    cdt.plc = std::move(plc);
    return cdt;
}

}  // namespace cavity::core
