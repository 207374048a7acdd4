#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/geometry/geometry.h"
#include "cavity/core/input/point_set.h"
#include "cavity/core/mesh/array_storage.h"

namespace cavity::core {

/// The array storage of a triangulation given as solid tetrahedra (positive right-hand volume, as
/// the API lists them, stored mirrored to orient3d > 0; vertex id = the given index), with a ghost
/// tetrahedron over every boundary triangle and every facet glued: the live form that flips and
/// vertex deletion work on. Two tetrahedra on the same side of a triangle (an inverted one, say)
/// are glued all the same, so that check_complex can name the culprit. \throws Error when a
/// triangle has more than two tetrahedra, when a hull edge has more than two hull triangles, or
/// when the boundary is not closed.
ArrayStorage complex_from_tets(std::span<const std::array<std::uint32_t, 4>> tets);

/// complex_from_tets(tets) with the solid facets already paired by the caller, who found the
/// triangles for checks of its own: across[4 t + f] is the tetrahedron on the other side of the
/// facet of tets[t] opposite its vertex tets[t][f], or -1 on the boundary (no triangle has more
/// than two tetrahedra). The pairing is a function of the tetrahedra, so the complex is the same.
ArrayStorage complex_from_tets(std::span<const std::array<std::uint32_t, 4>> tets,
                               std::span<const std::int32_t> across);

/// The live solid tetrahedra, in slot order.
std::vector<std::array<std::uint32_t, 4>> solid_tets(const ArrayStorage& storage);

/// Checks the live complex exactly: adjacency is symmetric and each glued pair is one triangle
/// seen with opposite orientations; every facet is glued; solid tetrahedra are stored with
/// orient3d > 0 (problems name them as the API lists them, mirrored); ghosts hold the ghost vertex
/// in slot 3 and the hull is locally convex (the apex behind every hull triangle and the third
/// vertex of every neighbouring hull triangle are not in front of it). Returns the problems found
/// (empty: valid).
std::vector<std::string> check_complex(const ArrayStorage& storage, const Geometry& geometry);

/// Geometry whose vertex ids are the input indices (key = index), for complexes built by
/// complex_from_tets.
Geometry geometry_by_index(const PointSet& points);

}  // namespace cavity::core
