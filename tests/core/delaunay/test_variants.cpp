// Every variant (insertion order x point location x storage) on the degenerate corpus: the result
// is valid (checked exactly by core::validate) and identical across variants, because the
// symbolic perturbation makes the triangulation unique.

#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/check/validate.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "corpus.h"

namespace cavity::test {
namespace {

using core::LocateKind;
using core::OrderKind;
using core::StorageKind;

class Variants : public ::testing::TestWithParam<CorpusCase> {};

/// Triangulates the case's points in every row of the name tables (a new variant is tested as
/// soon as it has a name), the orders seeded with `seed`, and hands each result to `check` with
/// the variant's name.
template <class Check>
void for_each_variant(const CorpusCase& c, std::uint64_t seed, bool count, Check&& check) {
    for (const auto& [order_name, order, order_help] : core::kOrderKinds) {
        for (const auto& [locate_name, locate, locate_help] : core::kLocateKinds) {
            for (const auto& [storage_name, storage, storage_help] : core::kStorageKinds) {
                core::OrderOptions order_options;
                order_options.kind = order;
                order_options.seed = seed;
                const auto sequence =
                    core::make_insertion_order(c.points.points, order_options).sequence;
                core::TriangulateOptions options;
                options.locate = locate;
                options.storage = storage;
                options.count = count;
                check(c.name + " order " + std::string(order_name) + " locate " +
                          std::string(locate_name) + " storage " + std::string(storage_name),
                      core::triangulate(c.points, sequence, options));
            }
        }
    }
}

TEST_P(Variants, ValidAndIdenticalForEveryOrderLocatorAndStorage) {
    const CorpusCase& c = GetParam();
    std::vector<std::array<std::uint32_t, 4>> reference;
    for_each_variant(c, 11, true, [&](const std::string& variant, const auto& tri) {
        const auto report = core::validate(c.points, tri.tets);
        ASSERT_TRUE(report.ok()) << variant << ": "
                                 << (report.problems.empty() ? "" : report.problems[0]);
        EXPECT_EQ(report.duplicates, tri.duplicates.size()) << variant;
        if (c.expected_tets >= 0) {
            EXPECT_EQ(static_cast<long long>(tri.tets.size()), c.expected_tets) << variant;
        }
        // Work identity of Bowyer–Watson: the final solid tetrahedra are those created minus
        // those deleted (the bootstrap tetrahedron counts as created).
        EXPECT_EQ(tri.counters.tets_created - tri.counters.tets_deleted, tri.tets.size())
            << variant;
        // And of its ghosts: one per hull triangle remains.
        EXPECT_EQ(tri.counters.ghosts_created - tri.counters.ghosts_deleted, tri.hull_triangles)
            << variant;
        const auto canon = canonical(tri.tets);
        if (reference.empty()) {
            reference = canon;
        } else {
            EXPECT_EQ(canon, reference) << variant << ": a different triangulation";
        }
    });
}

// The uncounted engine takes the fast routes (static filters; on integer grids the plain
// determinants and the lattice tie-break, geometry.h) while the counting engine keeps the staged
// predicates: both must build the same tetrahedra in every variant.
TEST_P(Variants, UncountedEngineMatchesTheCountingOne) {
    const CorpusCase& c = GetParam();
    const auto reference_sequence =
        core::make_insertion_order(c.points.points, core::OrderOptions{}).sequence;
    core::TriangulateOptions counted;
    counted.count = true;
    const auto reference = canonical(core::triangulate(c.points, reference_sequence, counted).tets);
    for_each_variant(c, 5, false, [&](const std::string& variant, const auto& tri) {
        EXPECT_EQ(canonical(tri.tets), reference) << variant << ": a different triangulation";
    });
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

/// Counts the engine's tetrahedra through its per-tetrahedron hooks, independently of the
/// totals it keeps: a deleted tetrahedron's kind is the one it was created with (ids are reused
/// only after deletion).
struct HookCounts : core::CountingObserver {
    std::vector<char> ghost;  // by TetId, as created
    std::uint64_t solids_created = 0;
    std::uint64_t ghosts_created = 0;
    std::uint64_t solids_deleted = 0;
    std::uint64_t ghosts_deleted = 0;

    void on_tet_created(core::TetId t, const core::TetVertices& v, std::uint64_t) {
        if (ghost.size() <= t) {
            ghost.resize(t + 1);
        }
        ghost[t] = core::is_ghost(v) ? 1 : 0;
        ++(ghost[t] != 0 ? ghosts_created : solids_created);
    }

    void on_tet_deleted(core::TetId t, std::uint64_t) {
        ++(ghost[t] != 0 ? ghosts_deleted : solids_deleted);
    }
};

// The counting engine adds its tetrahedron and test counts once per insertion, from what the
// cavity search kept in its own frame and from the insertion's lists (bowyer_watson.h); the
// hooks see every tetrahedron one at a time. Both must agree, for each storage and locator, on
// points in general position and on a grid whose ties the perturbation decides.
TEST(Variants, CountersAgreeWithThePerTetrahedronHooks) {
    const std::vector<std::pair<std::string, core::PointSet>> inputs{
        {"ball", core::generate_points("ball", 2000, 7, core::WeightSpec{})},
        {"grid", core::generate_points("grid", 1000, 7, core::WeightSpec{})}};
    for (const auto& [name, points] : inputs) {
        const auto sequence =
            core::make_insertion_order(points.points, core::OrderOptions{}).sequence;
        for (const auto& [locate_name, locate, locate_help] : core::kLocateKinds) {
            for (const auto& [storage_name, storage, storage_help] : core::kStorageKinds) {
                const std::string variant =
                    name + " " + std::string(locate_name) + " " + std::string(storage_name);
                core::TriangulateOptions options;
                options.locate = locate;
                options.storage = storage;
                options.count = true;
                HookCounts hooks;
                const auto tri = core::triangulate_observed(points, sequence, options, hooks);
                const core::Counters& c = tri.counters;
                EXPECT_EQ(c.tets_created, hooks.solids_created) << variant;
                EXPECT_EQ(c.ghosts_created, hooks.ghosts_created) << variant;
                EXPECT_EQ(c.tets_deleted, hooks.solids_deleted) << variant;
                EXPECT_EQ(c.ghosts_deleted, hooks.ghosts_deleted) << variant;
                EXPECT_EQ(c.insertions, points.points.size() - 4) << variant;
                // Every test the search made is one of the deleted tetrahedra but each
                // insertion's first, or a face of its cavity (one new tetrahedron each).
                EXPECT_EQ(c.dig_tests,
                          hooks.solids_deleted + hooks.ghosts_deleted - c.insertions +
                              hooks.solids_created + hooks.ghosts_created - 5)
                    << variant;
                EXPECT_GT(c.stage_calls[static_cast<std::size_t>(core::PredicateKind::kInsphere)]
                                       [static_cast<std::size_t>(predicates::Stage::kStatic)],
                          0u)
                    << variant;
                if (locate == LocateKind::kWalk) {
                    EXPECT_GT(c.walk_steps, 0u) << variant;
                }
            }
        }
    }
}

// The name tables are what users type: each name parses to its own row, the names are distinct,
// and any other name is refused with the list of the valid ones.
template <class Table>
void expect_consistent(const Table& table, std::string_view what, auto parse) {
    std::set<std::string_view> names;
    for (const auto& row : table) {
        EXPECT_TRUE(names.insert(row.name).second) << what << ": " << row.name << " twice";
        EXPECT_EQ(parse(row.name), row.kind) << row.name;
        EXPECT_EQ(core::name_of(table, row.kind), row.name);
        EXPECT_FALSE(row.help.empty()) << row.name;
    }
    try {
        parse("no-such-variant");
        ADD_FAILURE() << what << ": an unknown name was accepted";
    } catch (const core::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("unknown " + std::string(what) + " 'no-such-variant'"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find(std::string(table.back().name)), std::string::npos) << message;
    }
}

TEST(NameTables, EachNameParsesToItsRowAndOthersAreRefused) {
    expect_consistent(core::kOrderKinds, "insertion order", core::parse_order_kind);
    expect_consistent(core::kLocateKinds, "point location", core::parse_locate_kind);
    expect_consistent(core::kStorageKinds, "storage", core::parse_storage_kind);
    expect_consistent(core::kBootstrapRules, "bootstrap rule", core::parse_bootstrap_rule);
    EXPECT_EQ(core::kOrderKinds.size(), std::size_t{5});  // OrderKind's values, one row each
    EXPECT_EQ(core::kLocateKinds.size(), std::size_t{4});
}

}  // namespace
}  // namespace cavity::test
