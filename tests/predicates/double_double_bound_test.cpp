// The double-double stage at its bound: queries whose determinant, relative to u^2 times the
// permanent, sweeps across the acceptance threshold of the stage (58 u^2 P~ for the lifted
// predicates, 26 u^2 P~ for orient3d), so that both its accepted and its declined answers are
// exercised where its own rounding errors matter. An exactly degenerate integer configuration has
// its last point moved off the origin by tiny amounts (2^-60 .. 2^-135), so the rounded differences
// alone are still degenerate and the sign rests on the difference tails.
//
// For every query: an accepted sign must equal the oracle's; the stage must accept when the
// exact determinant (cpp_int, independent of the stage) exceeds the threshold plus the stage's
// own error bound; and the staged predicate must agree with the oracle.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <type_traits>

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

#include "cavity/predicates/detail/expansion.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"
#include "fused_products.h"
#include "insphere_permanent.h"
#include "lifted_adaptive.h"
#include "orient3d_adaptive.h"

namespace cavity::predicates {
namespace {

using Integer = boost::multiprecision::cpp_int;

constexpr int kQueries = 20000;
constexpr double kUnitRoundoffSquared = 0x1p-106;

/// Where a stage accepts (|det| / u^2 P~ of its computed determinant) and where it must accept
/// (that plus its own error bound, with room for the rounding of the reference ratio).
struct Threshold {
    double accept;
    double must_accept;
};

// The lifted stage accepts above 58 u^2 P~ and errs by at most 57 u^2 P~; orient3d's accepts
// above 26 u^2 P~ and errs by at most 26 u^2 P~.
constexpr Threshold kLifted = {58.0, 120.0};
constexpr Threshold kOrient3d = {26.0, 60.0};

/// The exact det[p - e, |p - e|^2 - (w_p - w_e)] (p = a..d) and the permanent P~ of the rounded
/// differences, as the stage defines it, for comparing |det| with the stage's threshold.
struct Reference {
    double det_over_bound_unit;  // |det| / (u^2 P~), approximately
    Sign sign;
};

Integer scaled_integer(double v, int scale) {
    return Integer(std::ldexp(v, scale));
}

Reference lifted_reference(const std::array<WeightedPoint3, 5>& p) {
    // All inputs are multiples of 2^-scale: scaled by 2^scale (weights by 2^(2 scale)) they are
    // integers, and the determinant scales by 2^(5 scale).
    int scale = 0;
    for (const WeightedPoint3& q : p) {
        for (const double v : {q.x, q.y, q.z}) {
            if (v != 0.0) {
                scale = std::max(scale, 52 - std::ilogb(v));
            }
        }
        if (q.w != 0.0) {
            scale = std::max(scale, (52 - std::ilogb(q.w) + 1) / 2);
        }
    }
    Integer m[4][4];
    double perm_rows[4][4];
    for (int i = 0; i < 4; ++i) {
        const Integer x = scaled_integer(p[i].x, scale) - scaled_integer(p[4].x, scale);
        const Integer y = scaled_integer(p[i].y, scale) - scaled_integer(p[4].y, scale);
        const Integer z = scaled_integer(p[i].z, scale) - scaled_integer(p[4].z, scale);
        const Integer w = scaled_integer(p[i].w, 2 * scale) - scaled_integer(p[4].w, 2 * scale);
        m[i][0] = x;
        m[i][1] = y;
        m[i][2] = z;
        m[i][3] = x * x + y * y + z * z - w;
        perm_rows[i][0] = std::abs(p[i].x - p[4].x);
        perm_rows[i][1] = std::abs(p[i].y - p[4].y);
        perm_rows[i][2] = std::abs(p[i].z - p[4].z);
        perm_rows[i][3] = perm_rows[i][0] * perm_rows[i][0] + perm_rows[i][1] * perm_rows[i][1] +
                          perm_rows[i][2] * perm_rows[i][2] + std::abs(p[i].w - p[4].w);
    }
    // Laplace expansion along the last column; the permanent the same with magnitudes.
    Integer det = 0;
    long double permanent = 0.0L;
    for (int r = 0; r < 4; ++r) {
        int rows[3];
        for (int i = 0, n = 0; i < 4; ++i) {
            if (i != r) {
                rows[n++] = i;
            }
        }
        const auto& a = m[rows[0]];
        const auto& b = m[rows[1]];
        const auto& c = m[rows[2]];
        const Integer minor = a[0] * (b[1] * c[2] - b[2] * c[1]) -
                              a[1] * (b[0] * c[2] - b[2] * c[0]) +
                              a[2] * (b[0] * c[1] - b[1] * c[0]);
        det += ((r % 2 == 0) ? -1 : 1) * m[r][3] * minor;
        const double* pa = perm_rows[rows[0]];
        const double* pb = perm_rows[rows[1]];
        const double* pc = perm_rows[rows[2]];
        const long double perm_minor =
            static_cast<long double>(pa[0]) * (pb[1] * pc[2] + pb[2] * pc[1]) +
            static_cast<long double>(pa[1]) * (pb[0] * pc[2] + pb[2] * pc[0]) +
            static_cast<long double>(pa[2]) * (pb[0] * pc[1] + pb[1] * pc[0]);
        permanent += perm_rows[r][3] * perm_minor;
    }
    const Sign sign = det > 0 ? Sign::kPos : (det < 0 ? Sign::kNeg : Sign::kZero);
    const double magnitude =
        std::ldexp(static_cast<double>(boost::multiprecision::abs(det)), -5 * scale);
    return {magnitude / (kUnitRoundoffSquared * static_cast<double>(permanent)), sign};
}

Reference orient3d_reference(const std::array<Point3, 4>& p) {
    int scale = 0;
    for (const Point3& q : p) {
        for (const double v : {q.x, q.y, q.z}) {
            if (v != 0.0) {
                scale = std::max(scale, 52 - std::ilogb(v));
            }
        }
    }
    Integer m[3][3];
    double perm_rows[3][3];
    for (int i = 0; i < 3; ++i) {
        m[i][0] = scaled_integer(p[i].x, scale) - scaled_integer(p[3].x, scale);
        m[i][1] = scaled_integer(p[i].y, scale) - scaled_integer(p[3].y, scale);
        m[i][2] = scaled_integer(p[i].z, scale) - scaled_integer(p[3].z, scale);
        perm_rows[i][0] = std::abs(p[i].x - p[3].x);
        perm_rows[i][1] = std::abs(p[i].y - p[3].y);
        perm_rows[i][2] = std::abs(p[i].z - p[3].z);
    }
    Integer det = 0;
    long double permanent = 0.0L;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        det += m[i][2] * (m[j][0] * m[k][1] - m[j][1] * m[k][0]);
        permanent += static_cast<long double>(perm_rows[i][2]) *
                     (static_cast<long double>(perm_rows[j][0]) * perm_rows[k][1] +
                      static_cast<long double>(perm_rows[j][1]) * perm_rows[k][0]);
    }
    const Sign sign = det > 0 ? Sign::kPos : (det < 0 ? Sign::kNeg : Sign::kZero);
    const double magnitude =
        std::ldexp(static_cast<double>(boost::multiprecision::abs(det)), -3 * scale);
    return {magnitude / (kUnitRoundoffSquared * static_cast<double>(permanent)), sign};
}

detail::LiftedRows lifted_rows(const std::array<WeightedPoint3, 5>& p) {
    detail::LiftedRows rows{};
    for (int i = 0; i < 4; ++i) {
        detail::two_diff(p[i].x, p[4].x, rows.x[i], rows.xt[i]);
        detail::two_diff(p[i].y, p[4].y, rows.y[i], rows.yt[i]);
        detail::two_diff(p[i].z, p[4].z, rows.z[i], rows.zt[i]);
        detail::two_diff(p[i].w, p[4].w, rows.w[i], rows.wt[i]);
    }
    return rows;
}

/// The stage as insphere runs it: with the permanent of its stage A (insphere_permanent.h).
std::optional<Sign> insphere_stage(const detail::LiftedRows& rows) {
    return detail::lifted_double_double(rows, detail::insphere_row_permanent(rows));
}

/// The stage as orient4d runs it.
std::optional<Sign> orient4d_stage(const detail::LiftedRows& rows) {
    return detail::lifted_double_double(rows, detail::lifted_permanent(rows));
}

class Source {
public:
    explicit Source(std::uint64_t seed) : rng_(seed) {}

    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

