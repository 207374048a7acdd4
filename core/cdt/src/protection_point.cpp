// The points of a segment whose coordinates are doubles, found exactly: where protect_edges can
// split a PLC edge without moving it.
//
// Along segment ab, p(t) = a + t(b - a). Where each coordinate keeps one binade (|p_c| in
// [2^e, 2^(e+1)], or the subnormal range), p_c is a double exactly when it is a multiple of that
// binade's spacing 2^q. For one coordinate the parameters where this holds form an arithmetic
// progression {(2^q k - a_c) / (b_c - a_c) : k integer}; a point with three double coordinates is a
// common member of the three progressions, which is again a progression (or nothing), found by the
// extended Euclidean algorithm. Cutting [0, 1] wherever a coordinate changes binade or sign and
// solving each piece finds every such point, with one exception that keeps the cost bounded: the
// binades more than kDepth = 60 below a coordinate's largest on the segment (where it passes
// within 2^-60 of its range from zero) form one piece, solved with the spacing of its top binade,
// which finds only the points there whose coordinate is a multiple of that spacing (zero included).
// Everything found is a double point of the segment: the spacing used is never finer than the
// binade's. Between decimal doubles nearly every window holds no such point; a sieve of integer
// congruences (double_point_sieve.h) says so first, without a rational. Along a segment where one
// coordinate alone varies, the same search runs in double expansions (axis_protection_point.h).
#include "protection_point.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "axis_protection_point.h"
#include "cavity/core/cdt/edge_protection.h"
#include "double_point_sieve.h"

