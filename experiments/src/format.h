#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "cavity/core/insertion_order.h"

/// Small helpers shared by the measurement files (private to the experiments layer).
namespace cavity::experiments::detail {

/// A double with 6 significant digits, enough for every ratio the report quotes.
inline std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

inline std::string number(std::uint64_t value) { return std::to_string(value); }

/// The insertion-order options of a suite's order name ("brio-noreverse" is BRIO without the
/// reversal of alternate rounds). Order seeds are offset from point seeds so that the two random
/// streams differ.
inline core::OrderOptions order_options(const std::string& name, double brio_ratio, std::uint64_t seed) {
    core::OrderOptions options;
    options.kind = core::parse_order_kind(name == "brio-noreverse" ? "brio" : name);
    options.reverse_alternate_rounds = name != "brio-noreverse";
    options.brio_ratio = brio_ratio;
    options.seed = seed + 1000;
    return options;
}

}  // namespace cavity::experiments::detail
