#include "legofeup/lessons/run_summary.hpp"

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

}  // namespace

nlohmann::json metrics_to_json(const RunMetrics& m) {
    nlohmann::json association = nlohmann::json::object();
    for (int i = 0; i < kAssociationOutcomeCount; ++i) {
        association[to_string(static_cast<AssociationOutcome>(i))] =
            m.association_outcomes[static_cast<std::size_t>(i)];
    }
    return {
        {"steps", m.steps},
        {"simulated_time_s", m.duration},
        {"rms_position_error_m", m.rms_position_error},
        {"max_position_error_m", m.max_position_error},
        {"final_position_error_m", m.final_position_error},
        {"rms_heading_error_rad", m.rms_heading_error},
        {"max_heading_error_rad", m.max_heading_error},
        {"final_heading_error_rad", m.final_heading_error},
        {"rms_odometry_position_error_m", m.rms_odometry_position_error},
        {"final_odometry_position_error_m", m.final_odometry_position_error},
        {"observations", m.observations},
        {"association", association},
        {"updates_applied", m.updates_applied},
        {"updates_rejected", m.updates_rejected},
        {"mean_update_position_step_m", m.mean_update_position_step},
        {"mean_update_heading_step_rad", m.mean_update_heading_step},
        {"rms_estimate_to_odometry_m", m.rms_estimate_to_odometry},
        {"mean_nees", m.mean_nees},
        {"nees_95_bounds", {m.nees_bounds.lower, m.nees_bounds.upper}},
        {"nees_inside_fraction", m.nees_inside_fraction},
        {"mean_nis", m.mean_nis},
        {"rms_odometry_heading_error_rad", m.rms_odometry_heading_error},
        {"max_odometry_heading_error_rad", m.max_odometry_heading_error},
        {"final_odometry_heading_error_rad", m.final_odometry_heading_error},
        {"beacon_bearings", m.beacon_bearings},
        {"beacon_updates_applied", m.beacon_updates_applied},
        {"mean_beacon_nis", m.mean_beacon_nis},
        {"rms_wheel_speed_error_kf_mps", m.rms_wheel_speed_error_kf},
        {"rms_wheel_speed_error_differentiated_mps", m.rms_wheel_speed_error_differentiated},
        {"rms_velocity_error_kf_mps", m.rms_velocity_error_kf},
        {"rms_velocity_error_encoders_mps", m.rms_velocity_error_encoders},
        {"rms_turn_rate_error_kf_radps", m.rms_turn_rate_error_kf},
        {"rms_turn_rate_error_encoders_radps", m.rms_turn_rate_error_encoders},
        {"rms_compass_heading_error_rad", m.rms_compass_heading_error},
        {"final_gyro_heading_error_rad", m.final_gyro_heading_error},
        {"shadow_rms_position_error_m", m.shadow_rms_position_error},
        {"shadow_final_position_error_m", m.shadow_final_position_error},
        {"shadow_rms_heading_error_rad", m.shadow_rms_heading_error},
        {"shadow_mean_nees", m.shadow_mean_nees},
        {"laser_scans", m.laser_scans},
        {"laser_matches", m.laser_matches},
        {"laser_skipped_scans", m.laser_skipped_scans},
        {"laser_recoveries", m.laser_recoveries},
        {"laser_match_fraction", m.laser_match_fraction},
        {"odometry_end_to_start_m", m.odometry_end_to_start},
        {"estimate_end_to_start_m", m.estimate_end_to_start},
        {"odometry_to_estimate_final_error_ratio", m.odometry_to_estimate_final_error_ratio},
        {"kidnappings", m.kidnappings},
        {"time_to_recover_s", m.time_to_recover},
        {"kidnap_recovered", m.kidnap_recovered},
        // Ratios for the lessons' comparisons (below 1: the first is better).
        {"wheel_speed_error_ratio",
         ratio(m.rms_wheel_speed_error_kf, m.rms_wheel_speed_error_differentiated)},
        {"velocity_error_ratio", ratio(m.rms_velocity_error_kf, m.rms_velocity_error_encoders)},
        {"turn_rate_error_ratio", ratio(m.rms_turn_rate_error_kf, m.rms_turn_rate_error_encoders)},
        {"heading_error_to_odometry_ratio",
         ratio(m.rms_heading_error, m.rms_odometry_heading_error)},
        {"shadow_position_error_ratio", ratio(m.shadow_rms_position_error, m.rms_position_error)},
    };
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
