#include "cavity/experiments/plc_families.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/mesh/tetrahedron.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::experiments {

namespace {

using core::Plc;
using core::Point3;
using core::Random;
using Loop = std::vector<std::uint32_t>;

constexpr PlcFamily kFamilies[] = {
    {"hull-faces", "the hull triangles of n/4 points near a sphere as polygons, among n points"},
    {"nested-boxes", "concentric cubes (6 square polygons each) with random points between"},
    {"terrain", "4 stacked height fields of triangles with random points between the layers"},
    {"voxel-grid", "every unit square of a k^3 integer lattice, with random points in the cells"},
};

/// Collects points and polygons; refuses repeated points so the PLC never has duplicates.
class PlcBuilder {
public:
    explicit PlcBuilder(std::string source) { plc_.source = std::move(source); }

    std::uint32_t point(const Point3& p) {
        const auto [it, fresh] = index_.try_emplace({p.x, p.y, p.z}, plc_.points.size());
        if (fresh) {
            plc_.points.points.push_back(p);
        }
        return static_cast<std::uint32_t>(it->second);
    }

    bool has(const Point3& p) const { return index_.contains({p.x, p.y, p.z}); }

    void polygon(Loop loop) {
        core::PlcFacet facet;
        facet.loops.push_back(std::move(loop));
        facet.marker = static_cast<int>(plc_.facets.size()) + 1;
        plc_.facets.push_back(std::move(facet));
    }

    const Point3& at(std::uint32_t i) const { return plc_.points.points[i]; }

    std::size_t size() const { return plc_.points.size(); }

