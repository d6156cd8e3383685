// The settings table, first part: the run itself (seed, laps, duration, world) and [filter],
// the EKF's noise model (paper: Q over [ε_d, ε_Δθ], R over [ε_ds1, ε_ds2]).

#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/world_file.hpp"
#include "setting_builders.hpp"

namespace legofeup::lessons {

using namespace setting_builders;

void add_run_and_filter_settings(std::vector<Setting>& s) {
    constexpr auto kRun = SettingPage::Run;
    constexpr auto kFilter = SettingPage::Filter;
    constexpr auto kLive = SettingApplies::Live;
    constexpr auto kNextStart = SettingApplies::NextStart;

    Setting seed =
        described({.key = "seed",
                   .field = "seed",
                   .label = in_words("seed"),
                   .help = tr_noop("seed of every random stream of the run (0 … 2^63−1)"),
                   .page = kRun,
                   .applies = kNextStart,
                   .use = kEveryRun},
                  SettingType::Integer);
    seed.get = [](const RunConfig& c) -> SettingValue { return static_cast<std::int64_t>(c.seed); };
    seed.set = [](RunConfig& c, const SettingValue& v) {
        c.seed = static_cast<std::uint64_t>(std::get<std::int64_t>(v));
    };
    s.push_back(seed);
    s.push_back(whole(
        {.key = "laps",
         .field = "laps",
         .label = in_words("laps"),
         .help = tr_noop("laps of the square path (1 … 1000)"),
         .page = kRun,
         .applies = kNextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.laps; }));
    s.push_back(real(
        {.key = "duration",
         .field = "duration",
         .label = in_words("duration"),
         .help = tr_noop("simulated seconds to run (a square or rectangle stops at its "
                         "laps or here, whichever comes first); 0: 200 s per lap"),
         .page = kRun,
         .applies = kNextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.duration; }));
    s.push_back(file({.key = "world",
                      .field = "world",
                      .label = in_words("world"),
                      .help = tr_noop("a built-in world (standard_arena, office) or a world file "
                                      "(relative to this file); empty: the standard arena"),
                      .page = kRun,
                      .applies = kNextStart,
                      .use = kEveryRun},
                     &RunConfig::world_file, built_in_world_names));

    s.push_back(real(
        {.key = "filter.q11",
         .field = "filter.q11",
         .label = paper_symbol("Q11"),
         .help = tr_noop("variance of ε_d per 50 ms period, m²"),
         .page = kFilter,
         .applies = kLive,
         .use = kOdometryQLessons},
        [](auto& c) -> auto& { return c.filter.q11; }));
    s.push_back(real(
        {.key = "filter.q22",
         .field = "filter.q22",
         .label = paper_symbol("Q22"),
         .help = tr_noop("variance of ε_Δθ per period, rad²"),
         .page = kFilter,
         .applies = kLive,
         .use = kOdometryQLessons},
        [](auto& c) -> auto& { return c.filter.q22; }));
    s.push_back(real(
        {.key = "filter.r11",
         .field = "filter.r11",
         .label = paper_symbol("R11"),
         .help = tr_noop("variance of the front IR distance, m²"),
         .page = kFilter,
         .applies = kLive,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.filter.r11; }));
    s.push_back(real(
        {.key = "filter.r22",
         .field = "filter.r22",
         .label = paper_symbol("R22"),
         .help = tr_noop("variance of the rear IR distance, m²"),
         .page = kFilter,
         .applies = kLive,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.filter.r22; }));
    s.push_back(boolean(
        {.key = "filter.wall_updates",
         .field = "filter.wall_updates",
         .label = in_words("wall updates"),
         .help = tr_noop("on: the IR distances to the walls correct the estimate; "
                         "off: odometry only (walls are associated but never used)"),
         .page = kFilter,
         .applies = kLive,
         .use = kWallLesson},
        [](auto& c) -> auto& { return c.filter.wall_updates; }));
    s.push_back(boolean(
        {.key = "filter.gate",
         .field = "filter.gate_enabled",
         .label = in_words("gate"),
         .help = tr_noop("reject updates whose NIS exceeds the χ²(2) gate"),
         .page = kFilter,
         .applies = kLive,
         .use = kWallLesson},
        [](auto& c) -> auto& { return c.filter.gate_enabled; }));
    s.push_back(real(
        {.key = "filter.gate_probability",
         .field = "filter.gate_probability",
         .label = in_words("gate probability"),
         .help = tr_noop("probability of the Mahalanobis gate, in (0, 1)"),
         .page = kFilter,
         .applies = kLive,
         .use = kWallLesson},
        [](auto& c) -> auto& { return c.filter.gate_probability; }));
    s.push_back(real(
        {.key = "filter.min_variance",
         .field = "filter.min_variance",
         .label = in_words("min variance"),
         .help = tr_noop("floor on every variance of P"),
         .page = kFilter,
         .applies = kLive,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.filter.limits.min_variance; }));
    s.push_back(real(
        {.key = "filter.max_variance",
         .field = "filter.max_variance",
         .label = in_words("max variance"),
         .help = tr_noop("ceiling on every variance of P"),
         .page = kFilter,
         .applies = kLive,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.filter.limits.max_variance; }));
}

}  // namespace legofeup::lessons
