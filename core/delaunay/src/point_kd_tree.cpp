#include "cavity/core/delaunay/point_kd_tree.h"

#include <algorithm>
#include <numeric>

#include "cavity/core/base/error.h"

namespace cavity::core {

using predicates::Point3;

namespace {

double coordinate(const Point3& p, int axis) {
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

}  // namespace

PointKdTree::PointKdTree(std::span<const Point3> points) {
    if (points.size() >= (std::size_t{1} << 32)) {
        throw Error("kd-tree: more than 2^32 - 1 points");
    }
    ids_.resize(points.size());
    std::iota(ids_.begin(), ids_.end(), 0u);
    points_.assign(points.begin(), points.end());
    if (points.empty()) {
        return;
    }
    // A tree of median splits over leaves of <= kLeafSize points has < 2n / kLeafSize + 1 nodes.
    nodes_.reserve(2 * points.size() / kLeafSize + 2);
    nodes_.push_back({});
    build(0, 0, static_cast<std::uint32_t>(points.size()), 0);
    std::vector<Point3> ordered(points.size());
    for (std::size_t k = 0; k < ids_.size(); ++k) {
        ordered[k] = points[ids_[k]];
    }
    points_ = std::move(ordered);
}

void PointKdTree::build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
    Box3 box{points_[ids_[begin]], points_[ids_[begin]]};
    for (std::uint32_t k = begin + 1; k < end; ++k) {
        const Point3& p = points_[ids_[k]];
        box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
        box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
    }
    nodes_[node] = {box, begin, end, 0};
    // Depth stays below 64 (the query's stack) for any n < 2^32 with median splits; the guard
    // only protects against a future change of the split rule.
    if (end - begin <= kLeafSize || depth >= 60) {
        return;
    }
    // Halved extents cannot overflow, whatever the finite coordinates.
    const double ex = box.hi.x / 2 - box.lo.x / 2;
    const double ey = box.hi.y / 2 - box.lo.y / 2;
    const double ez = box.hi.z / 2 - box.lo.z / 2;
    const int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(ids_.begin() + begin,
                     ids_.begin() + mid,
                     ids_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return coordinate(points_[a], axis) < coordinate(points_[b], axis);
                     });
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[node].left = left;
    build(left, begin, mid, depth + 1);
    build(left + 1, mid, end, depth + 1);
}

}  // namespace cavity::core
