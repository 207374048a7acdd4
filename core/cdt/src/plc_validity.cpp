#include "cavity/core/cdt/plc_validity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "box_grid.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/edge_protection.h"
#include "cavity/predicates/generic_predicates.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

Box loop_box(const Plc& plc, const std::vector<std::uint32_t>& loop) {
    Box box;
    for (std::uint32_t c : loop) {
        box.add(plc.points.points[c]);
    }
    return box;
}

/// A PLC edge and the facets that have it as a side (none: an explicit segment only).
struct OwnedEdge {
    Edge edge;
    std::vector<std::size_t> owners;
};

std::vector<OwnedEdge> owned_edges(const Plc& plc) {
    // Each edge once with its owners, in plc_edges' order, from one sort of (edge, owner) pairs:
    // a segment is owned by kSegment, after every facet, so each run lists its facets first.
    constexpr std::size_t kSegment = std::numeric_limits<std::size_t>::max();
    std::vector<std::pair<Edge, std::size_t>> sides;
    for (const auto& s : plc.segments) {
        sides.push_back({{std::min(s[0], s[1]), std::max(s[0], s[1])}, kSegment});
    }
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        for (const auto& loop : plc.facets[f].loops) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const std::uint32_t a = loop[i];
                const std::uint32_t b = loop[(i + 1) % loop.size()];
                sides.push_back({{std::min(a, b), std::max(a, b)}, f});
            }
        }
    }
    std::sort(sides.begin(), sides.end());
    sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
    std::vector<OwnedEdge> all;
    for (const auto& [e, owner] : sides) {
        if (all.empty() || all.back().edge != e) {
            all.push_back({e, {}});
        }
        if (owner != kSegment) {
            all.back().owners.push_back(owner);
        }
    }
    return all;
}

