#include "cavity/core/order/spatial_sort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "cavity/core/base/error.h"

namespace cavity::core {

namespace {

// Coordinates are copied next to their index so that the partitioning passes stream through
// memory instead of chasing indices into the point array.
struct Item {
    std::array<double, 3> c;
    std::uint32_t index;
};

// A strict total order along one axis: coordinate, then input index. Equal coordinates are
// therefore split deterministically, and a set that is flat in this axis still halves. The axis
// and direction are template arguments so that the partitioning loops compare without branching
// on them (half the sorting time for 10^6 points).
template <int kAxis, bool kAscending>
struct Precedes {
    bool operator()(const Item& a, const Item& b) const {
        const Item& first = kAscending ? a : b;
        const Item& second = kAscending ? b : a;
        const double u = first.c[kAxis];
        const double v = second.c[kAxis];
        return u < v || (u == v && first.index < second.index);
    }
};

template <int kAxis, bool kAscending>
void select_middle(Item* begin, Item* middle, Item* end) {
    std::nth_element(begin, middle, end, Precedes<kAxis, kAscending>{});
}

// Splits [begin, end) at its middle so that the first half precedes the second along the axis.
Item* split(Item* begin, Item* end, int axis, bool ascending) {
    Item* middle = begin + (end - begin) / 2;
    if (end - begin < 2) {
        return middle;
    }
    using Select = void (*)(Item*, Item*, Item*);
    static constexpr Select kSelect[3][2] = {
        {select_middle<0, false>, select_middle<0, true>},
        {select_middle<1, false>, select_middle<1, true>},
        {select_middle<2, false>, select_middle<2, true>},
    };
    kSelect[axis][ascending](begin, middle, end);
    return middle;
}

// The Hilbert curve in a cube, in its own frame (a0, a1, a2) with every axis ascending, enters
// at corner (0,0,0) and leaves at (1,0,0). It visits the octants in Gray code order
//   000 001 011 010 110 111 101 100   (bits u0 u1 u2 along a0 a1 a2)
// and runs through each octant as a scaled copy of itself. Continuity fixes each copy: its
// entry corner must touch the previous octant's exit and its exit the next octant's entry.
// Working this out for octants 0..7 gives, in octant-local corner bits:
//   octant   0     1     2     3     4     5     6     7
//   entry   000   000   000   011   011   110   110   101
//   exit    001   010   010   111   111   100   100   100
// The copy's first split axis is the one along which entry and exit differ (its net
// displacement), and an axis is descending in the copy exactly when the entry corner has a 1
// there. The two remaining axes may be taken in either order; keeping them a cyclic rotation
// lets one (axis, up[3]) pair describe every frame. The same construction is used by CGAL's
// Hilbert_sort_median_3.
struct Octant {
    int first_axis;               // local axis of the copy's first split
    std::array<bool, 3> reflect;  // local axes reversed in the copy (the entry corner bits)
};

constexpr std::array<Octant, 8> kHilbertOctants = {{
    {2, {false, false, false}},
    {1, {false, false, false}},
    {1, {false, false, false}},
    {0, {false, true, true}},
    {0, {false, true, true}},
    {1, {true, true, false}},
    {1, {true, true, false}},
    {2, {true, false, true}},
}};

// A curve of either kind is a binary tree of median splits. A level of the recursion works in the
// frame (a0, a1, a2) = (axis, axis+1, axis+2) mod 3: a split along a0 (depth 0), each half along
// a1 (depth 1), each quarter along a2 (depth 2); `octant` holds the bits of the halves taken so
// far. The Hilbert curve visits the halves of a1 and a2 in reflected (Gray code) order: the a1
// split of the upper a0 half and the a2 split of every odd quarter run backwards. At depth 3 the
// range is one octant, sorted as a new level in the octant's frame (Morton: the same frame).
// Below kParallelItems a thread would cost more than it saves; the splits are the same whichever
// thread makes them, so the order does not depend on `threads`.
template <bool kHilbert>
void curve_node(Item* begin,
                Item* end,
                int axis,
                std::array<bool, 3> up,
                int depth,
                int octant,
                unsigned threads) {
    if (end - begin < 2) {
        return;
    }
    if (depth == 3) {
        if constexpr (kHilbert) {
            const Octant& copy = kHilbertOctants[static_cast<std::size_t>(octant)];
            std::array<bool, 3> child_up = up;
            for (int j = 0; j < 3; ++j) {
                const int global = (axis + j) % 3;
                child_up[global] = up[global] != copy.reflect[j];
            }
            curve_node<true>(begin, end, (axis + copy.first_axis) % 3, child_up, 0, 0, threads);
        } else {
            curve_node<false>(begin, end, axis, up, 0, 0, threads);
        }
        return;
    }
    const int along = (axis + depth) % 3;
    const bool reflected = kHilbert && depth > 0 && (octant & 1) != 0;
    Item* const middle = split(begin, end, along, up[along] != reflected);
    constexpr std::ptrdiff_t kParallelItems = 1 << 15;
    if (threads >= 2 && end - begin >= kParallelItems) {
        std::jthread low([=] {
            curve_node<kHilbert>(begin, middle, axis, up, depth + 1, 2 * octant, threads / 2);
        });
        curve_node<kHilbert>(
            middle, end, axis, up, depth + 1, 2 * octant + 1, threads - threads / 2);
        return;
    }
    curve_node<kHilbert>(begin, middle, axis, up, depth + 1, 2 * octant, 1);
    curve_node<kHilbert>(middle, end, axis, up, depth + 1, 2 * octant + 1, 1);
}

std::vector<Item> gather(std::span<const Point3> points, std::span<const std::uint32_t> indices) {
    std::vector<Item> items;
    items.reserve(indices.size());
    for (const std::uint32_t i : indices) {
        const Point3& p = points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw Error("point " + std::to_string(i) + " has a non-finite coordinate");
        }
        items.push_back({{p.x, p.y, p.z}, i});
    }
    return items;
}

void scatter(const std::vector<Item>& items, std::span<std::uint32_t> indices) {
    for (std::size_t k = 0; k < items.size(); ++k) {
        indices[k] = items[k].index;
    }
}

}  // namespace

void hilbert_sort(std::span<const Point3> points,
                  std::span<std::uint32_t> indices,
                  unsigned threads) {
    std::vector<Item> items = gather(points, indices);
    curve_node<true>(
        items.data(), items.data() + items.size(), 0, {true, true, true}, 0, 0, threads);
    scatter(items, indices);
}

void morton_sort(std::span<const Point3> points,
                 std::span<std::uint32_t> indices,
                 unsigned threads) {
    std::vector<Item> items = gather(points, indices);
    curve_node<false>(
        items.data(), items.data() + items.size(), 0, {true, true, true}, 0, 0, threads);
    scatter(items, indices);
}

}  // namespace cavity::core
