#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/perturbation/sos.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"
#include "point_sets.h"
#include "symbolic_oracle.h"

namespace cavity::perturbation::test {

namespace {

constexpr std::uint64_t kSeed = 0x5eed'0001;

/// Keys below this bound keep the oracle's polynomials small.
constexpr std::uint32_t kKeyBound = 16;

using Points5 = std::array<WeightedPoint3, 5>;

std::string describe(const Points5& p, const Keys5& keys) {
    std::ostringstream out;
    out.precision(17);
    for (std::size_t i = 0; i < 5; ++i) {
        out << "(" << p[i].x << ", " << p[i].y << ", " << p[i].z << "; w " << p[i].w << ") key "
            << keys[i] << "\n";
    }
    return out.str();
}

SosVerdict insphere_of(const Points5& p, const Keys5& keys) {
    return insphere_sos_staged(
        position(p[0]), position(p[1]), position(p[2]), position(p[3]), position(p[4]), keys);
}

SosVerdict orient4d_of(const Points5& p, const Keys5& keys) {
    return orient4d_sos_staged(p[0], p[1], p[2], p[3], p[4], keys);
}

bool is_flat(const Points5& p) {
    return symbolic_orient3d(position(p[0]), position(p[1]), position(p[2]), position(p[3])) ==
           Sign::kZero;
}

/// Tallies of a batch of oracle comparisons, to check that the batch exercised the perturbation.
struct Tally {
    int ties = 0;
    std::array<int, 3> tie_signs{};  // indexed by sign + 1
    std::array<int, 6> depths{};     // indexed by the number of cofactors, non-flat cases only

