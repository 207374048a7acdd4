#include "split_triangle.h"

#include <variant>

#include "segment_interior.h"
#include "triangle_intersection.h"

namespace cavity::core {

namespace {

bool same(const Point3& p, const Point3& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

}  // namespace

std::optional<std::array<Point3, 3>> split_triangle_corners(
    const PointSet& points, const std::vector<std::uint32_t>& loop) {
    if (points.exact.empty()) {
        return std::nullopt;  // no implicit corner: a split triangle has more than three corners
    }
    std::array<Point3, 3> corners{};
    std::size_t count = 0;
    for (std::uint32_t c : loop) {
        if (const auto* p = std::get_if<Point3>(&points.exact[c])) {
            if (count == 3) {
                return std::nullopt;
            }
            corners[count++] = *p;
        }
    }
    if (count != 3 || is_degenerate_triangle(corners[0], corners[1], corners[2])) {
        return std::nullopt;
    }
    // The sides of the triangle each corner lies on, as bits: side k joins corners k and k + 1.
    const auto corner_of = [&](const Point3& p) -> int {
        for (int k = 0; k < 3; ++k) {
            if (same(p, corners[static_cast<std::size_t>(k)])) {
                return k;
            }
        }
        return -1;
    };
    std::vector<unsigned> sides;
    sides.reserve(loop.size());
    for (std::uint32_t c : loop) {
        if (const auto* p = std::get_if<Point3>(&points.exact[c])) {
            const int k = corner_of(*p);
            sides.push_back((1u << k) | (1u << ((k + 2) % 3)));
            continue;
        }
        const auto* s = std::get_if<predicates::SegmentParameterPoint>(&points.exact[c]);
        if (s == nullptr || !strictly_inside(*s)) {
            return std::nullopt;
        }
        const int i = corner_of(s->a);
        const int j = corner_of(s->b);
        if (i < 0 || j < 0 || i == j) {
            return std::nullopt;
        }
        // Side i when j follows i around the triangle, else side j (then i follows j).
        sides.push_back(1u << ((i + 1) % 3 == j ? i : j));
    }
    for (std::size_t k = 0; k < sides.size(); ++k) {
        if ((sides[k] & sides[(k + 1) % sides.size()]) == 0) {
            return std::nullopt;
        }
    }
    return corners;
}

}  // namespace cavity::core
