// The settings table: the further lessons' filters — the pose filter's kind and its UKF,
// [localisation], the beacons' bearings, the wheel-speed and (v, ω) KFs, the 5-state gyro
// fusion, the compass (eq. 5) and the inertial sensors' calibration. The loop takes them all
// at its next step (a new localisation continues from the current belief).

#include "setting_builders.hpp"

namespace legofeup::lessons {

using namespace setting_builders;

void add_lesson_filter_settings(std::vector<Setting>& s) {
    s.push_back(choice(
        {.key = "filter.kind",
         .field = "filter.kind",
         .label = in_words("kind"),
         .help = tr_noop("the pose filter: ekf, ukf or pf, the particle filter (may change "
                         "while running)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        {FilterKind::Ekf, FilterKind::Ukf, FilterKind::Pf}, filter_kind_from_string,
        [](auto& c) -> auto& { return c.lesson.kind; }));
    s.push_back(boolean(
        {.key = "filter.compare_kinds",
         .field = "filter.compare_kinds",
         .label = in_words("compare kinds"),
         .help = tr_noop("also run another kind on the same frames, for comparison only: the UKF "
                         "beside the EKF, the EKF beside the UKF or the particle filter"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.compare_kinds; }));
    s.push_back(real(
        {.key = "filter.ukf_kappa",
         .field = "filter.ukf_kappa",
         .label = in_words("ukf kappa"),
         .help =
             tr_noop("UKF spread κ: sigma points at ±√((n+κ)P), weights κ/(n+κ) and 1/(2(n+κ))"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.ukf.kappa; }));
    s.push_back(whole(
        {.key = "pf.particles",
         .field = "pf.particles",
         .label = in_words("particles"),
         .help = tr_noop("particles in the particle filter's cloud (1 … 1000000); a new count "
                         "resamples the cloud to it"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.particle_count; }));
    s.push_back(real(
        {.key = "pf.resample_threshold",
         .field = "pf.resample_threshold",
         .label = in_words("resample threshold"),
         .help = tr_noop("the particle filter resamples when N_eff falls below this share of "
                         "its particles (0 … 1; 1: after every update)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.resample_threshold; }));
    s.push_back(boolean(
        {.key = "pf.recovery",
         .field = "pf.recovery",
         .label = in_words("recovery"),
         .help = tr_noop("augmented MCL: while the short-term likelihood is below the long-term "
                         "one, replace particles by random poses in the free space (finds a "
                         "kidnapped robot)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.recovery; }));
    s.push_back(real(
        {.key = "pf.alpha_slow",
         .field = "pf.alpha_slow",
         .label = in_words("alpha slow"),
         .help = tr_noop("smoothing of the long-term average likelihood w_slow (0 … 1)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.alpha_slow; }));
    s.push_back(real(
        {.key = "pf.alpha_fast",
         .field = "pf.alpha_fast",
         .label = in_words("alpha fast"),
         .help = tr_noop("smoothing of the short-term average likelihood w_fast (above "
                         "alpha_slow, at most 1)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.alpha_fast; }));
    s.push_back(real(
        {.key = "pf.alpha1",
         .field = "pf.alpha1",
         .label = paper_symbol("alpha1"),
         .help = tr_noop("motion noise α₁ (Probabilistic Robotics, Table 5.6): variance of each "
                         "rotation's error per rad² of rotation, on top of Q (0 … 1; 0: off)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.motion_alphas.rotation_from_rotation; }));
    s.push_back(real(
        {.key = "pf.alpha2",
         .field = "pf.alpha2",
         .label = paper_symbol("alpha2"),
         .help = tr_noop("motion noise α₂: variance of each rotation's error, rad², per m² of "
                         "translation, on top of Q (0 … 1; 0: off)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& {
            return c.lesson.particles.motion_alphas.rotation_from_translation;
        }));
    s.push_back(real(
        {.key = "pf.alpha3",
         .field = "pf.alpha3",
         .label = paper_symbol("alpha3"),
         .help = tr_noop("motion noise α₃: variance of the translation's error per m² of "
                         "translation, on top of Q (0 … 1; 0: off)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& {
            return c.lesson.particles.motion_alphas.translation_from_translation;
        }));
    s.push_back(real(
        {.key = "pf.alpha4",
         .field = "pf.alpha4",
         .label = paper_symbol("alpha4"),
         .help = tr_noop("motion noise α₄: variance of the translation's error, m², per rad² of "
                         "rotation, on top of Q (0 … 1; 0: off)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& {
            return c.lesson.particles.motion_alphas.translation_from_rotation;
        }));
    s.push_back(real(
        {.key = "pf.sigma_hit",
         .field = "pf.sigma_hit",
         .label = in_words("sigma hit"),
         .help = tr_noop("laser likelihood field: standard deviation of a beam's end point "
                         "about the nearest obstacle, m"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.scan_model.sigma_hit; }));
    s.push_back(real(
        {.key = "pf.z_hit",
         .field = "pf.z_hit",
         .label = in_words("z hit"),
         .help = tr_noop("laser likelihood field: weight of the Gaussian about the nearest "
                         "obstacle (0 … 1, relative to z_random)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.scan_model.z_hit; }));
    s.push_back(real(
        {.key = "pf.z_random",
         .field = "pf.z_random",
         .label = in_words("z random"),
         .help = tr_noop("laser likelihood field: weight of the uniform density of random "
                         "readings, which keeps an unmapped obstacle from killing particles "
                         "(0 … 1)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.scan_model.z_random; }));
    s.push_back(whole(
        {.key = "pf.beam_stride",
         .field = "pf.beam_stride",
         .label = in_words("beam stride"),
         .help = tr_noop("laser likelihood field: use every k-th beam of a scan (1 … 1024)"),
         .page = SettingPage::Filter,
         .applies = SettingApplies::Live,
         .use = kPoseFilterLessons},
        [](auto& c) -> auto& { return c.lesson.particles.scan_model.beam_stride; }));
    s.push_back(choice(
        {.key = "localisation.method",
         .field = "localisation.method",
         .label = in_words("method"),
         .help = tr_noop(
             "what corrects the odometry: walls (IR), beacons (bearings), gyro_fusion (5-state EKF "
             "with encoders, accelerometers, gyro), compass or laser (scan matching in a map)"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        {Localisation::Walls, Localisation::Beacons, Localisation::GyroFusion,
         Localisation::Compass, Localisation::Laser},
        localisation_from_string, [](auto& c) -> auto& { return c.lesson.localisation; }));
    s.push_back(real(
        {.key = "beacons.r_bearing",
         .field = "beacons.r_bearing",
         .label = in_words("r bearing"),
         .help = tr_noop("variance of one beacon bearing, rad²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kBeaconLesson},
        [](auto& c) -> auto& { return c.lesson.beacons.r_bearing; }));
    s.push_back(boolean(
        {.key = "beacons.gate",
         .field = "beacons.gate_enabled",
         .label = in_words("gate"),
         .help = tr_noop("reject bearings whose NIS exceeds the χ²(1) gate"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kBeaconLesson},
        [](auto& c) -> auto& { return c.lesson.beacons.gate_enabled; }));
    s.push_back(real(
        {.key = "beacons.gate_probability",
         .field = "beacons.gate_probability",
         .label = in_words("gate probability"),
         .help = tr_noop("probability of the bearing gate, in (0, 1)"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kBeaconLesson},
        [](auto& c) -> auto& { return c.lesson.beacons.gate_probability; }));
    s.push_back(real(
        {.key = "wheel_speed_kf.q_angle",
         .field = "wheel_speed_kf.q_angle",
         .label = in_words("q angle"),
         .help = tr_noop("Q11 of each wheel's KF, °²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.wheel_speed.q_angle; }));
    s.push_back(real(
        {.key = "wheel_speed_kf.q_rate",
         .field = "wheel_speed_kf.q_rate",
         .label = in_words("q rate"),
         .help = tr_noop("Q22 of each wheel's KF, (°/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.wheel_speed.q_rate; }));
    s.push_back(real(
        {.key = "wheel_speed_kf.r_right",
         .field = "wheel_speed_kf.r_right",
         .label = in_words("r right"),
         .help = tr_noop("R of the right encoder, °²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.wheel_speed.r_right; }));
    s.push_back(real(
        {.key = "wheel_speed_kf.r_left",
         .field = "wheel_speed_kf.r_left",
         .label = in_words("r left"),
         .help = tr_noop("R of the left encoder, °²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.wheel_speed.r_left; }));
    s.push_back(real(
        {.key = "wheel_speed_kf.p0",
         .field = "wheel_speed_kf.p0",
         .label = in_words("p0"),
         .help = tr_noop("P0 = p0·I of each wheel's KF"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.wheel_speed.p0; }));
    s.push_back(real(
        {.key = "velocity_kf.q_v",
         .field = "velocity_kf.q_v",
         .label = in_words("q v"),
         .help = tr_noop("Q11 of the (v, ω) KF, (m/s)² per period"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.velocity.q_v; }));
    s.push_back(real(
        {.key = "velocity_kf.q_w",
         .field = "velocity_kf.q_w",
         .label = in_words("q w"),
         .help = tr_noop("Q22 of the (v, ω) KF, (rad/s)² per period"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.velocity.q_w; }));
    s.push_back(real(
        {.key = "velocity_kf.r_v",
         .field = "velocity_kf.r_v",
         .label = paper_symbol("R11"),
         .help = tr_noop("variance of the encoder speed, (m/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.velocity.r_v; }));
    s.push_back(real(
        {.key = "velocity_kf.r_w",
         .field = "velocity_kf.r_w",
         .label = paper_symbol("R22"),
         .help = tr_noop("variance of the encoder turn rate, (rad/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.velocity.r_w; }));
    s.push_back(real(
        {.key = "velocity_kf.p0",
         .field = "velocity_kf.p0",
         .label = in_words("p0"),
         .help = tr_noop("P0 = p0·I of the (v, ω) KF"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.velocity.p0; }));
    s.push_back(real(
        {.key = "gyro_fusion.q_position",
         .field = "gyro_fusion.q_position",
         .label = in_words("q position"),
         .help = tr_noop("5-state EKF: Q of x and y per period, m²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_position; }));
    s.push_back(real(
        {.key = "gyro_fusion.q_heading",
         .field = "gyro_fusion.q_heading",
         .label = in_words("q heading"),
         .help = tr_noop("5-state EKF: Q of θ per period, rad²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_heading; }));
    s.push_back(real(
        {.key = "gyro_fusion.q_v",
         .field = "gyro_fusion.q_v",
         .label = in_words("q v"),
         .help = tr_noop("5-state EKF: Q of v per period, (m/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_v; }));
    s.push_back(real(
        {.key = "gyro_fusion.q_w",
         .field = "gyro_fusion.q_w",
         .label = in_words("q w"),
         .help = tr_noop("5-state EKF: Q of ω per period, (rad/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_w; }));
    s.push_back(real(
        {.key = "gyro_fusion.r_v_encoders",
         .field = "gyro_fusion.r_v_encoders",
         .label = in_words("r v encoders"),
         .help = tr_noop("variance of the encoder speed, (m/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_v_encoders; }));
    s.push_back(real(
        {.key = "gyro_fusion.r_w_encoders",
         .field = "gyro_fusion.r_w_encoders",
         .label = in_words("r w encoders"),
         .help = tr_noop("variance of the encoder turn rate, (rad/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_w_encoders; }));
    s.push_back(real(
        {.key = "gyro_fusion.r_w_gyro",
         .field = "gyro_fusion.r_w_gyro",
         .label = in_words("r w gyro"),
         .help = tr_noop("variance of the gyro rate, (rad/s)²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_w_gyro; }));
    s.push_back(boolean(
        {.key = "gyro_fusion.use_gyro",
         .field = "gyro_fusion.use_gyro",
         .label = in_words("use gyro"),
         .help =
             tr_noop("on: the gyro's rate updates ω too; off: encoders (and accelerometers) only"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.use_gyro; }));
    s.push_back(boolean(
        {.key = "gyro_fusion.use_accelerometers",
         .field = "gyro_fusion.use_accelerometers",
         .label = in_words("use accelerometers"),
         .help = tr_noop(
             "on: the accelerometers drive the prediction; off: predict at constant velocity"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.use_accelerometers; }));
    s.push_back(real(
        {.key = "gyro_fusion.encoder_gate_probability",
         .field = "gyro_fusion.encoder_gate_probability",
         .label = in_words("encoder gate probability"),
         .help =
             tr_noop("slip gate: reject the encoders' (v, ω) when their NIS against the "
                     "gyro-corrected state exceeds the χ²(2) quantile at this probability; 0: off"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kGyroFusionLesson},
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.encoder_gate_probability; }));
    s.push_back(real(
        {.key = "compass.k_d",
         .field = "compass.k_d",
         .label = in_words("k d"),
         .help = tr_noop("eq. 5: translation error coefficient k_D, m per m"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kCompassLesson},
        [](auto& c) -> auto& { return c.lesson.compass.k_d; }));
    s.push_back(real(
        {.key = "compass.k_dtheta",
         .field = "compass.k_dtheta",
         .label = in_words("k dtheta"),
         .help = tr_noop("eq. 5: rotation error per distance k_Dθ, rad² per m"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kCompassLesson},
        [](auto& c) -> auto& { return c.lesson.compass.k_dtheta; }));
    s.push_back(real(
        {.key = "compass.k_theta",
         .field = "compass.k_theta",
         .label = in_words("k theta"),
         .help = tr_noop("eq. 5: rotation error per turn k_θ, rad² per rad"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kCompassLesson},
        [](auto& c) -> auto& { return c.lesson.compass.k_theta; }));
    s.push_back(real(
        {.key = "compass.r_compass",
         .field = "compass.r_compass",
         .label = in_words("r compass"),
         .help = tr_noop("variance of the compass heading, rad²"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kCompassLesson},
        [](auto& c) -> auto& { return c.lesson.compass.r_compass; }));
    s.push_back(boolean(
        {.key = "compass.use_compass",
         .field = "compass.use_compass",
         .label = in_words("use compass"),
         .help = tr_noop("on: the compass heading updates θ; off: odometry only (P still grows)"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kCompassLesson},
        [](auto& c) -> auto& { return c.lesson.compass.use_compass; }));
    s.push_back(real(
        {.key = "calibration.gyro_offset",
         .field = "calibration.gyro_offset",
         .label = in_words("gyro offset"),
         .help = tr_noop("raw gyro value at rest, counts"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.calibration.gyro_offset; }));
    s.push_back(real(
        {.key = "calibration.gyro_counts_per_dps",
         .field = "calibration.gyro_counts_per_dps",
         .label = in_words("gyro counts per dps"),
         .help = tr_noop("gyro counts per °/s"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.calibration.gyro_counts_per_dps; }));
    s.push_back(real(
        {.key = "calibration.accel_counts_per_g",
         .field = "calibration.accel_counts_per_g",
         .label = in_words("accel counts per g"),
         .help = tr_noop("accelerometer counts per g"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.calibration.accel_counts_per_g; }));
    s.push_back(boolean(
        {.key = "calibration.remove_accel_bias",
         .field = "calibration.remove_accel_bias",
         .label = in_words("remove accel bias"),
         .help = tr_noop("remove the accelerometers' bias before use, estimated from the run's "
                         "readings and encoders; false: use the readings as they are"),
         .page = SettingPage::Localisation,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.lesson.calibration.remove_accel_bias; }));
}

}  // namespace legofeup::lessons
