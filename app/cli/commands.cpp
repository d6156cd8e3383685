#include "commands.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "input_problems.hpp"
#include "legofeup/comms/link_error.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/links/link_registry.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/report/run_plots.hpp"
#include "legofeup/version.hpp"
#include "output_directory.hpp"
#include "progress_bar.hpp"

namespace legofeup::cli {
namespace {

namespace fs = std::filesystem;
using lessons::InputError;
using lessons::RunConfig;

// Passes every step to several observers.
class Observers final : public lessons::RunObserver {
  public:
    void add(lessons::RunObserver& observer) { observers_.push_back(&observer); }
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        for (lessons::RunObserver* observer : observers_) {
            observer->on_step(snapshot, truth);
        }
    }

  private:
    std::vector<lessons::RunObserver*> observers_;
};

/// The run's link from the registry (lessons/links/link_registry.hpp): null for lockstep,
/// the deterministic in-process simulator. Throws InputError naming the option.
std::unique_ptr<lessons::LinkPlan> plan_link(const RunOptions& options) {
    lessons::LinkRequest request;
    request.address = options.link;
    request.relay = options.relay;
    request.truth_url = options.truth_url;
    request.truth_port = options.truth_port;
    request.control_port = options.control_port;
    return lessons::plan_link(request);
}

std::string describe(const lessons::LinkPlan* link) {
    return link != nullptr ? link->describe() : std::string(lessons::kLockstepLink);
}

/// A run over a link: its result, what the connection says of itself, and why it ended
/// early if it did.
struct LinkRunReport {
    lessons::RunResult result;
    nlohmann::json link;  ///< RobotConnection::summary(): summary.json's "link"
    lessons::LinkHealth health;
    lessons::LinkCapabilities capabilities;  ///< ground_truth: truth_source() is not null
    std::string interrupted;  ///< the link failure that ended the run (empty: it did not)
};

// Counts the steps written, for a run the link cut short.
class StepCounter final : public lessons::RunObserver {
  public:
    void on_step(const LoopSnapshot& /*snapshot*/, const GroundTruth& /*truth*/) override {
        ++steps;
    }
    std::uint64_t steps = 0;
};

/// Connects (a failure to connect throws comms::LinkError: nothing was run) and runs; a link
/// that fails mid-run ends the run, and what was recorded so far is kept.
LinkRunReport run_on_link(const lessons::ResolvedRun& run, const lessons::LinkPlan& plan,
                          lessons::RunObserver& observer,
                          const lessons::ProgressCallback& progress) {
    const std::unique_ptr<lessons::RobotConnection> connection = plan.connect(run);
    lessons::UnknownTruth unknown;
    TruthSource* truth = connection->truth_source();
    LinkRunReport report;
    report.capabilities = connection->capabilities();
    try {
        report.result =
            lessons::run_with_link(run, connection->robot_link(),
                                   truth != nullptr ? *truth : unknown, &observer, progress);
    } catch (const comms::LinkError& failure) {
        report.interrupted = failure.what();
    } catch (const lessons::LinkSilent& failure) {
        report.interrupted = failure.what();
    }
    connection->close();
    report.health = connection->health();
    report.link = connection->summary();
    if (!report.interrupted.empty()) {
        report.link["interrupted"] = report.interrupted;
    }
    return report;
}

/// A robot's own cycle and battery (an NXT's), when the connection reports them.
void print_robot_health(const lessons::LinkHealth& q) {
    std::printf(
        "  robot link: %llu cycles at %.1f Hz (mean %.1f ms, max %.1f ms), %llu timeouts, "
        "%llu rejected replies",
        static_cast<unsigned long long>(q.frames), q.rate_hz(), 1e3 * q.mean_cycle_seconds,
        1e3 * q.max_cycle_seconds, static_cast<unsigned long long>(q.timeouts),
        static_cast<unsigned long long>(q.rejected_replies));
    if (q.battery_millivolts) {
        std::printf(", battery %.2f V", *q.battery_millivolts / 1000.0);
    }
    std::printf("\n");
}

void print_summary(const lessons::ResolvedRun& run, const lessons::RunResult& result,
                   const std::string& title, const std::string& link) {
    const RunMetrics& m = result.metrics;
    std::printf("LegoFeup %s on %s (seed %llu, %d lap%s): %llu steps\n", title.c_str(),
                link.c_str(), static_cast<unsigned long long>(run.config.seed), run.config.laps,
                run.config.laps == 1 ? "" : "s", static_cast<unsigned long long>(m.steps));
    std::printf("  simulated %.1f s in %.3f s (%.0fx real time)%s\n", m.duration,
                result.wall_seconds,
                result.wall_seconds > 0 ? m.duration / result.wall_seconds : 0.0,
                result.routine_finished ? "" : ", stopped at the time limit");
    if (const std::optional<TruthMetrics>& t = m.truth) {
        std::printf(
            "  position error: RMS %.3f m, max %.3f m, final %.3f m (odometry only: final %.3f "
            "m)\n",
            t->rms_position_error, t->max_position_error, t->final_position_error,
            t->final_odometry_position_error);
        std::printf("  heading error:  RMS %.2f deg, final %.2f deg\n",
                    radians_to_degrees(t->rms_heading_error),
                    radians_to_degrees(t->final_heading_error));
    } else {
        std::printf("  position error: — (no ground truth on this link)\n");
        std::printf("  heading error:  — (no ground truth on this link)\n");
    }
    std::printf("  wall updates: %llu applied, %llu rejected by the filter, %llu observations\n",
                static_cast<unsigned long long>(m.updates_applied),
                static_cast<unsigned long long>(m.updates_rejected),
                static_cast<unsigned long long>(m.observations));
    std::printf("  mean NIS %.2f over the applied updates\n", m.mean_nis);
    if (m.truth) {
        const TruthMetrics& t = *m.truth;
        std::printf(
            "  mean NEES %.2f (a consistent filter's lies in [%.3f, %.3f] at 95%%: a time "
            "average of %.0f effective samples); %.0f%% of steps inside one step's bounds "
            "[%.3f, %.3f]\n",
            t.mean_nees, t.time_average_nees_bounds.lower, t.time_average_nees_bounds.upper,
            t.nees_effective_samples, 100.0 * t.nees_inside_fraction, m.nees_bounds.lower,
            m.nees_bounds.upper);
    } else {
        std::printf("  NEES: — (no ground truth on this link; see trace.csv for the estimates)\n");
    }
    if (result.frames_missing > 0) {
        std::printf("  %llu control period%s ran without a frame (predict only)\n",
                    static_cast<unsigned long long>(result.frames_missing),
                    result.frames_missing == 1 ? "" : "s");
    }
}

}  // namespace

