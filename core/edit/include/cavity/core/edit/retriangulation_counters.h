#pragma once

#include <array>
#include <cstdint>

namespace cavity::core {

/// The bistellar flips of Cheng, Dey & Shewchuk §4.4 / Figure 4.7 in three dimensions. 2-2 is the
/// hull flip of two solid tetrahedra over a flat quadrilateral; with ghost tetrahedra it is the 4-4
/// flip of the edge whose ring holds the ghost vertex, and is counted as 2-2.
enum class FlipKind : std::uint8_t { k23 = 0, k32 = 1, k14 = 2, k41 = 3, k22 = 4, k44 = 5 };

inline constexpr int kFlipKindCount = 6;

/// Work done by flips, gift-wrapping (§5.6) and vertex deletion, for the experiments layer: the
/// chapter bounds gift-wrapping by O(nh) apex tests and polygon insertion by m^2 flips.
struct RetriangulationCounters {
    std::array<std::uint64_t, kFlipKindCount> flips{};  ///< performed, by FlipKind
    std::uint64_t flips_refused = 0;      ///< requested flips whose new tetrahedra were not valid
    std::uint64_t facets_wrapped = 0;     ///< unfinished facets taken from the dictionary
    std::uint64_t hull_facets = 0;        ///< wrapped facets with no apex in front (gift-wrap (a))
    std::uint64_t apex_orient_tests = 0;  ///< orient3d calls deciding which points are in front
    std::uint64_t insphere_calls =
        0;                         ///< perturbed conflict tests (insphere/orient4d/outer halfspace)
    std::uint64_t seed_steps = 0;  ///< tetrahedra visited while finding the seed tetrahedron
    std::uint64_t tets_created = 0;
    std::uint64_t tets_deleted = 0;
    std::uint64_t vertices_deleted = 0;

    std::uint64_t flip_count(FlipKind kind) const { return flips[static_cast<std::size_t>(kind)]; }
};

}  // namespace cavity::core
