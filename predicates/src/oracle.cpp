#include "cavity/predicates/oracle.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <boost/multiprecision/gmp.hpp>

// Each predicate is the sign of one lifted determinant with a trailing column of ones, evaluated
// in exact integers by fraction-free (Bareiss) elimination. Nothing here translates points or
// forms differences, so this code shares no formula with the staged predicates.
//
// Why the lifted forms have the documented signs: subtracting the last row from every other row
// leaves the determinant unchanged and turns the column of ones into (0, ..., 0, 1); expanding
// along it gives the (n-1)x(n-1) minor with sign (+1)^(n+n) = +1. Hence
//   det [a 1; b 1; c 1; d 1]          = det [a-d; b-d; c-d]                      (orient3d);
//   det [p h_p 1] over p = a..e       = det [p-e, h_p-h_e] over p = a..d         (orient4d);
// and for insphere, with h_p = |p|^2, the column operation  h -= 2 e_x x + 2 e_y y + 2 e_z z
// (determinant unchanged) turns h_p - h_e into |p-e|^2 for the rows p = a..d, so
//   det [p |p|^2 1] over p = a..e     = det [p-e, |p-e|^2] over p = a..d         (insphere).
// tests/predicates/oracle_test.cpp checks all three against the difference forms on small integers.
namespace cavity::predicates::oracle {

namespace {

using boost::multiprecision::mpz_int;

// A finite double as mantissa * 2^exponent with an odd mantissa (or zero).
struct Dyadic {
    std::int64_t mantissa;
    int exponent;
};

Dyadic decompose(double value) {
    if (!std::isfinite(value)) {
        throw std::invalid_argument("oracle: coordinates and weights must be finite");
    }
    if (value == 0.0) {
        return {0, 0};
    }
    int exponent = 0;
    const double fraction = std::frexp(value, &exponent);  // |fraction| in [0.5, 1)
    auto mantissa = static_cast<std::int64_t>(std::ldexp(fraction, 53));
    exponent -= 53;
    const int trailing = std::countr_zero(static_cast<std::uint64_t>(mantissa));
    return {mantissa >> trailing, exponent + trailing};
}

// The smallest exponent among the nonzero values: scaling them all by 2^-min makes them integers.
template <std::size_t N>
int min_exponent(const std::array<Dyadic, N>& values) {
    int result = 0;
    bool any = false;
    for (const Dyadic& v : values) {
        if (v.mantissa != 0 && (!any || v.exponent < result)) {
            result = v.exponent;
            any = true;
        }
    }
    return result;
}

// value * 2^shift, where shift >= 0 is guaranteed by the choice of the common scale.
mpz_int scaled(const Dyadic& v, int shift) {
    mpz_int result(v.mantissa);
    if (v.mantissa != 0) {
        result <<= static_cast<unsigned>(v.exponent + shift);
    }
    return result;
}

template <std::size_t N>
using Matrix = std::array<std::array<mpz_int, N>, N>;

// Sign of det(m) by Bareiss' fraction-free Gaussian elimination: after step k every entry below
// and right of the pivot is a (k+2)x(k+2) minor of the (row-permuted) input, so each division is
// exact and the last entry is the determinant. Row swaps flip the sign.
template <std::size_t N>
Sign determinant_sign(Matrix<N>& m) {
    int parity = 1;
    mpz_int previous_pivot(1);
    for (std::size_t k = 0; k + 1 < N; ++k) {
        if (m[k][k] == 0) {
            std::size_t r = k + 1;
            while (r < N && m[r][k] == 0) {
                ++r;
            }
            if (r == N) {
                return Sign::kZero;  // column k is zero below the diagonal: rank-deficient
            }
            std::swap(m[k], m[r]);
            parity = -parity;
        }
        for (std::size_t i = k + 1; i < N; ++i) {
            for (std::size_t j = k + 1; j < N; ++j) {
                m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) / previous_pivot;
            }
        }
        previous_pivot = m[k][k];
    }
    const int s = parity * boost::multiprecision::sign(m[N - 1][N - 1]);
    return s > 0 ? Sign::kPos : (s < 0 ? Sign::kNeg : Sign::kZero);
}

// Rows (x, y, z) of the points, all scaled by 2^scale_exponent so that they are integers; a common
// positive factor does not change the sign of a determinant that is linear in each column.
template <std::size_t N>
struct IntegerPoints {
    std::array<std::array<mpz_int, 3>, N> rows;
    int scale_exponent;
};

template <std::size_t N, typename P>
IntegerPoints<N> integer_coordinates(const std::array<const P*, N>& points) {
    std::array<Dyadic, 3 * N> parts{};
    for (std::size_t i = 0; i < N; ++i) {
        parts[3 * i] = decompose(points[i]->x);
        parts[3 * i + 1] = decompose(points[i]->y);
        parts[3 * i + 2] = decompose(points[i]->z);
    }
    IntegerPoints<N> result;
    result.scale_exponent = -min_exponent(parts);
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            result.rows[i][j] = scaled(parts[3 * i + j], result.scale_exponent);
        }
    }
    return result;
}

mpz_int squared_norm(const std::array<mpz_int, 3>& p) {
    return p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
}

}  // namespace

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const auto rows = integer_coordinates<4, Point3>({&a, &b, &c, &d}).rows;
    Matrix<4> m;
    for (std::size_t i = 0; i < 4; ++i) {
        m[i] = {rows[i][0], rows[i][1], rows[i][2], mpz_int(1)};
    }
    return determinant_sign(m);
}

Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const auto rows = integer_coordinates<5, Point3>({&a, &b, &c, &d, &e}).rows;
    Matrix<5> m;
    for (std::size_t i = 0; i < 5; ++i) {
        m[i] = {rows[i][0], rows[i][1], rows[i][2], squared_norm(rows[i]), mpz_int(1)};
    }
    return determinant_sign(m);
}

Sign orient4d(const WeightedPoint3& a,
              const WeightedPoint3& b,
              const WeightedPoint3& c,
              const WeightedPoint3& d,
              const WeightedPoint3& e) {
    const std::array<const WeightedPoint3*, 5> points{&a, &b, &c, &d, &e};
    const auto [rows, s] = integer_coordinates(points);  // coordinates scaled by 2^s
    std::array<Dyadic, 5> weights{};
    for (std::size_t i = 0; i < 5; ++i) {
        weights[i] = decompose(points[i]->w);
    }
    // The lifted column h = |p|^2 - w is scaled on its own by 2^t, with t large enough that both
    // |p|^2 2^t = |P|^2 2^(t-2s) and w 2^t are integers.
    const int t = std::max(2 * s, -min_exponent(weights));
    Matrix<5> m;
    for (std::size_t i = 0; i < 5; ++i) {
        mpz_int lifted = squared_norm(rows[i]);
        lifted <<= static_cast<unsigned>(t - 2 * s);
        lifted -= scaled(weights[i], t);
        m[i] = {rows[i][0], rows[i][1], rows[i][2], std::move(lifted), mpz_int(1)};
    }
    return determinant_sign(m);
}

}  // namespace cavity::predicates::oracle
