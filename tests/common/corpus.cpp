#include "corpus.h"

#include <cmath>
#include <utility>

#include "cavity/core/base/random.h"
#include "cavity/core/gen/generate.h"

namespace cavity::test {

namespace {

using core::PointSet;
using predicates::Point3;

PointSet from(std::vector<Point3> points, std::string source) {
    PointSet set;
    set.points = std::move(points);
    set.source = std::move(source);
    return set;
}

PointSet generated(const char* distribution, std::size_t n) {
    return core::generate_points(distribution, n, 7, core::WeightSpec{});
}

PointSet scaled(PointSet set, double factor) {
    for (Point3& p : set.points) {
        p = {p.x * factor, p.y * factor, p.z * factor};
    }
    return set;
}

PointSet offset(PointSet set, double by) {
    for (Point3& p : set.points) {
        p = {p.x + by, p.y + by, p.z + by};
    }
    return set;
}

// Moves every third point by one ulp in x: near-degenerate, so exact arithmetic decides.
PointSet ulp_moved(PointSet set) {
    for (std::size_t i = 0; i < set.points.size(); i += 3) {
        set.points[i].x = std::nextafter(set.points[i].x, 1e300);
    }
    return set;
}

std::vector<Point3> decimal_grid(int k) {
    std::vector<Point3> points;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
            for (int l = 0; l < k; ++l) {
                points.push_back({0.1 * i, 0.1 * j, 0.1 * l});
            }
        }
    }
    return points;
}

std::vector<Point3> cube_corners() {
    std::vector<Point3> points;
    points.reserve(8);
    for (int i = 0; i < 8; ++i) {
        points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    }
    return points;
}

std::vector<Point3> with_duplicates() {
    std::vector<Point3> points = generated("grid", 27).points;
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; i += 2) {
        points.push_back(points[i]);
    }
    points.push_back({-0.0, 0.0, -0.0});  // the same point as (0, 0, 0)
    return points;
}

// Coordinates of wildly different magnitudes in one set: 1e+-300, subnormals and ordinary values
// side by side, so that single queries span the whole exponent range of a double.
PointSet mixed_magnitudes(std::size_t n) {
    core::Random random(13);
    const double scales[] = {1e300, -1e300, 1e-300, 5e-324, 1.0, 3e-310};
    std::vector<Point3> points;
    for (std::size_t i = 0; i < n; ++i) {
        const auto scale = [&] { return scales[random.below(6)]; };
        points.push_back({scale() * random.uniform01(),
                          scale() * random.uniform01(),
                          scale() * random.uniform01()});
    }
    return from(std::move(points), "mixed magnitudes");
}

}  // namespace

std::vector<CorpusCase> degenerate_corpus() {
    std::vector<CorpusCase> corpus;
    corpus.push_back({"grid5", generated("grid", 125), 6LL * 4 * 4 * 4});
    corpus.push_back({"decimal_grid", from(decimal_grid(5), "decimal grid"), -1});
    corpus.push_back({"cospherical", generated("cospherical", 150), -1});
    corpus.push_back({"paraboloid", generated("paraboloid", 100), -1});
    corpus.push_back({"cube_corners", from(cube_corners(), "cube corners"), -1});
    corpus.push_back({"layers", generated("layers", 200), -1});
    corpus.push_back(
        {"duplicates", from(with_duplicates(), "grid with duplicates"), 6LL * 2 * 2 * 2});
    corpus.push_back({"grid_ulp", ulp_moved(generated("grid", 64)), -1});
    corpus.push_back({"cospherical_ulp", ulp_moved(generated("cospherical", 100)), -1});
    corpus.push_back({"grid_1e300", scaled(generated("grid", 64), 1e300), 6LL * 3 * 3 * 3});
    corpus.push_back({"grid_1em300", scaled(generated("grid", 64), 1e-300), 6LL * 3 * 3 * 3});
    corpus.push_back({"grid_subnormal", scaled(generated("grid", 64), 1e-310), 6LL * 3 * 3 * 3});
    corpus.push_back({"cospherical_1e300", scaled(generated("cospherical", 60), 1e300), -1});
    corpus.push_back({"grid_offset", offset(generated("grid", 64), 1e9), -1});
    corpus.push_back({"grid_offset_1e15", offset(generated("grid", 64), 1e15), 6LL * 3 * 3 * 3});
    // Integer grids at the largest span for which the plain determinants are exact (715 along
    // each axis, predicates/lattice.h) and just beyond it, where the engine must not use them.
    corpus.push_back({"grid_span_715", scaled(generated("grid", 216), 143), 6LL * 5 * 5 * 5});
    corpus.push_back({"grid_span_720", scaled(generated("grid", 216), 144), 6LL * 5 * 5 * 5});
    corpus.push_back({"mixed_magnitudes", mixed_magnitudes(100), -1});
    corpus.push_back({"moment", generated("moment", 20), (20LL - 2) * (20 - 3) / 2});
    corpus.push_back({"skew_lines", generated("skew-lines", 30), 14LL * 14});
    corpus.push_back({"cube_uniform", generated("cube", 300), -1});
    return corpus;
}

}  // namespace cavity::test
