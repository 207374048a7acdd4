#include "cavity/core/base/page_releaser.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cavity::core {

namespace {

std::uintptr_t page_size() {
#if defined(__linux__)
    static_assert(sizeof(long) == sizeof(std::uintptr_t));
    return static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
#else
    return 4096;
#endif
}

}  // namespace

PageReleaser::PageReleaser(unsigned char* begin) {
    // The first partial page may hold someone else's data: start at the next page boundary.
    const std::uintptr_t page = page_size();
    const auto b = reinterpret_cast<std::uintptr_t>(begin);
    // Page arithmetic needs the address as an integer: this file is where cavity does it.
    // NOLINTNEXTLINE(performance-no-int-to-ptr)
    released_ = reinterpret_cast<unsigned char*>((b + page - 1) / page * page);
}

void PageReleaser::release_before(unsigned char* mark) {
    const std::uintptr_t page = page_size();
    const auto end = reinterpret_cast<std::uintptr_t>(mark) / page * page;
    const auto start = reinterpret_cast<std::uintptr_t>(released_);
    if (end <= start) {
        return;
    }
#if defined(__linux__)
    madvise(released_, end - start, MADV_DONTNEED);
#endif
    released_ = reinterpret_cast<unsigned char*>(end);  // NOLINT(performance-no-int-to-ptr)
}

void fault_in_pages([[maybe_unused]] unsigned char* begin, [[maybe_unused]] unsigned char* end) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const std::uintptr_t page = page_size();
    const auto first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const auto last = reinterpret_cast<std::uintptr_t>(end) / page * page;
    if (last > first) {
        // NOLINTNEXTLINE(performance-no-int-to-ptr)
        madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
    }
#endif
}

void release_free_heap() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

}  // namespace cavity::core
