// Cost per call of the staged predicates next to a plain (non-robust) double determinant and the
// exact oracle, on three input classes:
//   random           coordinates (and weights) uniform in [-1, 1): the filter decides;
//   near_degenerate  the degenerate sets below with 1 to 4 coordinates moved 1-4 ulps (nextafter):
//                    the signs are tiny but nonzero;
//   degenerate       exactly degenerate integer sets: coplanar points (orient3d), points on the
//                    sphere x^2 + y^2 + z^2 = R^2 (insphere), weights that put the lifted points on
//                    one hyperplane (orient4d).
// Each benchmark cycles through 4096 pre-generated queries; the counters give the fraction decided
// by each stage of the cavity predicate on that query set. The `static` rows (orient3d, insphere)
// time the cascade the engine uses: a static filter for the bounding box of the whole query set,
// then the cavity predicate (semi-static filter, adaptive, exact) when it defers; their `static`
// counter is the fraction the static filter decides.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/insphere_static_filter.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient3d_static_filter.h"
#include "cavity/predicates/orient4d.h"

namespace {

using cavity::predicates::Point3;
using cavity::predicates::Sign;
using cavity::predicates::Stage;
using cavity::predicates::Verdict;
using cavity::predicates::WeightedPoint3;

constexpr std::size_t kQueries = 4096;  // a power of two: the index wraps with a mask

using Orient3dQuery = std::array<Point3, 4>;
using InsphereQuery = std::array<Point3, 5>;
using Orient4dQuery = std::array<WeightedPoint3, 5>;

// ---- plain double determinants: the same formulas as the filters, without error bounds -------

Sign sign_of(double det) {
    return det > 0 ? Sign::kPos : (det < 0 ? Sign::kNeg : Sign::kZero);
}

Sign plain_orient3d(const Orient3dQuery& q) {
    const auto& [a, b, c, d] = q;
    const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
    const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
    const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
    return sign_of(adz * (bdx * cdy - bdy * cdx) + bdz * (cdx * ady - cdy * adx) +
                   cdz * (adx * bdy - ady * bdx));
}

/// det[p - e, |p - e|^2 - dw_p] for rows of differences (dw = 0 for insphere).
double plain_lifted(const double (&x)[4],
                    const double (&y)[4],
                    const double (&z)[4],
                    const double (&w)[4]) {
    const double ab = x[0] * y[1] - x[1] * y[0];
    const double bc = x[1] * y[2] - x[2] * y[1];
    const double cd = x[2] * y[3] - x[3] * y[2];
    const double da = x[3] * y[0] - x[0] * y[3];
    const double ac = x[0] * y[2] - x[2] * y[0];
    const double bd = x[1] * y[3] - x[3] * y[1];
    const double abc = z[0] * bc - z[1] * ac + z[2] * ab;
    const double bcd = z[1] * cd - z[2] * bd + z[3] * bc;
    const double cda = z[2] * da + z[3] * ac + z[0] * cd;
    const double dab = z[3] * ab + z[0] * bd + z[1] * da;
    double lift[4];
    for (int i = 0; i < 4; ++i) {
        lift[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i] - w[i];
    }
    return (lift[3] * abc - lift[2] * dab) + (lift[1] * cda - lift[0] * bcd);
}

Sign plain_insphere(const InsphereQuery& q) {
    double x[4], y[4], z[4], w[4];
    for (int i = 0; i < 4; ++i) {
        x[i] = q[i].x - q[4].x;
        y[i] = q[i].y - q[4].y;
        z[i] = q[i].z - q[4].z;
        w[i] = 0.0;
    }
    return sign_of(plain_lifted(x, y, z, w));
}

Sign plain_orient4d(const Orient4dQuery& q) {
    double x[4], y[4], z[4], w[4];
    for (int i = 0; i < 4; ++i) {
        x[i] = q[i].x - q[4].x;
        y[i] = q[i].y - q[4].y;
        z[i] = q[i].z - q[4].z;
        w[i] = q[i].w - q[4].w;
    }
    return sign_of(plain_lifted(x, y, z, w));
}

// ---- the three implementations per predicate ---------------------------------------------------

namespace cp = cavity::predicates;

Sign cavity_orient3d(const Orient3dQuery& q) {
    return cp::orient3d(q[0], q[1], q[2], q[3]);
}

Sign cavity_insphere(const InsphereQuery& q) {
    return cp::insphere(q[0], q[1], q[2], q[3], q[4]);
}

Sign cavity_orient4d(const Orient4dQuery& q) {
    return cp::orient4d(q[0], q[1], q[2], q[3], q[4]);
}

Sign oracle_orient3d(const Orient3dQuery& q) {
    return cp::oracle::orient3d(q[0], q[1], q[2], q[3]);
}

Sign oracle_insphere(const InsphereQuery& q) {
    return cp::oracle::insphere(q[0], q[1], q[2], q[3], q[4]);
}

Sign oracle_orient4d(const Orient4dQuery& q) {
    return cp::oracle::orient4d(q[0], q[1], q[2], q[3], q[4]);
}

Verdict staged(const Orient3dQuery& q) {
    return cp::orient3d_staged(q[0], q[1], q[2], q[3]);
}

Verdict staged(const InsphereQuery& q) {
    return cp::insphere_staged(q[0], q[1], q[2], q[3], q[4]);
}

Verdict staged(const Orient4dQuery& q) {
    return cp::orient4d_staged(q[0], q[1], q[2], q[3], q[4]);
}

// The engine's cascade: the static filter first, the cavity predicate when it defers.
Sign cascade(const cp::Orient3dStaticFilter& filter, const Orient3dQuery& q) {
    if (const int s = filter.sign(q[0], q[1], q[2], q[3])) {
        return static_cast<Sign>(s);
    }
    return cavity_orient3d(q);
}

Sign cascade(const cp::InsphereStaticFilter& filter, const InsphereQuery& q) {
    if (const int s = filter.sign(q[0], q[1], q[2], q[3], q[4])) {
        return static_cast<Sign>(s);
    }
    return cavity_insphere(q);
}

// ---- query generators --------------------------------------------------------------------------

class Generator {
public:
    double uniform() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }

    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

