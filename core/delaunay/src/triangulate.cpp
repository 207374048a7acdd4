#include "cavity/core/delaunay/triangulate.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "cavity/core/base/error.h"
#include "cavity/core/delaunay/insertion_driver.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/geometry/duplicates.h"

namespace cavity::core {

LocateKind parse_locate_kind(std::string_view name) {
    return parse_kind(kLocateKinds, name, "point location");
}

StorageKind parse_storage_kind(std::string_view name) {
    return parse_kind(kStorageKinds, name, "storage");
}

namespace detail {

namespace {

// Bad input is reported before anything is built: a non-finite coordinate or weight (NaN would
// break every ordering and predicate), weights that do not match the points, or a sequence that is
// not a permutation of the points.
void check_input(const PointSet& input, std::span<const std::uint32_t> sequence) {
    const std::size_t n = input.size();
    if (input.weighted() && input.weights.size() != n) {
        throw Error(std::to_string(input.weights.size()) + " weights for " + std::to_string(n) +
                    " points");
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Point3& p = input.points[i];
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                            (!input.weighted() || std::isfinite(input.weights[i]));
        if (!finite) {
            throw Error("point " + std::to_string(i + static_cast<std::size_t>(input.index_base)) +
                        " has a non-finite coordinate or weight");
        }
    }
    if (sequence.size() != n) {
        throw Error("the insertion sequence has " + std::to_string(sequence.size()) +
                    " entries for " + std::to_string(n) + " points");
    }
    std::vector<bool> seen(n, false);
    for (std::uint32_t i : sequence) {
        if (i >= n || seen[i]) {
            throw Error("the insertion sequence is not a permutation of the points (entry " +
                        std::to_string(i) + ")");
        }
        seen[i] = true;
    }
}

}  // namespace

Prepared prepare(const PointSet& input,
                 std::span<const std::uint32_t> sequence,
                 BootstrapRule rule,
                 Triangulation& out,
                 unsigned threads) {
    check_input(input, sequence);
    const bool has_implicit = !input.exact.empty();
    const auto implicit = [&](std::uint32_t i) {
        return has_implicit && !std::holds_alternative<Point3>(input.exact[i]);
    };
    auto first = first_occurrences(input.points, input.weights, threads);
    if (has_implicit) {
        // An implicit point's rounding may equal another point's coordinates, but the point does
        // not: neither repeats the other.
        for (std::uint32_t i = 0; i < first.size(); ++i) {
            if (implicit(i) || implicit(first[i])) {
                first[i] = i;
            }
        }
    }
    std::vector<std::uint32_t> order;
    order.reserve(sequence.size());
    for (std::uint32_t i : sequence) {
        if (first[i] == i) {
            order.push_back(i);
        }
    }
    // The bootstrap tetrahedron is chosen on coordinates, so only among explicit points: the
    // implicit ones go last.
    const auto explicit_end = std::stable_partition(
        order.begin(), order.end(), [&](std::uint32_t i) { return !implicit(i); });
    for (std::uint32_t i = 0; i < first.size(); ++i) {
        if (first[i] != i) {
            out.duplicates.push_back({i, first[i]});
        }
    }
    const auto boot =
        find_bootstrap(input.points,
                       std::span<const std::uint32_t>(
                           order.data(), static_cast<std::size_t>(explicit_end - order.begin())),
                       rule);
    // Move the bootstrap four to the front, keeping the relative order of the rest.
    std::vector<std::uint32_t> seq;
    seq.reserve(order.size());
    for (std::size_t k : boot) {
        seq.push_back(order[k]);
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (std::find(boot.begin(), boot.end(), k) == boot.end()) {
            seq.push_back(order[k]);
        }
    }
    std::vector<Point3> points(seq.size());
    std::vector<double> weights(input.weighted() ? seq.size() : 0);
    std::vector<GenericPoint3> exact(has_implicit ? seq.size() : 0);
    for (std::size_t r = 0; r < seq.size(); ++r) {
        points[r] = input.points[seq[r]];
        if (has_implicit) {
            exact[r] = input.exact[seq[r]];
        }
        if (input.weighted()) {
            weights[r] = input.weights[seq[r]];
        }
    }
    return {Geometry(std::move(points), std::move(seq), std::move(weights), std::move(exact))};
}

void merge_conflict_tally(const ConflictTally& tally, Counters& counters, bool counted) {
    if (!counted) {
        counters.conflicts_created = tally.created;
        counters.ghost_conflicts_created = tally.ghost_created;
        counters.conflicts_deleted = tally.deleted;
        counters.ghost_conflicts_deleted = tally.ghost_deleted;
        counters.live_conflicts_max = tally.live_max;
        return;
    }
    if (counters.conflicts_created != tally.created ||
        counters.ghost_conflicts_created != tally.ghost_created ||
        counters.conflicts_deleted != tally.deleted ||
        counters.ghost_conflicts_deleted != tally.ghost_deleted ||
        counters.live_conflicts_max != tally.live_max) {
        throw InternalError(
            "internal error: the full conflict graph created " + std::to_string(tally.created) +
            " + " + std::to_string(tally.ghost_created) + " conflicts, the conflict counter " +
            std::to_string(counters.conflicts_created) + " + " +
            std::to_string(counters.ghost_conflicts_created));
    }
}

}  // namespace detail

}  // namespace cavity::core
