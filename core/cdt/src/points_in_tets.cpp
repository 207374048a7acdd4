#include "points_in_tets.h"

#include <algorithm>
#include <cmath>

#include "cavity/predicates/generic_predicates.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

/// p in the closed tetrahedron t of positive right-hand volume (orient3d < 0): replacing any
/// vertex by p never makes the orientation positive.
bool holds(const PointSet& pts,
           const std::array<std::uint32_t, 4>& t,
           const predicates::GenericPoint3& p) {
    for (std::size_t i = 0; i < 4; ++i) {
        std::array<predicates::GenericPoint3, 4> q{generic_point(pts, t[0]),
                                                   generic_point(pts, t[1]),
                                                   generic_point(pts, t[2]),
                                                   generic_point(pts, t[3])};
        q[i] = p;
        if (predicates::orient3d(q[0], q[1], q[2], q[3]) == predicates::Sign::kPos) {
            return false;
        }
    }
    return true;
}

/// The probes' bounding box cut into n^3 cells; a coordinate maps to its cell clamped to the
/// grid, so boxes reaching beyond it still find the probes on its border. Cells only prune: the
/// exact test decides.
class Grid {
public:
    explicit Grid(std::span<const Point3> probes) {
        lo_ = hi_ = {probes[0].x, probes[0].y, probes[0].z};
        for (const Point3& p : probes) {
            const std::array<double, 3> c{p.x, p.y, p.z};
            for (std::size_t k = 0; k < 3; ++k) {
                lo_[k] = std::min(lo_[k], c[k]);
                hi_[k] = std::max(hi_[k], c[k]);
            }
        }
        n_ = std::max<std::size_t>(
            1, static_cast<std::size_t>(std::cbrt(static_cast<double>(probes.size()))));
        cells_.resize(n_ * n_ * n_);
        for (std::uint32_t i = 0; i < probes.size(); ++i) {
            const Point3& p = probes[i];
            cells_[index(cell(0, p.x), cell(1, p.y), cell(2, p.z))].push_back(i);
        }
    }

    /// Calls visit(probe) for every probe in a cell the box [lo, hi] meets.
    template <class Visit>
    void each_near(const std::array<double, 3>& lo,
                   const std::array<double, 3>& hi,
                   Visit visit) const {
        for (std::size_t k = 0; k < 3; ++k) {
            if (hi[k] < lo_[k] || lo[k] > hi_[k]) {
                return;
            }
        }
        for (std::size_t x = cell(0, lo[0]); x <= cell(0, hi[0]); ++x) {
            for (std::size_t y = cell(1, lo[1]); y <= cell(1, hi[1]); ++y) {
                for (std::size_t z = cell(2, lo[2]); z <= cell(2, hi[2]); ++z) {
                    for (std::uint32_t i : cells_[index(x, y, z)]) {
                        visit(i);
                    }
                }
            }
        }
    }

private:
    std::size_t cell(std::size_t axis, double c) const {
        const double extent = hi_[axis] - lo_[axis];
        if (!(extent > 0) || c <= lo_[axis]) {
            return 0;
        }
        const double f = (c - lo_[axis]) / extent * static_cast<double>(n_);
        return std::min(n_ - 1, static_cast<std::size_t>(f));
    }

    std::size_t index(std::size_t x, std::size_t y, std::size_t z) const {
        return (x * n_ + y) * n_ + z;
    }

    std::array<double, 3> lo_{};
    std::array<double, 3> hi_{};
    std::size_t n_ = 1;
    std::vector<std::vector<std::uint32_t>> cells_;
};

}  // namespace

std::vector<std::optional<std::uint32_t>> points_in_tets(
    const PointSet& points,
    std::span<const std::array<std::uint32_t, 4>> tets,
    std::span<const predicates::GenericPoint3> probes) {
    std::vector<std::optional<std::uint32_t>> found(probes.size());
    if (probes.empty()) {
        return found;
    }
    std::vector<Point3> rounded;
    rounded.reserve(probes.size());
    for (const auto& p : probes) {
        rounded.push_back(rounded_point(p));
    }
    const Grid grid(rounded);
    const std::vector<Point3>& pts = points.points;
    for (std::uint32_t t = 0; t < tets.size(); ++t) {
        std::array<double, 3> lo{pts[tets[t][0]].x, pts[tets[t][0]].y, pts[tets[t][0]].z};
        std::array<double, 3> hi = lo;
        for (std::uint32_t v : tets[t]) {
            const std::array<double, 3> c{pts[v].x, pts[v].y, pts[v].z};
            for (std::size_t k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], c[k]);
                hi[k] = std::max(hi[k], c[k]);
            }
        }
        grid.each_near(lo, hi, [&](std::uint32_t i) {
            if (!found[i] && holds(points, tets[t], probes[i])) {
                found[i] = t;
            }
        });
    }
    return found;
}

}  // namespace cavity::core
