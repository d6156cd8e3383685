#pragma once
// The built-in frame-time counter: each view reports how long each of its repaints took, and
// the debug overlay (View ▸ Frame times) shows the statistics of the recent ones. 60 fps
// means every frame within 16.7 ms.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <string>

namespace legofeup::ui {

class FrameStats {
  public:
    static constexpr std::size_t kWindow = 600;  ///< the last 600 frames (10 s at 60 fps)

    void record(std::chrono::nanoseconds duration) {
        durations_ms_[next_] = std::chrono::duration<double, std::milli>(duration).count();
        next_ = (next_ + 1) % kWindow;
        count_ = std::min(count_ + 1, kWindow);
        ++total_;
    }

    struct Summary {
        std::size_t frames = 0;  ///< frames in the window
        double mean_ms = 0.0;
        double p99_ms = 0.0;
        double max_ms = 0.0;
        std::size_t total = 0;  ///< frames since the start
    };

    Summary summary() const {
        Summary summary;
        summary.frames = count_;
        summary.total = total_;
        if (count_ == 0) {
            return summary;
        }
        std::array<double, kWindow> sorted{};
        std::copy_n(durations_ms_.begin(), count_, sorted.begin());
        std::sort(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(count_));
        double sum = 0.0;
        for (std::size_t i = 0; i < count_; ++i) {
            sum += sorted[i];
        }
        summary.mean_ms = sum / static_cast<double>(count_);
        summary.p99_ms = sorted[std::min(count_ - 1, (count_ * 99) / 100)];
        summary.max_ms = sorted[count_ - 1];
        return summary;
    }

  private:
    std::array<double, kWindow> durations_ms_{};
    std::size_t next_ = 0;
    std::size_t count_ = 0;
    std::size_t total_ = 0;
};

/// Times one repaint: records its duration into `stats` when it goes out of scope.
class FrameTimer {
  public:
    explicit FrameTimer(FrameStats& stats)
        : stats_(stats), started_(std::chrono::steady_clock::now()) {}
    ~FrameTimer() { stats_.record(std::chrono::steady_clock::now() - started_); }
    FrameTimer(const FrameTimer&) = delete;
    FrameTimer& operator=(const FrameTimer&) = delete;

  private:
    FrameStats& stats_;
    std::chrono::steady_clock::time_point started_;
};

}  // namespace legofeup::ui