    void add(const SosVerdict& v, bool flat) {
        if (v.cofactors > 0) {
            ++ties;
            const int slot = to_int(v.sign) + 1;  // -1, 0, +1 -> 0, 1, 2
            ++tie_signs[static_cast<std::size_t>(slot)];
        }
        if (!flat) {
            ++depths[v.cofactors];
        }
    }
};

/// Compares one perturbed predicate with the oracle; also checks the guarantee of never kZero when
/// the reference tetrahedron a, b, c, d is not flat.
void expect_matches_oracle(const SosVerdict& verdict,
                           const Points5& p,
                           const Keys5& keys,
                           Tally& tally) {
    ASSERT_EQ(verdict.sign, symbolic_lifted(p, keys)) << describe(p, keys);
    const bool flat = is_flat(p);
    if (!flat) {
        ASSERT_NE(verdict.sign, Sign::kZero) << describe(p, keys);
    }
    tally.add(verdict, flat);
}

Points5 pick(const std::vector<WeightedPoint3>& set, const std::array<std::size_t, 5>& index) {
    return {set[index[0]], set[index[1]], set[index[2]], set[index[3]], set[index[4]]};
}

std::vector<WeightedPoint3> unweighted(const std::vector<Point3>& points) {
    std::vector<WeightedPoint3> weighted;
    weighted.reserve(points.size());
    for (const Point3& p : points) {
        weighted.push_back(test::unweighted(p));
    }
    return weighted;
}

int permutation_parity(const std::array<std::size_t, 5>& perm) {
    int inversions = 0;
    for (std::size_t i = 0; i < 5; ++i) {
        for (std::size_t j = i + 1; j < 5; ++j) {
            inversions += perm[i] > perm[j] ? 1 : 0;
        }
    }
    return inversions % 2 == 0 ? 1 : -1;
}

TEST(InsphereSos, MatchesOracleOnEveryTupleOfCubeCorners) {
    std::mt19937_64 rng(kSeed);
    const std::vector<WeightedPoint3> corners = unweighted(cube_corners());
    Tally tally;
    std::array<std::size_t, 5> index{};
    for (index[0] = 0; index[0] < 8; ++index[0]) {
        for (index[1] = 0; index[1] < 8; ++index[1]) {
            for (index[2] = 0; index[2] < 8; ++index[2]) {
                for (index[3] = 0; index[3] < 8; ++index[3]) {
                    for (index[4] = 0; index[4] < 8; ++index[4]) {
                        std::array<std::size_t, 5> sorted = index;
                        std::sort(sorted.begin(), sorted.end());
                        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
                            continue;
                        }
                        const Points5 p = pick(corners, index);
                        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
                        ASSERT_NO_FATAL_FAILURE(
                            expect_matches_oracle(insphere_of(p, keys), p, keys, tally));
                    }
                }
            }
        }
    }
    EXPECT_EQ(tally.ties, 6720);  // all eight corners are cospherical
    EXPECT_GT(tally.tie_signs[0], 0);
    EXPECT_GT(tally.tie_signs[2], 0);
    EXPECT_EQ(tally.tie_signs[1], 0);  // no five corners are coplanar
    EXPECT_GT(tally.depths[2], 0);
    EXPECT_EQ(tally.depths[3] + tally.depths[4] + tally.depths[5], 0);
}

TEST(InsphereSos, MatchesOracleOnCosphericalIntegerPoints) {
    std::mt19937_64 rng(kSeed + 1);
    const std::vector<WeightedPoint3> sphere = unweighted(sphere_points(9));
    ASSERT_EQ(sphere.size(), 30u);
    Tally tally;
    for (int trial = 0; trial < 1500; ++trial) {
        const Points5 p = pick(sphere, distinct_indices<5>(rng, sphere.size()));
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        ASSERT_NO_FATAL_FAILURE(expect_matches_oracle(insphere_of(p, keys), p, keys, tally));
    }
    EXPECT_EQ(tally.ties, 1500);
    EXPECT_GT(tally.depths[2], 0);
    // Two vanishing cofactors of a non-flat tetrahedron put e on an edge line, which meets the
    // sphere only at the edge's endpoints.
    EXPECT_EQ(tally.depths[3] + tally.depths[4] + tally.depths[5], 0);
}

TEST(InsphereSos, MatchesOracleOnGridPoints) {
    std::mt19937_64 rng(kSeed + 2);
    const std::vector<WeightedPoint3> points = unweighted(grid(0, 2));
    Tally tally;
    for (int trial = 0; trial < 2000; ++trial) {
        const Points5 p = pick(points, distinct_indices<5>(rng, points.size()));
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        ASSERT_NO_FATAL_FAILURE(expect_matches_oracle(insphere_of(p, keys), p, keys, tally));
    }
    EXPECT_GT(tally.ties, 50);
    EXPECT_GT(tally.depths[0], 500);
}

// The lattice tie-break (plain cofactors, for grids) against the oracle, and its cofactor count
// against the staged tie-break's, on every exact tie among random tuples of a coarse grid spanning
// the lattice bound (715, predicates/lattice.h), where the cofactors' intermediates are largest.
TEST(InsphereSos, LatticeTieBreakMatchesOracle) {
    std::mt19937_64 rng(kSeed + 9);
    std::vector<Point3> points = grid(0, 5);
    for (Point3& q : points) {
        q = {143 * q.x, 143 * q.y, 143 * q.z};
    }
    int ties = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const auto i = distinct_indices<5>(rng, points.size());
        const Point3 &a = points[i[0]], &b = points[i[1]], &c = points[i[2]], &d = points[i[3]],
                     &e = points[i[4]];
        if (symbolic_orient3d(a, b, c, d) == Sign::kZero ||
            predicates::insphere(a, b, c, d, e) != Sign::kZero) {
            continue;  // only exact ties of non-flat tetrahedra reach the tie-break
        }
        ++ties;
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        const Points5 p{test::unweighted(a),
                        test::unweighted(b),
                        test::unweighted(c),
                        test::unweighted(d),
                        test::unweighted(e)};
        const Sign sign = symbolic_lifted(p, keys);
        ASSERT_EQ(detail::sos_tie_on_lattice(a, b, c, d, e, keys), sign) << describe(p, keys);
        // The counting engine's lattice route: the same sign, and the staged route's count.
        const detail::SosTie tie = detail::sos_tie_on_lattice_counted(a, b, c, d, e, keys);
        ASSERT_EQ(tie.sign, sign) << describe(p, keys);
        ASSERT_EQ(tie.cofactors, detail::sos_tie_counted(a, b, c, d, e, keys).cofactors)
            << describe(p, keys);
    }
    EXPECT_GT(ties, 100);
}