    /// Moves 1 to 4 of the values 1 to 4 ulps up or down.
    template <std::size_t N>
    void nudge(std::array<double*, N> values) {
        const int moved = integer(1, 4);
        for (int k = 0; k < moved; ++k) {
            double& v = *values[static_cast<std::size_t>(integer(0, static_cast<int>(N) - 1))];
            const double toward = integer(0, 1) == 0 ? INFINITY : -INFINITY;
            for (int step = integer(1, 4); step > 0; --step) {
                v = std::nextafter(v, toward);
            }
        }
    }

private:
    std::mt19937_64 rng_{20240611};
};

/// Four integer points on the plane z = a x + b y + c.
Orient3dQuery coplanar(Generator& g) {
    const int a = g.integer(-8, 8), b = g.integer(-8, 8), c = g.integer(-1000, 1000);
    Orient3dQuery q;
    for (Point3& p : q) {
        const int x = g.integer(-1000, 1000), y = g.integer(-1000, 1000);
        p = {double(x), double(y), double(a * x + b * y + c)};
    }
    return q;
}

/// The integer points of the sphere x^2 + y^2 + z^2 = 45^2 (a few hundred of them).
std::vector<Point3> sphere_points() {
    constexpr int kR = 45;
    std::vector<Point3> points;
    for (int x = -kR; x <= kR; ++x) {
        for (int y = -kR; y <= kR; ++y) {
            const int z2 = kR * kR - x * x - y * y;
            const int z = static_cast<int>(std::lround(std::sqrt(double(std::max(z2, 0)))));
            if (z2 >= 0 && z * z == z2) {
                points.push_back({double(x), double(y), double(z)});
                if (z != 0) {
                    points.push_back({double(x), double(y), double(-z)});
                }
            }
        }
    }
    return points;
}

/// Five distinct integer points on a translated integer sphere.
InsphereQuery cospherical(Generator& g, const std::vector<Point3>& sphere) {
    const double ox = g.integer(-500, 500), oy = g.integer(-500, 500), oz = g.integer(-500, 500);
    InsphereQuery q;
    for (std::size_t i = 0; i < q.size(); ++i) {
        const Point3& p = sphere[static_cast<std::size_t>(g.integer(0, int(sphere.size()) - 1))];
        q[i] = {p.x + ox, p.y + oy, p.z + oz};
    }
    return q;
}

/// Integer points whose weights w = |p|^2 - (a x + b y + c z + d) put the lifted points
/// (p, |p|^2 - w) on one hyperplane.
Orient4dQuery cohyperplanar(Generator& g) {
    const int a = g.integer(-9, 9), b = g.integer(-9, 9), c = g.integer(-9, 9);
    const int d = g.integer(-99, 99);
    Orient4dQuery q;
    for (WeightedPoint3& p : q) {
        const double x = g.integer(-500, 500), y = g.integer(-500, 500), z = g.integer(-500, 500);
        p = {x, y, z, x * x + y * y + z * z - (a * x + b * y + c * z + d)};
    }
    return q;
}

template <typename Query>
std::array<double*, 3 * std::tuple_size_v<Query>> coordinates(Query& q) {
    std::array<double*, 3 * std::tuple_size_v<Query>> out{};
    std::size_t n = 0;
    for (auto& p : q) {
        out[n++] = &p.x;
        out[n++] = &p.y;
        out[n++] = &p.z;
    }
    return out;
}

enum class InputClass { kRandom, kNearDegenerate, kDegenerate };

const char* class_name(InputClass c) {
    switch (c) {
        case InputClass::kRandom:
            return "random";
        case InputClass::kNearDegenerate:
            return "near_degenerate";
        case InputClass::kDegenerate:
            return "degenerate";
    }
    return "?";
}

