#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/experiments/run.h"
#include "cavity/experiments/suite.h"

namespace cavity::experiments {
namespace {

constexpr const char* kGood = R"(# a comment
question  does it parse?
kind      runs
dist      cube ball     # trailing comment
n.quick   100 200
n.full    1000
seeds.quick 1..3
seeds.full  1
order     random brio-noreverse
locate    walk conflict-graph
count-conflicts yes
brio-ratio 0.125
bootstrap first
prefix    50
n.paper   1000 10000
seeds.paper 1..5
)";

/// The suite-kind table (suite_kinds.cpp) has a row for every kind: its name reads back as the
/// kind, and its measurement declares columns.
TEST(Suite, EveryKindHasARow) {
    for (int k = 0; k <= static_cast<int>(SuiteKind::kExtend); ++k) {
        const auto kind = static_cast<SuiteKind>(k);
        const std::string name(suite_kind_name(kind));
        const bool plc = kind == SuiteKind::kCdt;
        const std::string text =
            "question q\nkind " + name + "\ndist " + (plc ? "hull-faces" : "cube") +
            "\nn.quick 10\nseeds.quick 1\nn.full 10\nseeds.full 1\nadded.quick 2\nadded.full 2\n";
        EXPECT_EQ(parse_suite(text, "k.suite", "k").kind, kind) << name;
        EXPECT_FALSE(metric_columns(kind).empty()) << name;
    }
}

TEST(Suite, ParsesEveryKey) {
    const Suite suite = parse_suite(kGood, "good.suite", "good");
    EXPECT_EQ(suite.question, "does it parse?");
    EXPECT_EQ(suite.kind, SuiteKind::kRuns);
    EXPECT_EQ(suite.distributions, (std::vector<std::string>{"cube", "ball"}));
    EXPECT_EQ(suite.quick.seeds, (std::vector<std::uint64_t>{1, 2, 3}));
    EXPECT_EQ(suite.full.sizes, (std::vector<std::uint64_t>{1000}));
    EXPECT_EQ(suite.storages, (std::vector<std::string>{"array"}));
    EXPECT_FALSE(suite.validate);
    EXPECT_TRUE(suite.count_conflicts);
    EXPECT_EQ(suite.brio_ratio, 0.125);
    EXPECT_TRUE(suite.bootstrap_first);
    EXPECT_EQ(suite.prefix, 50u);
    EXPECT_EQ(suite.tier("paper").sizes, (std::vector<std::uint64_t>{1000, 10000}));
    EXPECT_EQ(suite.tier("paper").seeds.size(), 5u);
    // Sizes outermost: a long tier stopped part-way has finished its smaller sizes.
    const std::vector<RunSpec> paper = enumerate_runs(suite, suite.paper);
    EXPECT_TRUE(std::is_sorted(
        paper.begin(), paper.end(), [](const RunSpec& a, const RunSpec& b) { return a.n < b.n; }));
    // 2 dists x 2 sizes x 3 seeds x 2 orders x 2 locators.
    EXPECT_EQ(enumerate_runs(suite, suite.quick).size(), 48u);
}

/// The message of the Error that parsing `text` throws ("" when it does not throw).
std::string error_of(const std::string& text) {
    try {
        parse_suite(text, "bad.suite", "bad");
    } catch (const core::Error& e) {
        return e.what();
    }
    return "";
}

TEST(Suite, MalformedLinesAreNamedByFileAndLine) {
    const std::string head = "question q\nkind runs\n";
    const std::string rest = "n.quick 10\nn.full 10\nseeds.quick 1\nseeds.full 1\n";
    EXPECT_NE(
        error_of(head + "dist cube\nsizes 10\n" + rest).find("bad.suite:4: unknown key 'sizes'"),
        std::string::npos);
    EXPECT_NE(
        error_of(head + "dist cube\n" + "n.quick 10 ten\nn.full 10\nseeds.quick 1\nseeds.full 1\n")
            .find("bad.suite:4: 'ten' is not a non-negative integer"),
        std::string::npos);
    EXPECT_NE(
        error_of(head + "dist cube nowhere\n" + rest).find("bad.suite:3: unknown distribution"),
        std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\norder sideways\n" + rest).find("bad.suite:4:"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\ncount-conflicts maybe\n" + rest)
                  .find("bad.suite:4: count-conflicts takes yes or no"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\nbrio-ratio 1\n" + rest).find("bad.suite:4: brio-ratio"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\nkind jtets\n" + rest)
                  .find("bad.suite:4: key 'kind' given twice"),
              std::string::npos);
    EXPECT_NE(error_of("question q\nkind sometimes\n").find("bad.suite:2: unknown kind"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\nseeds.quick 5..2\n").find("bad.suite:4: bad range"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\n").find("bad.suite: missing key 'n.quick'"),
              std::string::npos);
    EXPECT_NE(
        error_of(head + "dist cube\nbootstrap best\n" + rest).find("bad.suite:4: bootstrap takes"),
        std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\nn.paper 10\n" + rest)
                  .find("n.paper and seeds.paper go together"),
              std::string::npos);
    EXPECT_NE(
        error_of(head + "dist cube\nn.huge 10\n" + rest).find("bad.suite:4: unknown key 'n.huge'"),
        std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\ncount-conflicts yes\nprefix 3\n" + rest)
                  .find("bad.suite:5: prefix must be at least 4"),
              std::string::npos);
    EXPECT_NE(error_of(head + "dist cube\nprefix 100\n" + rest)
                  .find("prefix needs kind runs and count-conflicts yes"),
              std::string::npos);
    try {
        parse_suite(head + "dist cube\n" + rest, "bad.suite", "bad").tier("paper");
        ADD_FAILURE() << "a suite without n.paper has no paper tier";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find("no paper tier"), std::string::npos);
    }
    EXPECT_EQ(error_of(head + "dist cube\n" + rest), "");
}

