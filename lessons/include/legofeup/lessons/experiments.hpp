#pragma once
// The guided experiments a–h: the steps of the built-in LegoFeup lesson
// (resources/lessons/legofeup.toml, lesson.hpp), seen as what the programs run. Each one is a
// title, instructions, the expected conclusion, and a configuration.

#include <string>
#include <string_view>
#include <vector>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

struct Experiment {
    std::string id;  ///< "a" … "h"
    std::string title;
    std::string instructions;
    std::string expectation;  ///< the conclusion the run should lead to
    RunConfig config;         ///< defaults + the file's base + this experiment's overlay
};

/// The experiments of the LegoFeup lesson, in order (parsed once).
const std::vector<Experiment>& legofeup_experiments();

/// The LegoFeup steps ("a" … "h") and every other built-in lesson's steps as
/// "<lesson>:<step>" ("beacons:a", "compass:c", …): what --experiment accepts.
const std::vector<Experiment>& all_experiments();

/// An experiment of all_experiments() by id, or nullptr.
const Experiment* find_experiment(std::string_view id);

}  // namespace legofeup::lessons
