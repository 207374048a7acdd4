#include "progress_bar.h"

#include <cstdio>
#include <utility>

#include <unistd.h>

namespace cavity::cli {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label))
    , enabled_(enabled && isatty(STDERR_FILENO) == 1)
    , start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    finish();
}

void ProgressBar::finish() {
    if (drawn_) {
        std::fputs("\r\033[K", stderr);  // leave the terminal line clean
        std::fflush(stderr);
        drawn_ = false;
    }
}

ProgressStage::ProgressStage(const std::string& label, bool enabled)
    : shown_(enabled && isatty(STDERR_FILENO) == 1) {
    if (shown_) {
        std::fprintf(stderr, "\r\033[K%s ...", label.c_str());
        std::fflush(stderr);
    }
}

ProgressStage::~ProgressStage() {
    if (shown_) {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
    }
}

void ProgressBar::update(std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) {
        return;
    }
    constexpr int kWidth = 30;
    const auto now = std::chrono::steady_clock::now();
    // Redrawn at most ten times a second, however often the caller reports.
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100) && done < total) {
        return;
    }
    last_draw_ = now;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar(static_cast<std::size_t>(filled), '=');
    bar.resize(kWidth, ' ');
    std::fprintf(stderr,
                 "\r%s [%s] %3d%%  %.1f s, ETA %.1f s",
                 label_.c_str(),
                 bar.c_str(),
                 static_cast<int>(fraction * 100.0),
                 elapsed,
                 eta);
    std::fflush(stderr);
    drawn_ = true;
}

}  // namespace cavity::cli
