#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// A 64-bit fingerprint (FNV-1a) of the point count and the exact bits of every coordinate: equal
/// for the same points however they were written (.node, .xyz, PLY; any number formatting), and
/// different, but for a 2^-64 chance, for any other points. Weights are left out: the same mesh
/// file serves `check` with and without --weighted.
std::uint64_t points_fingerprint(const PointSet& points);

/// The comment write_tetgen puts at the end of each .ele's header line, naming the fingerprint of
/// the points it was triangulated from: "# cavity: points fingerprint <16 hex digits>".
std::string points_fingerprint_comment(std::uint64_t fingerprint);

/// The fingerprint a .ele file names in its header line (or a comment line before it), or nothing
/// when it names none (a TetGen file, or cavity's before 0.2). Reads no further than the header.
/// \throws Error naming the file when it cannot be read.
std::optional<std::uint64_t> read_points_fingerprint(const std::filesystem::path& ele);

/// Refuses a .ele whose fingerprint names other points than `points` (read from `node`): the two
/// files come from different runs (two runs on one prefix, or one killed between its renames).
/// A .ele without a fingerprint passes. \throws Error naming both files and both fingerprints.
void check_points_fingerprint(const std::filesystem::path& ele,
                              const std::string& node,
                              const PointSet& points);

}  // namespace cavity::core
