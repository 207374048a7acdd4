#include "scaled_integers.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <variant>

#include "small_integers.h"

namespace cavity::predicates::detail {

namespace {

__extension__ using UInt128 = unsigned __int128;

/// A signed integer of N 64-bit limbs in two's complement, least significant limb first.
template <std::size_t N>
using Wide = std::array<std::uint64_t, N>;

template <std::size_t N>
bool negative(const Wide<N>& w) {
    return (w[N - 1] >> 63) != 0;
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
Wide<N> minus(const Wide<N>& a, const Wide<N>& b) {
    return plus(a, negated(b));
}

/// a b, by their magnitudes (schoolbook) and the sign. The callers' bounds keep every value
/// below half its width's range, so no magnitude wraps and the product fits.
template <std::size_t A, std::size_t B>
Wide<A + B> product(const Wide<A>& a, const Wide<B>& b) {
    const Wide<A> ma = negative(a) ? negated(a) : a;
    const Wide<B> mb = negative(b) ? negated(b) : b;
    Wide<A + B> p{};
    for (std::size_t i = 0; i < A; ++i) {
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < B; ++j) {
            const UInt128 s = static_cast<UInt128>(ma[i]) * mb[j] + p[i + j] + carry;
            p[i + j] = static_cast<std::uint64_t>(s);
            carry = static_cast<std::uint64_t>(s >> 64);
        }
        p[i + B] = carry;
    }
    return negative(a) != negative(b) ? negated(p) : p;
}

template <std::size_t N>
Sign sign_of(const Wide<N>& w) {
    if (negative(w)) {
        return Sign::kNeg;
    }
    return std::any_of(w.begin(), w.end(), [](std::uint64_t l) { return l != 0; }) ? Sign::kPos
                                                                                   : Sign::kZero;
}

/// The sign of det[p - e, |p - e|^2] over p = a..d, given the differences p - e in L limbs.
/// Bounds, with |d| < 2^(64 L - 2) for every difference (2^62 for L = 1, 2^126 for L = 2 and
/// the callers' 2^125): products of two are below 2^(128 L - 4), the 2x2 minors below
/// 2^(128 L - 3) in 2L limbs; the 3x3 minors below 3 * 2^(192 L - 5) < 2^(192 L - 3) in 3L
/// limbs; the lifts |d|^2 below 3 * 2^(128 L - 4) < 2^(128 L - 2) in 2L limbs; the four products
/// lift * minor below 2^(320 L - 5) and their sum below 2^(320 L - 3) in 5L limbs. Each stays
/// below half its width's range, so nothing overflows and the sign is exact. The formula is
/// lifted_small_integers' (lifted_adaptive.cpp) without weights.
template <std::size_t L>
Sign lifted_sign(const std::array<Wide<L>, 4>& dx,
                 const std::array<Wide<L>, 4>& dy,
                 const std::array<Wide<L>, 4>& dz) {
    const auto minor = [&](std::size_t i, std::size_t j) {
        return minus(product(dx[i], dy[j]), product(dx[j], dy[i]));
    };
    const Wide<2 *L> ab = minor(0, 1), bc = minor(1, 2), cd = minor(2, 3), da = minor(3, 0),
                     ac = minor(0, 2), bd = minor(1, 3);
    const Wide<3 * L> abc = plus(minus(product(bc, dz[0]), product(ac, dz[1])), product(ab, dz[2]));
    const Wide<3 * L> bcd = plus(minus(product(cd, dz[1]), product(bd, dz[2])), product(bc, dz[3]));
    const Wide<3 * L> cda = plus(plus(product(da, dz[2]), product(ac, dz[3])), product(cd, dz[0]));
    const Wide<3 * L> dab = plus(plus(product(ab, dz[3]), product(bd, dz[0])), product(da, dz[1]));
    std::array<Wide<2 * L>, 4> lift;
    for (std::size_t i = 0; i < 4; ++i) {
        lift[i] = plus(plus(product(dx[i], dx[i]), product(dy[i], dy[i])), product(dz[i], dz[i]));
    }
    return sign_of(plus(minus(product(abc, lift[3]), product(dab, lift[2])),
                        minus(product(cda, lift[1]), product(bcd, lift[0]))));
}

/// A nonzero double as odd 2^low (odd an odd integer below 2^53 in magnitude), with high the
/// exponent of its highest set bit.
struct Dyadic {
    std::int64_t odd = 0;
    int low = 0;
    int high = 0;
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

/// The span of a set of doubles: the least low and the greatest high of its nonzero members.
struct Span {
    int lowest = 0;
    int highest = 0;
    bool any = false;

