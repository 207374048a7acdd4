#include "cavity/core/cdt/cdt_regions.h"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "cavity/core/base/error.h"
#include "cavity/core/mesh/tetrahedron.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

namespace {

using Key = std::array<std::uint32_t, 3>;

Key sorted_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Key k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
}

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::uint64_t h = k[0];
        h = h * 0x9E37'79B9'7F4A'7C15ull ^ k[1];
        h = h * 0x9E37'79B9'7F4A'7C15ull ^ k[2];
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

/// The triangle of tetrahedron t opposite its vertex f (any vertex order: only sets are compared).
Key facet(const Tet& t, int f) {
    const auto& s = kFacetVertices[static_cast<std::size_t>(f)];
    return sorted_triangle(t[static_cast<std::size_t>(s[0])],
                           t[static_cast<std::size_t>(s[1])],
                           t[static_cast<std::size_t>(s[2])]);
}

/// p in the closed tetrahedron a, b, c, d of positive right-hand volume (orient3d < 0): replacing
/// any vertex by p never makes the orientation positive.
bool holds(const std::vector<Point3>& pts, const Tet& t, const Point3& p) {
    for (std::size_t i = 0; i < 4; ++i) {
        std::array<Point3, 4> q{pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]};
        q[i] = p;
        if (predicates::orient3d(q[0], q[1], q[2], q[3]) == predicates::Sign::kPos) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::vector<std::int32_t> region_markers(const Plc& plc,
                                         std::span<const Tet> tets,
                                         std::span<const CdtFace> faces) {
    std::vector<std::int32_t> marker(tets.size(), 0);
    if (plc.regions.empty()) {
        return marker;
    }
    std::unordered_set<Key, KeyHash> walls;
    for (const CdtFace& f : faces) {
        walls.insert(sorted_triangle(f.v[0], f.v[1], f.v[2]));
    }
    // Each triangle's one or two tetrahedra.
    std::unordered_map<Key, std::array<std::uint32_t, 2>, KeyHash> sides;
    sides.reserve(2 * tets.size());
    for (std::uint32_t t = 0; t < tets.size(); ++t) {
        for (int f = 0; f < 4; ++f) {
            auto [it, fresh] =
                sides.try_emplace(facet(tets[t], f), std::array<std::uint32_t, 2>{t, t});
            if (!fresh) {
                it->second[1] = t;
            }
        }
    }
    std::vector<bool> reached(tets.size(), false);
    std::vector<std::uint32_t> stack;
    for (const PlcRegion& region : plc.regions) {
        std::uint32_t seed = 0;
        while (seed < tets.size() && !holds(plc.points.points, tets[seed], region.point)) {
            ++seed;
        }
        if (seed == tets.size()) {
            const auto line =
                region.line > 0 ? std::optional<std::size_t>(region.line) : std::nullopt;
            throw Error(located_message(
                plc.source, line, "region point lies outside the tetrahedralization"));
        }
        if (reached[seed]) {
            continue;  // an earlier region holds it: the first to reach a tetrahedron keeps it
        }
        reached[seed] = true;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const std::uint32_t t = stack.back();
            stack.pop_back();
            marker[t] = region.marker;
            for (int f = 0; f < 4; ++f) {
                const Key k = facet(tets[t], f);
                if (walls.count(k) != 0) {
                    continue;
                }
                const auto& two = sides.at(k);
                const std::uint32_t other = two[0] == t ? two[1] : two[0];
                if (!reached[other]) {
                    reached[other] = true;
                    stack.push_back(other);
                }
            }
        }
    }
    return marker;
}

}  // namespace cavity::core
