#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

// Interval arithmetic under round-to-nearest, without switching the rounding mode (the predicates
// assume round-to-nearest everywhere, fp_environment.h): each operation rounds its endpoints to
// nearest and then moves each outward by d(r) = fl(fl(|r| 2^-52) + 2^-1074).
//
// Why that is sound. Let x be an exact endpoint and r = fl(x), rounded to nearest. x lies between
// pred(r) and succ(r): |x - r| is at most half the spacing of the doubles on x's side of r. For
// |r| in [2^e, 2^(e+1)) the spacing on either side of r is at most 2^(e-52) <= |r| 2^-52, and at
// least 2^-1074 everywhere (subnormals). d(r) is at least max(|r| 2^-52, 2^-1074): the product by
// a power of two is exact unless it falls below 2^-1022, and then both terms are multiples of
// 2^-1074 below 2^-1021, so the sum is exact and covers the product's rounding error of at most
// 2^-1075; otherwise adding 2^-1074 and rounding never gives less than the product. So r - d(r)
// is at most pred(r) (it moves a whole spacing down from r), and rounding it to nearest, which is
// monotone and keeps the double pred(r), gives a double at most pred(r) <= x; likewise upward.
// Overflow: a value that rounds to +inf exceeds DBL_MAX, and +inf - d = NaN below makes the
// interval the whole line; a finite r moved past DBL_MAX becomes an infinite, still sound, bound.
// By induction every interval holds the exact value of the expression it was computed for. An
// operation that meets inf - inf or 0 * inf gives NaN; such an interval is the whole line, which
// decides no sign.
namespace cavity::predicates::detail {

class Interval {
public:
    Interval() = default;

    explicit Interval(double x) : lo_(x), hi_(x) {}

    double lo() const { return lo_; }

    double hi() const { return hi_; }

    /// +1 or -1 when every value in the interval has that sign, 0 when it holds zero or is unknown.
    int sign() const {
        if (lo_ > 0.0) {
            return 1;
        }
        if (hi_ < 0.0) {
            return -1;
        }
        return 0;
    }

    friend Interval operator+(const Interval& u, const Interval& v) {
        return outward(u.lo_ + v.lo_, u.hi_ + v.hi_);
    }

    friend Interval operator-(const Interval& u, const Interval& v) {
        return outward(u.lo_ - v.hi_, u.hi_ - v.lo_);
    }

    friend Interval operator-(const Interval& u) { return exact(-u.hi_, -u.lo_); }

    friend Interval operator*(const Interval& u, const Interval& v) {
        const double p1 = u.lo_ * v.lo_;
        const double p2 = u.lo_ * v.hi_;
        const double p3 = u.hi_ * v.lo_;
        const double p4 = u.hi_ * v.hi_;
        // min and max may drop a NaN operand (0 * inf), so test each product.
        if (std::isnan(p1) || std::isnan(p2) || std::isnan(p3) || std::isnan(p4)) {
            return whole_line();
        }
        return outward(std::min(std::min(p1, p2), std::min(p3, p4)),
                       std::max(std::max(p1, p2), std::max(p3, p4)));
    }

private:
    static Interval exact(double lo, double hi) {
        Interval r;
        r.lo_ = lo;
        r.hi_ = hi;
        return r;
    }

    static Interval whole_line() {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        return exact(-kInf, kInf);
    }

    /// The widening d(r) above.
    static double slack(double r) {
        constexpr double kUlpScale = 0x1p-52;
        constexpr double kSmallestSubnormal = 0x1p-1074;
        return std::abs(r) * kUlpScale + kSmallestSubnormal;
    }

    /// [lo, hi] as rounded to nearest, moved outward by the slack (sound, see the top). A NaN
    /// endpoint can only come from an infinite input endpoint; such intervals are the whole line.
    static Interval outward(double lo, double hi) {
        const double down = lo - slack(lo);
        const double up = hi + slack(hi);
        if (std::isnan(down) || std::isnan(up)) {
            return whole_line();
        }
        return exact(down, up);
    }

    double lo_ = 0.0;
    double hi_ = 0.0;
};

}  // namespace cavity::predicates::detail
