#pragma once

// The broad phase of the exact PLC checks: bounding boxes in doubles and a uniform grid of them.
// A box only selects candidates, so rounding here never decides an answer: the exact tests do.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

struct Box {
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};

    void add(const Point3& p) {
        const std::array<double, 3> c{p.x, p.y, p.z};
        for (std::size_t k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], c[k]);
            hi[k] = std::max(hi[k], c[k]);
        }
    }

    bool contains(const Box& other) const {
        for (std::size_t k = 0; k < 3; ++k) {
            if (other.lo[k] < lo[k] || hi[k] < other.hi[k]) {
                return false;
            }
        }
        return true;
    }

    /// Closed boxes: touching counts, since a corner on a facet's boundary matters.
    bool meets(const Box& other) const {
        for (std::size_t k = 0; k < 3; ++k) {
            if (hi[k] < other.lo[k] || other.hi[k] < lo[k]) {
                return false;
            }
        }
        return true;
    }
};

/// A uniform grid over `bounds` holding items (edges, triangles) by the cells their boxes cover,
/// so a query box meets only the items registered in its own cells. Cell indices come from
/// one monotone function of a coordinate, so boxes that meet always share a cell.
class BoxGrid {
public:
    BoxGrid(const Box& bounds, const std::vector<Box>& boxes) : bounds_(bounds) {
        const auto n = static_cast<double>(boxes.size());
        resolution_ =
            std::clamp(static_cast<std::size_t>(std::cbrt(n)), std::size_t{1}, std::size_t{64});
        cells_.resize(resolution_ * resolution_ * resolution_);
        for (std::size_t e = 0; e < boxes.size(); ++e) {
            const auto [lo, hi] = range(boxes[e]);
            std::size_t count = 1;
            for (std::size_t k = 0; k < 3; ++k) {
                count *= hi[k] - lo[k] + 1;
            }
            if (count > kMaxCellsPerItem) {
                everywhere_.push_back(e);  // a long diagonal item: return it for every query
                continue;
            }
            for_cells(lo, hi, [&](std::size_t cell) { cells_[cell].push_back(e); });
        }
        stamp_.assign(boxes.size(), kNever);
    }

    /// The items registered in the cells of `box` (each once), for the query numbered `query`
    /// (distinct queries need distinct numbers).
    std::vector<std::size_t> near(const Box& box, std::size_t query) {
        std::vector<std::size_t> out;
        near(box, query, out);
        return out;
    }

    /// The same into `out`, replacing its contents: a loop of queries reuses one vector (a fresh
    /// one per query cost as much as reading its cells on surface meshes).
    void near(const Box& box, std::size_t query, std::vector<std::size_t>& out) {
        out.assign(everywhere_.begin(), everywhere_.end());
        const auto [lo, hi] = range(box);
        for_cells(lo, hi, [&](std::size_t cell) {
            for (std::size_t e : cells_[cell]) {
                if (stamp_[e] != query) {
                    stamp_[e] = query;
                    out.push_back(e);
                }
            }
        });
    }

private:
    static constexpr std::size_t kMaxCellsPerItem = 64;
    static constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();
    using Index3 = std::array<std::size_t, 3>;

    std::size_t cell_of(double x, std::size_t k) const {
        const double width = bounds_.hi[k] - bounds_.lo[k];
        if (!(width > 0)) {
            return 0;
        }
        const double f = std::floor((x - bounds_.lo[k]) / width * static_cast<double>(resolution_));
        return static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(resolution_ - 1)));
    }

    std::pair<Index3, Index3> range(const Box& box) const {
        Index3 lo{};
        Index3 hi{};
        for (std::size_t k = 0; k < 3; ++k) {
            lo[k] = cell_of(box.lo[k], k);
            hi[k] = cell_of(box.hi[k], k);
        }
        return {lo, hi};
    }

    template <class F>
    void for_cells(const Index3& lo, const Index3& hi, F&& f) const {
        for (std::size_t i = lo[0]; i <= hi[0]; ++i) {
            for (std::size_t j = lo[1]; j <= hi[1]; ++j) {
                for (std::size_t k = lo[2]; k <= hi[2]; ++k) {
                    f((i * resolution_ + j) * resolution_ + k);
                }
            }
        }
    }

    Box bounds_;
    std::size_t resolution_ = 1;
    std::vector<std::vector<std::size_t>> cells_;
    std::vector<std::size_t> everywhere_;
    std::vector<std::size_t> stamp_;
};

}  // namespace cavity::core
