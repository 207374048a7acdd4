#include "double_point_sieve.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "cavity/predicates/dyadic.h"
#include "wide_integer.h"

namespace cavity::core {

namespace {

/// Integers stay below 2^kMaxBits in magnitude: their difference still fits a signed 128-bit one.
constexpr int kMaxBits = 125;

/// x = odd * 2^exponent (x != 0, finite), odd < 2^53 in magnitude.
struct Binary {
    std::int64_t odd;
    int exponent;
};

Binary binary(double x) {
    const SplitDouble s = split_double(x);
    const int zeros =
        std::countr_zero(static_cast<std::uint64_t>(s.mantissa < 0 ? -s.mantissa : s.mantissa));
    return {s.mantissa >> zeros, s.exponent + zeros};
}

int trailing_zeros(Uint128 x) {
    const auto low = static_cast<std::uint64_t>(x);
    return low != 0 ? std::countr_zero(low)
                    : 64 + std::countr_zero(static_cast<std::uint64_t>(x >> 64));
}

/// Binary gcd (x, y not both zero).
Uint128 gcd(Uint128 x, Uint128 y) {
    if (x == 0) {
        return y;
    }
    if (y == 0) {
        return x;
    }
    const int shift = trailing_zeros(x | y);
    x >>= trailing_zeros(x);
    while (y != 0) {
        y >>= trailing_zeros(y);
        if (x > y) {
            std::swap(x, y);
        }
        y -= x;
    }
    return x << shift;
}

/// The inverse of odd x modulo 2^128: Newton's iteration doubles the bits that are right, and x is
/// its own inverse modulo 8.
Uint128 inverse(Uint128 x) {
    Uint128 y = x;
    for (int i = 0; i < 6; ++i) {
        y *= 2 - x * y;
    }
    return y;
}

Uint128 low_bits(Uint128 x, int bits) {
    return bits >= 128 ? x : (x & ((Uint128{1} << bits) - 1));
}

/// A lower bound on |a + t (b - a)| at the midpoint of every piece of the window that
/// protection_point's search makes (a != b), or 0. When the coordinate keeps one sign over the
/// window its magnitude is monotone there, and the smaller of its values at the window's ends is
/// such a bound. When it may vanish in the window: 0, for a piece that ends at its zero may end at
/// another coordinate's cut arbitrarily near it.
double smallest_piece_value(double a, double b, double lo, double hi) {
    // Each end's value in doubles is within three roundings of the operands' scale, and the
    // subnormals' absolute spacing (an overflow makes a comparison false or the error infinite),
    // but exact at the segment's ends.
    const double error = 0x1p-50 * (std::abs(a) + std::abs(b)) + 0x1p-1070;
    const auto at = [&](double t) -> std::pair<double, double> {
        if (t == 0 || t == 1) {
            return {t == 0 ? a : b, 0.0};
        }
        return {a + t * (b - a), error};
    };
    const auto [at_lo, lo_error] = at(lo);
    const auto [at_hi, hi_error] = at(hi);
    if ((at_lo > lo_error && at_hi > hi_error) || (at_lo < -lo_error && at_hi < -hi_error)) {
        // The factor covers the rounding of the subtraction.
        const auto least = [](double value, double e) {
            return e == 0 ? std::abs(value) : (std::abs(value) - e) * (1 - 0x1p-50);
        };
        return std::min(least(at_lo, lo_error), least(at_hi, hi_error));
    }
    return 0;
}

}  // namespace

bool may_hold_double_point(const Point3& a, const Point3& b, double lo, double hi) {
    const std::array<double, 3> pa{a.x, a.y, a.z};
    const std::array<double, 3> pb{b.x, b.y, b.z};
    // Per coordinate that changes along ab and keeps its sign over the window: the finest
    // spacing exponent f that the search uses for it there.
    std::array<int, 3> finest{};
    std::array<bool, 3> constrained{};
    int scale = 1 << 20;  // E: the least of every f and of the ends' lowest set bits
    for (std::size_t c = 0; c < 3; ++c) {
        constrained[c] = pa[c] != pb[c];
        if (!constrained[c]) {
            continue;
        }
        const double least = smallest_piece_value(pa[c], pb[c], lo, hi);
        if (!(least > 0)) {
            constrained[c] = false;  // no bound on its spacing: the others still constrain t
            continue;
        }
        finest[c] = predicates::spacing_exponent(least);
        scale = std::min(scale, finest[c]);
        for (const double x : {pa[c], pb[c]}) {
            if (x != 0) {
                scale = std::min(scale, binary(x).exponent);
            }
        }
    }
    // The ends as integers A, B in units of 2^E, and D = B - A.
    std::array<Int128, 3> start{};
    std::array<Int128, 3> change{};
    Uint128 g = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        if (!constrained[c]) {
            continue;
        }
        std::array<Int128, 2> ends{};
        for (std::size_t i = 0; i < 2; ++i) {
            const double x = i == 0 ? pa[c] : pb[c];
            if (x == 0) {
                continue;
            }
            const Binary s = binary(x);
            const int shift = s.exponent - scale;
            if (shift + 53 > kMaxBits) {
                return true;
            }
            ends[i] = Int128{s.odd} << shift;
        }
        start[c] = ends[0];
        change[c] = ends[1] - ends[0];
        g = gcd(g, magnitude(change[c]));
    }
    if (g == 0) {
        return true;  // no coordinate constrains t
    }
    // t = m / G; coordinate c asks A_c + m P_c = 0 modulo 2^(f_c - E), P_c = D_c / G. The
    // congruences so far: m = residue modulo 2^bits.
    Uint128 residue = 0;
    int bits = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        if (!constrained[c]) {
            continue;
        }
        const int modulus = finest[c] - scale;
        if (modulus >= 128) {
            return true;
        }
        const auto step =
            low_bits(static_cast<Uint128>(change[c] / static_cast<Int128>(g)), modulus);
        const Uint128 wanted = low_bits(-static_cast<Uint128>(start[c]), modulus);
        if (step == 0) {
            if (wanted != 0) {
                return false;  // the coordinate's value at every such t is off its spacing
            }
            continue;
        }
        const int twos = trailing_zeros(step);
        if (wanted != 0 && trailing_zeros(wanted) < twos) {
            return false;
        }
        const int own_bits = modulus - twos;
        const Uint128 own = low_bits((wanted >> twos) * inverse(step >> twos), own_bits);
        if (own_bits <= bits) {
            if (low_bits(residue, own_bits) != own) {
                return false;
            }
        } else {
            if (low_bits(own, bits) != residue) {
                return false;
            }
            residue = own;
            bits = own_bits;
        }
    }
    // Is there an integer j with lo G <= residue + j 2^bits <= hi G and 0 < m < G (the search
    // leaves out the segment's ends)? In doubles, with a margin far above their rounding (relative
    // 2^-50 of the operands): undecided ends say "maybe".
    const double unit = std::ldexp(1.0, -bits);
    const double offset = static_cast<double>(residue) * unit;  // in [0, 1]
    const double whole = static_cast<double>(g) * unit;
    const double from = (lo > 0 ? lo * whole : unit) - offset;
    const double to = (hi < 1 ? hi * whole : whole - unit) - offset;
    const double margin = 0x1p-40 * (std::abs(from) + std::abs(to) + 2);
    return std::floor(to + margin) >= std::ceil(from - margin);
}

}  // namespace cavity::core
