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

    /// Erases the bar, so that whatever is printed next starts on a clean line; the destructor
    /// does the same when finish() was not called.
    void finish();

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

/// A stage without a measurable fraction (reading, checking, writing): its name on stderr while
/// it runs, on a terminal only, erased when the stage ends (normally or by an exception).
class ProgressStage {
public:
    ProgressStage(const std::string& label, bool enabled);
    ~ProgressStage();
    ProgressStage(const ProgressStage&) = delete;
    ProgressStage& operator=(const ProgressStage&) = delete;

private:
    bool shown_;
};

}  // namespace cavity::cli
