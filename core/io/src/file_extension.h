#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace cavity::core {

/// A file's extension in lower case ("" when it has none): the readers choose the format by it,
/// whatever its case.
inline std::string lower_extension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) {
        return static_cast<char>(std::tolower(c));
    });
    return extension;
}

}  // namespace cavity::core
