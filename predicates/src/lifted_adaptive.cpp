#include "lifted_adaptive.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cavity/predicates/detail/expansion.h"
#include "small_integers.h"

namespace cavity::predicates::detail {
namespace {

// Error of the determinant of the rounded differences (u = 2^-53). With d = d~ + t, |t| <= u|d~|,
// each monomial (degree 5 in the coordinate differences, degree 4 when it holds a weight
// difference) moves by at most ((1 + u)^5 - 1) |m~| <= (5u + 10u^2 + 10u^3 + ...) |m~|. The
// permanent sum |m~|, with |dw| in place of -dw, is computed in doubles with at most 13 roundings
// along a path, and |det~| >= (1 - 2u) |largest component|. Accepting when |largest| >
// fl(C * permanent) needs C >= (5u + 11u^2) / ((1 - u)^14 (1 - 2u)) ~ 5u + 85u^2.
constexpr double kU = 0x1p-53;
constexpr double kRoundedDifferenceBound = (5.0 + 256.0 * kU) * kU;

/// h = sign * minor * (x^2 + y^2 + z^2 - w), exactly; h needs room for 14 * minor_len
/// components. Returns the length of h.
int lifted_term(int minor_len,
                const double* minor,
                double sign,
                double x,
                double y,
                double z,
                double w,
                double* h) {
    double once[48];
    double x_part[96];
    double y_part[96];
    double z_part[96];
    int once_len = scale_expansion(minor_len, minor, sign * x, once);
    const int x_len = scale_expansion(once_len, once, x, x_part);
    once_len = scale_expansion(minor_len, minor, sign * y, once);
    const int y_len = scale_expansion(once_len, once, y, y_part);
    once_len = scale_expansion(minor_len, minor, sign * z, once);
    const int z_len = scale_expansion(once_len, once, z, z_part);
    double xy[192];
    const int xy_len = expansion_sum(x_len, x_part, y_len, y_part, xy);
    if (w == 0.0) {
        return expansion_sum(xy_len, xy, z_len, z_part, h);
    }
    double xyz[288];
    const int xyz_len = expansion_sum(xy_len, xy, z_len, z_part, xyz);
    const int w_len = scale_expansion(minor_len, minor, -sign * w, once);
    return expansion_sum(xyz_len, xyz, w_len, once, h);
}

/// h = r * s - t * u + v * q for scalars r, t, v and expansions s, u, q of at most 4 components
/// (a 3x3 minor expanded along its z column). h needs room for 24 components.
int minor3(double r,
           int s_len,
           const double* s,
           double t,
           int u_len,
           const double* u,
           double v,
           int q_len,
           const double* q,
           double* h) {
    double rs[8];
    double tu[8];
    double vq[8];
    const int rs_len = scale_expansion(s_len, s, r, rs);
    const int tu_len = scale_expansion(u_len, u, -t, tu);
    const int vq_len = scale_expansion(q_len, q, v, vq);
    double partial[16];
    const int partial_len = expansion_sum(rs_len, rs, tu_len, tu, partial);
    return expansion_sum(partial_len, partial, vq_len, vq, h);
}

}  // namespace

std::optional<Sign> lifted_adaptive(const LiftedRows& rows) {
    const double* x = rows.x;
    const double* y = rows.y;
    const double* z = rows.z;
    const double* w = rows.w;

    enum { kA = 0, kB = 1, kC = 2, kD = 3 };

    // 2x2 minors of the x, y columns, then 3x3 minors along z (Shewchuk's insphere layout).
    double ab[4], bc[4], cd[4], da[4], ac[4], bd[4];
    const int ab_len = product_difference(x[kA], y[kB], x[kB], y[kA], ab);
    const int bc_len = product_difference(x[kB], y[kC], x[kC], y[kB], bc);
    const int cd_len = product_difference(x[kC], y[kD], x[kD], y[kC], cd);
    const int da_len = product_difference(x[kD], y[kA], x[kA], y[kD], da);
    const int ac_len = product_difference(x[kA], y[kC], x[kC], y[kA], ac);
    const int bd_len = product_difference(x[kB], y[kD], x[kD], y[kB], bd);

    double abc[24], bcd[24], cda[24], dab[24];
    // abc = aez*bc - bez*ac + cez*ab, bcd = bez*cd - cez*bd + dez*bc,
    // cda = cez*da + dez*ac + aez*cd, dab = dez*ab + aez*bd + bez*da.
    const int abc_len = minor3(z[kA], bc_len, bc, z[kB], ac_len, ac, z[kC], ab_len, ab, abc);
    const int bcd_len = minor3(z[kB], cd_len, cd, z[kC], bd_len, bd, z[kD], bc_len, bc, bcd);
    const int cda_len = minor3(z[kC], da_len, da, -z[kD], ac_len, ac, z[kA], cd_len, cd, cda);
    const int dab_len = minor3(z[kD], ab_len, ab, -z[kA], bd_len, bd, z[kB], da_len, da, dab);

    // det = (dlift*abc - clift*dab) + (blift*cda - alift*bcd)
    double d_term[336], c_term[336], b_term[336], a_term[336];
    const int d_len = lifted_term(abc_len, abc, 1.0, x[kD], y[kD], z[kD], w[kD], d_term);
    const int c_len = lifted_term(dab_len, dab, -1.0, x[kC], y[kC], z[kC], w[kC], c_term);
    const int b_len = lifted_term(cda_len, cda, 1.0, x[kB], y[kB], z[kB], w[kB], b_term);
    const int a_len = lifted_term(bcd_len, bcd, -1.0, x[kA], y[kA], z[kA], w[kA], a_term);
    double dc[672], ba[672];
    const int dc_len = expansion_sum(d_len, d_term, c_len, c_term, dc);
    const int ba_len = expansion_sum(b_len, b_term, a_len, a_term, ba);
    double det[1344];
    const int det_len = expansion_sum(dc_len, dc, ba_len, ba, det);

    if (rows.differences_exact) {
        return static_cast<Sign>(expansion_sign(det_len, det));
    }
    auto perm2 = [&](int i, int j) { return std::abs(x[i] * y[j]) + std::abs(x[j] * y[i]); };
    auto perm3 = [&](int i, int j, int k) {
        return std::abs(z[i]) * perm2(j, k) + std::abs(z[j]) * perm2(i, k) +
               std::abs(z[k]) * perm2(i, j);
    };
    auto lift = [&](int i) { return x[i] * x[i] + y[i] * y[i] + z[i] * z[i] + std::abs(w[i]); };
    const double permanent = (lift(kD) * perm3(kA, kB, kC) + lift(kC) * perm3(kA, kB, kD)) +
                             (lift(kB) * perm3(kA, kC, kD) + lift(kA) * perm3(kB, kC, kD));
    if (det_len > 0 && std::abs(det[det_len - 1]) > kRoundedDifferenceBound * permanent) {
        return static_cast<Sign>(expansion_sign(det_len, det));
    }
    return std::nullopt;
}

}  // namespace cavity::predicates::detail

