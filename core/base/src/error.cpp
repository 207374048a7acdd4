#include "cavity/core/base/error.h"

namespace cavity::core {

std::string located_message(const std::string& file,
                            std::optional<std::size_t> line,
                            const std::string& what) {
    if (file.empty()) {
        return what;
    }
    std::string message = file;
    if (line && *line != 0) {
        message += ':';
        message += std::to_string(*line);
    }
    message += ": ";
    message += what;
    return message;
}

}  // namespace cavity::core
