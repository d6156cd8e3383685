// The settings table: [laser], the laser scan-matching filter of paper 001 (validated as
// "lesson.laser.*"), and the simulated laser rangefinder ([laser_scanner]) with the
// kidnapping ([kidnap]). Both describe a scanner's geometry and mount the same way.

#include "legofeup/lessons/map_file.hpp"
#include "setting_builders.hpp"

namespace legofeup::lessons {
namespace {

using namespace setting_builders;

// A scanner's geometry and mount under `section` ("laser" for the filter's belief,
// "laser_scanner" for the simulated scanner), validated as "<field_prefix>.geometry.*" and
// "<field_prefix>.mount.*". `scanner` returns the scanner's settings of a configuration; an
// abbreviated template (`auto`), because lupdate files the texts of a `template <class …>`
// function under a wrong context.
void add_scanner_geometry(std::vector<Setting>& s, const std::string& section,
                          const std::string& field_prefix, const SectionFacts& where,
                          auto scanner) {
    const std::string k = section + ".";
    const std::string g = field_prefix + ".geometry.";
    const std::string m = field_prefix + ".mount.";
    s.push_back(whole(
        {.key = k + "beam_count",
         .field = g + "beam_count",
         .label = in_words("beam count"),
         .help = tr_noop("beams per scan (1 … 1024; URG-04LX: 682)"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).geometry.beam_count; }));
    s.push_back(degrees(
        {.key = k + "angle_min_deg",
         .field = g + "angle_min",
         .label = in_words("angle min deg"),
         .help = tr_noop(
             "direction of the first beam, ° counter-clockwise from the scanner's forward axis"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).geometry.angle_min; }));
    s.push_back(degrees(
        {.key = k + "angle_increment_deg",
         .field = g + "angle_increment",
         .label = in_words("angle increment deg"),
         .help = tr_noop(
             "angle between neighbouring beams, ° (field of view = beam_count · increment)"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).geometry.angle_increment; }));
    s.push_back(real(
        {.key = k + "range_min",
         .field = g + "range_min",
         .label = in_words("range min"),
         .help = tr_noop("shorter readings are errors, m"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).geometry.range_min; }));
    s.push_back(real(
        {.key = k + "range_max",
         .field = g + "range_max",
         .label = in_words("range max"),
         .help = tr_noop("longest reading the scanner reports, m"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).geometry.range_max; }));
    s.push_back(real(
        {.key = k + "mount_x",
         .field = m + "x",
         .label = in_words("mount x"),
         .help = tr_noop("scanner position ahead of the axle centre, m"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).mount.x; }));
    s.push_back(real(
        {.key = k + "mount_y",
         .field = m + "y",
         .label = in_words("mount y"),
         .help = tr_noop("scanner position left of the centre line, m"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).mount.y; }));
    s.push_back(degrees(
        {.key = k + "mount_heading_deg",
         .field = m + "theta",
         .label = in_words("mount heading deg"),
         .help = tr_noop("scanner's forward axis relative to the robot's, °"),
         .page = where.page.value,
         .applies = where.applies.value,
         .use = where.use.value},
        [scanner](auto& c) -> auto& { return scanner(c).mount.theta; }));
}

}  // namespace

void add_laser_settings(std::vector<Setting>& s) {
    s.push_back(real(
        {.key = "laser.q_x_static",
         .field = "lesson.laser.q_x_static",
         .label = in_words("q x static"),
         .help = tr_noop("eq. 13: Q of x added at every prediction, m²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_x_static; }));
    s.push_back(real(
        {.key = "laser.q_y_static",
         .field = "lesson.laser.q_y_static",
         .label = in_words("q y static"),
         .help = tr_noop("eq. 13: Q of y added at every prediction, m²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_y_static; }));
    s.push_back(real(
        {.key = "laser.q_theta_static",
         .field = "lesson.laser.q_theta_static",
         .label = in_words("q theta static"),
         .help = tr_noop("eq. 13: Q of θ added at every prediction, rad²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_theta_static; }));
    s.push_back(real(
        {.key = "laser.q_x_dynamic",
         .field = "lesson.laser.q_x_dynamic",
         .label = in_words("q x dynamic"),
         .help = tr_noop("eq. 13: Q of x per metre of odometry increment |Δx|, m²/m"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_x_dynamic; }));
    s.push_back(real(
        {.key = "laser.q_y_dynamic",
         .field = "lesson.laser.q_y_dynamic",
         .label = in_words("q y dynamic"),
         .help = tr_noop("eq. 13: Q of y per metre of odometry increment |Δy|, m²/m"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_y_dynamic; }));
    s.push_back(real(
        {.key = "laser.q_theta_dynamic",
         .field = "lesson.laser.q_theta_dynamic",
         .label = in_words("q theta dynamic"),
         .help = tr_noop("eq. 13: Q of θ per radian of odometry increment |Δθ|, rad²/rad"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.q_theta_dynamic; }));
    s.push_back(real(
        {.key = "laser.r_x",
         .field = "lesson.laser.r_x",
         .label = in_words("r x"),
         .help = tr_noop("eq. 16: R of the ICP pose observation's x, m²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.r_x; }));
    s.push_back(real(
        {.key = "laser.r_y",
         .field = "lesson.laser.r_y",
         .label = in_words("r y"),
         .help = tr_noop("eq. 16: R of the ICP pose observation's y, m²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.r_y; }));
    s.push_back(real(
        {.key = "laser.r_theta",
         .field = "lesson.laser.r_theta",
         .label = in_words("r theta"),
         .help = tr_noop("eq. 16: R of the ICP pose observation's θ, rad²"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.r_theta; }));
    s.push_back(choice(
        {.key = "laser.icp_metric",
         .field = "lesson.laser.icp.metric",
         .label = in_words("icp metric"),
         .help =
             tr_noop("ICP error: point_to_point or point_to_line (distance to the map's surface)"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        {IcpMetric::PointToPoint, IcpMetric::PointToLine}, icp_metric_from_string,
        [](auto& c) -> auto& { return c.lesson.laser.icp.metric; }));
    s.push_back(whole(
        {.key = "laser.icp_max_iterations",
         .field = "lesson.laser.icp.max_iterations",
         .label = in_words("icp max iterations"),
         .help = tr_noop("ICP gives up (not converged) after this many iterations"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.icp.max_iterations; }));
    s.push_back(real(
        {.key = "laser.icp_max_correspondence_distance",
         .field = "lesson.laser.icp.max_correspondence_distance",
         .label = in_words("icp max correspondence distance"),
         .help = tr_noop("a scan point farther than this from the expected scan is an outlier, m"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.icp.max_correspondence_distance; }));
    s.push_back(real(
        {.key = "laser.icp_trim_fraction",
         .field = "lesson.laser.icp.trim_fraction",
         .label = in_words("icp trim fraction"),
         .help = tr_noop("fraction of the worst pairs dropped each iteration, 0 … 0.9"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.icp.trim_fraction; }));
    s.push_back(real(
        {.key = "laser.icp_translation_epsilon",
         .field = "lesson.laser.icp.translation_epsilon",
         .label = in_words("icp translation epsilon"),
         .help = tr_noop("ICP converged when a step moves less than this, m …"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.icp.translation_epsilon; }));
    s.push_back(real(
        {.key = "laser.icp_rotation_epsilon",
         .field = "lesson.laser.icp.rotation_epsilon",
         .label = in_words("icp rotation epsilon"),
         .help = tr_noop("… and turns less than this, rad"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.icp.rotation_epsilon; }));
    s.push_back(whole(
        {.key = "laser.min_matched_points",
         .field = "lesson.laser.min_matched_points",
         .label = in_words("min matched points"),
         .help = tr_noop("mismatch gate: a match with fewer inlier points is not used (prediction "
                         "only; the paper names this condition, §III-B, but gives no number)"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.min_matched_points; }));
    s.push_back(boolean(
        {.key = "laser.kidnap_recovery",
         .field = "lesson.laser.kidnap_recovery",
         .label = in_words("kidnap recovery"),
         .help = tr_noop("after many mismatches in a row, inflate P and tighten ICP (paper §IV-B)"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.kidnap_recovery; }));
    s.push_back(whole(
        {.key = "laser.recovery_after_mismatches",
         .field = "lesson.laser.recovery_after_mismatches",
         .label = in_words("recovery after mismatches"),
         .help = tr_noop("consecutive mismatches that start the recovery"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.recovery_after_mismatches; }));
    s.push_back(real(
        {.key = "laser.recovery_covariance_factor",
         .field = "lesson.laser.recovery_covariance_factor",
         .label = in_words("recovery covariance factor"),
         .help = tr_noop("P is multiplied by this"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.recovery_covariance_factor; }));
    s.push_back(real(
        {.key = "laser.recovery_correspondence_factor",
         .field = "lesson.laser.recovery_correspondence_factor",
         .label = in_words("recovery correspondence factor"),
         .help = tr_noop("ICP's correspondence distance is multiplied by this (≤ 1: stricter)"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser.recovery_correspondence_factor; }));
    add_scanner_geometry(
        s, "laser", "lesson.laser",
        {.page = SettingPage::Laser, .applies = SettingApplies::Live, .use = kLaserLesson},
        [](auto& c) -> auto& { return c.lesson.laser; });
    // The field is the one the loop's validate() uses when the map is missing.
    s.push_back(file(
        {.key = "laser.map",
         .field = "map",
         .label = in_words("map"),
         .help = tr_noop("the filter's map: a built-in map (standard_arena, office) or a map YAML "
                         "file; empty: the world's map (a different one is an outdated map)"),
         .page = SettingPage::Laser,
         .applies = SettingApplies::Live,
         .use = kLaserLesson},
        &RunConfig::laser_map_file, built_in_map_names));
}

void add_laser_simulation_settings(std::vector<Setting>& s) {
    s.push_back(boolean(
        {.key = "laser_scanner.enabled",
         .field = "simulator.laser_scanner.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("simulate the laser rangefinder (URG-04LX-like)"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.enabled; }));
    add_scanner_geometry(
        s, "laser_scanner", "simulator.laser_scanner",
        {.page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner; });
    s.push_back(real(
        {.key = "laser_scanner.scan_period",
         .field = "simulator.laser_scanner.scan_period",
         .label = in_words("scan period"),
         .help = tr_noop("s between scans (a whole number of control periods)"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.scan_period; }));
    s.push_back(real(
        {.key = "laser_scanner.sigma_near",
         .field = "simulator.laser_scanner.sigma_near",
         .label = in_words("sigma near"),
         .help = tr_noop("σ of the range noise up to noise_knee, m"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.sigma_near; }));
    s.push_back(real(
        {.key = "laser_scanner.noise_knee",
         .field = "simulator.laser_scanner.noise_knee",
         .label = in_words("noise knee"),
         .help = tr_noop("range beyond which σ = sigma_relative · range, m"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.noise_knee; }));
    s.push_back(real(
        {.key = "laser_scanner.sigma_relative",
         .field = "simulator.laser_scanner.sigma_relative",
         .label = in_words("sigma relative"),
         .help = tr_noop("σ of the range noise beyond noise_knee, as a fraction of the range"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.sigma_relative; }));
    s.push_back(real(
        {.key = "laser_scanner.dropout_probability",
         .field = "simulator.laser_scanner.dropout_probability",
         .label = in_words("dropout probability"),
         .help = tr_noop("probability that a beam returns no measurement, 0 … 1"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.laser_scanner.dropout_probability; }));
    s.push_back(boolean(
        {.key = "kidnap.enabled",
         .field = "simulator.kidnap.enabled",
         .label = in_words("enabled"),
         .help = tr_noop("lift the robot once and put it down elsewhere (the filter is not told)"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.kidnap.enabled; }));
    s.push_back(real(
        {.key = "kidnap.time",
         .field = "simulator.kidnap.time",
         .label = in_words("time"),
         .help = tr_noop("simulated time of the kidnapping, s"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.kidnap.time; }));
    s.push_back(real(
        {.key = "kidnap.x",
         .field = "simulator.kidnap.pose.x",
         .label = in_words("x"),
         .help = tr_noop("where the robot is put down: x, m"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.x; }));
    s.push_back(real(
        {.key = "kidnap.y",
         .field = "simulator.kidnap.pose.y",
         .label = in_words("y"),
         .help = tr_noop("where the robot is put down: y, m"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.y; }));
    s.push_back(degrees(
        {.key = "kidnap.heading_deg",
         .field = "simulator.kidnap.pose.theta",
         .label = in_words("heading deg"),
         .help = tr_noop("heading it is put down with, °"),
         .page = SettingPage::SimulatedLaser,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.theta; }));
}

}  // namespace legofeup::lessons
