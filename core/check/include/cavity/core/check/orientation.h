#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"
#include "cavity/core/io/mesh_io.h"

namespace cavity::core {

/// How the tetrahedra of a mesh file are oriented, by the sign of their volume under the
/// right-hand rule, det[b−a, c−a, d−a], decided exactly (orient3d). Tetrahedra naming a point
/// outside the set are left uncounted (the validator names them).
struct OrientationCount {
    std::size_t positive = 0;  ///< TetGen's and VTK's convention, and what cavity writes
    std::size_t negative = 0;  ///< the engine's internal orientation (orient3d > 0)
    std::size_t flat = 0;
};

OrientationCount count_orientations(const PointSet& points, std::span<const Tet> tets);

/// Tetrahedra read from `file` are expected with positive volume (TetGen's files, VTK's cells,
/// cavity's own since version 0.2), as the validators take them. A mesh whose every non-flat
/// tetrahedron has negative volume is refused by a message naming the convention it follows
/// (cavity's files before 0.2 were written so), rather than by one problem per tetrahedron. A mixed
/// mesh passes: the validator reports each inverted one.
/// \throws Error naming the file for a consistently inverted mesh.
void refuse_inverted_mesh(const std::string& file,
                          const PointSet& points,
                          std::span<const Tet> tets);

}  // namespace cavity::core
