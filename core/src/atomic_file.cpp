#include "cavity/core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "cavity/core/error.h"

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
    std::string stem = ".";
    stem += target.filename().string();
    stem += ".tmp.";
    stem += std::to_string(::getpid());
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
    for (const auto& file : files_) {
        if (std::rename(file->temporary_.c_str(), file->target_.c_str()) != 0) {
            throw system_error(file->target_, "cannot rename into place", errno);
        }
    }
    committed_ = true;
}

}  // namespace cavity::core
