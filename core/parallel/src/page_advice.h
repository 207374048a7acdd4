#pragma once

#include <cstddef>

namespace cavity::core {

/// Advice to the operating system about the pages of the parallel construction's large buffers
/// (the shared mesh's records, the listed tetrahedra: 330 MB at 10^6 points), so that their page
/// faults and their release are shared by the threads instead of run by one while the others
/// wait. Each call acts on the whole pages inside [begin, begin + bytes), never on a page the
/// range shares with other data. Linux madvise; a no-op where the system offers no such call or
/// refuses it, as the advice is about time only.

/// Faults the pages in for writing without writing them (their content is unchanged).
void fault_in_pages(void* begin, std::size_t bytes);

/// Returns the pages to the system: the range must not be read again before it is written (a
/// write gets a zero page) or freed.
void release_pages(void* begin, std::size_t bytes);

}  // namespace cavity::core