int run_command(const RunOptions& options) {
    std::string title;
    lessons::ResolvedRun run;
    std::unique_ptr<lessons::LinkPlan> link;
    try {
        run = lessons::resolve(compose_cli_config(options, title));
        link = plan_link(options);
        if (!options.profile.empty()) {
            const lessons::RobotProfile profile = lessons::load_robot_profile(options.profile);
            lessons::apply_robot_profile(profile, run.loop);
            if (link) {
                link->apply_profile(profile);  // an NXT's wiring; a simulator has none
            }
            title += " + " + fs::path(options.profile).filename().string();
        }
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }

    const fs::path out(options.out_directory);
    if (!create_output_directory(out)) {
        return kExitOutputFailed;
    }
    try {
        fileio::AtomicFile trace(out / "trace.csv");  // throws if it cannot be created
        lessons::TraceCsvWriter writer(trace.stream(), run.loop);
        report::RunRecording recording;
        Observers observers;
        observers.add(writer);
        if (options.plots) {
            observers.add(recording);
        }
        ProgressBar progress("run " + (options.experiment.empty() ? "" : options.experiment));
        const auto show_progress = [&](double fraction, double simulated) {
            char detail[64];
            std::snprintf(detail, sizeof detail, "%.0f s simulated", simulated);
            progress.update(fraction, detail);
        };
        StepCounter steps;
        observers.add(steps);
        std::optional<lessons::RunLogWriter> run_log;  // --record: flushed as the run goes
        if (!options.record_file.empty()) {
            lessons::RunLogWriter::Options log_options;
            log_options.program = std::string("legofeup-cli ") + kVersion;
            log_options.link = describe(link.get());
            run_log.emplace(options.record_file, run, title, std::move(log_options));
            observers.add(*run_log);
        }
        std::optional<LinkRunReport> over_link;
        lessons::RunResult result;
        if (link) {
            over_link = run_on_link(run, *link, observers, show_progress);
            result = over_link->result;
        } else {
            result = lessons::run_lockstep(run, &observers, show_progress);
        }
        progress.finish();
        trace.commit();
        if (run_log) {
            run_log->close();
        }

        fileio::AtomicFile summary(out / "summary.json");
        nlohmann::json summary_json = lessons::run_summary(run, result, options.experiment, title);
        summary_json["link"] =
            over_link ? over_link->link : nlohmann::json{{"kind", lessons::kLockstepLink}};
        const bool interrupted = over_link && !over_link->interrupted.empty();
        if (interrupted) {
            summary_json["interrupted"] = over_link->interrupted;
            summary_json["steps_recorded"] = steps.steps;
        }
        summary.stream() << summary_json.dump(2) << '\n';
        summary.commit();
        // Plots compare the estimate with the truth: a real robot has none.
        const bool plots = options.plots && !(over_link && !over_link->capabilities.ground_truth);
        if (plots) {
            report::write_run_plots(recording, run.world, out, "LegoFeup " + title);
        }
        if (interrupted) {
            std::cerr << "error: the run on " << describe(link.get()) << " stopped after "
                      << steps.steps << " steps: " << over_link->interrupted << '\n'
                      << (over_link->capabilities.robot_health
                              ? "A stop was sent to the motors as far as the link still "
                                "carried it: check the robot. "
                              : "Is the simulator still running? ")
                      << out.string() << "/trace.csv and summary.json keep what was recorded.\n";
            return kExitLinkFailed;
        }
        if (!options.quiet) {
            print_summary(run, result, title, describe(link.get()));
            if (over_link && over_link->capabilities.robot_health) {
                print_robot_health(over_link->health);
            }
            std::printf("Results in %s: trace.csv, summary.json%s\n", out.string().c_str(),
                        plots ? ", trajectory, errors, covariance, ir_distances and "
                                "wheel_speeds (.png and .svg)"
                              : "");
        }
    } catch (const comms::LinkError& failure) {
        std::cerr << "error: " << failure.what() << '\n';
        return kExitLinkFailed;
    } catch (const std::exception& failure) {
        std::cerr << "error: " << failure.what() << '\n';
        return kExitOutputFailed;
    }
    return kExitOk;
}

int experiments_command() {
    for (const lessons::Experiment& experiment : lessons::legofeup_experiments()) {
        std::printf("%s  %s\n   %s\n\n", experiment.id.c_str(), experiment.title.c_str(),
                    experiment.instructions.c_str());
    }
    std::printf("Run one with: legofeup-cli run --experiment <id> --out <directory>\n");
    return kExitOk;
}

int config_command(const RunOptions& options) {
    std::string title;
    try {
        const RunConfig config = compose_cli_config(options, title);
        lessons::resolve(config);  // refuse to print a configuration that would not run
        std::cout << lessons::config_to_toml(config, "LegoFeup Lab — " + title);
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace legofeup::cli
