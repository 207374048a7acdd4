#include "cavity/core/tet_pool.h"

#include <algorithm>

namespace cavity::core {

void TetPool::reserve(std::size_t tets, std::size_t vertices) {
    vertices_.reserve(tets);
    alive_.reserve(tets);
    vertex_tet_.reserve(vertices);
}

TetId TetPool::allocate(const TetVertices& v) {
    TetId t;
    if (!free_.empty()) {
        t = free_.back();
        free_.pop_back();
        vertices_[t] = v;
        alive_[t] = 1;
    } else {
        t = static_cast<TetId>(vertices_.size());
        vertices_.push_back(v);
        alive_.push_back(1);
    }
    ++live_;
    for (VertexId u : v) {
        if (u == kGhostVertex) {
            continue;
        }
        if (u >= vertex_tet_.size()) {
            vertex_tet_.resize(std::max<std::size_t>(u + 1, 2 * vertex_tet_.size()), kNoTet);
        }
        vertex_tet_[u] = t;
    }
    return t;
}

void TetPool::release(TetId t) {
    alive_[t] = 0;
    released_.push_back(t);
    --live_;
}

void TetPool::recycle_released() {
    free_.insert(free_.end(), released_.begin(), released_.end());
    released_.clear();
}

TetId TetPool::tet_at_vertex(VertexId v) const {
    if (v >= vertex_tet_.size()) {
        return kNoTet;
    }
    const auto holds_v = [&](TetId t) {
        return alive(t) && std::find(vertices_[t].begin(), vertices_[t].end(), v) != vertices_[t].end();
    };
    const TetId recent = vertex_tet_[v];
    if (recent != kNoTet && holds_v(recent)) {
        return recent;
    }
    for (TetId t = 0; t < vertices_.size(); ++t) {
        if (holds_v(t)) {
            return t;
        }
    }
    return kNoTet;
}

std::size_t TetPool::bytes() const {
    return vertices_.capacity() * sizeof(TetVertices) + alive_.capacity() +
           (free_.capacity() + released_.capacity() + vertex_tet_.capacity()) * sizeof(TetId);
}

}  // namespace cavity::core
