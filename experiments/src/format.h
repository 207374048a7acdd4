#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cavity/core/base/error.h"
#include "cavity/core/order/insertion_order.h"

/// Small helpers shared by the measurement files (private to the experiments layer).
namespace cavity::experiments::detail {

/// A double with 6 significant digits, enough for every ratio the report quotes.
inline std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

inline std::string number(std::uint64_t value) {
    return std::to_string(value);
}

/// A sample's sum and sum of squares, for its mean and its standard deviation (n - 1 in the
/// denominator) over the insertion orders of a run.
struct Moments {
    double sum = 0;
    double squares = 0;

    void add(double x) {
        sum += x;
        squares += x * x;
    }

    double mean(double count) const { return sum / count; }

    double sd(double count) const {
        if (count < 2) {
            return 0.0;
        }
        const double m = sum / count;
        return std::sqrt(std::max(0.0, (squares - count * m * m) / (count - 1)));
    }
};

/// The insertion-order options of a suite's order name ("brio-noreverse" is BRIO without the
/// reversal of alternate rounds; "brio:R" is BRIO with ratio R in [0, 1), overriding the suite's
/// brio-ratio). Order seeds are offset from point seeds so that the two random streams differ.
/// \throws core::Error for an unknown name or a ratio that is not a number in [0, 1).
inline core::OrderOptions order_options(const std::string& name,
                                        double brio_ratio,
                                        std::uint64_t seed) {
    core::OrderOptions options;
    options.brio_ratio = brio_ratio;
    std::string kind = name == "brio-noreverse" ? "brio" : name;
    if (name.rfind("brio:", 0) == 0) {
        const std::string ratio = name.substr(5);
        char* stop = nullptr;
        options.brio_ratio = std::strtod(ratio.c_str(), &stop);
        if (ratio.empty() || stop != ratio.c_str() + ratio.size() ||
            !(options.brio_ratio >= 0 && options.brio_ratio < 1)) {
            throw core::Error("order '" + name + "': the BRIO ratio must be a number in [0, 1)");
        }
        kind = "brio";
    }
    options.kind = core::parse_order_kind(kind);
    options.reverse_alternate_rounds = name != "brio-noreverse";
    options.seed = seed + 1000;
    return options;
}

}  // namespace cavity::experiments::detail
