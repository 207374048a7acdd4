// The suites of the chapter's second half (§5.6-5.8): gift-wrapping against Bowyer-Watson, vertex
// deletion against rebuilding, and CDTs of generated PLCs against Propositions 5.5-5.6. Each kind
// parses, runs at tiny sizes and fills its columns with values that could have come out wrong.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/input/plc.h"
#include "cavity/experiments/harness.h"
#include "cavity/experiments/plc_families.h"
#include "cavity/experiments/run.h"
#include "cavity/experiments/suite.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::experiments {
namespace {

namespace fs = std::filesystem;
using Row = std::map<std::string, std::string>;

std::vector<Row> read_rows(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string f; std::getline(h, f, ',');) {
        header.push_back(f);
    }
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        Row row;
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

double value(const Row& row, const std::string& column) {
    return std::stod(row.at(column));
}

/// Runs a suite given as text in a scratch directory; returns its main and per-j rows.
struct TinyRun {
    std::vector<Row> rows;
    std::vector<Row> j_rows;
};

TinyRun run_suite(const std::string& name, const std::string& text) {
    const fs::path dir = fs::temp_directory_path() / ("cavity_retriangulation_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / (name + ".suite")) << text;
    HarnessOptions options;
    options.suite_file = dir / (name + ".suite");
    options.out_dir = dir / "out";
    const HarnessResult result = run_experiment(options);
    EXPECT_TRUE(result.merged);
    TinyRun run{read_rows(result.csv), {}};
    if (fs::exists(dir / "out" / (name + ".j.csv"))) {
        run.j_rows = read_rows(dir / "out" / (name + ".j.csv"));
    }
    fs::remove_all(dir);
    return run;
}

std::string parse_error(const std::string& text) {
    try {
        parse_suite(text, "r.suite", "r");
    } catch (const core::Error& e) {
        return e.what();
    }
    return "";
}

TEST(Retriangulation, ShippedSuitesParse) {
    const std::string dir = CAVITY_SUITES_DIR;
    EXPECT_EQ(read_suite(dir + "/giftwrap.suite").kind, SuiteKind::kGiftWrap);
    const Suite deletion = read_suite(dir + "/deletion.suite");
    EXPECT_EQ(deletion.kind, SuiteKind::kDeletion);
    EXPECT_EQ(deletion.quick.deletions, 300u);
    const Suite cdt = read_suite(dir + "/cdt.suite");
    EXPECT_EQ(cdt.kind, SuiteKind::kCdt);
    EXPECT_TRUE(cdt.validates(120));
    EXPECT_FALSE(cdt.validates(121));
    const Suite valid = read_suite(dir + "/cdtvalid.suite");
    EXPECT_EQ(valid.kind, SuiteKind::kCdt);
    EXPECT_TRUE(valid.validates(1000000));
    // Neither deletion nor cdt varies an insertion order.
    for (const Suite* suite : {&deletion, &cdt}) {
        for (const RunSpec& run : enumerate_runs(*suite, suite->quick)) {
            EXPECT_EQ(run.order, "-");
        }
    }
}

TEST(Retriangulation, DistributionNamesDependOnTheKind) {
    const std::string rest = "n.quick 10\nn.full 10\nseeds.quick 1\nseeds.full 1\n";
    EXPECT_EQ(parse_error("question q\nkind cdt\ndist terrain voxel-grid\n" + rest), "");
    EXPECT_NE(parse_error("question q\nkind cdt\ndist terrain cube\n" + rest)
                  .find("r.suite:3: unknown PLC family 'cube'"),
              std::string::npos);
    // The kind may come after the names.
    EXPECT_NE(parse_error("question q\ndist terrain\nkind giftwrap\n" + rest)
                  .find("r.suite:2: unknown distribution 'terrain'"),
              std::string::npos);
    EXPECT_NE(parse_error("question q\nkind deletion\ndist cube\n" + rest + "deletions.quick x\n")
                  .find("r.suite:8: 'x' is not a non-negative integer"),
              std::string::npos);
    EXPECT_NE(parse_error("question q\nkind cdt\ndist terrain\n" + rest + "validate often\n")
                  .find("r.suite:8: validate takes yes, no or a number of points"),
              std::string::npos);
}

TEST(Retriangulation, GiftWrapGivesBowyerWatsonsTetrahedraWithNhApexTests) {
    const TinyRun run = run_suite("gw",
                                  "question q\nkind giftwrap\ndist cube sphere grid\n"
                                  "n.quick 60 150\nn.full 60\nseeds.quick 3\nseeds.full 3\n"
                                  "order brio\n");
    ASSERT_EQ(run.rows.size(), 6u);
    for (const Row& row : run.rows) {
        SCOPED_TRACE(row.at("dist") + " " + row.at("n"));
        EXPECT_EQ(row.at("same_tets"), "1");
        EXPECT_EQ(row.at("same_hull"), "1");
        // Each unfinished facet is taken once and tests every other point for being in front.
        const double n = value(row, "points");
        EXPECT_EQ(value(row, "facets_wrapped"),
                  value(row, "tets") - 1 + value(row, "hull_triangles"));
        EXPECT_LE(value(row, "apex_orient_tests"), value(row, "facets_wrapped") * n);
        EXPECT_GT(value(row, "apex_per_facet_per_n"), 0.9);
        EXPECT_GT(value(row, "gw_insphere_calls"), 0);
        EXPECT_GT(value(row, "bw_predicates"), 0);
        EXPECT_GT(value(row, "gw_over_bw_predicates"), 1);
    }
}

TEST(Retriangulation, DeletionEqualsRebuildAndRecordsEachDeletion) {
    const TinyRun run = run_suite("del",
                                  "question q\nkind deletion\ndist cube grid\n"
                                  "n.quick 200\nn.full 200\nseeds.quick 5\nseeds.full 5\n"
                                  "deletions.quick 25\n");
    ASSERT_EQ(run.rows.size(), 2u);
    ASSERT_EQ(run.j_rows.size(), 50u);
    for (const Row& row : run.rows) {
        SCOPED_TRACE(row.at("dist"));
        EXPECT_EQ(row.at("deletions"), "25");
        EXPECT_EQ(row.at("equal_rebuild"), "1");
        EXPECT_LT(value(row, "tets_after"), value(row, "tets_before"));
        EXPECT_GT(value(row, "mean_degree"), 3);
    }
    double created = 0;
    for (const Row& row : run.j_rows) {
        // An interior vertex has at least 4 neighbours (a hull corner may have 3, plus the ghost),
        // and gift-wrapping its cavity tests at most all of them per facet.
        EXPECT_GE(value(row, "degree"), row.at("hull") == "1" ? 3 : 4);
        EXPECT_GE(value(row, "star_tets"), 4);
        EXPECT_GT(value(row, "facets_wrapped"), 0);
        EXPECT_LE(value(row, "apex_orient_tests"),
                  value(row, "facets_wrapped") * value(row, "degree"));
        if (row.at("dist") == "cube") {
            created += value(row, "created");
        }
    }
    EXPECT_EQ(created, value(run.rows[0], "tets_created"));
}

TEST(Retriangulation, CdtPolygonsStayBelowPropositions55And56) {
    const TinyRun run = run_suite("cdt",
                                  "question q\nkind cdt\n"
                                  "dist hull-faces nested-boxes terrain voxel-grid\n"
                                  "n.quick 60 120\nn.full 60\n"
                                  "seeds.quick 2\nseeds.full 2\n");
    ASSERT_EQ(run.rows.size(), 8u);
    std::map<std::string, std::size_t> records;
    for (const Row& row : run.j_rows) {
        ++records[row.at("dist") + " " + row.at("n")];
        const double m = value(row, "m");
        EXPECT_EQ(row.at("flips_below_m2"), "1");
        EXPECT_LT(value(row, "flips"), std::max(m * m, 1.0));
    }
    for (const Row& row : run.rows) {
        const std::string name = row.at("dist") + " " + row.at("n");
        SCOPED_TRACE(name);
        EXPECT_EQ(row.at("valid"), "1");
        EXPECT_EQ(row.at("cdt_problems"), "0");
        const double n = value(row, "vertices");
        EXPECT_EQ(n, value(row, "points") + value(row, "protection_points"));
        EXPECT_LT(value(row, "flips"), n * n);
        EXPECT_EQ(value(row, "flips"),
                  value(row, "flips_23") + value(row, "flips_32") + value(row, "flips_14") +
                      value(row, "flips_41") + value(row, "flips_22") + value(row, "flips_44"));
        // One record per polygon, or none at all while the insertion does not keep them.
        if (row.at("polygon_records") != "0") {
            EXPECT_EQ(row.at("polygon_records"), row.at("polygons"));
            EXPECT_EQ(records[name], static_cast<std::size_t>(value(row, "polygons")));
            EXPECT_LT(value(row, "flips"), value(row, "sum_m2") + 1);
        }
    }
    // The nested boxes cut through the Delaunay triangulation of their points: something flips.
    std::size_t boxes = 0;
    for (const Row& row : run.rows) {
        if (row.at("dist") == "nested-boxes") {
            ++boxes;
            EXPECT_GT(value(row, "flips"), 0) << "n = " << row.at("n");
        }
    }
    EXPECT_EQ(boxes, 2u);
}

TEST(PlcFamilies, ValidReproducibleAndAboutNPoints) {
    for (const PlcFamily& family : plc_families()) {
        SCOPED_TRACE(std::string(family.name));
        const core::Plc a = make_plc_family(family.name, 300, 4);
        const core::Plc b = make_plc_family(family.name, 300, 4);
        ASSERT_EQ(a.points.size(), b.points.size());
        for (std::size_t i = 0; i < a.points.size(); ++i) {
            EXPECT_EQ(a.points.points[i].x, b.points.points[i].x);
            EXPECT_EQ(a.points.points[i].z, b.points.points[i].z);
        }
        EXPECT_GE(a.points.size(), 300u);
        EXPECT_LE(a.points.size(), 400u);
        ASSERT_FALSE(a.facets.empty());
        for (const core::PlcFacet& facet : a.facets) {
            ASSERT_EQ(facet.loops.size(), 1u);
            const auto& loop = facet.loops.front();
            ASSERT_GE(loop.size(), 3u);
            for (std::size_t k = 3; k < loop.size(); ++k) {
                const auto& p = a.points.points;
                EXPECT_EQ(predicates::orient3d(p[loop[0]], p[loop[1]], p[loop[2]], p[loop[k]]),
                          predicates::Sign::kZero);
            }
        }
        const core::Plc other_seed = make_plc_family(family.name, 300, 5);
        EXPECT_NE(other_seed.points.points.back().x + other_seed.points.points.back().y,
                  a.points.points.back().x + a.points.points.back().y);
    }
    EXPECT_THROW(make_plc_family("sponge", 300, 1), core::Error);
    EXPECT_THROW(make_plc_family("terrain", 5, 1), core::Error);
}

}  // namespace
}  // namespace cavity::experiments
