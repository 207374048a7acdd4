#include "scaled_integers.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "small_integers.h"

namespace cavity::predicates::detail {

namespace {

__extension__ using UInt128 = unsigned __int128;

/// A signed integer of N 64-bit limbs in two's complement, least significant limb first.
template <std::size_t N>
using Wide = std::array<std::uint64_t, N>;

/// v's magnitude as two limbs (|v| < 2^127 here, so it never wraps).
UInt128 magnitude(Int128 v) {
    return v < 0 ? -static_cast<UInt128>(v) : static_cast<UInt128>(v);
}

template <std::size_t N>
Wide<N> negated(const Wide<N>& w) {
    Wide<N> r{};
    std::uint64_t carry = 1;
    for (std::size_t i = 0; i < N; ++i) {
        const UInt128 s = static_cast<UInt128>(~w[i]) + carry;
        r[i] = static_cast<std::uint64_t>(s);
        carry = static_cast<std::uint64_t>(s >> 64);
    }
    return r;
}

template <std::size_t N>
Wide<N> plus(const Wide<N>& a, const Wide<N>& b) {
    Wide<N> r{};
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < N; ++i) {
        const UInt128 s = static_cast<UInt128>(a[i]) + b[i] + carry;
        r[i] = static_cast<std::uint64_t>(s);
        carry = static_cast<std::uint64_t>(s >> 64);
    }
    return r;
}

template <std::size_t N>
bool negative(const Wide<N>& w) {
    return (w[N - 1] >> 63) != 0;
}

template <std::size_t N>
Sign sign_of(const Wide<N>& w) {
    if (negative(w)) {
        return Sign::kNeg;
    }
    return std::any_of(w.begin(), w.end(), [](std::uint64_t l) { return l != 0; }) ? Sign::kPos
                                                                                   : Sign::kZero;
}

/// The product m z of a 2x2 minor (|m| < 2^125) and a coordinate difference (|z| < 2^62).
Wide<3> times(Int128 m, std::int64_t z) {
    const UInt128 a = magnitude(m);
    const std::uint64_t b = z < 0 ? -static_cast<std::uint64_t>(z) : static_cast<std::uint64_t>(z);
    const UInt128 low = static_cast<UInt128>(static_cast<std::uint64_t>(a)) * b;
    const UInt128 high =
        static_cast<UInt128>(static_cast<std::uint64_t>(a >> 64)) * b + (low >> 64);
    const Wide<3> p{static_cast<std::uint64_t>(low),
                    static_cast<std::uint64_t>(high),
                    static_cast<std::uint64_t>(high >> 64)};
    return (m < 0) != (z < 0) ? negated(p) : p;
}

/// The product of a 3x3 minor (|m| < 2^189) and a lift (0 <= lift < 2^126).
Wide<5> times(const Wide<3>& m, UInt128 lift) {
    const Wide<3> a = negative(m) ? negated(m) : m;
    const std::array<std::uint64_t, 2> b{static_cast<std::uint64_t>(lift),
                                         static_cast<std::uint64_t>(lift >> 64)};
    Wide<5> p{};
    for (std::size_t i = 0; i < 3; ++i) {
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < 2; ++j) {
            const UInt128 s = static_cast<UInt128>(a[i]) * b[j] + p[i + j] + carry;
            p[i + j] = static_cast<std::uint64_t>(s);
            carry = static_cast<std::uint64_t>(s >> 64);
        }
        p[i + 2] = carry;
    }
    return negative(m) ? negated(p) : p;
}

/// A double as sign, odd significand and the exponent of its lowest set bit (v = odd 2^low).
struct Dyadic {
    std::int64_t odd;
    int low;
    int high;  ///< the exponent of its highest set bit
};

