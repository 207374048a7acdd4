#pragma once

#include <thread>
#include <vector>

namespace cavity::core {

/// Runs body(k) for k in [0, count) on `count` threads, k = 0 on the calling thread, and returns
/// when all have finished (std::jthread joins). For work split into parts by index, whose result
/// must not depend on the thread count.
template <class Body>
void on_threads(unsigned count, const Body& body) {
    std::vector<std::jthread> helpers;
    helpers.reserve(count);
    for (unsigned k = 1; k < count; ++k) {
        helpers.emplace_back(body, k);
    }
    body(0);
}

}  // namespace cavity::core