namespace cavity::core {

namespace {

using Integer = boost::multiprecision::mpz_int;
using Rational = boost::multiprecision::mpq_rational;

/// The rationals offset + k * step, k integer (step > 0).
struct Progression {
    Rational offset;
    Rational step;
};

Integer floor_div(const Integer& n, const Integer& d) {
    Integer q = n / d;  // truncates toward zero
    if ((n % d != 0) && ((n < 0) != (d < 0))) {
        --q;
    }
    return q;
}

Integer floor_of(const Rational& x) {
    return floor_div(numerator(x), denominator(x));
}

Integer ceil_of(const Rational& x) {
    return -floor_of(-x);
}

Integer lcm_of(const Integer& a, const Integer& b) {
    return a / gcd(a, b) * b;
}

/// The common members of two progressions.
std::optional<Progression> intersect(const Progression& p, const Progression& q) {
    const Integer scale = lcm_of(lcm_of(denominator(p.offset), denominator(p.step)),
                                 lcm_of(denominator(q.offset), denominator(q.step)));
    const Integer o1 = numerator(Rational(p.offset * scale));
    const Integer s1 = numerator(Rational(p.step * scale));
    const Integer o2 = numerator(Rational(q.offset * scale));
    const Integer s2 = numerator(Rational(q.step * scale));
    // o1 + i s1 = o2 + j s2  <=>  i s1 - j s2 = o2 - o1, solvable when gcd(s1, s2) divides it.
    Integer g;
    Integer x;
    Integer y;
    mpz_gcdext(g.backend().data(),
               x.backend().data(),
               y.backend().data(),
               s1.backend().data(),
               s2.backend().data());
    const Integer diff = o2 - o1;
    if (diff % g != 0) {
        return std::nullopt;
    }
    const Integer step = s1 / g * s2;
    Integer first = o1 + x * (diff / g) * s1;
    first -= floor_div(first, step) * step;  // the least non-negative member, to keep it small
    return Progression{Rational(first, scale), Rational(step, scale)};
}

/// Spacing exponent q of the doubles in the binade of |v| (v != 0): doubles there are the
/// multiples of 2^q.
int spacing_exponent(const Rational& v) {
    // convert_to<double> rounds to nearest, so a value just below a power of two may give the
    // spacing of the binade above: a coarser one, whose multiples are doubles in this binade too,
    // so the progression loses points but every point it keeps is still a double.
    const double d = std::abs(v.convert_to<double>());
    if (d < std::ldexp(1.0, -1022)) {
        return -1074;
    }
    return std::ilogb(d) - 52;
}

constexpr int kDepth = 60;

/// Parameters in (0, 1) where coordinate a_c + t d_c changes sign or binade, except some outside
/// [lo, hi]: a cut outside the window bounds no piece in it (the window's ends are cuts), and the
/// binade cuts are dozens per coordinate, each a rational division and then sorted, where a
/// window of a tenth of the segment holds a few.
void add_breakpoints(double a, double b, double lo, double hi, std::vector<Rational>& out) {
    if (a == b) {
        return;
    }
    const Rational ea(a);
    const Rational d = Rational(b) - ea;
    const auto add = [&](double v) {
        // Two differences and a quotient, each rounded once, put the estimate within a relative
        // 2^-50 of the parameter when nothing overflows or underflows (the range test): a margin
        // of 2^-40 of it, rounding of the comparison included, leaves out only cuts outside.
        const double estimate = (v - a) / (b - a);
        const double magnitude = std::abs(estimate);
        if (magnitude > 0x1p-900 && magnitude < 0x1p900) {  // false on NaN
            const double slack = 0x1p-40 * magnitude;
            if (estimate + slack < lo || estimate - slack > hi) {
                return;
            }
        }
        const Rational t = (Rational(v) - ea) / d;
        if (t > 0 && t < 1) {
            out.push_back(t);
        }
    };
    add(0.0);
    for (const double sign : {1.0, -1.0}) {
        const double low = std::min(sign * a, sign * b);  // magnitudes on this side of zero
        const double high = std::max(sign * a, sign * b);
        if (high <= 0) {
            continue;
        }
        // Binades more than kDepth below the largest are merged into one piece (see the top).
        const int e_top = std::ilogb(high);
        const int e_lo = std::max({low > 0 ? std::ilogb(low) : -1022, -1022, e_top - kDepth});
        for (int e = e_lo; e <= e_top; ++e) {
            add(sign * std::ldexp(1.0, e));
        }
    }
}

}  // namespace

std::optional<Point3> protection_point(const Point3& a, const Point3& b) {
    return protection_point(a, b, 0.5, 0.0, 1.0);
}

std::optional<Point3> protection_point(
    const Point3& a, const Point3& b, double target, double lo_bound, double hi_bound) {
    const double lo = std::max(lo_bound, 0.0);
    const double hi = std::min(hi_bound, 1.0);
    if (!(lo < hi) || !may_hold_double_point(a, b, lo, hi)) {
        return std::nullopt;
    }
    if (const AxisSearch axis = axis_protection_point(a, b, target, lo_bound, hi_bound);
        axis.handled) {
        return axis.point;
    }
    return rational_protection_point(a, b, target, lo_bound, hi_bound);
}

std::optional<Point3> rational_protection_point(
    const Point3& a, const Point3& b, double target, double lo_bound, double hi_bound) {
    const std::array<double, 3> pa{a.x, a.y, a.z};
    const std::array<double, 3> pb{b.x, b.y, b.z};
    const Rational window_lo(std::max(lo_bound, 0.0));
    const Rational window_hi(std::min(hi_bound, 1.0));
    if (window_lo >= window_hi) {
        return std::nullopt;
    }
    std::vector<Rational> cuts{window_lo, window_hi};
    for (std::size_t c = 0; c < 3; ++c) {
        add_breakpoints(pa[c], pb[c], std::max(lo_bound, 0.0), std::min(hi_bound, 1.0), cuts);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    // The pieces inside the window, nearest the target first.
    const Rational aim(target);
    const auto distance = [&](std::size_t i) -> Rational {
        if (cuts[i] <= aim && aim <= cuts[i + 1]) {
            return 0;
        }
        return cuts[i + 1] < aim ? aim - cuts[i + 1] : cuts[i] - aim;
    };
    std::vector<std::size_t> pieces;
    // Each piece's distance once: the sort compared rationals made afresh on every comparison.
    std::vector<Rational> distances(cuts.size());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (window_lo <= cuts[i] && cuts[i + 1] <= window_hi) {
            pieces.push_back(i);
            distances[i] = distance(i);
        }
    }
    std::stable_sort(pieces.begin(), pieces.end(), [&](std::size_t i, std::size_t j) {
        return distances[i] < distances[j];
    });
    for (std::size_t i : pieces) {
        const Rational lo = cuts[i];
        const Rational hi = cuts[i + 1];
        const Rational mid = (lo + hi) / 2;
        std::optional<Progression> t;
        bool first = true;
        for (std::size_t c = 0; c < 3 && (first || t); ++c) {
            if (pa[c] == pb[c]) {
                continue;
            }
            const Rational ea(pa[c]);
            const Rational d = Rational(pb[c]) - ea;
            const int q = spacing_exponent(ea + mid * d);
            const Rational spacing =
                q >= 0 ? Rational(Integer(1) << q) : Rational(Integer(1), Integer(1) << -q);
            const Progression own{-ea / d, spacing / abs(d)};
            t = first ? std::optional<Progression>(own) : intersect(*t, own);
            first = false;
        }
        if (!t) {
            continue;
        }
        // The member nearest the target within [lo, hi], strictly inside (0, 1).
        Integer k_min = ceil_of((lo - t->offset) / t->step);
        Integer k_max = floor_of((hi - t->offset) / t->step);
        if (t->offset + k_min * t->step == 0) {
            ++k_min;
        }
        if (t->offset + k_max * t->step == 1) {
            --k_max;
        }
        if (k_min > k_max) {
            continue;
        }
        const Rational half(1, 2);  // rounds to the nearest member
        const Integer k = std::clamp(floor_of((aim - t->offset) / t->step + half), k_min, k_max);
        const Rational at = t->offset + k * t->step;
        std::array<double, 3> p{};
        bool exact = true;
        for (std::size_t c = 0; c < 3; ++c) {
            const Rational v = Rational(pa[c]) + at * (Rational(pb[c]) - Rational(pa[c]));
            p[c] = v.convert_to<double>();
            exact = exact && Rational(p[c]) == v;
        }
        // Always exact by construction; checked because a point off the segment must never be
        // inserted.
        if (exact) {
            return Point3{p[0], p[1], p[2]};
        }
    }
    return std::nullopt;
}

}  // namespace cavity::core