    /// A random multiple of 2^-bits in (-1, 1): bits significant bits at most.
    double fraction(int bits) {
        const auto n = std::uniform_int_distribution<std::int64_t>(
            -(std::int64_t{1} << bits) + 1, (std::int64_t{1} << bits) - 1)(rng_);
        return std::ldexp(static_cast<double>(n), -bits);
    }

    /// +-m 2^-k with a random 53-bit m in [1, 2).
    double tiny(int k) {
        const double m = 1.0 + std::uniform_real_distribution<double>(0.0, 1.0)(rng_);
        return std::ldexp(integer(0, 1) == 0 ? m : -m, -k);
    }

private:
    std::mt19937_64 rng_;
};

/// Counts of the sweep: where the queries fell relative to the threshold and what the stage did.
struct Sweep {
    Threshold threshold;
    int accepted = 0;
    int declined_below = 0;  // declined with |det| under the threshold: the bound at work
    int must_accept = 0;
    int mismatches = 0;

    void check(const std::string& query,
               const Reference& ref,
               std::optional<Sign> stage,
               Sign staged,
               Sign oracle_sign) {
        EXPECT_EQ(ref.sign, oracle_sign) << "reference determinant: " << query;
        if (stage) {
            ++accepted;
            if (*stage != oracle_sign && ++mismatches <= 5) {
                ADD_FAILURE() << "stage sign " << to_int(*stage) << ", oracle "
                              << to_int(oracle_sign)
                              << ", |det| / u^2 P = " << ref.det_over_bound_unit << ": " << query;
            }
        } else if (ref.det_over_bound_unit < threshold.accept) {
            ++declined_below;
        }
        if (ref.det_over_bound_unit > threshold.must_accept) {
            ++must_accept;
            EXPECT_TRUE(stage.has_value())
                << "declined at |det| / u^2 P = " << ref.det_over_bound_unit << ": " << query;
        }
        if (staged != oracle_sign && ++mismatches <= 5) {
            ADD_FAILURE() << "staged sign " << to_int(staged) << ", oracle " << to_int(oracle_sign)
                          << ": " << query;
        }
    }

