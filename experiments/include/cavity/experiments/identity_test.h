#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <vector>

/// A joint test of Proposition 5.2's identity E[h_j] = f_j / C(j+4, 4) over all j at once. The
/// tetrahedra created in one insertion order are dependent (one creation makes others likely or
/// impossible), so per-j binomial intervals are wrong; the orders themselves are independent. So
/// each order contributes one vector h (created solid tetrahedra by j), and Hotelling's T² =
/// R (h̄ - μ)ᵀ S⁻¹ (h̄ - μ), with S the covariance of h estimated over the R orders, follows
/// χ² with as many degrees of freedom as bins when the identity holds (R ≫ bins).
namespace cavity::experiments {

class IdentityTest {
public:
    /// `expected[j]`: the exact mean of h_j per order. j is binned alone while at least
    /// `min_events` creations are expected over all `orders`; from the first j ≥ 1 below that, the
    /// rest are pooled into one bin (the χ² approximation needs counts, not single events).
    IdentityTest(std::span<const double> expected, std::uint64_t orders, double min_events = 100);

    /// One order's h: j -> created solid j-tetrahedra.
    void add(const std::map<std::uint64_t, std::uint64_t>& created_by_j);

    struct Result {
        std::size_t bins = 0;   ///< degrees of freedom: bins whose count varies between orders
        double t2 = 0;          ///< Hotelling's T²; +inf when a bin that never varies is off
        std::size_t fixed = 0;  ///< bins with the same count in every order (j = 0: all of f_0)
    };

    Result result() const;

private:
    std::vector<std::size_t> bin_of_j_;
    std::vector<double> expected_;      ///< per bin
    std::vector<std::uint64_t> sum_;    ///< per bin, over orders
    std::vector<std::uint64_t> cross_;  ///< bins × bins, Σ over orders of h_a h_b
    std::vector<std::uint64_t> h_;      ///< scratch: this order's h by bin
    std::uint64_t orders_ = 0;
};

}  // namespace cavity::experiments
