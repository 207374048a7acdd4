// Inputs with no 3D triangulation get an Error naming why (the affine dimension).

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/live/triangulate.h"

namespace cavity::test {
namespace {

std::string error_of(const std::vector<predicates::Point3>& points) {
    core::PointSet set;
    set.points = points;
    std::vector<std::uint32_t> sequence(points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    try {
        core::triangulate(set, sequence, core::TriangulateOptions{});
    } catch (const core::Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(Errors, CoplanarNamesDimensionTwo) {
    const std::vector<predicates::Point3> points{
        {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 5, 0}, {0.1, 0.3, 0}};
    EXPECT_NE(error_of(points).find("affine dimension 2"), std::string::npos) << error_of(points);
}

TEST(Errors, TiltedCoplanarNamesDimensionTwo) {
    std::vector<predicates::Point3> points;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            points.push_back({double(i), double(j), double(i + 2 * j)});  // the plane z = x + 2y
        }
    }
    EXPECT_NE(error_of(points).find("affine dimension 2"), std::string::npos) << error_of(points);
}

TEST(Errors, CollinearNamesDimensionOne) {
    std::vector<predicates::Point3> points;
    points.reserve(8);
    for (int t = 0; t < 8; ++t) {
        points.push_back({double(t), double(2 * t), double(3 * t)});
    }
    EXPECT_NE(error_of(points).find("affine dimension 1"), std::string::npos) << error_of(points);
}

TEST(Errors, FewerThanFourDistinctPoints) {
    const std::vector<predicates::Point3> points{
        {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {-0.0, 0, 0}};
    EXPECT_NE(error_of(points).find("fewer than 4 distinct points"), std::string::npos)
        << error_of(points);
    EXPECT_NE(error_of({}).find("no points"), std::string::npos);
}

TEST(Errors, SequenceMustCoverThePoints) {
    core::PointSet set;
    set.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<std::uint32_t> sequence{0, 1, 2};
    EXPECT_THROW(core::triangulate(set, sequence, core::TriangulateOptions{}), core::Error);
}

TEST(Errors, NonFiniteCoordinatesNameThePoint) {
    for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        std::vector<predicates::Point3> points{
            {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
        points[3].y = bad;
        EXPECT_NE(error_of(points).find("point 3 has a non-finite"), std::string::npos)
            << error_of(points);
    }
}

TEST(Errors, SequenceMustBeAPermutation) {
    core::PointSet set;
    set.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<std::uint32_t> repeated{0, 1, 2, 2};
    EXPECT_THROW(core::triangulate(set, repeated, core::TriangulateOptions{}), core::Error);
    const std::vector<std::uint32_t> outside{0, 1, 2, 7};
    EXPECT_THROW(core::triangulate(set, outside, core::TriangulateOptions{}), core::Error);
    set.weights = {0.0, 1.0};
    const std::vector<std::uint32_t> identity{0, 1, 2, 3};
    EXPECT_THROW(core::triangulate(set, identity, core::TriangulateOptions{}), core::Error);
}

// The three tiers of checks report a broken invariant as an internal error (exit 4, Python's
// RuntimeError), with the file and line; the expensive tier runs only where it was built in.
TEST(Assertions, AFailedAssertionIsAnInternalErrorWithItsPlace) {
    try {
        CAVITY_ASSERT(1 + 1 == 3, "arithmetic");
        ADD_FAILURE() << "a false assertion passed";
    } catch (const core::Error& e) {
        EXPECT_EQ(e.kind(), core::ErrorKind::kInternal);
        const std::string message = e.what();
        EXPECT_NE(message.find("test_errors.cpp:"), std::string::npos) << message;
        EXPECT_NE(message.find("arithmetic (1 + 1 == 3)"), std::string::npos) << message;
    }
    CAVITY_ASSERT(1 + 1 == 2, "arithmetic");
}

TEST(Assertions, ExpensiveChecksRunOnlyWhereBuiltIn) {
    int evaluated = 0;
    const auto problems = [&] {
        ++evaluated;
        return std::vector<std::string>{"a tetrahedron glued to itself"};
    };
    bool thrown = false;
    try {
        CAVITY_EXPENSIVE_CHECK(problems(), "the complex");
    } catch (const core::Error& e) {
        thrown = true;
        EXPECT_EQ(e.kind(), core::ErrorKind::kInternal);
        EXPECT_NE(std::string(e.what()).find("a tetrahedron glued to itself"), std::string::npos);
    }
#if defined(CAVITY_EXPENSIVE_CHECKS) && CAVITY_EXPENSIVE_CHECKS
    EXPECT_TRUE(thrown);
    EXPECT_EQ(evaluated, 1);
#else
    (void)problems;
    EXPECT_FALSE(thrown);
    EXPECT_EQ(evaluated, 0);  // not even evaluated: a release build pays nothing
#endif
}

}  // namespace
}  // namespace cavity::test
