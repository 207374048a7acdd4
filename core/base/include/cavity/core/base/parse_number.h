#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cavity::core {

/// Parses one finite double written in decimal or C99 hex-float form ("0x1.8p+3"), rounding
/// decimals to the nearest double. The whole token must be consumed. Subnormal results are
/// accepted; NaN, infinities, values that overflow, nonzero literals that underflow to zero, and
/// integer literals beyond 2^53 that no double holds exactly (they would be silently rounded) are
/// rejected. Returns the value, or an error message describing the token.
struct ParsedNumber {
    std::optional<double> value;
    std::string error;  ///< set when value is empty
};

ParsedNumber parse_number(std::string_view token);

}  // namespace cavity::core
