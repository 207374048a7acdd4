#pragma once

// The flood fill behind region markers and carving (TetGen's region attributes and holes): the
// tetrahedra of a CDT as a graph whose edges are the triangles in no polygon, so that a fill from
// one tetrahedron stops exactly at the polygons, plus exact location of a seed point.

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/cdt/cdt.h"

namespace cavity::core {

class TetFlood {
public:
    /// `tets` with positive volume, as Cdt::tets; `faces` the polygon triangles (the walls).
    /// \throws Error when a triangle has more than two tetrahedra (not a manifold).
    TetFlood(std::span<const Tet> tets, std::span<const CdtFace> faces);

    /// Marks as reached every tetrahedron reachable from `seed` across triangles that are not
    /// walls, stopping at tetrahedra already reached (by this fill or an earlier one), and calls
    /// visit(t) on each newly reached one. Nothing happens when `seed` is already reached.
    template <class Visit>
    void fill(std::uint32_t seed, Visit visit) {
        if (reached_[seed]) {
            return;
        }
        reached_[seed] = true;
        stack_.assign(1, seed);
        while (!stack_.empty()) {
            const std::uint32_t t = stack_.back();
            stack_.pop_back();
            visit(t);
            for (std::size_t f = 0; f < 4; ++f) {
                const std::int32_t other = across_[4 * std::size_t{t} + f];
                if (other >= 0 && !reached_[static_cast<std::uint32_t>(other)]) {
                    reached_[static_cast<std::uint32_t>(other)] = true;
                    stack_.push_back(static_cast<std::uint32_t>(other));
                }
            }
        }
    }

    /// Makes every tetrahedron unreached again, for fills of another kind (carving and region
    /// markers share one flood: its facet matching is most of its cost).
    void forget_reached() { std::fill(reached_.begin(), reached_.end(), false); }

    /// The tetrahedra with a boundary triangle (on no other tetrahedron) that is not a wall: the
    /// seeds of the exterior, the part of the hull no polygon encloses.
    std::vector<std::uint32_t> open_hull_tets() const;

    /// The first tetrahedron whose closure holds p (exact), or none when p is outside them all.
    std::optional<std::uint32_t> locate(const PointSet& pts, const Point3& p) const;

    /// Whether p (in the closure of some tetrahedron) lies in the closure of a wall: tested on
    /// every tetrahedron holding p, so that a wall through p is found whichever side it is seen
    /// from.
    bool on_wall(const PointSet& pts, const Point3& p) const;

private:
    /// across_ entries that are no tetrahedron: a wall, or a boundary triangle in no polygon.
    static constexpr std::int32_t kWall = -2;
    static constexpr std::int32_t kOpen = -1;

    std::span<const Tet> tets_;
    /// across_[4t + f]: the tetrahedron across the facet opposite slot f of t, or kWall, or
    /// kOpen. Read off one facet matching (no hash of every triangle, no lookups per step).
    std::vector<std::int32_t> across_;
    std::vector<bool> reached_;
    std::vector<std::uint32_t> stack_;  ///< reused by every fill
};

/// region_markers (cdt_regions.h) with the CDT's flood already built, every tetrahedron unreached.
std::vector<std::int32_t> region_markers(const Plc& plc, TetFlood& flood, std::size_t tets);

}  // namespace cavity::core
