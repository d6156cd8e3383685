// Arena view frame times at 1200×900 with a long history: a whole paint (fitted, and
// following the robot zoomed in), and one new sample taken in and painted.
//
// And the particle filter's cloud: the paint of the last step's 1,000 dots (the GUI's
// thinning of a 10,000-particle cloud, kParticlesShown) against the same frame without them.
//
// The argument is the number of laps of experiment f. A lap takes 84 s (≈1,680 samples at
// 20 Hz): 9 laps ≈ 15,300 samples, 22 laps ≈ 37,500 samples ≈ a 30-minute run.

#include <benchmark/benchmark.h>

#include <QImage>
#include <QPainter>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "legofeup/core/particle_cloud.hpp"

#include "legofeup/ui/arena/arena_view.hpp"
#include "support/lockstep_history.hpp"

namespace {

using legofeup::ui::ArenaView;
using legofeup::ui::RunHistory;
using legofeup::ui::RunSample;

using legofeup::ui::testing::LockstepRun;

const LockstepRun& run_of(int laps) {
    static std::map<int, LockstepRun> runs;
    auto found = runs.find(laps);
    if (found == runs.end()) {
        found = runs.emplace(laps, legofeup::ui::testing::lockstep_run("f", laps)).first;
    }
    return found->second;
}

const RunHistory& history_of(int laps) {
    static std::map<int, RunHistory> histories;
    auto found = histories.find(laps);
    if (found == histories.end()) {
        found = histories.emplace(laps, legofeup::ui::testing::history_of(run_of(laps))).first;
    }
    return found->second;
}

void paint(ArenaView& view, QImage& image) {
    QPainter painter(&image);
    view.render(&painter);
}

/// One paint of the whole view, fitted to the arena.
void BM_ArenaPaint(benchmark::State& state) {
    const RunHistory& history = history_of(static_cast<int>(state.range(0)));
    ArenaView view(history);
    view.resize(1200, 900);
    view.fitArena();
    QImage image(1200, 900, QImage::Format_ARGB32_Premultiplied);
    paint(view, image);  // the first paint simplifies the paths for this zoom
    for (auto _ : state) {
        paint(view, image);
        benchmark::DoNotOptimize(image.constBits());
    }
    state.counters["samples"] = static_cast<double>(history.size());
}
BENCHMARK(BM_ArenaPaint)->Arg(9)->Arg(22)->Unit(benchmark::kMillisecond);

/// The same while following the robot, zoomed in twice (only the centre moves between
/// frames, so the simplified paths are reused).
void BM_ArenaPaintFollowing(benchmark::State& state) {
    const RunHistory& history = history_of(static_cast<int>(state.range(0)));
    ArenaView view(history);
    view.resize(1200, 900);
    view.setFollowRobot(true);
    view.zoomIn();
    view.zoomIn();
    QImage image(1200, 900, QImage::Format_ARGB32_Premultiplied);
    paint(view, image);
    for (auto _ : state) {
        paint(view, image);
        benchmark::DoNotOptimize(image.constBits());
    }
}
BENCHMARK(BM_ArenaPaintFollowing)->Arg(9)->Arg(22)->Unit(benchmark::kMillisecond);

/// A run at 20 Hz: one sample arrives, the view takes it in and paints.
void BM_ArenaAppendOneSampleAndPaint(benchmark::State& state) {
    const LockstepRun& full = run_of(static_cast<int>(state.range(0)));
    const std::vector<RunSample>& all = full.samples;
    const std::size_t start = all.size() - 1000;  // the last 1,000 samples arrive one by one
    RunHistory history;
    const auto reset = [&] {
        history.restart(full.scene);
        history.append(std::vector<RunSample>(all.begin(), all.begin() + std::ptrdiff_t(start)));
    };
    reset();
    ArenaView view(history);
    view.resize(1200, 900);
    view.fitArena();
    QImage image(1200, 900, QImage::Format_ARGB32_Premultiplied);
    paint(view, image);
    std::size_t next = start;
    for (auto _ : state) {
        if (next == all.size()) {
            state.PauseTiming();
            reset();
            view.historyRestarted();
            paint(view, image);
            next = start;
            state.ResumeTiming();
        }
        history.append(std::vector<RunSample>{all[next]});
        view.samplesAppended(static_cast<int>(next), 1);
        ++next;
        paint(view, image);
        benchmark::DoNotOptimize(image.constBits());
    }
}
BENCHMARK(BM_ArenaAppendOneSampleAndPaint)->Arg(9)->Arg(22)->Unit(benchmark::kMillisecond);

/// One lap of experiment f as if a particle filter of 10,000 particles had run it: every
/// sample carries the thinned cloud, three clusters about the estimate with random weights.
RunHistory particle_history() {
    constexpr int kParticles = 10000;
    std::vector<RunSample> samples = run_of(1).samples;
    std::mt19937_64 random(7);
    std::normal_distribution<double> spread(0.0, 0.15);
    std::uniform_real_distribution<double> weight(0.0, 1.0);
    std::vector<double> xs(kParticles), ys(kParticles), thetas(kParticles), weights(kParticles);
    RunHistory history;
    history.restart(run_of(1).scene);
    for (RunSample& sample : samples) {
        const legofeup::StateVector& x = sample.snapshot.estimate;
        for (std::size_t i = 0; i < xs.size(); ++i) {
            const double cluster = static_cast<double>(i % 3) - 1.0;  // −1, 0, 1: 0.5 m apart
            xs[i] = x(legofeup::kX) + 0.5 * cluster + spread(random);
            ys[i] = x(legofeup::kY) + spread(random);
            thetas[i] = x(legofeup::kTheta) + spread(random);
            weights[i] = weight(random);
        }
        auto cloud = std::make_shared<std::vector<legofeup::ParticlePoint>>();
        legofeup::thin_particles(xs, ys, thetas, weights, legofeup::kParticlesShown, *cloud);
        sample.particles = std::move(cloud);
        sample.snapshot.particles.count = kParticles;
        sample.snapshot.particles.effective = 0.75 * kParticles;
    }
    history.append(std::move(samples));
    return history;
}

/// One paint of the fitted view at the end of that lap: range(0) = 1 with the cloud, 0 the
/// same history with the cloud taken away (the difference is the cloud's cost).
void BM_ArenaPaintParticleCloud(benchmark::State& state) {
    static const RunHistory with_cloud = particle_history();
    static const RunHistory without_cloud = [] {
        RunHistory history;
        history.restart(with_cloud.scene());
        std::vector<RunSample> samples = run_of(1).samples;
        history.append(std::move(samples));
        return history;
    }();
    const RunHistory& history = state.range(0) == 1 ? with_cloud : without_cloud;
    ArenaView view(history);
    view.resize(1200, 900);
    view.fitArena();
    QImage image(1200, 900, QImage::Format_ARGB32_Premultiplied);
    paint(view, image);
    for (auto _ : state) {
        paint(view, image);
        benchmark::DoNotOptimize(image.constBits());
    }
}
BENCHMARK(BM_ArenaPaintParticleCloud)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
