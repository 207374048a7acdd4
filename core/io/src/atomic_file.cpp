#include "cavity/core/io/atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include "cavity/core/base/error.h"

namespace cavity::core {

namespace {

constexpr std::size_t kFlushThreshold = std::size_t{1} << 16;

// Temporaries are hidden dot-files named after the target, the process and an attempt number;
// O_EXCL makes the creation fail rather than share a name with a concurrent writer.
constexpr int kMaxNameAttempts = 100;

SystemError system_error(const std::filesystem::path& file, const std::string& action, int error) {
    return SystemError(
        located_message(file.string(), std::nullopt, action + ": " + std::strerror(error)));
}

/// The directory a relative path names ("" is the working directory).
std::filesystem::path directory_of(const std::filesystem::path& file) {
    const std::filesystem::path dir = file.parent_path();
    return dir.empty() ? std::filesystem::path(".") : dir;
}

/// An exclusive flock on a directory, held while a group renames into it: groups of concurrent
/// runs commit one after the other, never interleaved.
class DirectoryLock {
public:
    explicit DirectoryLock(const std::filesystem::path& dir)
        : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
        if (fd_ < 0) {
            throw system_error(dir, "cannot open the directory to lock it", errno);
        }
        while (::flock(fd_, LOCK_EX) != 0) {
            if (errno != EINTR) {
                const int error = errno;
                ::close(fd_);
                throw system_error(dir, "cannot lock the directory", error);
            }
        }
    }

    DirectoryLock(DirectoryLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;
    DirectoryLock& operator=(DirectoryLock&&) = delete;

    ~DirectoryLock() {
        if (fd_ >= 0) {
            ::close(fd_);  // releases the lock
        }
    }

private:
    int fd_;
};

/// The distinct target directories, in a fixed (sorted) order so that two groups sharing several
/// directories lock them in the same order and cannot deadlock.
template <typename Files>
std::vector<std::filesystem::path> target_directories(const Files& files) {
    std::vector<std::filesystem::path> dirs;
    for (const auto& file : files) {
        std::error_code error;
        const std::filesystem::path dir = directory_of(file->target());
        const std::filesystem::path canonical = std::filesystem::weakly_canonical(dir, error);
        dirs.push_back(error ? dir : canonical);
    }
    std::sort(dirs.begin(), dirs.end());
    dirs.erase(std::unique(dirs.begin(), dirs.end()), dirs.end());
    return dirs;
}

/// Removes `dir`'s temporaries named PREFIX<pid>.<n> whose writer process no longer exists (a run
/// killed before it could clean up). A live process, or one of another user (EPERM), keeps its
/// files; failures to remove are ignored: the directory is only being tidied.
void remove_stale_temporaries(const std::filesystem::path& dir, const std::string& prefix) {
    std::error_code error;
    std::filesystem::directory_iterator entries(dir, error);
    if (error) {
        return;  // add() reports an unusable directory when it creates its own file
    }
    for (const auto& entry : entries) {
        const std::string name = entry.path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        const std::string rest = name.substr(prefix.size());
        const std::size_t dot = rest.find('.');
        if (dot == 0 || dot == std::string::npos || rest.find_first_not_of("0123456789") != dot ||
            rest.find_first_not_of("0123456789", dot + 1) != std::string::npos || dot > 9) {
            continue;
        }
        const auto pid = static_cast<pid_t>(std::stol(rest.substr(0, dot)));
        if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) {
            std::filesystem::remove(entry.path(), error);
        }
    }
}

}  // namespace

AtomicFileGroup::Writer::Writer(std::filesystem::path target,
                                std::filesystem::path temporary,
                                int fd)
    : target_(std::move(target)), temporary_(std::move(temporary)), fd_(fd) {}

AtomicFileGroup::Writer::~Writer() {
    if (fd_ >= 0) {
        ::close(fd_);
    }
}

void AtomicFileGroup::Writer::write(std::string_view bytes) {
    buffer_.append(bytes);
    if (buffer_.size() >= kFlushThreshold) {
        flush();
    }
}

void AtomicFileGroup::Writer::flush() {
    std::size_t done = 0;
    while (done < buffer_.size()) {
        const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            throw system_error(target_, "cannot write", errno);
        }
        done += static_cast<std::size_t>(n);
    }
    buffer_.clear();
}

void AtomicFileGroup::Writer::finish() {
    flush();
    if (::fsync(fd_) != 0) {
        throw system_error(target_, "cannot sync", errno);
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) {
        throw system_error(target_, "cannot close", errno);
    }
}

AtomicFileGroup::~AtomicFileGroup() {
    if (committed_) {
        return;
    }
    for (const auto& file : files_) {
        std::error_code ignored;
        std::filesystem::remove(file->temporary_, ignored);
    }
}

AtomicFileGroup::Writer& AtomicFileGroup::add(const std::filesystem::path& target) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) about "literal" + std::string.
    std::string prefix = ".";
    prefix += target.filename().string();
    prefix += ".tmp.";
    remove_stale_temporaries(directory_of(target), prefix);
    const std::string stem = prefix + std::to_string(::getpid());
    for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
        std::filesystem::path temporary =
            target.parent_path() / (stem + "." + std::to_string(attempt));
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            files_.push_back(std::unique_ptr<Writer>(new Writer(target, std::move(temporary), fd)));
            return *files_.back();
        }
        if (errno != EEXIST) {
            throw system_error(target, "cannot create a file in its directory", errno);
        }
    }
    throw SystemError(located_message(
        target.string(), std::nullopt, "cannot find a free temporary name in its directory"));
}

void AtomicFileGroup::commit() {
    for (const auto& file : files_) {
        file->finish();
    }
    std::vector<DirectoryLock> locks;
    for (const std::filesystem::path& dir : target_directories(files_)) {
        locks.emplace_back(dir);
    }
    for (const auto& file : files_) {
        if (std::rename(file->temporary_.c_str(), file->target_.c_str()) != 0) {
            throw system_error(file->target_, "cannot rename into place", errno);
        }
    }
    committed_ = true;
}

}  // namespace cavity::core
