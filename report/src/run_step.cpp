// Running one step of a lesson for the report: the same lockstep run as `legofeup-cli run`,
// kept in memory for the plots, with the step's checks evaluated on its metrics.

#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/report/student_report.hpp"

namespace legofeup::report {

StepOutcome run_step(const lessons::LessonStep& step, const lessons::RunConfig& config) {
    const lessons::ResolvedRun run = lessons::resolve(config);
    StepOutcome outcome;
    outcome.step_id = step.id;
    outcome.ran = true;
    outcome.config = run.config;
    outcome.world = run.world;
    const lessons::RunResult result = lessons::run_lockstep(run, &outcome.recording);
    outcome.metrics = lessons::result_metrics_to_json(result);
    outcome.checks = lessons::evaluate_checks(step.checks, outcome.metrics);
    return outcome;
}

}  // namespace legofeup::report