TEST(Orient4dSos, MatchesOracleOnCohyperplanarLifts) {
    std::mt19937_64 rng(kSeed + 3);
    const std::vector<Point3> points = grid(-1, 1);
    std::uniform_int_distribution<int> coefficient(-3, 3);
    Tally tally;
    for (int trial = 0; trial < 1500; ++trial) {
        const std::vector<WeightedPoint3> lifted = on_hyperplane(
            points, {coefficient(rng), coefficient(rng), coefficient(rng)}, coefficient(rng));
        Points5 p = pick(lifted, distinct_indices<5>(rng, lifted.size()));
        if (trial % 4 == 0) {
            p[trial / 4 % 5].w += coefficient(rng);  // off the hyperplane: usually no tie
        }
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        ASSERT_NO_FATAL_FAILURE(expect_matches_oracle(orient4d_of(p, keys), p, keys, tally));
    }
    EXPECT_GT(tally.ties, 900);
    EXPECT_GT(tally.depths[0], 100);
    EXPECT_GT(tally.depths[3], 0);  // collinear weighted points need a third cofactor
}

TEST(Orient4dSos, MatchesOracleWithCollinearWeightedPoints) {
    std::mt19937_64 rng(kSeed + 4);
    // Five points of one line and points off it: many cofactors vanish.
    std::vector<Point3> points;
    for (int t = -2; t <= 2; ++t) {
        points.push_back({double(t), double(2 * t), double(-t)});
    }
    points.push_back({1, 0, 0});
    points.push_back({0, 0, 1});
    points.push_back({0, 1, 1});
    const std::vector<WeightedPoint3> lifted = on_hyperplane(points, {1, -2, 0}, 3);
    Tally tally;
    for (int trial = 0; trial < 1000; ++trial) {
        const Points5 p = pick(lifted, distinct_indices<5>(rng, lifted.size()));
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        ASSERT_NO_FATAL_FAILURE(expect_matches_oracle(orient4d_of(p, keys), p, keys, tally));
    }
    EXPECT_EQ(tally.ties, 1000);
    EXPECT_GT(tally.tie_signs[1], 0);  // five points with four on the line: nothing decides
    EXPECT_GT(tally.depths[3], 0);
}

/// Calls visit(i, j, k, l, m) for every 5-subset i < j < k < l < m of n points.
template <class Visit>
void for_each_5_subset(std::size_t n, Visit visit) {
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                for (std::size_t l = k + 1; l < n; ++l) {
                    for (std::size_t m = l + 1; m < n; ++m) {
                        visit(std::array{i, j, k, l, m});
                    }
                }
            }
        }
    }
}

// Every 5-subset of the 3x3x3 grid, unweighted and with all lifts on one hyperplane (so that
// every power test ties): never zero on a non-flat tetrahedron, and the cascade never needs more
// cofactors than the bounds derived in sos.cpp (two cospherical, three weighted).
TEST(PerturbedLiftedSign, NeverZeroOnNonFlatTetrahedraOfTheGrid) {
    std::mt19937_64 rng(kSeed + 9);
    const std::vector<Point3> points = grid(-1, 1);
    const std::vector<WeightedPoint3> lifted = on_hyperplane(points, {1, -1, 2}, 1);
    int non_flat = 0;
    std::array<int, 6> insphere_depths{};
    std::array<int, 6> orient4d_depths{};
    for_each_5_subset(points.size(), [&](const std::array<std::size_t, 5>& index) {
        const Points5 p = pick(lifted, index);
        if (predicates::orient3d(position(p[0]), position(p[1]), position(p[2]), position(p[3])) ==
            Sign::kZero) {
            return;
        }
        ++non_flat;
        const Keys5 keys = distinct_keys<5>(rng, 1000);
        const SosVerdict unweighted = insphere_of(p, keys);
        const SosVerdict weighted = orient4d_of(p, keys);
        EXPECT_NE(unweighted.sign, Sign::kZero) << describe(p, keys);
        EXPECT_NE(weighted.sign, Sign::kZero) << describe(p, keys);
        ++insphere_depths[unweighted.cofactors];
        ++orient4d_depths[weighted.cofactors];
    });
    EXPECT_GT(non_flat, 50000);
    EXPECT_GT(insphere_depths[2], 0);
    EXPECT_EQ(insphere_depths[3] + insphere_depths[4] + insphere_depths[5], 0);
    EXPECT_EQ(orient4d_depths[0], 0);
    EXPECT_GT(orient4d_depths[3], 0);
    EXPECT_EQ(orient4d_depths[4] + orient4d_depths[5], 0);
}

