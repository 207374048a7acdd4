#include "page_advice.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace cavity::core {

namespace {

#if defined(__linux__)
/// madvise on the whole pages inside [begin, begin + bytes). Its failure (MADV_POPULATE_WRITE
/// needs Linux 5.14) only costs the time the advice would have saved.
void advise(void* begin, std::size_t bytes, int advice) {
    static_assert(sizeof(long) == sizeof(std::uintptr_t));
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const auto b = reinterpret_cast<std::uintptr_t>(begin);
    const std::uintptr_t first = (b + page - 1) / page * page;
    const std::uintptr_t last = (b + bytes) / page * page;
    if (last > first) {
        // Page arithmetic needs the address as an integer.
        // NOLINTNEXTLINE(performance-no-int-to-ptr)
        madvise(reinterpret_cast<void*>(first), last - first, advice);
    }
}
#endif

}  // namespace

void fault_in_pages([[maybe_unused]] void* begin, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    advise(begin, bytes, MADV_POPULATE_WRITE);
#endif
}

void release_pages([[maybe_unused]] void* begin, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__)
    advise(begin, bytes, MADV_DONTNEED);
#endif
}

}  // namespace cavity::core
