#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace legofeup::cli {
namespace {

constexpr auto kShowAfter = std::chrono::seconds(1);
constexpr auto kRedrawEvery = std::chrono::milliseconds(100);
constexpr int kBarWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::string label, std::FILE* stream)
    : label_(std::move(label)),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      started_(std::chrono::steady_clock::now()),
      last_draw_(started_) {}

ProgressBar::~ProgressBar() {
    finish();
}

void ProgressBar::update(double fraction, const std::string& detail) {
    const auto now = std::chrono::steady_clock::now();
    if (!terminal_ || now - started_ < kShowAfter || (drawn_ && now - last_draw_ < kRedrawEvery)) {
        return;
    }
    const double clamped = std::clamp(fraction, 0.0, 1.0);
    const int filled = static_cast<int>(std::lround(clamped * kBarWidth));
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kBarWidth, '.');
    std::fprintf(stream_, "\r%s [%s] %3.0f%% %s\033[K", label_.c_str(), bar.c_str(),
                 clamped * 100.0, detail.c_str());
    std::fflush(stream_);
    drawn_ = true;
    last_draw_ = now;
}

void ProgressBar::finish() {
    if (drawn_) {
        std::fprintf(stream_, "\r\033[K");
        std::fflush(stream_);
        drawn_ = false;
    }
}

}  // namespace legofeup::cli
