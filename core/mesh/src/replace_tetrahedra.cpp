#include "cavity/core/mesh/replace_tetrahedra.h"

#include <algorithm>
#include <array>

namespace cavity::core {

namespace {

using Triangle = std::array<VertexId, 3>;

Triangle sorted(Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
}

/// True when b is a with its orientation reversed (b is an odd permutation of a).
bool reversed(const Triangle& a, const Triangle& b) {
    for (int r = 0; r < 3; ++r) {
        if (b[0] == a[static_cast<std::size_t>(r)] &&
            b[1] == a[static_cast<std::size_t>((r + 2) % 3)] &&
            b[2] == a[static_cast<std::size_t>((r + 1) % 3)]) {
            return true;
        }
    }
    return false;
}

struct Side {
    Triangle key;       // sorted vertices: the triangle
    Triangle oriented;  // as seen from the tetrahedron holding this side
    HalfFacet outside;  // boundary: the half-facet across; new: 4 * (index in new_tets) + facet
    bool boundary;
    bool used = false;
};

}  // namespace

std::vector<TetId> replace_tetrahedra(ArrayStorage& storage,
                                      std::span<const TetId> old_tets,
                                      std::span<const TetVertices> new_tets) {
    const auto is_old = [&](TetId t) {
        return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end();
    };
    std::vector<Side> sides;
    for (TetId t : old_tets) {
        for (int f = 0; f < 4; ++f) {
            const HalfFacet h = storage.adjacent(t, f);
            if (h == kNoHalfFacet || !is_old(tet_of(h))) {
                const Triangle tri = facet_vertices(storage.vertices(t), f);
                sides.push_back({sorted(tri), tri, h, true});
            }
        }
    }
    const std::size_t boundary_count = sides.size();
    for (std::size_t n = 0; n < new_tets.size(); ++n) {
        for (int f = 0; f < 4; ++f) {
            const Triangle tri = facet_vertices(new_tets[n], f);
            sides.push_back({sorted(tri), tri, half_facet(static_cast<TetId>(n), f), false});
        }
    }
    // Pair every new side with a boundary side (seen from the old tetrahedron inside, so with the
    // same orientation) or with another new side (opposite orientation).
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t a = boundary_count; a < sides.size(); ++a) {
        if (sides[a].used) {
            continue;
        }
        std::size_t match = sides.size();
        for (std::size_t b = 0; b < sides.size(); ++b) {
            if (b != a && !sides[b].used && sides[b].key == sides[a].key) {
                match = b;
                break;
            }
        }
        if (match == sides.size()) {
            return {};
        }
        // Same key: either a rotation of the same orientation or reversed.
        if (reversed(sides[match].oriented, sides[a].oriented) == sides[match].boundary) {
            return {};
        }
        sides[a].used = sides[match].used = true;
        pairs.emplace_back(a, match);
    }
    for (std::size_t b = 0; b < boundary_count; ++b) {
        if (!sides[b].used) {
            return {};
        }
    }
    for (TetId t : old_tets) {
        storage.delete_tetrahedron(t);
    }
    std::vector<TetId> ids;
    ids.reserve(new_tets.size());
    for (const TetVertices& v : new_tets) {
        ids.push_back(storage.add_tetrahedron(v));
    }
    const auto real = [&](HalfFacet local) {
        return half_facet(ids[tet_of(local)], facet_of(local));
    };
    for (const auto& [a, b] : pairs) {
        const HalfFacet mine = real(sides[a].outside);
        if (!sides[b].boundary) {
            storage.glue(mine, real(sides[b].outside));
        } else if (sides[b].outside != kNoHalfFacet) {
            storage.glue(mine, sides[b].outside);
        }
    }
    storage.end_operation();
    return ids;
}

}  // namespace cavity::core