Dyadic dyadic(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const auto field = static_cast<int>((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
    // A normal number is (2^52 + fraction) 2^(field - 1075); a subnormal fraction 2^-1074.
    const std::uint64_t significand = field == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
    const int base = field == 0 ? -1074 : field - 1075;
    const int zeros = std::countr_zero(significand);
    const auto odd = static_cast<std::int64_t>(significand >> zeros);
    return {(bits >> 63) != 0 ? -odd : odd,
            base + zeros,
            base + static_cast<int>(std::bit_width(significand)) - 1};
}

/// The coordinates of `p` (x, y, z of each point in turn) as integers times one power of two,
/// when they are below 2^kScaledIntegerBits; none otherwise. Scaling. Every nonzero coordinate
/// is odd 2^low with an odd integer below 2^53; with E the least low over them all,
/// X = odd 2^(low - E) is an integer, and when every highest set bit lies less than 61 places
/// above E, |X| < 2^61. Scaling all coordinates by 2^-E multiplies a determinant by a positive
/// power of two and keeps its sign.
template <std::size_t N>
std::optional<std::array<std::int64_t, 3 * N>> scaled(const std::array<Point3, N>& p) {
    std::array<Dyadic, 3 * N> c{};
    int lowest = 0;
    int highest = 0;
    bool any = false;
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            const double v = k == 0 ? p[i].x : k == 1 ? p[i].y : p[i].z;
            if (!std::isfinite(v)) {
                return std::nullopt;
            }
            if (v == 0.0) {
                continue;  // odd 0 stays 0 at any scale
            }
            const Dyadic d = dyadic(v);
            c[3 * i + k] = d;
            lowest = any ? std::min(lowest, d.low) : d.low;
            highest = any ? std::max(highest, d.high) : d.high;
            any = true;
        }
    }
    if (highest - lowest >= kScaledIntegerBits) {
        return std::nullopt;
    }
    std::array<std::int64_t, 3 * N> x{};
    for (std::size_t j = 0; j < 3 * N; ++j) {
        // A zero keeps low 0, which need not lie above E: no shift for it.
        x[j] = c[j].odd == 0 ? 0 : c[j].odd * (std::int64_t{1} << (c[j].low - lowest));
    }
    return x;
}

}  // namespace

// Bounds. With |X| < 2^61 the differences d = X - X_e have |d| < 2^62; products of two are below
// 2^124, the 2x2 minors below 2^125 (128-bit), the 3x3 minors below 3 * 2^187 < 2^189 (three
// limbs), the lifts |d|^2 below 3 * 2^124 < 2^126, and the four products lift * minor below
// 2^315, their sum below 2^317: five limbs hold it with room, so nothing overflows and the sign
// is exact. The formula is lifted_small_integers' (lifted_adaptive.cpp) without weights.
std::optional<Sign> insphere_scaled_integers(const std::array<Point3, 5>& p) {
    const auto x = scaled(p);
    if (!x) {
        return std::nullopt;
    }
    std::int64_t dx[4], dy[4], dz[4];
    for (std::size_t i = 0; i < 4; ++i) {
        dx[i] = (*x)[3 * i] - (*x)[12];
        dy[i] = (*x)[3 * i + 1] - (*x)[13];
        dz[i] = (*x)[3 * i + 2] - (*x)[14];
    }
    const auto minor = [&](std::size_t i, std::size_t j) {
        return Int128{dx[i]} * dy[j] - Int128{dx[j]} * dy[i];
    };
    const Int128 ab = minor(0, 1), bc = minor(1, 2), cd = minor(2, 3), da = minor(3, 0),
                 ac = minor(0, 2), bd = minor(1, 3);
    const Wide<3> abc = plus(plus(times(bc, dz[0]), times(-ac, dz[1])), times(ab, dz[2]));
    const Wide<3> bcd = plus(plus(times(cd, dz[1]), times(-bd, dz[2])), times(bc, dz[3]));
    const Wide<3> cda = plus(plus(times(da, dz[2]), times(ac, dz[3])), times(cd, dz[0]));
    const Wide<3> dab = plus(plus(times(ab, dz[3]), times(bd, dz[0])), times(da, dz[1]));
    UInt128 lift[4];
    for (std::size_t i = 0; i < 4; ++i) {
        lift[i] = static_cast<UInt128>(Int128{dx[i]} * dx[i] + Int128{dy[i]} * dy[i] +
                                       Int128{dz[i]} * dz[i]);
    }
    const Wide<5> det = plus(plus(times(abc, lift[3]), negated(times(dab, lift[2]))),
                             plus(times(cda, lift[1]), negated(times(bcd, lift[0]))));
    return sign_of(det);
}

}  // namespace cavity::predicates::detail
