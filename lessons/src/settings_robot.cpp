// The settings table: the robot as the filter assumes it is built — [robot], the IR
// sensors' curve [ir_curve] (eq. 2, D = a·(C_M/(A + C_R) − b), its trusted range, and each
// sensor's own curve, calibrated per unit) and the walls' association [association]
// (Fig. 4). The loop takes them at its next step.

#include "setting_builders.hpp"

namespace legofeup::lessons {
namespace {

using namespace setting_builders;

constexpr auto kFront = static_cast<std::size_t>(kFrontSensor);
constexpr auto kRear = static_cast<std::size_t>(kRearSensor);

}  // namespace

void add_robot_settings(std::vector<Setting>& s) {
    s.push_back(real(
        {.key = "robot.wheel_diameter",
         .field = "robot.wheel_diameter",
         .label = in_words("wheel diameter"),
         .help = tr_noop("wheel diameter, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.robot.wheel_diameter; }));
    s.push_back(real(
        {.key = "robot.wheel_base",
         .field = "odometry.wheel_base",
         .label = paper_symbol("b"),
         .help = tr_noop("distance between the wheels, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.robot.wheel_base; }));
    s.push_back(real(
        {.key = "robot.counts_per_turn",
         .field = "robot.counts_per_turn",
         .label = in_words("counts per turn"),
         .help = tr_noop("encoder counts per wheel turn"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.robot.counts_per_turn; }));
    s.push_back(real(
        {.key = "robot.codo_right",
         .field = "odometry.codo_right",
         .label = paper_symbol("Codo1"),
         .help = tr_noop("right wheel counts per metre; 0: from the diameter"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.robot.codo_right; }));
    s.push_back(real(
        {.key = "robot.codo_left",
         .field = "odometry.codo_left",
         .label = paper_symbol("Codo2"),
         .help = tr_noop("left wheel counts per metre; 0: from the diameter"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.robot.codo_left; }));
    s.push_back(real(
        {.key = "robot.ir_front",
         .field = "ir_mount.front_longitudinal",
         .label = in_words("ir front"),
         .help = tr_noop("front IR sensor ahead of the axle, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.robot.ir_mount.front_longitudinal; }));
    s.push_back(real(
        {.key = "robot.ir_rear",
         .field = "ir_mount.rear_longitudinal",
         .label = in_words("ir rear"),
         .help = tr_noop("rear IR sensor ahead of the axle (negative: behind), m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.robot.ir_mount.rear_longitudinal; }));
    s.push_back(real(
        {.key = "robot.ir_lateral",
         .field = "ir_mount.lateral_offset",
         .label = in_words("ir lateral"),
         .help = tr_noop("IR sensors' distance from the centre line (right side), m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.robot.ir_mount.lateral_offset; }));
    s.push_back(real(
        {.key = "ir_curve.a",
         .field = "ir_curve.a",
         .label = paper_symbol("a"),
         .help = tr_noop("scale of the fit, m per fit unit"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.a; }));
    s.push_back(real(
        {.key = "ir_curve.c_m",
         .field = "ir_curve.c_m",
         .label = paper_symbol("C_M"),
         .help = tr_noop("constant of multiplication"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.c_m; }));
    s.push_back(real(
        {.key = "ir_curve.c_r",
         .field = "ir_curve.c_r",
         .label = paper_symbol("C_R"),
         .help = tr_noop("constant of linearisation"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.c_r; }));
    s.push_back(real(
        {.key = "ir_curve.b",
         .field = "ir_curve.b",
         .label = paper_symbol("b"),
         .help = tr_noop("offset of the fit, fit units"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.b; }));
    s.push_back(real(
        {.key = "ir_curve.min_range",
         .field = "ir_curve.min_range",
         .label = in_words("min range"),
         .help = tr_noop("closest trusted reading, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.min_range; }));
    s.push_back(real(
        {.key = "ir_curve.max_range",
         .field = "ir_curve.max_range",
         .label = in_words("max range"),
         .help = tr_noop("farthest trusted reading, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.max_range; }));
    s.push_back(real(
        {.key = "ir_curve.peak_distance",
         .field = "ir_curve.peak_distance",
         .label = in_words("peak distance"),
         .help = tr_noop("the sensor's output peaks here and folds back below, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.peak_distance; }));
    s.push_back(real(
        {.key = "ir_curve.contact_adc",
         .field = "ir_curve.contact_adc",
         .label = in_words("contact adc"),
         .help = tr_noop("A/D value with the target touching the sensor"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_curve.contact_adc; }));
    // Each sensor's own curve: an unset parameter is the shared one.
    s.push_back(optional_real(
        {.key = "ir_curve.front_a",
         .field = "ir_curve.front.a",
         .label = in_words("front a"),
         .help = tr_noop("the front sensor's own a, m per fit unit; unset: ir_curve.a"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kFront].a; },
        [](const RunConfig& c) { return c.ir_curve.a; }));
    s.push_back(optional_real(
        {.key = "ir_curve.front_c_m",
         .field = "ir_curve.front.c_m",
         .label = in_words("front c m"),
         .help = tr_noop("the front sensor's own C_M; unset: ir_curve.c_m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kFront].c_m; },
        [](const RunConfig& c) { return c.ir_curve.c_m; }));
    s.push_back(optional_real(
        {.key = "ir_curve.front_c_r",
         .field = "ir_curve.front.c_r",
         .label = in_words("front c r"),
         .help = tr_noop("the front sensor's own C_R; unset: ir_curve.c_r"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kFront].c_r; },
        [](const RunConfig& c) { return c.ir_curve.c_r; }));
    s.push_back(optional_real(
        {.key = "ir_curve.front_b",
         .field = "ir_curve.front.b",
         .label = in_words("front b"),
         .help = tr_noop("the front sensor's own b, fit units; unset: ir_curve.b"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kFront].b; },
        [](const RunConfig& c) { return c.ir_curve.b; }));
    s.push_back(optional_real(
        {.key = "ir_curve.rear_a",
         .field = "ir_curve.rear.a",
         .label = in_words("rear a"),
         .help = tr_noop("the rear sensor's own a, m per fit unit; unset: ir_curve.a"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kRear].a; },
        [](const RunConfig& c) { return c.ir_curve.a; }));
    s.push_back(optional_real(
        {.key = "ir_curve.rear_c_m",
         .field = "ir_curve.rear.c_m",
         .label = in_words("rear c m"),
         .help = tr_noop("the rear sensor's own C_M; unset: ir_curve.c_m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kRear].c_m; },
        [](const RunConfig& c) { return c.ir_curve.c_m; }));
    s.push_back(optional_real(
        {.key = "ir_curve.rear_c_r",
         .field = "ir_curve.rear.c_r",
         .label = in_words("rear c r"),
         .help = tr_noop("the rear sensor's own C_R; unset: ir_curve.c_r"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kRear].c_r; },
        [](const RunConfig& c) { return c.ir_curve.c_r; }));
    s.push_back(optional_real(
        {.key = "ir_curve.rear_b",
         .field = "ir_curve.rear.b",
         .label = in_words("rear b"),
         .help = tr_noop("the rear sensor's own b, fit units; unset: ir_curve.b"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.ir_sensor_curves[kRear].b; },
        [](const RunConfig& c) { return c.ir_curve.b; }));
    s.push_back(real(
        {.key = "association.segment_margin",
         .field = "association.segment_margin",
         .label = in_words("segment margin"),
         .help = tr_noop("predicted beams may miss a wall's end by this much, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.segment_margin; }));
    s.push_back(real(
        {.key = "association.range_margin",
         .field = "association.range_margin",
         .label = in_words("range margin"),
         .help = tr_noop("predicted beams may exceed the IR range by this much, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.range_margin; }));
    s.push_back(degrees(
        {.key = "association.max_incidence_deg",
         .field = "association.max_incidence",
         .label = in_words("max incidence deg"),
         .help = tr_noop("walls seen more obliquely are not used, °"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.max_incidence; }));
    s.push_back(degrees(
        {.key = "association.max_angle_error_deg",
         .field = "association.max_angle_error",
         .label = in_words("max angle error deg"),
         .help = tr_noop("largest accepted ObsAng error, °"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.max_angle_error; }));
    s.push_back(real(
        {.key = "association.max_distance_error",
         .field = "association.max_distance_error",
         .label = in_words("max distance error"),
         .help = tr_noop("largest accepted wall distance error, m"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.max_distance_error; }));
    s.push_back(choice(
        {.key = "association.gate",
         .field = "association.gate",
         .label = in_words("gate"),
         .help = tr_noop(
             "which test takes a wall: fixed (the paper's: the angle and distance errors under the "
             "limits above) or mahalanobis (νᵀS⁻¹ν with S = HPHᵀ + R under the χ²(2) quantile)"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        {AssociationGate::Fixed, AssociationGate::Mahalanobis}, association_gate_from_string,
        [](auto& c) -> auto& { return c.association.gate; }));
    s.push_back(real(
        {.key = "association.gate_probability",
         .field = "association.gate_probability",
         .label = in_words("gate probability"),
         .help = tr_noop("probability of the Mahalanobis association gate, in (0, 1)"),
         .page = SettingPage::Robot,
         .applies = SettingApplies::Live,
         .use = kWallLessonAssociation},
        [](auto& c) -> auto& { return c.association.gate_probability; }));
}

}  // namespace legofeup::lessons
