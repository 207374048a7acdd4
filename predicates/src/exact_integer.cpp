#include "exact_integer.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>

#include <gmp.h>

namespace cavity::predicates::detail {
namespace {

// Every finite double is m * 2^k with an integer |m| < 2^53. Scaling a whole query by 2^-E, with E
// the smallest such k, turns every coordinate into an integer; the determinants are homogeneous
// (orient3d of degree 3, insphere and orient4d of degree 5 when weights count twice, so weights are
// scaled by 2^-2E), so the scaling multiplies them by a positive number and keeps their sign.

/// RAII owner of one mpz_t.
class Integer {
public:
    Integer() { mpz_init(value_); }

    ~Integer() { mpz_clear(value_); }

    Integer(const Integer&) = delete;
    Integer& operator=(const Integer&) = delete;

    mpz_ptr get() { return value_; }

    mpz_srcptr get() const { return value_; }

private:
    mpz_t value_;
};

/// x == mantissa * 2^exponent with an integer mantissa of at most 53 bits.
struct Dyadic {
    std::int64_t mantissa = 0;
    int exponent = INT_MAX;  // INT_MAX for zero, so that zeros never lower the common exponent
};

Dyadic to_dyadic(double x) {
    if (x == 0.0) {
        return {};
    }
    int e = 0;
    const double fraction = std::frexp(x, &e);  // |fraction| in [0.5, 1), exact for subnormals too
    return {static_cast<std::int64_t>(std::ldexp(fraction, 53)), e - 53};
}

/// out = x * 2^-scale, an integer because scale <= x.exponent.
void set_scaled(mpz_ptr out, const Dyadic& x, int scale) {
    if (x.mantissa == 0) {
        mpz_set_ui(out, 0);
        return;
    }
    mpz_set_si(out, static_cast<long>(x.mantissa));
    mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(x.exponent - scale));
}

/// Floor division by 2, also for negative exponents.
int half_floor(int k) {
    return k >= 0 ? k / 2 : -((-k + 1) / 2);
}

/// Rows of differences p - q of integers: x, y, z and, for the lifted predicates, the lift.
struct Row {
    Integer x;
    Integer y;
    Integer z;
    Integer lift;
};

/// det of the 3x3 matrix with rows r, s, t (coordinates x, y, z), into out.
void det3(mpz_ptr out, const Row& r, const Row& s, const Row& t, mpz_ptr tmp) {
    // r.x (s.y t.z - s.z t.y) - r.y (s.x t.z - s.z t.x) + r.z (s.x t.y - s.y t.x)
    mpz_mul(tmp, s.y.get(), t.z.get());
    mpz_submul(tmp, s.z.get(), t.y.get());
    mpz_mul(out, r.x.get(), tmp);
    mpz_mul(tmp, s.x.get(), t.z.get());
    mpz_submul(tmp, s.z.get(), t.x.get());
    mpz_submul(out, r.y.get(), tmp);
    mpz_mul(tmp, s.x.get(), t.y.get());
    mpz_submul(tmp, s.y.get(), t.x.get());
    mpz_addmul(out, r.z.get(), tmp);
}

/// Sign of det[r_i, lift_i] over four rows: cofactor expansion along the lift column.
Sign det4_lifted_sign(const std::array<Row, 4>& r) {
    Integer minor;
    Integer tmp;
    Integer det;
    det3(minor.get(), r[1], r[2], r[3], tmp.get());
    mpz_submul(det.get(), r[0].lift.get(), minor.get());
    det3(minor.get(), r[0], r[2], r[3], tmp.get());
    mpz_addmul(det.get(), r[1].lift.get(), minor.get());
    det3(minor.get(), r[0], r[1], r[3], tmp.get());
    mpz_submul(det.get(), r[2].lift.get(), minor.get());
    det3(minor.get(), r[0], r[1], r[2], tmp.get());
    mpz_addmul(det.get(), r[3].lift.get(), minor.get());
    return static_cast<Sign>(mpz_sgn(det.get()));
}

/// The smallest exponent of the nonzero values; INT_MAX when all are zero.
template <std::size_t N>
int min_exponent(const std::array<Dyadic, N>& values) {
    int e = INT_MAX;
    for (const Dyadic& v : values) {
        e = std::min(e, v.exponent);
    }
    return e;
}

/// The scale of an all-zero query is arbitrary.
int finite_scale(int e) {
    return e == INT_MAX ? 0 : e;
}

/// Fills rows[i].{x,y,z} with the scaled differences p_i - q over the points p (the coordinates
/// come as consecutive triples in `coords`, q is the last triple).
template <std::size_t N, std::size_t R>
void scaled_differences(const std::array<Dyadic, N>& coords, int scale, std::array<Row, R>& rows) {
    Integer q[3];
    for (int k = 0; k < 3; ++k) {
        set_scaled(q[k].get(), coords[3 * R + k], scale);
    }
    for (std::size_t i = 0; i < R; ++i) {
        Row& row = rows[i];
        Integer* fields[3] = {&row.x, &row.y, &row.z};
        for (int k = 0; k < 3; ++k) {
            set_scaled(fields[k]->get(), coords[3 * i + k], scale);
            mpz_sub(fields[k]->get(), fields[k]->get(), q[k].get());
        }
    }
}

template <std::size_t R>
void add_squared_lengths(std::array<Row, R>& rows) {
    for (Row& row : rows) {
        mpz_addmul(row.lift.get(), row.x.get(), row.x.get());
        mpz_addmul(row.lift.get(), row.y.get(), row.y.get());
        mpz_addmul(row.lift.get(), row.z.get(), row.z.get());
    }
}

/// The coordinates of the points, in order, as dyadic numbers.
template <class... Points>
std::array<Dyadic, 3 * sizeof...(Points)> coordinates(const Points&... points) {
    std::array<Dyadic, 3 * sizeof...(Points)> out{};
    std::size_t i = 0;
    for (const Point3& p : {Point3{points.x, points.y, points.z}...}) {
        out[i++] = to_dyadic(p.x);
        out[i++] = to_dyadic(p.y);
        out[i++] = to_dyadic(p.z);
    }
    return out;
}

}  // namespace

