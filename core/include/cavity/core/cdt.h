#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cavity/core/edge_protection.h"
#include "cavity/core/plc.h"
#include "cavity/core/polygon_insertion.h"

/// The constrained Delaunay tetrahedralization of a PLC (Cheng, Dey & Shewchuk §5.8): the Delaunay
/// triangulation of its vertices, then each polygon inserted by flips. The result is checked by the
/// independent validator (cdt_validate.h) before it is returned, so a caller never sees an invalid
/// mesh.
namespace cavity::core {

struct CdtOptions {
    bool protect = false;              ///< split unprotected edges instead of refusing the PLC
    std::size_t max_protection_points = 100000;
};

struct CdtFace {
    std::array<std::uint32_t, 3> v;
    int marker = 0;
};

struct Cdt {
    Plc plc;  ///< the input, with the protecting points appended (indices from plc.points.size())
    std::vector<std::array<std::uint32_t, 4>> tets;  ///< 0-based, positively oriented
    std::vector<CdtFace> faces;                      ///< the polygons' triangles, with markers
    Protection protection;
    PolygonInsertionCounters counters;
};

/// \throws Error when the PLC is not edge-protected and options.protect is off (naming the
/// unprotected edges), when protection fails, when polygon insertion fails, or when the result does
/// not pass validate_cdt (the message lists the problems).
Cdt build_cdt(Plc plc, const CdtOptions& options);

}  // namespace cavity::core
