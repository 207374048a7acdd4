#include "integer_option.h"

#include <charconv>

namespace cavity::cli {

std::optional<std::uint64_t> parse_integer(std::string_view token, std::uint64_t max) {
    // Digits of the mantissa (underscores only between digits), then the exponent, so that the
    // value is exact: "2.5e6" is 25 x 10^5, never a rounded double.
    std::string digits;
    std::size_t i = 0;
    std::int64_t shift = 0;  // power of ten applied to `digits`
    bool seen_point = false;
    for (; i < token.size(); ++i) {
        const char c = token[i];
        if (c >= '0' && c <= '9') {
            digits += c;
            shift -= seen_point ? 1 : 0;
        } else if (c == '_' && i > 0 && i + 1 < token.size() && token[i - 1] >= '0' &&
                   token[i - 1] <= '9' && token[i + 1] >= '0' && token[i + 1] <= '9') {
            continue;
        } else if (c == '.' && !seen_point) {
            seen_point = true;
        } else {
            break;
        }
    }
    if (digits.empty()) {
        return std::nullopt;
    }
    if (i < token.size()) {
        if (token[i] != 'e' && token[i] != 'E') {
            return std::nullopt;
        }
        std::int64_t exponent = 0;
        const char* first = token.data() + i + 1;
        const char* last = token.data() + token.size();
        if (first < last && *first == '+') {
            ++first;
        }
        const auto [end, error] = std::from_chars(first, last, exponent);
        if (error != std::errc() || end != last || exponent > 40 || exponent < -40) {
            return std::nullopt;
        }
        shift += exponent;
    }
    while (shift < 0) {  // the dropped digits must be zeros: an integer, not a fraction
        if (digits.back() != '0') {
            return std::nullopt;
        }
        digits.pop_back();
        ++shift;
        if (digits.empty()) {
            digits = "0";
        }
    }
    digits.append(static_cast<std::size_t>(shift), '0');
    const std::size_t nonzero = digits.find_first_not_of('0');
    digits.erase(0, nonzero == std::string::npos ? digits.size() - 1 : nonzero);
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size() || value > max) {
        return std::nullopt;
    }
    return value;
}

CLI::Validator integer_in(const std::string& name, std::uint64_t min, std::uint64_t max) {
    const std::string range =
        name + " must be between " + std::to_string(min) + " and " + std::to_string(max);
    return CLI::Validator(
        [min, max, range](std::string& token) -> std::string {
            const std::optional<std::uint64_t> value = parse_integer(token, max);
            if (!value || *value < min) {
                return range + " (an integer such as 2000000, 2_000_000 or 2e6), got '" + token +
                       "'";
            }
            token = std::to_string(*value);
            return {};
        },
        "INT in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
}

}  // namespace cavity::cli
