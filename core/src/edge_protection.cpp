#include "cavity/core/edge_protection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cavity/core/error.h"
#include "cavity/core/plc_validity.h"
#include "cavity/core/triangulate.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

std::vector<std::array<std::uint32_t, 4>> delaunay_of(const Plc& plc) {
    std::vector<std::uint32_t> sequence(plc.points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    Triangulation dt = triangulate(plc.points, sequence, TriangulateOptions{});
    if (!dt.duplicates.empty()) {
        const auto& d = dt.duplicates.front();
        throw Error(located_message(plc.source, std::nullopt,
                                    "points " + std::to_string(d[0] + plc.points.index_base) +
                                        " and " + std::to_string(d[1] + plc.points.index_base) +
                                        " coincide"));
    }
    return std::move(dt.tets);
}

/// The parameters t = k / 2^j (k odd, 1 <= j <= kLevels) in (0, 1), nearest the middle first.
/// On a segment whose direction has no common odd factor, these are the only parameters whose
/// points can have dyadic (a fortiori double) coordinates.
std::vector<std::pair<std::uint32_t, int>> dyadic_parameters() {
    constexpr int kLevels = 10;
    std::vector<std::pair<std::uint32_t, int>> out;
    for (int j = 1; j <= kLevels; ++j) {
        for (std::uint32_t k = 1; k < (1u << j); k += 2) {
            out.emplace_back(k, j);
        }
    }
    const auto distance = [](const std::pair<std::uint32_t, int>& t) {
        return std::abs(std::ldexp(static_cast<double>(t.first), -t.second) - 0.5);
    };
    std::stable_sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
        return distance(x) < distance(y);
    });
    return out;
}

/// The first point a + t(b - a), t from `parameters`, whose three coordinates are doubles exactly.
std::optional<Point3> split_point(const Point3& a,
                                  const Point3& b,
                                  const std::vector<std::pair<std::uint32_t, int>>& parameters) {
    const ExactPoint ea = exact_point(a);
    const ExactPoint d{Rational(b.x) - ea[0], Rational(b.y) - ea[1], Rational(b.z) - ea[2]};
    for (const auto& [k, j] : parameters) {
        const Rational t(Rational(k) / Rational(std::ldexp(1.0, j)));
        std::array<double, 3> c{};
        bool exact = true;
        for (std::size_t i = 0; i < 3 && exact; ++i) {
            const Rational v = ea[i] + t * d[i];
            // mpq_get_d truncates, so a representable value converts to itself and no other does.
            c[i] = v.convert_to<double>();
            exact = Rational(c[i]) == v;
        }
        if (exact) {
            return Point3{c[0], c[1], c[2]};
        }
    }
    return std::nullopt;
}

void split_edge(Plc& plc, const Edge& e, std::uint32_t m) {
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

}  // namespace

std::vector<Edge> unprotected_edges(const Plc& plc, std::span<const std::array<std::uint32_t, 4>> tets) {
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
    return unprotected_edges(plc, delaunay_of(plc));
}

Protection protect_edges(Plc& plc, std::size_t max_points) {
    Protection result;
    const auto parameters = dyadic_parameters();
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
                throw Error(located_message(plc.source, std::nullopt,
                                            "still not edge-protected after inserting " +
                                                std::to_string(max_points) + " points (" + name +
                                                ")"));
            }
            const auto m = split_point(a, b, parameters);
            if (!m) {
                throw Error(located_message(
                    plc.source, std::nullopt,
                    name + " needs a split, but no point a + t(b - a) with t = k/2^j, j <= 10, "
                           "has coordinates that are exactly doubles (move its endpoints to "
                           "coordinates with fewer significant bits)"));
            }
            const auto id = static_cast<std::uint32_t>(plc.points.size());
            plc.points.points.push_back(*m);
            result.inserted.push_back(id);
            split_edge(plc, e, id);
        }
    }
}

}  // namespace cavity::core
