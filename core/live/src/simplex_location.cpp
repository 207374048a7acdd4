#include "cavity/core/live/simplex_location.h"

#include <algorithm>
#include <vector>

#include "cavity/predicates/orient3d.h"

namespace cavity::core {

namespace {

using predicates::Sign;

/// The side of facet i of `tet` that p is on: the orientation of the tetrahedron with vertex i
/// replaced by p, relative to the tetrahedron's own. kPos: strictly beyond the facet (the other
/// side from vertex i); kZero: on its plane; kNeg: on vertex i's side.
Sign beyond(std::span<const Point3> points, const Tet& tet, std::size_t i, const Point3& p) {
    std::array<const Point3*, 4> v{};
    for (std::size_t k = 0; k < 4; ++k) {
        v[k] = k == i ? &p : &points[tet[k]];
    }
    // The tetrahedron has positive right-hand volume, orient3d's negative sign (Shewchuk's
    // convention), so the positive sign is the other side of the facet.
    return predicates::orient3d(*v[0], *v[1], *v[2], *v[3]);
}

}  // namespace

SimplexLocator::SimplexLocator(std::span<const Point3> points,
                               std::span<const Tet> simplices,
                               std::span<const std::int32_t> neighbors)
    : points_(points), simplices_(simplices), neighbors_(neighbors) {}

std::int32_t SimplexLocator::find(const Point3& p, std::int32_t start) const {
    if (simplices_.empty()) {
        return -1;
    }
    const std::int32_t holding = walk(p, start);
    return holding < 0 ? -1 : lowest_holding(p, holding);
}

std::int32_t SimplexLocator::walk(const Point3& p, std::int32_t start) const {
    const auto m = static_cast<std::int64_t>(simplices_.size());
    std::int32_t t = start >= 0 && start < m ? start : 0;
    std::int32_t came_from = -1;
    // The facet tested first turns with every step, so that the walk does not keep preferring
    // one direction; any choice terminates, and the answer does not depend on it.
    for (std::size_t step = 0;; ++step) {
        const Tet& tet = simplices_[static_cast<std::size_t>(t)];
        std::int32_t next = t;
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t i = (k + step) % 4;
            const std::int32_t across = neighbors_[4 * static_cast<std::size_t>(t) + i];
            // p is strictly on this side of the facet just crossed.
            if (across >= 0 && across == came_from) {
                continue;
            }
            if (beyond(points_, tet, i, p) == Sign::kPos) {
                if (across < 0) {
                    return -1;  // strictly beyond a hull facet: outside the convex hull
                }
                next = across;
                break;
            }
        }
        if (next == t) {
            return t;
        }
        came_from = t;
        t = next;
    }
}

std::int32_t SimplexLocator::lowest_holding(const Point3& p, std::int32_t holding) const {
    std::vector<std::int32_t> found{holding};
    std::int32_t lowest = holding;
    for (std::size_t next = 0; next < found.size(); ++next) {
        const std::int32_t t = found[next];
        const Tet& tet = simplices_[static_cast<std::size_t>(t)];
        for (std::size_t i = 0; i < 4; ++i) {
            const std::int32_t across = neighbors_[4 * static_cast<std::size_t>(t) + i];
            if (across < 0 || std::find(found.begin(), found.end(), across) != found.end() ||
                beyond(points_, tet, i, p) != Sign::kZero) {
                continue;
            }
            found.push_back(across);
            lowest = std::min(lowest, across);
        }
    }
    return lowest;
}

}  // namespace cavity::core
