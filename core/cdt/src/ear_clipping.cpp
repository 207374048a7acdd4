#include "ear_clipping.h"

#include <algorithm>
#include <tuple>

namespace cavity::core {

namespace {

/// The orientation of the loop in the projection: the turn at its lexicographically least corner,
/// which a simple polygon makes strictly (its neighbours cannot both lie on one ray from it).
int loop_orientation(const std::vector<Point3>& points,
                     const std::vector<std::uint32_t>& loop,
                     int drop) {
    const auto key = [&](std::uint32_t v) {
        const Point3& p = points[v];
        return drop == 0   ? std::tuple(p.y, p.z)
               : drop == 1 ? std::tuple(p.z, p.x)
                           : std::tuple(p.x, p.y);
    };
    std::size_t least = 0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
        if (key(loop[i]) < key(loop[least])) {
            least = i;
        }
    }
    const std::size_t n = loop.size();
    return orient2d_projected(points[loop[(least + n - 1) % n]],
                              points[loop[least]],
                              points[loop[(least + 1) % n]],
                              drop);
}

}  // namespace

std::optional<std::vector<Triangle>> ear_clipping(const std::vector<Point3>& points,
                                                  const std::vector<std::uint32_t>& loop,
                                                  int drop) {
    const int turn = loop_orientation(points, loop, drop);
    if (turn == 0) {
        return std::nullopt;
    }
    std::vector<std::uint32_t> rest = loop;
    std::vector<Triangle> triangles;
    while (rest.size() > 3) {
        const std::size_t n = rest.size();
        bool clipped = false;
        for (std::size_t i = 0; i < n && !clipped; ++i) {
            const Point3& a = points[rest[(i + n - 1) % n]];
            const Point3& b = points[rest[i]];
            const Point3& c = points[rest[(i + 1) % n]];
            // An ear turns strictly the loop's way and no other corner lies in its closed
            // triangle (one on the new side ac would make that side pass through a corner).
            if (orient2d_projected(a, b, c, drop) != turn) {
                continue;
            }
            bool empty = true;
            for (std::size_t k = 0; k < n && empty; ++k) {
                if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) {
                    continue;
                }
                const Point3& p = points[rest[k]];
                empty = orient2d_projected(a, b, p, drop) == -turn ||
                        orient2d_projected(b, c, p, drop) == -turn ||
                        orient2d_projected(c, a, p, drop) == -turn;
            }
            if (empty) {
                triangles.push_back({rest[(i + n - 1) % n], rest[i], rest[(i + 1) % n]});
                rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
                clipped = true;
            }
        }
        if (!clipped) {
            return std::nullopt;
        }
    }
    if (orient2d_projected(points[rest[0]], points[rest[1]], points[rest[2]], drop) != turn) {
        return std::nullopt;
    }
    triangles.push_back({rest[0], rest[1], rest[2]});
    return triangles;
}

}  // namespace cavity::core
