#pragma once
// A progress bar on a terminal (stderr), shown only once an operation has taken longer than
// a second, and never when stderr is not a terminal (pipes, CI logs, files).

#include <chrono>
#include <cstdio>
#include <string>

namespace legofeup::cli {

class ProgressBar {
  public:
    explicit ProgressBar(std::string label, std::FILE* stream = stderr);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// `fraction` in [0, 1]; `detail` is shown after the bar (e.g. "93 / 190 s").
    void update(double fraction, const std::string& detail);
    /// Clears the bar's line (if it was drawn).
    void finish();

  private:
    std::string label_;
    std::FILE* stream_;
    bool terminal_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point started_;
    std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace legofeup::cli
