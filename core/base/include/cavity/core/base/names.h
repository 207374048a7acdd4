#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cavity/core/base/error.h"

namespace cavity::core {

/// One row of a variant's name table: the name users type (CLI, Python, suite files), the value,
/// and a line for help texts. One table per kind of variant (orders, locators, storages,
/// bootstrap rules) drives parsing, the CLI's choices and help, and the tests that run every
/// variant, so a new variant is one row.
template <class Kind>
struct NamedKind {
    std::string_view name;
    Kind kind;
    std::string_view help;
};

/// The value named `name`. \throws Error "unknown WHAT 'NAME' (expected a, b or c)".
template <class Kind, std::size_t N>
Kind parse_kind(const std::array<NamedKind<Kind>, N>& table,
                std::string_view name,
                std::string_view what) {
    for (const auto& row : table) {
        if (row.name == name) {
            return row.kind;
        }
    }
    std::string expected;
    for (std::size_t i = 0; i < N; ++i) {
        expected += i == 0 ? "" : i + 1 == N ? " or " : ", ";
        expected += table[i].name;
    }
    throw Error("unknown " + std::string(what) + " '" + std::string(name) + "' (expected " +
                expected + ")");
}

/// The name of `kind` in `table` ("?" for a value with no row, which a test rules out).
template <class Kind, std::size_t N>
std::string_view name_of(const std::array<NamedKind<Kind>, N>& table, Kind kind) {
    for (const auto& row : table) {
        if (row.kind == kind) {
            return row.name;
        }
    }
    return "?";
}

/// Every name, in the table's order.
template <class Kind, std::size_t N>
std::vector<std::string> names_of(const std::array<NamedKind<Kind>, N>& table) {
    std::vector<std::string> names;
    names.reserve(N);
    for (const auto& row : table) {
        names.emplace_back(row.name);
    }
    return names;
}

/// "name: help; name: help", for --help texts.
template <class Kind, std::size_t N>
std::string help_of(const std::array<NamedKind<Kind>, N>& table) {
    std::string text;
    for (std::size_t i = 0; i < N; ++i) {
        text +=
            (i == 0 ? "" : "; ") + std::string(table[i].name) + ": " + std::string(table[i].help);
    }
    return text;
}

}  // namespace cavity::core
