#include "coplanar_facets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "cavity/core/base/bucket_sort.h"
#include "ear_clipping.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

using Loop = std::vector<std::uint32_t>;

bool is_simple_face(const PlcFacet& f) {
    return f.loops.size() == 1 && f.holes.empty() && f.loops[0].size() >= 3;
}

std::uint64_t side_key(std::uint32_t p, std::uint32_t q) {
    return (std::uint64_t{std::min(p, q)} << 32) | std::max(p, q);
}

/// Union-find over facet indices, with path halving: the groups of coplanar neighbours.
class FacetGroups {
public:
    explicit FacetGroups(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
    }

    std::uint32_t find(std::uint32_t f) {
        while (parent_[f] != f) {
            parent_[f] = parent_[parent_[f]];
            f = parent_[f];
        }
        return f;
    }

    void unite(std::uint32_t f, std::uint32_t g) { parent_[find(f)] = find(g); }

private:
    std::vector<std::uint32_t> parent_;
};

/// The group's boundary as closed loops of corners: the sides that only one of its facets has,
/// chained at their corners. Nothing when a corner ends more than two such sides (the region
/// pinches there, and a loop through it would not be simple).
std::optional<std::vector<Loop>> boundary_loops(const Plc& plc,
                                                const std::vector<std::uint32_t>& group) {
    std::vector<std::uint64_t> keys;
    for (const std::uint32_t f : group) {
        const Loop& loop = plc.facets[f].loops[0];
        for (std::size_t i = 0; i < loop.size(); ++i) {
            keys.push_back(side_key(loop[i], loop[(i + 1) % loop.size()]));
        }
    }
    std::sort(keys.begin(), keys.end());
    // Each boundary side, from both of its ends, sorted by the corner it starts from.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) {
            ++j;
        }
        if (j - i == 1) {
            const auto low = static_cast<std::uint32_t>(keys[i] >> 32);
            const auto high = static_cast<std::uint32_t>(keys[i]);
            ends.emplace_back(low, high);
            ends.emplace_back(high, low);
        }
        i = j;
    }
    std::sort(ends.begin(), ends.end());
    for (std::size_t i = 0; i < ends.size(); i += 2) {
        const bool pair = i + 1 < ends.size() && ends[i + 1].first == ends[i].first;
        const bool more = i + 2 < ends.size() && ends[i + 2].first == ends[i].first;
        if (!pair || more) {
            return std::nullopt;
        }
    }
    // ends[2k] and ends[2k + 1] are the two boundary sides at one corner.
    const auto slot = [&](std::uint32_t corner) {
        const auto it =
            std::lower_bound(ends.begin(), ends.end(), std::make_pair(corner, std::uint32_t{0}));
        return static_cast<std::size_t>(it - ends.begin());
    };
    std::vector<bool> used(ends.size() / 2, false);
    std::vector<Loop> loops;
    for (std::size_t start = 0; start < ends.size(); start += 2) {
        if (used[start / 2]) {
            continue;
        }
        Loop loop;
        std::uint32_t previous = ends[start + 1].second;
        std::uint32_t corner = ends[start].first;
        while (!used[slot(corner) / 2]) {
            const std::size_t s = slot(corner);
            used[s / 2] = true;
            loop.push_back(corner);
            const std::uint32_t next =
                ends[s].second != previous ? ends[s].second : ends[s + 1].second;
            previous = corner;
            corner = next;
        }
        loops.push_back(std::move(loop));
    }
    if (loops.empty()) {
        return std::nullopt;
    }
    return loops;
}

/// The index of the loop that has a corner of every other loop strictly inside it, in the
/// projection dropping `drop`. The group is connected and pinch-free, so its region is bounded
/// by one outer loop with the others (its holes) inside; nothing when no loop is (exactly).
std::optional<std::size_t> outer_loop(const Plc& plc, const std::vector<Loop>& loops, int drop) {
    for (std::size_t i = 0; i < loops.size(); ++i) {
        bool encloses = true;
        for (std::size_t j = 0; j < loops.size() && encloses; ++j) {
            encloses = j == i ||
                       loop_position(plc, loops[i], drop, exact_point(plc.points, loops[j][0])) ==
                           LoopPosition::kInside;
        }
        if (encloses) {
            return i;
        }
    }
    return std::nullopt;
}

