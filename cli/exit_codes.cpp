#include "exit_codes.h"

namespace cavity::cli {

std::string usage_message(const std::string& what) {
    const std::size_t colon = what.find(": ");
    if (colon != std::string::npos && colon > 0) {
        const std::string name = what.substr(0, colon);
        std::string rest = what.substr(colon + 2);
        if (rest.compare(0, name.size() + 1, name + " ") == 0) {
            return rest;
        }
    }
    return what;
}

}  // namespace cavity::cli
