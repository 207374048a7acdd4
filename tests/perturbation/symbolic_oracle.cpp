#include "symbolic_oracle.h"

#include <bit>
#include <cstddef>
#include <map>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

namespace cavity::perturbation::test {

namespace {

using Rational = boost::multiprecision::mpq_rational;

/// A polynomial in eps, sparse: the coefficient of eps^k is at key k; no zero coefficients.
using Poly = std::map<std::uint32_t, Rational>;

using Matrix = std::vector<std::vector<Poly>>;

Poly constant(const Rational& c) {
    Poly p;
    if (c != 0) {
        p[0] = c;
    }
    return p;
}

void add_product(Poly& sum, const Poly& a, const Poly& b, int sign) {
    for (const auto& [i, ai] : a) {
        for (const auto& [j, bj] : b) {
            Rational& c = sum[i + j];
            c += sign * ai * bj;
            if (c == 0) {
                sum.erase(i + j);
            }
        }
    }
}

/// Laplace expansion along the first row, memoised on the set of columns left: the minor on the
/// columns in `mask` uses the last popcount(mask) rows. The matrices here are at most 5x5.
Poly determinant(const Matrix& m) {
    const std::size_t n = m.size();
    std::vector<Poly> minors(std::size_t{1} << n);
    for (std::size_t mask = 1; mask < minors.size(); ++mask) {
        const std::size_t row = n - static_cast<std::size_t>(std::popcount(mask));
        if (std::popcount(mask) == 1) {
            minors[mask] = m[row][static_cast<std::size_t>(std::countr_zero(mask))];
            continue;
        }
        int sign = 1;
        for (std::size_t col = 0; col < n; ++col) {
            if ((mask >> col & 1u) != 0) {
                add_product(
                    minors[mask], m[row][col], minors[mask & ~(std::size_t{1} << col)], sign);
                sign = -sign;
            }
        }
    }
    return minors.back();
}

Sign lowest_order_sign(const Poly& p) {
    if (p.empty()) {
        return Sign::kZero;
    }
    return p.begin()->second > 0 ? Sign::kPos : Sign::kNeg;
}

/// The exact height |p|^2 - w, lowered by eps^(key + 1).
Poly perturbed_height(const WeightedPoint3& p, std::uint32_t key) {
    const Rational x(p.x);
    const Rational y(p.y);
    const Rational z(p.z);
    Poly h = constant(x * x + y * y + z * z - Rational(p.w));
    h[key + 1] = -1;
    return h;
}

Sign sign_of_orient3d(const std::array<WeightedPoint3, 4>& p) {
    Matrix m;
    for (const WeightedPoint3& q : p) {
        m.push_back({constant(q.x), constant(q.y), constant(q.z), constant(1)});
    }
    return lowest_order_sign(determinant(m));
}

int product(Sign a, Sign b) {
    return to_int(a) * to_int(b);
}

}  // namespace

Sign symbolic_lifted(const std::array<WeightedPoint3, 5>& p,
                     const std::array<std::uint32_t, 5>& keys) {
    Matrix m;
    for (std::size_t i = 0; i < 5; ++i) {
        m.push_back({constant(p[i].x),
                     constant(p[i].y),
                     constant(p[i].z),
                     perturbed_height(p[i], keys[i]),
                     constant(1)});
    }
    return lowest_order_sign(determinant(m));
}

Sign symbolic_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return sign_of_orient3d({WeightedPoint3{a.x, a.y, a.z, 0},
                             WeightedPoint3{b.x, b.y, b.z, 0},
                             WeightedPoint3{c.x, c.y, c.z, 0},
                             WeightedPoint3{d.x, d.y, d.z, 0}});
}

Sign symbolic_outer_halfspace(const WeightedPoint3& v,
                              const WeightedPoint3& w,
                              const WeightedPoint3& x,
                              const WeightedPoint3& y,
                              const WeightedPoint3& u,
                              const std::array<std::uint32_t, 4>& keys) {
    const Sign side_u = sign_of_orient3d({v, w, x, u});
    if (side_u != Sign::kZero) {
        const Sign side_y = sign_of_orient3d({v, w, x, y});
        return product(side_u, side_y) < 0 ? Sign::kPos : Sign::kNeg;
    }
    // Project along a coordinate axis in which the normal of vwx has a nonzero component.
    const std::array<std::array<Rational, 3>, 4> p = {
        {{Rational(v.x), Rational(v.y), Rational(v.z)},
         {Rational(w.x), Rational(w.y), Rational(w.z)},
         {Rational(x.x), Rational(x.y), Rational(x.z)},
         {Rational(u.x), Rational(u.y), Rational(u.z)}}};
    const std::array<WeightedPoint3, 4> weighted = {v, w, x, u};
    for (std::size_t dropped = 0; dropped < 3; ++dropped) {
        const std::size_t s = dropped == 0 ? 1 : 0;
        const std::size_t t = dropped == 2 ? 1 : 2;
        Matrix triangle;
        Matrix lifted;
        for (std::size_t i = 0; i < 4; ++i) {
            if (i < 3) {
                triangle.push_back({constant(p[i][s]), constant(p[i][t]), constant(1)});
            }
            lifted.push_back({constant(p[i][s]),
                              constant(p[i][t]),
                              perturbed_height(weighted[i], keys[i]),
                              constant(1)});
        }
        const Sign orientation = lowest_order_sign(determinant(triangle));
        if (orientation != Sign::kZero) {
            // u is inside the (power) circle of v, w, x iff the lifted determinant has the sign of
            // the orientation of v, w, x.
            return product(lowest_order_sign(determinant(lifted)), orientation) > 0 ? Sign::kPos
                                                                                    : Sign::kNeg;
        }
    }
    return Sign::kZero;
}

}  // namespace cavity::perturbation::test
