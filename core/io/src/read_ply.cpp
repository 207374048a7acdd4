#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "point_readers.h"
#include "text_input.h"

namespace cavity::core {

namespace {

enum class Format { kAscii, kLittleEndian, kBigEndian };

enum class Type { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

struct Property {
    std::string name;
    Type type = Type::kFloat32;
    std::optional<Type> list_count_type;  ///< set for `property list COUNT ITEM name`
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::size_t line = 0;
    std::vector<Property> properties;
};

struct Header {
    Format format = Format::kAscii;
    std::vector<Element> elements;
    std::size_t data_offset = 0;  ///< first byte after `end_header\n`
    std::size_t data_line = 0;    ///< line number of the first ASCII data line
};

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

bool is_integer(Type type) {
    return type != Type::kFloat32 && type != Type::kFloat64;
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

/// The fewest bytes one instance of `element` takes: binary, its scalars and list lengths; ASCII,
/// a character and a separator per property.
std::uint64_t min_instance_bytes(const Element& element, bool ascii) {
    std::uint64_t bytes = 0;
    for (const Property& property : element.properties) {
        bytes +=
            ascii ? 2
                  : type_size(property.list_count_type ? *property.list_count_type : property.type);
    }
    return bytes;
}

Type checked_type(const TextSource& source, std::string_view name, std::size_t line) {
    const std::optional<Type> type = parse_type(name);
    if (!type) {
        source.fail(line, "unknown PLY property type '" + std::string(name) + "'");
    }
    return *type;
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

/// Positions of the properties read from the vertex element.
struct VertexLayout {
    std::size_t x, y, z;
    std::optional<std::size_t> weight;
};

std::optional<std::size_t> find_property(const Element& element, std::string_view name) {
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
        if (element.properties[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

VertexLayout vertex_layout(const TextSource& source, const Element& vertex, bool weighted) {
    VertexLayout layout{};
    std::size_t* targets[3] = {&layout.x, &layout.y, &layout.z};
    const char* names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        const auto index = find_property(vertex, names[axis]);
        if (!index) {
            source.fail(vertex.line,
                        std::string("the vertex element has no '") + names[axis] + "' property");
        }
        if (vertex.properties[*index].list_count_type) {
            source.fail(vertex.line,
                        std::string("the vertex property '") + names[axis] + "' is a list");
        }
        *targets[axis] = *index;
    }
    if (weighted) {
        layout.weight = find_property(vertex, "weight");
        if (!layout.weight) {
            layout.weight = find_property(vertex, "w");
        }
        if (!layout.weight || vertex.properties[*layout.weight].list_count_type) {
            source.fail(vertex.line, "weighted input needs a 'weight' or 'w' vertex property");
        }
    }
    return layout;
}

/// Reads ASCII data as a stream of whitespace-separated tokens, tracking line numbers.
class AsciiCursor {
public:
    AsciiCursor(std::string_view data, std::size_t line) : data_(data), line_(line) {}

    std::optional<std::string_view> next() {
        while (pos_ < data_.size() && std::strchr(" \t\r\n\v\f", data_[pos_]) != nullptr) {
            if (data_[pos_] == '\n') {
                ++line_;
            }
            ++pos_;
        }
        if (pos_ == data_.size()) {
            return std::nullopt;
        }
        const std::size_t start = pos_;
        while (pos_ < data_.size() && std::strchr(" \t\r\n\v\f", data_[pos_]) == nullptr) {
            ++pos_;
        }
        token_line_ = line_;
        return data_.substr(start, pos_ - start);
    }

    /// The line of the last token read (of the data's first line before any): where a value
    /// was wrong, or where the data stopped short.
    std::size_t line() const { return token_line_; }

private:
    std::string_view data_;
    std::size_t pos_ = 0;
    std::size_t line_;
    std::size_t token_line_ = line_;
};

/// Reads binary data in either byte order, independent of the host's.
class BinaryCursor {
public:
    BinaryCursor(std::string_view data, bool big_endian) : data_(data), big_endian_(big_endian) {}

    bool has(std::size_t bytes) const { return data_.size() - pos_ >= bytes; }

    std::size_t remaining() const { return data_.size() - pos_; }

    void skip(std::size_t bytes) { pos_ += bytes; }

    /// The next value of `type` as a double (exact for every PLY type); the caller checks has().
    double read(Type type) {
        const std::size_t size = type_size(type);
        std::uint64_t bits = 0;
        for (std::size_t i = 0; i < size; ++i) {
            const auto byte =
                static_cast<unsigned char>(data_[pos_ + (big_endian_ ? i : size - 1 - i)]);
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

private:
    std::string_view data_;
    std::size_t pos_ = 0;
    bool big_endian_;
};

std::string vertex_label(std::uint64_t i) {
    return "vertex " + std::to_string(i);
}

class PlyReader {
public:
    PlyReader(const TextSource& source, const Header& header, std::string_view bytes)
        : source_(source)
        , header_(header)
        , data_(bytes.substr(header.data_offset))
        , ascii_(data_, header.data_line)
        , binary_(data_, header.format == Format::kBigEndian) {}

    PointSet read(bool weighted) {
        // Every declared count is checked against the data before anything is read or reserved:
        // a header promising more instances than there are bytes is refused by name (a count
        // nearer the truth fails later, naming the instance where the data ends).
        for (const Element& element : header_.elements) {
            if (!element.properties.empty() && element.count > data_.size() + 1) {
                source_.fail(element.line,
                             "element '" + element.name + "' declares " +
                                 std::to_string(element.count) + " instances, more than the " +
                                 std::to_string(data_.size()) + " bytes of data can hold");
            }
        }
        const Element* vertex = nullptr;
        std::size_t vertex_position = 0;
        for (const Element& element : header_.elements) {
            if (element.name == "vertex") {
                vertex = &element;
                break;
            }
            skip_element(element);
            ++vertex_position;
        }
        if (vertex == nullptr) {
            source_.fail("the PLY file has no vertex element");
        }
        if (vertex->count == 0) {
            source_.fail(vertex->line, "the vertex element is empty: no points");
        }
        if (vertex->count > 0xFFFF'FFFFu) {
            source_.fail(vertex->line, "more points than 32-bit indices can number");
        }
        const VertexLayout layout = vertex_layout(source_, *vertex, weighted);
        PointSet result;
        result.source = source_.file();
        const std::uint64_t least =
            std::max<std::uint64_t>(min_instance_bytes(*vertex, ascii()), 1);
        result.points.reserve(std::min<std::uint64_t>(vertex->count, data_.size() / least + 1));
        for (std::uint64_t i = 0; i < vertex->count; ++i) {
            double values[4] = {0.0, 0.0, 0.0, 0.0};  // x, y, z, weight
            for (std::size_t p = 0; p < vertex->properties.size(); ++p) {
                const int slot = p == layout.x                            ? 0
                                 : p == layout.y                          ? 1
                                 : p == layout.z                          ? 2
                                 : (layout.weight && p == *layout.weight) ? 3
                                                                          : -1;
                if (slot < 0) {
                    skip_property(vertex->properties[p], *vertex, i);
                } else {
                    values[slot] = read_value(vertex->properties[p], i);
                }
            }
            result.points.push_back({values[0], values[1], values[2]});
            if (weighted) {
                result.weights.push_back(values[3]);
            }
        }
        // The rest of the file must be exactly what the header declares: a count that disagrees
        // with the payload is refused, not silently ignored.
        for (std::size_t e = vertex_position + 1; e < header_.elements.size(); ++e) {
            skip_element(header_.elements[e]);
        }
        refuse_trailing_data();
        return result;
    }

private:
    bool ascii() const { return header_.format == Format::kAscii; }

    void refuse_trailing_data() {
        if (ascii()) {
            if (ascii_.next()) {
                source_.fail(ascii_.line(), "data after the elements the header declares");
            }
        } else if (binary_.has(1)) {
            source_.fail(std::to_string(binary_.remaining()) +
                         " bytes of binary data after the elements the header declares");
        }
    }

    [[noreturn]] void fail_truncated(const Element& element, std::uint64_t i) const {
        const std::string what = "file ends in " + element.name + " " + std::to_string(i) +
                                 " of the " + std::to_string(element.count) + " declared";
        if (ascii()) {
            source_.fail(ascii_.line(), what);
        }
        source_.fail(what);
    }

    std::string_view ascii_token(const Element& element, std::uint64_t i) {
        const auto token = ascii_.next();
        if (!token) {
            fail_truncated(element, i);
        }
        return *token;
    }

    void skip_property(const Property& property, const Element& element, std::uint64_t i) {
        std::uint64_t items = 1;
        if (property.list_count_type) {
            if (ascii()) {
                items = source_.count(ascii_token(element, i), ascii_.line(), "list length");
            } else {
                if (!binary_.has(type_size(*property.list_count_type))) {
                    fail_truncated(element, i);
                }
                // An integer type (checked in the header), so the value is an exact integer of
                // at most 32 bits and the conversion is defined.
                const double length = binary_.read(*property.list_count_type);
                if (length < 0) {
                    source_.fail(element.name + " " + std::to_string(i) + ": negative list length");
                }
                items = static_cast<std::uint64_t>(length);
            }
        }
        for (std::uint64_t k = 0; k < items; ++k) {
            if (ascii()) {
                ascii_token(element, i);
            } else {
                if (!binary_.has(type_size(property.type))) {
                    fail_truncated(element, i);
                }
                binary_.skip(type_size(property.type));
            }
        }
    }

    void skip_element(const Element& element) {
        if (element.properties.empty()) {
            return;  // instances of nothing take no bytes
        }
        for (std::uint64_t i = 0; i < element.count; ++i) {
            for (const Property& property : element.properties) {
                skip_property(property, element, i);
            }
        }
    }

    double read_value(const Property& property, std::uint64_t i) {
        const std::string what = vertex_label(i) + " " + property.name;
        if (ascii()) {
            const auto token = ascii_.next();
            if (!token) {
                source_.fail(ascii_.line(), "file ends in " + vertex_label(i));
            }
            if (is_integer(property.type)) {
                // The declared type is a promise about the payload: "2.5" or 1e30 under an int
                // property is refused, not converted.
                const std::int64_t value = source_.integer(*token, ascii_.line(), what);
                const auto [low, high] = integer_range(property.type);
                if (value < low || value > high) {
                    source_.fail(ascii_.line(),
                                 what + ": " + std::to_string(value) +
                                     " is outside the range of its PLY type");
                }
                return static_cast<double>(value);
            }
            return source_.number(*token, ascii_.line(), what);
        }
        if (!binary_.has(type_size(property.type))) {
            source_.fail(vertex_label(i) + ": file ends in the binary vertex data");
        }
        const double value = binary_.read(property.type);
        if (!std::isfinite(value)) {
            source_.fail(what + ": not a finite number");
        }
        return value;
    }

    const TextSource& source_;
    const Header& header_;
    std::string_view data_;
    AsciiCursor ascii_;
    BinaryCursor binary_;
};

}  // namespace

PointSet read_ply(const std::string& file, std::string_view bytes, bool weighted) {
    const TextSource source(file);
    const Header header = parse_header(source, bytes);
    return PlyReader(source, header, bytes).read(weighted);
}

}  // namespace cavity::core
