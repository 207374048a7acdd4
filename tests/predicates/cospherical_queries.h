#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include "cavity/predicates/point.h"

/// Exactly cospherical insphere queries and their near misses, for the suites that probe the
/// exact zeros of insphere's stages: five of twelve integer points at distance 9 from an integer
/// centre, scaled by a power of two (exact), and the same with a few coordinates moved by ulps.
namespace cavity::predicates::testing {

/// Twelve integer points at distance 9 from the origin (x^2 + y^2 + z^2 = 81).
inline constexpr std::array<Point3, 12> kRadius9Sphere = {{{9, 0, 0},
                                                           {-9, 0, 0},
                                                           {0, 9, 0},
                                                           {0, -9, 0},
                                                           {0, 0, 9},
                                                           {0, 0, -9},
                                                           {1, 4, 8},
                                                           {-4, 8, 1},
                                                           {8, -1, -4},
                                                           {4, -8, 1},
                                                           {-8, 1, 4},
                                                           {-1, -4, -8}}};

/// Five points of kRadius9Sphere drawn by `rng`, moved to the integer centre (ox, oy, oz) and
/// scaled by 2^scale: exactly cospherical (insphere 0) whenever the moves and the scaling are
/// exact, as they are for centres below 2^44 and scales that keep the values normal.
template <class Rng>
std::array<Point3, 5> cospherical_query(Rng& rng, double ox, double oy, double oz, int scale) {
    std::uniform_int_distribution<int> pick(0, 11);
    std::array<Point3, 5> q{};
    for (Point3& p : q) {
        const Point3& s = kRadius9Sphere[static_cast<std::size_t>(pick(rng))];
        p = {std::ldexp(s.x + ox, scale), std::ldexp(s.y + oy, scale), std::ldexp(s.z + oz, scale)};
    }
    return q;
}

/// Moves the x coordinate of each point, with probability 1/2, by 1 to 4 ulps up or down.
template <class Rng>
void move_a_few_ulps(std::array<Point3, 5>& q, Rng& rng) {
    std::uniform_int_distribution<int> coin(0, 1), step(1, 4);
    for (Point3& p : q) {
        if (coin(rng) == 0) {
            for (int k = step(rng); k > 0; --k) {
                p.x = std::nextafter(p.x, coin(rng) == 0 ? INFINITY : -INFINITY);
            }
        }
    }
}

}  // namespace cavity::predicates::testing
