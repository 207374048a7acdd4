#include "query_generators.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace cavity::predicates::testing {

namespace {

using Vec = std::array<std::int64_t, 3>;

// All integer points of the sphere x^2 + y^2 + z^2 = 882 (324 of them): exactly cospherical.
const std::vector<Vec>& sphere_882() {
    static const std::vector<Vec> points = [] {
        std::vector<Vec> result;
        for (std::int64_t x = -29; x <= 29; ++x) {
            for (std::int64_t y = -29; y <= 29; ++y) {
                for (std::int64_t z = -29; z <= 29; ++z) {
                    if (x * x + y * y + z * z == 882) {
                        result.push_back({x, y, z});
                    }
                }
            }
        }
        return result;
    }();
    return points;
}

Vec random_vec(Rng& rng, std::int64_t bound) {
    return {rng.integer(-bound, bound), rng.integer(-bound, bound), rng.integer(-bound, bound)};
}

void set_point(Query& q, std::size_t i, const Vec& p) {
    for (std::size_t j = 0; j < 3; ++j) {
        q.v[stride(q.kind) * i + j] = static_cast<double>(p[j]);
    }
}

// Points o + i u + j v of one integer plane; small i, j repeat points or make lines now and then.
Query coplanar(Rng& rng) {
    Query q{Kind::kOrient3d};
    const Vec o = random_vec(rng, 1 << 20);
    const Vec u = random_vec(rng, 1000);
    const Vec v = random_vec(rng, 1000);
    for (std::size_t p = 0; p < 4; ++p) {
        const std::int64_t i = rng.integer(-8, 8), j = rng.integer(-8, 8);
        set_point(
            q,
            p,
            {o[0] + i * u[0] + j * v[0], o[1] + i * u[1] + j * v[1], o[2] + i * u[2] + j * v[2]});
    }
    return q;
}

Query cospherical(Kind k, Rng& rng) {
    Query q{k};
    const std::vector<Vec>& sphere = sphere_882();
    const Vec centre = random_vec(rng, 1 << 20);
    const std::int64_t scale = rng.integer(1, 4);
    for (std::size_t p = 0; p < 5; ++p) {
        const Vec& s = sphere[static_cast<std::size_t>(
            rng.integer(0, static_cast<std::int64_t>(sphere.size()) - 1))];
        set_point(
            q, p, {centre[0] + scale * s[0], centre[1] + scale * s[1], centre[2] + scale * s[2]});
    }
    return q;  // orient4d weights stay 0: the lifted points lie on the sphere's hyperplane
}

// Lifted heights |p|^2 - w = h(p) for one integer affine h: every lifted point on one hyperplane.
Query cohyperplanar(Rng& rng) {
    Query q{Kind::kOrient4d};
    const Vec gradient = random_vec(rng, 1 << 10);
    const std::int64_t offset = rng.integer(-(1 << 20), 1 << 20);
    for (std::size_t p = 0; p < 5; ++p) {
        const Vec x = random_vec(rng, 1 << 10);
        set_point(q, p, x);
        const std::int64_t norm = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        const std::int64_t h =
            gradient[0] * x[0] + gradient[1] * x[1] + gradient[2] * x[2] + offset;
        q.v[4 * p + 3] = static_cast<double>(norm - h);
    }
    return q;
}

Query nudged(Query q, Rng& rng) {
    const auto n = static_cast<std::int64_t>(value_count(q.kind));
    const std::int64_t moves = rng.integer(1, 3);
    for (std::int64_t m = 0; m < moves; ++m) {
        double& x = q.v[static_cast<std::size_t>(rng.integer(0, n - 1))];
        const double direction = rng.coin() ? std::numeric_limits<double>::infinity()
                                            : -std::numeric_limits<double>::infinity();
        for (std::int64_t ulp = rng.integer(1, 4); ulp > 0; --ulp) {
            x = std::nextafter(x, direction);
        }
    }
    return q;
}

// Multiplies coordinates by `s` and weights by `s2` (the square of s, or its own factor when that
// square is not representable), rounding each product.
Query scaled(Query q, double s, double s2) {
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        q.v[i] *= is_weight(q.kind, i) ? s2 : s;
    }
    return q;
}

// Coordinates times 2^e and weights times 2^2e (2^e when 2^2e is out of range): exact, unless a
// product leaves the normal range.
Query scaled_by_power_of_two(Query q, int e) {
    const int weight_exponent = std::abs(2 * e) <= 1020 ? 2 * e : e;
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        q.v[i] = std::ldexp(q.v[i], is_weight(q.kind, i) ? weight_exponent : e);
    }
    return q;
}