TEST(Suite, ShippedSuitesParse) {
    for (const char* name : {"jtets",
                             "creation",
                             "scaling",
                             "theorem",
                             "theorem-prefix",
                             "quadratic",
                             "walk",
                             "adversarial",
                             "degenerate"}) {
        const std::string path = std::string(CAVITY_SUITES_DIR) + "/" + name + ".suite";
        EXPECT_NO_THROW(read_suite(path)) << path;
    }
}

// The hj kind: per-j means of created tetrahedra that add up to the run's own totals, BRIO ratios
// named in the order ("brio:R"), and bad ratios refused by name.
TEST(Suite, HjRunsAddUpAndNameTheirRatio) {
    const Suite suite = parse_suite(R"(question q
kind hj
dist cube
n.quick 80
n.full 80
seeds.quick 1
seeds.full 1
order random brio:0.125
orders.quick 12
)",
                                    "hj.suite",
                                    "hj");
    const auto runs = enumerate_runs(suite, suite.quick);
    ASSERT_EQ(runs.size(), 2u);
    const auto columns = metric_columns(SuiteKind::kHj);
    const auto column = [&](const RunOutput& out, const std::string& name) {
        const auto at = std::find(columns.begin(), columns.end(), name) - columns.begin();
        return std::stod(out.values.at(static_cast<std::size_t>(at)));
    };
    for (const RunSpec& run : runs) {
        const RunOutput out = execute_run(suite, suite.quick, run);
        double created = 0;
        double sum_j = 0;
        for (const auto& row : out.j_rows) {
            created += std::stod(row[1]);
            sum_j += std::stod(row[0]) * std::stod(row[1]);
        }
        EXPECT_NEAR(created, column(out, "created_mean"), 1e-3 * created) << run.order;
        EXPECT_NEAR(sum_j, column(out, "sum_j_mean"), 1e-3 * sum_j) << run.order;
        if (run.order == "brio:0.125") {
            EXPECT_EQ(column(out, "brio_ratio"), 0.125);
        }
    }
    EXPECT_NE(error_of("question q\nkind hj\ndist cube\norder brio:1.5\nn.quick 10\nn.full 10\n"
                       "seeds.quick 1\nseeds.full 1\n")
                  .find("bad.suite:4: order 'brio:1.5'"),
              std::string::npos);
}

}  // namespace
}  // namespace cavity::experiments
