#include "cavity/core/cdt/edge_protection.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "exact_plane.h"

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

namespace {

using predicates::GenericPoint3;
using predicates::SegmentParameterPoint;

bool same(const Point3& p, const Point3& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

/// The implicit point halfway between p and q, two points of the segment of base edge ab (the
/// edge between input points that p or q, an implicit point, was made on): parameters are dyadic,
/// n / 2^j, so the midpoint's is again dyadic with doubles for numerator and denominator.
/// nullopt when the denominator would pass 2^53 (53 halvings of one edge), where the numerator
/// stops being exact.
std::optional<SegmentParameterPoint> implicit_midpoint(const GenericPoint3& p,
                                                       const GenericPoint3& q) {
    const auto* base = std::get_if<SegmentParameterPoint>(&p);
    if (base == nullptr) {
        base = &std::get<SegmentParameterPoint>(q);
    }
    // The parameter of an endpoint: its own when implicit, else 0 or 1 for the base's ends
    // (the pieces of a base edge end only at its ends and at points made on it).
    const auto parameter = [&](const GenericPoint3& g) -> std::pair<double, double> {
        if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
            CAVITY_ASSERT(same(s->a, base->a) && same(s->b, base->b),
                          "the pieces of a protected edge share its base");
            return {s->numerator, s->denominator};
        }
        const Point3& x = std::get<Point3>(g);
        CAVITY_ASSERT(same(x, base->a) || same(x, base->b),
                      "a piece of a protected edge ends on its base");
        return {same(x, base->a) ? 0.0 : 1.0, 1.0};
    };
    const auto [np, dp] = parameter(p);
    const auto [nq, dq] = parameter(q);
    // (np/dp + nq/dq) / 2 = (np (D/dp) + nq (D/dq)) / 2D with D = max(dp, dq): integers at most
    // 2D scaled by powers of two, so every operation is exact while 2D <= 2^53.
    const double d = std::max(dp, dq);
    if (2 * d > 0x1p53) {
        return std::nullopt;
    }
    return SegmentParameterPoint{base->a, base->b, np * (d / dp) + nq * (d / dq), 2 * d};
}

}  // namespace

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
            const GenericPoint3 ga = generic_point(plc.points, e[0]);
            const GenericPoint3 gb = generic_point(plc.points, e[1]);
            const bool explicit_ends =
                std::holds_alternative<Point3>(ga) && std::holds_alternative<Point3>(gb);
            // A point with double coordinates when the edge's ends are input points and one
            // exists; else the implicit midpoint, exactly on the edge (sos.h: its key is its
            // index, after every older point's).
            std::optional<GenericPoint3> m;
            if (explicit_ends) {
                if (const auto d = protection_point(a, b)) {
                    m = *d;
                }
            }
            if (!m) {
                const auto s = explicit_ends ? predicates::segment_parameter_point(a, b, 1, 2)
                                             : implicit_midpoint(ga, gb);
                if (!s) {
                    throw Error(located_message(
                        plc.source,
                        std::nullopt,
                        name + " needs a split, but its pieces are already 2^-53 of it"));
                }
                if (plc.points.exact.empty()) {
                    plc.points.exact.assign(plc.points.points.begin(), plc.points.points.end());
                }
                m = *s;
            }
            const auto id = static_cast<std::uint32_t>(plc.points.size());
            plc.points.points.push_back(rounded_point(*m));
            if (!plc.points.exact.empty()) {
                plc.points.exact.push_back(*m);
            }
            result.inserted.push_back(id);
            split_plc_edge(plc, e, id);
        }
    }
}

}  // namespace cavity::core
