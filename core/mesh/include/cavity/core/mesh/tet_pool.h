#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "cavity/core/base/page_releaser.h"
#include "cavity/core/base/pod_stack.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// The part both storages share: one record per tetrahedron slot (its four vertex ids first, plus
/// whatever the storage keeps beside them, in the same cache line), liveness, a free list, and the
/// per-vertex "a recently added tetrahedron" that answers Adjacent2Vertex (Cheng, Dey & Shewchuk
/// §5.1).
///
/// The vertex map is built on the first Adjacent2Vertex question and kept up to date from then on.
/// A batch triangulation never asks, and keeping it from the start cost four scattered stores per
/// new tetrahedron (issue 13: −4.6% with the cavity faces, cube 10^6) and 4 bytes per vertex.
///
/// A deleted tetrahedron keeps its record readable until end_operation(): the cavity search reads
/// the far side of facets of tetrahedra it has already deleted, and a slot must not be handed to a
/// new tetrahedron of the same cavity before that.
template <class Record>
class TetPool {
public:
    void reserve(std::size_t tets) {
        records_.reserve(tets);
        alive_.reserve(tets / 64 + 1);
    }

    const TetVertices& vertices(TetId t) const { return records_[t].v; }

    bool alive(TetId t) const { return ((alive_[t >> 6] >> (t & 63u)) & 1u) != 0; }

    /// Number of slots ever allocated (live, deleted and free).
    std::size_t capacity() const { return records_.size(); }

    std::size_t live_count() const { return live_; }

    /// Adjacent2Vertex: a live tetrahedron with vertex v, or kNoTet. Constant time unless the most
    /// recently added tetrahedron at v has since been deleted (then a scan, as the book warns), or
    /// on the first question (then the vertex map is built, one pass over the records).
    TetId tet_at_vertex(VertexId v) const {
        const auto holds_v = [&](TetId t) {
            const TetVertices& w = records_[t].v;
            return alive(t) && std::find(w.begin(), w.end(), v) != w.end();
        };
        if (vertex_tet_.empty()) {
            build_vertex_map();
        }
        if (v < vertex_tet_.size() && vertex_tet_[v] != kNoTet && holds_v(vertex_tet_[v])) {
            return vertex_tet_[v];
        }
        for (TetId t = 0; t < records_.size(); ++t) {
            if (holds_v(t)) {
                return t;
            }
        }
        return kNoTet;
    }

    /// Hands every live tetrahedron's vertices to `emit`, in slot order, then empties the pool.
    /// The records already visited are returned to the operating system as the visit advances
    /// (whole pages, with madvise on Linux), so that copying the tetrahedra out does not add a
    /// second copy on top of the storage at the peak. Nothing may read the pool afterwards.
    template <class Emit>
    void drain(Emit&& emit) {
        const std::size_t n = records_.size();
        PageReleaser releaser(reinterpret_cast<unsigned char*>(records_.data()));
        for (std::size_t t = 0; t < n; ++t) {
            if (alive(static_cast<TetId>(t))) {
                emit(records_[t].v);
            }
            // Every 4096 records (128 KiB): the copy written before a release adds to the peak,
            // and with 65536 it added 1 MiB at 10^6 points (0.4% of the storage).
            if ((t & 0xFFFu) == 0xFFFu) {
                releaser.release_before(reinterpret_cast<unsigned char*>(records_.data() + t + 1));
            }
        }
        std::vector<Record>().swap(records_);
        std::vector<std::uint64_t>().swap(alive_);
        free_ = PodStack<TetId>();
        std::vector<TetId>().swap(vertex_tet_);
        live_ = 0;
    }

    /// Renames every vertex v to rename[v] (the ghost vertex stays), with Adjacent2Vertex
    /// following: a relabelling, so orientation and adjacency are unchanged.
    void rename_vertices(std::span<const VertexId> rename) {
        for (Record& r : records_) {
            for (VertexId& v : r.v) {
                if (v != kGhostVertex) {
                    v = rename[v];
                }
            }
        }
        std::vector<TetId> moved;
        for (std::size_t v = 0; v < vertex_tet_.size() && v < rename.size(); ++v) {
            const VertexId to = rename[v];
            if (to >= moved.size()) {
                moved.resize(std::max<std::size_t>(to + 1, rename.size()), kNoTet);
            }
            moved[to] = vertex_tet_[v];
        }
        vertex_tet_ = std::move(moved);
    }

