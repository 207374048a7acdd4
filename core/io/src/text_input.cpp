#include "text_input.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>

#include "cavity/core/base/error.h"
#include "cavity/core/base/parse_number.h"

namespace cavity::core {

namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && is_space(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

}  // namespace

std::string read_file_bytes(const std::filesystem::path& file) {
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) {
        throw Error(located_message(file.string(), std::nullopt, "is a directory, not a file"));
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw Error(located_message(
            file.string(), std::nullopt, std::string("cannot open: ") + std::strerror(errno)));
    }
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        throw Error(located_message(file.string(), std::nullopt, "cannot read"));
    }
    return bytes;
}

bool LineReader::next() {
    while (!rest_.empty()) {
        const std::size_t end = rest_.find('\n');
        std::string_view line = rest_.substr(0, end);
        rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
        ++number_;
        line = trim(line.substr(0, line.find('#')));
        if (!line.empty()) {
            text_ = line;
            return true;
        }
    }
    return false;
}

std::vector<std::string_view> split_whitespace(std::string_view line) {
    std::vector<std::string_view> fields;
    split_whitespace(line, fields);
    return fields;
}

void split_whitespace(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !is_space(line[i])) {
            ++i;
        }
        if (i > start) {
            fields.push_back(line.substr(start, i - start));
        }
    }
}

std::vector<std::string_view> split_fields(std::string_view line) {
    if (line.find(',') == std::string_view::npos) {
        return split_whitespace(line);
    }
    std::vector<std::string_view> fields;
    for (;;) {
        const std::size_t comma = line.find(',');
        fields.push_back(trim(line.substr(0, comma)));
        if (comma == std::string_view::npos) {
            return fields;
        }
        line.remove_prefix(comma + 1);
    }
}

void TextSource::fail(std::size_t line, const std::string& what) const {
    throw Error(located_message(file_, line, what));
}

void TextSource::fail(const std::string& what) const {
    throw Error(located_message(file_, std::nullopt, what));
}

double TextSource::number(std::string_view token, std::size_t line, std::string_view what) const {
    const ParsedNumber parsed = parse_number(token);
    if (!parsed.value) {
        fail(line, std::string(what) + ": " + parsed.error);
    }
    return *parsed.value;
}

std::uint64_t TextSource::count(std::string_view token,
                                std::size_t line,
                                std::string_view what) const {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
        fail(line,
             std::string(what) + ": not a non-negative integer: '" + std::string(token) + "'");
    }
    return value;
}

std::uint64_t TextSource::count_at_most(std::string_view token,
                                        std::size_t line,
                                        std::string_view what,
                                        std::uint64_t limit,
                                        std::string_view why) const {
    const std::uint64_t value = count(token, line, what);
    if (value > limit) {
        fail(line,
             std::string(what) + " " + std::to_string(value) + " is more than " + std::string(why) +
                 " (" + std::to_string(limit) + ")");
    }
    return value;
}

std::int64_t TextSource::integer(std::string_view token,
                                 std::size_t line,
                                 std::string_view what) const {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
        fail(line, std::string(what) + ": not a 64-bit integer: '" + std::string(token) + "'");
    }
    return value;
}

}  // namespace cavity::core
