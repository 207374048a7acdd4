#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "cavity/predicates/point.h"

namespace cavity::core {

/// Finds four affinely independent points of an insertion sequence, exactly: the first point, the
/// first one distinct from it, then a point not collinear with those two and one not coplanar with
/// those three, each the best shaped of the first few valid candidates (Cheng, Dey & Shewchuk
/// §5.3: the bootstrap need not be random).
/// Returns their positions in `sequence`. Throws Error naming the affine dimension (0, 1 or 2) of
/// the input when no such four points exist, and "fewer than 4 distinct points" when that is why.
std::array<std::size_t, 4> find_bootstrap(std::span<const predicates::Point3> points,
                                          std::span<const std::uint32_t> sequence);

}  // namespace cavity::core
