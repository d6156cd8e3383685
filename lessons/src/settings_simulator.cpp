// The settings table: [simulator], the simulated robot's errors, noise, body and motors.
// They are the simulator's and wait for the next start, but for the wheels' errors and the
// noise, which the simulator takes while it runs (RobotConnection::set_noise).

#include "setting_builders.hpp"

namespace legofeup::lessons {

using namespace setting_builders;

void add_simulator_settings(std::vector<Setting>& s) {
    s.push_back(real(
        {.key = "simulator.wheel_diameter_ratio",
         .field = "simulator.wheel_diameter_ratio",
         .label = in_words("wheel diameter ratio"),
         .help = tr_noop("E_d = D_right/D_left of the real wheels"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.wheel_diameter_ratio; }));
    s.push_back(real(
        {.key = "simulator.wheel_base_ratio",
         .field = "simulator.wheel_base_ratio",
         .label = in_words("wheel base ratio"),
         .help = tr_noop("E_b = real / nominal wheel base"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.wheel_base_ratio; }));
    s.push_back(real(
        {.key = "simulator.slip_noise",
         .field = "simulator.slip_noise",
         .label = in_words("slip noise"),
         .help = tr_noop("random wheel slip, σ² = slip_noise²·distance, m^½"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.slip_noise; }));
    s.push_back(real(
        {.key = "simulator.ir_noise",
         .field = "simulator.ir_noise",
         .label = in_words("ir noise"),
         .help = tr_noop("σ of Gaussian noise on each IR distance, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::Live,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_noise; }));
    s.push_back(choice(
        {.key = "simulator.ir_model",
         .field = "simulator.ir_model",
         .label = in_words("ir model"),
         .help =
             tr_noop("the IR sensors: ideal (the filter's curve, noise constant in metres) or "
                     "realistic (each sensor its own curve from the seed, noise on the output)"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        {sim::IrSensorModel::Ideal, sim::IrSensorModel::Realistic},
        sim::ir_sensor_model_from_string, [](auto& c) -> auto& { return c.physical.ir_model; }));
    s.push_back(real(
        {.key = "simulator.ir_noise_distance",
         .field = "simulator.ir_noise_distance",
         .label = in_words("ir noise distance"),
         .help = tr_noop("realistic IR: the distance at which the noise is ir_noise, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_noise_distance; }));
    s.push_back(real(
        {.key = "simulator.ir_gain_spread",
         .field = "simulator.ir_gain_spread",
         .label = in_words("ir gain spread"),
         .help = tr_noop("realistic IR: σ of each sensor's output gain (data sheet: 0.044)"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_gain_spread; }));
    s.push_back(real(
        {.key = "simulator.ir_offset_spread",
         .field = "simulator.ir_offset_spread",
         .label = in_words("ir offset spread"),
         .help = tr_noop("realistic IR: σ of each sensor's output offset, A/D counts"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_offset_spread; }));
    s.push_back(real(
        {.key = "simulator.ir_period",
         .field = "simulator.ir_period",
         .label = in_words("ir period"),
         .help = tr_noop("IR update period (value held in between), s"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_period; }));
    s.push_back(real(
        {.key = "simulator.ir_ray_length",
         .field = "simulator.ir_ray_length",
         .label = in_words("ir ray length"),
         .help = tr_noop("the IR sensors see nothing beyond this, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kWallLessonIr},
        [](auto& c) -> auto& { return c.physical.ir_ray_length; }));
    s.push_back(real(
        {.key = "simulator.motor_time_constant",
         .field = "simulator.motor_time_constant",
         .label = in_words("motor time constant"),
         .help = tr_noop("first-order motor response, s"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.motor_time_constant; }));
    s.push_back(real(
        {.key = "simulator.max_motor_rpm",
         .field = "simulator.max_motor_rpm",
         .label = in_words("max motor rpm"),
         .help = tr_noop("motor no-load speed, rpm"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.max_motor_rpm; }));
    s.push_back(real(
        {.key = "simulator.mass",
         .field = "simulator.mass",
         .label = in_words("mass"),
         .help = tr_noop("robot mass, kg"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.mass; }));
    s.push_back(real(
        {.key = "simulator.traction",
         .field = "simulator.traction",
         .label = in_words("traction"),
         .help = tr_noop("tyre friction coefficient μ"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.traction; }));
    s.push_back(real(
        {.key = "simulator.wheel_load",
         .field = "simulator.wheel_load",
         .label = in_words("wheel load"),
         .help = tr_noop("share of the weight on the driven wheels"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.wheel_load; }));
    s.push_back(real(
        {.key = "simulator.chassis_front",
         .field = "simulator.chassis_front",
         .label = in_words("chassis front"),
         .help = tr_noop("chassis extent ahead of the axle, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.chassis_front; }));
    s.push_back(real(
        {.key = "simulator.chassis_rear",
         .field = "simulator.chassis_rear",
         .label = in_words("chassis rear"),
         .help = tr_noop("chassis extent behind the axle, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.chassis_rear; }));
    s.push_back(real(
        {.key = "simulator.chassis_half_width",
         .field = "simulator.chassis_half_width",
         .label = in_words("chassis half width"),
         .help = tr_noop("half the chassis width with wheels, m"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.physical.chassis_half_width; }));
    s.push_back(real(
        {.key = "simulator.physics_rate",
         .field = "simulator.physics_rate",
         .label = in_words("physics rate"),
         .help = tr_noop("physics steps per second, Hz"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.physics_rate; }));
    s.push_back(real(
        {.key = "simulator.control_period",
         .field = "simulator.control_period",
         .label = in_words("control period"),
         .help = tr_noop("control period of the loop, s"),
         .page = SettingPage::Simulator,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.simulator.control_period; }));
    s.push_back(
        pose_part({.key = "simulator.start_x",
                   .field = "simulator.start_x",
                   .label = in_words("start x"),
                   .help = tr_noop("where the robot really starts, m (default: world start)"),
                   .page = SettingPage::Simulator,
                   .applies = SettingApplies::NextStart,
                   .use = kEveryRun},
                  &RunConfig::true_start, &PoseOverride::x));
    s.push_back(pose_part({.key = "simulator.start_y",
                           .field = "simulator.start_y",
                           .label = in_words("start y"),
                           .help = tr_noop("real start y, m (default: world start)"),
                           .page = SettingPage::Simulator,
                           .applies = SettingApplies::NextStart,
                           .use = kEveryRun},
                          &RunConfig::true_start, &PoseOverride::y));
    s.push_back(pose_part({.key = "simulator.start_heading_deg",
                           .field = "simulator.start_heading",
                           .label = in_words("start heading deg"),
                           .help = tr_noop("real start heading, ° (default: world start)"),
                           .page = SettingPage::Simulator,
                           .applies = SettingApplies::NextStart,
                           .use = kEveryRun},
                          &RunConfig::true_start, &PoseOverride::theta, kPi / 180.0));
}

}  // namespace legofeup::lessons
