// The hard orient3d and insphere cases of Nanevski, Blelloch and Harper (2001), read from the
// shared fixtures folder (CAVITY_FIXTURES_DIR/nanevski), never copied into the repository. Skipped
// when the folder is absent.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "query.h"

namespace cavity::predicates::testing {

namespace {

Query parse_query(const std::string& line) {
    std::istringstream in(line);
    std::string name;
    in >> name;
    Query q{name == "insphere" ? Kind::kInsphere : Kind::kOrient3d};
    EXPECT_TRUE(name == "insphere" || name == "orient3d") << line;
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        std::string token;
        in >> token;
        q.v[i] = std::strtod(token.c_str(), nullptr);
    }
    return q;
}

TEST(NanevskiFixtures, EveryEvaluationGivesTheExpectedSign) {
    const std::filesystem::path dir = std::filesystem::path(CAVITY_FIXTURES_DIR) / "nanevski";
    std::ifstream queries(dir / "queries.txt");
    std::ifstream expected(dir / "expected.txt");
    if (!queries || !expected) {
        GTEST_SKIP() << "fixtures not found in " << dir;
    }
    std::string line;
    std::string sign;
    int line_number = 0;
    int failures = 0;
    while (std::getline(queries, line)) {
        ++line_number;
        ASSERT_TRUE(std::getline(expected, sign))
            << "expected.txt ends before line " << line_number;
        const Query q = parse_query(line);
        const auto want = static_cast<Sign>(std::stoi(sign));
        const Signs got = evaluate(q);
        const Sign exact = evaluate_oracle(q);
        if ((got.fast != want || got.staged != want || exact != want) && ++failures <= 10) {
            ADD_FAILURE() << "queries.txt:" << line_number << ": expected " << to_int(want)
                          << ", plain " << to_int(got.fast) << ", staged " << to_int(got.staged)
                          << ", oracle " << to_int(exact) << "\n  replay: " << to_line(q);
        }
    }
    EXPECT_EQ(line_number, 2000);
    EXPECT_EQ(failures, 0);
}

}  // namespace

}  // namespace cavity::predicates::testing
