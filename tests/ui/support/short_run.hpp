#pragma once
// A lesson step's preset cut short for GUI tests: a straight line for 3 simulated seconds
// (0.3 s at 10×), so a test sees a whole run — finished routine, outcome, conclusion — in
// well under a second. The routine and its length are tuning: the run still counts for the
// step (step_membership.hpp).

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::ui::testing {

inline lessons::RunConfig short_run(lessons::RunConfig config) {
    config.routine.kind = lessons::RoutineSpec::Kind::Line;
    config.duration = 3.0;
    return config;
}

}  // namespace legofeup::ui::testing
