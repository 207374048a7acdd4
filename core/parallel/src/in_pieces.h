#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace cavity::core {

/// Runs body(k, begin, end) on the `threads` consecutive pieces k of [0, count) at once, piece 0
/// on the calling thread; rethrows the first exception a piece threw.
template <class Body>
void in_pieces(std::size_t count, unsigned threads, Body&& body) {
    std::vector<std::exception_ptr> errors(threads);
    const auto piece = [&](unsigned k) {
        try {
            body(k, count * k / threads, count * (k + 1) / threads);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> helpers;
        for (unsigned k = 1; k < threads; ++k) {
            helpers.emplace_back(piece, k);
        }
        piece(0);
    }
    for (const std::exception_ptr& e : errors) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
}

}  // namespace cavity::core
