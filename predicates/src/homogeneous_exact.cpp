#include "homogeneous_exact.h"

#include <algorithm>
#include <cstddef>
#include <tuple>

#include <gmp.h>

#include "cavity/predicates/dyadic.h"

namespace cavity::predicates::detail {

namespace {

/// N integers, each given room for `bits` bits up front (one allocation each, none later while
/// values stay within it).
template <std::size_t N>
class Integers {
public:
    explicit Integers(const std::array<mp_bitcnt_t, N>& bits) {
        for (std::size_t i = 0; i < N; ++i) {
            mpz_init2(values_[i], bits[i]);
        }
    }

    ~Integers() {
        for (auto& v : values_) {
            mpz_clear(v);
        }
    }

    Integers(const Integers&) = delete;
    Integers& operator=(const Integers&) = delete;

    mpz_ptr operator[](std::size_t i) { return values_[i]; }

private:
    std::array<mpz_t, N> values_;
};

template <std::size_t N>
using Entries = std::array<std::array<mpz_srcptr, N>, N>;

mp_bitcnt_t bits_of(const ExactInteger& x) {
    return mpz_sizeinbase(x.backend().data(), 2);
}

/// The sign of det m by the Laplace expansion of homogeneous.h's determinant: minor[mask] is the
/// determinant of the last popcount(mask) rows restricted to the columns in mask. `entry_bits`
/// bounds the bits of every entry, so a minor of k rows, a sum of k! products of k entries,
/// has fewer than k (entry_bits + 3) bits.
template <std::size_t N>
int determinant_sign(const Entries<N>& m, mp_bitcnt_t entry_bits) {
    constexpr unsigned kMasks = 1u << N;
    std::array<mp_bitcnt_t, kMasks> room{};
    for (unsigned mask = 1; mask < kMasks; ++mask) {
        room[mask] = kMaskSize<N>[mask] * (entry_bits + 3);
    }
    Integers<kMasks> storage(room);
    std::array<mpz_srcptr, kMasks> minor{};
    for (std::size_t j = 0; j < N; ++j) {
        minor[1u << j] = m[N - 1][j];  // the last row's entries are its one-row minors
    }
    for (std::size_t size = 2; size <= N; ++size) {
        const std::size_t row = N - size;
        for (unsigned mask = 0; mask < kMasks; ++mask) {
            if (kMaskSize<N>[mask] != size) {
                continue;
            }
            const mpz_ptr sum = storage[mask];
            bool first = true;
            bool plus = true;  // the sign alternates along the row of the submatrix
            for (std::size_t j = 0; j < N; ++j) {
                if ((mask & (1u << j)) == 0) {
                    continue;
                }
                const mpz_srcptr rest = minor[mask & ~(1u << j)];
                if (first) {
                    mpz_mul(sum, m[row][j], rest);
                } else if (plus) {
                    mpz_addmul(sum, m[row][j], rest);
                } else {
                    mpz_submul(sum, m[row][j], rest);
                }
                first = false;
                plus = !plus;
            }
            minor[mask] = sum;
        }
    }
    return mpz_sgn(minor[kMasks - 1]);
}

}  // namespace

// X = den a + num (b - a) = (den - num) a + num b: two products of an integer by a scaled
// double each, where homogeneous<ExactInteger> made integers of a, b, b - a and both products
// first.
Homogeneous<ExactInteger> segment_row(const SegmentParameterPoint& s,
                                      int scale,
                                      int parameter_scale) {
    Homogeneous<ExactInteger> h;
    h.w = scaled_to_integer<ExactInteger>(s.denominator, parameter_scale);
    const ExactInteger num = scaled_to_integer<ExactInteger>(s.numerator, parameter_scale);
    ExactInteger rest;
    mpz_sub(rest.backend().data(), h.w.backend().data(), num.backend().data());
    ExactInteger term;
    for (const auto& [out, a, b] : {std::tuple{&h.x, s.a.x, s.b.x},
                                    std::tuple{&h.y, s.a.y, s.b.y},
                                    std::tuple{&h.z, s.a.z, s.b.z}}) {
        set_scaled_product(out->backend().data(), rest.backend().data(), a, scale);
        set_scaled_product(term.backend().data(), num.backend().data(), b, scale);
        mpz_add(out->backend().data(), out->backend().data(), term.backend().data());
    }
    return h;
}

int homogeneous_orient3d_sign(const std::array<Homogeneous<ExactInteger>, 4>& rows) {
    int w_signs = 1;
    mp_bitcnt_t bits = 1;
    Entries<4> m{};
    for (std::size_t i = 0; i < 4; ++i) {
        const Homogeneous<ExactInteger>& h = rows[i];
        w_signs *= h.w.sign();
        m[i] = {
            h.x.backend().data(), h.y.backend().data(), h.z.backend().data(), h.w.backend().data()};
        bits = std::max({bits, bits_of(h.x), bits_of(h.y), bits_of(h.z), bits_of(h.w)});
    }
    // As generic_predicates.cpp's orient3d_sign: a zero W leaves the sign undecided (0).
    if (w_signs == 0) {
        return 0;
    }
    return w_signs * determinant_sign<4>(m, bits);
}

int homogeneous_insphere_sign(const std::array<Homogeneous<ExactInteger>, 5>& rows) {
    mp_bitcnt_t coordinate_bits = 1;
    for (const Homogeneous<ExactInteger>& h : rows) {
        coordinate_bits =
            std::max({coordinate_bits, bits_of(h.x), bits_of(h.y), bits_of(h.z), bits_of(h.w)});
    }
    // A product of two coordinates has at most twice their bits, a sum of three two more.
    const mp_bitcnt_t entry_bits = 2 * coordinate_bits + 2;
    std::array<mp_bitcnt_t, 25> room{};
    room.fill(entry_bits);
    Integers<25> entries(room);
    Entries<5> m{};
    for (std::size_t i = 0; i < 5; ++i) {
        const mpz_srcptr x = rows[i].x.backend().data();
        const mpz_srcptr y = rows[i].y.backend().data();
        const mpz_srcptr z = rows[i].z.backend().data();
        const mpz_srcptr w = rows[i].w.backend().data();
        const auto e = [&](std::size_t j) { return entries[5 * i + j]; };
        mpz_mul(e(0), x, w);
        mpz_mul(e(1), y, w);
        mpz_mul(e(2), z, w);
        mpz_mul(e(3), x, x);
        mpz_addmul(e(3), y, y);
        mpz_addmul(e(3), z, z);
        mpz_mul(e(4), w, w);
        m[i] = {e(0), e(1), e(2), e(3), e(4)};
    }
    return determinant_sign<5>(m, entry_bits);
}

}  // namespace cavity::predicates::detail
