#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/experiments/harness.h"
#include "cavity/experiments/run.h"
#include "cavity/experiments/suite.h"

namespace cavity::experiments {
namespace {

namespace fs = std::filesystem;

TEST(Peers, ShippedSuiteParses) {
    const Suite suite = read_suite(std::string(CAVITY_SUITES_DIR) + "/peers.suite");
    EXPECT_EQ(suite.kind, SuiteKind::kPeers);
    for (const RunSpec& run : enumerate_runs(suite, suite.full)) {
        EXPECT_FALSE(run.dist == "cospherical" && run.n > 30000) << run.n;
    }
}

TEST(Peers, CapLeavesOutLargerSizesAndIsCheckedPerLine) {
    const std::string head =
        "question q\nkind peers\ndist cube cospherical\nn.quick 10 100\n"
        "n.full 10\nseeds.quick 1\nseeds.full 1\n";
    const Suite suite = parse_suite(head + "cap cospherical 50\n", "p.suite", "p");
    // cube at 10 and 100, cospherical at 10 only.
    EXPECT_EQ(enumerate_runs(suite, suite.quick).size(), 3u);
    const auto error_of = [&](const std::string& tail) -> std::string {
        try {
            parse_suite(head + tail, "p.suite", "p");
        } catch (const core::Error& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(error_of("cap cube 5\ncap cube 6\n").find("p.suite:9: key 'cap cube' given twice"),
              std::string::npos);
    EXPECT_NE(error_of("cap nowhere 5\n").find("p.suite:8: unknown distribution"),
              std::string::npos);
    EXPECT_NE(error_of("cap cube\n").find("p.suite:8: cap takes a distribution and a size"),
              std::string::npos);
    EXPECT_EQ(error_of("cap cube 5\ncap grid 6\n"), "");
}

/// The rows of a CSV as column -> value maps.
std::vector<std::map<std::string, std::string>> read_rows(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string f; std::getline(h, f, ',');) {
        header.push_back(f);
    }
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::map<std::string, std::string> row;
        std::stringstream r(line);
        std::size_t i = 0;
        for (std::string f; std::getline(r, f, ','); ++i) {
            row[header.at(i)] = f;
        }
        EXPECT_EQ(row.size(), header.size()) << line;
        rows.push_back(row);
    }
    return rows;
}

TEST(Peers, TinyRunWritesOneRowPerInputWithEveryAvailablePeer) {
    const fs::path dir = fs::temp_directory_path() / "cavity_peers_tiny";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "tiny.suite") << "question tiny\nkind peers\ndist cube grid cospherical\n"
                                         "n.quick 300\nn.full 300\nseeds.quick 1\nseeds.full 1\n"
                                         "order brio\n";
    HarnessOptions options;
    options.suite_file = dir / "tiny.suite";
    options.out_dir = dir / "out";
    const HarnessResult result = run_experiment(options);
    ASSERT_TRUE(result.merged);
    const auto rows = read_rows(result.csv);
    ASSERT_EQ(rows.size(), 3u);
    for (const auto& row : rows) {
        SCOPED_TRACE(row.at("dist"));
        EXPECT_GT(std::stoull(row.at("cavity_tets")), 0u);
        EXPECT_GT(std::stoull(row.at("cavity_peak_bytes")), 0u);
        EXPECT_GE(std::stoull(row.at("cavity_peak_bytes")),
                  std::stoull(row.at("input_peak_bytes")) / 2);
        for (const char* peer : {"cgal", "tetgen"}) {
            const std::string status = row.at(std::string(peer) + "_status");
            // A peer missing from this machine or build is skipped, never an error.
            if (status == "unavailable") {
                EXPECT_EQ(row.at(std::string(peer) + "_s"), "-");
                continue;
            }
            ASSERT_EQ(status, "ok") << peer;
            EXPECT_GT(std::stoull(row.at(std::string(peer) + "_peak_bytes")), 0u);
            // Uniform points have a unique Delaunay triangulation; the degenerate inputs may be
            // completed differently by each engine's tie-breaking.
            if (row.at("dist") == "cube") {
                EXPECT_EQ(row.at(std::string(peer) + "_tets"), row.at("cavity_tets")) << peer;
            } else {
                EXPECT_GT(std::stoull(row.at(std::string(peer) + "_tets")), 0u) << peer;
            }
        }
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace cavity::experiments
