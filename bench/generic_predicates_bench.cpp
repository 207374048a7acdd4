// Cost per call of orient3d and insphere on generic points (predicates/generic_predicates.h):
//   explicit_point3   the Point3 predicates on random points (the baseline);
//   explicit_generic  the same points through the generic predicates;
//   mixed             random mixes of explicit, segment-parameter and line-plane points: the
//                     interval filter decides;
//   degenerate        line-plane points exactly on the plane of three explicit points (orient3d)
//                     and segment points exactly on the sphere through four (insphere): GMP
//                     decides.
// Each benchmark cycles through 1024 pre-generated queries.
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "cavity/predicates/generic_predicates.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"

namespace {

using cavity::predicates::GenericPoint3;
using cavity::predicates::Point3;
using cavity::predicates::SegmentParameterPoint;

constexpr std::size_t kQueries = 1024;  // a power of two: the index wraps with a mask

using Query = std::array<GenericPoint3, 5>;

class Source {
public:
    Point3 point() { return {unit(), unit(), unit()}; }

    GenericPoint3 generic() {
        switch (std::uniform_int_distribution<int>(0, 2)(rng_)) {
            case 0:
                return point();
            case 1:
                return SegmentParameterPoint{point(), point(), unit(), 1.0};
            default:
                for (;;) {
                    if (auto l = cavity::predicates::line_plane_point(
                            point(), point(), point(), point(), point())) {
                        return *l;
                    }
                }
        }
    }

    double unit() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }

    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

private:
    std::mt19937_64 rng_{15};
};

std::vector<Query> explicit_queries() {
    Source s;
    std::vector<Query> q(kQueries);
    for (auto& query : q) {
        for (auto& p : query) {
            p = s.point();
        }
    }
    return q;
}

std::vector<Query> mixed_queries() {
    Source s;
    std::vector<Query> q(kQueries);
    for (auto& query : q) {
        for (auto& p : query) {
            p = s.generic();
        }
    }
    return q;
}

/// orient3d: p, q, r and two line-plane points on their plane; insphere: four corners of the cube
/// [0, 2]^3 and the segment point at parameter 1/4 of the segment from (0, 0, 0) - v to
/// (0, 0, 0) + 3v, which is the corner (0, 0, 0).
std::vector<Query> degenerate_queries(bool sphere) {
    Source s;
    std::vector<Query> q(kQueries);
    const auto lattice = [&] {
        return Point3{
            double(s.integer(-50, 50)), double(s.integer(-50, 50)), double(s.integer(-50, 50))};
    };
    for (auto& query : q) {
        if (sphere) {
            const Point3 v{
                double(s.integer(1, 5)), double(s.integer(-5, 5)), double(s.integer(-5, 5))};
            query = {Point3{2, 0, 0},
                     Point3{0, 2, 0},
                     Point3{0, 0, 2},
                     Point3{2, 2, 2},
                     SegmentParameterPoint{
                         Point3{-v.x, -v.y, -v.z}, Point3{3 * v.x, 3 * v.y, 3 * v.z}, 1.0, 4.0}};
            continue;
        }
        const Point3 p = lattice(), r = lattice(), t = lattice();
        const auto on_plane = [&]() -> GenericPoint3 {
            for (;;) {
                if (auto l = cavity::predicates::line_plane_point(lattice(), lattice(), p, r, t)) {
                    return *l;
                }
            }
        };
        query = {p, r, on_plane(), on_plane(), p};
    }
    return q;
}

Point3 as_point(const GenericPoint3& g) {
    return std::get<Point3>(g);
}

void BM_orient3d_explicit_point3(benchmark::State& state) {
    const auto q = explicit_queries();
    std::size_t i = 0;
    for (auto _ : state) {
        const Query& x = q[i++ & (kQueries - 1)];
        benchmark::DoNotOptimize(cavity::predicates::orient3d(
            as_point(x[0]), as_point(x[1]), as_point(x[2]), as_point(x[3])));
    }
}

void BM_insphere_explicit_point3(benchmark::State& state) {
    const auto q = explicit_queries();
    std::size_t i = 0;
    for (auto _ : state) {
        const Query& x = q[i++ & (kQueries - 1)];
        benchmark::DoNotOptimize(cavity::predicates::insphere(
            as_point(x[0]), as_point(x[1]), as_point(x[2]), as_point(x[3]), as_point(x[4])));
    }
}

void run_orient3d(benchmark::State& state, const std::vector<Query>& q) {
    std::size_t i = 0;
    for (auto _ : state) {
        const Query& x = q[i++ & (kQueries - 1)];
        benchmark::DoNotOptimize(cavity::predicates::orient3d(x[0], x[1], x[2], x[3]));
    }
}

void run_insphere(benchmark::State& state, const std::vector<Query>& q) {
    std::size_t i = 0;
    for (auto _ : state) {
        const Query& x = q[i++ & (kQueries - 1)];
        benchmark::DoNotOptimize(cavity::predicates::insphere(x[0], x[1], x[2], x[3], x[4]));
    }
}

void BM_orient3d_explicit_generic(benchmark::State& state) {
    run_orient3d(state, explicit_queries());
}

void BM_insphere_explicit_generic(benchmark::State& state) {
    run_insphere(state, explicit_queries());
}

void BM_orient3d_mixed(benchmark::State& state) {
    run_orient3d(state, mixed_queries());
}

void BM_insphere_mixed(benchmark::State& state) {
    run_insphere(state, mixed_queries());
}

void BM_orient3d_degenerate(benchmark::State& state) {
    run_orient3d(state, degenerate_queries(false));
}

void BM_insphere_degenerate(benchmark::State& state) {
    run_insphere(state, degenerate_queries(true));
}

}  // namespace

BENCHMARK(BM_orient3d_explicit_point3);
BENCHMARK(BM_orient3d_explicit_generic);
BENCHMARK(BM_orient3d_mixed);
BENCHMARK(BM_orient3d_degenerate);
BENCHMARK(BM_insphere_explicit_point3);
BENCHMARK(BM_insphere_explicit_generic);
BENCHMARK(BM_insphere_mixed);
BENCHMARK(BM_insphere_degenerate);

BENCHMARK_MAIN();
