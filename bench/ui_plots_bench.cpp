// Plots panel frame times with a 30-minute history (experiment f for 22 laps of ~84 s:
// ≈37,000 samples at 20 Hz) in a 1200×800 panel shown offscreen: one new sample taken in
// and the visible tab's plots replotted, for a 30 s window and for the whole run; and the
// initial load of the whole history.

#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QTabWidget>
#include <cstddef>
#include <vector>

#include "legofeup/ui/plots/plots_panel.hpp"
#include "support/lockstep_history.hpp"

namespace {

using legofeup::ui::PlotsPanel;
using legofeup::ui::RunHistory;
using legofeup::ui::RunSample;

const legofeup::ui::testing::LockstepRun& thirty_minutes() {
    static const auto run = legofeup::ui::testing::lockstep_run("f", 22);
    return run;
}

/// The first `count` samples of the 30-minute run, as a history of their own.
void fill(RunHistory& history, std::size_t count) {
    const auto& run = thirty_minutes();
    history.restart(run.scene);
    history.append(std::vector<RunSample>(run.samples.begin(),
                                          run.samples.begin() + static_cast<long>(count)));
}

/// One frame: a new sample appended to a panel that holds ≈36,000, then the queued replots
/// of the visible tab's plots (and the widget paint) run. Arguments: tab, window (s; 0 =
/// whole run).
void BM_PlotPanelFrame(benchmark::State& state) {
    const auto tab = static_cast<int>(state.range(0));
    const auto window = static_cast<double>(state.range(1));
    const std::vector<RunSample>& samples = thirty_minutes().samples;
    const std::size_t start = samples.size() - 1000;

    RunHistory history;
    fill(history, start);
    PlotsPanel panel(history);
    panel.resize(1200, 800);
    panel.findChild<QTabWidget*>()->setCurrentIndex(tab);
    panel.setTimeWindow(window);
    panel.show();
    QCoreApplication::processEvents();

    std::size_t next = start;
    for (auto _ : state) {
        if (next == samples.size()) {
            state.PauseTiming();
            fill(history, start);
            panel.historyRestarted();
            panel.samplesAppended(0, static_cast<int>(start));
            QCoreApplication::processEvents();
            next = start;
            state.ResumeTiming();
        }
        history.append({samples[next]});
        panel.samplesAppended(static_cast<int>(next), 1);
        QCoreApplication::processEvents();
        ++next;
    }
    const auto frames = panel.frameStats().summary();
    state.counters["samples"] = static_cast<double>(next);
    state.counters["replot_mean_ms"] = frames.mean_ms;
    state.counters["replot_p99_ms"] = frames.p99_ms;
}
BENCHMARK(BM_PlotPanelFrame)
    ->ArgNames({"tab", "window_s"})
    ->ArgsProduct({{0, 1, 2}, {30, 0}})
    ->Unit(benchmark::kMillisecond);

/// Taking a whole 30-minute history in at once (opening a recorded run), without drawing.
void BM_PlotPanelBulkLoad(benchmark::State& state) {
    static const RunHistory history = legofeup::ui::testing::history_of(thirty_minutes());
    for (auto _ : state) {
        PlotsPanel panel(history);  // the constructor takes in every step
        benchmark::DoNotOptimize(&panel);
    }
    state.counters["samples"] = static_cast<double>(history.size());
}
BENCHMARK(BM_PlotPanelBulkLoad)->Unit(benchmark::kMillisecond);

}  // namespace
