#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "cavity/core/base/names.h"
#include "cavity/core/input/point_set.h"

namespace cavity::core {

enum class OrderKind { kInput, kRandom, kBrio, kHilbert, kZOrder };

/// The orders' names (`--order`, Python's `order=`, suite files), one row per OrderKind.
inline constexpr std::array<NamedKind<OrderKind>, 5> kOrderKinds{{
    {"input", OrderKind::kInput, "the points' own order"},
    {"random", OrderKind::kRandom, "a uniform random permutation"},
    {"brio", OrderKind::kBrio, "a biased randomized insertion order, rounds along a Hilbert curve"},
    {"hilbert", OrderKind::kHilbert, "the whole set along a Hilbert curve"},
    {"zorder", OrderKind::kZOrder, "the whole set along a Z-order (Morton) curve"},
}};

/// A name of kOrderKinds. \throws Error for any other name.
OrderKind parse_order_kind(std::string_view name);

struct OrderOptions {
    OrderKind kind = OrderKind::kBrio;
    std::uint64_t seed = 0;
    /// BRIO: the fraction of points carried into the earlier rounds, the convention of Amenta, Choi
    /// and Rote (1/2), CGAL's spatial_sort and geogram (1/8): each point still unassigned goes to
    /// an earlier round with this probability, else stays in the latest remaining one. The default
    /// is the engines' 1/8 (HXT's is about the same): fewer rounds, so fewer sweeps of the walk
    /// across the whole mesh. The experiments' suites keep the theory's 1/2 unless they say.
    double brio_ratio = 0.125;
    /// BRIO: sort the even-numbered rounds backwards along the curve, so each round starts near
    /// where the previous one ended (Cheng, Dey, Shewchuk, "Delaunay Mesh Generation", §5.5).
    bool reverse_alternate_rounds = true;
    /// Threads that sort along the curve (every order but input and random). The order is the same
    /// for every count.
    unsigned threads = 1;
};

struct InsertionOrder {
    std::vector<std::uint32_t> sequence;     ///< input indices, in insertion order
    std::vector<std::uint32_t> round_begin;  ///< BRIO: start of each round in sequence, else empty
};

/// The order in which to insert `points`:
/// - kInput: 0, 1, ..., n-1.
/// - kRandom: a uniform permutation (Fisher–Yates driven by Random(seed)).
/// - kBrio: a biased randomized insertion order (Amenta, Choi, Rote 2003; the book's §5.3). With
///   ρ = brio_ratio, rounds are numbered 0..R, R the least integer with n ρ^R <= 1; each point
///   goes to round R with probability 1 - ρ, else to round R-1 with probability 1 - ρ, and so on;
///   round 0 keeps the rest. ρ = 0 is a single curve-sorted round. Rounds are inserted first to
///   last, each sorted along the Hilbert curve (hilbert_sort), even-numbered rounds reversed when
///   reverse_alternate_rounds is set. round_begin has R+1 entries; round r is [round_begin[r],
///   round_begin[r+1]) (to the end for the last), and may be empty.
/// - kHilbert: hilbert_sort of the whole set; kZOrder: morton_sort of the whole set.
/// The result depends only on the points and the options, never on the platform.
/// \throws Error for more than 2^32-1 points, a non-finite coordinate (curve orders), or a
/// brio_ratio outside [0, 1).
InsertionOrder make_insertion_order(std::span<const Point3> points, const OrderOptions& options);

}  // namespace cavity::core
