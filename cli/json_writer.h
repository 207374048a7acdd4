#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace cavity::cli {

/// A minimal streaming JSON writer for the --stats files: objects, arrays, numbers and strings,
/// with commas placed automatically. Doubles are written with 17 significant digits.
class JsonWriter {
public:
    void begin_object(std::string_view key = {});
    void end_object();
    void begin_array(std::string_view key = {});
    void end_array();
    void number(std::string_view key, double value);
    void integer(std::string_view key, std::uint64_t value);
    void string(std::string_view key, std::string_view value);
    void boolean(std::string_view key, bool value);
    void element(std::uint64_t value);

    const std::string& text() const { return out_; }

private:
    void prefix(std::string_view key);

    std::string out_;
    bool first_ = true;
    int depth_ = 0;
};

}  // namespace cavity::cli
