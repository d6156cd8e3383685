#include "legofeup/core/legofeup_loop.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {
LegoFeupLoop::LegoFeupLoop(LoopConfig config)
    : config_(std::move(config)), controller_(config_.controller) {
    if (const auto issues = validate(config_); !issues.empty()) {
        throw invalid_configuration("loop", issues);
    }
    apply_tuning();
    reset();
}

void LegoFeupLoop::apply_tuning() {
    const FilterTuning& tuning = config_.filter;
    process_noise_ = Eigen::Vector2d(tuning.q11, tuning.q22).asDiagonal();
    ir_noise_ = Eigen::Vector2d(tuning.r11, tuning.r22).asDiagonal();
    gate_.enabled = tuning.gate_enabled;
    gate_.threshold = chi_square_quantile(tuning.gate_probability, WallMeasurement::kSize);
    filter_.set_limits(tuning.limits);
}

void LegoFeupLoop::reset() {
    const InitialBelief& initial = config_.initial;
    const StateCovariance P0 =
        StateVector(initial.var_x, initial.var_y, initial.var_theta).asDiagonal();
    filter_.reset(to_state(initial.pose), P0);
    odometry_pose_ = {initial.pose.x, initial.pose.y, wrap_angle(initial.pose.theta)};
    controller_ = config_.controller;
    have_counts_ = false;
    steps_ = 0;
    snapshot_ = LoopSnapshot{};
    snapshot_.estimate = filter_.state();
    snapshot_.covariance = filter_.covariance();
    snapshot_.odometry_pose = odometry_pose_;
}

std::vector<ConfigIssue> LegoFeupLoop::reconfigure(LoopConfig config) {
    auto issues = validate(config);
    if (issues.empty()) {
        config_ = std::move(config);
        apply_tuning();
    }
    return issues;
}

void LegoFeupLoop::set_controller(Controller controller) {
    config_.controller = std::move(controller);
    controller_ = config_.controller;
}

void LegoFeupLoop::set_manual_command(const VelocityCommand& command) {
    if (auto* manual = std::get_if<ManualDrive>(&controller_)) {
        manual->set_command(command);
    }
}

void LegoFeupLoop::predict_from_encoders(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    s.increment = {};
    s.odometry_glitch = false;
    s.predict_status = StepStatus::NotAttempted;
    if (have_counts_) {
        // Eq. 9: pulses this period → wheel distances; eq. 8: d and Δθ.
        const OdometryIncrement increment = odometry_increment(
            encoder_delta(frame.encoder_counts[0], last_counts_[0]),
            encoder_delta(frame.encoder_counts[1], last_counts_[1]), config_.odometry);
        const double limit = config_.max_wheel_travel_per_step;
        if (std::abs(increment.d_right) > limit || std::abs(increment.d_left) > limit) {
            s.odometry_glitch = true;
        } else {
            s.increment = increment;
            // Eq. 11–13: X̂ ← f(X̂, U, 0), P ← ∇f_X P ∇f_Xᵀ + ∇f_q Q ∇f_qᵀ.
            s.predict_status = filter_.predict(OdometryProcessModel(increment, process_noise_));
            odometry_pose_ = advance_pose(odometry_pose_, increment);  // eq. 7, no updates
        }
    }
    last_counts_ = frame.encoder_counts;
    have_counts_ = true;
}

void LegoFeupLoop::observe_and_update(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    for (int i = 0; i < kIrSensorCount; ++i) {
        const auto index = static_cast<std::size_t>(i);
        IrSample& sample = s.ir[index];
        sample.adc = frame.ir_adc[index];
        sample.reading = frame.ir_valid[index]
                             ? distance_from_adc(sample.adc, config_.ir_curve)  // eq. 2
                             : IrDistance{0.0, IrStatus::Unavailable};
    }
    s.association = AssociationResult{};
    s.update = WallUpdateReport{};
    s.observation_available =
        s.ir[kFrontSensor].reading.in_range() && s.ir[kRearSensor].reading.in_range();
    if (!s.observation_available) {
        return;
    }
    // Eq. 3: (d_s1, d_s2) → (ObsAng, d_w, D_c).
    s.observation = observe_wall(s.ir[kFrontSensor].reading.distance,
                                 s.ir[kRearSensor].reading.distance, config_.ir_mount);
    // Fig. 4: which wall, judged from the current (predicted) estimate.
    s.association =
        associate_wall(to_pose(filter_.state()), s.observation, config_.walls, config_.ir_mount,
                       config_.ir_curve.max_range, config_.association);
    if (s.association.associated() && config_.filter.wall_updates) {
        // Eq. 14–21.
        const WallMeasurement measurement(config_.walls.line(s.association.wall),
                                          s.association.side, s.observation, ir_noise_);
        s.update = filter_.update(measurement, gate_);
    }
}

const LoopSnapshot& LegoFeupLoop::step(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    s.step = ++steps_;
    s.time = frame.time;
    s.sequence = frame.sequence;
    s.frame_missing = false;
    s.frame = frame;

    predict_from_encoders(frame);
    observe_and_update(frame);
    control_and_publish();
    return s;
}

const LoopSnapshot& LegoFeupLoop::step_without_frame(double time) {
    LoopSnapshot& s = snapshot_;
    s.step = ++steps_;
    s.time = time;
    s.frame_missing = true;
    s.frame = SensorFrame{};
    s.frame.time = time;

    // Eq. 11–13 with d = Δθ = 0: X̂ is unchanged and P ← P + ∇f_q Q ∇f_qᵀ. A period passed
    // in which the robot moved in some unknown way; its odometry arrives with the next frame.
    s.increment = {};
    s.odometry_glitch = false;
    s.predict_status = have_counts_
                           ? filter_.predict(OdometryProcessModel(s.increment, process_noise_))
                           : StepStatus::NotAttempted;
    for (IrSample& sample : s.ir) {
        sample = IrSample{0, IrDistance{0.0, IrStatus::Unavailable}};
    }
    s.observation_available = false;
    s.association = AssociationResult{};
    s.update = WallUpdateReport{};
    control_and_publish();
    return s;
}

void LegoFeupLoop::control_and_publish() {
    LoopSnapshot& s = snapshot_;
    // Control module on the updated estimate; eq. 1 turns (V, W) into wheel speeds.
    const ControlOutput control = run_controller(controller_, to_pose(filter_.state()),
                                                 config_.motion, config_.gains, s.controller);
    s.velocity = control.command;
    s.wheels = limit_wheel_speeds(wheel_speeds(control.command, config_.odometry.wheel_base),
                                  config_.max_wheel_speed);

    s.estimate = filter_.state();
    s.covariance = filter_.covariance();
    s.odometry_pose = odometry_pose_;
}

}  // namespace legofeup
