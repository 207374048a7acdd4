#include "cavity/core/cdt/cdt.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/cdt_vertex_insertion.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/check/complex_from_tets.h"

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

/// `dt`, the Delaunay triangulation of the PLC's points, refused when a PLC edge is missing from it
/// (the flip-based construction needs edge protection) or the PLC is invalid.
DelaunayTriangulation protected_delaunay(const Plc& plc, DelaunayTriangulation dt) {
    const std::vector<std::array<std::uint32_t, 4>> tets = dt.tets();
    const std::vector<Edge> missing = unprotected_edges(plc, tets);
    if (!missing.empty()) {
        throw Error(located_message(
            plc.source,
            std::nullopt,
            "the PLC is not edge-protected: " + std::to_string(missing.size()) +
                " edge(s) are not Delaunay edges of its vertices:" + edge_list(plc, missing) +
                " (the flip-based CDT needs edge protection; --protect splits them)"));
    }
    // Every edge was just found protected: plc_violations would search for them again.
    require_valid_protected_plc(plc);
    return dt;
}

}  // namespace

LiveCdt::Start LiveCdt::start(Plc plc, const CdtOptions& options) {
    if (!options.protect) {
        DelaunayTriangulation dt = plc_delaunay(plc);
        return {Protection{}, std::move(plc), std::move(dt)};
    }
    // Protection's own live triangulation: building the same one again from scratch cost as much
    // as the protection's insertions.
    ProtectedDelaunay p = protect_edges_live(plc, options.max_protection_points);
    return {std::move(p.protection), std::move(plc), std::move(p.triangulation)};
}

LiveCdt::LiveCdt(Plc plc, const CdtOptions& options) : LiveCdt(start(std::move(plc), options)) {}

LiveCdt::LiveCdt(Start start)
    : protection_(std::move(start.protection))
    , plc_(std::move(start.plc))
    , geometry_(geometry_by_index(plc_.points)) {
    // The live triangulation's own complex, renamed to the PLC's point indices: no facet matching.
    storage_ = protected_delaunay(plc_, std::move(start.delaunay)).release_by_index();
    ConstrainedFaces constrained;
    for (std::size_t f = 0; f < plc_.facets.size(); ++f) {
        for (const auto& g :
             insert_polygon(storage_, geometry_, plc_, f, constrained, polygon_counters_)) {
            add_face(g, static_cast<std::uint32_t>(f));
        }
    }
    for (const auto& e : plc_edges(plc_)) {
        plc_edges_.insert(e);
    }
    validate();
}

std::vector<std::array<std::uint32_t, 4>> LiveCdt::tets() const {
    return solid_tets(storage_);
}

void LiveCdt::validate() const {
    // validate_cdt rebuilds the complex from the tetrahedra and checks it (check_complex: glued,
    // positive, convex hull), so the live storage's own complex is checked again only in the
    // expensive-check build: it would prove the same of the output a second time.
    CAVITY_EXPENSIVE_CHECK(check_complex(storage_, geometry_), "the live CDT's complex");
    const CdtValidation check = validate_cdt(plc_, tets());
    if (check.ok()) {
        return;
    }
    std::string message = "internal error: the constructed mesh is not a CDT (" +
                          std::to_string(check.problem_count) + " problem(s)):";
    for (const auto& p : check.problems) {
        message += "\n  " + p;
    }
    throw InternalError(located_message(plc_.source, std::nullopt, message));
}

Cdt LiveCdt::snapshot() const {
    Cdt cdt;
    cdt.plc = plc_;
    cdt.tets = tets();
    cdt.faces = faces_;
    cdt.protection = protection_;
    cdt.counters = polygon_counters_;
    cdt.inserted = inserted_;
    cdt.insertion = counters_;
    return cdt;
}

Cdt build_cdt(Plc plc, const CdtOptions& options) {
    return LiveCdt(std::move(plc), options).snapshot();
}

}  // namespace cavity::core
