#include "cavity/core/mesh/face_hash_storage.h"

#include <algorithm>

namespace cavity::core {

namespace {

std::array<VertexId, 3> reversed(const std::array<VertexId, 3>& f) {
    return {f[0], f[2], f[1]};
}

}  // namespace

void FaceHashStorage::reserve(std::size_t tets) {
    TetPool::reserve(tets);
    std::size_t size = 16;
    while (size < 8 * tets) {  // 4 faces per tetrahedron at load factor <= 1/2
        size *= 2;
    }
    if (size > slots_.size()) {
        std::vector<Slot> old;
        old.swap(slots_);
        slots_.assign(size, Slot{{kNoVertex, kNoVertex, kNoVertex}, kNoHalfFacet});
        used_ = 0;
        for (const Slot& s : old) {
            if (s.face[0] != kNoVertex) {
                insert(s.face, s.value);
            }
        }
    }
}

std::array<VertexId, 3> FaceHashStorage::canonical(std::array<VertexId, 3> f) {
    // A cyclic rotation keeps the orientation, so the smallest id can always come first.
    if (f[1] < f[0] && f[1] < f[2]) {
        return {f[1], f[2], f[0]};
    }
    if (f[2] < f[0] && f[2] < f[1]) {
        return {f[2], f[0], f[1]};
    }
    return f;
}

std::size_t FaceHashStorage::home(const std::array<VertexId, 3>& f) const {
    std::uint64_t h = (static_cast<std::uint64_t>(f[0]) << 32) ^ f[1];
    h ^= static_cast<std::uint64_t>(f[2]) * 0x9E37'79B9'7F4A'7C15ull;
    h *= 0xBF58'476D'1CE4'E5B9ull;
    h ^= h >> 31;
    return static_cast<std::size_t>(h) & (slots_.size() - 1);
}

void FaceHashStorage::grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(2 * old.size(), Slot{{kNoVertex, kNoVertex, kNoVertex}, kNoHalfFacet});
    used_ = 0;
    for (const Slot& s : old) {
        if (s.face[0] != kNoVertex) {
            insert(s.face, s.value);
        }
    }
}

void FaceHashStorage::insert(const std::array<VertexId, 3>& face, HalfFacet value) {
    if (2 * (used_ + 1) > slots_.size()) {
        grow();
    }
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = home(face);
    while (slots_[i].face[0] != kNoVertex) {
        i = (i + 1) & mask;
    }
    slots_[i] = Slot{face, value};
    ++used_;
}

void FaceHashStorage::erase(const std::array<VertexId, 3>& face) {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = home(face);
    while (slots_[i].face != face) {
        i = (i + 1) & mask;
    }
    // Backward-shift deletion: pull later members of the probe run into the hole, so look-ups
    // never need tombstones.
    std::size_t hole = i;
    for (std::size_t j = (i + 1) & mask; slots_[j].face[0] != kNoVertex; j = (j + 1) & mask) {
        const std::size_t want = home(slots_[j].face);
        const bool movable = hole <= j ? (want <= hole || want > j) : (want <= hole && want > j);
        if (movable) {
            slots_[hole] = slots_[j];
            hole = j;
        }
    }
    slots_[hole].face = {kNoVertex, kNoVertex, kNoVertex};
    --used_;
}

TetId FaceHashStorage::add_tetrahedron(const TetVertices& v) {
    if (slots_.empty()) {
        reserve(16);
    }
    const TetId t = allocate(v);
    for (int f = 0; f < 4; ++f) {
        insert(canonical(facet_vertices(v, f)), half_facet(t, f));
    }
    return t;
}

void FaceHashStorage::delete_tetrahedron(TetId t) {
    const TetVertices& v = vertices(t);
    for (int f = 0; f < 4; ++f) {
        erase(canonical(facet_vertices(v, f)));
    }
    release(t);
}

HalfFacet FaceHashStorage::adjacent(TetId t, int f) const {
    const auto key = canonical(reversed(facet_vertices(vertices(t), f)));
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = home(key);; i = (i + 1) & mask) {
        ++probes_;
        if (slots_[i].face == key) {
            return slots_[i].value;
        }
        if (slots_[i].face[0] == kNoVertex) {
            return kNoHalfFacet;
        }
    }
}

std::size_t FaceHashStorage::bytes() const {
    return TetPool::bytes() + slots_.capacity() * sizeof(Slot);
}

}  // namespace cavity::core
