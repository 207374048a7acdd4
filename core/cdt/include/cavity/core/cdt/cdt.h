#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cavity/core/cdt/edge_protection.h"
#include "cavity/core/cdt/polygon_insertion.h"
#include "cavity/core/input/plc.h"

/// The constrained Delaunay tetrahedralization of a PLC (Cheng, Dey & Shewchuk §5.8): the Delaunay
/// triangulation of its vertices, then each polygon inserted by flips. The result is checked by the
/// independent validator (cdt_validate.h) before it is returned, so a caller never sees an invalid
/// mesh. To keep inserting vertices into it (§5.7), use LiveCdt (cdt_vertex_insertion.h).
namespace cavity::core {

struct CdtOptions {
    bool protect = false;  ///< split unprotected edges instead of refusing the PLC
    std::size_t max_protection_points = 100000;
};

struct CdtFace {
    std::array<std::uint32_t, 3> v;
    int marker = 0;
};

/// Work of CDT vertex insertion (§5.7), for the experiments: every attempt, and what it cost.
struct CdtInsertionCounters {
    std::uint64_t attempts = 0;
    std::uint64_t inserted = 0;
    std::uint64_t duplicates = 0;               ///< points equal to a vertex (not inserted)
    std::uint64_t refused_not_star_shaped = 0;  ///< diagnosis 1: a new tetrahedron not positive
    std::uint64_t refused_through_cavity = 0;   ///< diagnosis 2: a polygon, edge or vertex inside
    std::uint64_t refused_not_delaunay = 0;     ///< a new face not locally Delaunay (no CDT)
    std::uint64_t walk_steps = 0;               ///< tetrahedra visited by point location
    std::uint64_t conflict_tests = 0;           ///< perturbed insphere / ghost tests of the search
    std::uint64_t face_tests = 0;               ///< perturbed insphere tests of new faces (check 3)
    std::uint64_t tets_deleted = 0;             ///< solid, by accepted insertions
    std::uint64_t tets_created = 0;
    std::uint64_t ghosts_deleted = 0;
    std::uint64_t ghosts_created = 0;
    std::uint64_t on_polygon = 0;               ///< accepted points in a polygon's closure
    std::uint64_t on_plc_edge = 0;              ///< accepted points splitting a PLC edge
    std::uint64_t polygon_triangles_split = 0;  ///< constrained triangles replaced
};

struct Cdt {
    Plc plc;  ///< the input PLC, then the protecting points appended after the input's points
              ///< (their indices start at the input's point count), then the inserted vertices;
              ///< its edges split where those points lie on them
    /// 0-based, each with positive right-hand volume (handedness.h)
    std::vector<std::array<std::uint32_t, 4>> tets;
    std::vector<CdtFace> faces;  ///< the polygons' triangles, with markers
    Protection protection;
    PolygonInsertionCounters counters;
    std::vector<std::uint32_t> inserted;  ///< indices of the vertices inserted after the polygons
    CdtInsertionCounters insertion;
};

/// \throws Error when two points coincide, when the PLC is not edge-protected and options.protect
/// is off (naming the unprotected edges), when it is not a valid PLC (plc_validity.h: edges
/// through polygons, overlapping facets, crossing loops), when protection fails, when polygon
/// insertion fails, or when the result does not pass validate_cdt (the message lists the
/// problems).
Cdt build_cdt(Plc plc, const CdtOptions& options);

}  // namespace cavity::core
