#pragma once
// The settings of the further lessons' estimators (papers 002, 003, 004): which localisation
// the loop runs, EKF, UKF or particle filter, and each filter's noise model and sensor calibration.
// Part of LoopConfig; validated with it. Units are SI unless a field says otherwise; the
// wheel-speed filter keeps the paper's degree units so its numbers match eq. 19.

#include <cstdint>
#include <optional>
#include <string_view>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/likelihood_field.hpp"
#include "legofeup/core/odometry_alphas.hpp"

namespace legofeup {

/// What corrects the odometry prediction.
enum class Localisation : std::uint8_t {
    Walls,       ///< the LegoFeup lesson: two IR sensors and the four walls (paper 000)
    Beacons,     ///< bearing-only beacons (paper 002)
    GyroFusion,  ///< 5-state EKF [x, y, θ, v, ω]: encoders, accelerometers, gyroscope (paper 003
                 ///< §3.4)
    Compass,     ///< odometry with state-dependent noise + magnetic compass (paper 004)
    Laser,       ///< laser scan matched (ICP) against the expected scan in a map (paper 001)
};
const char* to_string(Localisation localisation);
/// The inverse of to_string ("walls", "beacons", "gyro_fusion", "compass", "laser"); nullopt
/// otherwise.
std::optional<Localisation> localisation_from_string(std::string_view text);

/// The filter that runs the pose estimate (Walls, Beacons, Compass and Laser): the two
/// Gaussian filters, or the particle filter (Monte Carlo localisation, particle_filter.hpp).
enum class FilterKind : std::uint8_t { Ekf, Ukf, Pf };
const char* to_string(FilterKind kind);
/// The inverse of to_string ("ekf", "ukf", "pf"); nullopt otherwise.
std::optional<FilterKind> filter_kind_from_string(std::string_view text);

/// Unscented transform spread: sigma points at ±√((n+κ)·P) with weights κ/(n+κ) and
/// 1/(2(n+κ)) (paper 002 eq. 11–13); n is the (augmented) dimension, n + κ > 0 required.
struct UkfParams {
    double kappa = 0.0;
};

/// The particle filter (Monte Carlo localisation: Thrun, Burgard & Fox, Probabilistic
/// Robotics, Table 4.3 with the low-variance sampler of Table 4.4 and the recovery of
/// augmented MCL, Table 8.3). Its motion noise is the Q the EKF uses, so that one tuning
/// serves all three filters; docs/particle_filter.md states the maths.
struct ParticleFilterTuning {
    int particle_count = 1000;
    /// Resample when the effective sample size N_eff = 1 / Σ wᵢ² falls below this share of
    /// the particle count (1: after every update; 0: never, unless recovery injects).
    double resample_threshold = 0.5;
    /// Augmented MCL: inject particles drawn uniformly from the free space with probability
    /// max(0, 1 − w_fast / w_slow), where w_slow and w_fast are long- and short-term averages
    /// of the measurement likelihood (smoothing factors alpha_slow ≪ alpha_fast). Off unless
    /// asked for (as in ROS AMCL): a wall reading fits a pose anywhere along a line at the
    /// right distance, so in the wall lessons injected particles can lure the cloud away.
    bool recovery = false;
    double alpha_slow = 0.001;
    double alpha_fast = 0.1;
    /// Extra motion noise proportional to the motion (Probabilistic Robotics' α₁…α₄,
    /// odometry_alphas.hpp), sampled on top of the lesson's Q; all zero by default, so that
    /// the particle filter's motion noise is the EKF's.
    OdometryAlphas motion_alphas;
    /// The laser lessons' measurement model: each scan weighs the particles by the likelihood
    /// field of the map (likelihood_field.hpp) rather than by an ICP match, which needs a
    /// guess near the truth and so cannot localise globally.
    LikelihoodFieldParams scan_model;

    friend bool operator==(const ParticleFilterTuning&, const ParticleFilterTuning&) = default;
};

/// The largest particle count accepted (10⁶ particles are 32 MB and about 0.1 s a step).
inline constexpr int kMaxParticleCount = 1'000'000;

/// Bearing-only beacon updates (paper 002).
struct BeaconTuning {
    /// Variance of one bearing, rad²: the paper's simulated π/8.
    double r_bearing = kPi / 8.0;
    bool gate_enabled = false;  ///< reject bearings whose NIS exceeds the χ²(1) gate
    double gate_probability = 0.99;
};

/// The per-wheel linear KF for wheel speed (paper 003 eq. 15–19): state [θ_wheel (°),
/// ω_wheel (°/s)], constant-rate model over the control period, encoder angle measured.
struct WheelSpeedKfTuning {
    double q_angle = 0.1;  ///< Q₁₁, °² per period
    double q_rate = 10.0;  ///< Q₂₂, (°/s)² per period
    double r_right = 2.5;  ///< R of the right encoder, °²
    double r_left = 1.5;   ///< R of the left encoder, °²
    double p0 = 10.0;      ///< P0 = p0·I

