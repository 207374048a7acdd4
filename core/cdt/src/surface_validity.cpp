#include "cavity/core/cdt/surface_validity.h"

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>

#include "box_grid.h"
#include "cavity/core/base/bucket_sort.h"
#include "cavity/core/base/error.h"
#include "ear_clipping.h"
#include "exact_plane.h"
#include "triangle_intersection.h"

namespace cavity::core {

namespace {

/// How many defects of each kind an error message lists before "and N more".
constexpr std::size_t kShown = 10;

void find_edge_defects(const Plc& plc, SurfaceDefects& defects) {
    std::vector<std::pair<std::array<std::uint32_t, 2>, std::size_t>> sides;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        for (const auto& loop : plc.facets[f].loops) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const std::uint32_t a = loop[i];
                const std::uint32_t b = loop[(i + 1) % loop.size()];
                if (a != b) {
                    sides.push_back({{std::min(a, b), std::max(a, b)}, f});
                }
            }
        }
    }
    bucket_sort(sides, [](const auto& side) { return std::size_t{side.first[0]}; });
    for (std::size_t i = 0; i < sides.size();) {
        SurfaceEdge edge{sides[i].first, {}};
        for (; i < sides.size() && sides[i].first == edge.edge; ++i) {
            edge.facets.push_back(sides[i].second);
        }
        if (edge.facets.size() == 1) {
            defects.open_edges.push_back(std::move(edge));
        } else if (edge.facets.size() > 2) {
            defects.non_manifold_edges.push_back(std::move(edge));
        }
    }
}

void find_coincident_points(const Plc& plc, SurfaceDefects& defects) {
    std::vector<std::uint32_t> corners;
    for (const PlcFacet& facet : plc.facets) {
        for (const auto& loop : facet.loops) {
            corners.insert(corners.end(), loop.begin(), loop.end());
        }
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    // Equal coordinates sort together (-0.0 == 0.0 compares equal, as it must), and by index
    // within a run, so each later index pairs with the first.
    const auto& pts = plc.points.points;
    const auto key = [&pts](std::uint32_t v) { return std::tuple(pts[v].x, pts[v].y, pts[v].z); };
    std::stable_sort(corners.begin(), corners.end(), [&](std::uint32_t a, std::uint32_t b) {
        return key(a) < key(b);
    });
    for (std::size_t i = 0; i < corners.size();) {
        std::size_t j = i + 1;
        for (; j < corners.size() && key(corners[j]) == key(corners[i]); ++j) {
            defects.coincident_points.push_back({corners[i], corners[j]});
        }
        i = j;
    }
    std::sort(defects.coincident_points.begin(), defects.coincident_points.end());
}

/// Why a facet is degenerate, or nothing.
std::optional<std::string> degeneracy(const Plc& plc, const PlcFacet& facet) {
    const auto& pts = plc.points.points;
    const auto base = static_cast<std::uint32_t>(plc.points.index_base);
    for (const auto& loop : facet.loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            for (std::size_t j = i + 1; j < loop.size(); ++j) {
                if (loop[i] == loop[j]) {
                    return "corner " + std::to_string(loop[i] + base) + " is listed twice";
                }
                const Point3& p = pts[loop[i]];
                const Point3& q = pts[loop[j]];
                if (p.x == q.x && p.y == q.y && p.z == q.z) {
                    return "corners " + std::to_string(loop[i] + base) + " and " +
                           std::to_string(loop[j] + base) + " are the same point";
                }
            }
        }
        if (loop.size() == 3 && is_degenerate_triangle(pts[loop[0]], pts[loop[1]], pts[loop[2]])) {
            return std::string("its corners are collinear (zero area)");
        }
    }
    if (facet.loops.size() == 1 && facet.loops[0].size() == 3) {
        return std::nullopt;  // a triangle with area is planar: no rational plane needed
    }
    const auto plane = ExactPlane::of_facet(plc, facet);
    if (!plane) {
        return std::string("its corners are collinear (zero area)");
    }
    for (const auto& loop : facet.loops) {
        for (const std::uint32_t c : loop) {
            if (plane->side(pts[c]) != predicates::Sign::kZero) {
                return "corner " + std::to_string(c + base) + " is not in the plane of the others";
            }
        }
    }
    return std::nullopt;
}

/// The triangles of the facets to test for intersection, each with its facet.
struct FacetTriangles {
    std::vector<Triangle> triangles;
    std::vector<std::size_t> facet;
    std::vector<std::size_t> unsimple;  ///< facets with a loop that is no simple polygon
};

FacetTriangles facet_triangles(const Plc& plc, const std::vector<bool>& degenerate) {
    FacetTriangles out;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        if (degenerate[f]) {
            continue;
        }
        const auto& loops = plc.facets[f].loops;
        if (loops.size() == 1 && loops[0].size() == 3) {
            out.triangles.push_back({loops[0][0], loops[0][1], loops[0][2]});
            out.facet.push_back(f);
            continue;
        }
        // A polygon: the projection of its plane, then its ears.
        const int drop = ExactPlane::of_facet(plc, plc.facets[f])->dropped_axis();
        for (const auto& loop : loops) {
            if (const auto ears = ear_clipping(plc.points.points, loop, drop)) {
                for (const Triangle& t : *ears) {
                    out.triangles.push_back(t);
                    out.facet.push_back(f);
                }
            } else {
                out.unsimple.push_back(f);
            }
        }
    }
    return out;
}