    /// False when v is not finite.
    bool add(double v) {
        if (!std::isfinite(v)) {
            return false;
        }
        if (v != 0.0) {
            const Dyadic d = dyadic(v);
            lowest = any ? std::min(lowest, d.low) : d.low;
            highest = any ? std::max(highest, d.high) : d.high;
            any = true;
        }
        return true;
    }

    bool add(const Point3& p) { return add(p.x) && add(p.y) && add(p.z); }
};

/// v 2^-scale, an integer when scale is at most v's low (0 for zero).
std::int64_t scaled_by(double v, int scale) {
    if (v == 0.0) {
        return 0;
    }
    const Dyadic d = dyadic(v);
    return d.odd * (std::int64_t{1} << (d.low - scale));
}

/// Differences of the five rows to the last, in L limbs.
template <std::size_t L, class Integer>
Sign lifted_sign_of_rows(const std::array<std::array<Integer, 3>, 5>& x) {
    std::array<Wide<L>, 4> dx{}, dy{}, dz{};
    const auto wide = [](Integer v) {
        Wide<L> w{};
        const Int128 s = static_cast<Int128>(v);
        w[0] = static_cast<std::uint64_t>(s);
        for (std::size_t i = 1; i < L; ++i) {
            w[i] = static_cast<std::uint64_t>(i == 1 ? (s >> 64) : (s >> 127));
        }
        return w;
    };
    for (std::size_t i = 0; i < 4; ++i) {
        dx[i] = wide(x[i][0] - x[4][0]);
        dy[i] = wide(x[i][1] - x[4][1]);
        dz[i] = wide(x[i][2] - x[4][2]);
    }
    return lifted_sign<L>(dx, dy, dz);
}

/// A segment point's parameter as odd 2^exponent (odd 0 for t = 0); none unless the denominator
/// is a power of two in magnitude (edge protection's parameters are dyadic).
struct DyadicParameter {
    std::int64_t odd = 0;
    int exponent = 0;
};

std::optional<DyadicParameter> dyadic_parameter(const SegmentParameterPoint& s) {
    if (!std::isfinite(s.numerator) || !std::isfinite(s.denominator) || s.denominator == 0.0) {
        return std::nullopt;
    }
    const Dyadic d = dyadic(s.denominator);
    if (d.odd != 1 && d.odd != -1) {
        return std::nullopt;
    }
    if (s.numerator == 0.0) {
        return DyadicParameter{};
    }
    const Dyadic n = dyadic(s.numerator);
    return DyadicParameter{d.odd * n.odd, n.low - d.low};
}

/// The bit length of |v|.
int bits_of(Int128 v) {
    const UInt128 m = v < 0 ? -static_cast<UInt128>(v) : static_cast<UInt128>(v);
    const auto high = static_cast<std::uint64_t>(m >> 64);
    return high != 0 ? 64 + static_cast<int>(std::bit_width(high))
                     : static_cast<int>(std::bit_width(static_cast<std::uint64_t>(m)));
}

}  // namespace

// Scaling. Every nonzero coordinate is odd 2^low with an odd integer below 2^53; with E the
// least low over the fifteen, X = odd 2^(low - E) is an integer, and when every highest set bit
// lies less than 61 places above E, |X| < 2^61 and every difference is below 2^62 (lifted_sign's
// bound for one limb). Scaling all coordinates by 2^-E multiplies the determinant by a positive
// power of two and keeps its sign.
std::optional<Sign> insphere_scaled_integers(const std::array<Point3, 5>& p) {
    Span span;
    for (const Point3& q : p) {
        if (!span.add(q)) {
            return std::nullopt;
        }
    }
    if (span.highest - span.lowest >= kScaledIntegerBits) {
        return std::nullopt;
    }
    std::array<std::array<std::int64_t, 3>, 5> x{};
    for (std::size_t i = 0; i < 5; ++i) {
        x[i] = {scaled_by(p[i].x, span.lowest),
                scaled_by(p[i].y, span.lowest),
                scaled_by(p[i].z, span.lowest)};
    }
    return lifted_sign_of_rows<1>(x);
}

// Scaling. The defining doubles (explicit points, segment ends) span at most 61 bits above their
// least low E, so each is an integer A 2^E with |A| < 2^61. A segment point with parameter
// t = T 2^tau (T an odd integer below 2^53) has coordinates 2^E (A + t (B - A)), so with
// S = E + min(0, least tau) every coordinate is an integer times 2^S: an explicit one A 2^(E - S),
// a segment point's A 2^(E - S) + T (B - A) 2^(tau + E - S), both shifts at least 0.
// Each is formed in 128 bits only while its bit length stays below kWideScaledIntegerBits, so
// |X| < 2^124 and every difference is below 2^125: lifted_sign's bound for two limbs.
std::optional<Sign> insphere_scaled_integers(const std::array<const GenericPoint3*, 5>& g) {
    Span span;
    std::array<DyadicParameter, 5> t{};
    int least_tau = 0;
    for (std::size_t i = 0; i < 5; ++i) {
        if (const auto* p = std::get_if<Point3>(g[i])) {
            if (!span.add(*p)) {
                return std::nullopt;
            }
        } else if (const auto* s = std::get_if<SegmentParameterPoint>(g[i])) {
            const std::optional<DyadicParameter> d = dyadic_parameter(*s);
            if (!d || !span.add(s->a) || !span.add(s->b)) {
                return std::nullopt;
            }
            t[i] = *d;
            if (d->odd != 0) {
                least_tau = std::min(least_tau, d->exponent);
            }
        } else {
            return std::nullopt;  // a LinePlanePoint: not dyadic in general
        }
    }
    if (span.highest - span.lowest >= kScaledIntegerBits) {
        return std::nullopt;
    }
    const int e = span.lowest;
    const int up = -least_tau;  // E - S
    // A shifted left by `by`, none when the result would reach kWideScaledIntegerBits bits.
    const auto shifted = [](Int128 v, int by) -> std::optional<Int128> {
        if (v == 0) {
            return Int128{0};
        }
        if (bits_of(v) + by >= kWideScaledIntegerBits) {
            return std::nullopt;
        }
        return v * (Int128{1} << by);
    };
    std::array<std::array<Int128, 3>, 5> x{};
    for (std::size_t i = 0; i < 5; ++i) {
        if (const auto* p = std::get_if<Point3>(g[i])) {
            const std::array<double, 3> c{p->x, p->y, p->z};
            for (std::size_t k = 0; k < 3; ++k) {
                const std::optional<Int128> v = shifted(scaled_by(c[k], e), up);
                if (!v) {
                    return std::nullopt;
                }
                x[i][k] = *v;
            }
            continue;
        }
        const auto& s = std::get<SegmentParameterPoint>(*g[i]);
        const std::array<double, 3> a{s.a.x, s.a.y, s.a.z};
        const std::array<double, 3> b{s.b.x, s.b.y, s.b.z};
        for (std::size_t k = 0; k < 3; ++k) {
            const Int128 ak = scaled_by(a[k], e);
            // |T| < 2^53 and |B - A| < 2^62: the product is below 2^115.
            const Int128 step = Int128{t[i].odd} * (scaled_by(b[k], e) - ak);
            const std::optional<Int128> base = shifted(ak, up);
            const std::optional<Int128> along =
                t[i].odd == 0 ? Int128{0} : shifted(step, t[i].exponent + up);
            if (!base || !along) {
                return std::nullopt;
            }
            // Both below 2^123 in magnitude: the sum is below 2^124.
            x[i][k] = *base + *along;
        }
    }
    return lifted_sign_of_rows<2>(x);
}

}  // namespace cavity::predicates::detail
