#include "lattice_sphere.h"

#include <cmath>
#include <string>

#include "cavity/core/base/error.h"

namespace cavity::core {

namespace {

std::uint64_t isqrt(std::uint64_t v) {
    auto r = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(v)));
    while (r * r > v) {
        --r;
    }
    while ((r + 1) * (r + 1) <= v) {
        ++r;
    }
    return r;
}

// Number of sign and order variants of a solution 0 <= x <= y <= z: distinct permutations
// times a sign choice for every nonzero coordinate.
std::uint32_t variants(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
    const std::uint32_t permutations = (x == y && y == z) ? 1 : (x == y || y == z) ? 3 : 6;
    const int nonzero = (x != 0) + (y != 0) + (z != 0);
    return permutations << nonzero;
}

// The least s <= bound with at least n solutions, or 0 if there is none. Counts every s at once
// by running over the solutions with 0 <= x <= y <= z (a 48th of the ball).
std::uint64_t least_radius_squared(std::size_t n, std::uint64_t bound) {
    std::vector<std::uint64_t> count(bound + 1, 0);
    for (std::uint64_t x = 0; 3 * x * x <= bound; ++x) {
        for (std::uint64_t y = x; x * x + 2 * y * y <= bound; ++y) {
            for (std::uint64_t z = y; x * x + y * y + z * z <= bound; ++z) {
                count[x * x + y * y + z * z] += variants(x, y, z);
            }
        }
    }
    for (std::uint64_t s = 1; s <= bound; ++s) {
        if (count[s] >= n) {
            return s;
        }
    }
    return 0;
}

}  // namespace

LatticeSphere lattice_sphere(std::size_t n) {
    if (n > kMaxLatticeSpherePoints) {
        throw Error("cospherical: at most " + std::to_string(kMaxLatticeSpherePoints) +
                    " points (the search for the radius grows like n^3); 'sphere' gives nearly "
                    "cospherical sets of any size");
    }
    std::uint64_t s = 0;
    for (std::uint64_t bound = 64; s == 0; bound *= 2) {
        s = least_radius_squared(n, bound);
    }
    LatticeSphere sphere{s, {}};
    const auto r = static_cast<std::int64_t>(isqrt(s));
    for (std::int64_t x = -r; x <= r; ++x) {
        for (std::int64_t y = -r; y <= r; ++y) {
            const std::int64_t rest = static_cast<std::int64_t>(s) - x * x - y * y;
            if (rest < 0) {
                continue;
            }
            const auto z = static_cast<std::int64_t>(isqrt(static_cast<std::uint64_t>(rest)));
            if (z * z != rest) {
                continue;
            }
            sphere.points.push_back(
                {static_cast<double>(x), static_cast<double>(y), static_cast<double>(-z)});
            if (z != 0 && sphere.points.size() < n) {
                sphere.points.push_back(
                    {static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)});
            }
            if (sphere.points.size() == n) {
                return sphere;
            }
        }
    }
    return sphere;
}

}  // namespace cavity::core