/// The coordinate `axis` of p.
double& coordinate(Point3& p, int axis) {
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

/// A point with double coordinates exactly in the plane whose projection lies strictly inside
/// the loop, for a hole point: a .poly hole point must lie in its facet's plane, which
/// `cavity check --poly` holds the written PLC to. Tried near the centroid of each of the loop's
/// ear-clipping triangles, its kept coordinates rounded to a few binary grids finer than the
/// triangle (so that the plane may pass exactly through a double above them), the dropped one
/// solved from the triangle's plane in doubles; both conditions are then checked exactly. On an
/// axis-parallel plane the solved coordinate is the plane's own; on a tilted one, no nearby
/// point with double coordinates may lie in the plane at all, and the group is not merged.
std::optional<Point3> point_inside(const Plc& plc, const Loop& loop, const ExactPlane& plane) {
    const int drop = plane.dropped_axis();
    const auto ears = ear_clipping(plc.points.points, loop, drop);
    if (!ears) {
        return std::nullopt;
    }
    const int u = (drop + 1) % 3;
    const int v = (drop + 2) % 3;
    for (const Triangle& t : *ears) {
        Point3 a = plc.points.points[t[0]];
        Point3 b = plc.points.points[t[1]];
        Point3 c = plc.points.points[t[2]];
        // n = (b - a) x (c - a) in doubles: only the candidates rest on it.
        const double bu = coordinate(b, u) - coordinate(a, u);
        const double bv = coordinate(b, v) - coordinate(a, v);
        const double bw = coordinate(b, drop) - coordinate(a, drop);
        const double cu = coordinate(c, u) - coordinate(a, u);
        const double cv = coordinate(c, v) - coordinate(a, v);
        const double cw = coordinate(c, drop) - coordinate(a, drop);
        const double nu = bv * cw - bw * cv;
        const double nv = bw * cu - bu * cw;
        const double nw = bu * cv - bv * cu;
        const double mu = coordinate(a, u) / 3 + coordinate(b, u) / 3 + coordinate(c, u) / 3;
        const double mv = coordinate(a, v) / 3 + coordinate(b, v) / 3 + coordinate(c, v) / 3;
        const double extent =
            std::max({std::fabs(bu), std::fabs(bv), std::fabs(cu), std::fabs(cv)});
        if (nw == 0 || extent == 0 || !std::isfinite(extent)) {
            continue;
        }
        for (const int finer : {6, 16, 30, 60}) {
            const int grid = std::ilogb(extent) - finer;
            Point3 x{};
            coordinate(x, u) = std::ldexp(std::nearbyint(std::ldexp(mu, -grid)), grid);
            coordinate(x, v) = std::ldexp(std::nearbyint(std::ldexp(mv, -grid)), grid);
            coordinate(x, drop) =
                coordinate(a, drop) - (nu * (coordinate(x, u) - coordinate(a, u)) +
                                       nv * (coordinate(x, v) - coordinate(a, v))) /
                                          nw;
            if (std::isfinite(coordinate(x, drop)) && plane.side(x) == predicates::Sign::kZero &&
                loop_position(plc, loop, drop, exact_point(x)) == LoopPosition::kInside) {
                return x;
            }
        }
    }
    return std::nullopt;
}

/// The group as one facet, or nothing when it has a pinch or a hole without a double inside.
std::optional<PlcFacet> merged_facet(const Plc& plc,
                                     const std::vector<std::uint32_t>& group,
                                     const ExactPlane& plane) {
    auto loops = boundary_loops(plc, group);
    if (!loops) {
        return std::nullopt;
    }
    const int drop = plane.dropped_axis();
    const auto outer = outer_loop(plc, *loops, drop);
    if (!outer) {
        return std::nullopt;
    }
    std::swap((*loops)[0], (*loops)[*outer]);
    const PlcFacet& first = plc.facets[group.front()];
    PlcFacet merged;
    merged.marker = first.marker;
    merged.line = first.line;
    merged.number = first.number;
    for (std::size_t i = 1; i < loops->size(); ++i) {
        const auto hole = point_inside(plc, (*loops)[i], plane);
        if (!hole) {
            return std::nullopt;
        }
        merged.holes.push_back(*hole);
    }
    merged.loops = std::move(*loops);
    return merged;
}

}  // namespace

