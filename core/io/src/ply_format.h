#pragma once

// The PLY format shared by the point reader (read_ply.cpp) and the surface reader
// (read_ply_surface.cpp): the header, and a cursor over the data in any of the three encodings.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text_input.h"

namespace cavity::core::ply {

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

bool is_integer(Type type);

/// The fewest bytes one instance of `element` takes: binary, its scalars and list lengths; ASCII,
/// a character and a separator per property.
std::uint64_t min_instance_bytes(const Element& element, bool ascii);

/// The position of the property called `name` in `element`.
std::optional<std::size_t> find_property(const Element& element, std::string_view name);

/// The header of a PLY file. \throws Error naming the file and line of a malformed header.
Header parse_header(const TextSource& source, std::string_view bytes);

/// Reads the data after the header, value by value, in the header's encoding. Errors name the file
/// and line (ASCII) or the element instance and byte offset (binary).
class Cursor {
public:
    Cursor(const TextSource& source, const Header& header, std::string_view bytes);

    bool ascii() const { return header_.format == Format::kAscii; }

    /// Refuses a header whose element counts the data cannot possibly hold, before anything is
    /// read or reserved (a count nearer the truth fails later, naming the instance where the data
    /// ends).
    void check_counts() const;

    /// The size of the data, for reservations bounded by what the file can hold.
    std::size_t data_size() const { return data_.size(); }

    /// One scalar of instance `i` of `element` (or one item of a list property, after its length),
    /// as a double (exact for every PLY type); an ASCII integer must fit its declared type, and
    /// every value must be finite.
    double scalar(const Property& property, const Element& element, std::uint64_t i);
    /// The length of a list property of instance `i`.
    std::uint64_t list_length(const Property& property, const Element& element, std::uint64_t i);

    void skip_property(const Property& property, const Element& element, std::uint64_t i);
    void skip_element(const Element& element);

    /// The rest of the file must be exactly what the header declares: a count that disagrees with
    /// the payload is refused, not silently ignored.
    void refuse_trailing_data();

    /// The line of the last ASCII token read (0 in binary data): where a face was read.
    std::size_t line() const { return ascii() ? token_line_ : 0; }

    /// Fails naming where the cursor is: the line of the last ASCII token, or the byte offset in
    /// the file of the last binary value read (or found missing).
    [[noreturn]] void fail(const std::string& what) const;

private:
    std::string_view ascii_token(const Element& element, std::uint64_t i);

    bool binary_has(std::size_t bytes) const { return data_.size() - pos_ >= bytes; }

    double binary_read(Type type);
    double value(Type type, const std::string& what, const Element& element, std::uint64_t i);
    [[noreturn]] void fail_truncated(const Element& element, std::uint64_t i) const;

    const TextSource& source_;
    const Header& header_;
    std::string_view data_;
    std::size_t pos_ = 0;          ///< next byte of data_ (both encodings)
    std::size_t value_start_ = 0;  ///< binary: where the last value read (or missing) starts
    std::size_t line_ = 0;         ///< ASCII: the line at pos_
    std::size_t token_line_ = 0;   ///< ASCII: the line of the last token read
};

}  // namespace cavity::core::ply
