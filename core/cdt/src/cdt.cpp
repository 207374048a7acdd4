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
/// `edges` are the PLC's plc_edges.
DelaunayTriangulation protected_delaunay(const Plc& plc,
                                         std::span<const Edge> edges,
                                         DelaunayTriangulation dt) {
    const std::vector<std::array<std::uint32_t, 4>> tets = dt.tets();
    const std::vector<Edge> missing = unprotected_edges(edges, plc.points.size(), tets);
    if (!missing.empty()) {
        throw Error(located_message(
            plc.source,
            std::nullopt,
            "the PLC is not edge-protected: " + std::to_string(missing.size()) +
                " edge(s) are not Delaunay edges of its vertices:" + edge_list(plc, missing) +
                " (the flip-based CDT needs edge protection; --protect splits them)"));
    }
    // Every edge was just found protected: plc_violations would search for them again.
    // A checked surface (Plc::surface_checked) cannot fail the check, which cost as much as the
    // Delaunay triangulation on large surface meshes. Its faces F were proven by
    // require_valid_surface to be non-degenerate simple polygons (tested as their ear triangles)
    // of a closed manifold surface, each side had by exactly two faces, any two faces meeting
    // only in the corners and sides they share. Merging unites edge-connected, exactly coplanar
    // faces into one facet whose loops are the group's boundary (the sides one member has), only
    // when no corner ends more than two of them: vertex-disjoint simple loops, the outer one
    // enclosing the others, the region exactly the union of the members. Edge protection only
    // puts points exactly on edges: every PLC edge e lies within a side E of some face, and every
    // facet's region and plane are those of its faces. What protected_plc_violations checks:
    // - collinear corners: every facet contains a face with area;
    // - crossing loops: vertex-disjoint simple loops never cross;
    // - a hole point on a loop side: each lies strictly inside its own inner loop (merge checks
    //   it exactly), a part of the plane no other loop of the connected region enters;
    // - an edge e crossing facet f, its ends strictly on either side of f's plane: the crossing
    //   point p is interior to E and lies in some face T of f. The face S that has E meets T at
    //   p, so p is a shared corner (no corner of a simple polygon is inside its side E) or on a
    //   shared side D; D and E are sides of S through p interior to E, so D = E, which lies in
    //   T's plane, and e cannot cross it;
    // - a side e of a facet g coplanar with f, not a side of f, lying in f's region: E's interior
    //   meets some face T of f. Inside T or crossing a side of T, E and T meet improperly;
    //   otherwise E runs along a side of T and is that side, of exactly two faces. When both
    //   are members of f, E is inside f and e is no PLC edge at all; else E is a side of f, and
    //   the check skips f's own sides.
    // A .poly, or any PLC not made by prepare_surface_mesh, is checked as before.
    if (!plc.surface_checked) {
        require_valid_protected_plc(plc);
    }
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
    // The PLC's edges, built once for the protection check and the constraint set.
    const std::vector<Edge> edges = plc_edges(plc_);
    storage_ = protected_delaunay(plc_, edges, std::move(start.delaunay)).release_by_index();
    ConstrainedFaces constrained;
    for (std::size_t f = 0; f < plc_.facets.size(); ++f) {
        for (const auto& g :
             insert_polygon(storage_, geometry_, plc_, f, constrained, polygon_counters_)) {
            add_face(g, static_cast<std::uint32_t>(f));
        }
    }
    for (const auto& e : edges) {
        plc_edges_.insert(plc_edges_.end(), e);  // sorted: each goes in at the end
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
