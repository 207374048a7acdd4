#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "cavity/core/base/page_releaser.h"
#include "cavity/core/mesh/array_storage.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// The tetrahedra of a parallel construction, shared by its threads: the array storage's records
/// (vertices and neighbours) and one owner byte per slot, which is the tetrahedron's lock and
/// says whether it lives.
///
/// The discipline that makes it race-free: a thread reads or writes a record only while it owns
/// the slot (try_lock acquired it, unlock releases it), so the lock's acquire and release order
/// every record access; the owner bytes, which neighbouring slots of different owners share, are
/// only touched atomically. A dead slot's byte is kDead, which try_lock never takes: the thread
/// that freed the slot (or claimed its block) is the only one that can hand it out again: it
/// writes the new record while the byte still says dead, then publishes it with unlock's release
/// store, no read-modify-write. A thread owns every tetrahedron it looks
/// at while inserting a point (the walk's current one, the cavity, the cavity's neighbours), as in
/// HXT's parallel Delaunay (Marot, Pellerin & Remacle 2019): whoever would change a tetrahedron,
/// or the neighbour pointer towards it, must own it first.
///
/// Slots are handed out in blocks (claim_block) from one counter, so threads never share a block.
/// The arrays grow only between passes, when no thread runs (grow).
class ConcurrentMesh {
public:
    /// Owner byte of a free slot; a thread's byte is its id (1 to 127), with kCavityBit set while
    /// the tetrahedron is in that thread's current cavity.
    static constexpr std::uint8_t kFree = 0;
    static constexpr std::uint8_t kCavityBit = 0x80;
    /// Owner byte of a dead slot (never handed out, or freed): the cavity bit of no thread, as
    /// no thread's id is 0.
    static constexpr std::uint8_t kDead = kCavityBit;

    /// Makes room for `slots` slots; the new ones are dead and free. No thread may run.
    ///
    /// The records are not initialised: a slot is written when a thread makes a tetrahedron in
    /// it, and read only while live. So their pages are first touched by the threads that claim
    /// them, each in its own blocks, not zeroed here on one thread (about 0.1 s for the 220 MB of
    /// 10^6 points).
    void grow(std::size_t slots) {
        const std::size_t keep = used();
        RecordArray records(static_cast<ArrayRecord*>(
            ::operator new (slots * sizeof(ArrayRecord), std::align_val_t{alignof(ArrayRecord)})));
        if (keep > 0) {
            // Bytes, not records: slots of a block that were never handed out hold garbage.
            std::memcpy(records.get(), records_.get(), keep * sizeof(ArrayRecord));
        }
        records_ = std::move(records);
        capacity_ = slots;
        owner_.resize(slots, kDead);
        next_.store(keep);
    }

    std::size_t capacity() const { return capacity_; }

    std::size_t bytes() const { return capacity_ * sizeof(ArrayRecord) + owner_.capacity(); }

    /// Slots handed out so far (every live tetrahedron is below).
    std::size_t used() const { return std::min<std::size_t>(next_.load(), capacity()); }

    /// Up to `count` fresh slots [first, end): end == first when the capacity is exhausted.
    struct Block {
        TetId first;
        TetId end;
    };

    Block claim_block(std::size_t count) {
        const std::size_t first = next_.fetch_add(count, std::memory_order_relaxed);
        const std::size_t cap = capacity();
        return {static_cast<TetId>(std::min(first, cap)),
                static_cast<TetId>(std::min(first + count, cap))};
    }

    /// The arrays' addresses and the slot operations, for a hot loop to keep in registers: the
    /// owner bytes' stores may alias anything, so through the mesh the compiler reloaded both
    /// addresses after each of them (about 4% of a parallel build's instructions, cube 10^5).
    /// Valid until the next grow or clear.
    struct Slots {
        ArrayRecord* records;
        std::uint8_t* owners;

        ArrayRecord& record(TetId t) const { return records[t]; }

        bool try_lock(TetId t, std::uint8_t me) const {
            std::uint8_t expected = kFree;
            return std::atomic_ref<std::uint8_t>(owners[t]).compare_exchange_strong(
                expected, me, std::memory_order_acquire, std::memory_order_relaxed);
        }

        std::uint8_t owner(TetId t) const {
            return std::atomic_ref<std::uint8_t>(owners[t]).load(std::memory_order_relaxed);
        }

        /// Changes the byte of a slot the caller owns (marks it in its cavity, or dead), or of a
        /// slot no thread can reach yet (the bootstrap's).
        void set_owner(TetId t, std::uint8_t value) const {
            std::atomic_ref<std::uint8_t>(owners[t]).store(value, std::memory_order_relaxed);
        }

        void unlock(TetId t) const {
            std::atomic_ref<std::uint8_t>(owners[t]).store(kFree, std::memory_order_release);
        }

        void prefetch_neighbours(TetId t) const {
            for (HalfFacet h : records[t].n) {
                if (h != kNoHalfFacet) {
                    __builtin_prefetch(&records[tet_of(h)]);
                }
            }
        }
    };

    Slots slots() { return {records_.get(), owner_.data()}; }

    ArrayRecord& record(TetId t) { return records_[t]; }

    const ArrayRecord& record(TetId t) const { return records_[t]; }

    bool try_lock(TetId t, std::uint8_t me) { return slots().try_lock(t, me); }

    std::uint8_t owner(TetId t) { return slots().owner(t); }

    void set_owner(TetId t, std::uint8_t value) { slots().set_owner(t, value); }

    void unlock(TetId t) { slots().unlock(t); }

    /// Whether slot t holds a tetrahedron: exact for a slot the caller owns, or when no thread
    /// runs. (A successful try_lock needs no such check: it takes live slots only.)
    bool alive(TetId t) { return owner(t) != kDead; }

    /// Returns the memory of slots [begin, end)'s records to the system, for a thread that has
    /// read its share of the slots for the last time: the threads then share what clear(), on
    /// one thread, would otherwise release alone (about 9 ms of unmapping at 10^6 points). The
    /// records are not read again; clear() follows.
    void release_records(std::size_t begin, std::size_t end) {
        auto* bytes = reinterpret_cast<unsigned char*>(records_.get());
        PageReleaser(bytes + begin * sizeof(ArrayRecord))
            .release_before(bytes + end * sizeof(ArrayRecord));
    }

    /// Frees the memory. No thread may run.
    void clear() {
        records_.reset();
        capacity_ = 0;
        std::vector<std::uint8_t>().swap(owner_);
        next_.store(0);
    }

    /// What CavityGluer asks of a storage, on slots the caller owns.
    struct OwnedRecords {
        Slots slots;

        const TetVertices& vertices(TetId t) const { return slots.record(t).v; }

        void set_adjacent(HalfFacet a, HalfFacet b) const {
            slots.record(tet_of(a)).n[static_cast<std::size_t>(facet_of(a))] = b;
        }

        void glue(HalfFacet a, HalfFacet b) const {
            set_adjacent(a, b);
            set_adjacent(b, a);
        }
    };

private:
    struct FreeRecords {
        void operator()(ArrayRecord* records) const {
            ::operator delete (records, std::align_val_t{alignof(ArrayRecord)});
        }
    };

    using RecordArray = std::unique_ptr<ArrayRecord[], FreeRecords>;

    RecordArray records_;
    std::size_t capacity_ = 0;
    std::vector<std::uint8_t> owner_;
    std::atomic<std::size_t> next_{0};
};

}  // namespace cavity::core
