#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/input/point_set.h"
#include "cavity/core/io/atomic_file.h"

namespace cavity::core {

/// Writes PREFIX.node (every input point, numbered from points.index_base, the weight as the
/// attribute when weighted) and PREFIX.ele (`<#tets> 4 0`, then `i v0 v1 v2 v3` numbered from
/// points.index_base). `tets` have positive volume by the right-hand rule, as TetGen writes them.
/// Both files are committed together (AtomicFileGroup): on any error neither appears. Coordinates
/// are printed so that they read back exactly. \throws Error naming the file for a failed write or
/// a tet index outside the point set.
void write_tetgen(const std::filesystem::path& prefix,
                  const PointSet& points,
                  std::span<const Tet> tets);

/// The same, adding both files to `group` (committed by the caller with its other files).
void write_tetgen(AtomicFileGroup& group,
                  const std::filesystem::path& prefix,
                  const PointSet& points,
                  std::span<const Tet> tets);

/// How a .vtu stores its arrays: base64 of zlib-compressed blocks (VTK's default, a third of the
/// size) or ASCII text (readable, diffable, several times larger).
enum class VtuEncoding { kBinary, kAscii };

struct VtuOptions {
    VtuEncoding encoding = VtuEncoding::kBinary;
    /// Empty, or one region marker per tetrahedron, written as the cell data "region".
    std::span<const std::int32_t> regions;
};

/// Writes PREFIX.vtu: a VTK XML UnstructuredGrid (Float64 points, Int64 connectivity, cell type
/// 10 = VTK_TETRA) for ParaView, meshio and VTK. Cell data "tet_id" is each cell's number in the
/// .ele file (points.index_base + position), "region" the markers when given; point data
/// "weight" when weighted. `tets` have positive volume, as VTK expects its cells. Atomic as above.
/// \throws Error naming the file.
void write_vtu(const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets,
               const VtuOptions& options = {});

/// The same, adding the file to `group` (committed by the caller with its other files).
void write_vtu(AtomicFileGroup& group,
               const std::filesystem::path& prefix,
               const PointSet& points,
               std::span<const Tet> tets,
               const VtuOptions& options = {});

struct Adjacency;

/// TetGen's companions of the .ele file.
struct TetgenExtras {
    bool neighbors = false;   ///< PREFIX.neigh, TetGen's -n
    bool hull_faces = false;  ///< PREFIX.face: the convex hull's triangles
};

/// Writes PREFIX.node and PREFIX.ele listing adjacency.simplices in their order, and as asked
/// PREFIX.neigh (`<#tets> 4`, then for each tetrahedron the ones across the facets opposite its
/// four vertices, -1 on the hull) and PREFIX.face
/// (`<#triangles> 0`, then each hull triangle counter-clockwise seen from outside, as TetGen
/// lists boundary faces). Every number follows points.index_base; -1 stays -1. Atomic as above.
void write_tetgen(AtomicFileGroup& group,
                  const std::filesystem::path& prefix,
                  const PointSet& points,
                  const Adjacency& adjacency,
                  const TetgenExtras& extras);

/// Reads a TetGen .ele file whose vertex references are numbered from `index_base`, returning
/// 0-based tets. Header `<#tets> <nodes per tet = 4> [<#attributes>]`; element numbers start at 0
/// or 1 and must be consecutive; attributes are ignored. The caller checks that the indices are
/// below the number of points.
/// \throws Error naming the file and line for any malformed, truncated or extra line.
std::vector<Tet> read_ele(const std::filesystem::path& file, int index_base);

}  // namespace cavity::core
