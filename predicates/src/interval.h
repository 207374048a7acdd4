#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

// Interval arithmetic under round-to-nearest, without switching the rounding mode (the predicates
// assume round-to-nearest everywhere, fp_environment.h): each operation rounds to nearest and then
// steps one double outward with nextafter.
//
// Why that is sound. For a real x with fl(x) its double rounded to nearest, x lies in
// [pred(fl(x)), succ(fl(x))]: |x - fl(x)| is at most half the spacing on the side of fl(x) where x
// lies (at a power of two the spacing below is half the one above, and a value below rounding up to
// 2^k is within a quarter of the upper spacing of it), and pred/succ step a whole spacing. This
// holds in the subnormal range (fixed spacing 2^-1074; a value rounding to 0 is within 2^-1075 of
// it), and on overflow: a value that rounds to +inf exceeds DBL_MAX, which is pred(+inf). So each
// endpoint computed as nextafter(fl(e), outward) bounds the exact operation on the input endpoints,
// and by induction every interval holds the exact value of the expression it was computed for. An
// operation that meets inf - inf or 0 * inf gives NaN; such an interval is made the whole line.
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

    /// [lo, hi] as rounded to nearest, widened by one double each way. A NaN endpoint can only
    /// come from an infinite input endpoint; such intervals are the whole line, which decides no
    /// sign.
    static Interval outward(double lo, double hi) {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        if (std::isnan(lo) || std::isnan(hi)) {
            return whole_line();
        }
        return exact(std::nextafter(lo, -kInf), std::nextafter(hi, kInf));
    }

    double lo_ = 0.0;
    double hi_ = 0.0;
};

}  // namespace cavity::predicates::detail
