// `cavity sign`: evaluates predicate queries read one per line and prints their exact signs.

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "cavity/core/base/error.h"
#include "cavity/core/base/parse_number.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"
#include "commands.h"

namespace cavity::cli {

namespace {

namespace pred = cavity::predicates;

enum class Predicate { kOrient3d, kInsphere, kOrient4d };

struct SignOptions {
    std::string file;  ///< empty: read standard input
    bool show_stage = false;
    bool use_oracle = false;
};

struct QueryKind {
    std::string_view name;
    Predicate predicate;
    std::size_t arity;  ///< numbers on the line
};

constexpr std::array<QueryKind, 3> kQueryKinds{{{"orient3d", Predicate::kOrient3d, 12},
                                                {"insphere", Predicate::kInsphere, 15},
                                                {"orient4d", Predicate::kOrient4d, 20}}};

constexpr std::size_t kMaxArity = 20;

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Splits off the next whitespace-separated token of `rest`; empty when none is left.
std::string_view next_token(std::string_view& rest) {
    std::size_t begin = 0;
    while (begin < rest.size() && is_space(rest[begin])) {
        ++begin;
    }
    std::size_t end = begin;
    while (end < rest.size() && !is_space(rest[end])) {
        ++end;
    }
    const std::string_view token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return token;
}

// std::from_chars rounds correctly, like the strtod behind parse_number, and allocates nothing,
// so it settles the common cases (a plain decimal or hex-float giving a normal double) on its
// own; it takes neither a sign before "0x" nor the prefix, so both are split off here. Every
// other token (zeros, subnormals, NaN, infinities, overflow, a stray second sign, junk) goes to
// parse_number, which has the last word on what is accepted and words the error.
std::optional<double> parse_coordinate(std::string_view token, std::string& error) {
    std::string_view body = token;
    const bool negative = !body.empty() && body.front() == '-';
    if (negative) {
        body.remove_prefix(1);
    }
    auto format = std::chars_format::general;
    if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
        body.remove_prefix(2);
        format = std::chars_format::hex;
    }
    if (!body.empty() && body.front() != '-' && body.front() != '+') {
        double value = 0.0;
        const char* last = body.data() + body.size();
        const auto [end, ec] = std::from_chars(body.data(), last, value, format);
        if (ec == std::errc() && end == last && std::isnormal(value)) {
            return negative ? -value : value;
        }
    }
    core::ParsedNumber parsed = core::parse_number(token);
    if (!parsed.value) {
        error = std::move(parsed.error);
    }
    return parsed.value;
}

// Reads lines of any length into one reused buffer; the file is closed on destruction.
class LineReader {
public:
    explicit LineReader(const std::string& file) : name_(file.empty() ? "<stdin>" : file) {
        if (file.empty()) {
            stream_ = stdin;
        } else {
            stream_ = std::fopen(file.c_str(), "rb");
            if (stream_ == nullptr) {
                throw core::Error(core::located_message(
                    name_, std::nullopt, std::string("cannot open: ") + std::strerror(errno)));
            }
        }
    }

    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    ~LineReader() {
        std::free(buffer_);
        if (stream_ != stdin) {
            std::fclose(stream_);
        }
    }

    /// The next line without its terminator, or false at the end of the input.
    bool next(std::string_view& line) {
        const ssize_t length = ::getline(&buffer_, &capacity_, stream_);
        if (length < 0) {
            if (std::ferror(stream_)) {
                throw core::Error(core::located_message(name_, number_ + 1, "read error"));
            }
            return false;
        }
        ++number_;
        line = std::string_view(buffer_, static_cast<std::size_t>(length));
        return true;
    }

    const std::string& name() const { return name_; }

    std::size_t line_number() const { return number_; }

private:
    std::string name_;
    std::FILE* stream_ = nullptr;
    char* buffer_ = nullptr;
    std::size_t capacity_ = 0;
    std::size_t number_ = 0;
};

// Collects output lines and writes them in large blocks.
class OutputBuffer {
public:
    OutputBuffer() { text_.reserve(kBlock + 64); }

    OutputBuffer(const OutputBuffer&) = delete;
    OutputBuffer& operator=(const OutputBuffer&) = delete;

    ~OutputBuffer() { flush(); }

    void append(std::string_view s) {
        text_ += s;
        if (text_.size() >= kBlock) {
            flush();
        }
    }

