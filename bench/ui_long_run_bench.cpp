// The GUI's memory and frame times over a long run, as the window lives through it: a run
// of the wall lesson (experiment f) or of the laser lesson (step a, the office) driven in
// lockstep for --minutes of simulated time, its samples taken in batches of
// --samples-per-frame (the session's one batch per 16 ms frame: 1 at real time, about 3 at
// 10×) into a RunHistory, the plots panel (1200×800, shown offscreen, --tab, --window s of
// history, 0 = the whole run) and the arena view (1200×900, fitted), the queued replots run
// and the arena painted after every batch. Each minute of run time it prints the process's
// resident memory (/proc/self/statm: the simulator, the loop and every view included, as in
// the application), the history's own bytes (RunHistory::bytes(): records, whole samples,
// trace rows) and the frame times of that minute; at the end, the frame times of the
// last 600 frames (the built-in counter's window) and the worst minute's p99. Frame times
// are the GUI thread's CPU time (CLOCK_THREAD_CPUTIME_ID): on a shared machine the wall
// clock also counts the time other processes had the core.
//
//   legofeup_ui_long_run_bench --lesson walls|laser [--minutes 30] [--samples-per-frame 2]
//                              [--tab N] [--window S]
//
// One run per process: memory freed by one run would otherwise count for the next.

#include <unistd.h>
#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QTabWidget>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/run_history.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace {

using namespace legofeup;

struct Options {
    std::string lesson = "walls";
    double minutes = 30.0;
    std::size_t samples_per_frame = 2;
    int tab = -1;  ///< -1: the lesson's own (Estimate for walls, Laser scan matching for laser)
    double window = 0.0;
};

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string_view name = argv[i];
        const char* value = argv[i + 1];
        if (name == "--lesson") {
            options.lesson = value;
        } else if (name == "--minutes") {
            options.minutes = std::atof(value);
        } else if (name == "--samples-per-frame") {
            options.samples_per_frame = std::max<std::size_t>(1, std::strtoul(value, nullptr, 10));
        } else if (name == "--tab") {
            options.tab = std::atoi(value);
        } else if (name == "--window") {
            options.window = std::atof(value);
        } else {
            std::fprintf(stderr, "unknown option %s\n", argv[i]);
            std::exit(2);
        }
    }
    if (options.lesson != "walls" && options.lesson != "laser") {
        std::fprintf(stderr, "--lesson is walls or laser\n");
        std::exit(2);
    }
    return options;
}

/// Resident memory of this process, MB.
double resident_mb() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0;
    long resident = 0;
    statm >> pages >> resident;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

/// mean / p99 / max of some frame times, ms.
struct Times {
    double mean = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};
Times times_of(std::vector<double> ms) {
    Times times;
    if (ms.empty()) {
        return times;
    }
    std::sort(ms.begin(), ms.end());
    double sum = 0.0;
    for (const double t : ms) {
        sum += t;
    }
    times.mean = sum / static_cast<double>(ms.size());
    times.p99 = ms[std::min(ms.size() - 1, ms.size() * 99 / 100)];
    times.max = ms.back();
    return times;
}

/// CPU time of this thread, ms.
double thread_cpu_ms() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

lessons::RunConfig config_of(const Options& options) {
    if (options.lesson == "laser") {
        return lessons::find_built_in_lesson("laser")->steps.front().config;
    }
    return lessons::find_experiment("f")->config;
}