std::vector<Edge> facet_sides(const PlcFacet& facet) {
    std::vector<Edge> sides;
    for (const auto& loop : facet.loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::uint32_t a = loop[i];
            const std::uint32_t b = loop[(i + 1) % loop.size()];
            sides.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(sides.begin(), sides.end());
    return sides;
}

std::string loop_name(const Plc& plc, const std::vector<std::uint32_t>& loop, std::size_t index) {
    std::string s = "polygon " + std::to_string(index + 1) + " (corners";
    for (std::size_t i = 0; i < loop.size() && i < 6; ++i) {
        s += " " + std::to_string(loop[i] + static_cast<std::uint32_t>(plc.points.index_base));
    }
    return s + (loop.size() > 6 ? " ...)" : ")");
}

/// Collects the messages of one facet, each located at the facet's line.
class FacetReport {
public:
    FacetReport(const Plc& plc, std::size_t f, std::vector<std::string>& out)
        : plc_(plc), facet_(plc.facets[f]), index_(f), out_(out) {}

    /// The facet is named only when reported: naming each of a surface mesh's facets cost more
    /// than checking most of them.
    void add(const std::string& what) {
        const auto base = static_cast<std::size_t>(plc_.points.index_base);
        out_.push_back(located_message(
            plc_.source,
            facet_.line == 0 ? std::nullopt : std::optional<std::size_t>(facet_.line),
            "facet " + std::to_string(facet_.number.value_or(index_ + base)) + ": " + what));
    }

private:
    const Plc& plc_;
    const PlcFacet& facet_;
    std::size_t index_;
    std::vector<std::string>& out_;
};

std::string edge_name(const Plc& plc, const Edge& e) {
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    return "edge " + std::to_string(e[0] + base) + "-" + std::to_string(e[1] + base);
}

/// True when every corner of facet g lies in the plane `side` measures.
template <class Side>
bool coplanar(const PlcFacet& g, const Side& side) {
    for (const auto& loop : g.loops) {
        for (std::uint32_t c : loop) {
            if (side(c) != 0) {
                return false;
            }
        }
    }
    return true;
}

/// Loops of one facet must overlap only by nesting.
void check_loops(const Plc& plc, const PlcFacet& facet, int drop, FacetReport& report) {
    std::vector<Box> boxes;
    for (const auto& loop : facet.loops) {
        boxes.push_back(loop_box(plc, loop));
    }
    for (std::size_t i = 0; i < facet.loops.size(); ++i) {
        for (std::size_t j = i + 1; j < facet.loops.size(); ++j) {
            if (!boxes[i].meets(boxes[j])) {
                continue;
            }
            const SidePieces a = side_pieces(plc, facet.loops[i], facet.loops[j], drop);
            const SidePieces b = side_pieces(plc, facet.loops[j], facet.loops[i], drop);
            if ((a.inside > 0 && a.outside > 0) || (b.inside > 0 && b.outside > 0)) {
                report.add(loop_name(plc, facet.loops[i], i) + " and " +
                           loop_name(plc, facet.loops[j], j) +
                           " cross: they overlap without one enclosing the other");
            }
        }
    }
}

void check_holes(const Plc& plc, const PlcFacet& facet, int drop, FacetReport& report) {
    for (std::size_t h = 0; h < facet.holes.size(); ++h) {
        for (std::size_t i = 0; i < facet.loops.size(); ++i) {
            if (loop_position(plc, facet.loops[i], drop, exact_point(facet.holes[h])) ==
                LoopPosition::kOnBoundary) {
                report.add("hole point " +
                           std::to_string(h + static_cast<std::size_t>(plc.points.index_base)) +
                           " lies on a side of " + loop_name(plc, facet.loops[i], i));
            }
        }
    }
}

/// True when p lies on the open segment ab.
bool inside_segment(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p) {
    const ExactPoint d = minus(b, a);
    const ExactPoint w = minus(p, a);
    if (!is_zero(cross(w, d))) {
        return false;
    }
    const Rational s = dot(w, d);
    return s > 0 && s < dot(d, d);
}

/// True when segments ab and cd (four distinct points) cross at one point interior to both: they
/// are coplanar, not collinear, and each separates the other's endpoints strictly in their plane.
bool segments_cross(const ExactPoint& a,
                    const ExactPoint& b,
                    const ExactPoint& c,
                    const ExactPoint& d) {
    const ExactPoint u = minus(b, a);
    const ExactPoint n = cross(u, minus(d, c));
    if (is_zero(n) || dot(n, minus(c, a)) != 0) {
        return false;  // parallel (overlaps are points inside segments) or skew
    }
    const auto side = [&](const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
        const Rational s = dot(n, cross(minus(q, p), minus(r, p)));
        return s > 0 ? 1 : s < 0 ? -1 : 0;
    };
    return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

}  // namespace

std::vector<std::string> edge_violations(const Plc& plc,
                                         std::span<const std::array<std::uint32_t, 2>> edges) {
    return edge_violations(plc, plc_edges(plc), edges);
}

std::vector<std::string> edge_violations(const Plc& plc,
                                         std::span<const std::array<std::uint32_t, 2>> all,
                                         std::span<const std::array<std::uint32_t, 2>> edges) {
    std::vector<std::string> out;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    const auto& pts = plc.points.points;
    const auto box_of = [&](std::uint32_t i, std::uint32_t j) {
        Box box;
        box.add(pts[i]);
        box.add(pts[j]);
        return box;
    };
    const auto ids = [&](const Edge& e) {
        return std::to_string(e[0] + base) + "-" + std::to_string(e[1] + base);
    };
    // Candidates come from grids of the points' and the edges' boxes, in index order (the order
    // of the messages): testing each edge against every point and edge was quadratic, and the
    // largest part of edge protection's checks on surface meshes.
    Box bounds;
    std::vector<Box> point_boxes;
    point_boxes.reserve(pts.size());
    for (std::uint32_t v = 0; v < pts.size(); ++v) {
        bounds.add(pts[v]);
        point_boxes.push_back(box_of(v, v));
    }
    std::vector<Box> edge_boxes;
    edge_boxes.reserve(all.size());
    for (const Edge& f : all) {
        edge_boxes.push_back(box_of(f[0], f[1]));
    }
    BoxGrid point_grid(bounds, point_boxes);
    BoxGrid edge_grid(bounds, edge_boxes);
    // Exact orientations settle most candidates without rationals: four points that are not
    // coplanar are no two crossing segments, and a point off the plane of a, b and some other
    // point is off line ab. Two corners of the bounding box serve as those other points; when
    // both lie in the plane (or orient3d is zero for any reason) the rationals decide.
    using predicates::GenericPoint3;
    using predicates::Sign;
    const std::array<GenericPoint3, 2> witnesses{
        GenericPoint3(Point3{bounds.lo[0], bounds.lo[1], bounds.hi[2]}),
        GenericPoint3(Point3{bounds.hi[0], bounds.lo[1], bounds.lo[2]})};
    const auto off_line = [&](const GenericPoint3& a, const GenericPoint3& b, std::uint32_t v) {
        const GenericPoint3 p = generic_point(plc.points, v);
        return std::any_of(witnesses.begin(), witnesses.end(), [&](const GenericPoint3& x) {
            return predicates::orient3d(a, b, p, x) != Sign::kZero;
        });
    };
    std::vector<std::size_t> near_points;
    std::vector<std::size_t> near_edges;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const Edge& e = edges[k];
        const Box box = box_of(e[0], e[1]);
        const GenericPoint3 ga = generic_point(plc.points, e[0]);
        const GenericPoint3 gb = generic_point(plc.points, e[1]);
        const ExactPoint a = exact_point(plc.points, e[0]);
        const ExactPoint b = exact_point(plc.points, e[1]);
        point_grid.near(box, k, near_points);
        std::sort(near_points.begin(), near_points.end());
        for (const std::size_t i : near_points) {
            const auto v = static_cast<std::uint32_t>(i);
            if (v != e[0] && v != e[1] && box.meets(point_boxes[v]) && !off_line(ga, gb, v) &&
                inside_segment(a, b, exact_point(plc.points, v))) {
                out.push_back(located_message(
                    plc.source,
                    std::nullopt,
                    "point " + std::to_string(v + base) + " lies inside edge " + ids(e)));
            }
        }
        edge_grid.near(box, k, near_edges);
        std::sort(near_edges.begin(), near_edges.end());
        for (const std::size_t i : near_edges) {
            const Edge& f = all[i];
            if (f[0] == e[0] || f[0] == e[1] || f[1] == e[0] || f[1] == e[1] ||
                !box.meets(edge_boxes[i]) ||
                predicates::orient3d(
                    ga, gb, generic_point(plc.points, f[0]), generic_point(plc.points, f[1])) !=
                    Sign::kZero) {
                continue;
            }
            if (segments_cross(
                    a, b, exact_point(plc.points, f[0]), exact_point(plc.points, f[1]))) {
                out.push_back(located_message(
                    plc.source, std::nullopt, "edges " + ids(e) + " and " + ids(f) + " cross"));
            }
        }
    }
    return out;
}

