#include <fstream>
#include <sstream>

#include "peer_engines.h"

namespace cavity::experiments::detail {

namespace {

/// The number after "Delaunay seconds:" in TetGen's report (it times with clock(), so CPU time
/// of the sort and the insertions, without reading and writing files).
std::optional<double> delaunay_seconds(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line;
    const std::string label = "Delaunay seconds:";
    while (std::getline(in, line)) {
        if (line.rfind(label, 0) == 0) {
            std::istringstream value(line.substr(label.size()));
            double seconds = 0;
            if (value >> seconds) {
                return seconds;
            }
        }
    }
    return std::nullopt;
}

}  // namespace

TetgenRun run_tetgen(const std::filesystem::path& tetgen, const std::filesystem::path& prefix) {
    const std::filesystem::path dir = prefix.parent_path();
    const std::filesystem::path log = dir / "tetgen.log";
    const ProgramOutcome outcome =
        run_program(tetgen, {"-NF", prefix.filename().string() + ".node"}, dir, log);
    TetgenRun run;
    run.cpu_seconds = outcome.cpu_seconds;
    run.peak_bytes = outcome.peak_bytes;
    run.delaunay_seconds = delaunay_seconds(log);
    if (outcome.exit_status != 0) {
        run.failure = outcome.exit_status < 0
                          ? "killed by a signal"
                          : "exit status " + std::to_string(outcome.exit_status);
        return run;
    }
    std::ifstream ele(prefix.string() + ".1.ele");
    if (!(ele >> run.tets)) {
        run.failure = "no readable " + prefix.filename().string() + ".1.ele";
        return run;
    }
    run.ok = true;
    return run;
}

}  // namespace cavity::experiments::detail
