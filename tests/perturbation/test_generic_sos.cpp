// The perturbed predicates on implicit (Steiner) points, against the symbolic oracle.
//
// The oracle takes doubles, and a Steiner point's coordinates are rarely doubles; but the
// perturbed signs are invariant under a uniform scaling of the configuration (the exact
// determinants scale by positive factors and the cofactors are orient3d, which scale by s^3 > 0),
// so a configuration whose Steiner points sit at fifths of integers is checked by scaling it by 5,
// which makes every coordinate an integer. Steiner points get the keys sos.h states: after every
// input point's, in creation order.

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/perturbation/outer_halfspace.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/orient3d.h"
#include "symbolic_oracle.h"

namespace cavity::perturbation::test {
namespace {

using predicates::GenericPoint3;
using predicates::SegmentParameterPoint;

/// An integer point of the lattice scaled by 5, and where it is in the original configuration:
/// an input point when every coordinate is a multiple of 5, else the Steiner point at parameter
/// 1/5 of the segment from the origin to it.
struct Site {
    Point3 scaled;
    GenericPoint3 original;
    bool steiner;
};

Site site(int x, int y, int z) {
    const Point3 scaled{double(x), double(y), double(z)};
    if (x % 5 == 0 && y % 5 == 0 && z % 5 == 0) {
        return {scaled, Point3{x / 5.0, y / 5.0, z / 5.0}, false};
    }
    return {scaled, SegmentParameterPoint{Point3{0, 0, 0}, scaled, 1.0, 5.0}, true};
}

/// The integer points of the sphere x^2 + y^2 + z^2 = 625 (radius 25): input points like
/// (15, 20, 0) and Steiner points like (9, 12, 20), whose unscaled coordinates (9/5, ...) are no
/// doubles. Every five of them are cospherical: each insphere is an exact tie.
std::vector<Site> sphere_sites() {
    std::vector<Site> sites;
    for (int x = -25; x <= 25; ++x) {
        for (int y = -25; y <= 25; ++y) {
            for (int z = -25; z <= 25; ++z) {
                if (x * x + y * y + z * z == 625) {
                    sites.push_back(site(x, y, z));
                }
            }
        }
    }
    return sites;
}

/// Keys as sos.h states: the input points first (here in a random order), then the Steiner points
/// in creation order (here their argument order).
template <std::size_t N>
std::array<std::uint32_t, N> keys_for(const std::array<const Site*, N>& s, std::mt19937_64& rng) {
    std::vector<std::uint32_t> input_keys;
    for (const Site* x : s) {
        if (!x->steiner) {
            input_keys.push_back(static_cast<std::uint32_t>(input_keys.size()));
        }
    }
    std::shuffle(input_keys.begin(), input_keys.end(), rng);
    std::array<std::uint32_t, N> keys{};
    std::size_t next_input = 0;
    auto next_steiner = static_cast<std::uint32_t>(input_keys.size());
    for (std::size_t i = 0; i < N; ++i) {
        keys[i] = s[i]->steiner ? next_steiner++ : input_keys[next_input++];
    }
    return keys;
}

WeightedPoint3 unweighted(const Point3& p) {
    return {p.x, p.y, p.z, 0.0};
}

TEST(GenericSos, InsphereMatchesTheOracleOnCosphericalSteinerPoints) {
    const std::vector<Site> sites = sphere_sites();
    std::mt19937_64 rng(15);
    std::uniform_int_distribution<std::size_t> pick(0, sites.size() - 1);
    int steiner_ties = 0;
    for (int n = 0; n < 3000; ++n) {
        std::array<const Site*, 5> s{};
        for (auto& x : s) {
            x = &sites[pick(rng)];
        }
        std::array<const Site*, 5> sorted = s;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            continue;
        }
        const Keys5 keys = keys_for(s, rng);
        const SosVerdict generic = insphere_sos_staged(
            s[0]->original, s[1]->original, s[2]->original, s[3]->original, s[4]->original, keys);
        const std::array<WeightedPoint3, 5> scaled{unweighted(s[0]->scaled),
                                                   unweighted(s[1]->scaled),
                                                   unweighted(s[2]->scaled),
                                                   unweighted(s[3]->scaled),
                                                   unweighted(s[4]->scaled)};
        ASSERT_EQ(generic.sign, symbolic_lifted(scaled, keys));
        ASSERT_EQ(generic.sign,
                  insphere_sos(
                      s[0]->scaled, s[1]->scaled, s[2]->scaled, s[3]->scaled, s[4]->scaled, keys));
        const bool is_flat =
            predicates::orient3d(s[0]->scaled, s[1]->scaled, s[2]->scaled, s[3]->scaled) ==
            Sign::kZero;
        if (!is_flat) {
            ASSERT_NE(generic.sign, Sign::kZero);
        }
        const bool any_steiner =
            std::any_of(s.begin(), s.end(), [](const Site* x) { return x->steiner; });
        steiner_ties += (any_steiner && generic.cofactors > 0) ? 1 : 0;
    }
    EXPECT_GT(steiner_ties, 1000);
}

/// With the keys sos.h states, a Steiner point is perturbed less than every input point: in a tie
/// of four input points and one Steiner point, the Steiner point's own cofactor is the last one
/// the cascade would reach, so the sign is decided by the lowest-keyed input point whose cofactor
/// is nonzero, exactly as when the Steiner point is replaced by any other point of the sphere with
/// a higher key.
TEST(GenericSos, SteinerKeysComeAfterTheInputs) {
    const std::vector<Site> sites = sphere_sites();
    std::vector<const Site*> inputs;
    std::vector<const Site*> steiner;
    for (const Site& s : sites) {
        (s.steiner ? steiner : inputs).push_back(&s);
    }
    ASSERT_GE(inputs.size(), 4u);
    ASSERT_GE(steiner.size(), 4u);
    std::mt19937_64 rng(1515);
    int decided = 0;
    for (int n = 0; n < 1000; ++n) {
        std::shuffle(inputs.begin(), inputs.end(), rng);
        const Site* st = steiner[rng() % steiner.size()];
        const auto& a = inputs[0]->original;
        const auto& b = inputs[1]->original;
        const auto& c = inputs[2]->original;
        const auto& d = inputs[3]->original;
        if (predicates::orient3d(a, b, c, d) == Sign::kZero) {
            continue;
        }
        const Keys5 keys{0, 1, 2, 3, 4};  // four inputs, then the first Steiner point
        const SosVerdict v = insphere_sos_staged(a, b, c, d, st->original, keys);
        // Key 0 (a) comes first: its cofactor is orient3d(b, c, d, e) for e the Steiner point.
        const Sign first = predicates::orient3d(b, c, d, st->original);
        if (first != Sign::kZero) {
            EXPECT_EQ(v.sign, first);
            EXPECT_EQ(v.cofactors, 1);
            ++decided;
        }
    }
    EXPECT_GT(decided, 500);
}

/// The ghost test when u is a Steiner point on the circumcircle of a hull triangle: the circle
/// x^2 + y^2 = 625 in the plane z = 0, scaled by 5 as above.
TEST(GenericSos, OuterHalfspaceMatchesTheOracleOnCocircularSteinerPoints) {
    std::vector<Site> circle;
    for (int x = -25; x <= 25; ++x) {
        for (int y = -25; y <= 25; ++y) {
            if (x * x + y * y == 625) {
                circle.push_back(site(x, y, 0));
            }
        }
    }
    std::mt19937_64 rng(151);
    std::uniform_int_distribution<std::size_t> pick(0, circle.size() - 1);
    int with_steiner = 0;
    for (int n = 0; n < 2000; ++n) {
        std::array<const Site*, 4> s{};  // v, w, x, u
        for (auto& p : s) {
            p = &circle[pick(rng)];
        }
        std::array<const Site*, 4> sorted = s;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            continue;
        }
        // y behind vwx: x w v y positively oriented.
        Site y = site(0, 0, 5);
        if (predicates::orient3d(s[2]->scaled, s[1]->scaled, s[0]->scaled, y.scaled) !=
            Sign::kPos) {
            y = site(0, 0, -5);
        }
        const std::array<const Site*, 4> vwxu{s[0], s[1], s[2], s[3]};
        const Keys4 keys = keys_for(vwxu, rng);
        const Sign generic = outer_halfspace_sos(
            s[0]->original, s[1]->original, s[2]->original, y.original, s[3]->original, keys);
        const Sign scaled = symbolic_outer_halfspace(unweighted(s[0]->scaled),
                                                     unweighted(s[1]->scaled),
                                                     unweighted(s[2]->scaled),
                                                     unweighted(y.scaled),
                                                     unweighted(s[3]->scaled),
                                                     keys);
        ASSERT_EQ(generic, scaled);
        ASSERT_NE(generic, Sign::kZero);
        with_steiner +=
            std::any_of(s.begin(), s.end(), [](const Site* p) { return p->steiner; }) ? 1 : 0;
    }
    EXPECT_GT(with_steiner, 500);
}

}  // namespace
}  // namespace cavity::perturbation::test
