#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/experiments/harness.h"

namespace cavity::experiments {
namespace {

namespace fs = std::filesystem;

class Harness : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cavity_harness_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "tiny.suite") << "question tiny\nkind runs\ndist cube skew-lines\n"
                                              "n.quick 60 90\nn.full 60\nseeds.quick 1 2\n"
                                              "seeds.full 1\norder random brio\nvalidate yes\n";
        std::ofstream(dir_ / "fj.suite")
            << "question fj\nkind jtets\ndist skew-lines\n"
               "n.quick 12 16\nn.full 12\nseeds.quick 1\nseeds.full 1\n";
    }

    void TearDown() override { fs::remove_all(dir_); }

    HarnessOptions options(const std::string& suite, const std::string& out) const {
        HarnessOptions o;
        o.suite_file = dir_ / (suite + ".suite");
        o.out_dir = dir_ / out;
        return o;
    }

    fs::path dir_;
};

/// The table without the columns that measure time or memory, which differ between runs.
std::vector<std::vector<std::string>> stable_columns(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string f; std::getline(h, f, ',');) {
        header.push_back(f);
    }
    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line)) {
        std::stringstream r(line);
        std::vector<std::string> row;
        std::size_t i = 0;
        for (std::string f; std::getline(r, f, ','); ++i) {
            const std::string& name = header.at(i);
            if (name.find("time") == std::string::npos && name != "order_s" &&
                name != "us_per_point" && name != "peak_rss_bytes") {
                row.push_back(f);
            }
        }
        rows.push_back(row);
    }
    return rows;
}

TEST_F(Harness, ShardsMergeIntoTheUnshardedTable) {
    const HarnessResult whole = run_experiment(options("tiny", "whole"));
    EXPECT_TRUE(whole.merged);
    EXPECT_EQ(whole.runs_total, 16u);
    HarnessOptions part = options("tiny", "sharded");
    part.shard_count = 3;
    for (std::uint64_t i = 1; i <= 3; ++i) {
        part.shard_index = i;
        const HarnessResult r = run_experiment(part);
        EXPECT_EQ(r.merged, i == 3);
    }
    EXPECT_TRUE(fs::exists(dir_ / "sharded" / "tiny.meta.json"));
    EXPECT_FALSE(fs::exists(dir_ / "sharded" / "tiny.part-1-of-3.csv"));
    EXPECT_EQ(stable_columns(dir_ / "whole" / "tiny.csv"),
              stable_columns(dir_ / "sharded" / "tiny.csv"));
}

TEST_F(Harness, APartialMergeResumesIntoTheWholeTable) {
    run_experiment(options("tiny", "whole"));
    HarnessOptions o = options("tiny", "long");
    o.shard_count = 3;
    o.shard_index = 1;
    const HarnessResult first = run_experiment(o);  // a third of the runs, then stopped
    EXPECT_FALSE(first.merged);
    o.merge_only = true;
    EXPECT_THROW(run_experiment(o), core::Error);  // a plain merge refuses missing runs
    o.partial = true;
    HarnessOptions empty = options("tiny", "nothing");
    empty.merge_only = true;
    empty.partial = true;
    EXPECT_THROW(run_experiment(empty), core::Error);  // nothing measured: nothing to merge
    const HarnessResult merged = run_experiment(o);
    EXPECT_TRUE(merged.merged);
    EXPECT_EQ(stable_columns(dir_ / "long" / "tiny.csv").size(), first.runs_done);
    std::ifstream meta(dir_ / "long" / "tiny.meta.json");
    const std::string text((std::istreambuf_iterator<char>(meta)),
                           std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"runs_measured\": " + std::to_string(first.runs_done)),
              std::string::npos);
    // Later, one unsharded process continues from the partial table and redoes nothing.
    HarnessOptions rest = options("tiny", "long");
    rest.resume = true;
    const HarnessResult finished = run_experiment(rest);
    EXPECT_EQ(finished.runs_skipped, first.runs_done);
    EXPECT_EQ(finished.runs_done, 16u - first.runs_done);
    EXPECT_TRUE(finished.merged);
    EXPECT_EQ(stable_columns(dir_ / "whole" / "tiny.csv"),
              stable_columns(dir_ / "long" / "tiny.csv"));
}

TEST_F(Harness, ResumeSkipsFinishedRows) {
    HarnessOptions o = options("tiny", "out");
    run_experiment(o);
    o.resume = true;
    const HarnessResult again = run_experiment(o);
    EXPECT_EQ(again.runs_done, 0u);
    EXPECT_EQ(again.runs_skipped, 16u);
    EXPECT_TRUE(again.merged);
}

TEST_F(Harness, ResumeAfterAnInterruptionRunsOnlyTheRest) {
    HarnessOptions o = options("fj", "out");
    o.shard_count = 2;
    o.shard_index = 1;
    run_experiment(o);  // half the runs, not merged
    // Tear the last row as an interrupted write would.
    const fs::path part = dir_ / "out" / "fj.part-1-of-2.csv";
    std::ofstream(part, std::ios::app) << "skew-lines,16,-,-";
    o.shard_index = 2;
    o.resume = true;
    const HarnessResult r = run_experiment(o);
    EXPECT_EQ(r.runs_done, 1u);
    EXPECT_TRUE(r.merged);
    EXPECT_EQ(stable_columns(dir_ / "out" / "fj.csv").size(), 2u);
    EXPECT_GT(stable_columns(dir_ / "out" / "fj.j.csv").size(), 10u);
}

TEST_F(Harness, MergeOnlyNamesWhatIsMissing) {
    HarnessOptions o = options("fj", "out");
    o.shard_count = 2;
    o.merge_only = true;
    try {
        run_experiment(o);
        FAIL() << "merge without parts succeeded";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find("2 part file(s)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace cavity::experiments