    void expect_threshold_probed() const {
        EXPECT_EQ(mismatches, 0);
        EXPECT_GT(accepted, kQueries / 10);
        EXPECT_GT(declined_below, kQueries / 10);
        EXPECT_GT(must_accept, kQueries / 10);
    }
};

template <typename P, std::size_t N>
std::string hex(const std::array<P, N>& points) {
    std::string text;
    char buffer[64];
    for (const P& q : points) {
        for (const double v : {q.x, q.y, q.z}) {
            std::snprintf(buffer, sizeof buffer, "%a ", v);
            text += buffer;
        }
        if constexpr (std::is_same_v<P, WeightedPoint3>) {
            std::snprintf(buffer, sizeof buffer, "%a", q.w);
            text += buffer;
        }
        text += "  ";
    }
    return text;
}

TEST(DoubleDoubleBound, Insphere) {
    // Integer points of the sphere of radius 25, translated so that the last one is the origin,
    // which then moves by tiny amounts in all three coordinates.
    constexpr int kSphere[][3] = {
        {9, 12, 20}, {12, 9, 20}, {20, 9, 12}, {0, 0, 25}, {15, 20, 0}, {20, 0, 15}, {0, 7, 24}};
    Source s(7001);
    Sweep sweep{kLifted};
    for (int q = 0; q < kQueries; ++q) {
        int offsets[5][3];
        for (auto& o : offsets) {
            const auto& k = kSphere[s.integer(0, 6)];
            for (int c = 0; c < 3; ++c) {
                o[c] = (s.integer(0, 1) * 2 - 1) * k[c];
            }
        }
        std::array<WeightedPoint3, 5> p;
        for (int i = 0; i < 4; ++i) {
            p[i] = {double(offsets[i][0] - offsets[4][0]),
                    double(offsets[i][1] - offsets[4][1]),
                    double(offsets[i][2] - offsets[4][2]),
                    0.0};
        }
        const int k = s.integer(60, 135);
        p[4] = {s.tiny(k), s.tiny(k + s.integer(0, 3)), s.tiny(k + s.integer(0, 3)), 0.0};
        const auto point = [](const WeightedPoint3& r) { return Point3{r.x, r.y, r.z}; };
        sweep.check(
            hex(p),
            lifted_reference(p),
            insphere_stage(lifted_rows(p)),
            insphere(point(p[0]), point(p[1]), point(p[2]), point(p[3]), point(p[4])),
            oracle::insphere(point(p[0]), point(p[1]), point(p[2]), point(p[3]), point(p[4])));
    }
    sweep.expect_threshold_probed();
}

TEST(DoubleDoubleBound, Orient4d) {
    // Points lifted onto the hyperplane h = a.p through the origin (weights |p|^2 - a.p, exact:
    // coordinates of 20 significant bits, integer a), the last one the origin with weight 0,
    // which then moves by tiny amounts in its coordinates and its weight. The products of the
    // stage beyond the 2x2 minors are rounded.
    Source s(7002);
    Sweep sweep{kLifted};
    for (int q = 0; q < kQueries; ++q) {
        const double a[3] = {
            double(s.integer(-9, 9)), double(s.integer(-9, 9)), double(s.integer(-9, 9))};
        std::array<WeightedPoint3, 5> p;
        for (int i = 0; i < 4; ++i) {
            const double x = s.fraction(20), y = s.fraction(20), z = s.fraction(20);
            p[i] = {x, y, z, x * x + y * y + z * z - (a[0] * x + a[1] * y + a[2] * z)};
        }
        const int k = s.integer(60, 135);
        p[4] = {s.tiny(k),
                s.tiny(k + s.integer(0, 3)),
                s.tiny(k + s.integer(0, 3)),
                s.tiny(k - s.integer(0, 6))};
        sweep.check(hex(p),
                    lifted_reference(p),
                    orient4d_stage(lifted_rows(p)),
                    orient4d(p[0], p[1], p[2], p[3], p[4]),
                    oracle::orient4d(p[0], p[1], p[2], p[3], p[4]));
    }
    sweep.expect_threshold_probed();
}

TEST(DoubleDoubleBound, FusedProductsAgreeBitForBit) {
    // The fused multiply-add variant of the stage (fused_products.h) must compute the same
    // determinant, head and tail, as Dekker's products: near-degenerate lifted rows whose products
    // are rounded, and rows of random doubles of 53 bits over the whole exponent window.
    if (!detail::fused_products_available()) {
        GTEST_SKIP() << "this processor has no fused multiply-add";
    }
    Source s(7004);
    const auto same = [](const detail::DoubleDouble& a, const detail::DoubleDouble& b) {
        return std::bit_cast<std::uint64_t>(a.hi) == std::bit_cast<std::uint64_t>(b.hi) &&
               std::bit_cast<std::uint64_t>(a.lo) == std::bit_cast<std::uint64_t>(b.lo);
    };
    int differ = 0;
    for (int q = 0; q < kQueries; ++q) {
        std::array<WeightedPoint3, 5> p;
        if (q % 2 == 0) {
            for (int i = 0; i < 4; ++i) {
                const double x = s.fraction(20), y = s.fraction(20), z = s.fraction(20);
                p[i] = {x, y, z, x * x + y * y + z * z};
            }
            const int k = s.integer(60, 135);
            p[4] = {s.tiny(k), s.tiny(k + 1), s.tiny(k + 2), s.tiny(k - 3)};
        } else {
            const int e = s.integer(-120, 120);
            for (auto& r : p) {
                r = {s.tiny(-e - s.integer(0, 20)),
                     s.tiny(-e - s.integer(0, 20)),
                     s.tiny(-e - s.integer(0, 20)),
                     s.integer(0, 1) == 0 ? 0.0 : s.tiny(-2 * e)};
            }
        }
        const detail::LiftedRows rows = lifted_rows(p);
        const detail::DoubleDouble dekker =
            detail::lifted_double_double_determinant(rows, detail::ProductKind::kDekker);
        const detail::DoubleDouble fused =
            detail::lifted_double_double_determinant(rows, detail::ProductKind::kFused);
        if (!same(dekker, fused) && ++differ <= 3) {
            ADD_FAILURE() << hex(p) << ": Dekker " << dekker.hi << " + " << dekker.lo << ", fused "
                          << fused.hi << " + " << fused.lo;
        }
    }
    EXPECT_EQ(differ, 0);
}

TEST(DoubleDoubleBound, ExactRowsAgreeWithTheGeneralEvaluation) {
    // Rows whose differences are exact (tails zero) take products without the tail terms
    // (lifted_adaptive.cpp): the determinant must have the same value, head and tail, as the
    // general evaluation, with both ways of finding the products' errors. Nearby points of 30
    // significant bits (their differences exact), near-cospherical or near-lifted.
    Source s(7006);
    int differ = 0;
    int compared = 0;
    for (int q = 0; q < kQueries; ++q) {
        std::array<WeightedPoint3, 5> p;
        const int e = s.integer(-100, 100);
        for (auto& r : p) {
            const double x = std::ldexp(0.5 + std::ldexp(s.fraction(30), -2), e);
            const double y = std::ldexp(0.5 + std::ldexp(s.fraction(30), -2), e);
            const double z = std::ldexp(0.5 + std::ldexp(s.fraction(30), -2), e);
            r = {x, y, z, q % 2 == 0 ? 0.0 : std::ldexp(s.fraction(30), 2 * e)};
        }
        detail::LiftedRows rows = lifted_rows(p);
        double tails = 0.0;
        for (int i = 0; i < 4; ++i) {
            tails += std::abs(rows.xt[i]) + std::abs(rows.yt[i]) + std::abs(rows.zt[i]) +
                     std::abs(rows.wt[i]);
        }
        ASSERT_EQ(tails, 0.0) << hex(p);
        for (const auto kind : {detail::ProductKind::kDekker, detail::ProductKind::kFused}) {
            if (kind == detail::ProductKind::kFused && !detail::fused_products_available()) {
                continue;
            }
            rows.differences_exact = false;
            const detail::DoubleDouble general =
                detail::lifted_double_double_determinant(rows, kind);
            rows.differences_exact = true;
            const detail::DoubleDouble exact = detail::lifted_double_double_determinant(rows, kind);
            ++compared;
            // Equal values (a zero's sign may differ).
            if ((general.hi != exact.hi || general.lo != exact.lo) && ++differ <= 3) {
                ADD_FAILURE() << hex(p) << ": general " << general.hi << " + " << general.lo
                              << ", exact rows " << exact.hi << " + " << exact.lo;
            }
        }
    }
    EXPECT_EQ(differ, 0);
    EXPECT_GE(compared, kQueries);
}

TEST(DoubleDoubleBound, Orient3d) {
    // Points of a plane z = a x + b y through the origin (a, b in {0, +-1/2, +-1, +-2}), with
    // coordinates of 40 significant bits, so that z is exact and the products in the stage are
    // rounded; the last one, the origin, moves by tiny amounts in all three coordinates.
    Source s(7003);
    Sweep sweep{kOrient3d};
    constexpr double kSlopes[] = {0.0, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0};
    for (int q = 0; q < kQueries; ++q) {
        const double a = kSlopes[s.integer(0, 6)], b = kSlopes[s.integer(0, 6)];
        std::array<Point3, 4> p;
        for (int i = 0; i < 3; ++i) {
            const double x = s.fraction(40), y = s.fraction(40);
            p[i] = {x, y, a * x + b * y};
        }
        const int k = s.integer(60, 135);
        p[3] = {s.tiny(k), s.tiny(k + s.integer(0, 3)), s.tiny(k + s.integer(0, 3))};
        detail::DoubleDouble x[3], y[3], z[3];
        for (int i = 0; i < 3; ++i) {
            x[i] = detail::exact_difference(p[i].x, p[3].x);
            y[i] = detail::exact_difference(p[i].y, p[3].y);
            z[i] = detail::exact_difference(p[i].z, p[3].z);
        }
        sweep.check(hex(p),
                    orient3d_reference(p),
                    detail::orient3d_double_double(x, y, z),
                    orient3d(p[0], p[1], p[2], p[3]),
                    oracle::orient3d(p[0], p[1], p[2], p[3]));
    }
    sweep.expect_threshold_probed();
}

}  // namespace
}  // namespace cavity::predicates
