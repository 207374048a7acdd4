#include "ply_format.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

namespace cavity::core::ply {

namespace {

std::optional<Type> parse_type(std::string_view name) {
    if (name == "char" || name == "int8")
        return Type::kInt8;
    if (name == "uchar" || name == "uint8")
        return Type::kUInt8;
    if (name == "short" || name == "int16")
        return Type::kInt16;
    if (name == "ushort" || name == "uint16")
        return Type::kUInt16;
    if (name == "int" || name == "int32")
        return Type::kInt32;
    if (name == "uint" || name == "uint32")
        return Type::kUInt32;
    if (name == "float" || name == "float32")
        return Type::kFloat32;
    if (name == "double" || name == "float64")
        return Type::kFloat64;
    return std::nullopt;
}

std::size_t type_size(Type type) {
    switch (type) {
        case Type::kInt8:
        case Type::kUInt8:
            return 1;
        case Type::kInt16:
        case Type::kUInt16:
            return 2;
        case Type::kInt32:
        case Type::kUInt32:
        case Type::kFloat32:
            return 4;
        case Type::kFloat64:
            return 8;
    }
    return 0;
}

/// The range of an integer PLY type, for ASCII values that must fit it.
std::pair<std::int64_t, std::int64_t> integer_range(Type type) {
    switch (type) {
        case Type::kInt8:
            return {-128, 127};
        case Type::kUInt8:
            return {0, 255};
        case Type::kInt16:
            return {-32768, 32767};
        case Type::kUInt16:
            return {0, 65535};
        case Type::kInt32:
            return {-2147483648LL, 2147483647};
        default:
            return {0, 4294967295LL};
    }
}

Type checked_type(const TextSource& source, std::string_view name, std::size_t line) {
    const std::optional<Type> type = parse_type(name);
    if (!type) {
        source.fail(line, "unknown PLY property type '" + std::string(name) + "'");
    }
    return *type;
}

/// ASCII PLY separators (strchr also matches the terminating NUL, so a NUL byte separates too).
bool is_space(char c) {
    return std::strchr(" \t\r\n\v\f", c) != nullptr;
}

}  // namespace

bool is_integer(Type type) {
    return type != Type::kFloat32 && type != Type::kFloat64;
}

std::uint64_t min_instance_bytes(const Element& element, bool ascii) {
    std::uint64_t bytes = 0;
    for (const Property& property : element.properties) {
        bytes +=
            ascii ? 2
                  : type_size(property.list_count_type ? *property.list_count_type : property.type);
    }
    return bytes;
}

std::optional<std::size_t> find_property(const Element& element, std::string_view name) {
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
        if (element.properties[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

Header parse_header(const TextSource& source, std::string_view bytes) {
    Header header;
    std::size_t offset = 0;
    std::size_t line = 0;
    bool have_format = false;
    if (bytes.empty()) {
        source.fail("empty file");
    }
    for (;;) {
        const std::size_t end = bytes.find('\n', offset);
        if (end == std::string_view::npos) {
            source.fail(line + 1, "PLY header has no end_header");
        }
        std::string_view text = bytes.substr(offset, end - offset);
        offset = end + 1;
        ++line;
        if (!text.empty() && text.back() == '\r') {
            text.remove_suffix(1);
        }
        const auto words = split_whitespace(text);
        if (line == 1) {
            if (words.size() != 1 || words[0] != "ply") {
                source.fail(line, "not a PLY file: the first line must be 'ply'");
            }
            continue;
        }
        if (words.empty() || words[0] == "comment" || words[0] == "obj_info") {
            continue;
        }
        if (words[0] == "end_header") {
            break;
        }
        if (words[0] == "format") {
            if (words.size() != 3) {
                source.fail(line, "expected 'format <kind> 1.0'");
            }
            if (words[1] == "ascii") {
                header.format = Format::kAscii;
            } else if (words[1] == "binary_little_endian") {
                header.format = Format::kLittleEndian;
            } else if (words[1] == "binary_big_endian") {
                header.format = Format::kBigEndian;
            } else {
                source.fail(line, "unknown PLY format '" + std::string(words[1]) + "'");
            }
            have_format = true;
        } else if (words[0] == "element") {
            if (words.size() != 3) {
                source.fail(line, "expected 'element <name> <count>'");
            }
            header.elements.push_back(
                {std::string(words[1]), source.count(words[2], line, "element count"), line, {}});
        } else if (words[0] == "property") {
            if (header.elements.empty()) {
                source.fail(line, "property before any element");
            }
            Property property;
            if (words.size() == 5 && words[1] == "list") {
                property.list_count_type = checked_type(source, words[2], line);
                if (!is_integer(*property.list_count_type)) {
                    source.fail(line,
                                "a PLY list length must have an integer type, not '" +
                                    std::string(words[2]) + "'");
                }
                property.type = checked_type(source, words[3], line);
                property.name = std::string(words[4]);
            } else if (words.size() == 3) {
                property.type = checked_type(source, words[1], line);
                property.name = std::string(words[2]);
            } else {
                source.fail(line, "expected 'property <type> <name>' or 'property list ...'");
            }
            header.elements.back().properties.push_back(std::move(property));
        } else {
            source.fail(line, "unknown PLY header keyword '" + std::string(words[0]) + "'");
        }
    }
    if (!have_format) {
        source.fail(line, "PLY header has no format line");
    }
    header.data_offset = offset;
    header.data_line = line + 1;
    return header;
}

Cursor::Cursor(const TextSource& source, const Header& header, std::string_view bytes)
    : source_(source)
    , header_(header)
    , data_(bytes.substr(header.data_offset))
    , line_(header.data_line)
    , token_line_(header.data_line) {}

void Cursor::check_counts() const {
    for (const Element& element : header_.elements) {
        if (!element.properties.empty() && element.count > data_.size() + 1) {
            source_.fail(element.line,
                         "element '" + element.name + "' declares " +
                             std::to_string(element.count) + " instances, more than the " +
                             std::to_string(data_.size()) + " bytes of data can hold");
        }
    }
}

void Cursor::fail(const std::string& what) const {
    if (ascii()) {
        source_.fail(token_line_, what);
    }
    source_.fail(what + " (byte " + std::to_string(header_.data_offset + value_start_) + ")");
}

void Cursor::fail_truncated(const Element& element, std::uint64_t i) const {
    fail("file ends in " + element.name + " " + std::to_string(i) + " of the " +
         std::to_string(element.count) + " declared");
}

std::string_view Cursor::ascii_token(const Element& element, std::uint64_t i) {
    while (pos_ < data_.size() && is_space(data_[pos_])) {
        if (data_[pos_] == '\n') {
            ++line_;
        }
        ++pos_;
    }
    if (pos_ == data_.size()) {
        fail_truncated(element, i);
    }
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !is_space(data_[pos_])) {
        ++pos_;
    }
    token_line_ = line_;
    return data_.substr(start, pos_ - start);
}

double Cursor::binary_read(Type type) {
    // Either byte order, independent of the host's.
    const std::size_t size = type_size(type);
    const bool big_endian = header_.format == Format::kBigEndian;
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < size; ++k) {
        const auto byte = static_cast<unsigned char>(data_[pos_ + (big_endian ? k : size - 1 - k)]);
        bits = (bits << 8) | byte;
    }
    pos_ += size;
    switch (type) {
        case Type::kInt8:
            return static_cast<std::int8_t>(bits);
        case Type::kUInt8:
            return static_cast<std::uint8_t>(bits);
        case Type::kInt16:
            return static_cast<std::int16_t>(bits);
        case Type::kUInt16:
            return static_cast<std::uint16_t>(bits);
        case Type::kInt32:
            return static_cast<std::int32_t>(bits);
        case Type::kUInt32:
            return static_cast<std::uint32_t>(bits);
        case Type::kFloat32:
            return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
        case Type::kFloat64:
            return std::bit_cast<double>(bits);
    }
    return 0.0;
}

double Cursor::value(Type type, const std::string& what, const Element& element, std::uint64_t i) {
    if (ascii()) {
        const std::string_view token = ascii_token(element, i);
        if (is_integer(type)) {
            // The declared type is a promise about the payload: "2.5" or 1e30 under an int
            // property is refused, not converted.
            const std::int64_t v = source_.integer(token, token_line_, what);
            const auto [low, high] = integer_range(type);
            if (v < low || v > high) {
                fail(what + ": " + std::to_string(v) + " is outside the range of its PLY type");
            }
            return static_cast<double>(v);
        }
        return source_.number(token, token_line_, what);
    }
    value_start_ = pos_;
    if (!binary_has(type_size(type))) {
        fail_truncated(element, i);
    }
    const double v = binary_read(type);
    if (!std::isfinite(v)) {
        fail(what + ": not a finite number");
    }
    return v;
}

double Cursor::scalar(const Property& property, const Element& element, std::uint64_t i) {
    return value(
        property.type, element.name + " " + std::to_string(i) + " " + property.name, element, i);
}

std::uint64_t Cursor::list_length(const Property& property,
                                  const Element& element,
                                  std::uint64_t i) {
    const std::string what = element.name + " " + std::to_string(i) + " list length";
    const double length = value(*property.list_count_type, what, element, i);
    // An integer type (checked in the header), so the value is an exact integer of at most 32
    // bits and the conversion is defined.
    if (length < 0) {
        fail(element.name + " " + std::to_string(i) + ": negative list length");
    }
    return static_cast<std::uint64_t>(length);
}

void Cursor::skip_property(const Property& property, const Element& element, std::uint64_t i) {
    const std::uint64_t items = property.list_count_type ? list_length(property, element, i) : 1;
    for (std::uint64_t k = 0; k < items; ++k) {
        if (ascii()) {
            ascii_token(element, i);
        } else {
            value_start_ = pos_;
            if (!binary_has(type_size(property.type))) {
                fail_truncated(element, i);
            }
            pos_ += type_size(property.type);
        }
    }
}

void Cursor::skip_element(const Element& element) {
    if (element.properties.empty()) {
        return;  // instances of nothing take no bytes
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {
        for (const Property& property : element.properties) {
            skip_property(property, element, i);
        }
    }
}

void Cursor::refuse_trailing_data() {
    if (ascii()) {
        while (pos_ < data_.size() && is_space(data_[pos_])) {
            if (data_[pos_] == '\n') {
                ++line_;
            }
            ++pos_;
        }
        if (pos_ < data_.size()) {
            source_.fail(line_, "data after the elements the header declares");
        }
    } else if (binary_has(1)) {
        source_.fail(std::to_string(data_.size() - pos_) +
                     " bytes of binary data after the elements the header declares");
    }
}

}  // namespace cavity::core::ply