    Plc take() { return std::move(plc_); }

private:
    Plc plc_;
    std::map<std::array<double, 3>, std::size_t> index_;
};

/// k / denominator for a uniform k in [1, cells * denominator): strictly inside (0, cells), exact.
double dyadic(Random& random, std::uint64_t cells, std::uint64_t denominator) {
    return static_cast<double>(1 + random.below(cells * denominator - 1)) /
           static_cast<double>(denominator);
}

bool on_plane_of(const PlcBuilder& b, const Loop& triangle, const Point3& p) {
    return predicates::orient3d(b.at(triangle[0]), b.at(triangle[1]), b.at(triangle[2]), p) ==
           predicates::Sign::kZero;
}

/// The hull triangles of n/4 points near a sphere, plus free points in the cube around it.
Plc hull_faces(std::size_t n, std::uint64_t seed, std::string source) {
    PlcBuilder b(std::move(source));
    Random random(seed);
    const std::size_t shell = std::max<std::size_t>(12, n / 4);
    while (b.size() < shell) {
        // A random direction, scaled to radius 1.5 about (2, 2, 2) and rounded to 1/256.
        const double x = random.normal();
        const double y = random.normal();
        const double z = random.normal();
        const double r = std::sqrt(x * x + y * y + z * z);
        if (r < 1e-3) {
            continue;
        }
        const auto grid = [](double c) { return std::round((2 + 1.5 * c) * 256) / 256; };
        b.point({grid(x / r), grid(y / r), grid(z / r)});
    }
    // Triangulating the shell alone gives its convex hull: the triangles on one tetrahedron only.
    core::PointSet shell_points;
    for (std::uint32_t i = 0; i < b.size(); ++i) {
        shell_points.points.push_back(b.at(i));
    }
    std::vector<std::uint32_t> sequence(shell_points.size());
    std::iota(sequence.begin(), sequence.end(), 0u);
    const core::Triangulation dt = core::triangulate(shell_points, sequence, {});
    std::map<std::array<std::uint32_t, 3>, int> seen;
    for (const auto& t : dt.tets) {
        for (int f = 0; f < 4; ++f) {
            auto g = core::facet_vertices(t, f);
            std::sort(g.begin(), g.end());
            ++seen[g];
        }
    }
    std::vector<Loop> triangles;
    for (const auto& [g, count] : seen) {
        if (count == 1) {
            triangles.push_back({g[0], g[1], g[2]});
        }
    }
    while (b.size() < n) {
        const Point3 p{dyadic(random, 4, 256), dyadic(random, 4, 256), dyadic(random, 4, 256)};
        if (b.has(p) || std::any_of(triangles.begin(), triangles.end(), [&](const Loop& t) {
                return on_plane_of(b, t, p);
            })) {
            continue;
        }
        b.point(p);
    }
    for (Loop& t : triangles) {
        b.polygon(std::move(t));
    }
    return b.take();
}

/// Cubes [L-i, L+i]^3, i = 1..L, and free points at multiples of 1/64 off the integer planes.
Plc nested_boxes(std::size_t n, std::uint64_t seed, std::string source) {
    PlcBuilder b(std::move(source));
    Random random(seed);
    const auto boxes = static_cast<std::uint32_t>(
        std::clamp(std::lround(std::cbrt(static_cast<double>(n)) / 3), 2L, 8L));
    for (std::uint32_t i = 1; i <= boxes; ++i) {
        const double lo = boxes - i;
        const double hi = boxes + i;
        std::array<std::uint32_t, 8> c{};
        for (std::uint32_t k = 0; k < 8; ++k) {
            c[k] = b.point({k & 1 ? hi : lo, k & 2 ? hi : lo, k & 4 ? hi : lo});
        }
        // Corner k has bit 0 = x, bit 1 = y, bit 2 = z; each face walks its square in order.
        for (const Loop& face : {Loop{c[0], c[1], c[3], c[2]},
                                 Loop{c[4], c[5], c[7], c[6]},
                                 Loop{c[0], c[1], c[5], c[4]},
                                 Loop{c[2], c[3], c[7], c[6]},
                                 Loop{c[0], c[2], c[6], c[4]},
                                 Loop{c[1], c[3], c[7], c[5]}}) {
            b.polygon(face);
        }
    }
    const auto off_plane = [&] {
        double c = 0;
        do {
            c = dyadic(random, 2 * std::uint64_t{boxes}, 64);
        } while (c == std::floor(c));
        return c;
    };
    while (b.size() < n) {
        const double x = off_plane();
        const double y = off_plane();
        b.point({x, y, off_plane()});
    }
    return b.take();
}

/// Four height fields z = layer + bump on a (g x g) grid of spacing 1/4, each grid cell split into
/// two triangles, and free points between the layers.
Plc terrain(std::size_t n, std::uint64_t seed, std::string source) {
    constexpr std::uint32_t kLayers = 4;
    PlcBuilder b(std::move(source));
    Random random(seed);
    const auto g = static_cast<std::uint32_t>(
        std::max(3L, std::lround(std::sqrt(static_cast<double>(n) / (2 * kLayers)))));
    const auto id = [g](std::uint32_t layer, std::uint32_t i, std::uint32_t j) {
        return (layer * g + j) * g + i;
    };
    for (std::uint32_t layer = 0; layer < kLayers; ++layer) {
        for (std::uint32_t j = 0; j < g; ++j) {
            for (std::uint32_t i = 0; i < g; ++i) {
                const double bump = (static_cast<double>(random.below(17)) - 8) / 64;
                b.point({i / 4.0, j / 4.0, layer + bump});
            }
        }
    }
    // cell_triangles[(layer, i, j)]: the two triangles of a cell, alternating diagonals.
    std::vector<std::array<Loop, 2>> cells;
    for (std::uint32_t layer = 0; layer < kLayers; ++layer) {
        for (std::uint32_t j = 0; j + 1 < g; ++j) {
            for (std::uint32_t i = 0; i + 1 < g; ++i) {
                const std::uint32_t p = id(layer, i, j), q = id(layer, i + 1, j);
                const std::uint32_t r = id(layer, i + 1, j + 1), s = id(layer, i, j + 1);
                using Pair = std::array<Loop, 2>;
                cells.push_back((i + j) % 2 == 0 ? Pair{Loop{p, q, r}, Loop{p, r, s}}
                                                 : Pair{Loop{p, q, s}, Loop{q, r, s}});
            }
        }
    }
    const auto cell = [g](std::uint32_t layer, std::uint32_t i, std::uint32_t j) {
        return (layer * (g - 1) + j) * (g - 1) + i;
    };
    const std::uint64_t width = g - 1;  // in units of 1/4
    while (b.size() < n) {
        const Point3 p{dyadic(random, width, 64) / 4,
                       dyadic(random, width, 64) / 4,
                       dyadic(random, kLayers, 256) - 0.5};
        // The triangles whose xy-box can hold p: the cells around its grid square.
        const auto ci = static_cast<std::uint32_t>(p.x * 4);
        const auto cj = static_cast<std::uint32_t>(p.y * 4);
        bool on_polygon_plane = b.has(p);
        for (std::uint32_t layer = 0; layer < kLayers && !on_polygon_plane; ++layer) {
            for (std::uint32_t j = cj == 0 ? 0 : cj - 1; j <= std::min(cj, g - 2); ++j) {
                for (std::uint32_t i = ci == 0 ? 0 : ci - 1; i <= std::min(ci, g - 2); ++i) {
                    for (const Loop& t : cells[cell(layer, i, j)]) {
                        on_polygon_plane = on_polygon_plane || on_plane_of(b, t, p);
                    }
                }
            }
        }
        if (!on_polygon_plane) {
            b.point(p);
        }
    }
    for (auto& pair : cells) {
        for (Loop& t : pair) {
            b.polygon(std::move(t));
        }
    }
    return b.take();
}

/// The integer lattice {0..k-1}^3 with every unit square between lattice points as a polygon
/// (k = cbrt(n/8)), and free points strictly inside the cells.
Plc voxel_grid(std::size_t n, std::uint64_t seed, std::string source) {
    PlcBuilder b(std::move(source));
    Random random(seed);
    const auto k = static_cast<std::uint32_t>(
        std::max(2L, std::lround(std::cbrt(static_cast<double>(n) / 8))));
    for (std::uint32_t z = 0; z < k; ++z) {
        for (std::uint32_t y = 0; y < k; ++y) {
            for (std::uint32_t x = 0; x < k; ++x) {
                b.point({static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)});
            }
        }
    }
    const auto id = [k](std::array<std::uint32_t, 3> c) { return (c[2] * k + c[1]) * k + c[0]; };
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t u = (axis + 1) % 3;
        const std::size_t v = (axis + 2) % 3;
        for (std::uint32_t level = 0; level < k; ++level) {
            for (std::uint32_t a = 0; a + 1 < k; ++a) {
                for (std::uint32_t c = 0; c + 1 < k; ++c) {
                    std::array<std::uint32_t, 3> p{};
                    p[axis] = level;
                    p[u] = a;
                    p[v] = c;
                    Loop square;
                    for (const auto [du, dv] : {std::array{0u, 0u}, {1u, 0u}, {1u, 1u}, {0u, 1u}}) {
                        std::array<std::uint32_t, 3> q = p;
                        q[u] += du;
                        q[v] += dv;
                        square.push_back(id(q));
                    }
                    b.polygon(std::move(square));
                }
            }
        }
    }
    const auto off_lattice = [&] {
        double c = 0;
        do {
            c = dyadic(random, k - 1, 64);
        } while (c == std::floor(c));
        return c;
    };
    while (b.size() < n) {
        const double x = off_lattice();
        const double y = off_lattice();
        b.point({x, y, off_lattice()});
    }
    return b.take();
}

}  // namespace

std::span<const PlcFamily> plc_families() {
    return kFamilies;
}

core::Plc make_plc_family(std::string_view family, std::size_t n, std::uint64_t seed) {
    if (n < 8) {
        throw core::Error("PLC family '" + std::string(family) + "': n = " + std::to_string(n) +
                          " is too small (at least 8 points)");
    }
    std::string source =
        std::string(family) + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
    if (family == "hull-faces") {
        return hull_faces(n, seed, std::move(source));
    }
    if (family == "nested-boxes") {
        return nested_boxes(n, seed, std::move(source));
    }
    if (family == "terrain") {
        return terrain(n, seed, std::move(source));
    }
    if (family == "voxel-grid") {
        return voxel_grid(n, seed, std::move(source));
    }
    throw core::Error("unknown PLC family '" + std::string(family) +
                      "' (hull-faces, nested-boxes, terrain or voxel-grid)");
}

}  // namespace cavity::experiments