template <typename Query, typename Degenerate>
std::vector<Query> make_queries(InputClass input, Degenerate degenerate) {
    Generator g;
    std::vector<Query> queries(kQueries);
    for (Query& q : queries) {
        if (input == InputClass::kRandom) {
            for (auto& p : q) {
                p.x = g.uniform();
                p.y = g.uniform();
                p.z = g.uniform();
                if constexpr (std::is_same_v<Query, Orient4dQuery>) {
                    p.w = g.uniform();
                }
            }
            continue;
        }
        q = degenerate(g);
        if (input == InputClass::kNearDegenerate) {
            g.nudge(coordinates(q));
        }
    }
    return queries;
}

/// Times `Predicate` over the queries (a template argument, so that it inlines into the loop as it
/// would in a caller); for the cavity rows, also the fraction decided per stage.
template <auto Predicate, typename Query>
void run(benchmark::State& state, const std::vector<Query>& queries, bool count_stages) {
    std::size_t i = 0;
    for (auto _ : state) {
        const Sign s = Predicate(queries[i++ & (kQueries - 1)]);
        benchmark::DoNotOptimize(s);
    }
    state.SetItemsProcessed(state.iterations());
    if (count_stages) {
        double decided[cp::kStageCount] = {};
        for (const Query& q : queries) {
            decided[static_cast<int>(staged(q).stage)] += 1.0;
        }
        // A predicate called alone starts at the semi-static filter: the static stage is the
        // cascade's (run_cascade's "static" counter), not a column of these rows.
        for (int s = static_cast<int>(Stage::kFilter); s < cp::kStageCount; ++s) {
            state.counters[std::string(cp::stage_name(static_cast<Stage>(s)))] =
                decided[s] / double(queries.size());
        }
    }
}

/// The static filter for the bounding box of every point of the queries.
template <typename Filter, typename Query>
Filter static_filter_for(const std::vector<Query>& queries) {
    Point3 lo = queries.front()[0], hi = lo;
    for (const Query& q : queries) {
        for (const Point3& p : q) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
    }
    return Filter(lo, hi);
}

/// Times the cascade (static filter for the query set's box, then the cavity predicate).
template <typename Filter, typename Query>
void run_cascade(benchmark::State& state, const std::vector<Query>& queries) {
    const Filter filter = static_filter_for<Filter>(queries);
    std::size_t i = 0;
    for (auto _ : state) {
        const Sign s = cascade(filter, queries[i++ & (kQueries - 1)]);
        benchmark::DoNotOptimize(s);
    }
    state.SetItemsProcessed(state.iterations());
    double decided = 0.0;
    for (const Query& q : queries) {
        decided +=
            std::apply([&](const auto&... p) { return filter.sign(p...); }, q) != 0 ? 1.0 : 0.0;
    }
    state.counters["static"] = decided / double(queries.size());
}

template <auto Cavity, auto Plain, auto Oracle, typename Query, typename Degenerate>
void register_predicate(const std::string& name, Degenerate degenerate) {
    for (InputClass input :
         {InputClass::kRandom, InputClass::kNearDegenerate, InputClass::kDegenerate}) {
        const auto queries =
            std::make_shared<std::vector<Query>>(make_queries<Query>(input, degenerate));
        const std::string suffix = std::string("/") + class_name(input);
        benchmark::RegisterBenchmark(
            ("BM_" + name + "/cavity" + suffix).c_str(),
            [queries](benchmark::State& s) { run<Cavity>(s, *queries, true); });
        if constexpr (std::is_same_v<Query, Orient3dQuery>) {
            benchmark::RegisterBenchmark(("BM_" + name + "/static" + suffix).c_str(),
                                         [queries](benchmark::State& s) {
                                             run_cascade<cp::Orient3dStaticFilter>(s, *queries);
                                         });
        } else if constexpr (std::is_same_v<Query, InsphereQuery>) {
            benchmark::RegisterBenchmark(("BM_" + name + "/static" + suffix).c_str(),
                                         [queries](benchmark::State& s) {
                                             run_cascade<cp::InsphereStaticFilter>(s, *queries);
                                         });
        }
        benchmark::RegisterBenchmark(
            ("BM_" + name + "/plain" + suffix).c_str(),
            [queries](benchmark::State& s) { run<Plain>(s, *queries, false); });
        benchmark::RegisterBenchmark(
            ("BM_" + name + "/oracle" + suffix).c_str(),
            [queries](benchmark::State& s) { run<Oracle>(s, *queries, false); });
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<Point3> sphere = sphere_points();
    register_predicate<cavity_orient3d, plain_orient3d, oracle_orient3d, Orient3dQuery>("orient3d",
                                                                                        coplanar);
    register_predicate<cavity_insphere, plain_insphere, oracle_insphere, InsphereQuery>(
        "insphere", [&sphere](Generator& g) { return cospherical(g, sphere); });
    register_predicate<cavity_orient4d, plain_orient4d, oracle_orient4d, Orient4dQuery>(
        "orient4d", cohyperplanar);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
