#include "cavity/core/parse_number.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace cavity::core {

namespace {

// True when a literal denotes zero: no digit other than 0 before any exponent. strtod reports
// ERANGE both for a total underflow and for a subnormal result, so this tells "0e-400" (zero,
// fine) from "1e-400" (a nonzero value that no double can hold).
bool literal_is_zero(std::string_view token) {
    bool hex = token.find("0x") != std::string_view::npos || token.find("0X") != std::string_view::npos;
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

}  // namespace

ParsedNumber parse_number(std::string_view token) {
    if (token.empty()) {
        return {std::nullopt, "empty number"};
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
        return {std::nullopt, literal_inf ? "infinity is not allowed: '" + text + "'"
                                          : "out of the range of a double: '" + text + "'"};
    }
    if (errno == ERANGE && value == 0.0 && !literal_is_zero(token)) {
        return {std::nullopt, "underflows to zero, out of the range of a double: '" + text + "'"};
    }
    return {value, {}};
}

}  // namespace cavity::core
