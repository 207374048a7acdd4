#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace cavity::cli {

/// A one-line progress bar with elapsed time and an ETA, drawn on stderr only when stderr is a
/// terminal and the user did not ask for quiet output.
class ProgressBar {
public:
    ProgressBar(std::string label, bool enabled);
    ~ProgressBar();

    void update(std::size_t done, std::size_t total);

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace cavity::cli
