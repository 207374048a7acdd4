#include "warped_facets.h"

#include <cmath>
#include <utility>

#include "ear_clipping.h"
#include "exact_plane.h"
#include "minimum_weight_triangulation.h"

namespace cavity::core {

namespace {

/// The coordinate axis a projection drops: the largest component of the loop's Newell normal, the
/// axis along which the loop's projected area is largest. Only the choice of projection rests on
/// floating point; ear clipping then decides exactly whether that projection is a simple polygon.
int newell_axis(const std::vector<Point3>& pts, const std::vector<std::uint32_t>& loop) {
    double n[3] = {0, 0, 0};
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point3& p = pts[loop[i]];
        const Point3& q = pts[loop[(i + 1) % loop.size()]];
        n[0] += (p.y - q.y) * (p.z + q.z);
        n[1] += (p.z - q.z) * (p.x + q.x);
        n[2] += (p.x - q.x) * (p.y + q.y);
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
        if (std::fabs(n[k]) > std::fabs(n[axis])) {
            axis = k;
        }
    }
    return axis;
}

bool is_warped(const Plc& plc, const PlcFacet& facet) {
    if (facet.loops.size() != 1 || facet.loops[0].size() < 4) {
        return false;
    }
    const auto plane = ExactPlane::of_facet(plc, facet);
    if (!plane) {
        return false;  // collinear corners: degenerate, not warped
    }
    for (const std::uint32_t c : facet.loops[0]) {
        if (plane->side(plc.points.points[c]) != predicates::Sign::kZero) {
            return true;
        }
    }
    return false;
}

/// The triangles a warped loop is cut into: ear clipping decides whether its projection is a simple
/// polygon and gives its orientation (the turn of any ear); the cut itself is the one whose new
/// sides are shortest in total, since each of them is a segment that edge protection must make a
/// Delaunay edge (on the bench this halved mpi.off's protecting points). Loops too long for that
/// search keep the ears.
std::optional<std::vector<Triangle>> cut_warped_loop(const std::vector<Point3>& points,
                                                     const std::vector<std::uint32_t>& loop) {
    const int drop = newell_axis(points, loop);
    auto ears = ear_clipping(points, loop, drop);
    if (!ears) {
        return std::nullopt;
    }
    const Triangle& ear = ears->front();
    const int turn = orient2d_projected(points[ear[0]], points[ear[1]], points[ear[2]], drop);
    auto shortest = minimum_weight_triangulation(points, loop, drop, turn);
    return shortest ? std::move(shortest) : std::move(ears);
}

}  // namespace

std::size_t split_warped_facets(Plc& plc) {
    std::vector<PlcFacet> facets;
    facets.reserve(plc.facets.size());
    std::size_t split = 0;
    for (PlcFacet& facet : plc.facets) {
        const auto pieces = is_warped(plc, facet)
                                ? cut_warped_loop(plc.points.points, facet.loops[0])
                                : std::nullopt;
        if (!pieces) {
            facets.push_back(std::move(facet));
            continue;
        }
        ++split;
        for (const Triangle& t : *pieces) {
            PlcFacet triangle;
            triangle.loops = {{t[0], t[1], t[2]}};
            triangle.marker = facet.marker;
            triangle.line = facet.line;
            triangle.number = facet.number;
            facets.push_back(std::move(triangle));
        }
    }
    plc.facets = std::move(facets);
    return split;
}

}  // namespace cavity::core
