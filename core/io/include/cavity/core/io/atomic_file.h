#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cavity::core {

/// Writes a group of files so that a reader never sees a half-written one: each file is written
/// to a temporary name in its target's directory (so the final rename stays within one file
/// system and is atomic), and only commit(), once every file is complete and synced, renames them
/// into place. A group destroyed without commit(), for instance by an exception thrown while
/// writing, removes its temporaries and leaves any existing targets untouched.
///
/// Concurrent runs: commit() holds an exclusive lock (flock) on each target directory while it
/// renames, so two groups committing the same names never interleave: the last one's set wins
/// whole. The renames themselves are one per file: a process killed between two of them leaves
/// files of two runs side by side, which is why the .ele carries the fingerprint of its points
/// (write_tetgen) and `cavity check` compares it with the .node. Temporaries of a killed writer
/// (its process gone) are removed by the next group that adds the same target.
class AtomicFileGroup {
public:
    /// One temporary file being written; output is buffered and flushed by commit().
    class Writer {
    public:
        /// Appends bytes. \throws Error naming the target when the system refuses the write.
        void write(std::string_view bytes);

        const std::filesystem::path& target() const { return target_; }

        Writer(const Writer&) = delete;
        Writer& operator=(const Writer&) = delete;
        ~Writer();

    private:
        friend class AtomicFileGroup;
        Writer(std::filesystem::path target, std::filesystem::path temporary, int fd);
        void flush();
        void finish();  // flush, fsync and close

        std::filesystem::path target_;
        std::filesystem::path temporary_;
        int fd_;
        std::string buffer_;
    };

    AtomicFileGroup() = default;
    AtomicFileGroup(const AtomicFileGroup&) = delete;
    AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
    ~AtomicFileGroup();

    /// Creates a fresh temporary file next to `target`. The writer lives as long as the group.
    /// \throws Error naming the target when the directory does not accept a new file.
    Writer& add(const std::filesystem::path& target);

    /// Completes every file and renames each temporary onto its target, replacing old files.
    /// \throws Error naming the file that failed; nothing is renamed if a write fails.
    void commit();

private:
    std::vector<std::unique_ptr<Writer>> files_;
    bool committed_ = false;
};

}  // namespace cavity::core