std::vector<std::string> plc_violations(
    const Plc& plc, std::span<const std::array<std::uint32_t, 4>> delaunay_tets) {
    std::vector<std::string> out;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    const std::vector<Edge> missing = unprotected_edges(plc, delaunay_tets);
    if (!missing.empty()) {
        std::string s = "cannot check the PLC: " + std::to_string(missing.size()) +
                        " edge(s) are not Delaunay edges of its points (protect them first):";
        for (std::size_t i = 0; i < missing.size() && i < 20; ++i) {
            s += " " + std::to_string(missing[i][0] + base) + "-" +
                 std::to_string(missing[i][1] + base);
        }
        out.push_back(located_message(plc.source, std::nullopt, s));
        return out;
    }
    return protected_plc_violations(plc);
}

std::vector<std::string> protected_plc_violations(const Plc& plc) {
    std::vector<std::string> out;
    const std::vector<OwnedEdge> edges = owned_edges(plc);
    std::vector<Box> edge_boxes;
    edge_boxes.reserve(edges.size());
    for (const OwnedEdge& e : edges) {
        Box box;
        box.add(plc.points.points[e.edge[0]]);
        box.add(plc.points.points[e.edge[1]]);
        edge_boxes.push_back(box);
    }
    Box bounds;
    for (const Point3& p : plc.points.points) {
        bounds.add(p);
    }
    BoxGrid grid(bounds, edge_boxes);
    const auto& pts = plc.points.points;
    RationalPoints rational(plc.points);
    // By point: the facet (index + 1) whose plane its side was last found for, and the side.
    std::vector<std::pair<std::uint32_t, int>> side_of(plc.points.size(), {0, 0});
    std::vector<std::size_t> near;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        const PlcFacet& facet = plc.facets[f];
        FacetReport report(plc, f, out);
        const auto plane = ExactPlane::of_facet(plc, facet);
        if (!plane) {
            report.add("its corners are collinear");
            continue;
        }
        check_loops(plc, facet, plane->dropped_axis(), report);
        check_holes(plc, facet, plane->dropped_axis(), report);
        Box box;
        for (const auto& loop : facet.loops) {
            for (std::uint32_t c : loop) {
                box.add(pts[c]);
            }
        }
        const std::vector<Edge> sides = facet_sides(facet);
        // A corner lies in the plane: no predicate needed (on a surface mesh most nearby edges
        // end at one, and an exact zero is orient3d's most expensive answer). Every other point's
        // side is kept for the facet: a point ends several nearby edges.
        const auto stamp = static_cast<std::uint32_t>(f + 1);
        for (const auto& loop : facet.loops) {
            for (std::uint32_t c : loop) {
                side_of[c] = {stamp, 0};
            }
        }
        const auto side = [&](std::uint32_t v) {
            if (side_of[v].first != stamp) {
                side_of[v] = {stamp, static_cast<int>(plane->side(generic_point(plc.points, v)))};
            }
            return side_of[v].second;
        };
        const FacetRegion region(plc, facet, *plane);
        // Whether a facet is coplanar with this one, by facet, asked once: a facet split by edge
        // protection has each piece of a side in this plane ask again.
        std::map<std::size_t, bool> coplanar_owner;
        grid.near(box, f, near);
        std::sort(near.begin(), near.end());
        for (std::size_t i : near) {
            const OwnedEdge& e = edges[i];
            if (!edge_boxes[i].meets(box) ||
                std::binary_search(sides.begin(), sides.end(), e.edge)) {
                continue;
            }
            const int sp = side(e.edge[0]);
            const int sq = side(e.edge[1]);
            // By the precondition the edge meets no side of the facet except at a shared corner,
            // so the point tested below is on no loop side and decides for the whole edge.
            if (sp == 0 && sq == 0) {
                // An edge lying in the region is legal (a slit, or the foot of a wall: the edge is
                // a cell, and the CDT has it as an edge among the polygon's triangles), unless it
                // is a side of a coplanar facet, whose region then overlaps this one.
                // An edge in the region is inside the facet's box: a cheap, exact filter, first.
                if (!box.contains(edge_boxes[i])) {
                    continue;
                }
                const auto g = std::find_if(e.owners.begin(), e.owners.end(), [&](std::size_t o) {
                    const auto [known, fresh] = coplanar_owner.emplace(o, false);
                    if (fresh) {
                        known->second = coplanar(plc.facets[o], side);
                    }
                    return known->second;
                });
                if (g == e.owners.end()) {
                    continue;
                }
                const ExactPoint& a = rational[e.edge[0]];
                const ExactPoint& b = rational[e.edge[1]];
                ExactPoint mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
                if (region.contains(std::move(mid))) {
                    report.add(edge_name(plc, e.edge) + ", a side of " + facet_name(plc, *g) +
                               ", lies inside it: the two coplanar facets overlap");
                }
            } else if (sp * sq < 0 && crosses_facet_region(plc,
                                                           facet,
                                                           *plane,
                                                           region,
                                                           generic_point(plc.points, e.edge[0]),
                                                           generic_point(plc.points, e.edge[1]))) {
                report.add(edge_name(plc, e.edge) +
                           (e.owners.empty()
                                ? " (a segment)"
                                : " (a side of " + facet_name(plc, e.owners[0]) + ")") +
                           " crosses it");
            }
        }
    }
    return out;
}

