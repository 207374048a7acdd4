#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

/// Runs a measurement in a child process, so that its peak memory (the child's ru_maxrss, as
/// wait4 reports it) belongs to that measurement alone and not to whatever the parent held
/// before. Private to the experiments layer.
namespace cavity::experiments::detail {

/// What an engine run reports from inside its child.
struct EngineReport {
    double seconds = 0;      ///< CPU seconds the engine itself measured
    std::uint64_t tets = 0;  ///< finite tetrahedra of its output
};

struct ChildOutcome {
    EngineReport report;
    double cpu_seconds = 0;        ///< user + system CPU time of the whole child
    std::uint64_t peak_bytes = 0;  ///< the child's peak resident set size
};

/// Process CPU time: the machine is shared, so wall-clock time would charge an engine for the
/// time it spent descheduled.
double process_cpu_seconds();

/// Forks, runs `work` in the child and returns what it reported. \throws Error with the child's
/// message when `work` threw, or when the child died (naming the signal or exit status).
ChildOutcome run_in_child(const std::function<EngineReport()>& work);

struct ProgramOutcome {
    int exit_status = -1;  ///< exit code, or -1 when killed by a signal
    double cpu_seconds = 0;
    std::uint64_t peak_bytes = 0;
};

/// Runs `program` with `arguments` in `directory`, its standard output and error going to
/// `log`, and waits for it.
ProgramOutcome run_program(const std::filesystem::path& program,
                           const std::vector<std::string>& arguments,
                           const std::filesystem::path& directory,
                           const std::filesystem::path& log);

/// The first executable file called `name` in the directories of $PATH, or an empty path.
std::filesystem::path find_on_path(const std::string& name);

}  // namespace cavity::experiments::detail
