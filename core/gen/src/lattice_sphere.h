#pragma once

#include <cstdint>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

struct LatticeSphere {
    std::uint64_t radius_squared;  ///< s: the points satisfy x^2 + y^2 + z^2 = s exactly
    std::vector<Point3> points;
};

/// The largest n lattice_sphere() accepts; its search takes seconds already (R^2 = 1371926).
inline constexpr std::size_t kMaxLatticeSpherePoints = 30000;

/// The first n, in lexicographic (x, y, z) order, of the integer solutions of x^2+y^2+z^2 = s for
/// the least s that has at least n of them. Cost grows like s^1.5 with s roughly (n / 25)^2, so
/// this is meant for n up to about 10^4 (R^2 = 174929, 0.2 s). \throws Error above
/// kMaxLatticeSpherePoints.
LatticeSphere lattice_sphere(std::size_t n);

}  // namespace cavity::core
