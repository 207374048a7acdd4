#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "cavity/core/base/names.h"
#include "cavity/predicates/point.h"

namespace cavity::core {

/// How the first tetrahedron is chosen from the insertion sequence.
enum class BootstrapRule {
    /// The first point, the first one distinct from it, then the widest triangle and the highest
    /// fourth point among the next 64 valid candidates: a well-shaped start (the conflict graph
    /// needs a representable point strictly inside it). §5.3: the bootstrap need not be random,
    /// for the asymptotic bounds; but it makes the order non-exchangeable, which biases exact
    /// identities such as Proposition 5.2's q_j = 1/C(j+4, 4).
    kWidest,
    /// The first point, the first distinct from it, the first not collinear with those two and
    /// the first not coplanar with those three, in sequence order. For points in general position
    /// in a uniform permutation these are the first four: the insertion order is the permutation
    /// itself, as the identities of §5.3 assume.
    kFirst,
};

/// The rules' names (`--bootstrap`, suite files), one row per BootstrapRule.
inline constexpr std::array<NamedKind<BootstrapRule>, 2> kBootstrapRules{{
    {"widest", BootstrapRule::kWidest, "the widest of the next 64 candidates"},
    {"first",
     BootstrapRule::kFirst,
     "the first four affinely independent points of the order (keeps a uniform order uniform)"},
}};

/// A name of kBootstrapRules. \throws Error for any other name.
BootstrapRule parse_bootstrap_rule(std::string_view name);

/// Finds four affinely independent points of an insertion sequence, exactly, by `rule`.
/// Returns their positions in `sequence`. Throws Error naming the affine dimension (0, 1 or 2) of
/// the input when no such four points exist, and "fewer than 4 distinct points" when that is why.
std::array<std::size_t, 4> find_bootstrap(std::span<const predicates::Point3> points,
                                          std::span<const std::uint32_t> sequence,
                                          BootstrapRule rule = BootstrapRule::kWidest);

}  // namespace cavity::core
