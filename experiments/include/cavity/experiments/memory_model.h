#pragma once

#include <cstdint>
#include <vector>

/// A simulated memory hierarchy for §5.3's locality claim: "randomized vertex insertions tend to
/// interact poorly with the memory hierarchy ... a BRIO greatly improves the efficiency of the
/// memory hierarchy". The engine's touches of tetrahedron and point records are mapped to blocks
/// (cache lines or pages) and run through least-recently-used caches of several sizes at once.
namespace cavity::experiments {

/// LRU misses of one stream of block numbers for several capacities at once, by Mattson's stack
/// distance: an access hits an LRU cache of C blocks iff fewer than C distinct other blocks were
/// accessed since the block's previous access. The distance is counted with a Fenwick tree over
/// access times that marks each block's latest access; when the times run out the marks are
/// renumbered in order, so memory stays proportional to the number of blocks.
class LruStack {
public:
    explicit LruStack(std::vector<std::uint64_t> capacities);

    /// One access to `block` (a dense block number: memory grows with the largest one).
    void access(std::uint64_t block);

    const std::vector<std::uint64_t>& capacities() const { return capacities_; }

    /// Misses so far of the LRU cache of capacities()[i] blocks (first accesses included).
    std::uint64_t misses(std::size_t i) const { return misses_[i]; }

    std::uint64_t accesses() const { return accesses_; }

private:
    void mark(std::uint64_t time, int delta);
    std::uint64_t marks_up_to(std::uint64_t time) const;  ///< marks at times [0, time)
    void renumber();

    std::vector<std::uint64_t> capacities_;
    std::vector<std::uint64_t> misses_;
    std::vector<std::uint64_t> last_;  ///< block -> latest access time + 1 (0: never)
    std::vector<std::uint32_t> tree_;  ///< Fenwick tree over access times
    std::uint64_t now_ = 0;
    std::uint64_t accesses_ = 0;
};

/// The blocks the engine touches, per insertion. A touch of tetrahedron record t or point record v
/// becomes a block of each granularity (line and page); within one insertion a block is counted
/// once, in the order of its first touch, so each insertion contributes its set of distinct blocks
/// to the LRU streams. That is exact LRU whenever a cache holds more blocks than one insertion
/// touches, the case for every capacity simulated here except on the longest walks.
class MemoryTrace {
public:
    struct Layout {
        std::uint64_t tet_bytes;    ///< size of one tetrahedron record
        std::uint64_t point_bytes;  ///< size of one point record
    };

    static constexpr std::uint64_t kLineBytes = 64;
    static constexpr std::uint64_t kPageBytes = 4096;

    MemoryTrace(Layout layout,
                std::vector<std::uint64_t> line_capacities,
                std::vector<std::uint64_t> page_capacities);

    void touch_tet(std::uint32_t t) { touch(std::uint64_t{t} * layout_.tet_bytes, 0); }

    void touch_point(std::uint32_t v) { touch(std::uint64_t{v} * layout_.point_bytes, 1); }

    /// Closes one insertion: its distinct blocks go to the LRU streams.
    void end_insertion();

    std::uint64_t insertions() const { return insertions_; }

    std::uint64_t touches() const { return touches_; }

    std::uint64_t distinct_lines() const { return lines_.accesses(); }  ///< summed per insertion

    std::uint64_t distinct_pages() const { return pages_.accesses(); }

    const LruStack& lines() const { return lines_; }

    const LruStack& pages() const { return pages_; }

private:
    /// The two records live in separate arrays (region 0: tetrahedra, 1: points); interleaving
    /// their block numbers keeps the numbering dense.
    void touch(std::uint64_t address, std::uint64_t region);

    struct Granularity {
        std::uint64_t shift;
        std::vector<std::uint64_t> pending;  ///< this insertion's blocks, first touch first
        std::vector<std::uint64_t> seen_in;  ///< block -> insertion number + 1 of its last touch
    };

    void add(Granularity& g, std::uint64_t address, std::uint64_t region);
    void flush(Granularity& g, LruStack& stack);

    Layout layout_;
    Granularity line_{6, {}, {}};
    Granularity page_{12, {}, {}};
    LruStack lines_;
    LruStack pages_;
    std::uint64_t insertions_ = 0;
    std::uint64_t touches_ = 0;
};

}  // namespace cavity::experiments