    /// Replaces the contents with `records`, every one live, in that order (slot t is
    /// records[t]), and makes room for vertex ids below `vertices`: how a triangulation built
    /// elsewhere (the parallel construction) becomes this storage.
    void assign(std::vector<Record> records, std::size_t vertices) {
        records_ = std::move(records);
        const std::size_t n = records_.size();
        alive_.assign(n / 64 + 1, 0);
        for (std::size_t w = 0; w < n / 64; ++w) {
            alive_[w] = ~std::uint64_t{0};
        }
        if (n % 64 != 0) {
            alive_[n / 64] = (std::uint64_t{1} << (n % 64)) - 1;
        }
        free_ = PodStack<TetId>();
        released_ = PodStack<TetId>();
        vertex_tet_.assign(vertices, kNoTet);
        for (std::size_t t = 0; t < n; ++t) {
            for (VertexId u : records_[t].v) {
                if (u != kGhostVertex) {
                    vertex_tet_[u] = static_cast<TetId>(t);
                }
            }
        }
        live_ = n;
    }

    std::size_t bytes() const {
        return records_.capacity() * sizeof(Record) + alive_.capacity() * sizeof(std::uint64_t) +
               (free_.capacity() + released_.capacity() + vertex_tet_.capacity()) * sizeof(TetId);
    }

protected:
    Record& record(TetId t) { return records_[t]; }

    const Record& record(TetId t) const { return records_[t]; }

    [[gnu::always_inline]] TetId allocate(const TetVertices& v) {
        TetId t;
        if (!free_.empty()) {
            t = free_.pop_back();
            records_[t].v = v;
        } else {
            t = append(v);
        }
        alive_[t >> 6] |= std::uint64_t{1} << (t & 63u);
        ++live_;
        if (!vertex_tet_.empty()) [[unlikely]] {
            note_vertices(v, t);
        }
        return t;
    }

    [[gnu::always_inline]] void release(TetId t) {
        alive_[t >> 6] &= ~(std::uint64_t{1} << (t & 63u));
        released_.push_back(t);
        --live_;
    }

    void recycle_released() {
        // An insertion creates more tetrahedra than it deletes, so it used up the free list: hand
        // the released ids over whole, in the order the copy below would give them.
        if (free_.empty()) {
            std::swap(free_, released_);
            return;
        }
        for (TetId t : released_) {
            free_.push_back(t);
        }
        released_.clear();
    }

private:
    /// A new slot at the end, for allocate() when no slot is free (a quarter of the allocations
    /// on a uniform cube). Out of line on purpose: inlined, std::vector's push_back made the
    /// insertion loop large enough that GCC left other calls in it out of line instead.
    [[gnu::noinline]] TetId append(const TetVertices& v) {
        const auto t = static_cast<TetId>(records_.size());
        records_.push_back(Record{v});
        if ((t >> 6) >= alive_.size()) {
            alive_.push_back(0);
        }
        return t;
    }

    void note_vertices(const TetVertices& v, TetId t) const {
        for (VertexId u : v) {
            if (u == kGhostVertex) {
                continue;
            }
            if (u >= vertex_tet_.size()) {
                vertex_tet_.resize(std::max<std::size_t>(u + 1, 2 * vertex_tet_.size()), kNoTet);
            }
            vertex_tet_[u] = t;
        }
    }

    void build_vertex_map() const {
        vertex_tet_.assign(1, kNoTet);  // not empty from now on, even with no tetrahedra
        for (TetId t = 0; t < records_.size(); ++t) {
            if (alive(t)) {
                note_vertices(records_[t].v, t);
            }
        }
    }

    std::vector<Record> records_;
    std::vector<std::uint64_t> alive_;  // one bit per slot: small enough to stay in cache
    PodStack<TetId> free_;
    PodStack<TetId> released_;  // deleted during the current operation
    // A cache: Adjacent2Vertex, a const question, fills it on first use.
    mutable std::vector<TetId> vertex_tet_;
    std::size_t live_ = 0;
};

}  // namespace cavity::core
