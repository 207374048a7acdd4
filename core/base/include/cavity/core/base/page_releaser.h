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

}  // namespace cavity::core
