#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/input/point_set.h"

/// Gift-wrapping (Cheng, Dey & Shewchuk §5.6): tetrahedra are built one at a time across the
/// facets of a dictionary of unfinished facets. Each unfinished facet gets the apex in front of it
/// that comes first in the pencil of (perturbed) circumballs through the facet: a single pass keeps
/// the current best apex and replaces it by any point inside the circumball of (facet, best), so
/// every decision is an insphere_sos (or orient4d_sos) call, never a computed circumcentre. Under
/// the symbolic perturbation the points are generic, so this builds exactly the perturbed
/// (weighted) Delaunay triangulation that Bowyer-Watson builds.
namespace cavity::core {

/// Output of gift_wrap_delaunay, in the input's own indices.
struct GiftWrapResult {
    std::vector<std::array<std::uint32_t, 4>> tets;  ///< positive right-hand volume (handedness.h)
    std::vector<std::array<std::uint32_t, 2>> duplicates;  ///< {point, its first occurrence}
    std::vector<std::uint32_t> redundant;  ///< weighted: points in no tetrahedron, increasing
    std::size_t hull_triangles = 0;
    RetriangulationCounters counters;
};

/// The (weighted) Delaunay triangulation of `points` under cavity's perturbation (keyed on the
/// input index), by gift-wrapping from one Delaunay seed tetrahedron. The seed is found without
/// distances: from any tetrahedron, while some point is in its perturbed circumball, step to the
/// tetrahedron of the 5-point flip that contains a fixed interior point; its lifted height there
/// strictly drops, so the walk ends at the Delaunay tetrahedron containing that point. Each of its
/// facets is a strongly Delaunay triangle (the perturbed points are generic), the seed §5.6 asks
/// for; the book's recipe for one (nearest neighbour, then the smallest circumcircle) compares
/// distances, whose ties on degenerate input the perturbation does not decide, so the walk replaces
/// it. O(n) tests per facet: O(n h) in all. \throws Error for fewer than 4 distinct or affinely
/// dependent points.
GiftWrapResult gift_wrap_delaunay(const PointSet& points);

/// Retriangulates a cavity by gift-wrapping: `boundary` lists the tetrahedra just outside the
/// cavity, each positively oriented with its facet 3 on the cavity's boundary (so its slot 3 is
/// the apex on that triangle's outer side), possibly with the ghost vertex; apices are
/// chosen among `candidates` (vertex ids of `geometry`), and the ghost vertex, when
/// `ghost_allowed`, closes facets with no candidate in front (new hull triangles). The cavity must
/// be fillable by the Delaunay tetrahedra of its vertices, e.g. the star of a deleted vertex.
/// Returns the new tetrahedra (positively oriented, ghost in slot 3).
/// \throws Error when a facet cannot be finished or the tetrahedra do not close up.
std::vector<TetVertices> gift_wrap_cavity(const Geometry& geometry,
                                          std::span<const TetVertices> boundary,
                                          std::span<const VertexId> candidates,
                                          bool ghost_allowed,
                                          RetriangulationCounters& counters);

}  // namespace cavity::core
