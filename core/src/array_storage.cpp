#include "cavity/core/array_storage.h"

namespace cavity::core {

void ArrayStorage::reserve(std::size_t tets, std::size_t vertices) {
    TetPool::reserve(tets, vertices);
    neighbors_.reserve(4 * tets);
}

TetId ArrayStorage::add_tetrahedron(const TetVertices& v) {
    const TetId t = allocate(v);
    if (4 * static_cast<std::size_t>(t) + 4 > neighbors_.size()) {
        neighbors_.resize(4 * static_cast<std::size_t>(t) + 4, kNoHalfFacet);
    }
    return t;
}

std::size_t ArrayStorage::bytes() const {
    return TetPool::bytes() + neighbors_.capacity() * sizeof(HalfFacet);
}

}  // namespace cavity::core
