// Every variant (insertion order x point location x storage) on the degenerate corpus: the result
// is valid (checked exactly by core::validate) and identical across variants, because the
// symbolic perturbation makes the triangulation unique.

#include <string>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/delaunay/triangulate.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/order/insertion_order.h"
#include "corpus.h"

namespace cavity::test {
namespace {

using core::LocateKind;
using core::OrderKind;
using core::StorageKind;

class Variants : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(Variants, ValidAndIdenticalForEveryOrderLocatorAndStorage) {
    const CorpusCase& c = GetParam();
    std::vector<std::array<std::uint32_t, 4>> reference;
    for (OrderKind order : {OrderKind::kInput,
                            OrderKind::kRandom,
                            OrderKind::kBrio,
                            OrderKind::kHilbert,
                            OrderKind::kZOrder}) {
        for (LocateKind locate : {LocateKind::kWalk,
                                  LocateKind::kConflictGraph,
                                  LocateKind::kFullConflictGraph,
                                  LocateKind::kStraightWalk}) {
            for (StorageKind storage : {StorageKind::kArray, StorageKind::kHash}) {
                core::OrderOptions order_options;
                order_options.kind = order;
                order_options.seed = 11;
                const auto sequence =
                    core::make_insertion_order(c.points.points, order_options).sequence;
                core::TriangulateOptions options;
                options.locate = locate;
                options.storage = storage;
                options.count = true;
                const auto tri = core::triangulate(c.points, sequence, options);
                const std::string variant = c.name + " order " + std::to_string(int(order)) +
                                            " locate " + std::to_string(int(locate)) + " storage " +
                                            std::to_string(int(storage));
                const auto report = core::validate(c.points, tri.tets);
                ASSERT_TRUE(report.ok())
                    << variant << ": " << (report.problems.empty() ? "" : report.problems[0]);
                EXPECT_EQ(report.duplicates, tri.duplicates.size()) << variant;
                if (c.expected_tets >= 0) {
                    EXPECT_EQ(static_cast<long long>(tri.tets.size()), c.expected_tets) << variant;
                }
                // Work identity of Bowyer–Watson: the final solid tetrahedra are those created
                // minus those deleted (the bootstrap tetrahedron counts as created).
                EXPECT_EQ(tri.counters.tets_created - tri.counters.tets_deleted, tri.tets.size())
                    << variant;
                const auto canon = canonical(tri.tets);
                if (reference.empty()) {
                    reference = canon;
                } else {
                    ASSERT_EQ(canon, reference) << variant << ": a different triangulation";
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(DegenerateCorpus,
                         Variants,
                         ::testing::ValuesIn(degenerate_corpus()),
                         [](const ::testing::TestParamInfo<CorpusCase>& p) {
                             return p.param.name;
                         });

TEST(Variants, UniformPointsMatchAcrossStoragesAndLocators) {
    const auto points = core::generate_points("ball", 3000, 3, core::WeightSpec{});
    const auto sequence = core::make_insertion_order(points.points, core::OrderOptions{}).sequence;
    core::TriangulateOptions options;
    const auto reference = canonical(core::triangulate(points, sequence, options).tets);
    options.locate = LocateKind::kConflictGraph;
    options.storage = StorageKind::kHash;
    EXPECT_EQ(canonical(core::triangulate(points, sequence, options).tets), reference);
    EXPECT_TRUE(core::validate(points, core::triangulate(points, sequence, options).tets).ok());
}

}  // namespace
}  // namespace cavity::test
