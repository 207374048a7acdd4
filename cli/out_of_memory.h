#pragma once

#include <new>
#include <string>
#include <utility>

#include "cavity/core/base/error.h"

namespace cavity::cli {

/// Runs `step`; an allocation failure inside it becomes a SystemError (exit status 3) that names
/// the operation, its input and the size it tried, e.g. "out of memory triangulating cube.node
/// (10000000 points, about 2.7 GiB)", instead of a bare std::bad_alloc.
template <class Step>
decltype(auto) naming_memory(const std::string& operation, Step&& step) {
    try {
        return std::forward<Step>(step)();
    } catch (const std::bad_alloc&) {
        throw core::SystemError("out of memory " + operation);
    }
}

/// "about 2.7 GiB": a size in the unit that keeps it readable.
std::string about_bytes(double bytes);

}  // namespace cavity::cli