    friend bool operator==(const WheelSpeedKfTuning&, const WheelSpeedKfTuning&) = default;
};

/// The defaults are our robot's: the accelerometers' noise (≈2 counts, 0.1 m/s²) over one
/// 50 ms period gives Q; one count of encoder quantisation at each end of the period (plus
/// the sampling jitter) gives R. The paper's numbers are in its own, unstated units.
/// The KF for the body velocities with accelerometer inputs (paper 003 eq. 20–23):
/// state [v (m/s), ω (rad/s)], input [a, α] from the two accelerometers, measurement
/// [v, ω] from differentiated encoders (eq. 14).
struct VelocityKfTuning {
    double q_v = 2e-5;  ///< Q₁₁, (m/s)² per period
    double q_w = 4e-3;  ///< Q₂₂, (rad/s)² per period
    double r_v = 2e-5;  ///< R₁₁, (m/s)² of the encoder speed
    double r_w = 3e-3;  ///< R₂₂, (rad/s)² of the encoder turn rate
    double p0 = 1e-2;   ///< P0 = p0·I
};

/// The 5-state EKF [x, y, θ, v, ω] (paper 003 §3.4, eq. 24–26).
struct GyroFusionTuning {
    double q_position = 1e-8;        ///< per period, m² (model error of x and y)
    double q_heading = 1e-7;         ///< per period, rad²
    double q_v = 2e-5;               ///< per period, (m/s)²
    double q_w = 4e-3;               ///< per period, (rad/s)²
    double r_v_encoders = 2e-5;      ///< (m/s)² of the encoder speed
    double r_w_encoders = 3e-3;      ///< (rad/s)² of the encoder turn rate
    double r_w_gyro = 3e-4;          ///< (rad/s)² of the gyroscope rate
    bool use_gyro = true;            ///< false: encoders (and accelerometers) only
    bool use_accelerometers = true;  ///< false: constant-velocity prediction
    /// Slip detection: with the gyro in use, the encoders' (v, ω) are rejected when their NIS
    /// against the gyro-corrected state exceeds the χ²(2) quantile at this probability — the
    /// wheels turn but the body does not (a robot pushing against a wall). 0 switches it off.
    double encoder_gate_probability = 0.999;
};

/// Odometry with state-dependent noise and a compass (paper 004 eq. 5 and 11).
struct CompassTuning {
    /// eq. 5: Q = diag(k_D·|ΔD·cos θ|, k_D·|ΔD·sin θ|, k_Dθ·|ΔD| + k_θ·|Δθ|), added to the
    /// pose each period (units m, m, rad² per m and rad² per rad).
    double k_d = 1e-4;
    double k_dtheta = 1e-3;
    double k_theta = 1e-3;
    double r_compass = degrees_to_radians(8.0) * degrees_to_radians(8.0);  ///< rad²
    bool use_compass = true;  ///< false: odometry only (the P still grows)
};

/// How raw extra sensors become SI units, as the filters believe them to be calibrated.
struct ExtraSensorCalibration {
    double gyro_offset = 600.0;        ///< raw value at rest, counts
    double gyro_counts_per_dps = 1.0;  ///< counts per °/s
    double accel_counts_per_g = 200.0;
    double gravity = 9.80665;  ///< m/s²
    /// Remove the accelerometers' bias before use (paper 003 §3.3), estimated from the run's
    /// own readings and encoders (accelerometer_bias.hpp).
    bool remove_accel_bias = true;
};

/// Laser scan matching against a map (paper 001): ray-cast the expected scan at the predicted
/// pose, ICP it against the measured scan, and use the match as a pose observation with
/// H = I (eq. 14–18). Q, R (appendix A) and the recovery's 100 mismatches and P × 10
/// (§IV-B) are the paper's; ICP's settings are not (docs/scan_matching.md says why), and the
/// paper gives no number for min_matched_points or for how much stricter ICP gets.
struct LaserTuning {
    /// eq. 13: Q = diag(q_stat + q_dyn·|Δ_odom|) for x, y, θ, added each prediction
    /// (m², m², rad²; the dynamic parts per metre / radian of odometry increment).
    double q_x_static = 0.0005;
    double q_y_static = 0.0005;
    double q_theta_static = 0.0005;
    double q_x_dynamic = 0.001;
    double q_y_dynamic = 0.001;
    double q_theta_dynamic = 0.0011;
    /// eq. 16: R = diag(r_x, r_y, r_θ) of the ICP pose observation (m², m², rad²).
    double r_x = 0.008;
    double r_y = 0.008;
    double r_theta = 0.01;
    IcpParams icp;
    /// Mismatch gating (§III-B): an ICP result that did not converge or matched fewer
    /// points than this is not used (prediction only). §III-B names the condition but not
    /// its number; 100 here is ours (the paper's 100 is the mismatch count of §IV-B).
    int min_matched_points = 100;
    /// Kidnapping recovery (§IV-B): after this many consecutive mismatches, P is multiplied
    /// by `recovery_covariance_factor` and the ICP correspondence distance by
    /// `recovery_correspondence_factor` (≤ 1: stricter) until the next match.
    bool kidnap_recovery = true;
    int recovery_after_mismatches = 100;
    double recovery_covariance_factor = 10.0;
    double recovery_correspondence_factor = 0.5;
    /// Where the scanner sits on the robot (robot frame) and how its beams point, as the
    /// filter believes; a scan's beam_count must equal geometry.beam_count.
    Pose2 mount{};
    ScanGeometry geometry;
};

struct LessonFilters {
    Localisation localisation = Localisation::Walls;
    FilterKind kind = FilterKind::Ekf;
    /// Also run the other filter kind on the same frames, for comparison only (its estimate
    /// never drives the robot): EKF and UKF side by side on one noise realisation.
    bool compare_kinds = false;
    UkfParams ukf;
    ParticleFilterTuning particles;
    BeaconTuning beacons;
    WheelSpeedKfTuning wheel_speed;
    VelocityKfTuning velocity;
    GyroFusionTuning gyro_fusion;
    CompassTuning compass;
    LaserTuning laser;
    ExtraSensorCalibration calibration;
};

}  // namespace legofeup
