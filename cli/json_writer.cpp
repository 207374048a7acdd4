#include "json_writer.h"

#include <cmath>
#include <cstdio>

namespace cavity::cli {

namespace {

std::string quoted(std::string_view s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            q += '\\';
            q += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
            q += buf;
        } else {
            q += c;
        }
    }
    return q + "\"";
}

}  // namespace

void JsonWriter::prefix(std::string_view key) {
    if (!first_) {
        out_ += ",";
    }
    if (depth_ > 0) {
        out_ += "\n" + std::string(static_cast<std::size_t>(2 * depth_), ' ');
    }
    if (!key.empty()) {
        out_ += quoted(key) + ": ";
    }
    first_ = false;
}

void JsonWriter::begin_object(std::string_view key) {
    prefix(key);
    out_ += "{";
    ++depth_;
    first_ = true;
}

void JsonWriter::end_object() {
    --depth_;
    out_ += "\n" + std::string(static_cast<std::size_t>(2 * depth_), ' ') + "}";
    first_ = false;
    if (depth_ == 0) {
        out_ += "\n";
    }
}

void JsonWriter::begin_array(std::string_view key) {
    prefix(key);
    out_ += "[";
    ++depth_;
    first_ = true;
}

void JsonWriter::end_array() {
    --depth_;
    out_ += "]";
    first_ = false;
}

void JsonWriter::number(std::string_view key, double value) {
    prefix(key);
    if (!std::isfinite(value)) {
        out_ += "null";
        return;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    out_ += buf;
}

void JsonWriter::integer(std::string_view key, std::uint64_t value) {
    prefix(key);
    out_ += std::to_string(value);
}

void JsonWriter::string(std::string_view key, std::string_view value) {
    prefix(key);
    out_ += quoted(value);
}

void JsonWriter::boolean(std::string_view key, bool value) {
    prefix(key);
    out_ += value ? "true" : "false";
}

void JsonWriter::element(std::uint64_t value) {
    if (!first_) {
        out_ += ",";
    }
    out_ += std::to_string(value);
    first_ = false;
}

}  // namespace cavity::cli
