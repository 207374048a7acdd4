#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"

/// A piecewise linear complex (Cheng, Dey & Shewchuk §4.5): points, planar polygons with holes and
/// segments, as a TetGen `.poly` file describes them. Indices are 0-based positions in `points`
/// (the perturbation keys); `points.index_base` keeps the file's numbering for output.
namespace cavity::core {

/// One TetGen facet: coplanar loops (polygons of 3 or more corners) whose sides do not cross, and
/// hole points. Its region follows TetGen's .poly semantics: the union of the loops' interiors,
/// minus every face of the loops' arrangement that holds a hole point. With non-crossing loops a
/// face is "inside loop L, outside L's children", so a loop nested in another cuts a hole only when
/// a hole point lies inside it and outside its own children (without one, the nested loop just
/// subdivides the region); a hole point outside every loop removes nothing. Two faces enclosed by
/// the same loops count as one face (a loop whose children split it is carved as a whole). A hole
/// point on a loop side is refused (read_poly, plc_violations).
/// Two-corner polygons of the facet are segments and go to Plc::segments.
struct PlcFacet {
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<Point3> holes;
    int marker = 0;
    std::size_t line = 0;  ///< line of the facet header in the file (0: not from a text file)
    /// Position in the file's facet list, numbered like the points; none for a PLC built in code.
    /// Kept by every piece when the reader cuts a face (warped_facets.h).
    std::optional<std::size_t> number{};
};

/// A region seed of a .poly file (TetGen's region list): the tetrahedra reachable from the one
/// holding `point` without crossing a polygon carry `marker` (cdt_regions.h).
struct PlcRegion {
    Point3 point;
    std::int32_t marker = 0;
    std::size_t line = 0;  ///< in the .poly file (0: not from a file)
};

/// A volume hole of a .poly file (TetGen's hole list): the tetrahedra reachable from the one
/// holding `point` without crossing a polygon are carved away (cdt_carve.h).
struct PlcVolumeHole {
    Point3 point;
    std::size_t line = 0;  ///< in the .poly file (0: not from a file)
};

struct Plc {
    PointSet points;
    std::vector<PlcFacet> facets;
    std::vector<std::array<std::uint32_t, 2>> segments;  ///< explicit segments (2-corner polygons)
    /// The CDT tetrahedralizes the whole convex hull of the points; carve_cdt (cdt_carve.h)
    /// removes these holes' volumes (and the exterior) from it.
    std::vector<PlcVolumeHole> volume_holes;
    std::vector<PlcRegion> regions;
    std::string source;
    /// Set only by prepare_surface_mesh (read_plc.h): the facets are a surface mesh's one-loop
    /// faces that passed require_valid_surface, at most merged by merge_coplanar_facets, and there
    /// are no segments. Edge protection keeps it (its split points lie exactly on the edges); the
    /// CDT then skips the protected PLC check, proven to pass (cdt.cpp). Code that changes the
    /// points, facets or segments otherwise must clear it.
    bool surface_checked = false;
};

/// "facet N (line L)" with N as the file numbers its facets (a binary file's: "facet N"); for a PLC
/// built in code (no number), N is the position in `facets` plus points.index_base.
std::string facet_name(const Plc& plc, std::size_t f);

/// Every PLC edge (the explicit segments and the sides of every loop), each once as {min, max}.
std::vector<std::array<std::uint32_t, 2>> plc_edges(const Plc& plc);

}  // namespace cavity::core