CoplanarMerge merge_coplanar_facets(Plc& plc) {
    const std::size_t n = plc.facets.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> sides;
    for (std::uint32_t f = 0; f < n; ++f) {
        if (!is_simple_face(plc.facets[f])) {
            continue;
        }
        const Loop& loop = plc.facets[f].loops[0];
        for (std::size_t i = 0; i < loop.size(); ++i) {
            sides.emplace_back(side_key(loop[i], loop[(i + 1) % loop.size()]), f);
        }
    }
    bucket_sort(sides, [](const auto& side) { return std::size_t{side.first >> 32}; });
    std::vector<std::optional<ExactPlane>> planes(n);
    std::vector<bool> planed(n, false);
    const auto plane_of = [&](std::uint32_t f) -> const std::optional<ExactPlane>& {
        if (!planed[f]) {
            planes[f] = ExactPlane::of_facet(plc, plc.facets[f]);
            planed[f] = true;
        }
        return planes[f];
    };
    const auto coplanar = [&](std::uint32_t f, std::uint32_t g) {
        const auto& plane = plane_of(f);
        if (!plane || !plane_of(g)) {
            return false;
        }
        // f is planar (the surface check refused it otherwise), so its own corners are on its
        // plane: of a triangle neighbour only the corner off the shared side is asked, and an
        // exactly zero orient3d is the predicate's most expensive answer.
        const Loop& own = plc.facets[f].loops[0];
        const Loop& corners = plc.facets[g].loops[0];
        return std::all_of(corners.begin(), corners.end(), [&](std::uint32_t c) {
            return std::find(own.begin(), own.end(), c) != own.end() ||
                   plane->side(plc.points.points[c]) == predicates::Sign::kZero;
        });
    };
    FacetGroups groups(n);
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        while (j < sides.size() && sides[j].first == sides[i].first) {
            ++j;
        }
        if (j - i == 2) {
            const std::uint32_t f = sides[i].second;
            const std::uint32_t g = sides[i + 1].second;
            if (f != g && plc.facets[f].marker == plc.facets[g].marker && coplanar(f, g)) {
                groups.unite(f, g);
            }
        }
        i = j;
    }
    std::vector<std::vector<std::uint32_t>> members(n);
    for (std::uint32_t f = 0; f < n; ++f) {
        members[groups.find(f)].push_back(f);
    }
    CoplanarMerge merge;
    std::vector<std::optional<PlcFacet>> merged(n);
    for (std::uint32_t r = 0; r < n; ++r) {
        if (members[r].size() >= 2) {
            merged[r] = merged_facet(plc, members[r], *plane_of(members[r].front()));
            if (merged[r]) {
                merge.faces += members[r].size();
                ++merge.polygons;
            }
        }
    }
    if (merge.polygons == 0) {
        return merge;
    }
    std::vector<PlcFacet> facets;
    facets.reserve(n - merge.faces + merge.polygons);
    for (std::uint32_t f = 0; f < n; ++f) {
        const std::uint32_t r = groups.find(f);
        if (!merged[r]) {
            facets.push_back(std::move(plc.facets[f]));
        } else if (members[r].front() == f) {
            facets.push_back(std::move(*merged[r]));
        }
    }
    plc.facets = std::move(facets);
    return merge;
}

}  // namespace cavity::core