TEST(Orient4dSos, EqualWeightsGiveInsphereSos) {
    std::mt19937_64 rng(kSeed + 5);
    const std::vector<Point3> points = sphere_points(9);
    int ties = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const std::array<std::size_t, 5> index = distinct_indices<5>(rng, points.size());
        const Keys5 keys = distinct_keys<5>(rng, 1u << 20);
        const double weight = std::array{0.0, 0.5, 3.0, -7.25}[trial % 4];
        Points5 p{};
        for (std::size_t i = 0; i < 5; ++i) {
            const Point3& q = points[index[i]];
            p[i] = {q.x, q.y, q.z, weight};
        }
        const SosVerdict unweighted = insphere_of(p, keys);
        ASSERT_EQ(orient4d_of(p, keys).sign, unweighted.sign) << describe(p, keys);
        ties += unweighted.cofactors > 0 ? 1 : 0;
    }
    EXPECT_EQ(ties, 3000);
}

TEST(PerturbedLiftedSign, FlipsUnderOddPermutationsOfPointsAndKeys) {
    std::mt19937_64 rng(kSeed + 6);
    const std::vector<WeightedPoint3> sphere = unweighted(sphere_points(9));
    const std::vector<WeightedPoint3> lifted = on_hyperplane(grid(-1, 1), {1, 0, -1}, 2);
    for (int trial = 0; trial < 60; ++trial) {
        const std::vector<WeightedPoint3>& set = trial % 2 == 0 ? sphere : lifted;
        const Points5 p = pick(set, distinct_indices<5>(rng, set.size()));
        const Keys5 keys = distinct_keys<5>(rng, 1000);
        const Sign insphere_reference = insphere_of(p, keys).sign;
        const Sign orient4d_reference = orient4d_of(p, keys).sign;
        std::array<std::size_t, 5> perm = {0, 1, 2, 3, 4};
        do {
            Points5 q{};
            Keys5 k{};
            for (std::size_t i = 0; i < 5; ++i) {
                q[i] = p[perm[i]];
                k[i] = keys[perm[i]];
            }
            const int parity = permutation_parity(perm);
            ASSERT_EQ(to_int(insphere_of(q, k).sign), parity * to_int(insphere_reference))
                << describe(q, k);
            ASSERT_EQ(to_int(orient4d_of(q, k).sign), parity * to_int(orient4d_reference))
                << describe(q, k);
        } while (std::next_permutation(perm.begin(), perm.end()));
    }
}

TEST(PerturbedLiftedSign, DependsOnlyOnTheOrderOfTheKeys) {
    std::mt19937_64 rng(kSeed + 7);
    const std::vector<WeightedPoint3> lifted = on_hyperplane(grid(-1, 1), {0, 2, 1}, -1);
    for (int trial = 0; trial < 500; ++trial) {
        const Points5 p = pick(lifted, distinct_indices<5>(rng, lifted.size()));
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        Keys5 spread{};
        for (std::size_t i = 0; i < 5; ++i) {
            spread[i] = 0xFFFF'FF00u + keys[i] * 8u;  // monotone, near the top of the range
        }
        ASSERT_EQ(orient4d_of(p, spread).sign, orient4d_of(p, keys).sign) << describe(p, keys);
    }
}

