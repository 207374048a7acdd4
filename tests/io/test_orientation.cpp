#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/error.h"
#include "cavity/core/orientation.h"

namespace cavity::core {
namespace {

// The unit tetrahedron o, x, y, z has volume +1/6 by the right-hand rule, and a fifth point in the
// plane z = 0 makes a flat one.
PointSet corner() {
    PointSet set;
    set.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    return set;
}

TEST(Orientation, CountsByRightHandVolume) {
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {1, 0, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 9}};
    const OrientationCount count = count_orientations(corner(), tets);
    EXPECT_EQ(count.positive, 1u);
    EXPECT_EQ(count.negative, 1u);
    EXPECT_EQ(count.flat, 1u);  // the out-of-range one is left to the validator
}

TEST(Orientation, PositiveFilesBecomeTheEngineOrientation) {
    const std::vector<Tet> file = {{0, 1, 2, 3}};
    const std::vector<Tet> engine = engine_orientation_from_file("m.ele", corner(), file);
    ASSERT_EQ(engine.size(), 1u);
    EXPECT_EQ(engine[0], swap_handedness(file[0]));
    EXPECT_EQ(count_orientations(corner(), engine).negative, 1u);
}

TEST(Orientation, AnInvertedMeshIsRefusedByName) {
    const std::vector<Tet> file = {{1, 0, 2, 3}, {0, 1, 2, 4}};
    try {
        engine_orientation_from_file("m.ele", corner(), file);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("m.ele"), std::string::npos) << what;
        EXPECT_NE(what.find("all 1 non-flat tetrahedra have negative volume"), std::string::npos)
            << what;
    }
}

TEST(Orientation, AMixedMeshIsLeftToTheValidator) {
    const std::vector<Tet> file = {{0, 1, 2, 3}, {1, 0, 2, 3}};
    EXPECT_EQ(engine_orientation_from_file("m.ele", corner(), file).size(), 2u);
}

}  // namespace
}  // namespace cavity::core
