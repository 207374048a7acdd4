#pragma once

// What the mesh writers share: file names, the .ele body, the check made before a file is added.

#include <filesystem>
#include <span>

#include "cavity/core/io/mesh_io.h"

namespace cavity::core {

/// A tetrahedron naming a point that does not exist would make a file no reader can use: refuse
/// it before anything is committed. \throws Error naming `file`, the tetrahedron and the point.
/// PREFIX + suffix (".node", ".ele"...): the suffix is appended, never substituted.
std::filesystem::path with_suffix(const std::filesystem::path& prefix, const char* suffix);

/// The body of a TetGen .ele file, `tets` as they are (positive volume).
void write_ele(AtomicFileGroup::Writer& out, const PointSet& points, std::span<const Tet> tets);

void check_tets(const std::filesystem::path& file,
                const PointSet& points,
                std::span<const Tet> tets);

}  // namespace cavity::core
