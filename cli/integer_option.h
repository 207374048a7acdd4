#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace cavity::cli {

/// The exact non-negative integer a command-line token denotes, in the forms the field writes
/// counts: 2000000, 2_000_000, 2e6, 2.5e6; nothing when it denotes a fraction, a negative number,
/// something that is not a number, or a value above `max`.
std::optional<std::uint64_t> parse_integer(std::string_view token, std::uint64_t max);

/// A CLI11 transform for an integer option or positional: rewrites the accepted forms to plain
/// digits before CLI11 converts them, and refuses anything else with "NAME must be between MIN
/// and MAX" (CLI11 alone wraps -1 to 2^64-1 and refuses 2e6).
CLI::Validator integer_in(const std::string& name, std::uint64_t min, std::uint64_t max);

}  // namespace cavity::cli
