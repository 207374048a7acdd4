#include "cavity/core/gen/generate.h"

#include <array>
#include <cmath>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/base/parse_number.h"
#include "cavity/core/base/random.h"
#include "lattice_sphere.h"

namespace cavity::core {

namespace {

constexpr std::array<Distribution, 11> kDistributions = {{
    {"cube", "uniform in the unit cube [0,1)^3"},
    {"ball", "uniform in the unit ball (rejection from the cube [-1,1)^3)"},
    {"sphere", "random unit vectors, rounded: nearly cospherical"},
    {"gaussian", "gaussian clusters (sigma 0.05) around max(1, min(16, n/256)) random centres"},
    {"grid", "the integer grid {0..k-1}^3, k = round(cbrt n): k^3 points"},
    {"cospherical",
     "exactly cospherical integer points: the first n, in lexicographic order, of the integer "
     "solutions of x^2+y^2+z^2 = s for the least s that has at least n"},
    {"paraboloid", "z = x^2+y^2 over the integer grid x, y in {-floor(k/2)..}, k = round(sqrt n)"},
    {"moment", "the moment curve (t, t^2, t^3), t = 0..n-1"},
    {"skew-lines", "ceil(n/2) points (t,0,0) and floor(n/2) points (0,t,1), t = 0, 1, ..."},
    {"pierced-skew-lines",
     "skew-lines of n-1 points, then the point midway between their middles: inserted last, it "
     "deletes a constant fraction of the Theta(n^2) tetrahedra (§5.2)"},
    {"layers", "4 coplanar layers z = 0..3 (point i on layer i mod 4), x, y uniform in [0,1)"},
}};

constexpr double kClusterSigma = 0.05;
constexpr std::uint64_t kLayers = 4;

// round(v^(1/root)) for root 2 or 3, in integers: with k the floor of the root, the root is at
// least k + 1/2 exactly when (2k+1)^root <= 2^root v (never a tie: the left side is odd).
std::uint64_t rounded_root(std::uint64_t v, int root) {
    const auto power = [root](std::uint64_t k) { return root == 2 ? k * k : k * k * k; };
    auto k = static_cast<std::uint64_t>(root == 2 ? std::sqrt(static_cast<double>(v))
                                                  : std::cbrt(static_cast<double>(v)));
    while (k > 0 && power(k) > v) {
        --k;
    }
    while (power(k + 1) <= v) {
        ++k;
    }
    return power(2 * k + 1) <= (root == 2 ? 4 : 8) * v ? k + 1 : k;
}

void cube(std::vector<Point3>& out, std::size_t n, Random& random) {
    for (std::size_t i = 0; i < n; ++i) {
        const double x = random.uniform01();
        const double y = random.uniform01();
        const double z = random.uniform01();
        out.push_back({x, y, z});
    }
}

// A uniform point of the closed unit ball, by rejection.
Point3 in_ball(Random& random) {
    for (;;) {
        const double x = random.uniform(-1.0, 1.0);
        const double y = random.uniform(-1.0, 1.0);
        const double z = random.uniform(-1.0, 1.0);
        if (x * x + y * y + z * z <= 1.0) {
            return {x, y, z};
        }
    }
}

void ball(std::vector<Point3>& out, std::size_t n, Random& random) {
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(in_ball(random));
    }
}

// Normalising a uniform point of the ball gives a uniform direction; points too near the centre
// are redrawn so that the division does not magnify their rounding.
void sphere(std::vector<Point3>& out, std::size_t n, Random& random) {
    while (out.size() < n) {
        const Point3 p = in_ball(random);
        const double norm2 = p.x * p.x + p.y * p.y + p.z * p.z;
        if (norm2 < 1e-4) {
            continue;
        }
        const double norm = std::sqrt(norm2);
        out.push_back({p.x / norm, p.y / norm, p.z / norm});
    }
}

void gaussian(std::vector<Point3>& out, std::size_t n, Random& random) {
    const std::size_t clusters = std::max<std::size_t>(1, std::min<std::size_t>(16, n / 256));
    std::vector<Point3> centres;
    cube(centres, clusters, random);
    for (std::size_t i = 0; i < n; ++i) {
        const Point3& c = centres[random.below(clusters)];
        const double x = c.x + kClusterSigma * random.normal();
        const double y = c.y + kClusterSigma * random.normal();
        const double z = c.z + kClusterSigma * random.normal();
        out.push_back({x, y, z});
    }
}

void grid(std::vector<Point3>& out, std::size_t n) {
    const std::uint64_t k = rounded_root(n, 3);
    for (std::uint64_t i = 0; i < k; ++i) {
        for (std::uint64_t j = 0; j < k; ++j) {
            for (std::uint64_t l = 0; l < k; ++l) {
                out.push_back(
                    {static_cast<double>(i), static_cast<double>(j), static_cast<double>(l)});
            }
        }
    }
}

void paraboloid(std::vector<Point3>& out, std::size_t n) {
    const auto k = static_cast<std::int64_t>(rounded_root(n, 2));
    for (std::int64_t i = 0; i < k; ++i) {
        for (std::int64_t j = 0; j < k; ++j) {
            const std::int64_t x = i - k / 2;
            const std::int64_t y = j - k / 2;
            out.push_back({static_cast<double>(x),
                           static_cast<double>(y),
                           static_cast<double>(x * x + y * y)});
        }
    }
}

void moment(std::vector<Point3>& out, std::size_t n) {
    // Beyond 2^53 not every integer is a double, and t^3 would be rounded off the curve.
    const std::uint64_t last = n - 1;
    if (last * last * last > (std::uint64_t{1} << 53)) {
        throw Error("moment curve: t^3 is not an exact double for t = " + std::to_string(last) +
                    "; n must be at most 208064");
    }
    for (std::uint64_t t = 0; t < n; ++t) {
        out.push_back(
            {static_cast<double>(t), static_cast<double>(t * t), static_cast<double>(t * t * t)});
    }
}

void skew_lines(std::vector<Point3>& out, std::size_t n) {
    for (std::size_t t = 0; t < (n + 1) / 2; ++t) {
        out.push_back({static_cast<double>(t), 0.0, 0.0});
    }
    for (std::size_t t = 0; t < n / 2; ++t) {
        out.push_back({0.0, static_cast<double>(t), 1.0});
    }
}

// (m1-1)/2 and (m2-1)/2 are half-integers, so the middle point is exact.
void pierced_skew_lines(std::vector<Point3>& out, std::size_t n) {
    skew_lines(out, n - 1);
    const std::size_t m1 = n / 2;        // ceil((n-1)/2)
    const std::size_t m2 = (n - 1) / 2;  // floor((n-1)/2)
    out.push_back({(static_cast<double>(m1) - 1) / 2, (static_cast<double>(m2) - 1) / 2, 0.5});
}

void layers(std::vector<Point3>& out, std::size_t n, Random& random) {
    for (std::size_t i = 0; i < n; ++i) {
        const double x = random.uniform01();
        const double y = random.uniform01();
        out.push_back({x, y, static_cast<double>(i % kLayers)});
    }
}

void add_weights(PointSet& set, const WeightSpec& spec, std::uint64_t seed) {
    switch (spec.kind) {
        case WeightSpec::Kind::kNone:
            return;
        case WeightSpec::Kind::kZero:
            set.weights.assign(set.size(), 0.0);
            return;
        case WeightSpec::Kind::kEqual:
            set.weights.assign(set.size(), spec.a);
            return;
        case WeightSpec::Kind::kUniform: {
            Random random(~seed);
            set.weights.reserve(set.size());
            for (std::size_t i = 0; i < set.size(); ++i) {
                set.weights.push_back(random.uniform(spec.a, spec.b));
            }
            return;
        }
    }
}

double weight_number(std::string_view spec, std::string_view token) {
    const ParsedNumber parsed = parse_number(token);
    if (!parsed.value) {
        throw Error("weights '" + std::string(spec) + "': " + parsed.error);
    }
    return *parsed.value;
}

}  // namespace