    void flush() {
        if (!text_.empty()) {
            std::fwrite(text_.data(), 1, text_.size(), stdout);
            text_.clear();
        }
        std::fflush(stdout);
    }

private:
    static constexpr std::size_t kBlock = std::size_t{1} << 16;
    std::string text_;
};

std::string_view sign_text(pred::Sign s) {
    switch (s) {
        case pred::Sign::kNeg:
            return "-1";
        case pred::Sign::kZero:
            return "0";
        case pred::Sign::kPos:
            return "1";
    }
    return "?";
}

pred::Point3 point(const double* v) {
    return {v[0], v[1], v[2]};
}

pred::WeightedPoint3 weighted_point(const double* v) {
    return {v[0], v[1], v[2], v[3]};
}

pred::Verdict evaluate_staged(Predicate predicate, const double* v) {
    switch (predicate) {
        case Predicate::kOrient3d:
            return pred::orient3d_staged(point(v), point(v + 3), point(v + 6), point(v + 9));
        case Predicate::kInsphere:
            return pred::insphere_staged(
                point(v), point(v + 3), point(v + 6), point(v + 9), point(v + 12));
        case Predicate::kOrient4d:
            return pred::orient4d_staged(weighted_point(v),
                                         weighted_point(v + 4),
                                         weighted_point(v + 8),
                                         weighted_point(v + 12),
                                         weighted_point(v + 16));
    }
    return {pred::Sign::kZero, pred::Stage::kExact};  // unreachable: every Predicate is covered
}

pred::Sign evaluate_oracle(Predicate predicate, const double* v) {
    switch (predicate) {
        case Predicate::kOrient3d:
            return pred::oracle::orient3d(point(v), point(v + 3), point(v + 6), point(v + 9));
        case Predicate::kInsphere:
            return pred::oracle::insphere(
                point(v), point(v + 3), point(v + 6), point(v + 9), point(v + 12));
        case Predicate::kOrient4d:
            return pred::oracle::orient4d(weighted_point(v),
                                          weighted_point(v + 4),
                                          weighted_point(v + 8),
                                          weighted_point(v + 12),
                                          weighted_point(v + 16));
    }
    return pred::Sign::kZero;  // unreachable: the switch covers every Predicate
}

[[noreturn]] void reject_line(OutputBuffer& out,
                              const LineReader& reader,
                              const std::string& what) {
    out.flush();  // the results of the lines before this one, as --help promises
    throw core::Error(core::located_message(reader.name(), reader.line_number(), what));
}

void run_sign(const SignOptions& options) {
    LineReader reader(options.file);
    OutputBuffer out;
    std::array<double, kMaxArity> values{};
    std::string error;
    std::string_view line;
    while (reader.next(line)) {
        std::string_view rest = line;
        const std::string_view name = next_token(rest);
        if (name.empty() || name.front() == '#') {
            continue;
        }
        const QueryKind* kind = nullptr;
        for (const QueryKind& k : kQueryKinds) {
            if (k.name == name) {
                kind = &k;
            }
        }
        if (kind == nullptr) {
            reject_line(out,
                        reader,
                        "unknown predicate '" + std::string(name) +
                            "' (expected orient3d, insphere or orient4d)");
        }
        const std::size_t arity = kind->arity;
        std::size_t count = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
            if (count == arity) {
                std::size_t total = count + 1;
                while (!next_token(rest).empty()) {
                    ++total;
                }
                reject_line(out,
                            reader,
                            std::string(name) + " expects " + std::to_string(arity) +
                                " numbers, got " + std::to_string(total));
            }
            const std::optional<double> value = parse_coordinate(token, error);
            if (!value) {
                reject_line(
                    out,
                    reader,
                    std::string(name) + " number " + std::to_string(count + 1) + ": " + error);
            }
            values[count++] = *value;
        }
        if (count != arity) {
            reject_line(out,
                        reader,
                        std::string(name) + " expects " + std::to_string(arity) + " numbers, got " +
                            std::to_string(count));
        }
        if (options.use_oracle) {
            out.append(sign_text(evaluate_oracle(kind->predicate, values.data())));
        } else {
            const pred::Verdict verdict = evaluate_staged(kind->predicate, values.data());
            out.append(sign_text(verdict.sign));
            if (options.show_stage) {
                out.append(" ");
                out.append(pred::stage_name(verdict.stage));
            }
        }
        out.append("\n");
    }
}

}  // namespace

void add_sign_command(CLI::App& app) {
    auto options = std::make_shared<SignOptions>();
    CLI::App* sign = app.add_subcommand("sign", "Print the exact sign of predicate queries");
    sign->add_option("file", options->file, "Query file (default: standard input)");
    CLI::Option* stage =
        sign->add_flag("--stage", options->show_stage, "Also print the stage that decided");
    sign->add_flag("--oracle", options->use_oracle, "Use the independent exact oracle (slow)")
        ->excludes(stage);
    sign->footer(
        "Input: one query per line, the predicate name then its numbers (decimal or C99 "
        "hex-float, e.g. 0x1.8p+3):\n"
        "  orient3d  ax ay az  bx by bz  cx cy cz  dx dy dz      sign det[a-d; b-d; c-d]\n"
        "  insphere  a b c d e (15 numbers)                      sign det[p-e, |p-e|^2]\n"
        "  orient4d  ax ay az aw ... ex ey ez ew (20 numbers)    power test, lifts |p|^2-w\n"
        "Blank lines and lines starting with # are skipped.\n"
        "Output: one line per query, the sign (-1, 0 or 1), then with --stage the deciding\n"
        "stage (filter, adaptive or exact), e.g. '1 filter'.\n"
        "Errors: the first malformed line (unknown predicate, wrong count, a number that is not\n"
        "a finite double) stops the run with FILE:LINE: message on stderr and exit status 1;\n"
        "the results of the lines before it have been printed, none for it or after it.\n");
    sign->callback([options] { run_sign(*options); });
}

}  // namespace cavity::cli
