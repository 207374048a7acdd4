#include "axis_protection_point.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "cavity/predicates/detail/expansion.h"

namespace cavity::core {

namespace {

using predicates::Point3;
namespace expansion = predicates::detail;

/// An exact sum of doubles (expansion.h). Values along the segment have at most five components
/// and no expression below adds more than four of them.
struct Exact {
    std::array<double, 32> c{};
    int n = 0;
};

Exact exact(double x) {
    Exact e;
    if (x != 0.0) {
        e.c[0] = x;
        e.n = 1;
    }
    return e;
}

Exact operator+(const Exact& a, const Exact& b) {
    Exact h;
    h.n = expansion::expansion_sum(a.n, a.c.data(), b.n, b.c.data(), h.c.data());
    return h;
}

Exact operator-(Exact a) {
    for (int i = 0; i < a.n; ++i) {
        a.c[static_cast<std::size_t>(i)] = -a.c[static_cast<std::size_t>(i)];
    }
    return a;
}

Exact operator-(const Exact& a, const Exact& b) {
    return a + (-b);
}

/// a 2^k, exact: the ranges checked on entry keep every component normal and finite.
Exact scaled(Exact a, int k) {
    for (int i = 0; i < a.n; ++i) {
        a.c[static_cast<std::size_t>(i)] = std::ldexp(a.c[static_cast<std::size_t>(i)], k);
    }
    return a;
}

int compare(const Exact& a, const Exact& b) {
    const Exact d = a - b;
    return expansion::expansion_sign(d.n, d.c.data());
}

double approximate(const Exact& e) {
    double sum = 0.0;
    for (int i = 0; i < e.n; ++i) {
        sum += e.c[static_cast<std::size_t>(i)];
    }
    return sum;
}

/// x y exactly.
Exact product(double x, double y) {
    double hi = 0.0;
    double lo = 0.0;
    expansion::two_product(x, y, hi, lo);
    Exact e;
    if (lo != 0.0) {
        e.c[static_cast<std::size_t>(e.n++)] = lo;
    }
    if (hi != 0.0) {
        e.c[static_cast<std::size_t>(e.n++)] = hi;
    }
    return e;
}

/// floor(y) for |y| <= 2^53, or nullopt beyond.
std::optional<std::int64_t> floor_of(const Exact& y) {
    double f = std::floor(approximate(y));
    if (!(std::abs(f) <= 0x1p53)) {
        return std::nullopt;
    }
    // The approximation is within a few units of y: a few exact steps settle it.
    for (int step = 0; step < 4; ++step) {
        if (compare(y, exact(f)) < 0) {
            f -= 1.0;
        } else if (compare(y, exact(f) + exact(1.0)) >= 0) {
            f += 1.0;
        } else {
            return static_cast<std::int64_t>(f);
        }
    }
    return std::nullopt;
}

/// The spacing exponent rational_protection_point's spacing_exponent takes at value m (not
/// zero): that of |m| rounded to nearest. With 2^E <= |m| < 2^(E+1), rounding gives 2^(E+1)
/// above the midpoint 2^(E+1) - 2^(E-53) between the two doubles around it. nullopt within a
/// unit in the last place of that midpoint, where the answer would rest on the conversion's
/// handling of ties, and outside the normal range.
std::optional<int> spacing_exponent(Exact m) {
    if (approximate(m) < 0.0) {
        m = -m;
    }
    const double estimate = approximate(m);
    if (!(estimate >= 0x1p-900 && estimate <= 0x1p+900)) {
        return std::nullopt;
    }
    int e = std::ilogb(estimate);
    while (compare(m, exact(std::ldexp(1.0, e))) < 0) {
        --e;
    }
    while (compare(m, exact(std::ldexp(1.0, e + 1))) >= 0) {
        ++e;
    }
    const Exact midpoint = exact(std::ldexp(1.0, e + 1)) - exact(std::ldexp(1.0, e - 53));
    if (compare(m, midpoint - exact(std::ldexp(1.0, e - 52))) <= 0) {
        return e - 52;
    }
    if (compare(m, midpoint + exact(std::ldexp(1.0, e - 52))) >= 0) {
        return e + 1 - 52;
    }
    return std::nullopt;
}

/// Zero or a magnitude in [2^-300, max]: products of two such numbers and their rounding errors
/// stay normal, so every expansion below is exact. False on NaN.
bool in_range(double x, double max) {
    return x == 0.0 || (std::abs(x) >= 0x1p-300 && std::abs(x) <= max);
}

}  // namespace

AxisSearch axis_protection_point(
    const Point3& a, const Point3& b, double target, double lo_bound, double hi_bound) {
    const std::array<double, 3> pa{a.x, a.y, a.z};
    const std::array<double, 3> pb{b.x, b.y, b.z};
    std::size_t axis = 3;
    for (std::size_t c = 0; c < 3; ++c) {
        if (pa[c] != pb[c]) {
            if (axis < 3) {
                return {};
            }
            axis = c;
        }
    }
    const double window_lo = std::max(lo_bound, 0.0);
    const double window_hi = std::min(hi_bound, 1.0);
    if (axis == 3 || !in_range(pa[axis], 0x1p+300) || !in_range(pb[axis], 0x1p+300) ||
        !in_range(window_lo, 1.0) || !in_range(window_hi, 1.0) || !in_range(target, 0x1p+10)) {
        return {};
    }
    AxisSearch out;
    out.handled = true;
    if (!(window_lo < window_hi)) {
        return out;
    }
    const double from = pa[axis];
    const double to = pb[axis];
    // The general search works in the parameter t; here in w = sigma (a + t (b - a)), the
    // varying coordinate signed to increase with t: an affine map that keeps every order,
    // every tie of distances and every piece, and turns the parameters of the double points
    // into multiples of a power of two.
    const double sigma = to > from ? 1.0 : -1.0;
    const auto along = [&](double t) {
        const Exact v = exact(from) + product(t, to) - product(t, from);
        return sigma > 0 ? v : -v;
    };
    const Exact lo = along(window_lo);
    const Exact hi = along(window_hi);
    const Exact aim = along(target);
    // The general search's cuts: zero and the powers of two where the coordinate changes sign
    // or binade strictly between a and b (add_breakpoints in protection_point.cpp), here those
    // strictly inside the window; with the window's ends they bound the pieces, in order.
    std::vector<double> cuts;
    const auto add = [&](double v) {
        if (std::min(from, to) < v && v < std::max(from, to)) {
            cuts.push_back(sigma * v);
        }
    };
    add(0.0);
    for (const double side : {1.0, -1.0}) {
        const double low = std::min(side * from, side * to);
        const double high = std::max(side * from, side * to);
        if (high <= 0) {
            continue;
        }
        const int e_top = std::ilogb(high);
        const int e_lo = std::max({low > 0 ? std::ilogb(low) : -1022, -1022, e_top - 60});
        for (int e = e_lo; e <= e_top; ++e) {
            add(side * std::ldexp(1.0, e));
        }
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<Exact> bounds{lo};
    for (const double w : cuts) {
        if (compare(exact(w), lo) > 0 && compare(exact(w), hi) < 0) {
            bounds.push_back(exact(w));
        }
    }
    bounds.push_back(hi);
    // The pieces nearest the aim first, ties in order along the segment (a stable sort).
    const std::size_t count = bounds.size() - 1;
    std::vector<Exact> distances(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (compare(bounds[i + 1], aim) < 0) {
            distances[i] = aim - bounds[i + 1];
        } else if (compare(bounds[i], aim) > 0) {
            distances[i] = bounds[i] - aim;
        }
    }
    std::vector<std::size_t> pieces(count);
    std::iota(pieces.begin(), pieces.end(), std::size_t{0});
    std::stable_sort(pieces.begin(), pieces.end(), [&](std::size_t i, std::size_t j) {
        return compare(distances[i], distances[j]) < 0;
    });
    for (const std::size_t i : pieces) {
        const Exact& p_lo = bounds[i];
        const Exact& p_hi = bounds[i + 1];
        const std::optional<int> q = spacing_exponent(scaled(p_lo + p_hi, -1));
        if (!q) {
            return {};
        }
        // The double points of the piece: w = k 2^q for k_min <= k <= k_max, t = 0 and t = 1
        // (the segment's ends) left out.
        const std::optional<std::int64_t> ceil_lo = floor_of(-scaled(p_lo, -*q));
        const std::optional<std::int64_t> floor_hi = floor_of(scaled(p_hi, -*q));
        if (!ceil_lo || !floor_hi) {
            return {};
        }
        std::int64_t k_min = -*ceil_lo;
        std::int64_t k_max = *floor_hi;
        const auto w_of = [&](std::int64_t k) { return std::ldexp(static_cast<double>(k), *q); };
        if (w_of(k_min) == sigma * from) {
            ++k_min;
        }
        if (w_of(k_max) == sigma * to) {
            --k_max;
        }
        if (k_min > k_max) {
            continue;
        }
        // The member nearest the aim, halves rounded up: floor(aim / 2^q + 1/2), clamped. An aim
        // outside the piece clamps to its nearer end without the division.
        std::int64_t k = k_min;
        if (compare(aim, p_hi) >= 0) {
            k = k_max;
        } else if (compare(aim, p_lo) > 0) {
            const std::optional<std::int64_t> nearest = floor_of(scaled(aim, -*q) + exact(0.5));
            if (!nearest) {
                return {};
            }
            k = std::clamp(*nearest, k_min, k_max);
        }
        // As the general search converts its rationals: a zero coordinate is +0.
        std::array<double, 3> p{pa[0] + 0.0, pa[1] + 0.0, pa[2] + 0.0};
        p[axis] = k == 0 ? 0.0 : sigma * w_of(k);
        out.point = Point3{p[0], p[1], p[2]};
        return out;
    }
    return out;
}

}  // namespace cavity::core
