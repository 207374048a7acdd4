#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "query.h"
#include "query_generators.h"

/// Metamorphic transformations whose effect on the exact sign is known in advance.
namespace cavity::predicates::testing {

/// The points of a query reordered, and the sign of that permutation (+1 even, -1 odd): every
/// predicate here is a determinant with one row per point, so an odd permutation flips its sign.
struct Permuted {
    Query query;
    int parity;
};

Permuted randomly_permuted(const Query& q, Rng& rng);

/// The query translated by (±2^i, ±2^j, ±2^k), weights unchanged, when some such translation is
/// exact for every coordinate (checked with the error term of two-sum); none otherwise. Exact
/// translation leaves every sign unchanged: orient3d and insphere depend on differences only, and
/// the power distance |x - p|^2 - w_p, hence the power test, is translation invariant.
std::optional<Query> translated_by_powers_of_two(const Query& q, Rng& rng);

}  // namespace cavity::predicates::testing