/// Takes the run's steps into the views as the session and the window do, one batch a frame.
class Window final : public lessons::RunObserver {
  public:
    Window(const lessons::ResolvedRun& run, const Options& options)
        : options_(options), plots_(history_), arena_(history_) {
        history_.restart(ui::scene_of(run));
        plots_.historyRestarted();
        arena_.historyRestarted();
        plots_.resize(1200, 800);
        const int tab = options.tab >= 0 ? options.tab : (options.lesson == "laser" ? 5 : 0);
        plots_.setWantedTab(tab);
        plots_.setTimeWindow(options.window);
        plots_.show();
        arena_.resize(1200, 900);
        arena_.fitArena();
        QCoreApplication::processEvents();
        std::printf("%s run, %.0f min, %zu samples a frame, plots tab %d, window %g s\n",
                    options.lesson.c_str(), options.minutes, options.samples_per_frame, tab,
                    options.window);
        std::printf("%6s %8s %12s %13s %25s %22s %22s\n", "minute", "steps", "resident MB",
                    "whole samples", "history MB rec/smp/trace", "plots ms mean/p99/max",
                    "arena ms mean/p99/max");
    }

    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        batch_.push_back(ui::make_run_sample(snapshot, truth));
        if (batch_.size() >= options_.samples_per_frame) {
            frame();
        }
        if (snapshot.time >= next_minute_ * 60.0) {
            report_minute();
        }
    }

    void finish() {
        if (!batch_.empty()) {
            frame();
        }
        const auto tail = [](const std::vector<double>& all) {
            const std::size_t from = all.size() > 600 ? all.size() - 600 : 0;
            return times_of({all.begin() + static_cast<std::ptrdiff_t>(from), all.end()});
        };
        const Times plots = tail(plot_ms_);
        const Times arena = tail(arena_ms_);
        const Times plots_run = times_of(plot_ms_);
        std::printf(
            "\n%s run of %.1f min: %zu steps, resident %.1f MB (peak of the minutes "
            "%.1f MB), %zu whole samples kept\n",
            options_.lesson.c_str(),
            history_.empty() ? 0.0 : history_.latest().snapshot.time / 60.0, history_.size(),
            resident_mb(), peak_mb_, history_.samples_kept());
        std::printf(
            "last 600 frames: plots %.1f / %.1f / %.1f ms, arena %.1f / %.1f / %.1f ms "
            "(mean / p99 / max)\n",
            plots.mean, plots.p99, plots.max, arena.mean, arena.p99, arena.max);
        std::printf("whole run: plots p99 %.1f ms, max %.1f ms; worst minute's plots p99 %.1f ms\n",
                    plots_run.p99, plots_run.max, worst_minute_p99_);
    }

  private:
    void frame() {
        const auto first = static_cast<int>(history_.size());
        const auto count = static_cast<int>(batch_.size());
        history_.append(std::move(batch_));
        batch_.clear();
        plots_.samplesAppended(first, count);
        arena_.samplesAppended(first, count);
        const double replots = thread_cpu_ms();
        QCoreApplication::processEvents();  // the queued replots of the visible plots
        plot_ms_.push_back(thread_cpu_ms() - replots);
        const double paint = thread_cpu_ms();
        {
            QPainter painter(&image_);
            arena_.render(&painter);
        }
        arena_ms_.push_back(thread_cpu_ms() - paint);
    }

    void report_minute() {
        const auto minute = [](const std::vector<double>& all, std::size_t from) {
            return times_of({all.begin() + static_cast<std::ptrdiff_t>(from), all.end()});
        };
        const Times plots = minute(plot_ms_, minute_start_);
        const Times arena = minute(arena_ms_, minute_start_);
        const double resident = resident_mb();
        peak_mb_ = std::max(peak_mb_, resident);
        worst_minute_p99_ = std::max(worst_minute_p99_, plots.p99);
        const ui::RunHistory::Bytes bytes = history_.bytes();
        std::printf(
            "%6d %8zu %12.1f %13zu %11.1f/%4.1f/%4.1f/%4.1f %8.1f/%5.1f/%6.1f %8.1f/%5.1f/%6.1f\n",
            next_minute_, history_.size(), resident, history_.samples_kept(),
            static_cast<double>(bytes.total()) / 1e6, static_cast<double>(bytes.records) / 1e6,
            static_cast<double>(bytes.samples) / 1e6, static_cast<double>(bytes.trace) / 1e6,
            plots.mean, plots.p99, plots.max, arena.mean, arena.p99, arena.max);
        std::fflush(stdout);
        minute_start_ = plot_ms_.size();
        ++next_minute_;
    }

    Options options_;
    ui::RunHistory history_;
    ui::PlotsPanel plots_;
    ui::ArenaView arena_;
    QImage image_{1200, 900, QImage::Format_ARGB32_Premultiplied};
    std::vector<ui::RunSample> batch_;
    std::vector<double> plot_ms_;
    std::vector<double> arena_ms_;
    std::size_t minute_start_ = 0;
    int next_minute_ = 1;
    double peak_mb_ = 0.0;
    double worst_minute_p99_ = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const Options options = parse(argc, argv);
    lessons::RunConfig config = config_of(options);
    config.laps = 1000;  // the time limit ends the run
    lessons::ResolvedRun run = lessons::resolve(config);
    run.max_duration = options.minutes * 60.0;
    Window window(run, options);
    lessons::run_lockstep(run, &window);
    window.finish();
    return 0;
}
