#pragma once

// The flood fill behind region markers and carving (TetGen's region attributes and holes): the
// tetrahedra of a CDT as a graph whose edges are the triangles in no polygon, so that a fill from
// one tetrahedron stops exactly at the polygons, plus exact location of a seed point.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/cdt/cdt.h"

namespace cavity::core {

class TetFlood {
public:
    /// `tets` with positive volume, as Cdt::tets; `faces` the polygon triangles (the walls).
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
        std::vector<std::uint32_t> stack{seed};
        while (!stack.empty()) {
            const std::uint32_t t = stack.back();
            stack.pop_back();
            visit(t);
            for (int f = 0; f < 4; ++f) {
                const std::optional<std::uint32_t> other = across(t, f);
                if (other && !reached_[*other]) {
                    reached_[*other] = true;
                    stack.push_back(*other);
                }
            }
        }
    }

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
    using Key = std::array<std::uint32_t, 3>;

    struct KeyHash {
        std::size_t operator()(const Key& k) const;
    };

    static Key facet_key(const Tet& t, int f);
    /// The tetrahedron across facet f of t, or none when that facet is a wall or on the boundary.
    std::optional<std::uint32_t> across(std::uint32_t t, int f) const;

    std::span<const Tet> tets_;
    std::unordered_set<Key, KeyHash> walls_;
    /// Each triangle's one or two tetrahedra (one: both entries equal).
    std::unordered_map<Key, std::array<std::uint32_t, 2>, KeyHash> sides_;
    std::vector<bool> reached_;
};

}  // namespace cavity::core
