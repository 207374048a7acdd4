#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cavity/core/input/plc.h"

/// Is a surface mesh (read_surface_mesh) the boundary of a solid? Checked before any meshing,
/// exactly, as TetGen's `-d` checks its input: what it reports makes the CDT of the domain
/// meaningless (an open or non-manifold boundary has no inside) or impossible (facets that cross).
/// A .poly is not held to this: it may have internal and dangling facets (plc_validity.h).
namespace cavity::core {

/// An edge (two point indices, 0-based) and the facets (positions in plc.facets) it is a side of.
struct SurfaceEdge {
    std::array<std::uint32_t, 2> edge;
    std::vector<std::size_t> facets;
};

/// A facet (position in plc.facets) with no area or no plane, and why.
struct DegenerateFacet {
    std::size_t facet;
    std::string why;
};

struct SurfaceDefects {
    /// Corners of facets at equal coordinates under different indices ({first, later} by index):
    /// OFF, OBJ and PLY keep the file's numbering, so such points are reported, not merged.
    std::vector<std::array<std::uint32_t, 2>> coincident_points;
    std::vector<SurfaceEdge> open_edges;          ///< a side of one facet only
    std::vector<SurfaceEdge> non_manifold_edges;  ///< a side of three facets or more
    /// A repeated corner, coincident or collinear corners, non-planar, or a loop that is not a
    /// simple polygon.
    std::vector<DegenerateFacet> degenerate;
    /// Pairs of facets (positions, first < second) meeting other than along the sides and corners
    /// they share: crossing, touching, overlapping or repeated. Degenerate facets are left out.
    std::vector<std::array<std::size_t, 2>> intersecting;

    bool empty() const {
        return coincident_points.empty() && open_edges.empty() && non_manifold_edges.empty() &&
               degenerate.empty() && intersecting.empty();
    }
};

/// Every defect of the surface. Edges come from the loop sides; triangles are tested pairwise
/// (exact orient3d signs) among the candidates a uniform grid of bounding boxes selects, and a
/// polygon as the triangles ear clipping cuts it into.
SurfaceDefects surface_defects(const Plc& plc);

/// The defects as one message: the counts of each kind, then up to `shown` of each, naming facets
/// and points as the file numbers them (facet_name).
std::string describe_defects(const Plc& plc, const SurfaceDefects& defects, std::size_t shown);

/// \throws Error naming the file, the counts and the first defects of each kind, when there are.
void require_valid_surface(const Plc& plc);

}  // namespace cavity::core