Sign orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const std::array<Dyadic, 12> coords = coordinates(a, b, c, d);
    std::array<Row, 3> rows;
    scaled_differences(coords, finite_scale(min_exponent(coords)), rows);
    Integer det;
    Integer tmp;
    det3(det.get(), rows[0], rows[1], rows[2], tmp.get());
    return static_cast<Sign>(mpz_sgn(det.get()));
}

Sign insphere_exact(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const std::array<Dyadic, 15> coords = coordinates(a, b, c, d, e);
    std::array<Row, 4> rows;
    scaled_differences(coords, finite_scale(min_exponent(coords)), rows);
    add_squared_lengths(rows);
    return det4_lifted_sign(rows);
}

Sign orient4d_exact(const WeightedPoint3& a,
                    const WeightedPoint3& b,
                    const WeightedPoint3& c,
                    const WeightedPoint3& d,
                    const WeightedPoint3& e) {
    const std::array<Dyadic, 15> coords = coordinates(a, b, c, d, e);
    const std::array<Dyadic, 5> weights = {
        to_dyadic(a.w),
        to_dyadic(b.w),
        to_dyadic(c.w),
        to_dyadic(d.w),
        to_dyadic(e.w),
    };
    // Coordinates scale by 2^-E and weights by 2^-2E, so E must not exceed half of the smallest
    // weight exponent either (rounded down, keeping every scaled weight an integer).
    int scale = min_exponent(coords);
    if (const int weight_exponent = min_exponent(weights); weight_exponent != INT_MAX) {
        scale = std::min(scale, half_floor(weight_exponent));
    }
    scale = finite_scale(scale);
    std::array<Row, 4> rows;
    scaled_differences(coords, scale, rows);
    add_squared_lengths(rows);
    // lift_p = |p - e|^2 - (w_p - w_e)
    Integer we;
    set_scaled(we.get(), weights[4], 2 * scale);
    Integer w;
    for (std::size_t i = 0; i < 4; ++i) {
        set_scaled(w.get(), weights[i], 2 * scale);
        mpz_sub(rows[i].lift.get(), rows[i].lift.get(), w.get());
        mpz_add(rows[i].lift.get(), rows[i].lift.get(), we.get());
    }
    return det4_lifted_sign(rows);
}

}  // namespace cavity::predicates::detail
