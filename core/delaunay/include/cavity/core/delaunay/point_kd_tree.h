#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cavity/predicates/point.h"

namespace cavity::core {

/// An axis-aligned box, closed.
struct Box3 {
    predicates::Point3 lo;
    predicates::Point3 hi;
};

/// A static kd-tree over a point set, for counting the points of a region that is tested exactly
/// point by point: a query descends only into boxes its caller cannot rule out, then hands each
/// point of the remaining leaves to the caller's exact test. Built once in O(n log n) (median
/// splits on the longest side, leaves of at most kLeafSize points); 36 bytes per point.
class PointKdTree {
public:
    static constexpr std::uint32_t kLeafSize = 32;

    /// Point ids are positions in `points`; the tree keeps its own copy of the points, in leaf
    /// order for locality. \throws Error for 2^32 points or more.
    explicit PointKdTree(std::span<const predicates::Point3> points);

    /// Calls visit(id, point) for every point in a box for which may_hold(box) is true, down from
    /// the root (so may_hold must be true for a box whenever it is for one of its sub-boxes:
    /// a test "the region meets the box" has that property).
    template <class MayHold, class Visit>
    void query(MayHold&& may_hold, Visit&& visit) const {
        count(
            may_hold, [](const Box3&) { return false; }, visit);
    }

    /// As query(), but a box for which holds_all(box) is true (tested only where may_hold is)
    /// is counted whole, without visiting its points; returns how many points were so counted.
    /// A region's interior is one that can certify whole boxes: counting is then proportional to
    /// the boxes along its boundary, not to the points it holds.
    template <class MayHold, class HoldsAll, class Visit>
    std::uint64_t count(MayHold&& may_hold, HoldsAll&& holds_all, Visit&& visit) const {
        return count_leaves(may_hold,
                            holds_all,
                            [&](const Box3&,
                                std::span<const std::uint32_t> ids,
                                std::span<const predicates::Point3> points) {
                                for (std::size_t k = 0; k < ids.size(); ++k) {
                                    visit(ids[k], points[k]);
                                }
                            });
    }

    /// As count(), but hands each remaining leaf whole to visit_leaf(box, ids, points), so that
    /// a caller can sweep a leaf's points without a branch per point.
    template <class MayHold, class HoldsAll, class VisitLeaf>
    std::uint64_t count_leaves(MayHold&& may_hold,
                               HoldsAll&& holds_all,
                               VisitLeaf&& visit_leaf) const {
        std::uint64_t whole = 0;
        if (nodes_.empty()) {
            return whole;
        }
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (!may_hold(node.box)) {
                continue;
            }
            if (holds_all(node.box)) {
                whole += node.end - node.begin;
                continue;
            }
            if (node.left == 0) {
                visit_leaf(
                    node.box,
                    std::span<const std::uint32_t>(ids_).subspan(node.begin, node.end - node.begin),
                    std::span<const predicates::Point3>(points_).subspan(node.begin,
                                                                         node.end - node.begin));
                continue;
            }
            stack[top++] = node.left + 1;
            stack[top++] = node.left;
        }
        return whole;
    }

    std::size_t size() const { return ids_.size(); }

private:
    struct Node {
        Box3 box;
        std::uint32_t begin;
        std::uint32_t end;
        std::uint32_t left;  ///< children at left and left + 1; 0 for a leaf (the root is no child)
    };

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> ids_;
    std::vector<predicates::Point3> points_;
};

}  // namespace cavity::core
