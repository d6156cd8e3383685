#pragma once
// Whether a run's configuration is a lesson step's, and which step a configuration came from.
//
// A step is an experiment: a world, a way of correcting the odometry, the filter that does it
// (EKF, UKF or particle filter: the mcl lesson's tracking step is the laser lesson's lap with
// a particle filter), and the sensors and events the simulated robot has (experiment_keys()).
// Everything else — Q and R, the noise, the routine and its length, the seed, the initial belief —
// is what students tune, and a run tuned so still counts for the step. A configuration whose
// experiment differs from a step's preset is not that step's, whatever step the Lesson dock shows:
// the laser lesson's run in the office (`legofeup-cli config -e laser:a`) is not LegoFeup step f's.

#include <cstddef>
#include <string>
#include <vector>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::ui {

/// The settings (keys) that make a run one experiment and not another: the world, the
/// localisation method, the filter kind, and every `enabled` of the simulated sensors and events
/// (beacon scanner, gyroscope, accelerometers, compass, laser scanner, kidnapping, displacement).
const std::vector<std::string>& experiment_keys();

/// The experiment keys in which `config` differs from `step`'s preset, in experiment_keys()
/// order; empty when the configuration is the step's.
std::vector<std::string> experiment_differences(const lessons::RunConfig& config,
                                                const lessons::LessonStep& step);

/// Whether `config` is `step`'s: its preset, tuned at most (experiment_differences() empty).
bool is_step_configuration(const lessons::RunConfig& config, const lessons::LessonStep& step);

/// How many settings of all (run_settings()) differ between two configurations.
std::size_t settings_differing(const lessons::RunConfig& first, const lessons::RunConfig& second);

struct StepOfConfiguration {
    const lessons::Lesson* lesson = nullptr;  ///< nullptr: the configuration is no step's
    const lessons::LessonStep* step = nullptr;
};

/// The step `config` came from: of the steps of `lessons` whose configuration it is, the one
/// whose preset it differs from in the fewest settings (the first in `lessons`' order of
/// equals). A preset itself gives its own step (unless an earlier step has the same preset).
StepOfConfiguration step_of_configuration(const lessons::RunConfig& config,
                                          const std::vector<const lessons::Lesson*>& lessons);

}  // namespace legofeup::ui
