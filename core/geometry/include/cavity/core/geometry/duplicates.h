#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cavity/predicates/point.h"

namespace cavity::core {

/// For every point, the input index of the first point with the same coordinates (and, when
/// weights are given, the same weight); a point that repeats none maps to itself. Found before
/// insertion so that the surviving copy is always the lowest index: the output never depends on
/// the insertion order. +0.0 and -0.0 are the same coordinate. Expected O(n) (hashing), shared
/// by `threads` threads; the result is the same for every count.
std::vector<std::uint32_t> first_occurrences(std::span<const predicates::Point3> points,
                                             std::span<const double> weights,
                                             unsigned threads = 1);

}  // namespace cavity::core
