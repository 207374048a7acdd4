#include "cavity/core/base/parse_number.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace cavity::core {

namespace {

// True when a literal denotes zero: no digit other than 0 before any exponent. strtod reports
// ERANGE both for a total underflow and for a subnormal result, so this tells "0e-400" (zero,
// fine) from "1e-400" (a nonzero value that no double can hold).
bool literal_is_zero(std::string_view token) {
    bool hex =
        token.find("0x") != std::string_view::npos || token.find("0X") != std::string_view::npos;
    std::size_t start = hex ? token.find_first_of("xX") + 1 : 0;
    for (std::size_t i = start; i < token.size(); ++i) {
        char c = token[i];
        if ((!hex && (c == 'e' || c == 'E')) || (hex && (c == 'p' || c == 'P'))) {
            break;
        }
        if ((c >= '1' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')))) {
            return false;
        }
    }
    return true;
}

// A decimal integer literal ("-12", "+0034") whose value the double does not hold exactly: beyond
// 2^53 most integers round. A user who writes an integer expects it exact, so such a literal is
// refused; returns the nearest double's digits for the message, or nothing when exact or when
// the token is not a plain integer.
std::optional<std::string> inexact_integer(std::string_view token, double value) {
    std::string_view digits = token;
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
        digits.remove_prefix(1);
    }
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
        return std::nullopt;
    }
    if (std::fabs(value) < 9007199254740992.0) {  // 2^53: below it every integer is exact
        return std::nullopt;
    }
    while (digits.size() > 1 && digits[0] == '0') {
        digits.remove_prefix(1);
    }
    char buffer[400];
    const auto result = std::to_chars(
        buffer, buffer + sizeof buffer, std::fabs(value), std::chars_format::fixed, 0);
    const std::string_view exact(buffer, static_cast<std::size_t>(result.ptr - buffer));
    if (exact == digits) {
        return std::nullopt;
    }
    return std::string(value < 0 ? "-" : "") + std::string(exact);
}

/// The value read from the token, or the refusal of an integer literal it does not hold exactly.
ParsedNumber unless_inexact_integer(std::string_view token, double value) {
    if (const auto nearest = inexact_integer(token, value)) {
        return {std::nullopt,
                "the integer '" + std::string(token) +
                    "' has no exact double (beyond 2^53; the nearest is " + *nearest +
                    "): refused rather than rounded"};
    }
    return {value, {}};
}

}  // namespace

ParsedNumber parse_number(std::string_view token) {
    if (token.empty()) {
        return {std::nullopt, "empty number"};
    }
    // The common case first: a plain decimal that std::from_chars reads whole into a finite
    // double, rounded to nearest as strtod rounds, without copying the token (strtod took about
    // 1300 instructions a number, most of the time of reading a large .node). Everything else
    // (a sign '+', hexadecimal, infinities, NaN, out of range) goes to strtod below, which accepts
    // what it always accepted and words the errors.
    double fast = 0.0;
    const auto [fast_end, fast_error] =
        std::from_chars(token.data(), token.data() + token.size(), fast);
    if (fast_error == std::errc{} && fast_end == token.data() + token.size() &&
        std::isfinite(fast)) {
        return unless_inexact_integer(token, fast);
    }
    const std::string text(token);  // strtod needs a terminated string
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (end != begin + text.size() || end == begin) {
        return {std::nullopt, "not a number: '" + text + "'"};
    }
    if (std::isnan(value)) {
        return {std::nullopt, "NaN is not allowed: '" + text + "'"};
    }
    if (std::isinf(value)) {
        const bool literal_inf = text.find_first_of("iI") != std::string::npos;
        return {std::nullopt,
                literal_inf ? "infinity is not allowed: '" + text + "'"
                            : "out of the range of a double: '" + text + "'"};
    }
    if (errno == ERANGE && value == 0.0 && !literal_is_zero(token)) {
        return {std::nullopt, "underflows to zero, out of the range of a double: '" + text + "'"};
    }
    return unless_inexact_integer(token, value);
}

}  // namespace cavity::core
