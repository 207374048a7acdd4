#pragma once

namespace cavity::core {

/// Returns the whole pages of a buffer that lie before a moving mark to the operating system, so a
/// buffer that is read once from front to back stops counting towards the resident memory as the
/// reading advances. The buffer stays allocated (its owner frees it as usual); the released bytes
/// must not be read again. A no-op where the system offers no such call.
class PageReleaser {
public:
    explicit PageReleaser(unsigned char* begin);

    /// Releases every whole page between the last mark and `mark`.
    void release_before(unsigned char* mark);

private:
    unsigned char* released_;  // everything before this has been released
};

/// Faults in for writing, without writing them, the whole pages of [begin, end) (their content is
/// unchanged), so that threads can share the page faults of a large buffer one thread fills or
/// zeroes afterwards. A no-op where the system offers no such call (MADV_POPULATE_WRITE needs
/// Linux 5.14) or refuses it: the advice is about time, never content.
void fault_in_pages(unsigned char* begin, unsigned char* end);

/// Returns the pages of the heap's free memory to the operating system. glibc keeps the pages of
/// blocks freed below the top of its heap resident (blocks of a few MiB land there once its
/// mmap threshold has grown), so the temporaries of one stage would otherwise stay in the
/// resident size under the next stage's peak (issue 13: 11 bytes per point at 10^6 after the
/// repeat detection). A no-op where the allocator offers no such call.
void release_free_heap();

}  // namespace cavity::core
