#include "legofeup/core/legofeup_loop.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/compass_model.hpp"
#include "legofeup/core/laser_process_model.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {
namespace {

/// P0 of the fusion filter's (v, ω): the robot starts at rest, known to about 0.1 m/s.
constexpr double kInitialVelocityVariance = 1e-2;

/// Wall-clock seconds `work` takes (the cost per step the beacon lesson compares).
template <class Work>
double timed(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LegoFeupLoop::LegoFeupLoop(LoopConfig config)
    : config_(std::move(config)),
      filter_(make_pose_estimator(FilterKind::Ekf)),
      shadow_(make_pose_estimator(FilterKind::Ekf)),
      controller_(config_.controller) {
    if (const auto issues = validate(config_); !issues.empty()) {
        throw invalid_configuration("loop", issues);
    }
    scan_endpoints_.reserve(static_cast<std::size_t>(kMaxScanBeams));
    apply_tuning();
    reset();
}

bool LegoFeupLoop::uses_pose_filter() const {
    return config_.lesson.localisation != Localisation::GyroFusion;
}

void LegoFeupLoop::apply_tuning() {
    const FilterTuning& tuning = config_.filter;
    const LessonFilters& lesson = config_.lesson;
    process_noise_ = Eigen::Vector2d(tuning.q11, tuning.q22).asDiagonal();
    ir_noise_ = Eigen::Vector2d(tuning.r11, tuning.r22).asDiagonal();
    gate_.enabled = tuning.gate_enabled;
    gate_.threshold = chi_square_quantile(tuning.gate_probability, WallMeasurement::kSize);
    beacon_gate_.enabled = lesson.beacons.gate_enabled;
    beacon_gate_.threshold =
        chi_square_quantile(lesson.beacons.gate_probability, BeaconBearingMeasurement::kSize);
    association_threshold_ = association_gate_threshold(config_.association.gate_probability);
    // A new kind starts from the current x and P, conditioned with the settings in force
    // so far; then both take the new ones.
    switch_kind(filter_, lesson.kind);
    switch_kind(shadow_, pose_estimator_entry(lesson.kind).shadow);
    update_map_models();
    estimator_settings_ = {tuning.limits, lesson.ukf, lesson.particles, config_.random_seed,
                           free_space_};
    filter_->configure(estimator_settings_);
    shadow_->configure(estimator_settings_);
    fusion_.set_limits(tuning.limits);
    laser_.configure(lesson.laser, config_.map);
    shadow_laser_.configure(lesson.laser, config_.map);
    speeds_.configure(lesson, config_.odometry);
}

// The free space and likelihood field take a pass over the map each (a building's map: a
// few milliseconds), so they are built again only when the map changes — and the field only
// once a filter weighs scans with it (the EKF and UKF match scans by ICP instead).
void LegoFeupLoop::update_map_models() {
    const bool on_map = config_.lesson.localisation == Localisation::Laser && config_.map;
    const OccupancyGrid* map = on_map ? config_.map.get() : nullptr;
    const double max_distance = config_.lesson.particles.scan_model.max_distance;
    const bool weighs_scans = filter_->weighs_scans() || shadow_->weighs_scans();
    if (map != nullptr && weighs_scans
        && (!likelihood_field_ || map != likelihood_field_map_
            || max_distance != likelihood_field_max_distance_)) {
        likelihood_field_ = std::make_shared<const LikelihoodField>(*map, max_distance);
        likelihood_field_map_ = map;
        likelihood_field_max_distance_ = max_distance;
    }
    if (free_space_ && map == free_space_map_ && map != nullptr) {
        return;  // the same map: its free cells are known
    }
    free_space_ = std::make_shared<const FreeSpace>(
        map != nullptr ? FreeSpace::of_grid(*map) : FreeSpace::bounding(config_.walls));
    free_space_map_ = map;
}

void LegoFeupLoop::switch_kind(std::unique_ptr<PoseEstimator>& estimator, FilterKind kind) const {
    if (estimator->kind() == kind) {
        return;
    }
    std::unique_ptr<PoseEstimator> next = make_pose_estimator(kind);
    next->configure(estimator_settings_);
    next->reset(estimator->state(), estimator->covariance());
    estimator = std::move(next);
}

void LegoFeupLoop::reset() {
    const InitialBelief& initial = config_.initial;
    const StateCovariance P0 =
        StateVector(initial.var_x, initial.var_y, initial.var_theta).asDiagonal();
    const StateVector x0 = to_state(initial.pose);
    // An unknown pose with no free space to spread over is refused by validate().
    if (!(initial.unknown_pose && filter_->reset_uniform())) {
        filter_->reset(x0, P0);
    }
    if (!(initial.unknown_pose && shadow_->reset_uniform())) {
        shadow_->reset(x0, P0);
    }
    fusion_.reset(x0, P0, kInitialVelocityVariance);
    laser_.reset();
    shadow_laser_.reset();
    speeds_.reset(initial.pose);
    odometry_pose_ = {initial.pose.x, initial.pose.y, wrap_angle(initial.pose.theta)};
    controller_ = config_.controller;
    have_counts_ = false;
    steps_ = 0;
    glitches_ = 0;
    last_time_ = 0.0;
    snapshot_ = LoopSnapshot{};
    laser_report_empty_ = true;
    snapshot_.localisation = config_.lesson.localisation;
    snapshot_.filter_kind = filter_->kind();
    snapshot_.estimate = filter_->state();
    snapshot_.covariance = filter_->covariance();
    snapshot_.particles = filter_->particles();
    snapshot_.odometry_pose = odometry_pose_;
}

std::vector<ConfigIssue> LegoFeupLoop::reconfigure(LoopConfig config) {
    auto issues = validate(config);
    if (!issues.empty()) {
        return issues;
    }
    const Localisation before = config_.lesson.localisation;
    const Localisation after = config.lesson.localisation;
    const bool shadow_starts = config.lesson.compare_kinds && !config_.lesson.compare_kinds;
    config_ = std::move(config);
    // A new localisation continues from the current belief rather than jumping back.
    if (after == Localisation::GyroFusion && before != Localisation::GyroFusion) {
        fusion_.reset(filter_->state(), filter_->covariance(), kInitialVelocityVariance);
    } else if (before == Localisation::GyroFusion && after != Localisation::GyroFusion) {
        filter_->reset(fusion_.pose(), fusion_.pose_covariance());
    }
    apply_tuning();
    if (shadow_starts) {
        shadow_->reset(filter_->state(), filter_->covariance());
        shadow_laser_.reset();
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

// Eq. 9 and 8: this period's wheel distances, d and Δθ; dead reckoning (eq. 7) alongside.
// Returns whether the filters predict this period: not on the first frame (no reference
// yet). A wheel that moved farther than max_wheel_travel_per_step per nominal period, times
// the periods since the last counts (at least one), is an encoder glitch (a counter reset): its
// motion is not used, and the filters predict with no increment and the noise of the skipped motion
// instead (skipped_motion_noise).
bool LegoFeupLoop::advance_odometry(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    s.increment = {};
    s.odometry_glitch = false;
    bool predict = false;
    if (have_counts_) {
        // The counts' last reading may be several periods back (frames went missing).
        const double elapsed_periods = periods_between(frame.time - last_counts_time_);
        const OdometryIncrement increment = odometry_increment(
            encoder_delta(frame.encoder_counts[0], last_counts_[0]),
            encoder_delta(frame.encoder_counts[1], last_counts_[1]), config_.odometry);
        const double limit = config_.max_wheel_travel_per_step * std::max(1.0, elapsed_periods);
        if (std::abs(increment.d_right) > limit || std::abs(increment.d_left) > limit) {
            s.odometry_glitch = true;
            ++glitches_;
        } else {
            s.increment = increment;
            odometry_pose_ = advance_pose(odometry_pose_, increment);  // eq. 7, no updates
        }
        predict = true;
    }
    s.odometry_glitches = glitches_;
    last_counts_ = frame.encoder_counts;
    last_counts_time_ = frame.time;
    have_counts_ = true;
    return predict;
}

double LegoFeupLoop::periods_between(double seconds) const {
    // On the microsecond grid that the UDP protocol and the NXT link carry times on, so a
    // run gives the same bits in-process and over a link, and regular frames exactly 1.
    const auto elapsed = std::llround(seconds * 1e6);
    const auto nominal = std::llround(config_.control_period * 1e6);
    if (elapsed <= 0 || nominal <= 0) {
        return 1.0;  // the first frame, or a clock that did not advance: one period
    }
    return static_cast<double>(elapsed) / static_cast<double>(nominal);
}

Eigen::Matrix2d LegoFeupLoop::skipped_motion_noise(double period) const {
    // Over a period whose counts were a glitch each wheel moved an unknown distance of at
    // most L = v_max·Δt either way: uniform on [−L, L], variance L²/3, independently. Then
    // d = (d_r + d_l)/2 has variance L²/6, Δθ = (d_r − d_l)/b has 2L²/(3b²), and the two
    // are uncorrelated.
    const double L = config_.max_wheel_speed * period;
    const double b = config_.odometry.wheel_base;
    return Eigen::Vector2d(L * L / 6.0, 2.0 * L * L / (3.0 * b * b)).asDiagonal();
}

// The estimators of this period, timed: the pose filter (and its shadow) or the 5-state
// fusion. `frame` is null when no frame came (prediction only).
void LegoFeupLoop::estimate(const SensorFrame* frame, bool predict, double period) {
    LoopSnapshot& s = snapshot_;
    s.predict_status = StepStatus::NotAttempted;
    s.filter_seconds = 0.0;
    s.shadow_filter_seconds = 0.0;
    if (!uses_pose_filter()) {
        // The fusion filter starts with the second frame (it needs a period), and skips a
        // period whose counts were a glitch (its wheel speeds would be the jump's).
        if (predict && !s.odometry_glitch) {
            s.filter_seconds = timed([&] { run_gyro_fusion(frame, period); });
        }
        return;
    }
    s.filter_seconds = timed([&] { run_pose_filter(*filter_, frame, predict, period, true); });
    if (config_.lesson.compare_kinds) {
        s.shadow_filter_seconds =
            timed([&] { run_pose_filter(*shadow_, frame, predict, period, false); });
    }
}

StepStatus LegoFeupLoop::predict_pose(PoseEstimator& filter, const OdometryIncrement& increment,
                                      double period) {
    // Eq. 11–13: X̂ ← f(X̂, U, 0), P ← ∇f_X P ∇f_Xᵀ + ∇f_q Q ∇f_qᵀ; the compass lesson's Q
    // depends on the motion and heading (paper 004 eq. 5), the laser lesson's has a static
    // and a motion-dependent part added to the pose (paper 001 eq. 11–13).
    //
    // Q is stated per nominal control period Ts (the settings' q11 and q22, the laser
    // lesson's static part). A step spanning Δt adds Q·Δt/Ts: the process noise is a
    // random walk whose variance grows in proportion to time, so frames 40–150 ms apart (an
    // NXT over Bluetooth) give the same covariance over a lap as the simulator's regular
    // 50 ms. The compass lesson's Q is proportional to the motion, which already is Δt's.
    const double elapsed_periods = periods_between(period);
    switch (config_.lesson.localisation) {
        case Localisation::Compass:
            return filter.predict(CompassOdometryProcessModel(increment, config_.lesson.compass));
        case Localisation::Laser: {
            LaserTuning tuning = config_.lesson.laser;
            tuning.q_x_static *= elapsed_periods;
            tuning.q_y_static *= elapsed_periods;
            tuning.q_theta_static *= elapsed_periods;
            return filter.predict(LaserProcessModel(increment, filter.state()(kTheta), tuning));
        }
        case Localisation::Walls:
        case Localisation::Beacons:
        case Localisation::GyroFusion:
            break;
    }
    Eigen::Matrix2d q = process_noise_ * elapsed_periods;
    if (snapshot_.odometry_glitch) {
        q += skipped_motion_noise(period);
    }
    return filter.predict(OdometryProcessModel(increment, q));
}

void LegoFeupLoop::read_ir(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto index = static_cast<std::size_t>(sensor);
        IrSample& sample = s.ir[index];
        sample.adc = frame.ir_adc[index];
        sample.reading = frame.ir_valid[index]  // eq. 2, with this sensor's own curve
                             ? distance_from_adc(sample.adc, ir_sensor_curve(config_, sensor))
                             : IrDistance{0.0, IrStatus::Unavailable};
    }
    s.observation_available =
        s.ir[kFrontSensor].reading.in_range() && s.ir[kRearSensor].reading.in_range();
    if (s.observation_available) {
        // Eq. 3: (d_s1, d_s2) → (ObsAng, d_w, D_c).
        s.observation = observe_wall(s.ir[kFrontSensor].reading.distance,
                                     s.ir[kRearSensor].reading.distance, config_.ir_mount);
    }
}

void LegoFeupLoop::update_with_walls(PoseEstimator& filter, bool primary) {
    LoopSnapshot& s = snapshot_;
    if (!s.observation_available) {
        return;
    }
    // Fig. 4: which wall, judged from this filter's current (predicted) estimate.
    const AssociationResult association =
        associate_wall({to_pose(filter.state()), filter.covariance()}, s.observation, config_.walls,
                       config_.ir_mount, config_.ir_curve.max_range, ir_noise_, config_.association,
                       association_threshold_);
    if (primary) {
        s.association = association;
    }
    if (association.associated() && config_.filter.wall_updates) {
        // Eq. 14–21.
        const WallMeasurement measurement(config_.walls.line(association.wall), association.side,
                                          s.observation, ir_noise_);
        const WallUpdateReport report = filter.update(measurement, gate_);
        if (primary) {
            s.update = report;
        }
    }
}

// Paper 002: each sighting is one bearing measurement h(X) = atan2(b_y − y, b_x − x) − θ,
// applied in turn (independent noises make sequential updates equal to a stacked one).
void LegoFeupLoop::update_with_beacons(PoseEstimator& filter, const SensorFrame& frame,
                                       bool primary) {
    const int count = std::min<int>(frame.beacons.count, kMaxBeaconSightings);
    for (int i = 0; i < count; ++i) {
        const BeaconSighting& sighting = frame.beacons.sightings[static_cast<std::size_t>(i)];
        BeaconUpdate update;
        update.id = sighting.id;
        update.bearing = sighting.bearing;
        if (const Beacon* beacon = find_beacon(config_.beacons, sighting.id)) {
            update.known = true;
            const BeaconBearingMeasurement measurement(beacon->position, sighting.bearing,
                                                       config_.lesson.beacons.r_bearing);
            // On top of the beacon (within 1 mm) the bearing says nothing: skip it.
            if (measurement.usable(filter.state())) {
                const auto report = filter.update(measurement, beacon_gate_);
                update.predicted = report.predicted(0);
                update.status = report.status;
                update.nis = report.nis;
            }
        }
        if (primary) {
            snapshot_.beacons.updates[static_cast<std::size_t>(i)] = update;
            snapshot_.beacons.count = static_cast<std::uint8_t>(i + 1);
        }
    }
}

void LegoFeupLoop::update_with_compass(PoseEstimator& filter, const LoopSnapshot& s) {
    if (s.readings.has_compass && config_.lesson.compass.use_compass) {
        filter.update(
            CompassMeasurement(s.readings.compass_heading, config_.lesson.compass.r_compass));
    }
}

// Paper 001: the scan matched against the expected scan at this filter's prediction; the
// match (if any) is a pose observation. The shadow filter matches too, unpublished.
void LegoFeupLoop::update_with_laser(PoseEstimator& filter, const SensorFrame& frame,
                                     bool primary) {
    if (filter.weighs_scans()) {
        if (primary) {
            weigh_scan(filter, frame.laser, snapshot_.laser);
        } else {
            shadow_laser_report_ = LaserUpdate{};
            weigh_scan(filter, frame.laser, shadow_laser_report_);
        }
        return;
    }
    if (primary) {
        laser_.process(filter, frame.laser, snapshot_.laser);
    } else {
        shadow_laser_report_ = LaserUpdate{};
        shadow_laser_.process(filter, frame.laser, shadow_laser_report_);
    }
}

// The particle filter's laser update: the scan's end points (every beam_stride-th beam with
// a range, in the robot frame through the scanner's mount) weighed against the map's
// likelihood field. The report says a scan came and how the update went; ICP's parts stay
// empty.
void LegoFeupLoop::weigh_scan(PoseEstimator& filter, const LaserScan& scan, LaserUpdate& report) {
    // The field is built for the map in force once a filter weighs scans (update_map_models).
    const bool field = likelihood_field_ && likelihood_field_map_ == config_.map.get();
    if (!field || scan.beam_count != config_.lesson.laser.geometry.beam_count) {
        report.wrong_beam_count = field;
        return;
    }
    const LaserTuning& laser = config_.lesson.laser;
    const LikelihoodFieldParams& model = config_.lesson.particles.scan_model;
    scan_endpoints(scan, laser.geometry, laser.mount, model.beam_stride, scan_endpoints_);
    report.scan_received = true;
    report.measured_points = static_cast<int>(scan_endpoints_.size());
    report.status = filter.update(
        ScanLikelihood{*likelihood_field_, scan_endpoints_, model, laser.geometry.range_max});
    report.matched = report.status == StepStatus::Applied;
}

// This period's laser report starts empty but for what outlives a scan (the mismatch
// streak, the recovery, the totals), so a period without a scan still shows them. Only the
// laser lesson writes the report: in the others it stays empty, and clearing it again (its
// expected scan is 2 KB) would be a third of the step.
void LegoFeupLoop::begin_laser_report() {
    if (!laser_report_empty_) {
        snapshot_.laser = LaserUpdate{};
        laser_report_empty_ = true;
    }
    if (config_.lesson.localisation == Localisation::Laser) {
        laser_.describe(snapshot_.laser);
        laser_report_empty_ = false;  // and process() may fill the rest
    }
}

// One filter's whole period: predict (when there was odometry), then the localisation's
// corrections. `frame` is null when only a prediction is due.
void LegoFeupLoop::run_pose_filter(PoseEstimator& filter, const SensorFrame* frame, bool predict,
                                   double period, bool primary) {
    if (predict) {
        const StepStatus status = predict_pose(filter, snapshot_.increment, period);
        if (primary) {
            snapshot_.predict_status = status;
        }
    }
    if (frame == nullptr) {
        return;
    }
    switch (config_.lesson.localisation) {
        case Localisation::Walls:
            update_with_walls(filter, primary);
            break;
        case Localisation::Beacons:
            if (frame->has_beacon_scan) {
                update_with_beacons(filter, *frame, primary);
            }
            break;
        case Localisation::Compass:
            update_with_compass(filter, snapshot_);
            break;
        case Localisation::Laser:
            if (frame->has_laser_scan) {
                update_with_laser(filter, *frame, primary);
            }
            break;
        case Localisation::GyroFusion:
            break;  // runs in run_gyro_fusion
    }
}

void LegoFeupLoop::run_gyro_fusion(const SensorFrame* frame, double period) {
    LoopSnapshot& s = snapshot_;
    const VelocityCommand* encoders =
        frame != nullptr && s.speeds.valid ? &s.speeds.body_encoders : nullptr;
    const double* gyro = frame != nullptr && s.readings.has_gyro ? &s.readings.gyro_rate : nullptr;
    const GyroFusionStep step = fusion_.step(period, speeds_.measured_acceleration(), encoders,
                                             gyro, config_.lesson.gyro_fusion);
    s.predict_status = step.predict;
}

const LoopSnapshot& LegoFeupLoop::step(const SensorFrame& frame) {
    LoopSnapshot& s = snapshot_;
    const double period =
        steps_ > 0 && frame.time > last_time_ ? frame.time - last_time_ : config_.control_period;
    s.step = ++steps_;
    s.time = frame.time;
    s.sequence = frame.sequence;
    s.frame_missing = false;
    s.frame = frame;
    s.association = AssociationResult{};
    s.update = WallUpdateReport{};
    s.beacons = BeaconUpdates{};
    begin_laser_report();

    read_ir(frame);
    speeds_.step(frame, period, s.speeds, s.readings);
    const bool predict = advance_odometry(frame);
    estimate(&frame, predict, period);
    control_and_publish();
    last_time_ = frame.time;
    return s;
}

const LoopSnapshot& LegoFeupLoop::step_without_frame(double time) {
    LoopSnapshot& s = snapshot_;
    const double period =
        steps_ > 0 && time > last_time_ ? time - last_time_ : config_.control_period;
    s.step = ++steps_;
    s.time = time;
    s.frame_missing = true;
    s.frame = SensorFrame{};
    s.frame.time = time;

    // Eq. 11–13 with d = Δθ = 0: X̂ is unchanged and P ← P + ∇f_q Q ∇f_qᵀ. A period passed
    // in which the robot moved in some unknown way; its odometry arrives with the next frame.
    s.increment = {};
    s.odometry_glitch = false;
    s.odometry_glitches = glitches_;
    begin_laser_report();
    estimate(nullptr, have_counts_, period);
    for (IrSample& sample : s.ir) {
        sample = IrSample{0, IrDistance{0.0, IrStatus::Unavailable}};
    }
    s.observation_available = false;
    s.association = AssociationResult{};
    s.update = WallUpdateReport{};
    s.beacons = BeaconUpdates{};
    s.speeds = SpeedEstimates{};
    s.readings = ExtraReadings{};
    control_and_publish();
    last_time_ = time;
    return s;
}

void LegoFeupLoop::control_and_publish() {
    LoopSnapshot& s = snapshot_;
    s.localisation = config_.lesson.localisation;
    s.filter_kind = filter_->kind();
    if (uses_pose_filter()) {
        s.estimate = filter_->state();
        s.covariance = filter_->covariance();
        s.fused_velocity = {};
    } else {
        s.estimate = fusion_.pose();
        s.covariance = fusion_.pose_covariance();
        s.fused_velocity = fusion_.velocity();
    }
    s.particles = uses_pose_filter() ? filter_->particles() : ParticleSummary{};
    s.shadow = ShadowEstimate{};
    if (config_.lesson.compare_kinds && uses_pose_filter()) {
        s.shadow = {true, shadow_->kind(), shadow_->state(), shadow_->covariance()};
    }
    // Control module on the updated estimate (or on odometry, LoopConfig::steer_by); eq. 1
    // turns (V, W) into wheel speeds.
    const Pose2 steering =
        config_.steer_by == SteeringPose::Odometry ? odometry_pose_ : to_pose(s.estimate);
    const ControlOutput control = run_controller(
        controller_, steering, config_.motion, config_.gains, config_.control_period, s.controller);
    s.velocity = control.command;
    s.wheels = limit_wheel_speeds(wheel_speeds(control.command, config_.odometry.wheel_base),
                                  config_.max_wheel_speed);
    s.odometry_pose = odometry_pose_;
}

}  // namespace legofeup
