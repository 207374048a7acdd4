#include "cavity/experiments/memory_model.h"

#include <algorithm>
#include <utility>

namespace cavity::experiments {

namespace {

constexpr std::size_t kInitialTimes = std::size_t{1} << 20;

}  // namespace

LruStack::LruStack(std::vector<std::uint64_t> capacities)
    : capacities_(std::move(capacities))
    , misses_(capacities_.size(), 0)
    , tree_(kInitialTimes + 1, 0) {}

void LruStack::mark(std::uint64_t time, int delta) {
    for (std::size_t i = time + 1; i < tree_.size(); i += i & (~i + 1)) {
        tree_[i] = static_cast<std::uint32_t>(static_cast<std::int64_t>(tree_[i]) + delta);
    }
}

std::uint64_t LruStack::marks_up_to(std::uint64_t time) const {
    std::uint64_t sum = 0;
    for (std::size_t i = time; i > 0; i -= i & (~i + 1)) {
        sum += tree_[i];
    }
    return sum;
}

void LruStack::renumber() {
    // Only the order of the latest accesses matters: give them the times 0..m-1 and start a tree
    // with room for three times as many accesses again.
    std::vector<std::uint64_t> blocks;
    for (std::uint64_t b = 0; b < last_.size(); ++b) {
        if (last_[b] != 0) {
            blocks.push_back(b);
        }
    }
    std::sort(blocks.begin(), blocks.end(), [this](std::uint64_t a, std::uint64_t b) {
        return last_[a] < last_[b];
    });
    tree_.assign(std::max(kInitialTimes, 4 * blocks.size()) + 1, 0);
    now_ = 0;
    for (std::uint64_t b : blocks) {
        last_[b] = now_ + 1;
        mark(now_, 1);
        ++now_;
    }
}

void LruStack::access(std::uint64_t block) {
    if (now_ + 1 >= tree_.size()) {
        renumber();
    }
    if (block >= last_.size()) {
        last_.resize(std::max<std::size_t>(block + 1, 2 * last_.size()), 0);
    }
    ++accesses_;
    if (last_[block] == 0) {
        for (std::uint64_t& m : misses_) {
            ++m;  // a first access misses every cache
        }
    } else {
        const std::uint64_t previous = last_[block] - 1;
        const std::uint64_t others = marks_up_to(now_) - marks_up_to(previous + 1);
        for (std::size_t i = 0; i < capacities_.size(); ++i) {
            misses_[i] += others >= capacities_[i] ? 1 : 0;
        }
        mark(previous, -1);
    }
    mark(now_, 1);
    last_[block] = now_ + 1;
    ++now_;
}

MemoryTrace::MemoryTrace(Layout layout,
                         std::vector<std::uint64_t> line_capacities,
                         std::vector<std::uint64_t> page_capacities)
    : layout_(layout), lines_(std::move(line_capacities)), pages_(std::move(page_capacities)) {}

void MemoryTrace::add(Granularity& g, std::uint64_t address, std::uint64_t region) {
    const std::uint64_t block = ((address >> g.shift) << 1) | region;
    if (block >= g.seen_in.size()) {
        g.seen_in.resize(std::max<std::size_t>(block + 1, 2 * g.seen_in.size()), 0);
    }
    if (g.seen_in[block] != insertions_ + 1) {
        g.seen_in[block] = insertions_ + 1;
        g.pending.push_back(block);
    }
}

void MemoryTrace::touch(std::uint64_t address, std::uint64_t region) {
    ++touches_;
    add(line_, address, region);
    add(page_, address, region);
}

void MemoryTrace::flush(Granularity& g, LruStack& stack) {
    for (std::uint64_t block : g.pending) {
        stack.access(block);
    }
    g.pending.clear();
}

void MemoryTrace::end_insertion() {
    flush(line_, lines_);
    flush(page_, pages_);
    ++insertions_;
}

}  // namespace cavity::experiments
