#include <algorithm>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/measure.h"
#include "cavity/experiments/suite.h"

namespace cavity::experiments {
namespace {

/// Tetrahedra and ghost tetrahedra of the Delaunay triangulation of `points`.
double cells(const core::PointSet& points) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    const core::Triangulation d = core::triangulate(points, order, {});
    return static_cast<double>(d.tets.size() + d.hull_triangles);
}

// Exercise 2's measurement splits each run where S ends: what T's insertions create minus what
// they delete must turn Del S into Del(S ∪ T) exactly, in every order (so also on average), and
// the brute-force conflict graph of Del S holds at least one conflict per point of T.
TEST(Extend, PhaseSplitTurnsDelSIntoDelSAndT) {
    const Suite suite = parse_suite(R"(question q
kind extend
dist skew-lines cube
n.quick 30
n.full 30
seeds.quick 2
seeds.full 2
added.quick 7 40
added.full 7
orders.quick 6
)",
                                    "extend.suite",
                                    "extend");
    const auto runs = enumerate_runs(suite, suite.quick);
    ASSERT_EQ(runs.size(), 2u);
    const auto j_cols = j_columns(SuiteKind::kExtend);
    const auto at = [&](const std::vector<std::string>& row, const std::string& name) {
        const auto k = std::find(j_cols.begin(), j_cols.end(), name) - j_cols.begin();
        return std::stod(row.at(static_cast<std::size_t>(k)));
    };
    for (const RunSpec& run : runs) {
        const RunOutput out = execute_run(suite, suite.quick, run);
        ASSERT_EQ(out.j_rows.size(), 2u);
        const core::PointSet s_points = core::generate_points(run.dist, run.n, run.seed);
        for (const auto& row : out.j_rows) {
            const auto t = static_cast<std::uint64_t>(at(row, "t"));
            const double growth =
                cells(measure::extend_points(s_points, t, run.seed)) - cells(s_points);
            // The table's means have six significant digits.
            EXPECT_NEAR(at(row, "created_mean") - at(row, "deleted_mean"),
                        growth,
                        1e-5 * at(row, "created_mean"))
                << run.dist << " t = " << t;
            EXPECT_GE(at(row, "initial_conflicts_mean"), static_cast<double>(t));
            EXPECT_LE(at(row, "first_deleted_mean"), at(row, "max_cavity_mean"));
            EXPECT_GT(at(row, "scratch_conflicts_mean"), 0.0);
        }
    }
}

TEST(Extend, NeedsTheSizesOfT) {
    try {
        parse_suite(
            "question q\nkind extend\ndist cube\nn.quick 10\nn.full 10\nseeds.quick 1\n"
            "seeds.full 1\nadded.quick 5\n",
            "bad.suite",
            "bad");
        FAIL() << "an extend suite without added.full parsed";
    } catch (const core::Error& e) {
        EXPECT_NE(std::string(e.what()).find("added.TIER"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace cavity::experiments