Query decimal_scaled(const Query& q, Rng& rng) {
    constexpr std::array<double, 5> kSteps{0.1, 0.01, 0.3, 1.1, 0.007};
    const double step = kSteps[static_cast<std::size_t>(rng.integer(0, kSteps.size() - 1))];
    return scaled(q, step, step * step);
}

// Coordinates of one point multiplied by 2^e_p with an unrelated e_p per point (weights, all below
// 2^23, by 2^2e_p):
// exact unless the product leaves the normal range.
Query mixed_scales(Query q, Rng& rng) {
    const std::size_t st = stride(q.kind);
    for (std::size_t p = 0; p < point_count(q.kind); ++p) {
        const int e = static_cast<int>(rng.integer(-480, 480));
        for (std::size_t j = 0; j < st; ++j) {
            double& x = q.v[st * p + j];
            x = std::ldexp(x, is_weight(q.kind, st * p + j) ? 2 * e : e);
        }
    }
    return q;
}

// A small configuration (spacing 1e-3 .. 1) placed at a large offset (1e6 .. 1e15), as with
// georeferenced data: every sum rounds, and the differences carry only a few bits.
Query offset(Query q, Rng& rng) {
    const double spacing = std::ldexp(1.0, static_cast<int>(rng.integer(-10, 0)));
    std::array<double, 3> origin{};
    for (double& o : origin) {
        o = std::pow(10.0, static_cast<double>(rng.integer(6, 15))) * (1.0 + rng.unit() / 4);
        o = rng.coin() ? o : -o;
    }
    const std::size_t st = stride(q.kind);
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        q.v[i] =
            is_weight(q.kind, i) ? q.v[i] * spacing * spacing : origin[i % st] + q.v[i] * spacing;
    }
    return q;
}

Query degenerate_or_near(Kind k, Rng& rng) {
    return rng.coin() ? degenerate_query(k, rng) : near_degenerate_query(k, rng);
}

}  // namespace

std::int64_t Rng::integer(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(engine_);
}

double Rng::unit() {
    return std::ldexp(static_cast<double>(engine_() >> 11), -52) - 1.0;
}

Query random_query(Kind k, Rng& rng) {
    Query q{k};
    for (std::size_t i = 0; i < value_count(k); ++i) {
        q.v[i] = rng.unit();
    }
    return q;
}

Query degenerate_query(Kind k, Rng& rng) {
    switch (k) {
        case Kind::kOrient3d:
            return coplanar(rng);
        case Kind::kInsphere:
            return cospherical(k, rng);
        case Kind::kOrient4d:
            return rng.coin() ? cohyperplanar(rng) : cospherical(k, rng);
    }
    return Query{k};
}

Query near_degenerate_query(Kind k, Rng& rng) {
    const Query q = degenerate_query(k, rng);
    return rng.coin() ? nudged(q, rng) : decimal_scaled(q, rng);
}

Query extreme_query(Kind k, Rng& rng) {
    const Query base = rng.coin() ? random_query(k, rng) : degenerate_or_near(k, rng);
    switch (rng.integer(0, 5)) {
        case 0: {  // 2^+-1000, or 2^+-500 so that weights can take the square and stay degenerate
            const bool half = rng.coin();
            const auto e = static_cast<int>(half ? rng.integer(450, 495) : rng.integer(900, 1000));
            return scaled_by_power_of_two(base, rng.coin() ? e : -e - (half ? 0 : 60));
        }
        case 1: {  // 1e+-300: every product rounds (weights by the same factor: no square exists)
            const int e =
                static_cast<int>(rng.coin() ? rng.integer(280, 300) : rng.integer(-320, -280));
            const double s = std::pow(10.0, e);
            return scaled(base, s, s);
        }
        case 2:  // subnormal: degenerate integers times 2^-1074 stay exact (and stay degenerate)
            return scaled(degenerate_or_near(k, rng), 0x1p-1074, 0x1p-1074);
        case 3:  // near the bottom of the normal range, crossing into subnormals
            return scaled(base, 1e-310, 1e-310);
        case 4:
            return mixed_scales(base, rng);
        default:
            return offset(base, rng);
    }
}

Query any_query(Kind k, Rng& rng) {
    switch (rng.integer(0, 3)) {
        case 0:
            return random_query(k, rng);
        case 1:
            return degenerate_query(k, rng);
        case 2:
            return near_degenerate_query(k, rng);
        default:
            return extreme_query(k, rng);
    }
}

}  // namespace cavity::predicates::testing
