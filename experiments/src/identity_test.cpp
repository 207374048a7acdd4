#include "cavity/experiments/identity_test.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavity::experiments {

IdentityTest::IdentityTest(std::span<const double> expected,
                           std::uint64_t orders,
                           double min_events) {
    const auto all_orders = static_cast<double>(orders);
    bin_of_j_.resize(expected.size());
    bool pooling = false;
    for (std::size_t j = 0; j < expected.size(); ++j) {
        if (!pooling) {
            // A bin of its own, or the first j of the pooled tail.
            pooling = j >= 1 && all_orders * expected[j] < min_events;
            expected_.push_back(0);
        }
        bin_of_j_[j] = expected_.size() - 1;
        expected_.back() += expected[j];
    }
    sum_.assign(expected_.size(), 0);
    cross_.assign(expected_.size() * expected_.size(), 0);
    h_.assign(expected_.size(), 0);
}

void IdentityTest::add(const std::map<std::uint64_t, std::uint64_t>& created_by_j) {
    std::fill(h_.begin(), h_.end(), 0);
    for (const auto& [j, count] : created_by_j) {
        // A j beyond the table cannot be created; it shows in the last bin as a deviation.
        h_[j < bin_of_j_.size() ? bin_of_j_[j] : h_.size() - 1] += count;
    }
    const std::size_t p = h_.size();
    for (std::size_t a = 0; a < p; ++a) {
        sum_[a] += h_[a];
        if (h_[a] == 0) {
            continue;
        }
        for (std::size_t b = 0; b <= a; ++b) {
            cross_[a * p + b] += h_[a] * h_[b];
        }
    }
    ++orders_;
}

IdentityTest::Result IdentityTest::result() const {
    Result result;
    const std::size_t p = h_.size();
    const auto r = static_cast<double>(orders_);
    if (orders_ < 2) {
        result.t2 = std::numeric_limits<double>::quiet_NaN();
        return result;
    }
    const auto covariance = [&](std::size_t a, std::size_t b) {
        const std::uint64_t cross = a >= b ? cross_[a * p + b] : cross_[b * p + a];
        return (static_cast<double>(cross) -
                static_cast<double>(sum_[a]) * static_cast<double>(sum_[b]) / r) /
               (r - 1);
    };
    // Bins whose count never varies (j = 0 always, and bins never created) carry no variance:
    // they are compared exactly and left out of the covariance.
    std::vector<std::size_t> varying;
    std::vector<double> deviation;
    for (std::size_t a = 0; a < p; ++a) {
        const double mean = static_cast<double>(sum_[a]) / r;
        if (cross_[a * p + a] * orders_ == sum_[a] * sum_[a]) {
            ++result.fixed;
            if (std::fabs(mean - expected_[a]) > 1e-9 * std::max(1.0, expected_[a])) {
                result.t2 = std::numeric_limits<double>::infinity();
            }
            continue;
        }
        varying.push_back(a);
        deviation.push_back(mean - expected_[a]);
    }
    const std::size_t q = varying.size();
    result.bins = q;
    if (std::isinf(result.t2)) {
        return result;
    }
    // Cholesky S = L Lᵀ, then T² = R |L⁻¹ d|².
    std::vector<double> l(q * q, 0.0);
    for (std::size_t a = 0; a < q; ++a) {
        for (std::size_t b = 0; b <= a; ++b) {
            double s = covariance(varying[a], varying[b]);
            for (std::size_t k = 0; k < b; ++k) {
                s -= l[a * q + k] * l[b * q + k];
            }
            if (a == b) {
                if (!(s > 0)) {
                    result.t2 = std::numeric_limits<double>::quiet_NaN();
                    return result;
                }
                l[a * q + a] = std::sqrt(s);
            } else {
                l[a * q + b] = s / l[b * q + b];
            }
        }
    }
    double t2 = 0;
    std::vector<double> y(q);
    for (std::size_t a = 0; a < q; ++a) {
        double s = deviation[a];
        for (std::size_t k = 0; k < a; ++k) {
            s -= l[a * q + k] * y[k];
        }
        y[a] = s / l[a * q + a];
        t2 += y[a] * y[a];
    }
    result.t2 = r * t2;
    return result;
}

}  // namespace cavity::experiments