namespace {

void throw_violations(const std::vector<std::string>& problems, const std::string& what) {
    std::string message = what + " (" + std::to_string(problems.size()) + " violation(s)):";
    for (std::size_t i = 0; i < problems.size() && i < 20; ++i) {
        message += "\n  " + problems[i];
    }
    if (problems.size() > 20) {
        message += "\n  ...";
    }
    throw Error(message);
}

}  // namespace

void require_valid_plc(const Plc& plc,
                       std::span<const std::array<std::uint32_t, 4>> delaunay_tets) {
    const std::vector<std::string> problems = plc_violations(plc, delaunay_tets);
    if (!problems.empty()) {
        throw_violations(problems, "the input is not a piecewise linear complex");
    }
}

void require_valid_protected_plc(const Plc& plc) {
    const std::vector<std::string> problems = protected_plc_violations(plc);
    if (!problems.empty()) {
        throw_violations(problems, "the input is not a piecewise linear complex");
    }
}

void require_edges_meet_properly(const Plc& plc,
                                 std::span<const std::array<std::uint32_t, 2>> all,
                                 std::span<const std::array<std::uint32_t, 2>> edges) {
    const std::vector<std::string> problems = edge_violations(plc, all, edges);
    if (!problems.empty()) {
        throw_violations(problems,
                         "the input is not a piecewise linear complex, and splitting cannot "
                         "protect its edges");
    }
}

}  // namespace cavity::core
