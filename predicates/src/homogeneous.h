#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "cavity/predicates/generic_point.h"

// Homogeneous coordinates of generic points and the two determinants the predicates take of them,
// written once over a number type T (an interval for the filter, an exact integer behind it). T
// needs +, -, * and construction from an int and from what `lift` and `parameter` return.
namespace cavity::predicates::detail {

template <class T>
struct Homogeneous {
    T x;
    T y;
    T z;
    T w;
};

/// The homogeneous coordinates of g as in generic_point.h. `lift` maps a defining point to its
/// three coordinates in T, `parameter` a double of a SegmentParameterPoint's parameter to T. The
/// caller may translate every defining point by one vector and scale every coordinate by one
/// positive constant (the filter translates to a point of the query, so that the intervals stay
/// as narrow as the query's extent allows; the exact stage scales to integers): LNC and LPI points
/// are affine constructions, so they move with their defining points, and orient3d and insphere
/// keep their signs under translation and positive scaling. Scaling one point's numerator and
/// denominator together scales its (X, Y, Z, W), which keeps the point.
template <class T, class Lift, class Parameter>
Homogeneous<T> homogeneous(const GenericPoint3& g, Lift lift, Parameter parameter) {
    const auto minus = [](const std::array<T, 3>& u, const std::array<T, 3>& v) {
        return std::array<T, 3>{T(u[0] - v[0]), T(u[1] - v[1]), T(u[2] - v[2])};
    };
    if (const auto* p = std::get_if<Point3>(&g)) {
        const std::array<T, 3> c = lift(*p);
        return {c[0], c[1], c[2], T(1)};
    }
    if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        const std::array<T, 3> a = lift(s->a);
        const std::array<T, 3> d = minus(lift(s->b), a);
        const T num(parameter(s->numerator));
        const T den(parameter(s->denominator));
        return {T(den * a[0] + num * d[0]),
                T(den * a[1] + num * d[1]),
                T(den * a[2] + num * d[2]),
                den};
    }
    const auto& l = std::get<LinePlanePoint>(g);
    const std::array<T, 3> a = lift(l.a);
    const std::array<T, 3> p = lift(l.p);
    const std::array<T, 3> d = minus(lift(l.b), a);
    const std::array<T, 3> u = minus(lift(l.q), p);
    const std::array<T, 3> v = minus(lift(l.r), p);
    const std::array<T, 3> n{
        T(u[1] * v[2] - u[2] * v[1]), T(u[2] * v[0] - u[0] * v[2]), T(u[0] * v[1] - u[1] * v[0])};
    const std::array<T, 3> pa = minus(p, a);
    const T w(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
    const T s(n[0] * pa[0] + n[1] * pa[1] + n[2] * pa[2]);
    return {T(w * a[0] + s * d[0]), T(w * a[1] + s * d[1]), T(w * a[2] + s * d[2]), w};
}

template <class T, std::size_t N>
using Matrix = std::array<std::array<T, N>, N>;

/// The number of set bits of every N-bit mask, computed at compile time: std::popcount compiles to
/// a library call on the baseline x86-64 target (no POPCNT), which cost 12% of a protection run.
template <std::size_t N>
inline constexpr std::array<std::uint8_t, (1u << N)> kMaskSize = [] {
    std::array<std::uint8_t, (1u << N)> size{};
    for (unsigned mask = 1; mask < (1u << N); ++mask) {
        size[mask] = static_cast<std::uint8_t>(size[mask >> 1] + (mask & 1u));
    }
    return size;
}();

/// det of an N x N matrix by Laplace expansion, each minor computed once: minor[mask] is the
/// determinant of the last popcount(mask) rows restricted to the columns in mask, expanded along
/// its first row. For N = 5 that is 75 products (plain cofactor recursion takes 205), and no
/// division, so it serves intervals and integers alike.
template <class T, std::size_t N>
T determinant(const Matrix<T, N>& m) {
    constexpr unsigned kMasks = 1u << N;
    std::array<T, kMasks> minor{};
    for (std::size_t j = 0; j < N; ++j) {
        minor[1u << j] = m[N - 1][j];
    }
    for (std::size_t size = 2; size <= N; ++size) {
        const std::size_t row = N - size;
        for (unsigned mask = 0; mask < kMasks; ++mask) {
            if (kMaskSize<N>[mask] != size) {
                continue;
            }
            bool first = true;
            bool plus = true;  // the sign alternates along the row of the submatrix
            T sum(0);
            for (std::size_t j = 0; j < N; ++j) {
                if ((mask & (1u << j)) == 0) {
                    continue;
                }
                const T term(m[row][j] * minor[mask & ~(1u << j)]);
                sum = first ? term : (plus ? T(sum + term) : T(sum - term));
                first = false;
                plus = !plus;
            }
            minor[mask] = sum;
        }
    }
    return minor[kMasks - 1];
}

}  // namespace cavity::predicates::detail
