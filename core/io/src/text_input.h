#pragma once

// Helpers shared by the text readers (.node, .ele, .xyz, ASCII PLY): whole-file reading, line
// splitting with '#' comments, and number parsing that reports FILE:LINE.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cavity::core {

/// The bytes of `file`. \throws Error naming the file when it is missing or unreadable.
std::string read_file_bytes(const std::filesystem::path& file);

/// The non-blank lines of a text, with '#' comments and a trailing '\r' removed, each with its
/// 1-based line number.
class LineReader {
public:
    explicit LineReader(std::string_view text) : rest_(text) {}

    /// Moves to the next line holding data; false at the end of the text.
    bool next();

    std::string_view text() const { return text_; }

    std::size_t number() const { return number_; }

private:
    std::string_view rest_;
    std::string_view text_;
    std::size_t number_ = 0;
};

/// Whitespace-separated fields.
std::vector<std::string_view> split_whitespace(std::string_view line);

/// The same into `fields`, replacing its contents: a reader's loop over lines reuses one vector.
void split_whitespace(std::string_view line, std::vector<std::string_view>& fields);

/// Fields separated by commas when the line has one (each trimmed, none may be empty; an empty
/// field comes back as ""), else by whitespace.
std::vector<std::string_view> split_fields(std::string_view line);

/// Reports errors of one file as "FILE:LINE: what".
class TextSource {
public:
    explicit TextSource(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    [[noreturn]] void fail(std::size_t line, const std::string& what) const;
    /// An error about the file as a whole (an empty file has no line to name).
    [[noreturn]] void fail(const std::string& what) const;

    /// A finite double (decimal or hex-float); `what` names the field in the message.
    double number(std::string_view token, std::size_t line, std::string_view what) const;
    /// A non-negative decimal integer.
    std::uint64_t count(std::string_view token, std::size_t line, std::string_view what) const;
    /// A count from a header, refused when above `limit` (what the file can possibly hold, or
    /// what 32-bit indices can number) before any arithmetic or allocation uses it.
    std::uint64_t count_at_most(std::string_view token,
                                std::size_t line,
                                std::string_view what,
                                std::uint64_t limit,
                                std::string_view why) const;
    /// A decimal integer of either sign that fits 64 bits (a boundary marker).
    std::int64_t integer(std::string_view token, std::size_t line, std::string_view what) const;

private:
    std::string file_;
};

}  // namespace cavity::core
