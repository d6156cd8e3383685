#include "legofeup/lessons/run_summary.hpp"

#include <algorithm>
#include <iterator>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/lessons/config_schema.hpp"

namespace legofeup::lessons {
namespace {

nlohmann::json value_to_json(const SettingValue& value) {
    struct ToJson {
        nlohmann::json operator()(double x) const { return x; }
        nlohmann::json operator()(std::int64_t x) const { return x; }
        nlohmann::json operator()(bool x) const { return x; }
        nlohmann::json operator()(const std::string& x) const { return x; }
        nlohmann::json operator()(const Vector2& x) const { return {x.x(), x.y()}; }
    };
    return std::visit(ToJson{}, value);
}

}  // namespace

nlohmann::json config_to_json(const RunConfig& config) {
    nlohmann::json json = nlohmann::json::object();
    for (const Setting& setting : run_settings()) {
        if (setting.is_set && !setting.is_set(config)) {
            continue;
        }
        nlohmann::json& section = setting.section().empty() ? json : json[setting.section()];
        section[setting.name()] = value_to_json(setting.get(config));
    }
    return json;
}

namespace {

/// a / b, or 0 when b is 0 (nothing to compare with).
double ratio(double a, double b) {
    return b > 0.0 ? a / b : 0.0;
}

/// A metric of summary.json that needs the ground truth: its name and how it is read.
struct TruthMetric {
    const char* name;
    nlohmann::json (*value)(const TruthMetrics&);
};

/// A TruthMetrics member as it is written.
template <auto Member>
nlohmann::json field(const TruthMetrics& t) {
    return t.*Member;
}

/// A TruthMetrics interval as [lower, upper]: a bounds metric for `within`.
template <auto Member>
nlohmann::json bounds(const TruthMetrics& t) {
    return {(t.*Member).lower, (t.*Member).upper};
}

/// The interval of mean_nees at another confidence than TruthMetrics' 95 % (the same N_eff).
template <int PerThousand>
nlohmann::json time_average_nees_bounds(const TruthMetrics& t) {
    if (!(t.nees_effective_samples > 0.0)) {
        return {0.0, 0.0};
    }
    const ChiSquareInterval bounds = time_average_chi_square_interval(
        kStateSize, t.nees_effective_samples, PerThousand / 1000.0);
    return {bounds.lower, bounds.upper};
}

/// The ratio of two TruthMetrics members (below 1: the first is better).
template <auto Numerator, auto Denominator>
nlohmann::json ratio_of(const TruthMetrics& t) {
    return ratio(t.*Numerator, t.*Denominator);
}

// The one list of the metrics that need the truth: null in a run without one.
constexpr TruthMetric kTruthMetrics[] = {
    {"rms_position_error_m", field<&TruthMetrics::rms_position_error>},
    {"max_position_error_m", field<&TruthMetrics::max_position_error>},
    {"final_position_error_m", field<&TruthMetrics::final_position_error>},
    {"rms_heading_error_rad", field<&TruthMetrics::rms_heading_error>},
    {"max_heading_error_rad", field<&TruthMetrics::max_heading_error>},
    {"final_heading_error_rad", field<&TruthMetrics::final_heading_error>},
    {"rms_odometry_position_error_m", field<&TruthMetrics::rms_odometry_position_error>},
    {"final_odometry_position_error_m", field<&TruthMetrics::final_odometry_position_error>},
    {"mean_nees", field<&TruthMetrics::mean_nees>},
    {"nees_inside_fraction", field<&TruthMetrics::nees_inside_fraction>},
    {"nees_effective_samples", field<&TruthMetrics::nees_effective_samples>},
    {"nees_autocorrelation_time", field<&TruthMetrics::nees_autocorrelation_time>},
    {"time_average_nees_95_bounds", bounds<&TruthMetrics::time_average_nees_bounds>},
    {"time_average_nees_99_9_bounds", time_average_nees_bounds<999>},
    {"rms_odometry_heading_error_rad", field<&TruthMetrics::rms_odometry_heading_error>},
    {"max_odometry_heading_error_rad", field<&TruthMetrics::max_odometry_heading_error>},
    {"final_odometry_heading_error_rad", field<&TruthMetrics::final_odometry_heading_error>},
    {"rms_wheel_speed_error_kf_mps", field<&TruthMetrics::rms_wheel_speed_error_kf>},
    {"rms_wheel_speed_error_differentiated_mps",
     field<&TruthMetrics::rms_wheel_speed_error_differentiated>},
    {"rms_velocity_error_kf_mps", field<&TruthMetrics::rms_velocity_error_kf>},
    {"rms_velocity_error_encoders_mps", field<&TruthMetrics::rms_velocity_error_encoders>},
    {"rms_turn_rate_error_kf_radps", field<&TruthMetrics::rms_turn_rate_error_kf>},
    {"rms_turn_rate_error_encoders_radps", field<&TruthMetrics::rms_turn_rate_error_encoders>},
    {"rms_wheel_kf_position_error_m", field<&TruthMetrics::rms_wheel_kf_position_error>},
    {"final_wheel_kf_position_error_m", field<&TruthMetrics::final_wheel_kf_position_error>},
    {"wheel_kf_position_to_odometry_ratio",
     field<&TruthMetrics::wheel_kf_position_to_odometry_ratio>},
    {"rms_velocity_kf_position_error_m", field<&TruthMetrics::rms_velocity_kf_position_error>},
    {"final_velocity_kf_position_error_m", field<&TruthMetrics::final_velocity_kf_position_error>},
    {"velocity_kf_position_to_odometry_ratio",
     field<&TruthMetrics::velocity_kf_position_to_odometry_ratio>},
    {"rms_compass_heading_error_rad", field<&TruthMetrics::rms_compass_heading_error>},
    {"final_gyro_heading_error_rad", field<&TruthMetrics::final_gyro_heading_error>},
    {"shadow_rms_position_error_m", field<&TruthMetrics::shadow_rms_position_error>},
    {"shadow_final_position_error_m", field<&TruthMetrics::shadow_final_position_error>},
    {"shadow_rms_heading_error_rad", field<&TruthMetrics::shadow_rms_heading_error>},
    {"shadow_mean_nees", field<&TruthMetrics::shadow_mean_nees>},
    {"odometry_end_to_start_m", field<&TruthMetrics::odometry_end_to_start>},
    {"estimate_end_to_start_m", field<&TruthMetrics::estimate_end_to_start>},
    {"odometry_to_estimate_final_error_ratio",
     field<&TruthMetrics::odometry_to_estimate_final_error_ratio>},
    {"kidnappings", field<&TruthMetrics::kidnappings>},
    {"time_to_recover_s", field<&TruthMetrics::time_to_recover>},
    {"kidnap_recovered", field<&TruthMetrics::kidnap_recovered>},
    // Ratios for the lessons' comparisons.
    {"wheel_speed_error_ratio", ratio_of<&TruthMetrics::rms_wheel_speed_error_kf,
                                         &TruthMetrics::rms_wheel_speed_error_differentiated>},
    {"velocity_error_ratio",
     ratio_of<&TruthMetrics::rms_velocity_error_kf, &TruthMetrics::rms_velocity_error_encoders>},
    {"turn_rate_error_ratio",
     ratio_of<&TruthMetrics::rms_turn_rate_error_kf, &TruthMetrics::rms_turn_rate_error_encoders>},
    {"heading_error_to_odometry_ratio",
     ratio_of<&TruthMetrics::rms_heading_error, &TruthMetrics::rms_odometry_heading_error>},
    {"position_error_to_odometry_ratio",
     ratio_of<&TruthMetrics::rms_position_error, &TruthMetrics::rms_odometry_position_error>},
    {"shadow_position_error_ratio",
     ratio_of<&TruthMetrics::shadow_rms_position_error, &TruthMetrics::rms_position_error>},
};

}  // namespace

bool is_truth_metric(std::string_view name) {
    return std::any_of(std::begin(kTruthMetrics), std::end(kTruthMetrics),
                       [&](const TruthMetric& metric) { return metric.name == name; });
}

nlohmann::json metrics_to_json(const RunMetrics& m) {
    nlohmann::json association = nlohmann::json::object();
    for (int i = 0; i < kAssociationOutcomeCount; ++i) {
        association[to_string(static_cast<AssociationOutcome>(i))] =
            m.association_outcomes[static_cast<std::size_t>(i)];
    }
    nlohmann::json json = {
        {"steps", m.steps},
        {"simulated_time_s", m.duration},
        {"observations", m.observations},
        {"association", association},
        {"updates_applied", m.updates_applied},
        {"updates_rejected", m.updates_rejected},
        {"mean_update_position_step_m", m.mean_update_position_step},
        {"mean_update_heading_step_rad", m.mean_update_heading_step},
        {"rms_estimate_to_odometry_m", m.rms_estimate_to_odometry},
        {"nees_95_bounds", {m.nees_bounds.lower, m.nees_bounds.upper}},
        {"mean_nis", m.mean_nis},
        {"beacon_bearings", m.beacon_bearings},
        {"beacon_updates_applied", m.beacon_updates_applied},
        {"mean_beacon_nis", m.mean_beacon_nis},
        {"laser_scans", m.laser_scans},
        {"laser_matches", m.laser_matches},
        {"laser_skipped_scans", m.laser_skipped_scans},
        {"laser_recoveries", m.laser_recoveries},
        {"laser_match_fraction", m.laser_match_fraction},
    };
    for (const TruthMetric& metric : kTruthMetrics) {
        json[metric.name] = m.truth ? metric.value(*m.truth) : nlohmann::json(nullptr);
    }
    return json;
}

nlohmann::json result_metrics_to_json(const RunResult& result) {
    nlohmann::json metrics = metrics_to_json(result.metrics);
    metrics["wall_time_s"] = result.wall_seconds;
    metrics["real_time_factor"] =
        result.wall_seconds > 0.0 ? result.metrics.duration / result.wall_seconds : 0.0;
    // Cost per step of the pose filter and of its shadow (machine-dependent, like wall time).
    const RunMetrics& m = result.metrics;
    metrics["mean_filter_us"] = m.mean_filter_microseconds;
    metrics["mean_shadow_filter_us"] = m.mean_shadow_filter_microseconds;
    metrics["shadow_to_filter_cost_ratio"] =
        m.mean_filter_microseconds > 0.0
            ? m.mean_shadow_filter_microseconds / m.mean_filter_microseconds
            : 0.0;
    metrics["routine_finished"] = result.routine_finished;
    metrics["frames_missing"] = result.frames_missing;
    metrics["steps_without_truth"] = result.steps_without_truth;
    return metrics;
}

bool is_machine_dependent_metric(std::string_view name) {
    return name == "wall_time_s" || name == "real_time_factor" || name == "mean_filter_us"
           || name == "mean_shadow_filter_us" || name == "shadow_to_filter_cost_ratio";
}

nlohmann::json run_summary(const ResolvedRun& run, const RunResult& result,
                           std::string_view experiment, std::string_view title) {
    nlohmann::json walls = nlohmann::json::array();
    for (const Wall& wall : run.world.walls) {
        walls.push_back({{"name", wall.name},
                         {"from", {wall.start.x(), wall.start.y()}},
                         {"to", {wall.end.x(), wall.end.y()}}});
    }
    return {
        {"experiment", experiment},
        {"title", title},
        {"seed", run.config.seed},
        {"config", config_to_json(run.config)},
        {"world", {{"name", run.world.name}, {"walls", walls}}},
        {"metrics", result_metrics_to_json(result)},
    };
}

}  // namespace legofeup::lessons
