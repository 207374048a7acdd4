#pragma once

#include <cstdint>

namespace cavity::core {

/// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", 2014): turns
/// one 64-bit seed into a stream of well-mixed words. Used only to seed Xoshiro256 from a single
/// integer, as its authors recommend.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E37'79B9'7F4A'7C15u);
        z = (z ^ (z >> 30)) * 0xBF58'476D'1CE4'E5B9u;
        z = (z ^ (z >> 27)) * 0x94D0'49BB'1331'11EBu;
        return z ^ (z >> 31);
    }

private:
    std::uint64_t state_;
};

/// xoshiro256** (Blackman, Vigna, "Scrambled linear pseudorandom number generators", 2021) with
/// the transforms cavity needs. Everything is integer or exactly rounded arithmetic, never a
/// std:: distribution or a libm function, so a seed gives the same numbers on every platform and
/// standard library; that is what makes generated inputs and random orders reproducible.
class Random {
public:
    explicit Random(std::uint64_t seed) {
        SplitMix64 mix(seed);
        for (std::uint64_t& word : state_) {
            word = mix.next();
        }
    }

    std::uint64_t next_u64() {
        const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
        const std::uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }

    /// Uniform in [0, 1): the top 53 bits as a multiple of 2^-53, so every value is exact.
    double uniform01() { return static_cast<double>(next_u64() >> 11) * 0x1p-53; }

    /// Uniform in [a, b).
    double uniform(double a, double b) { return a + (b - a) * uniform01(); }

    /// Uniform integer in [0, bound), bound > 0, without modulo bias: draws falling in the
    /// incomplete last block of 2^64 mod bound values are rejected.
    std::uint64_t below(std::uint64_t bound) {
        const std::uint64_t limit = (0 - bound) % bound;  // 2^64 mod bound
        for (;;) {
            const std::uint64_t r = next_u64();
            if (r >= limit) {
                return r % bound;
            }
        }
    }

    /// Approximately standard normal: the Irwin–Hall sum of 12 uniforms minus 6 (mean 0,
    /// variance 1, tails cut at ±6). Box–Muller would need log and cos, whose last bits differ
    /// between libm implementations; this uses additions only.
    double normal() {
        double sum = 0.0;
        for (int i = 0; i < 12; ++i) {
            sum += uniform01();
        }
        return sum - 6.0;
    }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

    std::uint64_t state_[4];
};

}  // namespace cavity::core
