#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cavity/core/point_set.h"

/// A piecewise linear complex (Cheng, Dey & Shewchuk §4.5): points, planar polygons with holes and
/// segments, as a TetGen `.poly` file describes them. Indices are 0-based positions in `points`
/// (the perturbation keys); `points.index_base` keeps the file's numbering for output.
namespace cavity::core {

/// One TetGen facet: coplanar loops (polygons of 3 or more corners) that do not cross. Its region
/// is given by the even-odd rule: the points inside an odd number of loops, so a loop nested in
/// another is a hole. The facet's hole points are kept but not needed by that rule (TetGen uses
/// them to carve holes; a loop nested without a hole point is therefore read differently).
/// Two-corner polygons of the facet are segments and go to Plc::segments.
struct PlcFacet {
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<Point3> holes;
    int marker = 0;
    std::size_t line = 0;  ///< line of the facet header in the .poly file, for messages
};

struct Plc {
    PointSet points;
    std::vector<PlcFacet> facets;
    std::vector<std::array<std::uint32_t, 2>> segments;  ///< explicit segments (2-corner polygons)
    std::vector<Point3> volume_holes;                    ///< read, not used by the CDT
    std::string source;
};

/// Every PLC edge (the explicit segments and the sides of every loop), each once as {min, max}.
std::vector<std::array<std::uint32_t, 2>> plc_edges(const Plc& plc);

/// Reads a TetGen `.poly` file. Part 1 lists the points (or declares 0 points, and then they come
/// from the `.node` file of the same name); part 2 lists the facets: `<#polygons> [<#holes>
/// [<marker>]]`, then each polygon `<#corners> c1 c2 ...`, then each hole `<i> x y z`; part 3 the
/// volume holes; a region part, if present, is ignored. Loops of one facet must be coplanar, with
/// distinct corners and no three consecutive corners collinear-degenerate (a loop with all corners
/// collinear is refused).
/// \throws Error naming the file and line of any malformed, truncated or inconsistent entry.
Plc read_poly(const std::filesystem::path& file);

}  // namespace cavity::core