namespace cavity::predicates::detail {

std::optional<Sign> lifted_small_integers(const LiftedRows& rows) {
    const double* x = rows.x;
    const double* y = rows.y;
    const double* z = rows.z;
    const double* w = rows.w;
    double max = 0.0;
    for (int i = 0; i < 4; ++i) {
        max = std::max({max, std::abs(x[i]), std::abs(y[i]), std::abs(z[i])});
    }
    if (max > 0x1p16) {
        return std::nullopt;
    }
    // With differences of at most 2^16: the 2x2 minors are below 2^33 and the 3x3 minors below
    // 2^51, exact in doubles; the lifts x^2 + y^2 + z^2 - dw (|dw| < 2^51 for weights below 2^50)
    // are below 2^52, exact too; the four products lift * minor, below 2^103, and their sum are
    // exact in 128-bit integers.
    const double ab = x[0] * y[1] - x[1] * y[0];
    const double bc = x[1] * y[2] - x[2] * y[1];
    const double cd = x[2] * y[3] - x[3] * y[2];
    const double da = x[3] * y[0] - x[0] * y[3];
    const double ac = x[0] * y[2] - x[2] * y[0];
    const double bd = x[1] * y[3] - x[3] * y[1];
    const auto abc = static_cast<std::int64_t>(z[0] * bc - z[1] * ac + z[2] * ab);
    const auto bcd = static_cast<std::int64_t>(z[1] * cd - z[2] * bd + z[3] * bc);
    const auto cda = static_cast<std::int64_t>(z[2] * da + z[3] * ac + z[0] * cd);
    const auto dab = static_cast<std::int64_t>(z[3] * ab + z[0] * bd + z[1] * da);
    std::int64_t lift[4];
    for (int i = 0; i < 4; ++i) {
        lift[i] = static_cast<std::int64_t>(x[i] * x[i] + y[i] * y[i] + z[i] * z[i] - w[i]);
    }
    const Int128 det = (Int128{lift[3]} * abc - Int128{lift[2]} * dab) +
                       (Int128{lift[1]} * cda - Int128{lift[0]} * bcd);
    return sign_of(det);
}

}  // namespace cavity::predicates::detail
