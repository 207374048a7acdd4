#include "small_dyadic.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include "cavity/predicates/lattice.h"
#include "small_integers.h"
#include "staged_pipeline.h"

namespace cavity::predicates::detail {

namespace {

/// The width of a column: kNarrow when its entries are integers times one power of two below
/// 2^31, kWide when below 2^62, kOther otherwise.
enum class Width { kNarrow, kWide, kOther };

/// 2^(bits - 1 - t) for the column's largest magnitude in [2^t, 2^(t+1)), which brings it into
/// [2^(bits - 1), 2^bits); 0 when t or that exponent is not a normal one.
double scale_for(double largest, int bits) {
    const auto biased = static_cast<int>((std::bit_cast<std::uint64_t>(largest) >> 52) & 0x7ff);
    const int k = (bits - 1) - (biased - 1023);
    if (biased == 0 || biased == 0x7ff || k < -1022 || k > 1023) {
        return 0.0;
    }
    return power_of_two(k);
}

/// True when every entry scaled by `scale` is an integer (and none underflows to zero): then the
/// largest lands below 2^bits and the scaled entries are the integers sought. is_integral's round
/// trip through a 64-bit integer answers at any magnitude; the rounding test of is_small_integer
/// (adding and subtracting 1.5 * 2^52) holds only below 2^51, and a wide column reaches 2^62.
bool scaled_integers(const double (&column)[3], double scale, std::int64_t (&out)[3]) {
    for (int i = 0; i < 3; ++i) {
        const double v = column[i] * scale;
        if (!(std::abs(v) < 0x1p62) || !is_integral(v) || (v == 0.0 && column[i] != 0.0)) {
            return false;  // NaN fails the first test
        }
        out[i] = static_cast<std::int64_t>(v);
    }
    return true;
}

Width column_width(const double (&column)[3], std::int64_t (&out)[3]) {
    const double largest =
        std::fmax(std::fmax(std::abs(column[0]), std::abs(column[1])), std::abs(column[2]));
    if (largest == 0.0) {
        out[0] = out[1] = out[2] = 0;
        return Width::kNarrow;
    }
    const double narrow = scale_for(largest, 31);
    if (narrow != 0.0 && scaled_integers(column, narrow, out)) {
        return Width::kNarrow;
    }
    const double wide = scale_for(largest, 62);
    if (wide != 0.0 && scaled_integers(column, wide, out)) {
        return Width::kWide;
    }
    return Width::kOther;
}

}  // namespace

std::optional<Sign> orient3d_small_dyadic(const double (&x)[3],
                                          const double (&y)[3],
                                          const double (&z)[3]) {
    // Scaling a column by a power of two scales the determinant by it: each column has its own.
    std::int64_t c[3][3];
    const Width widths[3] = {column_width(x, c[0]), column_width(y, c[1]), column_width(z, c[2])};
    // Rotate the columns (which keeps the determinant) so that the last is the one that may be
    // wide: the 2x2 minors of the first two, below 2^63, then the products with the last, below
    // 2^125, and their sum, below 2^127.
    int last = 2;
    int wide = 0;
    for (int k = 0; k < 3; ++k) {
        if (widths[k] == Width::kOther) {
            return std::nullopt;
        }
        if (widths[k] == Width::kWide) {
            last = k;
            ++wide;
        }
    }
    if (wide > 1) {
        return std::nullopt;
    }
    const std::int64_t(&u)[3] = c[(last + 1) % 3];
    const std::int64_t(&v)[3] = c[(last + 2) % 3];
    const std::int64_t(&w)[3] = c[last];
    // det = w0 (u1 v2 - v1 u2) + w1 (u2 v0 - v2 u0) + w2 (u0 v1 - v0 u1)
    Int128 det = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        const std::int64_t minor = u[j] * v[k] - v[j] * u[k];
        det += Int128{w[i]} * minor;
    }
    return sign_of(det);
}

}  // namespace cavity::predicates::detail
