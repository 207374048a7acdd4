#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/perturbation/outer_halfspace.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/orient3d.h"
#include "point_sets.h"
#include "symbolic_oracle.h"

namespace cavity::perturbation::test {

namespace {

constexpr std::uint64_t kSeed = 0x5eed'0002;

constexpr std::uint32_t kKeyBound = 16;

/// A hull triangle v w x with the apex y of the solid tetrahedron x w v y behind it, and a point u.
struct GhostQuery {
    WeightedPoint3 v;
    WeightedPoint3 w;
    WeightedPoint3 x;
    WeightedPoint3 y;
    WeightedPoint3 u;
    Keys4 keys;
};

std::string describe(const GhostQuery& q) {
    std::ostringstream out;
    out.precision(17);
    const std::array<const WeightedPoint3*, 5> points = {&q.v, &q.w, &q.x, &q.y, &q.u};
    const char* names = "vwxyu";
    for (std::size_t i = 0; i < 5; ++i) {
        const WeightedPoint3& p = *points[i];
        out << names[i] << " (" << p.x << ", " << p.y << ", " << p.z << "; w " << p.w << ")";
        if (i != 3) {
            out << " key " << q.keys[i < 3 ? i : 3];
        }
        out << "\n";
    }
    return out.str();
}

SosVerdict weighted_test(const GhostQuery& q) {
    return outer_halfspace_weighted_sos_staged(q.v, q.w, q.x, q.y, q.u, q.keys);
}

SosVerdict unweighted_test(const GhostQuery& q) {
    return outer_halfspace_sos_staged(
        position(q.v), position(q.w), position(q.x), position(q.y), position(q.u), q.keys);
}

/// Orients v w x so that x w v y is positive (swapping v and x with their keys); false when v, w,
/// x, y are coplanar.
bool orient_behind(GhostQuery& q) {
    const Sign s = symbolic_orient3d(position(q.x), position(q.w), position(q.v), position(q.y));
    if (s == Sign::kNeg) {
        std::swap(q.v, q.x);
        std::swap(q.keys[0], q.keys[2]);
    }
    return s != Sign::kZero;
}

struct Tally {
    int queries = 0;
    std::array<int, 4> depths{};  // indexed by the number of cofactors
};

/// For u in the plane of vwx, the ghost test and the solid tetrahedron x w v y behind it see the
/// same degeneracy, and must agree whatever y's key: after a rigid motion (which keeps the lifted
/// determinant) that puts the plane at z = 0, expanding the 5x5 lifted determinant of x, w, v, y,
/// u along its z column leaves y's z times the 4x4 in-plane determinant, perturbation included.
void expect_agrees_with_solid_tetrahedron(const GhostQuery& q, bool weighted, Sign ghost) {
    for (const std::uint32_t y_key : {0u, 7u, 1000u}) {
        const Keys5 keys = {q.keys[2], q.keys[1], q.keys[0], y_key, q.keys[3]};
        if (std::count(keys.begin(), keys.end(), y_key) > 1) {
            continue;
        }
        const Sign solid = weighted ? orient4d_sos(q.x, q.w, q.v, q.y, q.u, keys)
                                    : insphere_sos(position(q.x),
                                                   position(q.w),
                                                   position(q.v),
                                                   position(q.y),
                                                   position(q.u),
                                                   keys);
        ASSERT_EQ(solid, ghost) << "y key " << y_key << "\n" << describe(q);
    }
}

/// Checks one query against the oracle, the never-zero guarantee and the invariance under a
/// cyclic rotation of the triangle.
void expect_matches_oracle(const GhostQuery& q, bool weighted, Tally& tally) {
    const SosVerdict verdict = weighted ? weighted_test(q) : unweighted_test(q);
    const WeightedPoint3 y = q.y;
    ASSERT_EQ(verdict.sign, symbolic_outer_halfspace(q.v, q.w, q.x, y, q.u, q.keys)) << describe(q);
    ASSERT_NE(verdict.sign, Sign::kZero) << describe(q);
    const GhostQuery rotated{q.w, q.x, q.v, q.y, q.u, {q.keys[1], q.keys[2], q.keys[0], q.keys[3]}};
    ASSERT_EQ((weighted ? weighted_test(rotated) : unweighted_test(rotated)).sign, verdict.sign)
        << describe(rotated);
    ++tally.queries;
    ++tally.depths[verdict.cofactors];
    if (symbolic_orient3d(position(q.v), position(q.w), position(q.x), position(q.u)) ==
        Sign::kZero) {
        ASSERT_NO_FATAL_FAILURE(expect_agrees_with_solid_tetrahedron(q, weighted, verdict.sign));
    }
}

/// Runs every triangle of `plane` (with the apex y behind it) against every other point of
/// `plane` and of `off_plane`.
void compare_all_triangles(const std::vector<WeightedPoint3>& plane,
                           const std::vector<WeightedPoint3>& off_plane,
                           const WeightedPoint3& y,
                           bool weighted,
                           std::mt19937_64& rng,
                           Tally& tally) {
    std::vector<WeightedPoint3> candidates = plane;
    candidates.insert(candidates.end(), off_plane.begin(), off_plane.end());
    for (std::size_t i = 0; i < plane.size(); ++i) {
        for (std::size_t j = i + 1; j < plane.size(); ++j) {
            for (std::size_t k = j + 1; k < plane.size(); ++k) {
                for (std::size_t m = 0; m < candidates.size(); ++m) {
                    if (m == i || m == j || m == k) {
                        continue;
                    }
                    GhostQuery q{plane[i],
                                 plane[j],
                                 plane[k],
                                 y,
                                 candidates[m],
                                 distinct_keys<4>(rng, kKeyBound)};
                    if (!orient_behind(q)) {
                        break;  // v, w, x collinear
                    }
                    ASSERT_NO_FATAL_FAILURE(expect_matches_oracle(q, weighted, tally));
                }
            }
        }
    }
}

std::vector<WeightedPoint3> unweighted(const std::vector<Point3>& points) {
    std::vector<WeightedPoint3> weighted;
    weighted.reserve(points.size());
    for (const Point3& p : points) {
        weighted.push_back(test::unweighted(p));
    }
    return weighted;
}

TEST(OuterHalfspaceSos, MatchesOracleOnACircleInAnAxisPlane) {
    std::mt19937_64 rng(kSeed);
    std::vector<Point3> plane;
    for (int s = -5; s <= 5; ++s) {
        for (int t = -5; t <= 5; ++t) {
            if (s * s + t * t == 25) {
                plane.push_back({double(s), double(t), 0});
            }
        }
    }
    ASSERT_EQ(plane.size(), 12u);
    plane.push_back({0, 0, 0});
    plane.push_back({4, 4, 0});
    const std::vector<WeightedPoint3> off_plane = unweighted({{0, 0, 1}, {2, 1, -1}});
    Tally tally;
    ASSERT_NO_FATAL_FAILURE(
        compare_all_triangles(unweighted(plane), off_plane, {1, 2, -3, 0}, false, rng, tally));
    EXPECT_GT(tally.depths[1], 1000);  // the circle: u on the circumcircle of 12 choose 3 triangles
    EXPECT_GT(tally.depths[0], 1000);
    EXPECT_EQ(tally.depths[2] + tally.depths[3], 0);  // no three cocircular points are collinear
}

TEST(OuterHalfspaceSos, MatchesOracleOnACircleInATiltedPlane) {
    std::mt19937_64 rng(kSeed + 1);
    // The plane x + y + z = 3 meets the sphere x^2 + y^2 + z^2 = 9 in a circle through six
    // integer points; (1, 1, 1) is its centre.
    const std::vector<Point3> plane = {
        {3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {2, 2, -1}, {2, -1, 2}, {-1, 2, 2}, {1, 1, 1}, {4, -1, 0}};
    const std::vector<WeightedPoint3> off_plane = unweighted({{1, 1, 0}, {2, 2, 2}});
    Tally tally;
    for (const WeightedPoint3& y : {WeightedPoint3{0, 0, 0, 0}, WeightedPoint3{3, 3, 3, 0}}) {
        ASSERT_NO_FATAL_FAILURE(
            compare_all_triangles(unweighted(plane), off_plane, y, false, rng, tally));
    }
    EXPECT_GT(tally.depths[1], 100);
}

TEST(OuterHalfspaceSos, MatchesOracleOnAGridFace) {
    std::mt19937_64 rng(kSeed + 2);
    std::vector<Point3> plane;
    for (int s = 0; s < 4; ++s) {
        for (int t = 0; t < 3; ++t) {
            plane.push_back({double(s), 1, double(t)});
        }
    }
    Tally tally;
    ASSERT_NO_FATAL_FAILURE(compare_all_triangles(
        unweighted(plane), unweighted({{1, 2, 1}}), {2, 0, 1, 0}, false, rng, tally));
    EXPECT_GT(tally.depths[1], 100);
}

TEST(OuterHalfspaceWeightedSos, MatchesOracleOnCoplanarLifts) {
    std::mt19937_64 rng(kSeed + 3);
    std::vector<Point3> plane;
    for (int s = -1; s <= 1; ++s) {
        for (int t = -1; t <= 1; ++t) {
            plane.push_back({double(s), double(t), double(s + t)});
        }
    }
    plane.push_back({2, 0, 2});
    Tally tally;
    std::uniform_int_distribution<int> coefficient(-3, 3);
    for (int round = 0; round < 5; ++round) {
        std::vector<WeightedPoint3> lifted = on_hyperplane(
            plane, {coefficient(rng), coefficient(rng), coefficient(rng)}, coefficient(rng));
        if (round % 4 == 3) {
            lifted[static_cast<std::size_t>(round) % lifted.size()].w += 1;
        }
        const std::vector<WeightedPoint3> off_plane = {{0, 0, 1, 2}, {1, -1, -3, 0}};
        ASSERT_NO_FATAL_FAILURE(
            compare_all_triangles(lifted, off_plane, {0, 1, -2, 5}, true, rng, tally));
    }
    EXPECT_GT(tally.depths[1], 500);
    EXPECT_GT(tally.depths[2], 50);  // u on an edge line of vwx
}

// Each path of the test: in front or behind (orient3d alone), inside or outside the circumdisk
// (the disk test alone), on the circumcircle (one cofactor), and a weighted u on an edge line
// whose cofactor vanishes (two cofactors).
TEST(OuterHalfspaceSos, CascadeStopsAtEachDepth) {
    const Point3 v{0, 0, 0};
    const Point3 w{2, 0, 0};
    const Point3 x{0, 2, 0};
    const Point3 y{0, 0, 1};  // x w v y is positive: vwx faces -z
    ASSERT_EQ(symbolic_orient3d(x, w, v, y), Sign::kPos);
    const Keys4 keys = {0, 1, 2, 3};

    const SosVerdict front = outer_halfspace_sos_staged(v, w, x, y, {1, 1, -1}, keys);
    EXPECT_EQ(front.sign, Sign::kPos);
    EXPECT_EQ(front.cofactors, 0);
    EXPECT_EQ(front.stage, predicates::orient3d_staged(v, w, x, {1, 1, -1}).stage);
    EXPECT_EQ(outer_halfspace_sos(v, w, x, y, {1, 1, 1}, keys), Sign::kNeg);

    const SosVerdict inside = outer_halfspace_sos_staged(v, w, x, y, {1, 0.5, 0}, keys);
    EXPECT_EQ(inside.sign, Sign::kPos);
    EXPECT_EQ(inside.cofactors, 0);
    EXPECT_EQ(outer_halfspace_sos(v, w, x, y, {3, 3, 0}, keys), Sign::kNeg);

    // (2, 2) is on the circumcircle of the right triangle; v's key is lowest and decides.
    const SosVerdict tie = outer_halfspace_sos_staged(v, w, x, y, {2, 2, 0}, keys);
    EXPECT_EQ(tie.cofactors, 1);
    EXPECT_EQ(tie.sign,
              symbolic_outer_halfspace(test::unweighted(v),
                                       test::unweighted(w),
                                       test::unweighted(x),
                                       test::unweighted(y),
                                       {2, 2, 0, 0},
                                       keys));
    // With u's own key lowest, lowering u's height puts it inside.
    EXPECT_EQ(outer_halfspace_sos(v, w, x, y, {2, 2, 0}, {1, 2, 3, 0}), Sign::kPos);

    // All heights on h = 0, u = (1, 0) on the line of v and w; x first: o(v, w, u) = 0.
    const std::vector<WeightedPoint3> p = on_hyperplane({v, w, x, y, {1, 0, 0}}, {0, 0, 0}, 0);
    const Keys4 x_first = {1, 2, 0, 3};
    const SosVerdict collinear =
        outer_halfspace_weighted_sos_staged(p[0], p[1], p[2], p[3], p[4], x_first);
    EXPECT_EQ(collinear.cofactors, 2);
    EXPECT_EQ(collinear.sign, symbolic_outer_halfspace(p[0], p[1], p[2], p[3], p[4], x_first));
}

/// The triangles of a planar point set that no other point of it is in conflict with, for
/// the given apex y below the plane, as sorted index triples.
std::set<std::array<std::size_t, 3>> hull_triangles(const std::vector<Point3>& face,
                                                    const std::vector<std::uint32_t>& keys,
                                                    const Point3& y,
                                                    bool use_oracle) {
    std::set<std::array<std::size_t, 3>> triangles;
    const std::size_t n = face.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                std::array<std::size_t, 3> t = {i, j, k};
                const Sign s = symbolic_orient3d(face[k], face[j], face[i], y);
                if (s == Sign::kZero) {
                    continue;
                }
                if (s == Sign::kNeg) {
                    std::swap(t[0], t[2]);
                }
                bool empty = true;
                for (std::size_t m = 0; m < n && empty; ++m) {
                    if (m == i || m == j || m == k) {
                        continue;
                    }
                    const Keys4 q = {keys[t[0]], keys[t[1]], keys[t[2]], keys[m]};
                    const Sign conflict =
                        use_oracle ? symbolic_outer_halfspace(test::unweighted(face[t[0]]),
                                                              test::unweighted(face[t[1]]),
                                                              test::unweighted(face[t[2]]),
                                                              test::unweighted(y),
                                                              test::unweighted(face[m]),
                                                              q)
                                   : outer_halfspace_sos(
                                         face[t[0]], face[t[1]], face[t[2]], y, face[m], q);
                    EXPECT_NE(conflict, Sign::kZero);
                    empty = conflict == Sign::kNeg;
                }
                if (empty) {
                    triangles.insert({i, j, k});
                }
            }
        }
    }
    return triangles;
}

