// parse_number against the C library's strtod, the reference it was written on: the same double,
// bit for bit, for every decimal it accepts, and the same refusals. Its fast path (from_chars)
// and its strtod path must not be told apart.

#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "cavity/core/base/parse_number.h"

namespace cavity::core {
namespace {

/// strtod's value when it reads the whole token to a finite double and is not an underflow.
std::optional<double> reference(const std::string& token) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(token.c_str(), &end);
    if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

std::string random_decimal(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> digit(0, 9);
    std::uniform_int_distribution<int> count(1, 25);
    std::string s;
    if (rng() % 3 == 0) {
        s += '-';
    }
    for (int i = count(rng); i > 0; --i) {
        s += static_cast<char>('0' + digit(rng));
    }
    if (rng() % 2 == 0) {
        s += '.';
        for (int i = count(rng); i > 0; --i) {
            s += static_cast<char>('0' + digit(rng));
        }
    }
    if (rng() % 2 == 0) {
        s += rng() % 2 == 0 ? 'e' : 'E';
        s += std::to_string(std::uniform_int_distribution<int>(-340, 310)(rng));
    }
    return s;
}

TEST(ParseNumber, DecimalsReadAsStrtodReadsThem) {
    std::mt19937_64 rng(2026);
    for (int i = 0; i < 200000; ++i) {
        const std::string token = random_decimal(rng);
        const ParsedNumber parsed = parse_number(token);
        const std::optional<double> expected = reference(token);
        if (parsed.value) {
            ASSERT_TRUE(expected) << token;
            ASSERT_EQ(std::bit_cast<std::uint64_t>(*parsed.value),
                      std::bit_cast<std::uint64_t>(*expected))
                << token;
        } else {
            // Refused: out of range, an underflow to zero, or an integer beyond 2^53.
            ASSERT_FALSE(parsed.error.empty()) << token;
        }
    }
}

TEST(ParseNumber, ShortestRoundTripsOfRandomDoubles) {
    // What the writers write (to_chars' shortest form) reads back to the same double.
    std::mt19937_64 rng(7);
    for (int i = 0; i < 200000; ++i) {
        double v = std::bit_cast<double>(rng());
        if (!std::isfinite(v)) {
            continue;
        }
        char buffer[32];
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
        const ParsedNumber parsed = parse_number(std::string_view(buffer, end - buffer));
        ASSERT_TRUE(parsed.value) << std::string_view(buffer, end - buffer);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(*parsed.value), std::bit_cast<std::uint64_t>(v));
    }
}

TEST(ParseNumber, EveryFormStrtodAcceptsAndEveryRefusal) {
    const auto value = [](std::string_view t) { return parse_number(t).value; };
    EXPECT_EQ(value("+1.5"), 1.5);
    EXPECT_EQ(value("0x1.8p1"), 3.0);
    EXPECT_EQ(value("-0X10"), -16.0);
    EXPECT_EQ(value("1."), 1.0);
    EXPECT_EQ(value(".5"), 0.5);
    EXPECT_EQ(value("4.9e-324"), std::ldexp(1.0, -1074));
    EXPECT_EQ(value("0e-400"), 0.0);
    EXPECT_TRUE(std::signbit(*value("-0")));
    EXPECT_EQ(value("9007199254740992"), 9007199254740992.0);
    for (const char* bad : {"",
                            "1e400",
                            "-1e400",
                            "1e-400",
                            "inf",
                            "-Infinity",
                            "nan",
                            "NaN(1)",
                            "1e",
                            "--1",
                            "1,5",
                            "0x",
                            "9007199254740993",
                            "+18446744073709551617"}) {
        const ParsedNumber parsed = parse_number(bad);
        EXPECT_FALSE(parsed.value) << bad;
        EXPECT_FALSE(parsed.error.empty()) << bad;
    }
    EXPECT_NE(parse_number("9007199254740993").error.find("no exact double"), std::string::npos);
    EXPECT_NE(parse_number("1e-400").error.find("underflows"), std::string::npos);
    EXPECT_NE(parse_number("inf").error.find("infinity"), std::string::npos);
}

}  // namespace
}  // namespace cavity::core
