#include "dyadic_point.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include "cavity/predicates/dyadic.h"
#include "wide_integer.h"

namespace cavity::core {

namespace {

/// Binades whose spacings differ by more than this do not fit the integers: 53 + 60 bits for the
/// finer-scaled coordinate, 10 more for the factor, one for the sum, and the sign stay below 128.
constexpr int kMaxShift = 60;

/// (2^j - k) a + k b scaled by 2^-j, when it is a double; nullopt when it is not; the outer
/// nullopt when undecided.
std::optional<std::optional<double>> coordinate(double a, double b, std::int64_t k, int j) {
    const SplitDouble sa = split_double(a);
    const SplitDouble sb = split_double(b);
    // The exponent of the common spacing: the finer one of the nonzero terms.
    int e = 0;
    if (sa.mantissa != 0 && sb.mantissa != 0) {
        if (std::abs(sa.exponent - sb.exponent) > kMaxShift) {
            return std::nullopt;
        }
        e = std::min(sa.exponent, sb.exponent);
    } else {
        e = sa.mantissa != 0 ? sa.exponent : sb.exponent;
    }
    const auto aligned = [&](const SplitDouble& s) {
        return s.mantissa == 0 ? Int128{0} : Int128{s.mantissa} * (Int128{1} << (s.exponent - e));
    };
    const Int128 n = aligned(sa) * ((std::int64_t{1} << j) - k) + aligned(sb) * k;
    if (n == 0) {
        return std::optional<double>(0.0);
    }
    // n 2^(e - j) = m 2^(e - j + z) with m odd: a double exactly when m has at most 53 bits and
    // its last bit is not below the subnormals' spacing (no overflow: the point lies between a and
    // b).
    const Uint128 size = magnitude(n);
    const auto low = static_cast<std::uint64_t>(size);
    const int z = low != 0 ? std::countr_zero(low)
                           : 64 + std::countr_zero(static_cast<std::uint64_t>(size >> 64));
    const Uint128 odd = size >> z;
    const int exponent = e - j + z;
    if ((odd >> 53) != 0 || exponent < -1074) {
        return std::optional<double>();
    }
    const double value = std::ldexp(static_cast<double>(static_cast<std::uint64_t>(odd)), exponent);
    return std::optional<double>(n < 0 ? -value : value);
}

/// The double nearest to (2^j - n) a + n b scaled by 2^-j; nullopt as rounded_dyadic_point says.
std::optional<double> rounded_coordinate(double a, double b, std::int64_t n, int j) {
    const SplitDouble sa = split_double(a);
    const SplitDouble sb = split_double(b);
    int e = 0;
    if (sa.mantissa != 0 && sb.mantissa != 0) {
        e = std::min(sa.exponent, sb.exponent);
    } else {
        e = sa.mantissa != 0 ? sa.exponent : sb.exponent;
    }
    // Each term below 2^(53 + shift + j), their sum below twice that: 127 bits at most.
    const int shift = std::max(sa.exponent, sb.exponent) - e;
    if (53 + shift + j + 1 > 126) {
        return std::nullopt;
    }
    const auto aligned = [&](const SplitDouble& s) {
        return s.mantissa == 0 ? Int128{0} : Int128{s.mantissa} * (Int128{1} << (s.exponent - e));
    };
    const Int128 sum = aligned(sa) * ((std::int64_t{1} << j) - n) + aligned(sb) * n;
    if (sum == 0) {
        return 0.0;
    }
    const Uint128 size = magnitude(sum);
    const auto high = static_cast<std::uint64_t>(size >> 64);
    const int bits = high != 0 ? 128 - std::countl_zero(high)
                               : 64 - std::countl_zero(static_cast<std::uint64_t>(size));
    const int exponent = e - j;  // value = size 2^exponent
    if (exponent + bits - 1 < -1022) {
        return std::nullopt;  // below the normals: leave the spacing's subtleties to the rationals
    }
    const int dropped = std::max(bits - 53, 0);
    Uint128 kept = size >> dropped;
    if (dropped > 0) {
        const Uint128 rest = size & ((Uint128{1} << dropped) - 1);
        const Uint128 half = Uint128{1} << (dropped - 1);
        if (rest == half) {
            return std::nullopt;
        }
        kept += rest > half ? 1 : 0;  // 2^53 at most: still a double
    }
    const double value =
        std::ldexp(static_cast<double>(static_cast<std::uint64_t>(kept)), exponent + dropped);
    return sum < 0 ? -value : value;
}

}  // namespace

std::optional<Point3> rounded_dyadic_point(const predicates::SegmentParameterPoint& s) {
    int exponent = 0;
    const double fraction = std::frexp(s.denominator, &exponent);
    const int j = exponent - 1;  // denominator = 2^j when fraction is 1/2
    if (fraction != 0.5 || j < 1 || j > 62 || !(s.numerator > 0) ||
        !(s.numerator < s.denominator) || std::trunc(s.numerator) != s.numerator) {
        return std::nullopt;
    }
    const auto n = static_cast<std::int64_t>(s.numerator);
    const double as[3] = {s.a.x, s.a.y, s.a.z};
    const double bs[3] = {s.b.x, s.b.y, s.b.z};
    double out[3] = {};
    for (int c = 0; c < 3; ++c) {
        const std::optional<double> v = rounded_coordinate(as[c], bs[c], n, j);
        if (!v) {
            return std::nullopt;
        }
        out[c] = *v;
    }
    return Point3{out[0], out[1], out[2]};
}

DyadicPoint dyadic_point(const Point3& a, const Point3& b, std::int64_t k, int j) {
    const double as[3] = {a.x, a.y, a.z};
    const double bs[3] = {b.x, b.y, b.z};
    double out[3] = {};
    bool undecided = false;
    for (int c = 0; c < 3; ++c) {
        const auto v = coordinate(as[c], bs[c], k, j);
        if (!v) {
            undecided = true;  // unless another coordinate is surely not a double
        } else if (!*v) {
            return {true, false, {}};
        } else {
            out[c] = **v;
        }
    }
    if (undecided) {
        return {false, false, {}};
    }
    return {true, true, {out[0], out[1], out[2]}};
}

}  // namespace cavity::core
