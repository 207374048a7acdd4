#include "child_process.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cavity/core/base/error.h"

namespace cavity::experiments::detail {

namespace {

using core::Error;

/// The fixed-size message a child writes to its pipe before exiting.
struct Wire {
    int ok = 0;
    EngineReport report;
    char message[512] = {};
};

double seconds_of(const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

/// Waits for `pid` and returns its status and resource usage, retrying on EINTR.
int wait_for(pid_t pid, rusage& usage) {
    int status = 0;
    while (wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) {
            throw Error(std::string("wait4: ") + std::strerror(errno));
        }
    }
    return status;
}

std::string describe(int status) {
    if (WIFSIGNALED(status)) {
        return std::string("killed by signal ") + strsignal(WTERMSIG(status));
    }
    return "exit status " + std::to_string(WEXITSTATUS(status));
}

void write_all(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t w = write(fd, p, size);
        if (w < 0 && errno == EINTR) {
            continue;
        }
        if (w <= 0) {
            return;
        }
        p += w;
        size -= static_cast<std::size_t>(w);
    }
}

std::size_t read_all(int fd, void* data, std::size_t size) {
    char* p = static_cast<char*>(data);
    std::size_t got = 0;
    while (got < size) {
        const ssize_t r = read(fd, p + got, size - got);
        if (r < 0 && errno == EINTR) {
            continue;
        }
        if (r <= 0) {
            break;
        }
        got += static_cast<std::size_t>(r);
    }
    return got;
}

}  // namespace

double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

ChildOutcome run_in_child(const std::function<EngineReport()>& work) {
    int fds[2];
    if (pipe(fds) != 0) {
        throw Error(std::string("pipe: ") + std::strerror(errno));
    }
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        // The child: never return into the caller's stack, never flush the parent's buffers.
        close(fds[0]);
        Wire wire;
        try {
            wire.report = work();
            wire.ok = 1;
        } catch (const std::exception& e) {
            std::strncpy(wire.message, e.what(), sizeof wire.message - 1);
        }
        write_all(fds[1], &wire, sizeof wire);
        close(fds[1]);
        _exit(wire.ok ? 0 : 1);
    }
    close(fds[1]);
    Wire wire;
    const std::size_t got = read_all(fds[0], &wire, sizeof wire);
    close(fds[0]);
    rusage usage{};
    const int status = wait_for(pid, usage);
    if (got != sizeof wire) {
        throw Error("measuring child " + describe(status) + " before reporting");
    }
    if (!wire.ok) {
        throw Error(wire.message);
    }
    return {wire.report,
            seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime),
            static_cast<std::uint64_t>(usage.ru_maxrss) * 1024u};
}

ProgramOutcome run_program(const std::filesystem::path& program,
                           const std::vector<std::string>& arguments,
                           const std::filesystem::path& directory,
                           const std::filesystem::path& log) {
    std::vector<std::string> words{program.string()};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    argv.reserve(words.size() + 1);
    for (std::string& w : words) {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    const std::string dir = directory.string();
    const std::string log_name = log.string();
    const pid_t pid = fork();
    if (pid < 0) {
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        const int out = open(log_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || chdir(dir.c_str()) != 0) {
            _exit(127);
        }
        dup2(out, STDOUT_FILENO);
        dup2(out, STDERR_FILENO);
        close(out);
        execv(argv[0], argv.data());
        _exit(127);
    }
    rusage usage{};
    const int status = wait_for(pid, usage);
    ProgramOutcome outcome;
    outcome.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
    outcome.peak_bytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024u;
    return outcome;
}

std::filesystem::path find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) {
            end = dirs.size();
        }
        const std::string dir = dirs.substr(start, end - start);
        start = end + 1;
        if (dir.empty()) {
            continue;
        }
        std::filesystem::path candidate = std::filesystem::path(dir) / name;
        if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) {
            return candidate;
        }
    }
    return {};
}

}  // namespace cavity::experiments::detail
