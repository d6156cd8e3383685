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
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/lessons/udp_run.hpp"
#include "legofeup/report/run_plots.hpp"
#include "legofeup/version.hpp"
#include "nxt_choice.hpp"
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

/// The link a run uses: the deterministic in-process simulator, a server over UDP, or an NXT.
struct LinkChoice {
    std::optional<lessons::UdpTarget> udp;  ///< both unset: lockstep
    std::unique_ptr<NxtChoice> nxt;

    std::string describe() const {
        if (nxt) {
            return nxt->address();
        }
        return udp ? "udp://" + udp->robot.to_string() : "lockstep";
    }
};

LinkChoice choose_link(const RunOptions& options) {
    LinkChoice choice;
    choice.nxt = choose_nxt(options);
    if (choice.nxt) {
        return choice;
    }
    if (options.relay || !options.truth_url.empty()) {
        throw InputError(
            {{"", 0, options.relay ? "--relay" : "--truth", options.relay ? "" : options.truth_url,
              "only applies to an NXT link (--link bt:…, serial:… or tcp:…)"}});
    }
    if (options.link != "lockstep") {
        choice.udp =
            lessons::parse_udp_target(options.link, options.truth_port, options.control_port);
    }
    return choice;
}

/// What an NXT run adds to the summary: the link's health, and why it ended early if it did.
struct NxtRunReport {
    lessons::RunResult result;
    lessons::LinkHealth health;
    bool truth_known = false;
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

NxtRunReport run_on_nxt(const lessons::ResolvedRun& run, const NxtChoice& nxt,
                        lessons::RunObserver& observer, const lessons::ProgressCallback& progress) {
    const std::unique_ptr<lessons::RobotConnection> connection = nxt.connect();
    lessons::UnknownTruth unknown;
    TruthSource* truth = connection->truth_source();
    NxtRunReport report;
    report.truth_known = truth != nullptr;
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
    return report;
}

nlohmann::json nxt_to_json(const NxtChoice& nxt, const NxtRunReport& report) {
    const lessons::LinkHealth& q = report.health;
    nlohmann::json json = nxt.to_json();
    json.update({
        {"cycles", q.frames},
        {"rate_hz", q.rate_hz()},
        {"mean_cycle_s", q.mean_cycle_seconds},
        {"max_cycle_s", q.max_cycle_seconds},
        {"timeouts", q.timeouts},
        {"rejected_replies", q.rejected_replies},
        {"invalid_ir_readings", q.invalid_readings},
        {"battery_mv", q.battery_millivolts ? nlohmann::json(*q.battery_millivolts) : nullptr},
    });
    if (!report.interrupted.empty()) {
        json["interrupted"] = report.interrupted;
    }
    return json;
}

void print_nxt_link(const NxtRunReport& report) {
    const lessons::LinkHealth& q = report.health;
    std::printf(
        "  NXT link: %llu cycles at %.1f Hz (mean %.1f ms, max %.1f ms), %llu timeouts, "
        "%llu rejected replies",
        static_cast<unsigned long long>(q.frames), q.rate_hz(), 1e3 * q.mean_cycle_seconds,
        1e3 * q.max_cycle_seconds, static_cast<unsigned long long>(q.timeouts),
        static_cast<unsigned long long>(q.rejected_replies));
    if (q.battery_millivolts) {
        std::printf(", battery %.2f V", *q.battery_millivolts / 1000.0);
    }
    std::printf("\n");
}

nlohmann::json link_to_json(const LinkChoice& link, const lessons::UdpRunReport& report) {
    if (!link.udp) {
        return {{"kind", "lockstep"}};
    }
    const comms::ServerCounters& c = report.server.counters;
    return {
        {"kind", "udp"},
        {"robot", link.udp->robot.to_string()},
        {"truth", link.udp->truth.to_string()},
        {"control", link.udp->control.to_string()},
        {"frames_received", report.link.frames.accepted},
        {"frames_duplicate", report.link.frames.duplicate},
        {"frames_late", report.link.frames.late},
        {"frame_timeouts", report.link.timeouts},
        {"server_time_scale", report.server.time_scale},
        {"server_commands_accepted", c.commands_accepted},
        {"server_commands_missing", c.commands_missing},
        {"server_overruns", c.overruns},
    };
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
    LinkChoice link;
    try {
        run = lessons::resolve(compose_cli_config(options, title));
        link = choose_link(options);
        if (!options.profile.empty()) {
            const lessons::RobotProfile profile = lessons::load_robot_profile(options.profile);
            lessons::apply_robot_profile(profile, run.loop);
            if (link.nxt) {
                link.nxt->apply_profile(profile);
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
            log_options.link = link.describe();
            run_log.emplace(options.record_file, run, title, std::move(log_options));
            observers.add(*run_log);
        }
        lessons::UdpRunReport report;
        std::optional<NxtRunReport> nxt;
        if (link.nxt) {
            nxt = run_on_nxt(run, *link.nxt, observers, show_progress);
            report.result = nxt->result;
        } else if (link.udp) {
            report = lessons::run_over_udp(run, *link.udp, &observers, show_progress);
        } else {
            report.result = lessons::run_lockstep(run, &observers, show_progress);
        }
        const lessons::RunResult& result = report.result;
        progress.finish();
        trace.commit();
        if (run_log) {
            run_log->close();
        }

        fileio::AtomicFile summary(out / "summary.json");
        nlohmann::json summary_json = lessons::run_summary(run, result, options.experiment, title);
        summary_json["link"] = nxt ? nxt_to_json(*link.nxt, *nxt) : link_to_json(link, report);
        const bool interrupted = nxt && !nxt->interrupted.empty();
        if (interrupted) {
            summary_json["interrupted"] = nxt->interrupted;
            summary_json["steps_recorded"] = steps.steps;
        }
        summary.stream() << summary_json.dump(2) << '\n';
        summary.commit();
        // Plots compare the estimate with the truth: a real robot has none.
        const bool plots = options.plots && !(nxt && !nxt->truth_known);
        if (plots) {
            report::write_run_plots(recording, run.world, out, "LegoFeup " + title);
        }
        if (interrupted) {
            std::cerr << "error: the run on " << link.describe() << " stopped after " << steps.steps
                      << " steps: " << nxt->interrupted
                      << "\nA stop was sent to the motors as far as the link still carried it: "
                         "check the robot. "
                      << out.string() << "/trace.csv and summary.json keep what was recorded.\n";
            return kExitLinkFailed;
        }
        if (!options.quiet) {
            print_summary(run, result, title, link.describe());
            if (nxt) {
                print_nxt_link(*nxt);
            }
            std::printf("Results in %s: trace.csv, summary.json%s\n", out.string().c_str(),
                        plots ? ", trajectory, errors, covariance, ir_distances and "
                                "wheel_speeds (.png and .svg)"
                              : "");
        }
    } catch (const comms::LinkError& failure) {
        std::cerr << "error: " << failure.what() << '\n';
        return kExitLinkFailed;
    } catch (const lessons::LinkSilent& failure) {
        std::cerr << "error: " << failure.what() << " from " << link.describe()
                  << " (did legofeup-sim stop?); nothing was written"
                  << (options.record_file.empty()
                          ? std::string()
                          : " but the run log " + options.record_file + " (steps so far)")
                  << '\n';
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