void find_intersections(const Plc& plc,
                        const std::vector<bool>& degenerate,
                        SurfaceDefects& defects) {
    const auto& pts = plc.points.points;
    const FacetTriangles tris = facet_triangles(plc, degenerate);
    for (const std::size_t f : tris.unsimple) {
        defects.degenerate.push_back({f, "its loop is not a simple polygon (no ear to clip)"});
    }
    std::sort(defects.degenerate.begin(),
              defects.degenerate.end(),
              [](const DegenerateFacet& a, const DegenerateFacet& b) { return a.facet < b.facet; });
    std::vector<Box> boxes;
    Box bounds;
    for (const Triangle& t : tris.triangles) {
        Box box;
        for (const std::uint32_t v : t) {
            box.add(pts[v]);
        }
        bounds.add(pts[t[0]]);
        bounds.add(pts[t[1]]);
        bounds.add(pts[t[2]]);
        boxes.push_back(box);
    }
    BoxGrid grid(bounds, boxes);
    std::vector<std::size_t> near;
    for (std::size_t i = 0; i < tris.triangles.size(); ++i) {
        grid.near(boxes[i], i, near);
        for (const std::size_t j : near) {
            // Each pair once (j > i), never within one facet, and a pair of facets once.
            if (j <= i || tris.facet[j] == tris.facet[i] || !boxes[i].meets(boxes[j])) {
                continue;
            }
            const std::array<std::size_t, 2> pair{std::min(tris.facet[i], tris.facet[j]),
                                                  std::max(tris.facet[i], tris.facet[j])};
            if (triangles_meet_improperly(pts, tris.triangles[i], tris.triangles[j])) {
                defects.intersecting.push_back(pair);
            }
        }
    }
    std::sort(defects.intersecting.begin(), defects.intersecting.end());
    defects.intersecting.erase(
        std::unique(defects.intersecting.begin(), defects.intersecting.end()),
        defects.intersecting.end());
}

std::string point_name(const Plc& plc, std::uint32_t v) {
    return std::to_string(v + static_cast<std::uint32_t>(plc.points.index_base));
}

std::string edge_line(const Plc& plc, const SurfaceEdge& e) {
    std::string s = "edge " + point_name(plc, e.edge[0]) + "-" + point_name(plc, e.edge[1]) + ": ";
    s += e.facets.size() == 1 ? "only " : std::to_string(e.facets.size()) + " facets, ";
    for (std::size_t k = 0; k < e.facets.size(); ++k) {
        s += (k > 0 ? ", " : "") + facet_name(plc, e.facets[k]);
    }
    return s;
}

/// "N things" then up to `shown` lines, then "and M more".
template <class T, class Line>
void append_kind(std::string& out,
                 const std::vector<T>& items,
                 std::size_t shown,
                 const std::string& heading,
                 Line line) {
    if (items.empty()) {
        return;
    }
    out += "\n  " + std::to_string(items.size()) + " " + heading + ":";
    for (std::size_t k = 0; k < items.size() && k < shown; ++k) {
        out += "\n    " + line(items[k]);
    }
    if (items.size() > shown) {
        out += "\n    and " + std::to_string(items.size() - shown) + " more";
    }
}

}  // namespace

SurfaceDefects surface_defects(const Plc& plc) {
    SurfaceDefects defects;
    find_coincident_points(plc, defects);
    find_edge_defects(plc, defects);
    std::vector<bool> degenerate(plc.facets.size(), false);
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        if (auto why = degeneracy(plc, plc.facets[f])) {
            degenerate[f] = true;
            defects.degenerate.push_back({f, std::move(*why)});
        }
    }
    find_intersections(plc, degenerate, defects);
    return defects;
}

std::string describe_defects(const Plc& plc, const SurfaceDefects& defects, std::size_t shown) {
    std::string out = "the surface mesh does not bound a solid (nothing was meshed):";
    append_kind(out,
                defects.coincident_points,
                shown,
                "pairs of facet corners at the same coordinates (only STL is merged on reading)",
                [&](const std::array<std::uint32_t, 2>& p) {
                    return "points " + point_name(plc, p[0]) + " and " + point_name(plc, p[1]);
                });
    append_kind(out,
                defects.open_edges,
                shown,
                "open edges (a side of one facet only)",
                [&](const SurfaceEdge& e) { return edge_line(plc, e); });
    append_kind(out,
                defects.non_manifold_edges,
                shown,
                "non-manifold edges (a side of more than two facets)",
                [&](const SurfaceEdge& e) { return edge_line(plc, e); });
    append_kind(out, defects.degenerate, shown, "degenerate facets", [&](const DegenerateFacet& d) {
        return facet_name(plc, d.facet) + ": " + d.why;
    });
    append_kind(out,
                defects.intersecting,
                shown,
                "pairs of intersecting facets (meeting other than along shared sides and corners)",
                [&](const std::array<std::size_t, 2>& p) {
                    return facet_name(plc, p[0]) + " and " + facet_name(plc, p[1]);
                });
    return out;
}

void require_valid_surface(const Plc& plc) {
    const SurfaceDefects defects = surface_defects(plc);
    if (!defects.empty()) {
        throw Error(
            located_message(plc.source, std::nullopt, describe_defects(plc, defects, kShown)));
    }
}

}  // namespace cavity::core
