#include "cavity/core/base/assert.h"

#include <algorithm>

#include "cavity/core/base/error.h"

namespace cavity::core::detail {

void assertion_failed(const char* condition, const std::string& what, const char* file, int line) {
    throw InternalError("internal error: " + std::string(file) + ":" + std::to_string(line) + ": " +
                        what + " (" + condition + ")");
}

void require_no_problems(const std::vector<std::string>& problems,
                         const std::string& what,
                         const char* file,
                         int line) {
    if (problems.empty()) {
        return;
    }
    std::string message = "internal error: " + std::string(file) + ":" + std::to_string(line) +
                          ": " + what + ": " + std::to_string(problems.size()) + " problem(s)";
    for (std::size_t i = 0; i < std::min<std::size_t>(problems.size(), 10); ++i) {
        message += "\n  " + problems[i];
    }
    throw InternalError(message);
}

}  // namespace cavity::core::detail