/// Twice the signed area of the projection of pqr onto the xy-plane.
double doubled_area(const Point3& p, const Point3& q, const Point3& r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

// The 3x3 grid on the top face of the cube [0, 2]^3 is a flat hull face full of ties (the corners
// of each unit square, and of the whole face, are cocircular). The perturbed test must break them
// into one triangulation, the 2D perturbed Delaunay triangulation, whatever apex lies behind it.
TEST(OuterHalfspaceSos, FlatHullFaceIsThePerturbedDelaunayTriangulation) {
    std::vector<Point3> face;
    for (int s = 0; s <= 2; ++s) {
        for (int t = 0; t <= 2; ++t) {
            face.push_back({double(s), double(t), 2});
        }
    }
    std::mt19937_64 rng(kSeed + 4);
    std::vector<std::uint32_t> keys(face.size());
    for (int round = 0; round < 40; ++round) {
        const std::array<std::uint32_t, 9> drawn = distinct_keys<9>(rng, kKeyBound);
        std::copy(drawn.begin(), drawn.end(), keys.begin());
        const auto triangles = hull_triangles(face, keys, {1, 1, 1}, false);
        ASSERT_EQ(triangles.size(), 8u);
        // Generic sample points (off every grid line and diagonal) lie in exactly one triangle.
        for (int s = 0; s < 2; ++s) {
            for (int t = 0; t < 2; ++t) {
                for (const auto& [ds, dt] :
                     {std::pair{0.1, 0.3}, {0.3, 0.1}, {0.8, 0.6}, {0.6, 0.8}}) {
                    const Point3 sample{s + ds, t + dt, 2};
                    int covering = 0;
                    for (const auto& tri : triangles) {
                        const Point3& a = face[tri[0]];
                        const Point3& b = face[tri[1]];
                        const Point3& c = face[tri[2]];
                        const double orientation = doubled_area(a, b, c);
                        const bool inside = doubled_area(a, b, sample) * orientation > 0 &&
                                            doubled_area(b, c, sample) * orientation > 0 &&
                                            doubled_area(c, a, sample) * orientation > 0;
                        covering += inside ? 1 : 0;
                    }
                    ASSERT_EQ(covering, 1) << "round " << round;
                }
            }
        }
        // y only orients the plane: another apex behind the face gives the same triangles.
        ASSERT_EQ(hull_triangles(face, keys, {0, 2, 0}, false), triangles);
        if (round < 6) {
            ASSERT_EQ(hull_triangles(face, keys, {1, 1, 1}, true), triangles);
        }
    }
}

}  // namespace

}  // namespace cavity::perturbation::test
