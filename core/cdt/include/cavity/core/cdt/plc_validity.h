#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/input/plc.h"

/// Is the input a piecewise linear complex? Cheng, Dey & Shewchuk §4.5: the intersection of any two
/// cells is a union of cells, so polygons meet segments and one another only along shared sides and
/// corners. The .poly reader checks each facet alone (coplanar corners); this checks how the cells
/// meet, exactly (rational arithmetic), once the PLC is edge-protected.
namespace cavity::core {

/// The violations of the PLC conditions, each a message naming the file, the facet (its number and
/// line, facet_name) and point ids as the file numbers them; empty for a valid PLC.
///
/// Precondition: `delaunay_tets` is the Delaunay triangulation of plc.points (0-based indices) and
/// every PLC edge is one of its edges (edge protection). Then two PLC edges meet only at a shared
/// corner and no point lies inside an edge, so what is left to check is:
///  - no PLC edge crosses the region of a facet it is not a side of (its endpoints strictly on both
///    sides of the plane, the crossing point in the region);
///  - no facet has a side in the region of a coplanar facet (the two facets would overlap);
///  - the loops of one facet do not cross: two loops overlap only by nesting (each has pieces of
///    sides only inside-or-on or only outside-or-on the other);
///  - no hole point lies on a loop side.
/// Accepted, as the definition and TetGen accept them, and as build_cdt handles them (tested): a
/// point inside a polygon's region (the CDT has it as a vertex among the polygon's triangles); a
/// segment lying in a polygon's region (a slit) and a non-coplanar facet with a side in it (a wall
/// standing on the polygon): the edge is a cell, and an edge of the CDT among the polygon's
/// triangles. Not reported: coplanar facets with the same sides (duplicates, or the same loops with
/// different hole points).
/// When the precondition fails, the only message names the edges that are not Delaunay edges.
/// Cost: candidate pairs come from a uniform grid of bounding boxes (in doubles), so only edges
/// near a facet and loops near each other reach the exact tests.
std::vector<std::string> plc_violations(
    const Plc& plc, std::span<const std::array<std::uint32_t, 4>> delaunay_tets);

/// plc_violations of a PLC whose edges the caller has found among the Delaunay edges of its points
/// (the precondition): the same checks without finding them again.
std::vector<std::string> protected_plc_violations(const Plc& plc);

/// The violations that keep the given PLC edges from ever being protected: a PLC point inside one
/// of them, or a PLC edge crossing one of them at a point interior to both (exact; no Delaunay
/// triangulation needed). Checked by protect_edges on the unprotected edges before it splits them.
std::vector<std::string> edge_violations(const Plc& plc,
                                         std::span<const std::array<std::uint32_t, 2>> edges);

/// The same with `all`, the PLC's plc_edges already built.
std::vector<std::string> edge_violations(const Plc& plc,
                                         std::span<const std::array<std::uint32_t, 2>> all,
                                         std::span<const std::array<std::uint32_t, 2>> edges);

/// plc_violations, as an exception.
/// \throws Error listing the first violations and their number.
void require_valid_plc(const Plc& plc, std::span<const std::array<std::uint32_t, 4>> delaunay_tets);

/// protected_plc_violations, as an exception. \throws Error as require_valid_plc.
void require_valid_protected_plc(const Plc& plc);

/// edge_violations, as an exception. \throws Error listing the first violations.
/// `all` is the PLC's plc_edges.
void require_edges_meet_properly(const Plc& plc,
                                 std::span<const std::array<std::uint32_t, 2>> all,
                                 std::span<const std::array<std::uint32_t, 2>> edges);

}  // namespace cavity::core
