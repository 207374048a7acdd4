#include "cavity/core/mesh/star.h"

#include <algorithm>

#include "cavity/core/base/error.h"

namespace cavity::core {

int slot_of(const TetVertices& t, VertexId v) {
    for (int s = 0; s < 4; ++s) {
        if (t[static_cast<std::size_t>(s)] == v) {
            return s;
        }
    }
    return -1;
}

EdgeRing edge_ring(const ArrayStorage& storage, TetId t, int i, int j) {
    const TetVertices& first = storage.vertices(t);
    EdgeRing out{first[static_cast<std::size_t>(i)], first[static_cast<std::size_t>(j)], {}, {}};
    int k = 0;
    while (k == i || k == j) {
        ++k;
    }
    const int l = 6 - i - j - k;
    // Walk from tet to tet across the facet opposite the vertex we came from: it holds the edge
    // and the vertex ahead, so the next tet shares both.
    VertexId back = first[static_cast<std::size_t>(k)];
    VertexId ahead = first[static_cast<std::size_t>(l)];
    TetId current = t;
    do {
        out.tets.push_back(current);
        out.ring.push_back(back);
        const HalfFacet h = storage.adjacent(current, slot_of(storage.vertices(current), back));
        if (h == kNoHalfFacet || out.tets.size() > storage.capacity()) {
            throw Error("edge ring is not closed: the triangulation has a hole");
        }
        current = tet_of(h);
        const TetVertices& next = storage.vertices(current);
        back = ahead;
        ahead = next[static_cast<std::size_t>(facet_of(h))];
    } while (current != t);
    return out;
}

std::vector<TetId> vertex_star(const ArrayStorage& storage, VertexId v) {
    std::vector<TetId> star;
    vertex_star_into(
        storage,
        v,
        [](const std::vector<TetId>& reached, TetId t) {
            return std::find(reached.begin(), reached.end(), t) == reached.end();
        },
        [](TetId) { return false; },
        star);
    return star;
}

}  // namespace cavity::core