// The cascade stops at each possible depth: the exact predicate alone (0), the first cofactor
// (1), a second one when four points are cocircular (2), and a third when a weighted point lies on
// an edge line of the reference tetrahedron (3).
TEST(PerturbedLiftedSign, CascadeStopsAtEachDepth) {
    const Point3 a{0, 0, 0};
    const Point3 b{1, 0, 0};
    const Point3 c{0, 1, 0};
    const Point3 d{0, 0, 1};
    // abcd is negatively oriented in Shewchuk's convention; swap to make it positive.
    ASSERT_EQ(symbolic_orient3d(b, a, c, d), Sign::kPos);

    const SosVerdict inside = insphere_sos_staged(b, a, c, d, {0.25, 0.25, 0.25}, {0, 1, 2, 3, 4});
    EXPECT_EQ(inside.sign, Sign::kPos);
    EXPECT_EQ(inside.cofactors, 0);
    EXPECT_EQ(inside.stage, predicates::insphere_staged(b, a, c, d, {0.25, 0.25, 0.25}).stage);

    // (1, 1, 1) is on the circumsphere of the corner tetrahedron; its own key is lowest, so its
    // cofactor orient3d(b, a, c, d) > 0 decides at once: e is inside.
    const Point3 e{1, 1, 1};
    const SosVerdict first = insphere_sos_staged(b, a, c, d, e, {1, 2, 3, 4, 0});
    EXPECT_EQ(first.sign, Sign::kPos);
    EXPECT_EQ(first.cofactors, 1);

    // Four corners of the top face are cocircular: with the bottom corner first, its cofactor
    // vanishes and the next one decides.
    const Point3 t0{0, 0, 1};
    const Point3 t1{1, 0, 1};
    const Point3 t2{1, 1, 1};
    const Point3 t3{0, 1, 1};
    const Keys5 bottom_first = {0, 1, 2, 3, 4};
    const SosVerdict second = insphere_sos_staged(a, t0, t1, t2, t3, bottom_first);
    EXPECT_NE(second.sign, Sign::kZero);
    EXPECT_EQ(second.cofactors, 2);
    EXPECT_EQ(second.sign,
              symbolic_lifted({test::unweighted(a),
                               test::unweighted(t0),
                               test::unweighted(t1),
                               test::unweighted(t2),
                               test::unweighted(t3)},
                              bottom_first));

    // All points lifted onto h = 0; e = (0, 0, 1) lies on the line of c' = (0, 0, 0) and
    // d' = (0, 0, 2), so the cofactors of a' and b' both vanish.
    const std::vector<WeightedPoint3> p =
        on_hyperplane({{1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 2}, {0, 0, 1}}, {0, 0, 0}, 0);
    const Points5 collinear = {p[0], p[1], p[2], p[3], p[4]};
    const SosVerdict third = orient4d_of(collinear, bottom_first);
    EXPECT_NE(third.sign, Sign::kZero);
    EXPECT_EQ(third.cofactors, 3);
    EXPECT_EQ(third.sign, symbolic_lifted(collinear, bottom_first));
}

// A larger weight (a lower height) puts e inside: the sign of the dominant term agrees with
// the direction of the perturbation for whichever point comes first.
TEST(PerturbedLiftedSign, FirstKeyAlone) {
    const Point3 a{1, 0, 0};
    const Point3 b{0, 0, 0};
    const Point3 c{0, 1, 0};
    const Point3 d{0, 0, 1};
    const Point3 e{1, 1, 1};
    EXPECT_EQ(insphere_sos(a, b, c, d, e, {9, 10, 11, 12, 3}), Sign::kPos);
    // With a first, a is pushed inside the sphere of b, c, d, e: e ends up outside that of abcd.
    EXPECT_EQ(insphere_sos(a, b, c, d, e, {3, 10, 11, 12, 13}), Sign::kNeg);
}

// Powers of two scale the determinant by a positive factor and translations by integers leave it
// unchanged, so the perturbed signs are the same at any exponent: the predicates are exact there.
TEST(PerturbedLiftedSign, SameAtExtremeScalesAndOffsets) {
    std::mt19937_64 rng(kSeed + 8);
    const std::vector<WeightedPoint3> lifted = on_hyperplane(grid(-1, 1), {1, 1, 0}, 1);
    const std::vector<WeightedPoint3> sphere = unweighted(sphere_points(9));
    for (int trial = 0; trial < 400; ++trial) {
        const std::vector<WeightedPoint3>& set = trial % 2 == 0 ? sphere : lifted;
        const Points5 p = pick(set, distinct_indices<5>(rng, set.size()));
        const Keys5 keys = distinct_keys<5>(rng, kKeyBound);
        const Sign reference = orient4d_of(p, keys).sign;
        const Sign insphere_reference = insphere_of(p, keys).sign;
        for (const int exponent : {-520, -300, -60, 60, 300, 500}) {
            Points5 scaled{};
            for (std::size_t i = 0; i < 5; ++i) {
                scaled[i] = {std::ldexp(p[i].x, exponent),
                             std::ldexp(p[i].y, exponent),
                             std::ldexp(p[i].z, exponent),
                             std::ldexp(p[i].w, 2 * exponent)};
            }
            ASSERT_EQ(orient4d_of(scaled, keys).sign, reference) << "2^" << exponent << "\n"
                                                                 << describe(scaled, keys);
            ASSERT_EQ(insphere_of(scaled, keys).sign, insphere_reference)
                << "2^" << exponent << "\n"
                << describe(scaled, keys);
        }
        Points5 shifted = p;
        for (WeightedPoint3& q : shifted) {
            q.x += 0x1p40;
            q.y -= 0x1p30;
        }
        ASSERT_EQ(insphere_of(shifted, keys).sign, insphere_reference) << describe(shifted, keys);
    }
}

}  // namespace

}  // namespace cavity::perturbation::test
