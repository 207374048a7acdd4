#include "cavity/core/delaunay/triangulate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <variant>

#include "cavity/core/base/error.h"
#include "cavity/core/base/on_threads.h"
#include "cavity/core/base/page_releaser.h"
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

namespace {

/// The engine's keys: `sequence` without repeats (each point kept at its lowest index, the others
/// listed in out.duplicates), the bootstrap four (by `rule`) first, the rest in their order. Works
/// in `sequence`'s own array.
std::vector<std::uint32_t> engine_keys(const PointSet& input,
                                       std::vector<std::uint32_t> sequence,
                                       BootstrapRule rule,
                                       Triangulation& out,
                                       unsigned threads) {
    const bool has_implicit = !input.exact.empty();
    const auto implicit = [&](std::uint32_t i) {
        return has_implicit && !std::holds_alternative<Point3>(input.exact[i]);
    };
    {
        auto first = first_occurrences(input.points, input.weights, threads);
        if (has_implicit) {
            // An implicit point's rounding may equal another point's coordinates, but the point
            // does not: neither repeats the other.
            for (std::uint32_t i = 0; i < first.size(); ++i) {
                if (implicit(i) || implicit(first[i])) {
                    first[i] = i;
                }
            }
        }
        std::erase_if(sequence, [&](std::uint32_t i) { return first[i] != i; });
        for (std::uint32_t i = 0; i < first.size(); ++i) {
            if (first[i] != i) {
                out.duplicates.push_back({i, first[i]});
            }
        }
    }
    // The repeat detection's arrays (8 to 12 bytes per point) are gone; their pages would
    // otherwise stay resident under the storage.
    release_free_heap();
    // The bootstrap tetrahedron is chosen on coordinates, so only among explicit points: the
    // implicit ones go last.
    const auto explicit_end = std::stable_partition(
        sequence.begin(), sequence.end(), [&](std::uint32_t i) { return !implicit(i); });
    const auto boot = find_bootstrap(
        input.points,
        std::span<const std::uint32_t>(sequence.data(),
                                       static_cast<std::size_t>(explicit_end - sequence.begin())),
        rule);
    // Move the bootstrap four to the front, keeping the relative order of the rest: the rest
    // shift towards the back, from the back, so that no entry is overwritten before it is read.
    std::array<std::uint32_t, 4> front{};
    for (std::size_t j = 0; j < 4; ++j) {
        front[j] = sequence[boot[j]];
    }
    std::size_t write = sequence.size();
    for (std::size_t k = sequence.size(); k-- > 0;) {
        if (std::find(boot.begin(), boot.end(), k) == boot.end()) {
            sequence[--write] = sequence[k];
        }
    }
    std::copy(front.begin(), front.end(), sequence.begin());
    return sequence;
}

/// Below this many rows per thread, threads cost more than they save.
constexpr std::size_t kRowsPerThread = std::size_t{1} << 16;

/// Marks point i; true when it was marked already.
bool test_and_set(std::vector<std::uint64_t>& marks, std::size_t i) {
    const std::uint64_t bit = std::uint64_t{1} << (i & 63u);
    const bool was = (marks[i >> 6] & bit) != 0;
    marks[i >> 6] |= bit;
    return was;
}

}  // namespace

Prepared prepare(const PointSet& input,
                 std::span<const std::uint32_t> sequence,
                 BootstrapRule rule,
                 Triangulation& out,
                 unsigned threads) {
    check_input(input, sequence);
    std::vector<std::uint32_t> seq = engine_keys(
        input, std::vector<std::uint32_t>(sequence.begin(), sequence.end()), rule, out, threads);
    const bool has_implicit = !input.exact.empty();
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
    return {
        Geometry(std::move(points), std::move(seq), std::move(weights), std::move(exact)), {}, {}};
}

Prepared prepare_in_place(PointSet& input,
                          std::vector<std::uint32_t>&& sequence,
                          BootstrapRule rule,
                          Triangulation& out,
                          unsigned threads) {
    check_input(input, sequence);
    std::vector<std::uint32_t> seq = engine_keys(input, std::move(sequence), rule, out, threads);
    const bool has_implicit = !input.exact.empty();
    std::vector<double> weights(input.weighted() ? seq.size() : 0);
    std::vector<GenericPoint3> exact(has_implicit ? seq.size() : 0);
    for (std::size_t r = 0; r < seq.size(); ++r) {
        if (has_implicit) {
            exact[r] = input.exact[seq[r]];
        }
        if (input.weighted()) {
            weights[r] = input.weights[seq[r]];
        }
    }
    // Row r takes the point of input index seq[r], the repeats go after the keys in index order.
    // The rows are gathered into a new array by the threads, and the lent array goes back to the
    // allocator at once: that moment's two copies (48 bytes a point) stay far below the peak,
    // which comes later with the mesh, while permuting in place, cycle by cycle, was the largest
    // step of the parallel build left on one thread (65 ms at 10^6 points).
    const std::size_t n = input.size();
    const std::size_t m = seq.size();
    std::vector<std::uint64_t> marks(n / 64 + 1, 0);
    std::vector<Point3> repeats(n - m);
    std::vector<Point3> p(n);
    // Everything that can fail is done: from here the points move, and only give_back returns
    // them.
    const auto origin = [&](std::size_t j) {
        return j < m ? std::size_t{seq[j]} : std::size_t{out.duplicates[j - m][0]};
    };
    const unsigned parts = static_cast<unsigned>(
        std::clamp<std::size_t>(n / kRowsPerThread, 1, std::max(1u, threads)));
    on_threads(parts, [&](unsigned k) {
        for (std::size_t j = n * k / parts; j < n * (k + 1) / parts; ++j) {
            p[j] = input.points[origin(j)];
        }
    });
    std::vector<Point3>().swap(input.points);
    std::copy(p.begin() + static_cast<std::ptrdiff_t>(m), p.end(), repeats.begin());
    p.resize(m);
    // give_back zeroes the marks before it reads them, so their pages can leave the resident
    // memory while the engine builds (n/8 bytes at its peak).
    PageReleaser(reinterpret_cast<unsigned char*>(marks.data()))
        .release_before(reinterpret_cast<unsigned char*>(marks.data() + marks.size()));
    return {Geometry(std::move(p), std::move(seq), std::move(weights), std::move(exact)),
            std::move(repeats),
            std::move(marks)};
}

void give_back(Prepared& prep, const Triangulation& out, PointSet& input) noexcept {
    const std::size_t m = prep.geometry.size();
    const std::size_t n = m + prep.repeats.size();
    std::vector<Point3> p = std::move(prep.geometry).take_points();
    // Within the array's capacity (it held all n points): no allocation.
    p.resize(n);
    std::copy(prep.repeats.begin(), prep.repeats.end(), p.begin() + static_cast<std::ptrdiff_t>(m));
    std::fill(prep.marks.begin(), prep.marks.end(), 0);
    const auto origin = [&](std::size_t j) {
        return j < m ? std::size_t{prep.geometry.key(static_cast<VertexId>(j))}
                     : std::size_t{out.duplicates[j - m][0]};
    };
    // The inverse of prepare_in_place's permutation: the point in row j goes to index origin(j).
    for (std::size_t start = 0; start < n; ++start) {
        if (test_and_set(prep.marks, start)) {
            continue;
        }
        Point3 carried = p[start];
        std::size_t j = start;
        do {
            const std::size_t to = origin(j);
            std::swap(carried, p[to]);
            test_and_set(prep.marks, to);
            j = to;
        } while (j != start);
    }
    input.points = std::move(p);
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
