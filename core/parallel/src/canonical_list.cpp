#include "canonical_list.h"

#include <algorithm>
#include <span>

#include "canonical_rotation.h"
#include "cavity/core/base/page_releaser.h"
#include "in_pieces.h"

namespace cavity::core {

namespace {

using Tet = std::array<std::uint32_t, 4>;

/// A solid tetrahedron's vertex ids in the canonical rotation: lowest id first, then the lowest
/// of the other three, the last two in the orientation's order. The rotation alone carries the
/// orientation, so the list is sorted and rotated in place, with no slot or key beside it.
Tet rotated(const TetVertices& v) {
    // Solid: no ghost vertex to rank below the others, so the ids compare as they are.
    const Perm p = solid_perm(v, [](VertexId w) { return w; });
    return {v[p[0]], v[p[1]], v[p[2]], v[p[3]]};
}

/// The highest id of a rotated tetrahedron (one of its last two: the first two are the lowest).
std::uint32_t top(const Tet& t) {
    return std::max(t[2], t[3]);
}

/// The canonical order of tetrahedra sharing their highest id: by the other three, highest first.
/// Written out rather than as arrays compared with <: the three-way compare of std::array cost
/// about a third of the list's sorting (callgrind, cube 10^5).
bool before(const Tet& x, const Tet& y) {
    const std::uint32_t x2 = std::min(x[2], x[3]);
    const std::uint32_t y2 = std::min(y[2], y[3]);
    if (x2 != y2) {
        return x2 < y2;
    }
    return x[1] != y[1] ? x[1] < y[1] : x[0] < y[0];
}

/// Sorts a group of tetrahedra sharing their highest id by `before`. Groups have about 6.5
/// tetrahedra: an insertion sort, where std::sort's moved each new smallest element with a call
/// to memmove; the rare large group (a vertex inserted with a large star) goes to std::sort.
void sort_group(Tet* first, Tet* last) {
    if (last - first > 16) {
        std::sort(first, last, [](const Tet& x, const Tet& y) { return before(x, y); });
        return;
    }
    for (Tet* i = first + 1; i < last; ++i) {
        const Tet moving = *i;
        Tet* j = i;
        for (; j > first && before(moving, *(j - 1)); --j) {
            *j = *(j - 1);
        }
        *j = moving;
    }
}

/// Tetrahedra are first spread into buckets of 2^shift consecutive highest ids, then each bucket
/// is sorted on its own (in cache). Wide enough for few buckets (a count per bucket and thread),
/// narrow enough for a bucket's tetrahedra (about 6.5 per id) to stay in the cache.
unsigned bucket_shift(std::size_t vertices, unsigned threads) {
    unsigned shift = 10;
    while ((vertices >> shift) * threads > (std::size_t{1} << 22)) {
        ++shift;
    }
    return shift;
}

/// Sorts the rotated tetrahedra of one bucket, whose highest ids are in [base, base + width),
/// and writes them back as input indices in the API's orientation. `scratch` and `start` are the
/// caller's, reused from bucket to bucket.
void sort_bucket(std::span<Tet> bucket,
                 std::uint32_t base,
                 std::size_t width,
                 const Geometry& geometry,
                 std::vector<Tet>& scratch,
                 std::vector<std::size_t>& start) {
    // A counting sort by the highest id, then the few tetrahedra sharing one by the others.
    start.assign(width + 1, 0);
    for (const Tet& t : bucket) {
        ++start[top(t) - base + 1];
    }
    for (std::size_t b = 1; b <= width; ++b) {
        start[b] += start[b - 1];
    }
    scratch.resize(bucket.size());
    for (const Tet& t : bucket) {
        scratch[start[top(t) - base]++] = t;
    }
    // Placing moved each group's start to its end, the next group's start.
    std::size_t begin = 0;
    for (std::size_t g = 0; g < width; ++g) {
        const std::size_t end = start[g];
        sort_group(scratch.data() + begin, scratch.data() + end);
        begin = end;
    }
    // The stored orientation mirrored, as every list of tetrahedra is handed out
    // (detail::drain_into, handedness.h).
    for (std::size_t i = 0; i < bucket.size(); ++i) {
        const Tet& v = scratch[i];
        bucket[i] = {
            geometry.key(v[1]), geometry.key(v[0]), geometry.key(v[2]), geometry.key(v[3])};
    }
}

}  // namespace

std::size_t list_canonically(ConcurrentMesh& mesh,
                             const Geometry& geometry,
                             unsigned threads,
                             std::vector<std::array<std::uint32_t, 4>>& tets) {
    const std::size_t used = mesh.used();
    const unsigned shift = bucket_shift(geometry.size(), threads);
    const std::size_t buckets = (geometry.size() >> shift) + 1;
    // count[k * buckets + b]: the solid tetrahedra piece k of the slots has in bucket b, then
    // where piece k places its first one there. Pieces place into their own ranges, so the
    // spread needs no atomics and each bucket's content is sorted afterwards anyway.
    std::vector<std::size_t> count(threads * buckets, 0);
    std::vector<std::size_t> ghosts(threads, 0);
    in_pieces(used, threads, [&](unsigned k, std::size_t begin, std::size_t end) {
        std::size_t* mine = count.data() + k * buckets;
        for (std::size_t t = begin; t < end; ++t) {
            if (!mesh.alive(static_cast<TetId>(t))) {
                continue;
            }
            const TetVertices& v = mesh.record(static_cast<TetId>(t)).v;
            if (is_ghost(v)) {
                ++ghosts[k];
            } else {
                ++mine[std::max(std::max(v[0], v[1]), std::max(v[2], v[3])) >> shift];
            }
        }
    });
    std::vector<std::size_t> bucket_begin(buckets + 1, 0);
    std::size_t placed = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
        bucket_begin[b] = placed;
        for (unsigned k = 0; k < threads; ++k) {
            const std::size_t c = count[k * buckets + b];
            count[k * buckets + b] = placed;
            placed += c;
        }
    }
    bucket_begin[buckets] = placed;
    // std::vector zero-fills the list on one thread; its page faults were most of that (about
    // 26000 at 10^6 points): the threads take them first, each on its share, and leave the
    // resize a memset of resident pages.
    tets.reserve(placed);
    in_pieces(placed, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        auto* bytes = reinterpret_cast<unsigned char*>(tets.data());
        fault_in_pages(bytes + begin * sizeof(Tet), bytes + end * sizeof(Tet));
    });
    tets.resize(placed);
    in_pieces(used, threads, [&](unsigned k, std::size_t begin, std::size_t end) {
        std::size_t* next = count.data() + k * buckets;
        for (std::size_t t = begin; t < end; ++t) {
            if (!mesh.alive(static_cast<TetId>(t))) {
                continue;
            }
            const TetVertices& v = mesh.record(static_cast<TetId>(t)).v;
            if (!is_ghost(v)) {
                const Tet r = rotated(v);
                tets[next[top(r) >> shift]++] = r;
            }
        }
        // The slots of this piece are read for the last time.
        mesh.release_records(begin, end);
    });
    mesh.clear();
    // Each thread sorts the buckets that start in its share of the list.
    in_pieces(placed, threads, [&](unsigned, std::size_t begin, std::size_t end) {
        std::vector<Tet> scratch;
        std::vector<std::size_t> start;
        const auto first = static_cast<std::size_t>(
            std::lower_bound(bucket_begin.begin(), bucket_begin.end() - 1, begin) -
            bucket_begin.begin());
        for (std::size_t b = first; b < buckets && bucket_begin[b] < end; ++b) {
            sort_bucket(std::span<Tet>(tets.data() + bucket_begin[b],
                                       bucket_begin[b + 1] - bucket_begin[b]),
                        static_cast<std::uint32_t>(b << shift),
                        std::size_t{1} << shift,
                        geometry,
                        scratch,
                        start);
        }
    });
    std::size_t hull = 0;
    for (std::size_t g : ghosts) {
        hull += g;
    }
    return hull;
}

}  // namespace cavity::core
