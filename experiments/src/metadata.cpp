#include "cavity/experiments/metadata.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <thread>

#include "suite_kinds.h"

namespace cavity::experiments {

namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

/// First line of a shell command's output, or "" when it fails (no git, not a checkout).
std::string command_output(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) {
        return "";
    }
    std::string out;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe.get()) != nullptr) {
        out += buffer;
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) {
        out.pop_back();
    }
    return out;
}

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown";
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buffer;
}

std::string list(const std::vector<std::uint64_t>& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += (i ? ", " : "") + std::to_string(values[i]);
    }
    return out + "]";
}

}  // namespace

std::string metadata_json(const Suite& suite,
                          const std::string& tier,
                          const TierSettings& settings,
                          std::size_t runs,
                          std::size_t runs_measured,
                          std::uint64_t shard_count,
                          const std::string& command_line) {
    const std::string source = CAVITY_SOURCE_DIR;
    const std::string git = "git -C '" + source + "' ";
    const std::string commit = command_output(git + "rev-parse HEAD 2>/dev/null");
    const std::string changes = command_output(git + "status --porcelain 2>/dev/null | wc -l");
    std::string json = "{\n";
    const auto field = [&json](const std::string& key, const std::string& value, bool quoted) {
        json += "  \"" + key + "\": " + (quoted ? "\"" + escape(value) + "\"" : value) + ",\n";
    };
    field("suite", suite.name, true);
    field("question", suite.question, true);
    field("kind", std::string(suite_kind_name(suite.kind)), true);
    field("suite_file", suite.file, true);
    field("tier", tier, true);
    field("runs", std::to_string(runs), false);
    field("runs_measured", std::to_string(runs_measured), false);
    field("sizes", list(settings.sizes), false);
    field("seeds", list(settings.seeds), false);
    field("order_seed_offset", "1000", false);
    // BRIO's ratio, in the literature's convention (the fraction carried to earlier rounds).
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.17g", suite.brio_ratio);
    field("brio_ratio", ratio, false);
    field("count_conflicts", suite.count_conflicts ? "true" : "false", false);
    if (suite.prefix != 0) {
        field("prefix", std::to_string(suite.prefix), false);
    }
    const SuiteKindInfo& kind = suite_kind_info(suite.kind);
    field("bootstrap", suite.bootstrap_first || kind.own_first ? "first" : "widest", true);
    if (kind.timed) {
        // What time_s and peak_rss_bytes measure (measure_triangulation.cpp).
        field("timed_engine", suite.count_conflicts ? "counting" : "uninstrumented", true);
    }
    if (suite.kind == SuiteKind::kExtend) {
        field("added", list(settings.added), false);
        field("orders", std::to_string(settings.orders), false);
    }
    if (suite.kind == SuiteKind::kDeletion) {
        field("deletions", std::to_string(settings.deletions), false);
        field("deletion_seed_offset", "2000", false);
    }
    field("shards", std::to_string(shard_count), false);
    field("command", command_line, true);
    field("git_commit", commit.empty() ? "unknown" : commit, true);
    field("git_changed_files", changes.empty() ? "null" : changes, false);
    field("compiler", __VERSION__, true);
    field("build_type", CAVITY_BUILD_TYPE, true);
    field("cxx_flags", CAVITY_CXX_FLAGS, true);
    field("cpu", cpu_model(), true);
    field("hardware_threads", std::to_string(std::thread::hardware_concurrency()), false);
    json += "  \"date_utc\": \"" + utc_now() + "\"\n}\n";
    return json;
}

}  // namespace cavity::experiments