WeightSpec parse_weight_spec(std::string_view spec) {
    if (spec == "none") {
        return {};
    }
    if (spec == "zero") {
        return {WeightSpec::Kind::kZero, 0.0, 0.0};
    }
    if (spec.starts_with("equal:")) {
        return {WeightSpec::Kind::kEqual, weight_number(spec, spec.substr(6)), 0.0};
    }
    if (spec.starts_with("uniform:")) {
        const std::string_view bounds = spec.substr(8);
        const std::size_t colon = bounds.find(':');
        if (colon == std::string_view::npos) {
            throw Error("weights '" + std::string(spec) + "': expected uniform:A:B");
        }
        const double a = weight_number(spec, bounds.substr(0, colon));
        const double b = weight_number(spec, bounds.substr(colon + 1));
        if (!(a < b) || !std::isfinite(b - a)) {
            throw Error("weights '" + std::string(spec) + "': need A < B with B - A finite");
        }
        return {WeightSpec::Kind::kUniform, a, b};
    }
    throw Error("unknown weights '" + std::string(spec) +
                "' (expected none, zero, equal:W or uniform:A:B)");
}

std::span<const Distribution> distributions() {
    return kDistributions;
}

PointSet generate_points(std::string_view distribution,
                         std::size_t n,
                         std::uint64_t seed,
                         const WeightSpec& weights) {
    if (n == 0 || n > 0xFFFF'FFFFu) {
        throw Error("the number of points must be between 1 and 2^32-1, got " + std::to_string(n));
    }
    PointSet set;
    set.source =
        std::string(distribution) + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
    std::vector<Point3>& out = set.points;
    Random random(seed);
    if (distribution == "cube") {
        cube(out, n, random);
    } else if (distribution == "ball") {
        ball(out, n, random);
    } else if (distribution == "sphere") {
        sphere(out, n, random);
    } else if (distribution == "gaussian") {
        gaussian(out, n, random);
    } else if (distribution == "grid") {
        grid(out, n);
    } else if (distribution == "cospherical") {
        LatticeSphere lattice = lattice_sphere(n);
        out = std::move(lattice.points);
        set.source += " R^2=" + std::to_string(lattice.radius_squared);
    } else if (distribution == "paraboloid") {
        paraboloid(out, n);
    } else if (distribution == "moment") {
        moment(out, n);
    } else if (distribution == "skew-lines") {
        skew_lines(out, n);
    } else if (distribution == "pierced-skew-lines") {
        pierced_skew_lines(out, n);
    } else if (distribution == "layers") {
        layers(out, n, random);
    } else {
        throw Error("unknown distribution '" + std::string(distribution) + "'");
    }
    add_weights(set, weights, seed);
    return set;
}

}  // namespace cavity::core
