#include "minimum_weight_triangulation.h"

#include <cmath>
#include <limits>

namespace cavity::core {

namespace {

double length(const Point3& a, const Point3& b) {
    return std::hypot(a.x - b.x, std::hypot(a.y - b.y, a.z - b.z));  // no overflow near DBL_MAX
}

}  // namespace

std::optional<std::vector<Triangle>> minimum_weight_triangulation(
    const std::vector<Point3>& points, const std::vector<std::uint32_t>& loop, int drop, int turn) {
    const std::size_t n = loop.size();
    if (n < 3 || n > kMinimumWeightCorners || turn == 0) {
        return std::nullopt;
    }
    const auto at = [&](std::size_t i) -> const Point3& { return points[loop[i]]; };
    // weight[i * n + j], i < j: the least total length of the diagonals of a triangulation of the
    // sub-polygon i, i+1, ..., j closed by ji, counting ji unless it is the loop's side (infinite
    // when it has none); apex[i * n + j]: the corner of its triangle on ji.
    //
    // Why every triangle turning the loop's way suffices, with no test that a diagonal lies inside
    // the polygon or misses its sides: each diagonal is a side of two of the chosen triangles,
    // traversed both ways, so the triangles' boundaries add up to the loop's. Then at every point
    // off their sides the number of triangles covering it is the loop's winding number there: 1
    // inside a simple polygon, 0 outside. So they tile the polygon, and none has a corner on a side
    // (points outside are near every corner, and would be covered there).
    constexpr double kNone = std::numeric_limits<double>::infinity();
    std::vector<double> weight(n * n, kNone);
    std::vector<std::size_t> apex(n * n, n);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        weight[i * n + i + 1] = 0;
    }
    for (std::size_t span = 2; span < n; ++span) {
        for (std::size_t i = 0; i + span < n; ++i) {
            const std::size_t j = i + span;
            const double own = span == n - 1 ? 0 : length(at(i), at(j));
            for (std::size_t k = i + 1; k < j; ++k) {
                const double sides = weight[i * n + k] + weight[k * n + j];
                if (sides + own < weight[i * n + j] &&
                    orient2d_projected(at(i), at(k), at(j), drop) == turn) {
                    weight[i * n + j] = sides + own;
                    apex[i * n + j] = k;
                }
            }
        }
    }
    if (apex[n - 1] == n) {
        return std::nullopt;
    }
    std::vector<Triangle> triangles;
    std::vector<std::pair<std::size_t, std::size_t>> open{{0, n - 1}};
    while (!open.empty()) {
        const auto [i, j] = open.back();
        open.pop_back();
        const std::size_t k = apex[i * n + j];
        triangles.push_back({loop[i], loop[k], loop[j]});
        if (k - i > 1) {
            open.emplace_back(i, k);
        }
        if (j - k > 1) {
            open.emplace_back(k, j);
        }
    }
    return triangles;
}

}  // namespace cavity::core
